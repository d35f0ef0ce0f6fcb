#pragma once
// nlohmann::json keeps no source positions, so this scanner re-reads a document that nlohmann has
// already accepted and records where every value and every object key starts, keyed by JSON pointer.
// It also finds duplicate keys, which nlohmann silently merges. Linear in the text's size; recursion and the
// pointers it stores are bounded by kMaxJsonDepth, which the text must respect (check with excessiveNesting).
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hexc {

// Materials and scenes nest 5 levels deep; 32 leaves room and bounds the locator's recursion and memory.
constexpr int kMaxJsonDepth = 32;

// The offset of the first `[` or `{` that opens a level deeper than kMaxJsonDepth, if any (strings skipped).
std::optional<size_t> excessiveNesting(std::string_view text);

// A UTF-8 byte order mark at the start of the text takes no column: positions count from after it.
size_t byteOrderMarkSize(std::string_view text);

struct TextPos {
    int line = 1, col = 1;
};

class JsonLocator {
public:
    explicit JsonLocator(std::string_view text);

    // Start of the value at `pointer`; of the nearest located ancestor when the pointer is not in the text.
    TextPos value(const std::string& pointer) const;
    // Start of the key that names the member at `pointer` (the value's position for array elements).
    TextPos key(const std::string& pointer) const;

    struct Duplicate {
        std::string pointer;
        TextPos first, second;
    };
    const std::vector<Duplicate>& duplicates() const { return duplicates_; }

    // Byte offsets of the value at `pointer`, [begin, end), and of the key naming it (objects' members only); nullopt
    // when the pointer is not in the text. For rewriting a document while keeping what did not change (json_text.h).
    struct Span {
        size_t begin = 0, end = 0;
    };
    std::optional<Span> valueSpan(const std::string& pointer) const;
    std::optional<size_t> keyOffset(const std::string& pointer) const;

private:
    void parseValue(const std::string& pointer);
    void parseString();
    void skipSpace();
    TextPos here();

    std::string_view text_;  // must outlive the locator
    size_t pos_ = 0;
    // here() advances from the last position it reported, so locating every value is linear even when the
    // whole document is one line.
    size_t scanned_ = 0;
    TextPos scannedPos_;
    // One entry a value and one a key (a document may hold millions of values): where each starts, and its bytes.
    struct Value {
        TextPos pos;
        Span span;
    };
    struct Key {
        TextPos pos;
        size_t offset = 0;
    };
    std::map<std::string, Value> values_;
    std::map<std::string, Key> keys_;
    std::vector<Duplicate> duplicates_;
};

// 1-based line and column (in characters) of a byte offset; works on any text, valid JSON or not.
TextPos textPosition(std::string_view text, size_t offset);

// textPosition for many offsets in any order: built once per document (linear), each look-up a binary search over the
// line starts and a count of at most kStride bytes, so a document with a diagnostic on every line stays linear.
class LineIndex {
public:
    explicit LineIndex(std::string_view text);
    TextPos at(size_t offset) const;

private:
    static constexpr size_t kStride = 256;
    size_t charsBefore(size_t offset) const;  // characters (not UTF-8 continuation bytes) in [bom, offset)

    std::string_view text_;            // must outlive the index
    size_t bom_;                       // byteOrderMarkSize
    std::vector<size_t> lineStarts_;   // byte offset of each line's first byte
    std::vector<size_t> checkpoints_;  // charsBefore(bom_ + k * kStride)
};

// The byte offset of each attribute name in the XML start tag at `tagStart` (for the MaterialX reader, which pugixml
// gives only element offsets); read once per element, however many of its attributes are reported.
std::map<std::string, size_t, std::less<>> xmlAttributeOffsets(std::string_view text, size_t tagStart);

// "/a/b" + "c~d/e" -> "/a/b/c~0d~1e"
std::string pointerAppend(const std::string& pointer, std::string_view token);
std::string pointerAppend(const std::string& pointer, size_t index);

}  // namespace hexc
