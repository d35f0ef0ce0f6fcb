#include <sstream>

#include "backends/backends.h"
#include "hexc/histogram.h"

namespace hexc {

namespace {

// A histogram slot's derived textures (hexc/histogram.h): the files hexc writes and how an engine binds them, in
// structured fields (docs/manifest.schema.json).
nlohmann::json histogramEntry(const std::string& material, const std::string& slot, const std::string& texture, bool exr) {
    // PFM holds RGB float32, EXR RGBA; upload as RGBA float (PFM's alpha 1). Linear values: no sRGB format.
    const nlohmann::json format = {{"container", exr ? "exr" : "pfm"},
                                   {"channels", exr ? "rgba" : "rgb"},
                                   {"type", "float32"},
                                   {"upload", "rgba32f"},
                                   {"colorspace", "linear"}};
    return {{"gaussian",
             {{"file", histogramFileName(material, slot, "gaussian", exr)},
              {"format", format},
              // In place of the slot's own texture, at its binding: hexc's sampler over a full mip chain.
              {"binding", {{"texture", slot}, {"replaces", texture}, {"sampler", "hexcSampler"}, {"mip_chain", "full"}}}}},
            {"lut",
             {{"file", histogramFileName(material, slot, "lut", exr)},
              {"format", format},
              // Its own texture in each target's `textures`; only level 0 is read.
              {"binding", {{"texture", slot + ".lut"}, {"sampler", "hexcSampler"}, {"mip_chain", "level0"}}}}}};
}

// A packed texture (docs/material-format.md#pack): its file, colour space, size and which channels each slot reads.
nlohmann::json packedEntry(const std::string& material, const ShaderPlan& plan, const PackPlan& p) {
    const std::string first = plan.slots[p.slots.front()].name;
    nlohmann::json slots = nlohmann::json::object();
    for (size_t k = 0; k < p.slots.size(); ++k) slots[plan.slots[p.slots[k]].name] = p.channels[k];
    // An sRGB format decodes RGB only: alpha stays linear. The file holds level 0; the engine builds the chain.
    return {{"name", first + ".packed"},
            {"file", packedFileName(material, first)},
            {"format", {{"container", "png"}, {"channels", "rgba"}, {"type", "unorm8"}, {"alpha", "linear"}, {"levels_in_file", 1}}},
            {"colorspace", p.srgb ? "srgb" : "linear"},
            {"size", {p.width, p.height}},
            {"slots", slots},
            // At slot `first`'s binding in each target's textures; the other packed slots' bindings stay unused.
            {"binding", {{"texture", first + ".packed"}, {"slot", first}, {"sampler", "hexcSampler"}, {"mip_chain", "full"}}}};
}

// Every setting a slot was compiled with, as the material format names it (docs/material-format.md): the values as
// the material wrote them (the parameters' initial values), and what the plan decided of them, the taps, from the plan.
nlohmann::json hextilingEntry(const HexTiling& h, const SlotPlan& sp) {
    return {{"enabled", h.enabled},
            {"tiling", {h.tiling[0], h.tiling[1]}},
            {"rotation", h.rotation},
            {"falloff", h.falloff},
            {"falloffcontrast", h.falloffcontrast},
            {"exponent", h.exponent},
            {"mode", toString(h.mode)},
            {"split_coordinates", h.splitCoordinates},
            {"mask", toString(h.mask)},
            {"maskscale", h.maskScale},
            {"taps", sp.adaptive ? nlohmann::json("adaptive") : nlohmann::json(sp.taps)},
            {"blend", toString(h.blend)},
            {"lod", toString(h.lod)},
            {"projection", toString(h.projection)},
            {"planesharpness", h.planeSharpness},
            {"rotationrange", {h.rotationRange[0], h.rotationRange[1]}},
            {"rotationsteps", h.rotationSteps},
            {"scalerange", {h.scaleRange[0], h.scaleRange[1]}},
            {"offset", h.offset},
            {"offsetsteps", {h.offsetSteps[0], h.offsetSteps[1]}}};
}

// The slot's entry. What the shader does with the slot (its kind, taps, flip, sRGB decoding, luma weights, height
// map) is the plan's; the texture's file, size, colour space and channel and the settings' values are the material's
// (a packed slot's plan reads another channel, of the packed texture: its entry in packed_textures).
nlohmann::json slotEntry(const std::string& material, const SlotPlan& sp, bool exrTables) {
    const Slot& s = *sp.slot;
    const HexTiling& h = s.hex;
    const SlotKindRow& kind = kindRow(sp.kind);
    const std::string channel(1, "rgba"[s.channel]);
    nlohmann::json slot = {
        {"name", sp.name},
        {"kind", toString(sp.kind)},
        {"texture", s.texture},
        {"size", {s.width, s.height}},
        {"colorspace", toString(s.colorSpace)},
        {"hextiling", hextilingEntry(h, sp)},
    };
    if (h.mode == HashMode::MaterialX && !kind.derivative) slot["hextiling"]["lumacoeffs"] = sp.luma;
    // MaterialX mode filters an sRGB texture's stored texels: bind it with a linear (UNORM) format; the shader decodes.
    if (sp.srgb) slot["decode"] = "shader";
    if (s.heightBlend) slot["height_blend"] = {{"slot", sp.heightMapName}, {"width", s.heightBlend->width}};
    // Bound for another slot's height blending only: the shader has no function for it.
    if (sp.heightOnly) slot["height_map_only"] = true;
    if (sp.histogram) slot["histogram"] = histogramEntry(material, sp.name, s.texture, exrTables);
    if (kind.oneChannel) slot["channel"] = channel;
    if (kind.derivative) slot["flip_y"] = sp.flipY;
    if (kind.derivative) slot["normal_green"] = sp.flipY ? "down (DirectX)" : "up (OpenGL)";
    // The texture channels the shader reads: what a packing tool may not reuse.
    slot["reads"] = kind.oneChannel ? channel : kind.reads;
    return slot;
}

// The template's own words on its stage inputs: its comment from "// Stage inputs:" to the next line that is not a
// continuation of it (empty when it has none).
std::string stageInputs(const std::string& templateSource) {
    const size_t at = templateSource.find("// Stage inputs:");
    if (at == std::string::npos) return "";
    std::istringstream in(templateSource.substr(at + 17));
    std::string text, line;
    for (bool first = true; std::getline(in, line); first = false) {
        if (!first && (!line.starts_with("// ") || line.starts_with("// hexc slot") || line.starts_with("// Slots"))) break;
        text += (text.empty() ? "" : " ") + (first ? line : line.substr(3));
    }
    return text;
}

// What the shader's inputs and outputs mean: uv origin and direction, normal maps, tangent sign, colour spaces
// (docs/conventions.md).
nlohmann::json conventionsEntry(const ShaderPlan& plan) {
    const bool up = plan.uvBottomLeft;
    return {{"uv_origin", up ? "bottom-left" : "top-left"},
            {"v_direction", up ? "up the image" : "down the image"},
            {"texture_rows", "uploaded as the file stores them, top row first (no flip)"},
            {"normal_maps", "green up (OpenGL) unless the slot's flip_y (green down, DirectX): slots[].normal_green"},
            {"tangent_sign", "the bitangent cross(N, T) * w runs along +v of the uv the shader takes (MikkTSpace)"},
            {"derivative", "a normal slot's value: (dH/du, dH/dy), y up the image"},
            {"tangent_normal", "x along +u, y up the image, z out of the surface (green up)"},
            {"stage_inputs", stageInputs(plan.templateSource)},
            {"texture_color_space", "an srgb slot's texture is bound in an sRGB format, decoded before filtering"},
            {"output_color_space", "linear: an sRGB render target or the engine encodes it"}};
}

// Per role the shader reads, its textures across layers: one 2D array texture (layer i is slot i's texture, at the
// first slot's binding in each target's textures) or, with the reason, one texture per slot.
nlohmann::json arraysEntry(const ShaderPlan& plan) {
    nlohmann::json arrays = nlohmann::json::array();
    for (const LayerArrayPlan& a : plan.layers->arrays) {
        std::vector<std::string> slots;
        for (size_t i : a.slots) slots.push_back(plan.slots[i].name);
        if (!a.refused.empty()) {
            arrays.push_back({{"role", a.role}, {"slots", slots}, {"array", false}, {"why_not", a.refused}});
            continue;
        }
        const Slot& first = *plan.slots[a.slots.front()].slot;
        // A KTX2 array is bound as the file is, every layer of it: an engine loads it whole.
        const size_t layers = a.ktx2.empty() ? a.slots.size() : size_t(first.file->info.layers);
        nlohmann::json entry = {{"role", a.role},
                                {"slots", slots},
                                {"array", true},
                                {"size", {first.width, first.height, layers}},
                                {"colorspace", first.samplerDecodes() ? "srgb" : "linear"},
                                {"binding",
                                 {{"texture", plan.textureName(a.slots.front())},
                                  {"slot", slots.front()},
                                  {"type", "texture2DArray"},
                                  {"sampler", "hexcSampler"},
                                  {"mip_chain", "full"}}}};
        if (!a.ktx2.empty()) entry["file"] = a.ktx2;
        arrays.push_back(std::move(entry));
    }
    return arrays;
}

}  // namespace

// Where the weights come from; the vertex colour's input. The plan cannot know the mesh: with vertex weights alone the
// expected fetches are unknown (null); with both, they are counted over the splat maps (an upper bound: the vertex
// colour is clamped to [0, 1], so a product at least skip_below needs a splat weight at least skip_below).
// In a shader the colour is a stage input; the functions output's functions take it as their parameter `color`.
void addVertexWeights(const LayersPlan& lp, nlohmann::json& entry) {
    entry["weights"] = toString(lp.weights);
    if (lp.weights == LayerWeights::Splat) return;
    entry["vertex_color"] = lp.vertexColorLocation < 0
                                ? nlohmann::json{{"parameter", "color"}, {"type", "vec4"}}
                                : nlohmann::json{{"input", "hexcVertexColor"}, {"location", lp.vertexColorLocation}, {"type", "vec4"}};
    if (lp.weights == LayerWeights::Vertex) entry["fetches_per_pixel"]["expected"] = nullptr;
}

// A layered material's blend: which slots each role blends, the splat maps, and its fetches per pixel (plan/layers.cpp).
nlohmann::json layersEntry(const ShaderPlan& plan) {
    const LayersPlan& lp = *plan.layers;
    auto names = [&](const std::vector<size_t>& slots) {
        std::vector<std::string> out;
        for (size_t i : slots) out.push_back(plan.slots[i].name);
        return out;
    };
    nlohmann::json roles = nlohmann::json::array();
    for (const LayerRolePlan& r : lp.roles) roles.push_back({{"name", r.name}, {"slots", names(r.slots)}});
    nlohmann::json entry = {{"count", lp.count},
                            {"mode", toString(lp.blend)},
                            {"roles", roles},
                            {"splat_maps", names(lp.splats)},
                            {"skip_below", lp.skipBelow},
                            {"coverage", lp.coverage},
                            {"fetches_per_pixel", {{"worst", lp.worstFetches}, {"expected", lp.expectedFetches}}}};
    if (!lp.heights.empty()) entry["heights"] = names(lp.heights), entry["width"] = lp.width;
    addVertexWeights(lp, entry);
    if (!lp.arrays.empty()) entry["arrays"] = arraysEntry(plan);
    return entry;
}

nlohmann::json buildManifest(const Material& material, const ShaderPlan& plan, const nlohmann::json& targets) {
    nlohmann::json slots = nlohmann::json::array(), packed = nlohmann::json::array();
    for (const SlotPlan& sp : plan.slots) {
        slots.push_back(slotEntry(material.name, sp, plan.exrTables));
        if (!sp.array.empty())
            slots.back()["array"] = {{"texture", plan.textureName(size_t(&sp - plan.slots.data()))}, {"layer", sp.arrayLayer}};
    }
    for (const PackPlan& p : plan.packs) {
        packed.push_back(packedEntry(material.name, plan, p));
        for (size_t k = 0; k < p.slots.size(); ++k)
            slots[p.slots[k]]["packed"] = {{"texture", packed.back()["name"]}, {"channels", p.channels[k]}};
    }
    nlohmann::json members = nlohmann::json::array(), constants = nlohmann::json::array(), specialised = nlohmann::json::array();
    for (const ParamMember& p : plan.specialised) specialised.push_back({{"name", p.name}, {"value", p.value[0]}, {"slots", p.slots}});
    for (const ParamMember& p : plan.params) {
        nlohmann::json value = p.value.size() == 1 ? nlohmann::json(p.value[0]) : nlohmann::json(p.value);
        nlohmann::json entry = {{"name", p.name}, {"type", p.type}, {"value", value}, {"slots", p.slots}};
        // The other slots' names for the same storage (a shared lattice's settings): setting one sets them all.
        if (!p.aliases.empty()) entry["aliases"] = p.aliases;
        if (!p.perFrame.empty()) entry["per_frame"] = p.perFrame;
        if (p.constantId) {
            entry["constant_id"] = *p.constantId;
            constants.push_back(std::move(entry));
        } else {
            entry["offset"] = p.offset;
            members.push_back(std::move(entry));
        }
    }
    nlohmann::json manifest = {
        {"hexc_version", version()},
        {"material", material.name},
        {"template", plan.templateShown},
        {"conventions", conventionsEntry(plan)},
        // The state hexc's one sampler (hexcSampler) must have: the blend assumes trilinear filtering over a full
        // mip chain and repeat addressing (tiles sample outside [0, 1)); anisotropic filtering may be added.
        {"sampler",
         {{"min_filter", "linear"},
          {"mag_filter", "linear"},
          {"mipmap_mode", "linear"},
          {"address_mode", "repeat"},
          {"mip_chain", "full"},
          {"anisotropy", "optional"}}},
        {"slots", slots},
        // Uniforms are run-time parameters; baked constants (--bake) and specialised settings (whole-number
        // exponents, multiplied out) are fixed in the code and listed for reference only.
        {"parameters", {{"block", "HexcParams"}, {"layout", "std140"}, {"size", plan.paramBlockSize}, {"members", members}}},
        {"baked_constants", constants},
        {"specialised", specialised},
        {"targets", targets},
    };
    // Only with packing: other manifests stay as they were.
    if (!packed.empty()) manifest["packed_textures"] = packed;
    if (plan.layers) manifest["layers"] = layersEntry(plan);
    return manifest;
}

nlohmann::json functionsEntry(const ShaderPlan& plan) {
    nlohmann::json functions = nlohmann::json::array();
    for (const EngineFunction& f : engineFunctions(plan)) {
        const SlotKindRow& kind = kindRow(f.slot->kind);
        const char* value = f.tangentNormal   ? "tangent-space normal, unit length: x along +u, y up the image, z out (green up)"
                            : kind.derivative ? "height derivative (dH/du, dH/dy), y up the image (as docs/conventions.md)"
                            : kind.oneChannel ? "the scalar value"
                                              : "RGBA, linear";
        functions.push_back({{"name", f.name},
                             {f.role.empty() ? "slot" : "role", f.role.empty() ? f.slot->name : f.role},
                             {"parameters", f.vertexColor ? "vec2 uv, vec4 color" : "vec2 uv"},
                             {"returns", f.tangentNormal ? "vec3" : f.slot->type},
                             {"value", value}});
    }
    return functions;
}

namespace {

// `file` relative to the folder `from`, with `/` separators, whatever the current folder is.
std::string relativeTo(const std::filesystem::path& file, const std::filesystem::path& from) {
    const std::filesystem::path base = std::filesystem::absolute(from).lexically_normal();
    return std::filesystem::absolute(file).lexically_normal().lexically_relative(base).generic_string();
}

}  // namespace

nlohmann::json sourcePaths(const Material& material, const ShaderPlan& plan, const std::filesystem::path& from) {
    nlohmann::json textures = nlohmann::json::object();
    for (const SlotPlan& sp : plan.slots) textures[sp.name] = relativeTo(sp.slot->texturePath, from);
    nlohmann::json source = {
        {"relative_to", "this manifest's folder"}, {"material", relativeTo(material.sourceFile, from)}, {"textures", textures}};
    if (!plan.templateFile.empty()) source["template"] = relativeTo(plan.templateFile, from);
    if (!plan.layout.sourceFile.empty()) source["layout"] = relativeTo(plan.layout.sourceFile, from);
    return source;
}

}  // namespace hexc
