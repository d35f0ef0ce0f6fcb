#pragma once
// A material document's `layers` and `layer_blend` (docs/material-format.md#layers) -> Material::layers. Each layer's
// slots are read as the material's slots are, then become slots of the material named <layer>_<role>; the splat maps
// become plain-tiled linear colour slots splat0, splat1.
#include <algorithm>
#include <functional>
#include <string>

#include "material/rules.h"

namespace hexc {

// The narrowest height-blend `width` (a layer blend's or a slot's) that float resolves: 2^-22, the spacing of floats
// just below 2, the most a height plus a weight reaches. A narrower width is read as this: the top layer's (or tile's)
// share, its sum plus the width less the top, then stays positive in float in whichever order it is evaluated, where
// one under that spacing can round away and leave every share 0, a black pixel.
constexpr double kMinHeightWidth = 0x1p-22;

// What the material's validator reads for the layers: a slot under given hex-tiling defaults, a `hextiling` block
// merged into settings, and a slot's texture file.
struct LayerReaders {
    std::function<Slot(const nlohmann::json&, const std::string&, const HexTiling&)> slot;
    std::function<void(const nlohmann::json&, const std::string&, HexTiling&)> hex;
    std::function<void(Slot&, const std::string&)> texture;
};

// Reads doc's `layers` and `layer_blend` into m (after m.slots holds the material's own slots), reporting to `rules`.
void parseLayers(JsonRules& rules, const nlohmann::json& doc, Material& m, const LayerReaders& read);

}  // namespace hexc
