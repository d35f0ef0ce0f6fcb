#pragma once
// One set of fetches for the slots of a packed texture (docs/material-format.md#pack).
#include <cstdint>
#include <vector>

namespace hexc {

// The optimised module with each repeated texture read merged into the first: an explicit-LOD sample of the same
// texture and sampler with the same operands, a size query of the same texture (lod "shared"), or a screen-space
// derivative of the same value, whose first occurrence dominates it. spirv-opt merges neither (it gives every OpSampledImage a value of its own, and keeps each derivative),
// so two slot functions reading one packed texture at the same taps would fetch twice. Run it, then spirv-opt, twice:
// the first round merges the derivatives, spirv-opt the gradients computed from them, the second round the samples.
// A derivative moved to a dominating occurrence keeps its value: both see the same quad. std::runtime_error on a hexc bug.
std::vector<uint32_t> shareTextureReads(const std::vector<uint32_t>& words);

}  // namespace hexc
