#include "codegen/codegen.h"

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

std::string injectedCode(const ShaderPlan& plan) {
    const auto sections = snippetSections("slots.glsl");
    std::string out = lineDirective(1, "hexc/hextiling.glsl") + embeddedText("hextiling.glsl");
    out += lineDirective(1, "hexc/generated") + "\n";
    if (plan.slots.empty()) return out;

    std::string members;
    for (const ParamMember& p : plan.params) members += "    " + p.type + " " + p.name + ";\n";
    members.pop_back();
    out += replaceAll(sections.at("params"), {{"$members", members}}) + "\n";
    out += replaceAll(sections.at("sampler"), {{"$binding", std::to_string(kSamplerBinding)}}) + "\n";
    const Slot& first = *plan.slots.front().slot;
    out += replaceAll(sections.at("first"), {{"$name", first.name}, {"$kind", std::string(toString(first.kind))}}) + "\n";
    for (const SlotPlan& sp : plan.slots) {
        const Slot& s = *sp.slot;
        auto param = [&](const char* setting) { return "hexcParams." + s.name + "_" + setting; };
        static const char* kChannels[] = {"r", "g", "b", "a"};
        static const char* kChannelVectors[] = {"vec4(1.0, 0.0, 0.0, 0.0)", "vec4(0.0, 1.0, 0.0, 0.0)",
                                                "vec4(0.0, 0.0, 1.0, 0.0)", "vec4(0.0, 0.0, 0.0, 1.0)"};
        std::map<std::string, std::string> values = {
            {"$name", s.name},
            {"$binding", std::to_string(sp.binding)},
            {"$tiling", param("tiling")},
            {"$rotation", param("rotation")},
            {"$falloff", param("falloff")},
            {"$falloffcontrast", param("falloffcontrast")},
            {"$exponent", param("exponent")},
            {"$origincell", param("origin_cell")},
            {"$originoffset", param("origin_offset")},
            // Scalar maps weight tiles by their own channel; colour by luminance (Eq. 4).
            {"$luma", s.kind == SlotKind::Scalar ? kChannelVectors[s.channel] : "hexcLuma"},
            {"$channel", kChannels[s.channel]},
            {"$flipy", s.flipY ? "true" : "false"},
        };
        const char* lattice = s.hex.mode == HashMode::Paper ? "lattice.paper" : s.hex.splitCoordinates ? "lattice.split" : "lattice.stable";
        values["$lattice"] = replaceAll(sections.at(lattice), values);
        values["$lattice"].pop_back();  // the section's final newline
        out += replaceAll(sections.at("texture"), values) + "\n";
        out += replaceAll(sections.at(sp.section), values) + "\n";
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
