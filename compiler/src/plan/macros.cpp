#include "plan/macros.h"

#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <vector>

namespace hexc {
namespace {

using TokenList = std::vector<std::string>;

// A size as a function of the sizes of the parameters of the macro being measured: c + sum k[i] * size(param i).
struct Affine {
    double c = 0;
    std::vector<double> k;

    void add(const Affine& other, double times) {
        if (times == 0) return;  // 0 * inf would be NaN, which compares below every limit
        c += times * other.c;
        for (size_t i = 0; i < k.size(); ++i)
            if (other.k[i] != 0) k[i] += times * other.k[i];
    }
};

struct Macro {
    bool function = false;
    TokenList params, body;
    std::optional<Affine> size;  // memoised while the definitions stay the same
};

// Beyond this many macros inside one another the bound is infinite (it also bounds this file's recursion).
constexpr int kMaxDepth = 1000;

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Identifiers, numbers (`1.5e3`, `.5`) and single punctuation characters: enough to find macro names.
TokenList tokenize(const std::string& text, size_t from = 0) {
    TokenList out;
    for (size_t i = from; i < text.size();) {
        char ch = text[i];
        bool number = std::isdigit(static_cast<unsigned char>(ch)) ||
                      (ch == '.' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1])));
        if (std::isspace(static_cast<unsigned char>(ch))) {
            ++i;
        } else if (number || identifierChar(ch)) {
            size_t end = i + 1;
            while (end < text.size() && (identifierChar(text[end]) || (number && text[end] == '.'))) ++end;
            out.push_back(text.substr(i, end - i));
            i = end;
        } else {
            out.emplace_back(1, text[i++]);
        }
    }
    return out;
}

class Measure {
public:
    std::map<std::string, Macro> macros;

    // The size of tokens [begin, end) as a function of `params` (the parameters of the macro they belong to).
    Affine size(const TokenList& t, size_t begin, size_t end, const TokenList& params, int depth) {
        Affine out{0, std::vector<double>(params.size())};
        if (depth > kMaxDepth) {
            out.c = INFINITY;
            return out;
        }
        for (size_t i = begin; i < end; ++i) {
            if (size_t p = indexOf(params, t[i]); p < params.size()) {
                out.k[p] += 1;
                continue;
            }
            auto it = macros.find(t[i]);
            if (it == macros.end() || active_.count(t[i]) || (it->second.function && (i + 1 >= end || t[i + 1] != "("))) {
                out.c += 1;
                continue;
            }
            const Affine& m = macroSize(it->first, it->second, depth + 1);
            if (!it->second.function) {
                out.c += m.c;
                continue;
            }
            out.c += m.c;
            i = addArguments(t, i + 1, end, params, m, depth, out);
        }
        return out;
    }

private:
    std::set<std::string> active_;  // macros being measured: inside their own body they do not expand (C rules)

    static size_t indexOf(const TokenList& list, const std::string& token) {
        size_t i = 0;
        while (i < list.size() && list[i] != token) ++i;
        return i;
    }

    const Affine& macroSize(const std::string& name, Macro& m, int depth) {
        if (!m.size) {
            active_.insert(name);
            m.size = size(m.body, 0, m.body.size(), m.params, depth);
            active_.erase(name);
        }
        return *m.size;
    }

    // Adds, for the invocation whose `(` is at `open`, each argument's size times its uses; returns the index of
    // the closing `)` (or the last token when it is missing).
    size_t addArguments(const TokenList& t, size_t open, size_t end, const TokenList& params, const Affine& m, int depth, Affine& out) {
        size_t argument = 0, start = open + 1, i = open + 1;
        for (int nesting = 0; i < end; ++i) {
            bool last = t[i] == ")" && nesting == 0;
            if ((t[i] == "," && nesting == 0) || last) {
                if (argument < m.k.size()) out.add(size(t, start, i, params, depth), m.k[argument]);
                ++argument, start = i + 1;
                if (last) return i;
            }
            nesting += t[i] == "(" ? 1 : t[i] == ")" ? -1 : 0;
        }
        return end - 1;
    }
};

// `#define NAME body` or `#define NAME(a, b) body`: the parameter list only when `(` follows the name at once.
void define(Measure& measure, const std::string& line, size_t at) {
    while (at < line.size() && std::isspace(static_cast<unsigned char>(line[at]))) ++at;
    size_t nameEnd = at;
    while (nameEnd < line.size() && identifierChar(line[nameEnd])) ++nameEnd;
    if (nameEnd == at) return;  // glslang reports the malformed directive
    Macro m;
    size_t bodyAt = nameEnd;
    if (nameEnd < line.size() && line[nameEnd] == '(') {
        m.function = true;
        bodyAt = line.find(')', nameEnd);
        if (bodyAt == std::string::npos) return;
        for (const std::string& p : tokenize(line.substr(nameEnd + 1, bodyAt - nameEnd - 1)))
            if (p != ",") m.params.push_back(p);
        ++bodyAt;
    }
    m.body = tokenize(line, bodyAt);
    for (auto& [name, other] : measure.macros) other.size.reset();
    measure.macros[line.substr(at, nameEnd - at)] = std::move(m);
}

// The source as logical lines (continuations joined, comments blanked), each with its first physical line.
std::vector<std::pair<std::string, int>> logicalLines(const std::string& source) {
    std::vector<std::pair<std::string, int>> out;
    std::string line;
    int number = 1, first = 1;
    for (size_t i = 0; i < source.size(); ++i) {
        char ch = source[i];
        if (ch == '\\' && i + 1 < source.size() && source[i + 1] == '\n') {
            ++i, ++number;
        } else if (ch == '/' && i + 1 < source.size() && source[i + 1] == '/') {
            while (i + 1 < source.size() && source[i + 1] != '\n') ++i;
        } else if (ch == '/' && i + 1 < source.size() && source[i + 1] == '*') {
            size_t close = source.find("*/", i + 2);
            size_t stop = close == std::string::npos ? source.size() : close + 2;
            for (size_t j = i; j < stop; ++j) number += source[j] == '\n';
            line += ' ', i = stop - 1;
        } else if (ch == '\n') {
            out.emplace_back(std::move(line), first);
            line.clear(), first = ++number;
        } else {
            line += ch;
        }
    }
    out.emplace_back(std::move(line), first);
    return out;
}

// Keywords a `(` follows that call nothing.
const std::set<std::string> kNotCalls = {"if", "for", "while", "switch", "return", "layout"};
// Keywords an expression (and so a call) may follow; any other word before `name(` makes it a declaration
// (`float f(`), which calls nothing.
const std::set<std::string> kBeforeExpressions = {"return", "else", "case", "do"};

// A built-in type, whose `type(` constructs a value and calls nothing: float, int, uint, bool, double, [iubd]vecN, [d]matN[xM].
bool builtinType(const std::string& name) {
    static const std::set<std::string> scalars = {"float", "int", "uint", "bool", "double"};
    if (scalars.contains(name)) return true;
    std::string rest = name;
    if (rest.size() > 4 && std::string("iubd").find(rest[0]) != std::string::npos && rest.substr(1, 3) == "vec") rest = rest.substr(1);
    if (rest.size() == 4 && rest.starts_with("vec")) return rest[3] >= '2' && rest[3] <= '4';
    if (rest.starts_with("dmat")) rest = rest.substr(1);
    const bool square = rest.size() == 4, sized = rest.size() == 6 && rest[4] == 'x' && rest[5] >= '2' && rest[5] <= '4';
    return rest.starts_with("mat") && (square || sized) && rest[3] >= '2' && rest[3] <= '4';
}

// Whether tokens[i] `(` is a call: a name, not a keyword, type constructor or the name a declaration defines.
bool isCall(const TokenList& tokens, size_t i) {
    const std::string& name = tokens[i];
    if (tokens[i + 1] != "(" || !identifierChar(name[0]) || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
    if (kNotCalls.contains(name) || builtinType(name)) return false;
    return i == 0 || !identifierChar(tokens[i - 1][0]) || kBeforeExpressions.contains(tokens[i - 1]);
}

}  // namespace

MacroExpansion boundMacroExpansion(const std::string& source) {
    Measure measure;
    MacroExpansion out;
    for (const auto& [line, number] : logicalLines(source)) {
        size_t at = line.find_first_not_of(" \t\r\f\v");
        if (at != std::string::npos && line[at] == '#') {
            TokenList directive = tokenize(line, at + 1);
            if (!directive.empty() && directive[0] == "define") define(measure, line, line.find("define", at) + 6);
            if (directive.size() > 1 && directive[0] == "undef") {
                measure.macros.erase(directive[1]);
                for (auto& [name, other] : measure.macros) other.size.reset();
            }
            continue;
        }
        TokenList tokens = tokenize(line);
        out.tokens += measure.size(tokens, 0, tokens.size(), {}, 0).c;
        if (out.line == 0 && !(out.tokens <= kMaxExpandedTokens)) out.line = number;
        for (size_t i = 0; i + 1 < tokens.size(); ++i) out.calls += isCall(tokens, i);
        if (out.callsLine == 0 && out.calls > kMaxTemplateCalls) out.callsLine = number;
    }
    return out;
}

}  // namespace hexc
