#pragma once
// The source lines a debug module keeps for the text targets (CompileOptions::lineDirectives): SPIRV-Cross writes a
// `#line` for each OpLine it meets, and glslang puts one before nearly every statement.
#include <cstdint>
#include <vector>

namespace hexc {

// The module with only each function's first OpLine (and no OpNoLine inside functions): SPIRV-Cross then writes one
// `#line` before the function and one at its first statement.
std::vector<uint32_t> functionLinesOnly(const std::vector<uint32_t>& words);

// The module without any OpLine or OpNoLine: for naga (the WGSL target), whose SPIR-V reader stops at them.
std::vector<uint32_t> withoutLines(const std::vector<uint32_t>& words);

}  // namespace hexc
