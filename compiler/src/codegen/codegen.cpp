#include "codegen/codegen.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

#include "codegen/array_forms.h"
#include "codegen/assembly.h"
#include "codegen/layers.h"
#include "codegen/pieces.h"
#include "common/templates.h"
#include "common/text.h"

namespace hexc {
namespace {

std::string lineDirective(int line, const std::string& file) { return "#line " + std::to_string(line) + " \"" + file + "\"\n"; }

// Back in the template: source string 0, which glslang names after the template file it was given. Not the path in
// quotes: a `#line` string cannot hold a `"`, and a path can.
std::string templateLine(int line) { return "#line " + std::to_string(line) + " 0\n"; }

std::string literal(double v) { return floatLiteral(v); }

std::string literal(bool v) { return v ? "true" : "false"; }
std::string literal(int v) { return std::to_string(v); }

class Emitter {
public:
    explicit Emitter(const ShaderPlan& plan) : plan_(plan) {}

    // The section expanded, without its final newline.
    std::string expand(const std::string& section, const Tokens& values) const {
        static const std::map<std::string, std::string> sections = snippetSections("slots.glsl");
        return expandSection(sections, section, values);
    }

    // How the code reads a parameter: a baked constant by its name, a block member through the block.
    std::string read(size_t param) const {
        const ParamMember& p = plan_.params[param];
        return p.constantId ? p.name : "hexcParams." + p.name;
    }

    // Specialisation constants, the parameter block, the sampler and the textures.
    std::string resources() const {
        std::string out, members;
        for (const ParamMember& p : plan_.params) {
            if (!p.constantId) {
                members += (members.empty() ? "" : "\n") + std::string("    ") + p.type + " " + p.name + ";";
                continue;
            }
            if (p.type == "vec2")
                out += expand("constant.vec2", {{"id", std::to_string(*p.constantId)},
                                                {"idy", std::to_string(*p.constantId + 1)},
                                                {"name", p.name},
                                                {"x", literal(p.value[0])},
                                                {"y", literal(p.value[1])}}) +
                       "\n";
            else
                out += expand("constant",
                              {{"id", std::to_string(*p.constantId)}, {"type", p.type}, {"name", p.name}, {"value", literal(p.value[0])}}) +
                       "\n";
        }
        const HexcBindings& b = plan_.bindings;
        const std::string set = std::to_string(b.set);
        if (!members.empty()) out += expand("params", {{"set", set}, {"binding", std::to_string(b.params)}, {"members", members}}) + "\n";
        out += expand("sampler", {{"set", set}, {"binding", std::to_string(b.sampler)}}) + "\n";
        // Every texture first: a slot may read another's as its height map.
        for (size_t i = 0; i < plan_.slots.size(); ++i) {
            const SlotPlan& sp = plan_.slots[i];
            const char* section = !plan_.textureBound(i) ? "has" : sp.array.empty() ? "texture" : "texture.array";
            out +=
                expand(section, {{"name", sp.name}, {"set", set}, {"binding", std::to_string(sp.binding)}, {"variable", sp.array}}) + "\n";
        }
        for (size_t i = 0; i < plan_.luts.size(); ++i)
            out += expand("lut", {{"name", plan_.slots[plan_.luts[i]].name},
                                  {"set", set},
                                  {"binding", std::to_string(b.firstTexture + plan_.slots.size() + i)}}) +
                   "\n";
        return out;
    }

    // The slot's sampling and coordinates functions, their library calls resolved in `assembly`: to functions with the
    // slot's fixed settings folded in, or (plan.general) to the general ones, which read every setting from the structs.
    std::string slot(const SlotPlan& sp, Assembly& assembly) const {
        const LatticePlan& l = plan_.lattices[sp.lattice];
        Settings fixed;
        Tokens t = {
            {"name", sp.name},
            {"type", sp.type},
            {"plain", sp.explicitGradients ? "hexcPlainColorGrad" : "hexcPlainColor"},
            {"flipy", literal(sp.flipY)},
            {"channel", literal(sp.channel)},
            {"texture", sp.texture},
            {"tex", textureOf(sp)},
            {"heighttex", textureOf(sp.heightMap ? plan_.slots[*sp.heightMap] : sp)},
            {"tiles", sp.layerLattice ? layerLatticeCall(plan_, *sp.layerLattice) : tiles(l)},
            {"settings", settings(l, sp, fixed, !sp.layerLattice, true)},
            {"luma", "vec3(" + literal(sp.luma[0]) + ", " + literal(sp.luma[1]) + ", " + literal(sp.luma[2]) + ")"},
            {"srgb", literal(sp.srgb)},
            {"uv", expand(plan_.uvBottomLeft ? "uv.bottomleft" : "uv.topleft", {})},
        };
        addParam(t, "tiling", l.tiling);
        addParam(t, "planesharpness", l.planeSharpness);
        addParam(t, "origincell", l.originCell);
        addParam(t, "originoffset", l.originOffset);
        if (!sp.array.empty()) fixed[kArrayLayer] = literal(double(sp.arrayLayer));  // read by the library's array forms
        std::string sampling = expand(sp.section, t);
        for (size_t empty; (empty = sampling.find("\n\n")) != std::string::npos;) sampling.erase(empty, 1);  // ${settings}, ${fields} empty
        return assembly.use(sampling + "\n\n" + expand(sp.coordinates, t), plan_.general ? nullptr : &fixed, sp.name) + "\n";
    }

    // The call computing a lattice's tiles; the periodic lattices' matrix, repeats and cells a row are literals.
    std::string tiles(const LatticePlan& l) const {
        const std::array<int, 4>& p = l.period;
        return expand(l.section,
                      {{"period", "ivec4(" + literal(p[0]) + ", " + literal(p[1]) + ", " + literal(p[2]) + ", " + literal(p[3]) + ")"},
                       {"repeats", literal(l.repeats)},
                       {"cells", literal(l.repeats * l.maskScale)}});
    }

    // The function computing the tiles of the layers' lattice `index` (LayersPlan::lattices) and the variable sharing
    // them, with the settings of the lattice's first slot (which names its specialised library functions).
    std::string layerLattice(size_t index, Assembly& assembly) const {
        const SlotPlan& sp = plan_.slots[plan_.layers->lattices[index].slot];
        const LatticePlan& l = plan_.lattices[sp.lattice];
        Settings fixed;
        const std::string text = hexc::layerLattice(plan_, index, tiles(l), settings(l, sp, fixed, true, false));
        return assembly.use(text, plan_.general ? nullptr : &fixed, sp.name) + "\n\n";
    }

    // The functions output's code after the slots' (templates/builtin/functions.glsl): each normal slot's (a layered
    // material's: normal role's) tangent-space normal, and hexcEngineCalls, which calls every engine function once.
    std::string engineFunctions() const {
        std::string normals, calls;
        for (const EngineFunction& f : hexc::engineFunctions(plan_)) {
            if (f.tangentNormal) continue;  // engine.normal, after its derivative's
            Tokens name = vertexColorTokens(plan_);
            name["name"] = f.name.substr(std::string_view("hexc_").size());
            if (calls.empty() && f.vertexColor) calls = expand("engine.color", {}) + "\n";
            if (kindRow(f.slot->kind).derivative) normals += expand("engine.normal", name) + "\n\n";
            calls += expand("engine.call." + std::string(toString(kindRow(f.slot->kind).like)), name) + "\n";
        }
        if (calls.ends_with('\n')) calls.pop_back();
        return normals + expand("engine.calls", {{"calls", calls}}) + "\n";
    }

private:
    // The slot's texture variable: its own, or its layered role's array.
    static std::string textureOf(const SlotPlan& sp) { return sp.array.empty() ? "hexcTex_" + sp.name : sp.array; }

    // A field of HexcLattice or HexcBlend and its value: a literal hexc fixes, or a parameter's read.
    struct Field {
        std::string name, value;
    };
    using Fields = std::vector<Field>;

    void addParam(Fields& to, const std::string& field, ParamRef ref) const {
        if (ref) to.push_back({field, read(*ref)});
    }

    void addParam(Tokens& to, const std::string& token, ParamRef ref) const {
        if (ref) to[token] = read(*ref);
    }

    // The slot's HexcLattice `lattice` and HexcBlend `blend`, built for the library's functions in general code (those
    // asked for: a layered slot takes its lattice's tiles ready), with every field the plan gives. Otherwise no struct is
    // built: every field's value (the plan's, a parameter's read, else the neutral one) goes to `fixed`, as the library
    // names it, to fold into the functions, which then take neither.
    std::string settings(const LatticePlan& l, const SlotPlan& sp, Settings& fixed, bool lattice, bool blend) const {
        const std::pair<const char*, Fields> structs[] = {{"lattice", latticeSettings(l, sp.aspect)}, {"blend", blendSettings(sp)}};
        std::string out;
        for (const auto& [name, fields] : structs) {
            const std::string prefix = name[0] + std::string(".");
            if (!plan_.general) {
                for (const auto& [field, value] : library().neutral.at(name[0] == 'l' ? "HexcLattice" : "HexcBlend"))
                    fixed[prefix + field] = value;
                for (const Field& f : fields) fixed[prefix + f.name] = f.value;
                continue;
            }
            if (!(name[0] == 'l' ? lattice : blend)) continue;
            std::string lines;
            for (const Field& f : fields)
                lines += (lines.empty() ? "" : "\n") + expand("set", {{"struct", name}, {"field", f.name}, {"value", f.value}});
            out += (out.empty() ? "" : "\n") + expand("settings." + std::string(name), {{"fields", lines}});
        }
        return out;
    }

    // The lattice's settings, and the slot's texture aspect (its tiles turn in texel-isotropic space).
    Fields latticeSettings(const LatticePlan& l, double aspect) const {
        Fields fields = {
            {"rotate", literal(l.rotate)},
            {"transform", literal(l.transform)},
            {"rotationSteps", literal(l.rotationSteps)},
            {"offsetSteps", "ivec2(" + literal(l.offsetSteps[0]) + ", " + literal(l.offsetSteps[1]) + ")"},
            {"maskScale", literal(l.maskScale)},
            {"triple", literal(l.triple)},
            {"aspect", literal(aspect)},
        };
        addParam(fields, "rotation", l.rotation);
        addParam(fields, "rotationRange", l.rotationRange);
        addParam(fields, "scaleRange", l.scaleRange);
        addParam(fields, "offset", l.offset);
        return fields;
    }

    Fields blendSettings(const SlotPlan& sp) const {
        Fields fields = {
            {"metric", literal(sp.metric)},
            {"gain", literal(sp.gain)},
            {"exponentInt", literal(sp.exponentInt)},
            {"gainInt", literal(sp.gainInt)},
            {"taps", literal(sp.taps)},
            {"sharedLod", literal(sp.sharedLod)},
            {"height", literal(sp.heightMap.has_value())},
            {"adaptive", literal(sp.adaptive)},
            {"adaptiveError", literal(HexTiling::kAdaptiveError)},
        };
        if (sp.heightMap) fields.push_back({"heightLuma", "hexcChannel(" + literal(sp.heightChannel) + ")"});
        addParam(fields, "falloff", sp.falloff);
        addParam(fields, "falloffContrast", sp.falloffContrast);
        addParam(fields, "exponent", sp.exponent);
        addParam(fields, "heightWidth", sp.heightWidth);
        return fields;
    }

    const ShaderPlan& plan_;
};

// hexc's resources, the library code the slots' functions and the template reach (which may read the resources), then
// the slots' functions.
std::string injectedCode(const ShaderPlan& plan) {
    Assembly assembly;
    std::string resources = "\n", functions;
    if (!plan.slots.empty()) {
        Emitter emit(plan);
        resources += emit.resources();
        const SlotPlan& first = *std::find_if(plan.slots.begin(), plan.slots.end(), [](const SlotPlan& sp) { return !sp.heightOnly; });
        // A layered material's first slot is its first role read.
        const LayerRolePlan* role = plan.layers ? &plan.layers->roles.front() : nullptr;
        resources += emit.expand("first", {{"name", role ? role->name : first.name},
                                           {"kind", std::string(toString(kindRow(role ? role->kind : first.kind).like))},
                                           {"projection", std::string(toString(first.projection))}}) +
                     "\n";
        for (size_t k = 0; plan.layers && k < plan.layers->lattices.size(); ++k) functions += emit.layerLattice(k, assembly);
        for (const SlotPlan& sp : plan.slots)
            if (!sp.heightOnly) functions += emit.slot(sp, assembly);
        functions += layerFunctions(
            plan, [&](size_t p) { return emit.read(p); }, emit.expand(plan.uvBottomLeft ? "uv.bottomleft" : "uv.topleft", {}));
    }
    if (plan.functions) functions += assembly.use(Emitter(plan).engineFunctions(), nullptr, "");  // also for a pass without slots
    assembly.use(plan.templateSource, nullptr, "");  // what the template calls itself, as it is
    const int next = 1 + int(std::count(resources.begin(), resources.end(), '\n'));
    return lineDirective(1, "hexc/generated") + resources + assembly.text() + lineDirective(next, "hexc/generated") + functions;
}

}  // namespace

std::string floatLiteral(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    std::string s = buf;
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string expandSection(const std::map<std::string, std::string>& sections, const std::string& section, const Tokens& values) {
    std::string text = expandTokens(sections.at(section), values, section);
    if (text.ends_with('\n')) text.pop_back();
    return text;
}

std::string expandTokens(const std::string& text, const Tokens& values, const std::string& section) {
    std::string out;
    size_t at = 0;
    for (size_t open; (open = text.find("${", at)) != std::string::npos; at = text.find('}', open) + 1) {
        size_t close = text.find('}', open);
        std::string name = text.substr(open + 2, close == std::string::npos ? std::string::npos : close - open - 2);
        auto it = values.find(name);
        if (close == std::string::npos || it == values.end())
            throw CompileError{
                {Diagnostic::make(Code::Internal, {"hexc/slots.glsl"}, "",
                                  "internal error: section `" + section + "` has token `${" + name + "}`, which hexc does not fill")}};
        out.append(text, at, open - at).append(it->second);
    }
    return out.append(text, at);
}

std::string generateGlsl(const ShaderPlan& plan) {
    std::istringstream in(plan.templateSource);
    std::string out, line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.rfind("#include <hexc>", 0) == 0) {
            out += injectedCode(plan);
            out += templateLine(number + 1);
        } else {
            out += line + "\n";
            if (number == 1) {
                // Right after #version: lets `#line` name files, so errors point into the user's template.
                out += "#extension GL_GOOGLE_cpp_style_line_directive : require\n";
                out += templateLine(2);
            }
        }
    }
    return out;
}

std::string generateLibraryGlsl() {
    const std::string& entry = *embeddedText("entry.glsl");
    const std::string marker = "#include <hexc/hextiling.glsl>\n";  // not <hexc>: no built-in template
    const size_t at = entry.find(marker);
    const int next = 2 + int(std::count(entry.begin(), entry.begin() + std::ptrdiff_t(at), '\n'));
    return entry.substr(0, at) + lineDirective(1, "hexc/hextiling.glsl") + *embeddedText("hextiling.glsl") +
           lineDirective(next, "hexc/entry.glsl") + entry.substr(at + marker.size());
}

std::string generateVertexGlsl(const std::vector<Varying>& inputs) {
    const std::map<std::string, std::string> sections = snippetSections("vertex.glsl");
    std::string varyings, copies;
    uint32_t attribute = 1;
    for (const Varying& v : inputs) {
        const bool integer =
            v.type.starts_with("int") || v.type.starts_with("uint") || v.type.starts_with("ivec") || v.type.starts_with("uvec");
        varyings += expandTokens(sections.at("varying"),
                                 {{"name", v.name},
                                  {"type", v.type},
                                  {"location", std::to_string(v.location)},
                                  {"attribute", std::to_string(attribute++)},
                                  {"flat", integer ? "flat " : ""}},
                                 "varying");
        copies += expandTokens(sections.at("copy"), {{"name", v.name}}, "copy");
    }
    return expandTokens(sections.at("main"), {{"varyings", varyings}, {"copies", copies}}, "main");
}

}  // namespace hexc
