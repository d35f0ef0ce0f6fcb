#include "plan/plan.h"

#include <cmath>
#include <regex>

#include "hexc/files.h"
#include "common/templates.h"

namespace hexc {
namespace {

bool readsIdentifier(const std::string& source, const std::string& identifier) {
    return std::regex_search(source, std::regex("\\b" + identifier + "\\b"));
}

// Slots share a lattice when everything the lattice computes from is the same.
bool sameLattice(const HexTiling& a, const HexTiling& b) {
    return a.enabled == b.enabled && a.mode == b.mode && a.splitCoordinates == b.splitCoordinates && a.tiling == b.tiling &&
           a.rotation == b.rotation && a.rotationRange == b.rotationRange && a.rotationSteps == b.rotationSteps &&
           a.scaleRange == b.scaleRange && a.offset == b.offset && a.offsetSteps == b.offsetSteps && a.mask == b.mask &&
           a.maskScale == b.maskScale && a.projection == b.projection && a.planeSharpness == b.planeSharpness;
}

class ParamBuilder {
public:
    ParamBuilder(ShaderPlan& plan, bool bake) : plan_(plan), bake_(bake) {}

    // A setting of `slots`; per-frame values are always block members, others are baked on request.
    void add(const std::string& name, std::vector<double> value, std::vector<std::string> slots, bool integer = false,
             std::string perFrame = {}) {
        std::string type = value.size() == 2 ? (integer ? "ivec2" : "vec2") : (integer ? "int" : "float");
        ParamMember m{name, type, std::move(value), std::move(slots), std::move(perFrame), 0, std::nullopt};
        if (bake_ && m.perFrame.empty()) {
            m.constantId = nextConstant_;
            nextConstant_ += uint32_t(m.value.size());
            constants_.push_back(std::move(m));
            return;
        }
        // std140: scalars align to 4, two-component vectors to 8.
        uint32_t size = uint32_t(m.value.size()) * 4;
        m.offset = (plan_.paramBlockSize + size - 1) / size * size;
        plan_.paramBlockSize = m.offset + size;
        plan_.params.push_back(std::move(m));
    }

    void finish() {
        plan_.paramBlockSize = (plan_.paramBlockSize + 15) / 16 * 16;
        plan_.params.insert(plan_.params.end(), constants_.begin(), constants_.end());
    }

private:
    ShaderPlan& plan_;
    bool bake_;
    uint32_t nextConstant_ = 0;
    std::vector<ParamMember> constants_;
};

}  // namespace

const ParamMember* ShaderPlan::param(const std::string& name) const {
    for (const ParamMember& p : params)
        if (p.name == name) return &p;
    return nullptr;
}

ShaderPlan planShader(const Material& material, const CompileOptions& options) {
    ShaderPlan plan;
    plan.materialName = material.name;
    auto error = [&](std::string message) {
        plan.diagnostics.push_back({Diagnostic::Severity::Error, {plan.templateName, 0, 0}, "", std::move(message), {}});
    };

    std::string ref = options.templateFile.empty() ? material.templateName : options.templateFile.string();
    if (ref.ends_with(".glsl")) {
        plan.templateName = ref;
        std::string why;
        std::optional<std::string> text = readFile(ref, &why);
        if (!text) {
            error("cannot read template file: " + why);
            return plan;
        }
        plan.templateSource = std::move(*text);
    } else {
        plan.templateName = "templates/" + ref + ".glsl";
        const std::string* text = embeddedText(ref + ".glsl");
        if (!text) {
            error("no built-in template `" + ref + "`");
            return plan;
        }
        plan.templateSource = *text;
    }
    if (!std::regex_search(plan.templateSource, std::regex("^#version[^\n]*\n"))) error("a template must start with a `#version` line");
    static const std::regex include("(^|\n)#include <hexc>[ \t]*(\r?\n|$)");
    auto begin = std::sregex_iterator(plan.templateSource.begin(), plan.templateSource.end(), include);
    if (std::distance(begin, std::sregex_iterator()) != 1)
        error("a template must contain the line `#include <hexc>` exactly once (where hexc injects its code)");

    bool readsFirst = readsIdentifier(plan.templateSource, "HEXC_FIRST_SLOT");
    // The slots the template reads, and the height maps they blend by (of which only the texture may be needed).
    std::vector<bool> read(material.slots.size()), needed(material.slots.size());
    for (size_t i = 0; i < material.slots.size(); ++i) {
        const Slot& slot = material.slots[i];
        if (!readsIdentifier(plan.templateSource, "hexc_" + slot.name) && !(i == 0 && readsFirst)) continue;
        read[i] = needed[i] = true;
        if (slot.heightBlend)
            for (size_t j = 0; j < material.slots.size(); ++j) needed[j] = needed[j] || material.slots[j].name == slot.heightBlend->slot;
    }
    uint32_t binding = kFirstTextureBinding;
    for (size_t i = 0; i < material.slots.size(); ++i) {
        const Slot& slot = material.slots[i];
        if (!needed[i]) {
            plan.diagnostics.push_back({Diagnostic::Severity::Warning, {material.sourceFile.string(), 0, 0}, "",
                                        "slot `" + slot.name + "` is not read by template " + plan.templateName + "; it is left out", {}});
            continue;
        }
        if (!read[i]) {
            SlotPlan heights;
            heights.slot = &slot;
            heights.binding = binding++;
            heights.heightOnly = true;
            plan.slots.push_back(heights);
            continue;
        }
        const HexTiling& h = slot.hex;
        // Without specialisation every feature is emitted, and the values decide at run time.
        bool all = !options.specialize;
        // One tap needs no falloff metric: it has a single sample to weigh.
        SlotPlan sp{&slot, std::string(toString(slot.kind)) + (!h.enabled ? ".plain" : h.taps == 1 ? ".hex1" : ".hex"), binding++, 0,
                    h.taps != 1 && (all || h.falloffcontrast != 0), all || h.falloff != 0.5};
        // Whole-number exponents become multiplications: gamma = 7 (the paper's) and the gain at r = 1 - 2^-k
        // (the paper's 0.75 is k = 2) then cost no pow. Like the feature switches, they fix the value in the code.
        if (!all && h.exponent == std::floor(h.exponent) && h.exponent <= 16) sp.exponentInt = int(h.exponent);
        double k = std::log2(1.0 / (1.0 - h.falloff));
        if (!all && sp.gain && std::fabs(k - std::round(k)) < 1e-12 && k >= 2 && k <= 16) sp.gainInt = int(std::round(k));
        size_t lattice = 0;
        while (lattice < plan.lattices.size() && !(options.shareLattice && sameLattice(plan.lattices[lattice].settings, h))) ++lattice;
        if (lattice == plan.lattices.size()) plan.lattices.push_back({slot.name, h, all || h.rotation != 0, h.hasTransforms()});
        sp.lattice = lattice;
        plan.slots.push_back(sp);
    }

    // Parameters: each lattice's, then each slot's, only for the features emitted.
    ParamBuilder params(plan, options.bake);
    for (size_t i = 0; i < plan.lattices.size(); ++i) {
        const LatticePlan& l = plan.lattices[i];
        std::vector<std::string> users;
        for (const SlotPlan& sp : plan.slots)
            if (sp.lattice == i && !sp.heightOnly) users.push_back(sp.slot->name);
        const HexTiling& h = l.settings;
        params.add(l.name + "_tiling", {h.tiling[0], h.tiling[1]}, users);
        if (h.projection == Projection::Triplanar) params.add(l.name + "_planesharpness", {h.planeSharpness}, users);
        if (!h.enabled) continue;
        if (l.rotate) params.add(l.name + "_rotation", {h.rotation}, users);
        if (l.transform) {
            params.add(l.name + "_rotationrange", {h.rotationRange[0], h.rotationRange[1]}, users);
            params.add(l.name + "_scalerange", {h.scaleRange[0], h.scaleRange[1]}, users);
            params.add(l.name + "_offset", {h.offset}, users);
        }
        if (h.splitCoordinates) {
            // Filled per frame by the engine from its double-precision origin (docs/precision.md).
            params.add(l.name + "_origin_cell", {0, 0}, users, true,
                       "floor(st / (28, 1)) with st = origin_uv * tiling in double, stored modulo 2^32 (hexc/origin.h)");
            params.add(l.name + "_origin_offset", {0, 0}, users, false, "st - cell * (28, 1), as float (hexc/origin.h)");
        }
    }
    for (const SlotPlan& sp : plan.slots) {
        const HexTiling& h = sp.slot->hex;
        if (!h.enabled || sp.heightOnly) continue;
        const std::string& n = sp.slot->name;
        auto fixed = [&](const std::string& name, double value) { plan.specialised.push_back({name, "float", {value}, {n}, {}, 0, std::nullopt}); };
        if (sp.gainInt) fixed(n + "_falloff", h.falloff);
        else if (sp.gain) params.add(n + "_falloff", {h.falloff}, {n});
        if (sp.metric) params.add(n + "_falloffcontrast", {h.falloffcontrast}, {n});
        if (sp.exponentInt) fixed(n + "_exponent", h.exponent);
        else params.add(n + "_exponent", {h.exponent}, {n});
        if (sp.slot->heightBlend) params.add(n + "_heightwidth", {sp.slot->heightBlend->width}, {n});
    }
    params.finish();
    return plan;
}

}  // namespace hexc
