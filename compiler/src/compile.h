#pragma once
// What a compile makes, typed, before it becomes files: compile() writes these, and a layer above the compiler (the
// engine packages, engines/) writes its own files from them without reading back any text hexc wrote.
#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

#include "hexc/compiler.h"
#include "plan/plan.h"

namespace hexc {

struct CompiledMaterial {
    ShaderPlan plan;                        // every decision: the slots, their textures, the functions and their roles
    std::map<Target, std::string> sources;  // each target's shader, or its functions (plan.functions), without the banner
    std::string banner;                     // the lines compile() puts on top of each source (after GLSL's #version)
    nlohmann::json manifest;                // as compile() writes it
    // compile()'s other files: the vertex stage's and the generated GLSL (with their banners), the derived textures.
    std::vector<OutputFile> files;
    CompileResult result;  // the diagnostics, the generated GLSL and the SPIR-V; no files
};

// Never throws: problems come back in result.diagnostics (and nothing else is set). functionArrays: planShader's.
CompiledMaterial compileMaterial(const Material& material, const CompileOptions& options, bool functionArrays = false);

}  // namespace hexc
