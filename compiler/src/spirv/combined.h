#pragma once
// Combined image samplers for the SPIR-V output (ResourceLayout::Vulkan::combined).
#include <cstdint>
#include <vector>

#include "plan/plan.h"

namespace hexc {

// The optimised module with hexc's textures as combined image samplers at their bindings and without its shared
// sampler. CompileError when the template reads hexc's sampler or textures itself; std::runtime_error on a hexc bug.
std::vector<uint32_t> combineSamplers(const std::vector<uint32_t>& words, const ShaderPlan& plan);

}  // namespace hexc
