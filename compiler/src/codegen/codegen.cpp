#include "codegen/codegen.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

#include "common/templates.h"

namespace hexc {
namespace {

std::string replaceAll(std::string text, const std::map<std::string, std::string>& values) {
    // Longest placeholder first, so `$falloff` never eats the start of `$falloffcontrast`.
    for (auto it = values.rbegin(); it != values.rend(); ++it) {
        for (size_t pos = 0; (pos = text.find(it->first, pos)) != std::string::npos; pos += it->second.size())
            text.replace(pos, it->first.size(), it->second);
    }
    return text;
}

std::string lineDirective(int line, const std::string& file) {
    return "#line " + std::to_string(line) + " \"" + file + "\"\n";
}

// A GLSL float literal that reads back as the same float32.
std::string literal(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    std::string s = buf;
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string injectedCode(const ShaderPlan& plan) {
    const auto sections = snippetSections("slots.glsl");
    std::string out = lineDirective(1, "hexc/hextiling.glsl") + *embeddedText("hextiling.glsl");
    out += lineDirective(1, "hexc/generated") + "\n";
    if (plan.slots.empty()) return out;

    std::string members;
    for (const ParamMember& p : plan.params) {
        if (p.constantId) {
            if (p.type == "vec2")
                out += replaceAll(sections.at("constant.vec2"), {{"$id", std::to_string(*p.constantId)}, {"$idy", std::to_string(*p.constantId + 1)},
                                                                  {"$name", p.name}, {"$x", literal(p.value[0])}, {"$y", literal(p.value[1])}});
            else
                out += replaceAll(sections.at("constant"), {{"$id", std::to_string(*p.constantId)}, {"$type", p.type}, {"$name", p.name},
                                                             {"$value", literal(p.value[0])}});
        } else {
            members += "    " + p.type + " " + p.name + ";\n";
        }
    }
    if (!members.empty()) {
        members.pop_back();
        out += replaceAll(sections.at("params"), {{"$members", members}}) + "\n";
    }
    out += replaceAll(sections.at("sampler"), {{"$binding", std::to_string(kSamplerBinding)}}) + "\n";
    // Every texture first: a slot may read another's as its height map.
    for (const SlotPlan& sp : plan.slots)
        out += replaceAll(sections.at("texture"), {{"$name", sp.slot->name}, {"$binding", std::to_string(sp.binding)}}) + "\n";
    const SlotPlan& first = *std::find_if(plan.slots.begin(), plan.slots.end(), [](const SlotPlan& sp) { return !sp.heightOnly; });
    out += replaceAll(sections.at("first"), {{"$name", first.slot->name}, {"$kind", std::string(toString(first.slot->kind))},
                                             {"$projection", std::string(toString(first.slot->hex.projection))}}) +
           "\n";
    for (const SlotPlan& sp : plan.slots) {
        if (sp.heightOnly) continue;
        const Slot& s = *sp.slot;
        const LatticePlan& lattice = plan.lattices[sp.lattice];
        // A setting reads as its block member or its constant; a feature left out reads as its neutral value.
        auto param = [&](const std::string& name, const char* neutral) -> std::string {
            const ParamMember* p = plan.param(name);
            if (!p) return neutral;
            return p->constantId ? name : "hexcParams." + name;
        };
        static const char* kChannels[] = {"r", "g", "b", "a"};
        static const char* kChannelVectors[] = {"vec4(1.0, 0.0, 0.0, 0.0)", "vec4(0.0, 1.0, 0.0, 0.0)",
                                                "vec4(0.0, 0.0, 1.0, 0.0)", "vec4(0.0, 0.0, 0.0, 1.0)"};
        const bool triplanar = s.hex.projection == Projection::Triplanar;
        static const char* kTypes[] = {"vec4", "float", "vec2"};
        std::string height = "false, hexcTex_" + s.name + ", vec4(0.0), 0.0";
        if (s.heightBlend) {
            const Slot& h = *std::find_if(plan.slots.begin(), plan.slots.end(), [&](const SlotPlan& p) { return p.slot->name == s.heightBlend->slot; })->slot;
            height = "true, hexcTex_" + h.name + ", " + kChannelVectors[h.channel] + ", " + param(s.name + "_heightwidth", "");
        }
        std::map<std::string, std::string> values = {
            {"$name", s.name},
            {"$type", triplanar && s.kind == SlotKind::Normal ? "vec3" : kTypes[size_t(s.kind)]},
            {"$height", height},
            {"$taps", std::to_string(s.hex.maskTaps())},
            {"$maskscale", std::to_string(s.hex.maskScale)},
            {"$triple", s.hex.mask == Mask::Noise3 ? "true" : "false"},
            {"$explicit", triplanar ? "true" : "false"},
            {"$planesharpness", param(lattice.name + "_planesharpness", "4.0")},
            {"$tiling", param(lattice.name + "_tiling", "")},
            {"$rotation", param(lattice.name + "_rotation", "0.0")},
            {"$origincell", param(lattice.name + "_origin_cell", "ivec2(0)")},
            {"$originoffset", param(lattice.name + "_origin_offset", "vec2(0.0)")},
            {"$falloff", param(s.name + "_falloff", "0.5")},
            {"$falloffcontrast", param(s.name + "_falloffcontrast", "0.0")},
            {"$exponent", param(s.name + "_exponent", "7.0")},
            {"$rotate", lattice.rotate ? "true" : "false"},
            {"$transform", lattice.transform ? "true" : "false"},
            {"$rotationrange", param(lattice.name + "_rotationrange", "vec2(-180.0, 180.0)")},
            {"$scalerange", param(lattice.name + "_scalerange", "vec2(1.0)")},
            {"$offset", param(lattice.name + "_offset", "1.0")},
            {"$rotationsteps", std::to_string(lattice.settings.rotationSteps)},
            {"$offsetstepsx", std::to_string(lattice.settings.offsetSteps[0])},
            {"$offsetstepsy", std::to_string(lattice.settings.offsetSteps[1])},
            {"$metric", sp.metric ? "true" : "false"},
            {"$gain", sp.gain ? "true" : "false"},
            {"$exponentint", std::to_string(sp.exponentInt)},
            {"$gainint", std::to_string(sp.gainInt)},
            // Scalar maps weight tiles by their own channel; colour by luminance (Eq. 4).
            {"$luma", s.kind == SlotKind::Scalar ? kChannelVectors[s.channel] : "hexcLuma"},
            {"$channel", kChannels[s.channel]},
            {"$flipy", s.flipY ? "true" : "false"},
        };
        static const char* kMaskLattices[] = {"lattice.stable", "lattice.checker", "lattice.noise", "lattice.noise"};
        const char* latticeSection = s.hex.mode == HashMode::Paper ? "lattice.paper" : kMaskLattices[size_t(s.hex.mask)];
        values["$tf"] = replaceAll(sections.at("transform"), values);
        values["$tf"].pop_back();  // the section's final newline
        values["$lattice"] = replaceAll(sections.at(latticeSection), values);
        values["$lattice"].pop_back();  // the section's final newline
        out += replaceAll(sections.at(sp.section), values) + "\n";
        out += replaceAll(sections.at(triplanar ? "triplanar" : s.hex.splitCoordinates ? "uv.split" : "uv"), values) + "\n";
    }
    return out;
}

}  // namespace

std::string generateGlsl(const ShaderPlan& plan) {
    std::istringstream in(plan.templateSource);
    std::string out, line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.rfind("#include <hexc>", 0) == 0) {
            out += injectedCode(plan);
            out += lineDirective(number + 1, plan.templateName);
        } else {
            out += line + "\n";
            if (number == 1) {
                // Right after #version: lets `#line` name files, so errors point into the user's template.
                out += "#extension GL_GOOGLE_cpp_style_line_directive : require\n";
                out += lineDirective(2, plan.templateName);
            }
        }
    }
    return out;
}

}  // namespace hexc
