#pragma once
// Shader code as compiled from the generated GLSL, and its format in the shader cache (hexc/cache.h).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "backends/backends.h"

namespace hexc {

// The optimised SPIR-V and each target's output. It is compiled with the entry point kEntryPlaceholder and named
// afterwards (withEntryPoint), so that materials whose code differs in that name only share one cache entry.
struct ShaderCode {
    std::vector<uint32_t> spirv;
    std::map<Target, TargetOutput> targets;  // the SPIR-V target's source holds its file's bytes
};
// A name hexc reserves (docs/templates.md), so it stands for the entry point alone.
constexpr std::string_view kEntryPlaceholder = "hexcEntryPoint";

// Everything that can change a ShaderCode: the generated GLSL, the template's name (glslang's debug info holds it),
// the slots' names (the manifest's), the options that reach glslang, spirv-opt and SPIRV-Cross, and hexc's build.
std::string shaderCodeKey(const std::string& glsl, const ShaderPlan& plan, const CompileOptions& options);

// The cache entry's bytes, and back: null when the bytes are not a ShaderCode for `targets` (an entry of another format).
std::string toBytes(const ShaderCode& code);
std::optional<ShaderCode> shaderCodeFromBytes(const std::string& bytes, const std::vector<Target>& targets);

// The code with its entry point named `entry` wherever the placeholder stands: SPIR-V strings, the sources (MSL
// builds its stage structs' names from it) and the manifest's descriptions.
void withEntryPoint(ShaderCode& code, const std::string& entry);

}  // namespace hexc
