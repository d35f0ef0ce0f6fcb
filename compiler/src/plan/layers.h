#pragma once
// A layered material's plan (Material::layers -> ShaderPlan::layers): which of its slots the template's reads of the
// roles reach, and the fetches per pixel the blend costs.
#include <string>

#include "plan/plan.h"

namespace hexc {

// Whether material slot `index` belongs to the layers and the template reads it through a role: a layer's slot of a
// role it reads (`readsFirst`: the template reads HEXC_FIRST_SLOT, the first role), the height role's and the splat
// maps when it reads any role.
bool layerSlotRead(const Material& material, size_t index, const std::string& templateSource, bool readsFirst);

// plan.layers, after plan.slots; nothing when the material has no layers or the template reads none of its roles.
// `shareTiles` (CompileOptions::shareLattice): each lattice's tiles are computed once per pixel with the weights and
// read by every layer's slot of that lattice; without, each slot computes its own, so that its function also works
// called alone, outside a role's read (hexc edit's views of a layer's slot).
void planLayers(const Material& material, bool shareTiles, ShaderPlan& plan);

}  // namespace hexc
