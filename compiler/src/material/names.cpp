// The enums' names (names.h) and toString over them.
#include "material/names.h"

#include "hexc/material.h"

namespace hexc {

const std::vector<std::string> kKinds = {"color", "scalar", "normal"};
const std::vector<std::string> kChannels = {"r", "g", "b", "a"};
const std::vector<std::string> kColorSpaces = {"srgb", "linear"};
const std::vector<std::string> kModes = {"stable", "paper", "materialx"};
const std::vector<std::string> kMasks = {"hex", "checker", "noise", "noise3"};
const std::vector<std::string> kProjections = {"uv", "triplanar"};
const std::vector<std::string> kBlends = {"falloff", "histogram"};
const std::vector<std::string> kLods = {"gradients", "shared"};
const std::vector<std::string> kLayerBlends = {"linear", "height"};
const std::vector<std::string> kRoles = {"albedo", "normal", "roughness", "metallic", "ao", "emission"};

SlotKind roleKind(const std::string& role) {
    if (role == "normal") return SlotKind::Normal;
    return role == "albedo" || role == "emission" ? SlotKind::Color : SlotKind::Scalar;
}

std::string_view toString(SlotKind kind) { return kKinds[size_t(kind)]; }
std::string_view toString(ColorSpace space) { return kColorSpaces[size_t(space)]; }
std::string_view toString(HashMode mode) { return kModes[size_t(mode)]; }
std::string_view toString(Mask mask) { return kMasks[size_t(mask)]; }
std::string_view toString(Blend blend) { return kBlends[size_t(blend)]; }
std::string_view toString(Lod lod) { return kLods[size_t(lod)]; }
std::string_view toString(LayerBlend blend) { return kLayerBlends[size_t(blend)]; }
std::string_view toString(Projection projection) { return kProjections[size_t(projection)]; }

}  // namespace hexc
