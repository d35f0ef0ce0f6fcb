#pragma once
// The role table: which engine input a slot fills (its role, from its name and kind: docs/engines.md, "Slots and engine
// inputs"), per engine, and the wiring every package shares: each engine function with the input it fills, a slot no
// input takes reported.
#include <string>
#include <string_view>
#include <vector>

#include "engines/table.h"
#include "hexc/diagnostics.h"
#include "hexc/material.h"
#include "plan/plan.h"

namespace hexc {

// "albedo", "roughness", "metallic", "ao", "emission", "normal" (every normal slot), or empty: no role. The slot's
// `role` if the material gives one, else its name's.
std::string slotRole(const Slot& slot);

// An engine function with the input of the engine it fills: the role table's entry for the engine (a statement with
// `%` for the value, a pin or, for the web engines, the role the module wires), or null: it fills none. A normal
// slot's derivative function fills none and is no warning: the engines take its tangent-space normal.
struct WiredFunction {
    EngineFunction function;
    std::string role;
    const char* input = nullptr;
};

// Each of `functions` wired for `engine`: each input takes the first function of its role; a slot whose function no
// input takes is a warning in `diagnostics`, located at the slot.
std::vector<WiredFunction> wire(const Material& material, const std::vector<EngineFunction>& functions, const EngineRow& engine,
                                Diagnostics& diagnostics);

// `pattern` with its `%` as `value`.
std::string filled(std::string pattern, const std::string& value);

}  // namespace hexc
