#pragma once
// What every engine package shares: which engine input a slot fills (its role, from its name and kind: docs/engines.md,
// "Slots and engine inputs"), and the warning for a slot no input takes.
#include <string>
#include <string_view>

#include "hexc/diagnostics.h"
#include "hexc/material.h"

namespace hexc {

// "albedo", "roughness", "metallic", "ao", "emission", "normal" (every normal slot), or empty: no role.
std::string slotRole(const std::string& slot, SlotKind kind);

Diagnostic unusedSlot(const Material& material, const std::string& slot, std::string_view engine, const std::string& function);

}  // namespace hexc
