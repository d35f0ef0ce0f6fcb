#pragma once
// nlohmann::json keeps no source positions, so this scanner re-reads a document that nlohmann has
// already accepted and records where every value and every object key starts, found by JSON pointer.
// It also finds duplicate keys, which nlohmann silently merges. Linear in the text's size; recursion is bounded by
// kMaxJsonDepth, which the text must respect (check with excessiveNesting). Memory: 20 bytes a value (offsets only; a
// line and column are counted when asked for), allocated once, plus 4 bytes a container while parsing; a value takes at
// least two bytes of text (itself and a comma or a bracket), so at most 10 times the text's size (12 while parsing), and
// 2 MB for a document parseJson accepts (at most kMaxJsonValues values).
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hexc {

// Materials and scenes nest 5 levels deep; 32 leaves room and bounds the locator's recursion and memory.
constexpr int kMaxJsonDepth = 32;
// A material of 16 slots holds about 600 values. nlohmann's document costs 16 to 130 bytes a value (a small array's
// vector, an object member's key and tree node) and the locator 20: more than 8 times the text for any text of small
// values (`1,` is 2 bytes). Bounding the count bounds both, whatever the document's shape: about 15 MB at most.
constexpr size_t kMaxJsonValues = 100000;

// Where a JSON text first passes a bound (strings skipped): the `[` or `{` that opens a level deeper than
// kMaxJsonDepth, or the start of the value after the first `maxValues`.
struct JsonExcess {
    size_t offset;
    bool tooDeep;  // else too many values
};
std::optional<JsonExcess> excessiveShape(std::string_view text, size_t maxValues);
// The offset of the first `[` or `{` that opens a level deeper than kMaxJsonDepth, if any (strings skipped).
std::optional<size_t> excessiveNesting(std::string_view text);

// A UTF-8 byte order mark at the start of the text takes no column: positions count from after it.
size_t byteOrderMarkSize(std::string_view text);

struct TextPos {
    int line = 1, col = 1;
};

// textPosition for many offsets in any order: built once per document (linear), each look-up a binary search over the
// line starts and a count of at most kStride bytes, so a document with a diagnostic on every line stays linear.
class LineIndex {
public:
    explicit LineIndex(std::string_view text);
    TextPos at(size_t offset) const;

private:
    static constexpr size_t kStride = 256;
    size_t charsBefore(size_t offset) const;  // characters (not UTF-8 continuation bytes) in [bom, offset)

    std::string_view text_;  // must outlive the index
    size_t bom_;             // byteOrderMarkSize
    // 32 bits: hexc reads no text of 4 GiB (the input limit is 64 MiB), and a text of one-byte lines takes 4 bytes a line.
    std::vector<uint32_t> lineStarts_;   // byte offset of each line's first byte
    std::vector<uint32_t> checkpoints_;  // charsBefore(bom_ + k * kStride)
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
    // One value: its bytes [begin, end), the offset of the key naming it (kNoKey for array elements and the root), and
    // its children, which are contiguous: nodes_[first, first + count), an object's sorted by key (document order
    // among equal keys). Offsets fit 32 bits: hexc reads no document of 4 GiB (a larger text is not located).
    struct Node {
        uint32_t begin = 0, end = 0, key = kNoKey, first = 0, count = 0;
    };
    static constexpr uint32_t kNoKey = UINT32_MAX;
    struct Found {
        uint32_t node;    // the value at the pointer, or its nearest ancestor in the text
        bool whole;       // the pointer's every token was found
        uint32_t parent;  // node's parent (when node is not the root)
    };

    void parseValue(uint32_t slot, const std::string& pointer);  // into nodes_[slot]
    void parseMember(uint32_t slot, const std::string& object);
    void sortMembers(const Node& object, const std::string& pointer);
    void parseString();
    void skipSpace();
    std::string_view keyAt(uint32_t offset, std::string& scratch) const;
    std::optional<uint32_t> child(const Node& parent, std::string_view token) const;
    std::optional<Found> find(const std::string& pointer) const;

    std::string_view text_;  // must outlive the locator
    size_t pos_ = 0;
    LineIndex lines_;
    std::vector<Node> nodes_;  // the root first (when the text holds a value)
    // While parsing: each container's number of children in the order they open, how many have opened, and the
    // first node no container has taken yet.
    std::vector<uint32_t> childCounts_;
    size_t containersRead_ = 0;
    uint32_t nextFree_ = 1;
    struct DuplicateAt {
        std::string pointer;
        uint32_t first, second;  // the keys' offsets
    };
    std::vector<DuplicateAt> duplicateOffsets_;  // while parsing
    std::vector<Duplicate> duplicates_;
};

// 1-based line and column (in characters) of a byte offset; works on any text, valid JSON or not.
TextPos textPosition(std::string_view text, size_t offset);

// The byte offset of each attribute name in the XML start tag at `tagStart` (for the MaterialX reader, which pugixml
// gives only element offsets); read once per element, however many of its attributes are reported.
std::map<std::string, size_t, std::less<>> xmlAttributeOffsets(std::string_view text, size_t tagStart);

// "/a/b" + "c~d/e" -> "/a/b/c~0d~1e"
std::string pointerAppend(const std::string& pointer, std::string_view token);
std::string pointerAppend(const std::string& pointer, size_t index);

}  // namespace hexc
