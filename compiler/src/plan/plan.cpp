#include "plan/plan.h"

#include <fstream>
#include <regex>
#include <sstream>

#include "common/templates.h"

namespace hexc {
namespace {

bool readsIdentifier(const std::string& source, const std::string& identifier) {
    return std::regex_search(source, std::regex("\\b" + identifier + "\\b"));
}

// Appends a member with std140 alignment (scalars: 4, two-component vectors: 8).
void addParam(ShaderPlan& plan, const std::string& name, std::vector<double> value, bool integer = false, std::string perFrame = {}) {
    uint32_t size = uint32_t(value.size()) * 4;
    uint32_t offset = (plan.paramBlockSize + size - 1) / size * size;
    std::string type = value.size() == 2 ? (integer ? "ivec2" : "vec2") : (integer ? "int" : "float");
    plan.params.push_back({name, type, offset, std::move(value), std::move(perFrame)});
    plan.paramBlockSize = offset + size;
}

}  // namespace

ShaderPlan planShader(const Material& material, const std::filesystem::path& templateOverride) {
    ShaderPlan plan;
    plan.materialName = material.name;
    auto error = [&](std::string message) {
        plan.diagnostics.push_back({Diagnostic::Severity::Error, {plan.templateName, 0, 0}, "", std::move(message), {}});
    };

    std::string ref = templateOverride.empty() ? material.templateName : templateOverride.string();
    if (ref.ends_with(".glsl")) {
        plan.templateName = ref;
        std::ifstream in(ref, std::ios::binary);
        if (!in) {
            error("cannot read template file");
            return plan;
        }
        std::stringstream ss;
        ss << in.rdbuf();
        plan.templateSource = ss.str();
    } else {
        plan.templateName = "templates/" + ref + ".glsl";
        plan.templateSource = embeddedText(ref + ".glsl");
    }
    if (!std::regex_search(plan.templateSource, std::regex("^#version[^\n]*\n"))) error("a template must start with a `#version` line");
    static const std::regex include("(^|\n)#include <hexc>[ \t]*(\r?\n|$)");
    auto begin = std::sregex_iterator(plan.templateSource.begin(), plan.templateSource.end(), include);
    if (std::distance(begin, std::sregex_iterator()) != 1)
        error("a template must contain the line `#include <hexc>` exactly once (where hexc injects its code)");

    bool readsFirst = readsIdentifier(plan.templateSource, "HEXC_FIRST_SLOT");
    uint32_t binding = kFirstTextureBinding;
    for (const Slot& slot : material.slots) {
        bool first = &slot == &material.slots.front();
        if (!readsIdentifier(plan.templateSource, "hexc_" + slot.name) && !(first && readsFirst)) {
            plan.diagnostics.push_back({Diagnostic::Severity::Warning, {material.sourceFile.string(), 0, 0}, "",
                                        "slot `" + slot.name + "` is not read by template " + plan.templateName + "; it is left out", {}});
            continue;
        }
        plan.slots.push_back({&slot, std::string(toString(slot.kind)) + (slot.hex.enabled ? ".hex" : ".plain"), binding++});
        const HexTiling& h = slot.hex;
        addParam(plan, slot.name + "_tiling", {h.tiling[0], h.tiling[1]});
        if (h.enabled) {
            addParam(plan, slot.name + "_rotation", {h.rotation});
            addParam(plan, slot.name + "_falloff", {h.falloff});
            addParam(plan, slot.name + "_falloffcontrast", {h.falloffcontrast});
            addParam(plan, slot.name + "_exponent", {h.exponent});
            if (h.splitCoordinates) {
                // Filled per frame by the engine from its double-precision origin (docs/precision.md).
                addParam(plan, slot.name + "_origin_cell", {0, 0}, true,
                         "floor(st / (28, 1)) with st = origin_uv * tiling in double, stored modulo 2^32 (hexc/origin.h)");
                addParam(plan, slot.name + "_origin_offset", {0, 0}, false, "st - cell * (28, 1), as float (hexc/origin.h)");
            }
        }
    }
    plan.paramBlockSize = (plan.paramBlockSize + 15) / 16 * 16;
    return plan;
}

}  // namespace hexc
