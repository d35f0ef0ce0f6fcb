#pragma once
// Plain searches in source text. hexc uses no regular expressions (the standard library's <regex>): they are slow to
// build, and building one on several threads races on libstdc++'s shared ctype cache (ThreadSanitizer reports it
// when a scene compiles in parallel).
#include <optional>
#include <string>
#include <string_view>

namespace hexc {

inline bool isIdentifierChar(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; }

// True when `word` occurs in `text` with no identifier character either side (regex \bword\b).
inline bool containsWord(std::string_view text, std::string_view word) {
    for (size_t at = text.find(word); at != std::string_view::npos; at = text.find(word, at + 1)) {
        size_t end = at + word.size();
        if ((at == 0 || !isIdentifierChar(text[at - 1])) && (end == text.size() || !isIdentifierChar(text[end]))) return true;
    }
    return false;
}

// `text` without its leading blanks.
inline std::string_view trimmedStart(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    return text;
}

// The number of lines of `text` that read `line`, ignoring trailing blanks and a CR.
inline int countLines(std::string_view text, std::string_view line) {
    int count = 0;
    for (size_t begin = 0; begin <= text.size();) {
        size_t end = text.find('\n', begin);
        if (end == std::string_view::npos) end = text.size();
        std::string_view current = text.substr(begin, end - begin);
        while (!current.empty() && (current.back() == ' ' || current.back() == '\t' || current.back() == '\r')) current.remove_suffix(1);
        count += current == line;
        begin = end + 1;
    }
    return count;
}

// A byte as two hexadecimal digits, for messages.
inline std::string hexByte(char c) {
    const char* digits = "0123456789ABCDEF";
    return {digits[static_cast<unsigned char>(c) >> 4], digits[static_cast<unsigned char>(c) & 15]};
}

// The offset of the first byte that does not begin or continue a well-formed UTF-8 character, if any: text hexc
// carries into JSON (a MaterialX document, a template's comments in the manifest) must be UTF-8.
inline std::optional<size_t> invalidUtf8(std::string_view s) {
    for (size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        const size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 && c >= 0xC2 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E && c <= 0xF4 ? 4 : 0;
        if (n == 0 || i + n > s.size()) return i;
        for (size_t k = 1; k < n; ++k)
            if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return i;
        const unsigned c1 = static_cast<unsigned char>(s[i + 1 < s.size() ? i + 1 : i]);
        if ((c == 0xE0 && c1 < 0xA0) || (c == 0xED && c1 >= 0xA0) || (c == 0xF0 && c1 < 0x90) || (c == 0xF4 && c1 >= 0x90))
            return i;  // overlong, a surrogate, or beyond U+10FFFF
        i += n;
    }
    return std::nullopt;
}

}  // namespace hexc
