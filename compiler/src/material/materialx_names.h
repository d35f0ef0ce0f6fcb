#pragma once
// What the MaterialX reader and writer agree on (docs/materialx.md): which surface shader inputs carry which slots,
// and which hexc settings travel as hexc_* attributes because MaterialX has no input for them.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace hexc::mtlx {

// Surface inputs that carry the built-in templates' slots, and the weights named like the inputs of their lobe
// (standard_surface `coat` beside `coat_color`): a slot named `coat` would start with `coat_color`'s name and `_`,
// which generated parameter names cannot tell apart, so it is `coat_weight` (OpenPBR's name). Any other input
// carries the slot named after it in snake_case (standard_surface `metalness` -> `metalness`, UsdPreviewSurface
// `emissiveColor` -> `emissive_color`).
struct SlotInput {
    std::string_view shader, input, slot;
};
inline constexpr SlotInput kSlotInputs[] = {
    {"standard_surface", "base_color", "albedo"},
    {"standard_surface", "specular_roughness", "roughness"},
    {"standard_surface", "normal", "normal"},
    {"standard_surface", "specular", "specular_weight"},
    {"standard_surface", "transmission", "transmission_weight"},
    {"standard_surface", "subsurface", "subsurface_weight"},
    {"standard_surface", "sheen", "sheen_weight"},
    {"standard_surface", "coat", "coat_weight"},
    {"standard_surface", "emission", "emission_weight"},
    {"gltf_pbr", "base_color", "albedo"},
    {"gltf_pbr", "roughness", "roughness"},
    {"gltf_pbr", "normal", "normal"},
    {"gltf_pbr", "specular", "specular_weight"},
    {"gltf_pbr", "clearcoat", "clearcoat_weight"},
    {"gltf_pbr", "iridescence", "iridescence_weight"},
    {"gltf_pbr", "emissive", "emissive_color"},
    {"open_pbr_surface", "base_color", "albedo"},
    {"open_pbr_surface", "specular_roughness", "roughness"},
    {"open_pbr_surface", "geometry_normal", "normal"},
    {"UsdPreviewSurface", "diffuseColor", "albedo"},
    {"UsdPreviewSurface", "roughness", "roughness"},
    {"UsdPreviewSurface", "normal", "normal"},
    {"UsdPreviewSurface", "displacement", "height"},
    {"UsdPreviewSurface", "clearcoat", "clearcoat_weight"},
    {"displacement", "displacement", "height"},
};

// The slot a shader's input carries: the table above, else the input's name in snake_case. The reader names slots
// by it and the writer picks the input whose slot has the name.
std::string slotName(std::string_view shader, std::string_view input);

// Generated parameters are named <slot>_<setting>, so the JSON rules refuse a slot name that another extends by
// `_`; among the slots of a document (objects with a string "name"), the shorter of two such names, or the later
// of equal ones, gets the first number that clashes with no other name (`subsurface_radius2` beside
// `subsurface_radius_scale`).
void uniqueSlotNames(nlohmann::json& slots);

// hextiling keys with no MaterialX input: a texture node carries them as hexc_<key> attributes.
inline const std::vector<std::string> kNodeKeys = {"exponent",  "mode", "split_coordinates", "rotationsteps", "offsetsteps", "mask",
                                                   "maskscale", "taps", "falloffcontrast",   "blend",         "lod"};
// Slot keys of the same kind: a plain normal map's flip (the normalmap node has no flip_g) and height blending.
inline const std::vector<std::string> kSlotKeys = {"flip_y", "height_blend", "height_blend_width"};
// Material-wide settings, as hexc_<key> attributes of the surfacematerial.
inline const std::vector<std::string> kMaterialKeys = {"template", "projection", "planesharpness", "pack", "mode"};

// The luma weights hexc's colour path uses (Rec. 601, paper Eq. 4); MaterialX's `lumacoeffs` names them.
inline constexpr std::array<double, 3> kLuma = {0.299, 0.587, 0.114};

}  // namespace hexc::mtlx
