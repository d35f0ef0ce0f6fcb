#pragma once
// The library code a shader reaches: each piece (codegen/pieces.h) the generated functions and the template use, once,
// in the general form or in the forms the slots' settings make of it (codegen/specialise.h).
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "codegen/specialise.h"

namespace hexc {

// What a reference to a library piece becomes: its name, and the positions of the arguments its calls drop.
struct PieceName {
    std::string name;
    std::vector<size_t> dropped;
};

class Assembly {
public:
    // `text` (generated code) with its references to the library renamed to the forms `settings` make of the pieces (the
    // general ones without settings), which are then part of the assembly. With settings, which then give every field
    // of HexcLattice and HexcBlend, a piece that takes them becomes `<piece>_<slot>` (shared with the slots that make
    // the same of it) without its `l` and `b` parameters: calls to it drop those arguments.
    std::string use(const std::string& text, const Settings* settings, const std::string& slot);

    // The pieces used, in library order, each form after a `#line` to where its text is in the library.
    std::string text() const;

private:
    struct Form {
        PieceName name;
        std::string key;  // its text before its own renaming, which tells forms apart
        std::vector<SourceLine> lines;
    };

    PieceName form(size_t piece, const Settings* settings, const std::string& slot);
    void useGeneral(size_t piece);
    std::vector<SourceLine> renamed(const std::vector<SourceLine>& lines, size_t self, const Settings* settings, const std::string& slot);

    std::map<size_t, bool> general_;                             // pieces used as they are
    std::map<size_t, std::vector<Form>> forms_;                  // and specialised
    std::map<std::pair<size_t, std::string>, PieceName> names_;  // (piece, slot) -> what it is called
};

}  // namespace hexc
