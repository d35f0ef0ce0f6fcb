#pragma once
// The functions output (CompileOptions::functions): the engine functions stay functions through spirv-opt.
#include <cstdint>
#include <string>
#include <vector>

namespace hexc {

// glslang's module with each function whose name is in `names` marked DontInline (glslang names a function by its
// signature: "hexc_albedo(vf2;", which tells an overload apart), so that spirv-opt's
// inliner, which honours the mark, leaves each a function of its own (it still inlines what they call, and optimises
// their bodies as it would main's); SPIRV-Cross then writes them by name. std::runtime_error on a module that does not
// parse (a hexc bug).
std::vector<uint32_t> keepFunctions(const std::vector<uint32_t>& words, const std::vector<std::string>& names);

}  // namespace hexc
