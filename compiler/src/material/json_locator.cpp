#include "material/json_locator.h"

#include <algorithm>

#include <nlohmann/json.hpp>

namespace hexc {

std::string pointerAppend(const std::string& pointer, std::string_view token) {
    std::string out = pointer + "/";
    for (char c : token) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

std::string pointerAppend(const std::string& pointer, size_t index) { return pointer + "/" + std::to_string(index); }

namespace {

// Advances p over text[from, to).
void advance(TextPos& p, std::string_view text, size_t from, size_t to) {
    for (size_t i = from; i < to && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++p.line;
            p.col = 1;
        } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
            ++p.col;  // columns count characters, not UTF-8 continuation bytes
        }
    }
}

}  // namespace

size_t byteOrderMarkSize(std::string_view text) { return text.starts_with("\xEF\xBB\xBF") ? 3 : 0; }

TextPos textPosition(std::string_view text, size_t offset) {
    TextPos p;
    advance(p, text, byteOrderMarkSize(text), offset);
    return p;
}

LineIndex::LineIndex(std::string_view text) : text_(text), bom_(byteOrderMarkSize(text)), lineStarts_{bom_} {
    size_t chars = 0;
    for (size_t i = bom_; i < text.size(); ++i) {
        if ((i - bom_) % kStride == 0) checkpoints_.push_back(chars);
        if (text[i] == '\n') lineStarts_.push_back(i + 1);
        chars += (static_cast<unsigned char>(text[i]) & 0xC0) != 0x80;
    }
    checkpoints_.push_back(chars);  // for offsets at the end
}

size_t LineIndex::charsBefore(size_t offset) const {
    const size_t k = std::min((offset - bom_) / kStride, checkpoints_.size() - 1);
    size_t chars = checkpoints_[k];
    for (size_t i = bom_ + k * kStride; i < offset; ++i) chars += (static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80;
    return chars;
}

TextPos LineIndex::at(size_t offset) const {
    offset = std::clamp(offset, bom_, std::max(bom_, text_.size()));
    const size_t line = size_t(std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset) - lineStarts_.begin()) - 1;
    return {int(line + 1), int(charsBefore(offset) - charsBefore(lineStarts_[line]) + 1)};
}

std::map<std::string, size_t, std::less<>> xmlAttributeOffsets(std::string_view text, size_t tagStart) {
    std::map<std::string, size_t, std::less<>> offsets;
    const size_t end = std::min(text.find('>', tagStart), text.size());
    auto space = [&](size_t i) { return text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n'; };
    for (size_t at = tagStart; at < end;) {  // name = "value" or 'value', the name being what stands before the `=`
        const size_t eq = text.find('=', at);
        if (eq >= end) break;
        size_t nameEnd = eq, nameStart;
        while (nameEnd > at && space(nameEnd - 1)) --nameEnd;
        for (nameStart = nameEnd; nameStart > at && !space(nameStart - 1);) --nameStart;
        offsets.emplace(std::string(text.substr(nameStart, nameEnd - nameStart)), nameStart);
        const size_t quote = text.find_first_of("\"'", eq), close = quote >= end ? end : text.find(text[quote], quote + 1);
        at = close >= end ? end : close + 1;
    }
    return offsets;
}

std::optional<size_t> excessiveNesting(std::string_view text) {
    int depth = 0;
    bool inString = false;
    for (size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth) return i;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return std::nullopt;
}

JsonLocator::JsonLocator(std::string_view text) : text_(text), pos_(byteOrderMarkSize(text)), scanned_(pos_) {
    skipSpace();
    if (pos_ < text_.size()) parseValue("");
}

TextPos JsonLocator::here() {
    advance(scannedPos_, text_, scanned_, pos_);  // pos_ only moves forward
    scanned_ = pos_;
    return scannedPos_;
}

TextPos JsonLocator::value(const std::string& pointer) const {
    std::string p = pointer;
    for (;;) {
        if (auto it = values_.find(p); it != values_.end()) return it->second.pos;
        if (p.empty()) return {1, 1};
        p.erase(p.rfind('/'));
    }
}

std::optional<JsonLocator::Span> JsonLocator::valueSpan(const std::string& pointer) const {
    if (auto it = values_.find(pointer); it != values_.end()) return it->second.span;
    return std::nullopt;
}

std::optional<size_t> JsonLocator::keyOffset(const std::string& pointer) const {
    if (auto it = keys_.find(pointer); it != keys_.end()) return it->second.offset;
    return std::nullopt;
}

TextPos JsonLocator::key(const std::string& pointer) const {
    if (auto it = keys_.find(pointer); it != keys_.end()) return it->second.pos;
    return value(pointer);
}

void JsonLocator::skipSpace() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\n' || text_[pos_] == '\r')) ++pos_;
}

void JsonLocator::parseString() {
    ++pos_;  // opening quote
    while (pos_ < text_.size() && text_[pos_] != '"') pos_ += text_[pos_] == '\\' ? 2 : 1;
    ++pos_;  // closing quote
}

namespace {
// A key as nlohmann reads it: the text between the quotes, its escapes decoded ("n\\u0061me" is "name"), so that
// pointers match the parsed document's. Escapes are rare in material keys: only those keys are decoded.
std::string keyText(std::string_view quoted) {
    if (quoted.find('\\') == std::string_view::npos) return std::string(quoted.substr(1, quoted.size() - 2));
    return nlohmann::json::parse(quoted).get<std::string>();  // the document already parsed, so this string does
}
}  // namespace

void JsonLocator::parseValue(const std::string& pointer) {
    Value& located = values_.emplace(pointer, Value{here(), {pos_, pos_}}).first->second;  // no insertion moves it
    char c = text_[pos_];
    if (c == '{') {
        ++pos_;
        skipSpace();
        while (pos_ < text_.size() && text_[pos_] != '}') {
            TextPos keyPos = here();
            size_t start = pos_;
            parseString();
            std::string key = keyText(text_.substr(start, pos_ - start));
            std::string child = pointerAppend(pointer, key);
            if (auto [it, added] = keys_.try_emplace(child, Key{keyPos, start}); !added) {
                duplicates_.push_back({child, it->second.pos, keyPos});
                it->second.offset = start;  // the last one's text, as nlohmann keeps its value
            }
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
    located.span.end = std::min(pos_, text_.size());
}

}  // namespace hexc
