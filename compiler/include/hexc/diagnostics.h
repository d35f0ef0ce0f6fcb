#pragma once
// Every problem hexc finds is a Diagnostic: where (file:line:col and JSON path), what was expected.
#include <string>
#include <vector>

namespace hexc {

struct SourceLoc {
    std::string file;  // as given by the user (relative paths stay relative)
    int line = 0;      // 1-based; 0 when unknown
    int col = 0;       // 1-based; 0 when unknown
};

struct Diagnostic {
    enum class Severity { Error, Warning };
    Severity severity = Severity::Error;
    SourceLoc loc;
    std::string path;     // JSON pointer, e.g. /slots/0/falloff; empty when not about a JSON value
    std::string message;  // what is wrong and what was expected
    std::string hint;     // optional: "did you mean `rotation`?"

    // "file:line:col: error: /path: message (hint)"
    std::string format() const;
};

using Diagnostics = std::vector<Diagnostic>;

bool hasErrors(const Diagnostics& diags);
std::string formatAll(const Diagnostics& diags);

// Thrown only by stages that cannot continue; carries the located problems.
struct CompileError {
    Diagnostics diagnostics;
};

}  // namespace hexc
