#include "material/json_locator.h"

#include <algorithm>

namespace hexc {

std::string pointerAppend(const std::string& pointer, std::string_view token) {
    std::string out = pointer + "/";
    for (char c : token) {
        if (c == '~') out += "~0";
        else if (c == '/') out += "~1";
        else out += c;
    }
    return out;
}

std::string pointerAppend(const std::string& pointer, size_t index) {
    return pointer + "/" + std::to_string(index);
}

TextPos textPosition(std::string_view text, size_t offset) {
    TextPos p;
    for (size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++p.line;
            p.col = 1;
        } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
            ++p.col;  // columns count characters, not UTF-8 continuation bytes
        }
    }
    return p;
}

JsonLocator::JsonLocator(std::string_view text) : text_(text) {
    lineStarts_.push_back(0);
    for (size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') lineStarts_.push_back(i + 1);
    skipSpace();
    if (pos_ < text_.size()) parseValue("");
}

TextPos JsonLocator::here() const {
    // Only the current line is scanned for the column, so locating every value stays linear.
    size_t line = size_t(std::upper_bound(lineStarts_.begin(), lineStarts_.end(), pos_) - lineStarts_.begin());
    size_t start = lineStarts_[line - 1];
    TextPos p = textPosition(text_.substr(start), pos_ - start);
    return {int(line), p.col};
}

TextPos JsonLocator::value(const std::string& pointer) const {
    std::string p = pointer;
    for (;;) {
        if (auto it = values_.find(p); it != values_.end()) return it->second;
        if (p.empty()) return {1, 1};
        p.erase(p.rfind('/'));
    }
}

TextPos JsonLocator::key(const std::string& pointer) const {
    if (auto it = keys_.find(pointer); it != keys_.end()) return it->second;
    return value(pointer);
}

void JsonLocator::skipSpace() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\n' || text_[pos_] == '\r'))
        ++pos_;
}

void JsonLocator::parseString() {
    ++pos_;  // opening quote
    while (pos_ < text_.size() && text_[pos_] != '"') pos_ += text_[pos_] == '\\' ? 2 : 1;
    ++pos_;  // closing quote
}

void JsonLocator::parseValue(const std::string& pointer) {
    values_.emplace(pointer, here());
    char c = text_[pos_];
    if (c == '{') {
        ++pos_;
        skipSpace();
        while (pos_ < text_.size() && text_[pos_] != '}') {
            TextPos keyPos = here();
            size_t start = pos_;
            parseString();
            // The raw key between the quotes; escapes are rare in material keys and kept as written.
            std::string key(text_.substr(start + 1, pos_ - start - 2));
            std::string child = pointerAppend(pointer, key);
            if (auto it = keys_.find(child); it != keys_.end()) duplicates_.push_back({child, it->second, keyPos});
            else keys_.emplace(child, keyPos);
            skipSpace();
            ++pos_;  // ':'
            skipSpace();
            values_.erase(child);  // for a duplicate, the last one wins, as in nlohmann
            parseValue(child);
            skipSpace();
            if (text_[pos_] == ',') ++pos_;
            skipSpace();
        }
        ++pos_;
    } else if (c == '[') {
        ++pos_;
        skipSpace();
        for (size_t i = 0; pos_ < text_.size() && text_[pos_] != ']'; ++i) {
            parseValue(pointerAppend(pointer, i));
            skipSpace();
            if (text_[pos_] == ',') ++pos_;
            skipSpace();
        }
        ++pos_;
    } else if (c == '"') {
        parseString();
    } else {
        // number, true, false, null
        while (pos_ < text_.size() && std::string_view(",]} \t\r\n").find(text_[pos_]) == std::string_view::npos) ++pos_;
    }
}

}  // namespace hexc
