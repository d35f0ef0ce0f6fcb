#pragma once
// A bound on what a template's `#define`s expand to, checked before glslang preprocesses it: chained macros
// (`#define M2 (M1 + M1)`) double per line, so a few hundred bytes can ask glslang for 2^40 tokens, and glslang
// has no limit or time-out of its own.
#include <string>

namespace hexc {

// Templates expanding to more tokens are refused: a few seconds of glslang (a chain expanding to 2.1 M tokens
// compiled in 1.6 s here), far above any template an engine writes (the built-in `lit` is about 2,000 tokens).
constexpr double kMaxExpandedTokens = 4'000'000;

// Templates calling more functions are refused too: glslang's call graph is quadratic in calls (10,000 took 17 s) and
// spirv-opt's inliner in functions times calls. Counted as written, `name(` outside directives that neither a
// declaration defines (`float f(`) nor a built-in type constructs (`vec3(`): built-in functions count too (the
// built-in `lit` makes 18).
constexpr int kMaxTemplateCalls = 4000;

struct MacroExpansion {
    double tokens = 0;  // the tokens after expansion (infinite past what a double holds)
    int line = 0;       // the line at which the running total first exceeded kMaxExpandedTokens; 0 if it never did
    int calls = 0;      // calls outside directives, macros unexpanded (see kMaxTemplateCalls)
    int callsLine = 0;  // the line at which calls first exceeded kMaxTemplateCalls; 0 if they never did
};

// Walks the source once, keeping the macros defined so far, and sums each line's expanded size and calls. Each macro's size
// is memoised as an affine function of its parameters' sizes, so nested invocations (`D(D(D(x)))`) and chains cost
// time linear in the source. Token pasting (`##`) is counted as written.
MacroExpansion boundMacroExpansion(const std::string& source);

}  // namespace hexc
