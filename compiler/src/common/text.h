#pragma once
// Plain searches in source text. hexc uses no regular expressions (the standard library's <regex>): they are slow to
// build, and building one on several threads races on libstdc++'s shared ctype cache (ThreadSanitizer reports it
// when a scene compiles in parallel).
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

}  // namespace hexc
