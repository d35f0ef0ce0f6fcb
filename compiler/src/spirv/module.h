#pragma once
// A SPIR-V module as a list of instructions, for the word-level rewrites hexc does after spirv-opt (combined.h,
// share.h).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hexc/diagnostics.h"

namespace hexc::spirv {

struct Instruction {
    std::vector<uint32_t> words;
    std::vector<uint16_t> ids;  // word offsets of the id operands (result id excluded)
    uint16_t opcode() const { return uint16_t(words[0] & 0xffff); }
};

struct Module {
    std::vector<uint32_t> header;
    std::vector<Instruction> code;
};

// An error naming `templateName` (HX209) when glslang's module holds more functions or calls than spirv-opt's inliner
// is given: its work grows with functions times calls (10,000 one-line functions take over a minute), and hexc's own
// code for the largest material stays far below the bounds. nullopt when within them.
std::optional<Diagnostic> beyondOptimiserBound(const std::vector<uint32_t>& words, const std::string& templateName);

// std::runtime_error naming `what` (the rewrite) when the module does not parse: a hexc bug.
Module parse(const std::vector<uint32_t>& words, const std::string& what);

}  // namespace hexc::spirv
