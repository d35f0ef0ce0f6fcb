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

LineIndex::LineIndex(std::string_view text)
    : text_(text.substr(0, UINT32_MAX)), bom_(byteOrderMarkSize(text)), lineStarts_{uint32_t(bom_)} {
    uint32_t chars = 0;
    for (size_t i = bom_; i < text_.size(); ++i) {
        if ((i - bom_) % kStride == 0) checkpoints_.push_back(chars);
        if (text_[i] == '\n') lineStarts_.push_back(uint32_t(i + 1));
        chars += (static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80;
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

std::optional<JsonExcess> excessiveShape(std::string_view text, size_t maxValues) {
    bool inObject[kMaxJsonDepth + 1] = {};  // at each open level: an object, where a key follows `{` and `,`
    int depth = 0;
    size_t values = 0;
    char last = 0;  // the last character read outside strings and space; '"' for a whole string
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') continue;
        const bool afterSeparator = last == 0 || last == '[' || last == ':' || (last == ',' && !inObject[depth]);
        if (afterSeparator && c != ']' && c != '}' && c != ',' && ++values > maxValues) return JsonExcess{i, false};
        if (c == '"') {
            for (++i; i < text.size() && text[i] != '"';) i += text[i] == '\\' ? 2 : 1;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth) return JsonExcess{i, true};
            inObject[depth] = c == '{';
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
        last = c;
    }
    return std::nullopt;
}

std::optional<size_t> excessiveNesting(std::string_view text) {
    const std::optional<JsonExcess> e = excessiveShape(text, SIZE_MAX);
    return e ? std::optional(e->offset) : std::nullopt;
}

namespace {

// The number of children of each array and object of a JSON text, in the order they open: a non-empty container has
// one more than the commas at its level. Strings are skipped; the text is one nlohmann accepted.
std::vector<uint32_t> childCounts(std::string_view text) {
    std::vector<uint32_t> counts;
    std::vector<size_t> open;  // indexes into counts, innermost last
    bool opened = false;       // a container opened and nothing but space read since
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') continue;
        if (opened && c != ']' && c != '}') counts[open.back()] = 1;
        opened = false;
        if (c == '"') {
            for (++i; i < text.size() && text[i] != '"';) i += text[i] == '\\' ? 2 : 1;
        } else if (c == '[' || c == '{') {
            open.push_back(counts.size());
            counts.push_back(0);
            opened = true;
        } else if ((c == ']' || c == '}') && !open.empty()) {
            open.pop_back();
        } else if (c == ',' && !open.empty()) {
            ++counts[open.back()];
        }
    }
    return counts;
}

}  // namespace

JsonLocator::JsonLocator(std::string_view text) : text_(text), pos_(byteOrderMarkSize(text)), lines_(text) {
    if (text_.size() >= UINT32_MAX) return;  // beyond 32-bit offsets: nothing located (every position is 1:1)
    skipSpace();
    if (pos_ >= text_.size()) return;
    // Every value's node in place from the start: the root, then each container's children where it opens.
    childCounts_ = childCounts(text_.substr(pos_));
    size_t values = 1;
    for (uint32_t n : childCounts_) values += n;
    nodes_.resize(values);
    parseValue(0, "");
    childCounts_ = {};
    // In document order of the second key, as nlohmann meets them.
    std::stable_sort(duplicateOffsets_.begin(), duplicateOffsets_.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    for (const DuplicateAt& d : duplicateOffsets_) duplicates_.push_back({d.pointer, lines_.at(d.first), lines_.at(d.second)});
    duplicateOffsets_ = {};
}

void JsonLocator::skipSpace() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\n' || text_[pos_] == '\r')) ++pos_;
}

void JsonLocator::parseString() {
    ++pos_;  // opening quote
    while (pos_ < text_.size() && text_[pos_] != '"') pos_ += text_[pos_] == '\\' ? 2 : 1;
    ++pos_;  // closing quote
}

// The key whose opening quote is at `offset` as nlohmann reads it: the text between the quotes, its escapes decoded
// ("n\\u0061me" is "name") into `scratch`, so that pointers match the parsed document's. Escapes are rare in
// material keys: only those keys are decoded.
std::string_view JsonLocator::keyAt(uint32_t offset, std::string& scratch) const {
    size_t end = size_t(offset) + 1;
    while (end < text_.size() && text_[end] != '"') end += text_[end] == '\\' ? 2 : 1;
    const std::string_view quoted = text_.substr(offset, end + 1 - offset);
    if (quoted.find('\\') == std::string_view::npos) return quoted.substr(1, quoted.size() - 2);
    scratch = nlohmann::json::parse(quoted).get<std::string>();  // the document already parsed, so this string does
    return scratch;
}

void JsonLocator::parseValue(uint32_t slot, const std::string& pointer) {
    const uint32_t begin = uint32_t(pos_);
    const char c = text_[pos_];
    uint32_t first = 0, count = 0;
    if (c == '{' || c == '[') {
        count = childCounts_[containersRead_++];
        first = nextFree_, nextFree_ += count;
        ++pos_;
        skipSpace();
        for (uint32_t i = 0; i < count && pos_ < text_.size() && text_[pos_] != (c == '{' ? '}' : ']'); ++i) {
            if (c == '{')
                parseMember(first + i, pointer);
            else
                parseValue(first + i, pointerAppend(pointer, i));
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
    Node& node = nodes_[slot];
    node.begin = begin, node.end = uint32_t(std::min(pos_, text_.size())), node.first = first, node.count = count;
    if (c == '{') sortMembers(node, pointer);
}

void JsonLocator::parseMember(uint32_t slot, const std::string& object) {
    const size_t keyStart = pos_;
    parseString();
    skipSpace();
    ++pos_;  // ':'
    skipSpace();
    std::string scratch;
    parseValue(slot, pointerAppend(object, keyAt(uint32_t(keyStart), scratch)));
    nodes_[slot].key = uint32_t(keyStart);
}

// An object's members sorted by key, document order kept among equal keys (the last of them is the one nlohmann
// keeps), and its duplicate keys noted: each later one against the first.
void JsonLocator::sortMembers(const Node& object, const std::string& pointer) {
    const auto members = nodes_.begin() + std::ptrdiff_t(object.first), end = members + std::ptrdiff_t(object.count);
    std::string a, b;
    std::stable_sort(members, end, [&](const Node& x, const Node& y) { return keyAt(x.key, a) < keyAt(y.key, b); });
    for (auto run = members; run != end;) {
        auto next = run + 1;
        for (; next != end && keyAt(next->key, a) == keyAt(run->key, b); ++next)
            duplicateOffsets_.push_back({pointerAppend(pointer, keyAt(run->key, b)), run->key, next->key});
        run = next;
    }
}

std::optional<uint32_t> JsonLocator::child(const Node& parent, std::string_view token) const {
    const auto members = nodes_.begin() + std::ptrdiff_t(parent.first), end = members + std::ptrdiff_t(parent.count);
    if (text_[parent.begin] == '[') {
        size_t index = 0;
        if (token.empty() || token.size() > 9 || (token.size() > 1 && token[0] == '0') ||
            !std::all_of(token.begin(), token.end(), [](char d) { return d >= '0' && d <= '9'; }))
            return std::nullopt;
        for (char d : token) index = index * 10 + size_t(d - '0');
        return index < parent.count ? std::optional(uint32_t(parent.first + index)) : std::nullopt;
    }
    if (text_[parent.begin] != '{') return std::nullopt;
    std::string scratch;
    const auto after = std::upper_bound(members, end, token, [&](std::string_view t, const Node& n) { return t < keyAt(n.key, scratch); });
    if (after == members || keyAt((after - 1)->key, scratch) != token) return std::nullopt;
    return uint32_t(after - 1 - nodes_.begin());  // the last of equal keys, as nlohmann keeps it
}

// Walks `pointer`'s tokens ("~1" is "/", "~0" is "~") down from the root as far as the text holds them.
std::optional<JsonLocator::Found> JsonLocator::find(const std::string& pointer) const {
    if (nodes_.empty()) return std::nullopt;
    Found found{0, true, 0};
    for (size_t at = 0; at < pointer.size();) {
        const size_t next = std::min(pointer.find('/', at + 1), pointer.size());
        std::string token;
        for (size_t i = at + 1; i < next; ++i) {
            const bool escape = pointer[i] == '~' && i + 1 < next;
            token += escape ? (pointer[i + 1] == '1' ? '/' : '~') : pointer[i];
            i += escape;
        }
        const std::optional<uint32_t> c = child(nodes_[found.node], token);
        if (!c) return Found{found.node, false, found.parent};
        found.parent = found.node, found.node = *c, at = next;
    }
    return found;
}

TextPos JsonLocator::value(const std::string& pointer) const {
    const std::optional<Found> f = find(pointer);
    return f ? lines_.at(nodes_[f->node].begin) : TextPos{};
}

TextPos JsonLocator::key(const std::string& pointer) const {
    const std::optional<Found> f = find(pointer);
    if (!f || !f->whole || nodes_[f->node].key == kNoKey) return value(pointer);
    // The first of equal keys: where a duplicated member was first named.
    uint32_t node = f->node;
    std::string a, b;
    while (node > nodes_[f->parent].first && keyAt(nodes_[node - 1].key, a) == keyAt(nodes_[node].key, b)) --node;
    return lines_.at(nodes_[node].key);
}

std::optional<JsonLocator::Span> JsonLocator::valueSpan(const std::string& pointer) const {
    const std::optional<Found> f = find(pointer);
    if (!f || !f->whole) return std::nullopt;
    return Span{nodes_[f->node].begin, nodes_[f->node].end};
}

std::optional<size_t> JsonLocator::keyOffset(const std::string& pointer) const {
    const std::optional<Found> f = find(pointer);
    if (!f || !f->whole || nodes_[f->node].key == kNoKey) return std::nullopt;
    return nodes_[f->node].key;
}

}  // namespace hexc
