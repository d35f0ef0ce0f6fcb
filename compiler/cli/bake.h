#pragma once
// `hexc bake`: each slot of a material rendered on the Vulkan runner as a texture that repeats seamlessly, with
// hex-tiling's variety inside it (the periodic lattice, CompileOptions::periodicRepeats), and a material that tiles
// those textures plainly. Not the compile flag --bake, which folds settings into code.
#include <string>
#include <vector>

#include "hexc/image.h"
#include "hexc/material.h"
#include "hexc/report.h"
#include "vk/runner.h"

namespace hexc::cli {

int bakeCommand(const std::vector<std::string>& args);

// What `hexc bake` refuses (HX134, at the slot): a layered material, and slots whose hex-tiling has no periodic form
// (triplanar projection, paper or materialx mode, the noise masks).
Diagnostics bakeRefusals(const Material& material);

// The view a slot is baked over: size x size pixels covering st in [0, repeats]^2 (uv = st / tiling), one pixel's
// st being the gradients, so that the bake is filtered for its own resolution.
View bakeView(const Slot& slot, int size, int repeats);

// One slot baked on `runner`, encoded as its texture is: a colour (or scalar) slot's value, sRGB-encoded when the
// slot is sRGB; a normal slot's normal n * 0.5 + 0.5 with green down when the slot is flip_y. Floats, before a file
// quantises them.
Image bakeSlot(vk::Runner& runner, const Material& material, const Slot& slot, int size, int repeats);

}  // namespace hexc::cli
