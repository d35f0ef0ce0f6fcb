#pragma once
// Material -> ShaderPlan: which template, which code each slot needs, where every resource and
// parameter lives. Everything later stages emit is decided here.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "hexc/compiler.h"
#include "hexc/diagnostics.h"
#include "hexc/material.h"

namespace hexc {

// Fixed descriptor layout, the same on every target (set 0): parameter block, one shared sampler,
// then one texture per slot in declaration order.
constexpr uint32_t kParamsBinding = 0;
constexpr uint32_t kSamplerBinding = 1;
constexpr uint32_t kFirstTextureBinding = 2;

// A numeric setting the shader reads: a member of the HexcParams block, or (baked) a specialisation
// constant that spirv-opt freezes.
struct ParamMember {
    std::string name;            // "<slot>_<setting>"; lattice settings are named after the lattice's first slot
    std::string type;            // "float", "vec2", "int" or "ivec2"
    std::vector<double> value;   // the material's value, what an engine writes by default
    std::vector<std::string> slots;  // the slots that read it
    std::string perFrame;        // set for values the engine computes each frame: how (the manifest says it)
    uint32_t offset = 0;         // std140 byte offset, for block members
    std::optional<uint32_t> constantId;  // set when baked: its first specialisation constant id
};

// The lattice (Listing 1 plus the tile transforms) that one or more slots share: slots with the same
// coordinates, tiling, rotation and mode evaluate it once.
struct LatticePlan {
    std::string name;            // the first slot's name; names the lattice's parameters
    HexTiling settings;          // enabled, mode, split, tiling, rotation
    bool rotate = true;          // the rotation code is emitted
    bool transform = false;      // per-tile transforms (ranges, steps, scale, offset amount) are emitted
};

struct SlotPlan {
    const Slot* slot = nullptr;
    std::string section;         // snippet in templates/library/slots.glsl, e.g. "color.hex"; empty when heightOnly
    uint32_t binding = 0;        // texture binding (set 0)
    size_t lattice = 0;          // index into ShaderPlan::lattices
    bool metric = true;          // the falloff metric code is emitted (falloffcontrast != 0)
    bool gain = true;            // the gain code is emitted (falloff != 0.5)
    int exponentInt = 0;         // > 0: the exponent is this whole number, multiplied out (no pow, no uniform)
    int gainInt = 0;             // > 0: the gain's k = log2(1 / (1 - falloff)) is this whole number, likewise
    bool heightOnly = false;     // only the texture is used, as another slot's height map (no function, no lattice)
};

struct ShaderPlan {
    std::string materialName;
    std::string templateName;    // as shown in diagnostics: "templates/lit.glsl" or the user's path
    std::string templateSource;
    std::vector<SlotPlan> slots; // only the slots the template reads
    std::vector<LatticePlan> lattices;
    std::vector<ParamMember> params;  // block members first, in block order, then baked constants
    std::vector<ParamMember> specialised;  // settings fixed in the code as whole-number exponents
    uint32_t paramBlockSize = 0; // std140 size, rounded up to 16
    Diagnostics diagnostics;     // warnings (e.g. a slot the template never reads) or errors

    const ParamMember* param(const std::string& name) const;
};

ShaderPlan planShader(const Material& material, const CompileOptions& options);

}  // namespace hexc
