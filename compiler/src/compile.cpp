// The one place the stages are chained: plan -> codegen -> glslang -> spirv-opt -> SPIRV-Cross -> manifest.
#include <spirv_cross_error_handling.hpp>

#include <algorithm>
#include <new>
#include <optional>

#include "backends/backends.h"
#include "backends/shader_code.h"
#include "codegen/codegen.h"
#include "compile.h"
#include "hexc/cache.h"
#include "hexc/compiler.h"
#include "hexc/lint.h"
#include "hexc/spirv.h"
#include "plan/plan.h"
#include "precompute/derived.h"
#include "spirv/module.h"
#include "spirv/keep.h"
#include "spirv/share.h"
#include "spirv/unroll.h"

namespace hexc {
namespace {

void append(Diagnostics& to, const Diagnostics& from) { to.insert(to.end(), from.begin(), from.end()); }

// The engine functions as glslang names them: each takes the texture coordinate, and a layered role's the vertex colour
// when it weighs the layers.
std::vector<std::string> engineSignatures(const ShaderPlan& plan) {
    std::vector<std::string> names;
    for (const EngineFunction& f : engineFunctions(plan)) names.push_back(f.name + (f.vertexColor ? "(vf2;vf4;" : "(vf2;"));
    return names;
}

// The generated GLSL through glslang and spirv-opt, then each target.
ShaderCode compileCode(const std::string& glsl, const ShaderPlan& plan, const CompileOptions& options, const std::vector<Target>& targets,
                       Diagnostics& diagnostics) {
    SpirvResult front = compileToSpirv(glsl, ShaderStage::Fragment, plan.templateName, SourceLanguage::Glsl, plan.entryPoint, {},
                                       options.debug ? plan.templateShown : "");
    append(diagnostics, front.diagnostics);
    if (front.words.empty()) return {};
    if (std::optional<Diagnostic> d = spirv::beyondOptimiserBound(front.words, plan.templateName)) {
        diagnostics.push_back(*d);
        return {};
    }
    if (plan.functions) front.words = keepFunctions(front.words, engineSignatures(plan));
    if (options.unrollLoops) front.words = unrollEveryLoop(front.words);
    SpirvResult optimized = optimizeSpirv(front.words, options.bake, false, !options.debug);
    append(diagnostics, optimized.diagnostics);
    if (optimized.words.empty()) return {};
    // The unrolled loops' arrays, now indexed by constants only, become scalars in a second round of the recipe.
    if (options.unrollLoops && !options.debug) {
        optimized = optimizeSpirv(optimized.words, false, false, true);
        append(diagnostics, optimized.diagnostics);
        if (optimized.words.empty()) return {};
    }
    // A packed texture's slots fetch it once per tap (spirv/share.h); --debug keeps each slot's function and fetches.
    for (int round = 0; round < 2 && !plan.packs.empty() && !options.debug; ++round) {
        optimized = optimizeSpirv(shareTextureReads(optimized.words), false, false, true);
        append(diagnostics, optimized.diagnostics);
        if (optimized.words.empty()) return {};
    }
    return {optimized.words, emitTargets(optimized.words, plan, options, targets)};
}

// compileCode through CompileOptions::cache. A compile with diagnostics (warnings) is not stored, so a hit has none
// to report.
ShaderCode cachedCode(const std::string& glsl, const ShaderPlan& plan, const CompileOptions& options, const std::vector<Target>& targets,
                      Diagnostics& diagnostics) {
    if (!options.cache) return compileCode(glsl, plan, options, targets, diagnostics);
    std::optional<ShaderCode> compiled;
    auto compute = [&]() -> std::optional<std::string> {
        Diagnostics own;
        compiled = compileCode(glsl, plan, options, targets, own);
        append(diagnostics, own);
        if (compiled->spirv.empty() || !own.empty()) return std::nullopt;
        return toBytes(*compiled);
    };
    // A folder entry is used only if it decodes into every target and valid SPIR-V; otherwise it is replaced.
    std::optional<ShaderCode> found;
    auto usable = [&](const std::string& bytes) {
        found = shaderCodeFromBytes(bytes, targets);
        return found && validationErrors(found->spirv).empty();
    };
    std::optional<std::string> bytes = options.cache->getOrCompute(shaderCodeKey(glsl, plan, options), compute, usable);
    if (compiled) return std::move(*compiled);
    if (found || (found = shaderCodeFromBytes(*bytes, targets))) return std::move(*found);
    return compileCode(glsl, plan, options, targets, diagnostics);
}

// The fragment shader's code, named `plan.entryPoint` after being compiled (or found) under the placeholder name.
ShaderCode fragmentCode(const std::string& glsl, const ShaderPlan& plan, const CompileOptions& options, const std::vector<Target>& targets,
                        Diagnostics& diagnostics) {
    ShaderPlan placeholder = plan;
    placeholder.entryPoint = kEntryPlaceholder;
    ShaderCode code = cachedCode(glsl, placeholder, options, targets, diagnostics);
    if (!code.spirv.empty()) withEntryPoint(code, plan.entryPoint);
    return code;
}

// The pass-through vertex stage feeding the fragment shader's inputs: its files into `files`, its manifest entry returned.
nlohmann::json vertexStage(const Material& material, const ShaderPlan& plan, const CompileOptions& options,
                           const std::vector<Target>& targets, const std::vector<uint32_t>& fragment, std::vector<OutputFile>& files) {
    const std::vector<Varying> inputs = fragmentInputs(fragment);
    const std::string& frag = plan.entryPoint;
    const std::string entry = (frag.ends_with("_frag") ? frag.substr(0, frag.size() - 5) : frag) + "_vert";
    SpirvResult front = compileToSpirv(generateVertexGlsl(inputs), ShaderStage::Vertex, "hexc/vertex.glsl", SourceLanguage::Glsl, entry);
    SpirvResult optimized = front.words.empty() ? front : optimizeSpirv(front.words);
    if (optimized.words.empty()) throw CompileError{optimized.diagnostics};  // hexc's own code: a bug
    return emitVertexStage(optimized.words, inputs, entry, material.name, options, targets, files);
}

void run(const Material& material, const CompileOptions& options, CompiledMaterial& out) {
    CompileResult& result = out.result;
    out.plan = planShader(material, options);
    const ShaderPlan& plan = out.plan;
    append(result.diagnostics, plan.diagnostics);
    if (hasErrors(plan.diagnostics)) return;
    if (options.lintTextures) append(result.diagnostics, lintMaterial(material));
    if (options.debug && plan.layout.vulkan.combined)
        throw CompileError{{Diagnostic::make(Code::TargetUnsupported, {"--debug"}, "",
                                             "--debug keeps hexc's functions, which take a texture and a sampler apart; combined image "
                                             "samplers (layout vulkan.combined) need the optimised, inlined shader")}};
    const std::vector<Target> targets = sortedTargets(options);
    // The functions output is source to include: no binary module.
    if (plan.functions && std::any_of(targets.begin(), targets.end(), [](Target t) { return targetRow(t).binary; }))
        throw CompileError{{Diagnostic::make(Code::TargetUnsupported, {"--functions"}, "",
                                             "the functions output is source to include in an engine's material: HLSL, GLSL, MSL or WGSL, "
                                             "not SPIR-V")}};
    result.glsl = generateGlsl(plan);
    ShaderCode code = fragmentCode(result.glsl, plan, options, targets, result.diagnostics);
    if (code.spirv.empty()) return;
    result.spirv = std::move(code.spirv);

    nlohmann::json described = nlohmann::json::object();
    const char* stage = plan.functions ? "functions" : "frag";
    for (auto& [t, target] : code.targets) {
        target.target["file"] = shaderFileName(material.name, t, stage);
        if (plan.functions) {
            target.source = functionsOnly(target.source, t, plan.entryPoint);
            for (const char* key : {"entry_point", "stage", "inputs", "outputs"}) target.target.erase(key);
        }
        described[std::string(toString(t))] = std::move(target.target);
        out.sources[t] = std::move(target.source);
    }
    out.manifest = buildManifest(material, plan, described);
    if (plan.functions) out.manifest["functions"] = functionsEntry(plan);
    if (options.vertex) out.manifest["vertex"] = vertexStage(material, plan, options, targets, result.spirv, out.files);
    if (!options.manifestPathsFrom.empty()) out.manifest["source"] = sourcePaths(material, plan, options.manifestPathsFrom);
    if (options.emitGenerated) out.files.push_back({material.name + ".generated.frag", result.glsl});
    out.banner = banner(material, plan, options);
    addBanners(out.files, out.banner);
    if (options.derivedTextures)
        for (OutputFile& f : derivedTextureFiles(material, plan, options.cache)) out.files.push_back(std::move(f));  // images: no banner
}

}  // namespace

CompiledMaterial compileMaterial(const Material& material, const CompileOptions& options) {
    CompiledMaterial out;
    CompileResult& result = out.result;
    try {
        run(material, options, out);
    } catch (const CompileError& e) {
        append(result.diagnostics, e.diagnostics);
    } catch (const spirv_cross::CompilerError& e) {
        result.diagnostics.push_back(
            Diagnostic::make(Code::TargetUnsupported, {material.sourceFile.string()}, "", std::string("SPIRV-Cross: ") + e.what()));
    } catch (const std::bad_alloc&) {  // what the budgets do not foresee (a huge template, many large textures at once)
        result.diagnostics.push_back(Diagnostic::make(Code::OutOfMemory, {material.sourceFile.string()}, "",
                                                      "out of memory compiling this material (docs/cli.md#budgets)"));
    } catch (const std::exception& e) {
        // compileMaterial() never throws: anything else is hexc's own fault, reported as such.
        result.diagnostics.push_back(
            Diagnostic::make(Code::Internal, {material.sourceFile.string()}, "", std::string("internal error: ") + e.what()));
    }
    if (!result.ok()) {
        out.sources.clear();
        out.files.clear();
    }
    return out;
}

CompileResult compile(const Material& material, const CompileOptions& options) {
    CompiledMaterial c = compileMaterial(material, options);
    CompileResult result = std::move(c.result);
    if (!result.ok()) return result;
    const char* stage = c.plan.functions ? "functions" : "frag";
    for (auto& [t, source] : c.sources) result.files.push_back({shaderFileName(material.name, t, stage), std::move(source)});
    addBanners(result.files, c.banner);
    for (OutputFile& f : c.files) result.files.push_back(std::move(f));
    result.files.push_back({material.name + ".manifest.json", c.manifest.dump(2) + "\n"});
    std::sort(result.files.begin(), result.files.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
    return result;
}

}  // namespace hexc
