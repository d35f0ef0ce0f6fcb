#pragma once
// SPIR-V -> target source through SPIRV-Cross. One file per target holds only what differs: compiler
// options, how hexc's fixed resource layout (plan.h) is pinned, and how the manifest addresses it.
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "codegen/codegen.h"
#include "hexc/compiler.h"
#include "plan/plan.h"

namespace spirv_cross {
class Compiler;
class CompilerGLSL;
class CompilerHLSL;
class CompilerMSL;
}  // namespace spirv_cross

namespace hexc {

// Where one resource lives on a target, as written to the manifest.
enum class ResourceKind { Params, Sampler, Texture };

// A resource the template declares itself (per-frame blocks, shadow maps, push constants...): anything but
// hexc's own (plan.h, HexcBindings). Each target places them after hexc's, per register class.
// Named after Vulkan's descriptor types: SampledImage a texture2D (SAMPLED_IMAGE), CombinedImageSampler a sampler2D.
enum class ResourceClass { UniformBuffer, StorageBuffer, PushConstant, CombinedImageSampler, SampledImage, Sampler, StorageImage };
struct TemplateResource {
    uint32_t id = 0;  // SPIR-V variable
    std::string name;
    ResourceClass cls = ResourceClass::UniformBuffer;
    uint32_t set = 0, binding = 0;  // as declared (none for push constants)
    uint32_t offset = 0, size = 0;  // push constants: the byte range the block's members take (a VkPushConstantRange)
};

// The template's resources in (class, set, binding) order. One at a binding hexc's layout takes is a located error
// (CompileError).
std::vector<TemplateResource> templateResources(const spirv_cross::Compiler& c, const ShaderPlan& plan);
// {name, kind, vulkan: {set, binding, descriptor_type}} (push constants: {offset, size}) for the manifest; a target
// adds where it placed the resource.
nlohmann::json describe(const TemplateResource& r);

struct TargetOutput {
    std::string source;  // empty for the SPIR-V target (its output is the binary)
    std::string entryPoint;
    nlohmann::json target;  // the manifest's description of this target
};

TargetOutput emitHlsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options);
TargetOutput emitGlsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options);
// The same through `c`, a compiler of `spirv`: the GLSL engines' dialects are its subclasses (engines/glsl.cpp).
TargetOutput emitGlsl(spirv_cross::CompilerGLSL& c, const std::vector<uint32_t>& spirv, const ShaderPlan& plan,
                      const CompileOptions& options);
TargetOutput emitMsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options);
// WGSL (wgsl.cpp): the module translated by naga, resources at their Vulkan set and binding as @group and @binding.
TargetOutput emitWgsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options);
TargetOutput vertexWgsl(const std::vector<uint32_t>& spirv, const CompileOptions& options, const std::string& entry);
// `hexc library`'s module as WGSL, without its stage (wgslWithoutStage): the library's functions take their arguments
// as naga writes a glslang function's, `ptr<function, T>` but for textures and samplers.
std::string libraryWgsl(const std::vector<uint32_t>& spirv);
// naga's WGSL of a fragment module up to its entry point `entry`, without the private variables holding the stage's
// inputs and outputs and without `fn <entry>_1`, the entry's body; each resource's @group and @binding on its declaration's line.
std::string wgslWithoutStage(const std::string& wgsl, const std::string& entry);
TargetOutput describeSpirv(const std::vector<uint32_t>& spirv, const ShaderPlan& plan);

// Whether the text targets carry `#line` directives (--debug, unless --line-directives none).
inline bool emitsLineDirectives(const CompileOptions& o) { return o.debug && o.lineDirectives != LineDirectives::None; }

// Each target's SPIRV-Cross options from hexc's (version, shader model), for the fragment and the vertex stage alike.
void configureHlsl(spirv_cross::CompilerHLSL& c, const CompileOptions& options);
void configureGlsl(spirv_cross::CompilerGLSL& c, const CompileOptions& options);
void configureMsl(spirv_cross::CompilerMSL& c, const CompileOptions& options);

// The name SPIRV-Cross gives a fragment entry point `entry` in MSL: `entry`, or `entry0` where MSL reserves it.
std::string mslEntryName(const std::string& entry);

// SPIRV-Cross names the HLSL entry function `main` whatever the module's entry point is: gives it `entry`.
void renameHlslEntry(std::string& source, const std::string& entry);

// The fragment shader's inputs, in location order: what a pass-through vertex stage must write.
std::vector<Varying> fragmentInputs(const std::vector<uint32_t>& spirv);
// Each SPIRV-Cross target's pass-through vertex stage, `hexc library` code and banner settings (hlsl.cpp, glsl.cpp,
// msl.cpp), for its row.
TargetOutput vertexHlsl(const std::vector<uint32_t>& spirv, const CompileOptions& options, const std::string& entry);
TargetOutput vertexGlsl(const std::vector<uint32_t>& spirv, const CompileOptions& options, const std::string& entry);
TargetOutput vertexMsl(const std::vector<uint32_t>& spirv, const CompileOptions& options, const std::string& entry);
std::string libraryHlsl(const std::vector<uint32_t>& spirv);
std::string libraryGlsl(const std::vector<uint32_t>& spirv);
std::string libraryMsl(const std::vector<uint32_t>& spirv);
std::string settingsHlsl(const CompileOptions& options);
std::string settingsGlsl(const CompileOptions& options);
std::string settingsMsl(const CompileOptions& options);

// Shared by the backends (reflection.cpp). `locate` gives a target's address of one resource;
// `ioName` the target's name for a stage input/output location (semantic, attribute), or null.
using Locate = std::function<nlohmann::json(ResourceKind kind, uint32_t index)>;
using IoName = nlohmann::json (*)(uint32_t location, bool input);
// `placed`: the template's resources as the target placed them (describe() plus the target's address).
nlohmann::json describeTarget(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const std::string& entryPoint, Locate locate,
                              IoName ioName, const nlohmann::json& placed);

// The pass-through vertex stage's files on every target from its optimised module into `files`, and its description
// for the manifest: each target's file and entry point, and the attributes feeding `inputs`.
nlohmann::json emitVertexStage(const std::vector<uint32_t>& spirv, const std::vector<Varying>& inputs, const std::string& entry,
                               const std::string& material, const CompileOptions& options, const std::vector<Target>& targets,
                               std::vector<OutputFile>& files);

// The manifest (manifest.cpp): material, slots, parameter block, and every target's description.
nlohmann::json buildManifest(const Material& material, const ShaderPlan& plan, const nlohmann::json& targets);
// CompileOptions::manifestPathsFrom: where the compile's input files were, relative to the folder `from`.
nlohmann::json sourcePaths(const Material& material, const ShaderPlan& plan, const std::filesystem::path& from);

// The target table (targets.cpp): one row per target, in Target order. Everything that differs by target and is not
// in its backend file (backends/<target>.cpp) is a column here.
struct TargetRow {
    Target target;
    const char* name;       // --targets, the manifest's key (`targets.<name>`), the CMake and Bazel packages' name
    const char* alias;      // another --targets name for it, or ""
    const char* extension;  // <material>.<stage>.<extension>
    const char* layout;     // the layout file's section that places its resources (hexc/layout.h)
    bool binary;            // its source is a binary module (no banner; the entry point is renamed in its words)
    bool byDefault;         // in CompileOptions::targets by default
    // The start of the entry point's code in the emitted text, from which the functions output and `hexc library` cut.
    const char* entryLine;
    // The functions output's source before that cut (functions.cpp), for entry point `entry`: without what the
    // translator writes for the stage beyond the cut's reach (the lines from `entryLine` on, SPIRV-Cross's stage structs).
    std::string (*withoutStage)(const std::string& source, const std::string& entry);
    // The fragment stage from the optimised module; `text`: the same module with the source lines --debug shows.
    TargetOutput (*emit)(const std::vector<uint32_t>& spirv, const std::vector<uint32_t>& text, const ShaderPlan& plan,
                         const CompileOptions& options);
    // The pass-through vertex stage, its entry point `entry`.
    TargetOutput (*vertex)(const std::vector<uint32_t>& spirv, const CompileOptions& options, const std::string& entry);
    std::string (*entryName)(const std::string& entry);      // what the target's code calls a fragment entry point `entry`
    std::string (*settings)(const CompileOptions& options);  // its settings on the banner, "" for none
    const char* translator;                                  // what writes its code from SPIR-V, as `hexc library`'s banner says
    // What can change the translator's output that hexc's build id does not hold (the shader cache's key), or "".
    std::string (*translatorIdentity)();
    const char* libraryName;  // `hexc library --target` name, its file's extension
    const char* libraryExtension;
    std::string (*library)(const std::vector<uint32_t>& spirv);  // `hexc library`'s unoptimised module in its language
};
const TargetRow& targetRow(Target target);
// Every row, in Target order.
const std::array<TargetRow, kTargetCount>& targetRows();

// options.targets in target order, each once.
std::vector<Target> sortedTargets(const CompileOptions& options);
// A SPIR-V module as its file's bytes.
std::string spirvBytes(const std::vector<uint32_t>& words);
// Each target from the optimised module, the SPIR-V target with combined samplers when the layout asks for them.
std::map<Target, TargetOutput> emitTargets(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options,
                                           const std::vector<Target>& targets);

// The manifest's "functions" (manifest.cpp): each engine function, its slot, what it returns and in which convention.
nlohmann::json functionsEntry(const ShaderPlan& plan);

// The functions output (functions.cpp): `source`, a target's code of the `functions` template, without the entry point
// `entry`, its stage input and output, and GLSL's #version line.
std::string functionsOnly(const std::string& source, Target target, const std::string& entry);

// The banner (banner.cpp): two comment lines naming hexc, the material, the template and the settings.
std::string banner(const Material& material, const ShaderPlan& plan, const CompileOptions& options);
// `top` (a banner) on top of every shader source in `files`, after GLSL's `#version` line.
void addBanners(std::vector<OutputFile>& files, const std::string& top);

}  // namespace hexc
