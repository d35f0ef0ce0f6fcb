#pragma once
// A layered material's texture arrays (docs/material-format.md#texture-arrays): per role, its textures across layers
// bound as one 2D array texture when one sampler reads them alike, else one texture per slot and the reason.
#include "plan/plan.h"

namespace hexc {

// plan.layers->arrays, and each arrayed slot's SlotPlan::array and arrayLayer; after the slots' sections and packing.
// Refuses a shader binding more than 16 textures so (HX110).
void planLayerArrays(const Material& material, ShaderPlan& plan);

}  // namespace hexc
