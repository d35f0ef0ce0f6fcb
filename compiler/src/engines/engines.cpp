// The engine layer (hexc/engines.h): above compile(), which knows no engine. Each package is the compile of the
// material's functions in the engine's language (compileMaterial, typed), written by its row's writer.
#include "hexc/engines.h"

#include <algorithm>
#include <array>
#include <set>

#include "common/by_enum.h"
#include "engines/roles.h"
#include "engines/table.h"
#include "plan/plan.h"

namespace hexc {
namespace {

// In Engine order; a missing row does not compile.
const std::array<EngineRow, kEngineCount>& engineRows() {
    using L = EngineLanguage;
    // engine, name, shown, language, files, uv bottom-left, copies textures, unroll loops, wgsl, writer, arrays
    static const std::array<EngineRow, kEngineCount> rows = byEnum<kLastEngine, EngineRow>({
        {Engine::Godot3, "godot3", "godot3", L::Glsl330, {{"godot3.shader", ".shader"}}, false, false, true, false, glslPackage},
        {Engine::Godot4,
         "godot4",
         "godot4",
         L::Glsl330,
         {{"godot4.gdshader", ".gdshader"}},
         false,
         false,
         false,
         false,
         glslPackage,
         FunctionArrays::All},
        {Engine::Filament, "filament", "filament", L::Glsl330, {{"filament.mat", ".mat"}}, false, false, false, false, glslPackage},
        {Engine::Threejs,
         "threejs",
         "three.js",
         L::GlslEs300,
         {{"package.three.js", ".three.js"}},
         true,
         true,
         false,
         false,
         webPackage,
         FunctionArrays::All},
        {Engine::Babylon,
         "babylon",
         "Babylon.js",
         L::GlslEs300,
         {{"package.babylon.js", ".babylon.js"}},
         true,
         true,
         false,
         true,
         webPackage,
         FunctionArrays::Linear},
        {Engine::Unity,
         "unity",
         "unity",
         L::Hlsl,
         {{"hexc.hlsl", ".hexc.hlsl"}, {"urp.shader", ".shader"}},
         true,
         false,
         false,
         false,
         hlslPackage,
         FunctionArrays::All},
        {Engine::Unreal, "unreal", "unreal", L::Hlsl, {{"hexc.ush", ".ush"}}, false, false, false, false, hlslPackage, FunctionArrays::All},
        {Engine::ThreejsWebgpu,
         "threejs-webgpu",
         "three.js WebGPU",
         L::Wgsl,
         {{"package.webgpu.js", ".three-webgpu.js"}},
         true,
         true,
         false,
         true,
         webPackage},
    });
    return rows;
}

bool asksForWgsl(const CompileOptions& options) {
    return std::find(options.targets.begin(), options.targets.end(), Target::Wgsl) != options.targets.end();
}

// The names of the engines whose row has `what`, as messages list them: "a, b and c".
std::string enginesWith(bool EngineRow::*what) {
    std::vector<std::string> names;
    for (const EngineRow& e : engineRows())
        if (e.*what) names.push_back(e.name);
    std::string out;
    for (size_t i = 0; i < names.size(); ++i) out += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return out;
}

// What the engine refuses of this compile, and why (HX300), or nothing.
std::optional<Diagnostic> refused(const EngineRow& e, const CompileOptions& options) {
    if (!e.wgsl && asksForWgsl(options))
        return Diagnostic::make(Code::TargetUnsupported, {"--targets"}, "",
                                "the " + std::string(e.name) + " package has no WGSL form: --targets wgsl with --engine is for " +
                                    enginesWith(&EngineRow::wgsl) + " (docs/engines.md); leave wgsl out for this engine");
    return std::nullopt;
}

// The target of an engine language's functions.
Target targetOf(EngineLanguage language) {
    switch (language) {
        case EngineLanguage::Hlsl:
            return Target::Hlsl;
        case EngineLanguage::Wgsl:
            return Target::Wgsl;
        default:
            return Target::Glsl;
    }
}

// The functions output a package holds, in the engine's language (and Babylon's WGSL too when --targets names wgsl),
// every setting baked.
CompileOptions packageOptions(const EngineRow& e, CompileOptions options) {
    const bool wgsl = e.wgsl && asksForWgsl(options) && e.language != EngineLanguage::Wgsl;
    options.functions = true;
    options.unrollLoops = e.unrollLoops;
    options.functionArrays = e.arrays;
    options.bake = true;       // the engine's material has no block for hexc's parameters
    options.exrTables = true;  // engines import EXR, not PFM
    options.targets = {targetOf(e.language)};
    if (wgsl) options.targets.push_back(Target::Wgsl);
    options.glslEs = e.language == EngineLanguage::GlslEs300;
    options.glslVersion = options.glslEs ? 300 : 330;
    // The package's manifest sits in "<engine>/": where it says the inputs are, it says so from there.
    if (!options.manifestPathsFrom.empty()) options.manifestPathsFrom /= std::string(e.name);
    return options;
}

// The textures the functions read, bound, in the manifest's (name) order.
std::vector<EngineTexture> textures(const ShaderPlan& plan) {
    std::vector<EngineTexture> out;
    for (size_t i = 0; i < plan.textureCount(); ++i) {
        if (!plan.textureBound(i)) continue;
        EngineTexture t{plan.textureName(i), plan.textureVariable(i)};
        const bool own = i < plan.slots.size() && plan.slots[i].array.empty();
        if (own && plan.slots[i].pack) t.pack = &plan.packs[*plan.slots[i].pack];
        if (own && !plan.slots[i].pack) t.slot = &plan.slots[i];
        if (i >= plan.slots.size()) t.table = &plan.slots[plan.luts[i - plan.slots.size()]];
        if (i < plan.slots.size() && !own)  // an array, bound at its layer 0 slot: as that slot's texture is
            t.array = &*std::find_if(plan.layers->arrays.begin(), plan.layers->arrays.end(),
                                     [&](const LayerArrayPlan& a) { return a.slots.front() == i; });
        const SlotPlan* sampled = t.array ? &plan.slots[i] : t.slot;
        t.srgb = t.pack ? t.pack->srgb : sampled && sampled->slot->colorSpace == ColorSpace::Srgb && !sampled->srgb;
        out.push_back(std::move(t));
    }
    std::sort(out.begin(), out.end(), [](const EngineTexture& a, const EngineTexture& b) { return a.name < b.name; });
    return out;
}

// The package's own files' names, under no folder: its templates', and a web package's copies of the slots' textures.
std::vector<std::string> packageNames(const Material& material, const EngineRow& e, const ShaderPlan& plan) {
    std::vector<std::string> names;
    for (const auto& [templ, suffix] : e.files) names.push_back(material.name + suffix);
    if (e.copiesTextures)
        for (const EngineTexture& t : textures(plan))
            for (const SlotPlan* slot : loadedSlots(plan, t)) names.push_back(textureCopyName(material, *slot->slot));
    return names;
}

// The package's manifest names only files the package holds, or a file outside it from the package's folder: each
// target's `file` is the package file that holds the functions, a slot's `texture` its copy in the package (the web
// packages') or, where the caller says where the package goes (`source`, from CompileOptions::manifestPathsFrom), the
// material's texture from the package's folder, as is a role's KTX2 array file. Histogram tables and packed textures
// are files of the package already.
std::string packageManifest(const Material& material, nlohmann::json manifest, const std::vector<OutputFile>& package) {
    for (auto& [target, entry] : manifest["targets"].items()) entry["file"] = package.front().name;
    for (nlohmann::json& s : manifest["slots"]) {
        const Slot& slot = *std::find_if(material.slots.begin(), material.slots.end(), [&](const Slot& m) { return m.name == s["name"]; });
        const std::string copy = textureCopyName(material, slot);
        if (std::any_of(package.begin(), package.end(), [&](const OutputFile& f) { return f.name == copy; }))
            s["texture"] = copy;
        else if (manifest.contains("source"))
            s["texture"] = manifest["source"]["textures"][slot.name];
    }
    // A KTX2 array a role reads (a package that binds arrays) is its layers' slots' file, named from the package too.
    if (manifest.contains("source") && manifest.contains("layers") && manifest["layers"].contains("arrays"))
        for (nlohmann::json& a : manifest["layers"]["arrays"])
            if (a.contains("file")) a["file"] = manifest["source"]["textures"][a["slots"][0].get<std::string>()];
    return manifest.dump(2) + "\n";
}

}  // namespace

const EngineRow& engineRow(Engine engine) { return engineRows()[size_t(engine)]; }

std::vector<const SlotPlan*> loadedSlots(const ShaderPlan& plan, const EngineTexture& t) {
    if (t.slot) return {t.slot};
    std::vector<const SlotPlan*> out;
    for (size_t i : t.array ? t.array->slots : std::vector<size_t>{}) out.push_back(&plan.slots[i]);
    return out;
}

bool takesVertexColor(const PackageInput& input) {
    return std::any_of(input.functions.begin(), input.functions.end(), [](const EngineFunction& f) { return f.vertexColor; });
}

std::string textureCopyName(const Material& material, const Slot& slot) {
    return material.name + "." + slot.name + slot.texturePath.extension().string();
}

std::string_view toString(Engine engine) { return engineRow(engine).name; }

bool isWebEngine(Engine engine) { return engineRow(engine).copiesTextures; }

std::vector<std::string_view> engineNames() {
    std::vector<std::string_view> out;
    for (const EngineRow& e : engineRows()) out.push_back(e.name);
    return out;
}

std::optional<Engine> engineNamed(std::string_view name) {
    for (const EngineRow& e : engineRows())
        if (name == e.name) return e.engine;
    return std::nullopt;
}

CompileResult compileForEngine(const Material& material, Engine engine, CompileOptions options) {
    const EngineRow& e = engineRow(engine);
    if (std::optional<Diagnostic> d = refused(e, options)) return {{}, {*d}, {}, {}};
    options = packageOptions(e, options);
    CompiledMaterial compiled = compileMaterial(material, options);
    CompileResult& r = compiled.result;  // the writer reads its SPIR-V
    if (!r.ok()) return std::move(r);
    const PackageInput input{material, e, compiled, options, engineFunctions(compiled.plan), textures(compiled.plan)};
    std::vector<OutputFile> package = e.write(input, r.diagnostics);
    if (!r.ok()) return std::move(r);
    const std::string dir = std::string(e.name) + "/";
    compiled.files.push_back({material.name + ".manifest.json", packageManifest(material, compiled.manifest, package)});
    std::sort(compiled.files.begin(), compiled.files.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
    for (OutputFile& f : compiled.files) r.files.push_back({dir + f.name, std::move(f.contents)});
    for (OutputFile& f : package) r.files.push_back({dir + f.name, std::move(f.contents)});
    return std::move(r);
}

OutputNames engineOutputNames(const Material& material, Engine engine, const CompileOptions& options) {
    const EngineRow& e = engineRow(engine);
    const CompileOptions o = packageOptions(e, options);
    OutputNames base = outputNames(material, o), out{{}, base.diagnostics};
    if (hasErrors(out.diagnostics)) return out;
    std::set<std::string> functions;  // the package holds the functions
    for (Target t : o.targets) functions.insert(shaderFileName(material.name, t, "functions"));
    const std::string dir = std::string(e.name) + "/";
    for (const std::string& name : base.names)
        if (!functions.count(name)) out.names.push_back(dir + name);
    for (const std::string& name : packageNames(material, e, planShader(material, o))) out.names.push_back(dir + name);
    return out;
}

CompileResult compilePackages(const Material& material, const std::vector<std::string>& engines, const CompileOptions& options) {
    CompileResult all;
    for (const std::string& name : engines) {
        std::optional<Engine> engine = engineNamed(name);
        CompileResult r = engine ? compileForEngine(material, *engine, options) : CompileResult{};
        if (!engine)
            r.diagnostics.push_back(
                Diagnostic::make(Code::TargetUnsupported, {"--engine"}, "", "hexc has no package for engine `" + name + "`"));
        all.diagnostics.insert(all.diagnostics.end(), r.diagnostics.begin(), r.diagnostics.end());
        for (OutputFile& f : r.files) all.files.push_back(std::move(f));
    }
    if (!all.ok()) all.files.clear();
    std::sort(all.files.begin(), all.files.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
    return all;
}

OutputNames packageOutputNames(const Material& material, const std::vector<std::string>& engines, const CompileOptions& options) {
    OutputNames out;
    for (const std::string& name : engines) {
        const std::optional<Engine> engine = engineNamed(name);
        if (!engine) continue;  // the compile reports it
        OutputNames each = engineOutputNames(material, *engine, options);
        out.names.insert(out.names.end(), each.names.begin(), each.names.end());
        for (const Diagnostic& d : each.diagnostics)  // the same plan's for every engine: once
            if (std::none_of(out.diagnostics.begin(), out.diagnostics.end(), [&](const Diagnostic& o) { return o.format() == d.format(); }))
                out.diagnostics.push_back(d);
    }
    std::sort(out.names.begin(), out.names.end());
    return out;
}

}  // namespace hexc
