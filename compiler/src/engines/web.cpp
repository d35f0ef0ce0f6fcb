// The web engines' packages (three.js, Babylon.js; docs/engines.md): the engine's ES module
// (compiler/integrations/<engine>/package.<engine>.js) filled with the material's functions in GLSL ES 3.00 (or WGSL:
// three.js's WebGPURenderer, package.webgpu.js), the textures they read and the engine input each slot fills; beside it,
// the slots' textures it loads.
#include <nlohmann/json.hpp>
#include <spirv_glsl.hpp>

#include "common/templates.h"
#include "engines/roles.h"
#include "engines/table.h"
#include "hexc/image.h"
#include "hexc/suggest.h"

namespace hexc {
namespace {

// The browser decodes the textures (an Image element): PNG, JPEG or WebP, 8 bits per channel.
bool browserImage(const std::filesystem::path& file) {
    const std::string extension = lowerCase(file.extension().string());
    return extension == ".png" || extension == ".jpg" || extension == ".jpeg" || extension == ".webp";
}

Diagnostic unloadable(const PackageInput& in, const std::string& what) {
    return Diagnostic::make(
        Code::TargetUnsupported, {in.material.sourceFile.string()}, "",
        std::string(in.engine.shown) + " packages load textures with the browser's image decoder (PNG, JPEG or WebP): " + what);
}

// Each texture the functions read, as the module loads it: its file beside the module (an array: its layers' files,
// which the module stacks), its sampler uniform, its colour space as the sampler decodes it.
nlohmann::json textures(const PackageInput& in, Diagnostics& diagnostics) {
    nlohmann::json out = nlohmann::json::array();
    for (const EngineTexture& t : in.textures) {
        if (t.table) {
            diagnostics.push_back(
                unloadable(in, "the histogram blend's tables are float (slot `" + t.table->name + "`; blend it by falloff)"));
            continue;
        }
        if (t.array && !t.array->ktx2.empty()) {  // said once for the role, not per layer's slot
            diagnostics.push_back(unloadable(in, "role `" + t.array->role + "` reads the KTX2 array " + t.array->ktx2 +
                                                     " (give each layer's `" + t.array->role + "` a PNG, JPEG or WebP file)"));
            continue;
        }
        nlohmann::json files = nlohmann::json::array();
        for (const SlotPlan* slot : loadedSlots(in.compiled.plan, t)) {
            if (!browserImage(slot->slot->texturePath))
                diagnostics.push_back(
                    unloadable(in, "slot `" + slot->name + "` reads `" + slot->slot->texturePath.filename().string() + "`"));
            files.push_back(textureCopyName(in.material, *slot->slot));
        }
        if (t.pack) files.push_back(packedFileName(in.material.name, in.compiled.plan.slots[t.pack->slots.front()].name));
        nlohmann::json entry = {{"uniform", t.uniform}, {"colorspace", t.srgb ? "srgb" : "linear"}};
        if (t.array)
            entry["layers"] = files;
        else
            entry["file"] = files.front();
        out.push_back(std::move(entry));
    }
    return out;
}

// The uniform of the texture a slot reads: its own, the packed texture or the layered role's array that holds it.
std::string uniformOf(const SlotPlan& slot, const PackageInput& in) {
    const PackPlan* pack = slot.pack ? &in.compiled.plan.packs[*slot.pack] : nullptr;
    for (const EngineTexture& t : in.textures)
        if (t.slot == &slot || (pack && t.pack == pack) || (t.array && !slot.array.empty() && t.uniform == slot.array)) return t.uniform;
    return "";  // a slot that reads no texture of its own (none does today)
}

// SPIRV-Cross's GLSL ES without its header: the engine writes its own #version, and a default precision statement
// would change the engine's own code after the functions (each declaration carries its precision).
class WebGlsl : public spirv_cross::CompilerGLSL {
public:
    using CompilerGLSL::CompilerGLSL;

protected:
    void emit_header() override {}
};

}  // namespace

std::vector<OutputFile> webPackage(const PackageInput& in, Diagnostics& diagnostics) {
    const CompiledMaterial& c = in.compiled;
    nlohmann::json data = {
        {"material", in.material.name}, {"uv_origin", toString(in.options.uvOrigin)}, {"textures", textures(in, diagnostics)}};
    if (c.sources.count(Target::Glsl)) {  // WebGPU's package has none
        WebGlsl glsl(c.result.spirv);
        data["glsl"] = c.banner + "\n" + glslFunctions(glsl, in);
    }
    if (c.sources.count(Target::Wgsl)) data["wgsl"] = c.banner + c.sources.at(Target::Wgsl);
    // The slots the engine fills (name, role, the call of their function with UV for the uv and COLOR for the vertex
    // colour, their texture's uniform), and those it has no input for; vertex_color: some call takes the colour.
    data["vertex_color"] = takesVertexColor(in);
    data["slots"] = data["unmapped"] = nlohmann::json::array();
    for (const WiredFunction& w : wire(in.material, in.functions, in.engine, diagnostics)) {
        const SlotPlan& slot = *w.function.slot;
        if (!w.input && kindRow(slot.kind).derivative && !w.function.tangentNormal) continue;  // the engine takes the normal
        if (!w.input) {
            data["unmapped"].push_back(slot.name);
            continue;
        }
        data["slots"].push_back({{"name", slot.name},
                                 {"role", w.role},
                                 {"call", w.function.name + (w.function.vertexColor ? "(UV, COLOR)" : "(UV)")},
                                 {"uniform", uniformOf(slot, in)}});
    }
    const auto& [templ, suffix] = in.engine.files.front();
    const std::string marker = "/* hexc:data */ null", shared = "/* hexc:textures */";
    std::string module = *embeddedText(templ);
    module.replace(module.find(marker), marker.size(), data.dump(2));
    // The three.js packages' one copy of their texture loading (threejs/textures.three.js).
    if (const size_t at = module.find(shared); at != std::string::npos)
        module.replace(at, shared.size(), *embeddedText("textures.three.js"));
    std::vector<OutputFile> files = {{in.material.name + suffix, std::move(module)}};
    for (const EngineTexture& t : in.textures)
        for (const SlotPlan* slot : loadedSlots(in.compiled.plan, t))  // the bytes the parser read
            files.push_back({textureCopyName(in.material, *slot->slot), slot->slot->file->bytes});
    return files;
}

}  // namespace hexc
