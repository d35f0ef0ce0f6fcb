#pragma once
// SPIR-V -> target source through SPIRV-Cross. One file per target holds only what differs: compiler
// options, how hexc's fixed resource layout (plan.h) is pinned, and how the manifest addresses it.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hexc/compiler.h"
#include "plan/plan.h"

namespace hexc {

// Where one resource lives on a target, as written to the manifest.
enum class ResourceKind { Params, Sampler, Texture };

struct TargetOutput {
    std::string source;             // empty for the SPIR-V target (its output is the binary)
    std::string entryPoint;
    nlohmann::json target;          // the manifest's description of this target
};

TargetOutput emitHlsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options);
TargetOutput emitGlsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options);
TargetOutput emitMsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options);
TargetOutput describeSpirv(const std::vector<uint32_t>& spirv, const ShaderPlan& plan);

// Shared by the backends (reflection.cpp). `locate` gives a target's address of one resource;
// `ioName` the target's name for a stage input/output location (semantic, attribute), or null.
using Locate = nlohmann::json (*)(ResourceKind kind, uint32_t index);
using IoName = nlohmann::json (*)(uint32_t location, bool input);
nlohmann::json describeTarget(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const std::string& entryPoint,
                              Locate locate, IoName ioName);

// The manifest (manifest.cpp): material, slots, parameter block, and every target's description.
nlohmann::json buildManifest(const Material& material, const ShaderPlan& plan, const nlohmann::json& targets);

}  // namespace hexc
