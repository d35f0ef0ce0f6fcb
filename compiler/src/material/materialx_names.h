#pragma once
// What the MaterialX reader and writer agree on (docs/materialx.md): which surface shader inputs carry which slots,
// and which hexc settings travel as hexc_* attributes because MaterialX has no input for them.
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace hexc::mtlx {

// Surface inputs that carry the built-in templates' slots; any other input carries the slot named after it in
// snake_case (standard_surface `metalness` -> `metalness`, UsdPreviewSurface `emissiveColor` -> `emissive_color`).
struct SlotInput {
    std::string_view shader, input, slot;
};
inline constexpr SlotInput kSlotInputs[] = {
    {"standard_surface", "base_color", "albedo"},
    {"standard_surface", "specular_roughness", "roughness"},
    {"standard_surface", "normal", "normal"},
    {"open_pbr_surface", "base_color", "albedo"},
    {"open_pbr_surface", "specular_roughness", "roughness"},
    {"open_pbr_surface", "geometry_normal", "normal"},
    {"UsdPreviewSurface", "diffuseColor", "albedo"},
    {"UsdPreviewSurface", "roughness", "roughness"},
    {"UsdPreviewSurface", "normal", "normal"},
    {"UsdPreviewSurface", "displacement", "height"},
    {"displacement", "displacement", "height"},
};

// The slot a shader's input carries: the table above, else the input's name in snake_case. The reader names slots
// by it and the writer picks the input whose slot has the name.
std::string slotName(std::string_view shader, std::string_view input);

// hextiling keys with no MaterialX input: a texture node carries them as hexc_<key> attributes.
inline const std::vector<std::string> kNodeKeys = {"exponent",  "mode", "split_coordinates", "rotationsteps", "offsetsteps", "mask",
                                                   "maskscale", "taps", "falloffcontrast",   "blend",         "lod"};
// Slot keys of the same kind: a plain normal map's flip (the normalmap node has no flip_g) and height blending.
inline const std::vector<std::string> kSlotKeys = {"flip_y", "height_blend", "height_blend_width"};
// Material-wide settings, as hexc_<key> attributes of the surfacematerial.
inline const std::vector<std::string> kMaterialKeys = {"template", "projection", "planesharpness", "pack"};

// The luma weights hexc's colour path uses (Rec. 601, paper Eq. 4); MaterialX's `lumacoeffs` names them.
inline constexpr std::array<double, 3> kLuma = {0.299, 0.587, 0.114};

}  // namespace hexc::mtlx
