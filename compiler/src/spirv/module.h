#pragma once
// A SPIR-V module as a list of instructions, for the word-level rewrites hexc does after spirv-opt (combined.h,
// share.h).
#include <spirv.hpp>

#include <cstdint>
#include <optional>
#include <map>
#include <string>
#include <vector>

#include "hexc/diagnostics.h"

namespace hexc::spirv {

struct Instruction {
    std::vector<uint32_t> words;
    std::vector<uint16_t> ids;  // word offsets of the id operands (result id excluded)
    spv::Op opcode() const { return spv::Op(words[0] & spv::OpCodeMask); }
    // Each id operand found in `replaced` becomes the id it maps to.
    void replaceIds(const std::map<uint32_t, uint32_t>& replaced);
};

struct Module {
    std::vector<uint32_t> header;
    std::vector<Instruction> code;
    std::map<uint32_t, uint32_t> types = {};  // each result id's type, as parsed (rewrites do not keep it)
    // The module's words: the header, then each instruction's.
    std::vector<uint32_t> words() const;
};

// An error naming `templateName` (HX209) when the functions glslang's module reaches from its entry point make more
// calls than spirv-opt's inliner is given: its work grows with functions times calls (10,000 one-line functions, each
// called once, take over a minute), and hexc's own code for the largest material stays far below the bound; functions
// nothing calls do not count. nullopt when within it.
std::optional<Diagnostic> beyondOptimiserBound(const std::vector<uint32_t>& words, const std::string& templateName);

// std::runtime_error naming `what` (the rewrite) when the module does not parse: a hexc bug.
Module parse(const std::vector<uint32_t>& words, const std::string& what);

// An instruction of `op` from its operands; `ids`: which of them (counted from 0) are ids.
Instruction instruction(spv::Op op, std::vector<uint32_t> operands, std::vector<uint16_t> ids);

// `code` with `added` before its first function, where types, constants and global variables end.
void insertBeforeFunctions(std::vector<Instruction>& code, std::vector<Instruction> added);

// The rewritten module's words; std::runtime_error naming `what` (the rewrite) when they do not validate: a hexc bug.
std::vector<uint32_t> validWords(const Module& m, const std::string& what);

}  // namespace hexc::spirv
