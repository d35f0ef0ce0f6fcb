#pragma once
// Material -> ShaderPlan: which template, which code each slot needs, where every resource and
// parameter lives. Everything later stages emit is decided here.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "hexc/diagnostics.h"
#include "hexc/material.h"

namespace hexc {

// Fixed descriptor layout, the same on every target (set 0): parameter block, one shared sampler,
// then one texture per slot in declaration order.
constexpr uint32_t kParamsBinding = 0;
constexpr uint32_t kSamplerBinding = 1;
constexpr uint32_t kFirstTextureBinding = 2;

struct ParamMember {
    std::string name;            // member of the HexcParams block, "<slot>_<setting>"
    std::string type;            // "float", "vec2", "int" or "ivec2"
    uint32_t offset = 0;         // std140 byte offset
    std::vector<double> value;   // the material's value, what an engine writes by default
    std::string perFrame;        // set for values the engine computes each frame: how (the manifest says it)
};

struct SlotPlan {
    const Slot* slot = nullptr;
    std::string section;         // snippet in templates/slots.glsl, e.g. "color.hex"
    uint32_t binding = 0;        // texture binding (set 0)
};

struct ShaderPlan {
    std::string materialName;
    std::string templateName;    // as shown in diagnostics: "templates/lit.glsl" or the user's path
    std::string templateSource;
    std::vector<SlotPlan> slots; // only the slots the template reads
    std::vector<ParamMember> params;
    uint32_t paramBlockSize = 0; // std140 size, rounded up to 16
    Diagnostics diagnostics;     // warnings (e.g. a slot the template never reads) or errors
};

ShaderPlan planShader(const Material& material, const std::filesystem::path& templateOverride);

}  // namespace hexc
