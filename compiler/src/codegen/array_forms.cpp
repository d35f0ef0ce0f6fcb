#include "codegen/array_forms.h"

#include <stdexcept>

#include "common/text.h"

namespace hexc {
namespace {

bool wordAt(std::string_view code, size_t at, std::string_view word) {
    return code.substr(at, word.size()) == word && (at == 0 || !isIdentifierChar(code[at - 1])) &&
           (at + word.size() == code.size() || !isIdentifierChar(code[at + word.size()]));
}

// The name of the call whose first argument starts at `at` ("textureGrad" in `textureGrad(sampler2D(...`).
std::string callAround(std::string_view code, size_t at) {
    size_t open = code.find_last_not_of(' ', at - 1);
    if (open == std::string_view::npos || code[open] != '(') return {};
    size_t begin = open;
    while (begin > 0 && isIdentifierChar(code[begin - 1])) --begin;
    return std::string(code.substr(begin, open - begin));
}

// The end of the argument that starts at `at`: its top-level `,` or the call's `)`.
size_t argumentEnd(std::string_view code, size_t at) {
    for (size_t i = at; i < code.size(); ++i) {
        if (code[i] == '(' || code[i] == '[')
            i = closingBracket(code, i) - 1;
        else if (code[i] == ',' || code[i] == ')')
            return i;
    }
    throw std::logic_error("hexc library: a sampling call beyond its line");
}

std::string inArray(std::string code, const std::string& layer) {
    for (size_t at = code.size(); at-- > 0;) {
        if (wordAt(code, at, "texture2D")) code.insert(at + 9, "Array");
        if (!wordAt(code, at, "sampler2D") || at + 9 >= code.size() || code[at + 9] != '(') continue;
        const size_t afterSampler = closingBracket(code, at + 9);
        const std::string call = callAround(code, at);
        if (call == "texture" || call == "textureGrad" || call == "textureLod") {
            const size_t begin = code.find_first_not_of(' ', code.find(',', afterSampler) + 1), end = argumentEnd(code, begin);
            code.replace(begin, end - begin, "vec3(" + code.substr(begin, end - begin) + ", " + layer + ")");
        } else if (call != "textureSize") {
            throw std::logic_error("hexc library: no array form of `" + call + "`");
        }
        code.insert(at + 9, "Array");
    }
    return code;
}

}  // namespace

std::vector<SourceLine> inArray(const std::vector<SourceLine>& lines, const std::string& layer) {
    std::vector<SourceLine> out = lines;
    for (SourceLine& l : out) {
        const size_t code = codeOf(l.text).size();
        l.text = inArray(l.text.substr(0, code), layer) + l.text.substr(code);
    }
    return out;
}

}  // namespace hexc
