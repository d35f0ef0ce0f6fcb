#pragma once
// A library function with a slot's fixed settings folded in, at the source: the branches they decide keep only the
// path taken, so glslang and spirv-opt see only the code the slot runs (the general function, for any settings, is
// the same text left as it is).
#include <map>
#include <string>
#include <vector>

#include "codegen/pieces.h"

namespace hexc {

// The settings a slot fixes, by how the library reads them: "l.rotate" -> "true", "b.exponentInt" -> "7". The library
// names its HexcLattice parameter `l` and its HexcBlend parameter `b` (templates/library/hextiling/).
using Settings = std::map<std::string, std::string>;

// `lines` with `settings` folded in: an `if (c) {...} else {...}` or `if (c) statement;` whose condition c the settings
// decide keeps the branch taken (its body one level less indented), a `... = c ? x : y;` or `return c ? x : y;` keeps x
// or y, and every other read of a setting becomes its value. Comments are left as they are.
std::vector<SourceLine> specialise(const std::vector<SourceLine>& lines, const Settings& settings);

// A condition under `settings`: `taken` 1 true, 0 false, -1 when it reads anything else (a run-time value); then `rest`
// is the condition without what the settings decide in it (`!false || f.x` -> `f.x`), or empty when it is not a
// condition read here (arithmetic, a call, an index).
struct Decision {
    int taken = -1;
    std::string rest;
};
Decision decide(std::string_view condition, const Settings& settings);

}  // namespace hexc
