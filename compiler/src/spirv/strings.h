#pragma once
// Literal strings of a SPIR-V module (names, the entry point's, debug sources) rewritten in place.
#include <cstdint>
#include <string_view>
#include <vector>

namespace hexc {

// `text` as a SPIR-V literal string operand: its bytes, a terminating NUL, padded with NULs to whole words.
std::vector<uint32_t> spirvString(std::string_view text);

// The module with every occurrence of `from` in its literal string operands replaced by `to`, each instruction
// re-encoded to its new length. std::runtime_error when the module does not parse (a hexc bug).
std::vector<uint32_t> replaceInStrings(const std::vector<uint32_t>& words, std::string_view from, std::string_view to);

// The module with each function's name (OpName) without the signature glslang appends ("hexc_albedo(vf2;" becomes
// "hexc_albedo"): for naga (the WGSL target), which would spell the signature into the name. SPIRV-Cross cuts it itself.
std::vector<uint32_t> plainFunctionNames(const std::vector<uint32_t>& words);

}  // namespace hexc
