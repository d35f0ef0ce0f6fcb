#pragma once
// A library function as it reads a layer of a 2D array texture (docs/material-format.md#texture-arrays): a slot of a
// layered role whose textures are one array gets the forms of the pieces it reaches with its layer folded in.
#include <string>
#include <vector>

#include "codegen/pieces.h"

namespace hexc {

// The setting (codegen/specialise.h) that gives an arrayed slot's layer, a float literal; no slot setting has its `array.`.
inline const std::string kArrayLayer = "array.layer";

// `lines` reading layer `layer` of array textures: each `texture2D` is a `texture2DArray`, each `sampler2D(tex, samp)` a
// `sampler2DArray(tex, samp)`, and the coordinate of a sampling call through it `vec3(coordinate, layer)` (gradients
// and levels are as they were; textureSize's first two components are the layer's size).
std::vector<SourceLine> inArray(const std::vector<SourceLine>& lines, const std::string& layer);

}  // namespace hexc
