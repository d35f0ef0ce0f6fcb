#pragma once
// The hex-tiling library (templates/library/hextiling/, materialx.glsl) as pieces: each top-level constant, struct
// and function (overloads together), so that codegen emits only those a shader reaches, and each function in the
// form a slot's settings make of it (codegen/specialise.h).
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace hexc {

// One line of library code and its line number in its file (for `#line`).
struct SourceLine {
    int number = 0;
    std::string text;
    bool operator==(const SourceLine&) const = default;
};

struct Piece {
    std::string name;                     // hexcColor, HexcTiles, hexcPi
    std::string file;                     // as `#line` names it: "hexc/hextiling.glsl"
    std::vector<SourceLine> lines;        // the comment right above it, then its code
    bool lattice = false, blend = false;  // it takes the settings `HexcLattice l`, `HexcBlend b`
    std::vector<size_t> uses;             // the pieces its code names (indexes into Library::pieces)
};

struct Library {
    std::vector<Piece> pieces;  // in file order: a piece only uses those before it
    std::map<std::string, size_t, std::less<>> byName;
    // The fields of the settings structs (HexcLattice, HexcBlend) with the values their neutral constructors
    // (hexcLattice(), hexcBlend()) give, in field order.
    std::map<std::string, std::vector<std::pair<std::string, std::string>>> neutral;
};

// hextiling.glsl then materialx.glsl, parsed once per process.
const Library& library();

// `text` without its `//` comments: the code whose identifiers count.
std::string_view codeOf(std::string_view text);

// The identifiers of `text` (comments included), in order.
std::vector<std::string_view> identifiers(std::string_view text);

// The index just past the bracket that closes the one at `open` ('(' or '['), or npos.
size_t closingBracket(std::string_view text, size_t open);

// A comma-separated list (arguments, parameters) split at its top-level commas, each item trimmed.
std::vector<std::string> splitList(std::string_view list);

}  // namespace hexc
