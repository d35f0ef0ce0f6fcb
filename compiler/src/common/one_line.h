#pragma once
// Names from the user's file system written into text another tool parses (a shader's banner, a `#line` name, an XML
// comment): they stay on their line.
#include <string>
#include <string_view>

namespace hexc {

// `text` (a file name, a path) as one line of printable text, for a comment or a quoted name in a file another tool
// parses: a backslash doubled, each control character written as a C escape (`\n`, `\r`, `\t`, `\xHH`), and the
// Unicode line ends JavaScript also ends a comment at (NEL, U+2028, U+2029) as `\uXXXX`. A line break would end a `//`
// comment and make the rest of the name code; escaped, any legal name stays readable.
inline std::string oneLine(std::string_view text) {
    static constexpr const char* kHex = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size(); ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        const std::string_view rest = text.substr(i);
        if (byte == '\\')
            out += "\\\\";
        else if (byte == '\n')
            out += "\\n";
        else if (byte == '\r')
            out += "\\r";
        else if (byte == '\t')
            out += "\\t";
        else if (byte < 0x20 || byte == 0x7f)
            out += std::string("\\x") + kHex[byte >> 4] + kHex[byte & 15];
        else if (rest.starts_with("\xC2\x85"))
            out += "\\u0085", i += 1;
        else if (rest.starts_with("\xE2\x80\xA8") || rest.starts_with("\xE2\x80\xA9"))
            out += std::string("\\u202") + kHex[8 + (text[i + 2] & 1)], i += 2;
        else
            out += text[i];
    }
    return out;
}

}  // namespace hexc
