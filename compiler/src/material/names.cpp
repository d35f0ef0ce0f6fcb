// The enums' names (names.h) and toString over them, and the slot-kind table (hexc/material.h).
#include "material/names.h"

#include "common/by_enum.h"
#include "hexc/material.h"

namespace hexc {
namespace {

constexpr std::array<SlotKindRow, kSlotKindCount> kKindRows = {{
    // kind, name, glslType, mtlxType, reads, colorSpace, derivative, oneChannel, mayPack, mayUseHistogram, like
    {SlotKind::Color, "color", "vec4", "color3", "rgba", ColorSpace::Srgb, false, false, true, true, SlotKind::Color},
    {SlotKind::Scalar, "scalar", "float", "float", "", ColorSpace::Linear, false, true, true, true, SlotKind::Scalar},
    {SlotKind::Normal, "normal", "vec2", "vector3", "rgb", ColorSpace::Linear, true, false, false, false, SlotKind::Normal},
}};

constexpr bool sameText(const char* a, const char* b) {
    while (*a && *a == *b) ++a, ++b;
    return *a == *b;
}

// A row is at its kind's place, `reads` is empty exactly for one channel, and the kind it is read like reads itself
// (it has the snippets) and returns the same type.
constexpr bool inKindOrder() {
    for (size_t i = 0; i < kKindRows.size(); ++i) {
        const SlotKindRow& row = kKindRows[i];
        const SlotKindRow& like = kKindRows[size_t(row.like)];
        if (size_t(row.kind) != i || row.name == nullptr || row.oneChannel != (*row.reads == '\0') || like.like != like.kind ||
            !sameText(like.glslType, row.glslType))
            return false;
    }
    return true;
}
static_assert(inKindOrder(),
              "the slot-kind table has one row per SlotKind, in SlotKind order; `reads` empty for one channel; `like` a kind "
              "with its own snippets and the same GLSL type");

// An enum's names in its order; `Last` is its last value, so a name missing or extra does not compile.
template <auto Last, size_t N>
std::vector<std::string> enumNames(const char* const (&names)[N]) {
    const auto checked = byEnum<Last>(names);
    return {checked.begin(), checked.end()};
}

std::vector<std::string> kindNames() {
    std::vector<std::string> names;
    for (const SlotKindRow& row : kKindRows) names.push_back(row.name);
    return names;
}

}  // namespace

const std::vector<std::string> kKinds = kindNames();
const std::vector<std::string> kChannels = {"r", "g", "b", "a"};
const std::vector<std::string> kColorSpaces = enumNames<ColorSpace::Linear>({"srgb", "linear"});
const std::vector<std::string> kModes = enumNames<HashMode::MaterialX>({"stable", "paper", "materialx"});
const std::vector<std::string> kMasks = enumNames<Mask::Noise3>({"hex", "checker", "noise", "noise3"});
const std::vector<std::string> kProjections = enumNames<Projection::Triplanar>({"uv", "triplanar"});
const std::vector<std::string> kBlends = enumNames<Blend::Histogram>({"falloff", "histogram"});
const std::vector<std::string> kLods = enumNames<Lod::Shared>({"gradients", "shared"});
const std::vector<std::string> kLayerBlends = enumNames<LayerBlend::Height>({"linear", "height"});
const std::vector<std::string> kLayerWeights = enumNames<LayerWeights::Both>({"splat", "vertex", "both"});
const std::vector<std::string> kRoles = {"albedo", "normal", "roughness", "metallic", "ao", "emission"};

const SlotKindRow& kindRow(SlotKind kind) { return kKindRows.at(size_t(kind)); }

const std::array<SlotKindRow, kSlotKindCount>& kindRows() { return kKindRows; }

std::string kindsWhere(bool SlotKindRow::*property) {
    std::string text;
    for (const SlotKindRow& row : kKindRows)
        if (row.*property) text += (text.empty() ? "`" : " or `") + std::string(row.name) + "`";
    return text;
}

SlotKind roleKind(const std::string& role) {
    if (role == "normal") return SlotKind::Normal;
    return role == "albedo" || role == "emission" ? SlotKind::Color : SlotKind::Scalar;
}

std::string_view toString(SlotKind kind) { return kindRow(kind).name; }
std::string_view toString(ColorSpace space) { return kColorSpaces[size_t(space)]; }
std::string_view toString(HashMode mode) { return kModes[size_t(mode)]; }
std::string_view toString(Mask mask) { return kMasks[size_t(mask)]; }
std::string_view toString(Blend blend) { return kBlends[size_t(blend)]; }
std::string_view toString(Lod lod) { return kLods[size_t(lod)]; }
std::string_view toString(LayerBlend blend) { return kLayerBlends[size_t(blend)]; }
std::string_view toString(LayerWeights weights) { return kLayerWeights[size_t(weights)]; }
std::string_view toString(Projection projection) { return kProjections[size_t(projection)]; }

}  // namespace hexc
