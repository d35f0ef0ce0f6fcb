#include "vk/render.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "hexc/histogram.h"
#include "hexc/spirv.h"
#include "vk/shaders.h"

namespace hexc::vk {
namespace {

std::vector<uint32_t> spirvOrThrow(SpirvResult r) {
    if (r.words.empty()) throw CompileError{std::move(r.diagnostics)};
    return r.words;
}

const std::vector<uint32_t>& vertexShader() {
    static const std::vector<uint32_t> words = spirvOrThrow(
        compileToSpirv(harnessShaders().at("fullscreen.vert.glsl"), ShaderStage::Vertex, "templates/harness/fullscreen.vert.glsl"));
    return words;
}

const std::string& outputFile(const CompileResult& r, const std::string& suffix) {
    for (const OutputFile& f : r.files)
        if (f.name.ends_with(suffix)) return f.contents;
    throw std::logic_error("compile produced no " + suffix);
}

void setView(RenderRequest& request, const View& view) {
    request.width = view.width;
    request.height = view.height;
    request.uvRect = {float(view.uvRect[0]), float(view.uvRect[1]), float(view.uvRect[2]), float(view.uvRect[3])};
}

}  // namespace

Image renderShader(Runner& runner, const std::string& templateFile, const std::vector<uint8_t>& uniforms, const View& view) {
    RenderRequest request;
    request.fragmentSpirv =
        spirvOrThrow(compileToSpirv(harnessShaders().at(templateFile), ShaderStage::Fragment, "templates/harness/" + templateFile));
    request.uniformData = uniforms;
    return renderFragment(runner, std::move(request), view);
}

Image renderFragment(Runner& runner, RenderRequest request, const View& view, std::vector<double>* frameMs) {
    request.vertexSpirv = vertexShader();
    setView(request, view);
    RenderResult result = runner.render(request);
    if (frameMs) *frameMs = std::move(result.frameMs);
    return std::move(result.image);
}

namespace {

// The slot an output shows, by kind only (slotForOutput adds what the projection rules out).
const Slot& fittingSlot(const Material& material, RenderOutput output, const std::string& slotName) {
    auto fits = [&](const Slot& s) {
        switch (output) {
            case RenderOutput::Albedo:
                return !kindRow(s.kind).derivative;
            case RenderOutput::Normal:
            case RenderOutput::Derivative:
                return kindRow(s.kind).derivative;
            default:
                return true;
        }
    };
    const char* what = output == RenderOutput::Albedo ? "color or scalar slot" : output == RenderOutput::Weights ? "slot" : "normal slot";
    if (!slotName.empty()) {
        for (const Slot& s : material.slots) {
            if (s.name != slotName) continue;
            if (!fits(s))
                throw std::invalid_argument("slot `" + slotName + "` is of kind " + std::string(toString(s.kind)) +
                                            "; this output needs a " + what);
            return s;
        }
        throw std::invalid_argument("material `" + material.name + "` has no slot `" + slotName + "`");
    }
    std::string preferred = output == RenderOutput::Albedo ? "albedo" : output == RenderOutput::Weights ? "" : "normal";
    for (const Slot& s : material.slots)
        if (s.name == preferred && fits(s)) return s;
    for (const Slot& s : material.slots)
        if (fits(s)) return s;
    throw std::invalid_argument("material `" + material.name + "` has no " + what);
}

}  // namespace

const Slot& slotForOutput(const Material& material, RenderOutput output, const std::string& slotName) {
    const Slot& s = fittingSlot(material, output, slotName);
    // A triplanar normal slot returns a world-space surface gradient, which no tangent-space encoding shows.
    if (output == RenderOutput::Normal && s.hex.projection == Projection::Triplanar)
        throw std::invalid_argument("slot `" + s.name +
                                    "` is triplanar: it returns a world-space surface gradient; use the derivative output");
    return s;
}

std::optional<size_t> layerRole(const Material& material, const std::string& name) {
    if (!material.layers) return std::nullopt;
    const std::vector<Layers::Role>& roles = material.layers->roles;
    const auto it = std::find_if(roles.begin(), roles.end(), [&](const Layers::Role& r) { return r.name == name; });
    return it == roles.end() ? std::nullopt : std::optional<size_t>(size_t(it - roles.begin()));
}

Material layerRoleFirst(Material m, size_t role) {
    Layers& l = *m.layers;
    const auto r = std::ptrdiff_t(role);
    std::rotate(l.roles.begin(), l.roles.begin() + r, l.roles.begin() + r + 1);
    for (Layers::Layer& layer : l.layers) std::rotate(layer.slots.begin(), layer.slots.begin() + r, layer.slots.begin() + r + 1);
    if (l.heightRole) l.heightRole = *l.heightRole == role ? 0 : *l.heightRole < role ? *l.heightRole + 1 : *l.heightRole;
    m.templ = TemplateRef::builtin("value");
    return m;
}

Material renderedMaterial(const Material& material, RenderOutput output, const std::string& slotName) {
    if (output == RenderOutput::Shaded) return material;
    if (const std::optional<size_t> role = layerRole(material, slotName); role && output != RenderOutput::Weights) {
        const bool derivative = kindRow(material.layers->roles[*role].kind).derivative;
        if (derivative != (output != RenderOutput::Albedo))
            throw std::invalid_argument("role `" + slotName + "` is of kind " + std::string(toString(material.layers->roles[*role].kind)) +
                                        "; this output needs a " + (derivative ? "color or scalar role" : "normal role"));
        return layerRoleFirst(material, *role);
    }
    Material m = material;
    const Slot& shown = slotForOutput(material, output, slotName);
    m.slots = {shown};
    m.layers.reset();  // a slot output shows that slot alone, not a layered material's blend
    // A height-blended slot also reads its height slot's texture.
    for (const Slot& s : material.slots)
        if (shown.heightBlend && s.name == shown.heightBlend->slot && s.name != shown.name) m.slots.push_back(s);
    m.templ = TemplateRef::builtin(output == RenderOutput::Weights ? "weights" : "value");
    return m;
}

// The built-in template a material is shown with when its own declares resources only an engine can fill.
constexpr const char* kFallbackTemplate = "lit";

Material shownMaterial(Material material, const std::string& templateName, const CompileOptions& options, std::string* note) {
    if (!templateName.empty()) material.templ = TemplateRef::parse(templateName);
    CompileOptions spirvOnly = options;
    spirvOnly.targets = {Target::Spirv};
    CompileResult compiled = compile(material, spirvOnly);
    if (!compiled.ok()) throw CompileError{compiled.diagnostics};
    return shownMaterial(std::move(material), compiled, note);
}

Material shownMaterial(Material material, const CompileResult& compiled, std::string* note) {
    // Every target's entry lists the same resources of the template's (each reflects the one SPIR-V module).
    const nlohmann::json targets = nlohmann::json::parse(outputFile(compiled, ".manifest.json"))["targets"];
    const nlohmann::json own = targets.begin()->value("template_resources", nlohmann::json());
    note->clear();
    if (own.empty()) return material;
    std::string names;
    for (const nlohmann::json& r : own) names += (names.empty() ? "" : ", ") + r["name"].get<std::string>();
    *note = "template `" + material.templ.written() + "` declares resources of its own (" + names +
            "): shown with the built-in template `" + kFallbackTemplate + "`";
    material.templ = TemplateRef::builtin(kFallbackTemplate);
    return material;
}

Material plainTiled(Material material) {
    for (Slot& s : material.slots) s.hex.enabled = false;
    return material;
}

std::vector<uint8_t> packParameters(const nlohmann::json& manifest, const ParameterValues& parameters) {
    const auto& params = manifest["parameters"];
    std::vector<uint8_t> bytes(params["size"].get<size_t>(), 0);
    for (const auto& m : params["members"]) {
        const bool integer = m["type"].get<std::string>()[0] == 'i';
        nlohmann::json values = m["value"].is_array() ? m["value"] : nlohmann::json::array({m["value"]});
        // A member is set by its name or any of its aliases (other slots' names for a shared setting).
        std::vector<std::string> names = {m["name"]};
        if (m.contains("aliases")) names.insert(names.end(), m["aliases"].begin(), m["aliases"].end());
        for (const std::string& name : names)
            if (auto it = parameters.find(name); it != parameters.end()) values = it->second;
        uint8_t* at = bytes.data() + m["offset"].get<size_t>();
        for (const auto& v : values) {
            // int32 and float32 are both 4 bytes in std140.
            if (integer) {
                int32_t i = v.get<int32_t>();
                std::memcpy(at, &i, 4);
            } else {
                float f = v.get<float>();
                std::memcpy(at, &f, 4);
            }
            at += 4;
        }
    }
    return bytes;
}

namespace {

// The manifest's name of the target whose output is executed.
const char* manifestTarget(ExecutedTarget target) {
    return target == ExecutedTarget::Glsl ? "glsl" : target == ExecutedTarget::Hlsl ? "hlsl" : "spirv";
}

// The Vulkan binding glslang gives an HLSL register ("t3": kHlslTextureShift + 3; spirv.h).
uint32_t hlslBinding(const std::string& reg) {
    const uint32_t n = uint32_t(std::stoul(reg.substr(1)));
    return n + (reg[0] == 's' ? kHlslSamplerShift : reg[0] == 't' ? kHlslTextureShift : reg[0] == 'u' ? kHlslUavShift : 0);
}

// The lowest of hexc's textures' bindings in a target's manifest entry, each read by `binding` (they are
// consecutive); UINT32_MAX when there are none.
uint32_t lowestTexture(const nlohmann::json& target, uint32_t (*binding)(const nlohmann::json&)) {
    uint32_t lowest = UINT32_MAX;
    for (const auto& [slot, where] : target["textures"].items()) lowest = std::min(lowest, binding(where));
    return lowest;
}

// hexc's own resources where the executed target's manifest entry puts them.
void bindHexcs(const nlohmann::json& manifest, ExecutedTarget target, RenderRequest& request) {
    if (target == ExecutedTarget::Hlsl) {
        const nlohmann::json& hlsl = manifest["targets"]["hlsl"];
        request.set = hlsl["sampler"]["space"];
        request.samplerBinding = hlslBinding(hlsl["sampler"]["register"]);
        request.paramsBinding = hlsl.contains("params") ? hlslBinding(hlsl["params"]["register"]) : request.samplerBinding + 1;
        request.firstTextureBinding = lowestTexture(hlsl, [](const nlohmann::json& t) { return hlslBinding(t["register"]); });
        return;
    }
    if (target == ExecutedTarget::Glsl) {  // OpenGL block bindings and texture units, as compileToSpirv maps them
        const nlohmann::json& glsl = manifest["targets"]["glsl"];
        request.set = 0;
        request.samplerBinding = kGlDefaultBlockBinding + 1;  // unread: OpenGL combines the sampler into each texture
        // Bound by name (GLSL 330, ES 3.00): the manifest's units are hexc's suggestion, and glslang's auto-mapping
        // numbers blocks and units in declaration order, which is where they are for one slot.
        request.paramsBinding = glsl.contains("params") ? glsl["params"].value("binding", 0u) : request.samplerBinding + 1;
        request.firstTextureBinding =
            lowestTexture(glsl, [](const nlohmann::json& t) { return kGlTextureShift + t["texture_unit"].get<uint32_t>(); });
        return;
    }
    // hexc's block at binding b, the sampler at b + 1 (unused with layout vulkan.combined), textures from b + 2.
    const nlohmann::json& spirv = manifest["targets"]["spirv"];
    request.combinedSamplers = spirv["sampler"].contains("combined_into_textures");
    uint32_t base = 0;
    if (!request.combinedSamplers) {
        request.set = spirv["sampler"]["set"];
        base = spirv["sampler"]["binding"].get<uint32_t>() - 1;
    } else if (spirv.contains("params")) {
        request.set = spirv["params"]["set"];
        base = spirv["params"]["binding"];
    } else if (!spirv["textures"].empty()) {
        request.set = spirv["textures"].begin().value()["set"];  // hexc's resources share one set
        base = lowestTexture(spirv, [](const nlohmann::json& t) { return t["binding"].get<uint32_t>(); }) - 2;
    }
    request.paramsBinding = base;
    request.samplerBinding = base + 1;
    request.firstTextureBinding = base + 2;
}

// One template resource as a target's manifest entry places it: SPIR-V as declared; HLSL in its registers, a
// sampler2D split into a texture and a SamplerState, push constants a cbuffer that keeps their offsets; OpenGL GLSL
// at its block binding or texture unit (a separate texture combined with its sampler), push constants loose uniforms.
void placeTemplateResource(const nlohmann::json& r, ExecutedTarget target, const TemplateInputs& own, RenderRequest& request) {
    using Kind = TemplateResource::Kind;
    if (r["kind"] == "push_constant") {
        if (target == ExecutedTarget::Spirv) {  // the runner's fragment range starts at byte 16: the manifest's must too
            if (r["offset"] != 16 || r["size"] != own.pushConstants.size())
                throw std::invalid_argument("the manifest's push constant range " + r["offset"].dump() + "+" + r["size"].dump() +
                                            " is not the fragment range the harness pushes (16+" +
                                            std::to_string(own.pushConstants.size()) + ")");
            request.fragmentPushConstants = own.pushConstants;
        } else if (target == ExecutedTarget::Glsl) {  // a struct uniform: its std140 offsets are the block's from byte 16
            request.templateResources.push_back({Kind::UniformBuffer, 0, kGlDefaultBlockBinding, own.pushConstants, nullptr});
        } else {
            TemplateResource block{Kind::UniformBuffer, request.set, hlslBinding(r["register"]), std::vector<uint8_t>(16), nullptr};
            block.data.insert(block.data.end(), own.pushConstants.begin(), own.pushConstants.end());
            request.templateResources.push_back(std::move(block));
        }
        return;
    }
    if (r.value("combined_into_textures", false)) return;  // OpenGL: bound with its texture
    // The caller gives the data and images; the descriptor types come from the manifest alone, as an engine that
    // builds its VkDescriptorSetLayouts from it takes them.
    static const std::map<std::string, Kind> kinds = {{"UNIFORM_BUFFER", Kind::UniformBuffer},
                                                      {"COMBINED_IMAGE_SAMPLER", Kind::CombinedImageSampler},
                                                      {"SAMPLED_IMAGE", Kind::SampledImage},
                                                      {"SAMPLER", Kind::Sampler}};
    TemplateResource placed = own.resources.at(r["name"]);
    placed.kind = kinds.at(r["vulkan"]["descriptor_type"]);
    if (target == ExecutedTarget::Spirv) {
        placed.set = r["vulkan"]["set"];
        placed.binding = r["vulkan"]["binding"];
    } else if (target == ExecutedTarget::Glsl) {
        placed.set = 0;
        if (r.contains("texture_unit")) {
            placed.kind = Kind::CombinedImageSampler;
            placed.binding = kGlTextureShift + r["texture_unit"].get<uint32_t>();
        } else {
            placed.binding = r["binding"];
        }
    } else {
        placed.set = r["space"];
        placed.binding = hlslBinding(r["register"]);
        if (r.contains("sampler_register")) {
            placed.kind = Kind::SampledImage;
            request.templateResources.push_back({Kind::Sampler, placed.set, hlslBinding(r["sampler_register"]), {}, nullptr});
        }
    }
    request.templateResources.push_back(std::move(placed));
}

// The template's resources where the executed target's manifest says. A shader whose template
// declares resources `own` does not provide cannot be drawn (unbound descriptors are undefined behaviour, and
// lavapipe crashes): std::invalid_argument naming them.
void bindTemplateInputs(const nlohmann::json& manifest, ExecutedTarget target, const TemplateInputs& own, RenderRequest& request) {
    const nlohmann::json listed = manifest["targets"][manifestTarget(target)].value("template_resources", nlohmann::json::array());
    std::string missing;
    for (const nlohmann::json& r : listed) {
        const bool given = r["kind"] == "push_constant" ? !own.pushConstants.empty() : own.resources.count(r["name"]) > 0;
        if (!given) missing += (missing.empty() ? "" : ", ") + r["name"].get<std::string>();
    }
    if (!missing.empty())
        throw std::invalid_argument("template " + manifest["template"].get<std::string>() + " declares resources of its own (" + missing +
                                    ") that only the engine can bind; render a slot output instead (--output albedo, normal, ...)");
    if (listed.size() != own.resources.size() + (own.pushConstants.empty() ? 0 : 1))
        throw std::invalid_argument("a template resource given is not in the manifest");
    for (const nlohmann::json& r : listed) placeTemplateResource(r, target, own, request);
}

// The packed texture `name` as the engine loads it: the PNG the compile wrote, in the colour space the manifest gives.
Texture packedTexture(const nlohmann::json& manifest, const CompileResult& compiled, const std::string& name) {
    for (const nlohmann::json& p : manifest["packed_textures"])
        if (p["name"] == name) return decodeTexture(outputFile(compiled, p["file"].get<std::string>()), p["colorspace"] == "srgb");
    throw std::logic_error("the manifest lists no packed texture " + name);
}

// D3D matches stage inputs by semantic, but glslang numbers HLSL inputs in declaration order: each `: TEXCOORD<n>`
// input gets [[vk::location(n)]], where the harness's vertex stage writes it (a layered material's vertex colour sits
// after a gap in the template's locations).
std::string pinnedInputLocations(const std::string& hlsl) {
    static const std::regex input(R"(^(\s*)(\w+ \w+ : TEXCOORD(\d+);))");
    std::istringstream in(hlsl);
    std::string out;
    for (std::string line; std::getline(in, line);) out += std::regex_replace(line, input, "$1[[vk::location($3)]] $2") + "\n";
    return out;
}

// The executed target's fragment shader as SPIR-V: the .spv file, or the HLSL or OpenGL GLSL source compiled again.
void setFragmentShader(RenderRequest& request, const CompileResult& compiled, const nlohmann::json& manifest, const Material& m,
                       ExecutedTarget target, const CompileOptions& options) {
    switch (target) {
        case ExecutedTarget::Spirv:  // the .spv file, as an engine loads it (combined samplers are in it only)
            request.fragmentSpirv = spirvWords(outputFile(compiled, ".spv"));
            break;
        case ExecutedTarget::Hlsl:
            request.fragmentSpirv =
                spirvOrThrow(optimizeSpirv(spirvOrThrow(compileToSpirv(pinnedInputLocations(outputFile(compiled, ".hlsl")),
                                                                       ShaderStage::Fragment, m.name + ".frag.hlsl", SourceLanguage::Hlsl,
                                                                       manifest["targets"]["hlsl"]["entry_point"], options.layout)),
                                           false, true));
            break;
        case ExecutedTarget::Glsl:
            request.fragmentSpirv = spirvOrThrow(
                optimizeSpirv(spirvOrThrow(compileToSpirv(outputFile(compiled, ".glsl"), ShaderStage::Fragment, m.name + ".frag.glsl",
                                                          SourceLanguage::OpenGlGlsl, "main", options.layout))));
            request.combinedSamplers = true;
            break;
    }
}

// Textures in manifest order, which is binding order; a histogram slot's Gaussian texture in its place, its look-up
// table after every slot's (as the manifest lists them); a packed texture, as the compile wrote it, in its first
// slot's place (the other slots' own textures in theirs, which the shader does not read).
std::vector<Texture> boundTextures(const nlohmann::json& manifest, const CompileResult& compiled, const Material& m) {
    std::vector<Texture> textures, luts;
    for (const auto& s : manifest["slots"]) {
        for (const Slot& slot : m.slots) {
            if (slot.name != s["name"]) continue;
            Texture t = s.contains("packed") && s["packed"]["texture"] == slot.name + ".packed"
                            ? packedTexture(manifest, compiled, slot.name + ".packed")
                            : loadTexture(slot.texturePath, slot.samplerDecodes(), slot.textureLayer);
            if (s.contains("histogram")) {
                HistogramTransform h = histogramTransform(t, slot);
                t = std::move(h.gaussian);
                luts.push_back(std::move(h.lut));
            }
            textures.push_back(std::move(t));
        }
    }
    textures.insert(textures.end(), std::make_move_iterator(luts.begin()), std::make_move_iterator(luts.end()));
    return textures;
}

// Per bound texture, the layers of a 2D array texture (the manifest's `array` of its slots, docs/cli.md): at its layer
// 0 slot's place, the slots' own textures in layer order; empty for a 2D texture.
std::vector<std::vector<const Texture*>> textureArrays(const nlohmann::json& manifest, const std::vector<Texture>& textures) {
    const nlohmann::json& slots = manifest["slots"];
    std::map<std::string, size_t> at;  // an array's name -> its layer 0 slot's place
    for (size_t i = 0; i < slots.size(); ++i)
        if (slots[i].contains("array") && slots[i]["array"]["layer"] == 0) at[slots[i]["array"]["texture"]] = i;
    std::vector<std::vector<const Texture*>> arrays(slots.size());
    for (size_t i = 0; i < slots.size(); ++i) {
        if (!slots[i].contains("array")) continue;
        std::vector<const Texture*>& layers = arrays[at.at(slots[i]["array"]["texture"])];
        const size_t layer = slots[i]["array"]["layer"];
        layers.resize(std::max(layers.size(), layer + 1));
        layers[layer] = &textures[i];
    }
    return arrays;
}

}  // namespace

Image render(Runner& runner, const Material& material, RenderOutput output, const std::string& slotName, const View& view,
             ExecutedTarget target, int timedFrames, std::vector<double>* frameMs, const ParameterValues& parameters,
             const CompileOptions& compileOptions, const TemplateInputs& own) {
    Material m = renderedMaterial(material, output, slotName);
    CompileOptions options = compileOptions;
    options.targets = {Target::Spirv, target == ExecutedTarget::Hlsl ? Target::Hlsl : Target::Glsl};
    CompileResult compiled = compile(m, options);
    if (!compiled.ok()) throw CompileError{compiled.diagnostics};
    nlohmann::json manifest = nlohmann::json::parse(outputFile(compiled, ".manifest.json"));

    RenderRequest request;
    request.vertexSpirv = vertexShader();
    setFragmentShader(request, compiled, manifest, m, target, options);
    // Bound where the manifest says, as an engine would.
    bindHexcs(manifest, target, request);
    // glslang keeps an HLSL entry point's name; OpenGL GLSL's is `main`.
    request.fragmentEntry = manifest["targets"][manifestTarget(target)]["entry_point"];
    request.uniformData = packParameters(manifest, parameters);
    bindTemplateInputs(manifest, target, own, request);
    const std::vector<Texture> textures = boundTextures(manifest, compiled, m);
    for (const Texture& t : textures) request.textures.push_back(&t);
    request.textureArrays = textureArrays(manifest, textures);
    setView(request, view);
    request.timedFrames = timedFrames;
    RenderResult result = runner.render(request);
    if (frameMs) *frameMs = result.frameMs;

    if (output == RenderOutput::Normal) derivativeToNormalMap(result.image);
    return std::move(result.image);
}

void derivativeToNormalMap(Image& image) {
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        float* p = &image.rgba[i];
        float len = std::sqrt(p[0] * p[0] + p[1] * p[1] + 1.0f);
        p[0] = -p[0] / len * 0.5f + 0.5f;
        p[1] = -p[1] / len * 0.5f + 0.5f;
        p[2] = 1.0f / len * 0.5f + 0.5f;
        p[3] = 1.0f;
    }
}

}  // namespace hexc::vk
