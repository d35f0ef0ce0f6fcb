#pragma once
// CompileOptions::unrollLoops: every loop of the module asks spirv-opt to unroll it.
#include <cstdint>
#include <vector>

namespace hexc {

// glslang's module with every loop's control set to Unroll (DontUnroll cleared), as `[[unroll]]` on each would: the
// recipe's --loop-unroll then unrolls each loop whose trip count is a constant (the layers' weight loops run over 8),
// which leaves their arrays indexed by constants only, and a later round of the recipe makes them scalars. For
// languages with no arrays to copy or pass and only `for` loops of their own form (Godot 3's). std::runtime_error on
// a module that does not parse (a hexc bug).
std::vector<uint32_t> unrollEveryLoop(const std::vector<uint32_t>& words);

}  // namespace hexc
