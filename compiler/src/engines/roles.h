#pragma once
// What every engine package shares: which engine input a slot fills (its role, from its name and kind: docs/engines.md,
// "Slots and engine inputs"), and the warning for a slot no input takes.
#include <set>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>

#include "hexc/diagnostics.h"
#include "hexc/material.h"

namespace hexc {

// "albedo", "roughness", "metallic", "ao", "emission", "normal" (every normal slot), or empty: no role. The slot's
// `role` if the material gives one, else its name's.
std::string slotRole(const Slot& slot);

// The slot an entry of the manifest's `functions` is of: its `slot`, or for a layered material's role function, the
// role's slot in the first layer (where a warning about it points).
const Slot& functionSlot(const Material& material, const nlohmann::json& function);

// The engine input an entry of the manifest's `functions` fills: its slot's role, or a role function's role by its
// name and kind, as a slot's.
std::string functionRole(const Material& material, const nlohmann::json& function);

// The textures of the manifest (a slot's or a packed texture's name) whose sampler decodes them from sRGB: an sRGB slot
// the shader does not decode itself (no `"decode": "shader"`), or an sRGB packed texture (docs/bind-a-manifest.md,
// step 3). Every other texture is linear.
std::set<std::string> samplerDecodesSrgb(const nlohmann::json& manifest);

// The warning for a slot no input of `engine` takes, located at the slot.
Diagnostic unusedSlot(const Material& material, const Slot& slot, std::string_view engine, const std::string& function);

}  // namespace hexc
