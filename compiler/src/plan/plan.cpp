#include "plan/plan.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "hexc/files.h"
#include "hexc/suggest.h"
#include "common/by_enum.h"
#include "common/templates.h"
#include "common/text.h"
#include "material/json_locator.h"
#include "plan/layer_arrays.h"
#include "plan/layers.h"
#include "plan/macros.h"
#include "plan/pack.h"
#include "plan/template_fit.h"

namespace hexc {

namespace {

// Reads the template the options or the material name into plan.templateSource; false (with an error) when it
// cannot be used.
bool loadTemplate(const Material& material, const CompileOptions& options, ShaderPlan& plan) {
    auto error = [&](Code code, std::string message) {
        plan.diagnostics.push_back(Diagnostic::make(code, {plan.templateName}, "", std::move(message)));
    };
    const TemplateRef ref = effectiveTemplate(material, options);
    plan.templateName = ref.path();
    if (ref.file) {
        plan.templateFile = ref.name;
        std::string why;
        std::optional<std::string> text = readFile(ref.name, &why);
        if (!text) {
            error(Code::TemplateUnreadable, "cannot read template file: " + why);
            return false;
        }
        plan.templateSource = std::move(*text);
    } else {
        const std::string* text = embeddedText(ref.name + ".glsl");
        if (!text) {
            error(Code::UnknownTemplate, "no built-in template `" + ref.name + "`");
            return false;
        }
        plan.templateSource = *text;
    }
    // The manifest names a material's own template as the material wrote it, so it does not depend on where hexc
    // was run from; a --template file as given.
    plan.templateShown = ref.file ? ref.asWritten : plan.templateName;
    if (std::optional<size_t> at = invalidUtf8(plan.templateSource)) {  // its comments go into the manifest, JSON
        const TextPos p = textPosition(plan.templateSource, *at);
        plan.diagnostics.push_back(Diagnostic::make(Code::TemplateUnreadable, {plan.templateName, p.line, p.col}, "",
                                                    "the template is not UTF-8 (byte 0x" + hexByte(plan.templateSource[*at]) + ")"));
        return false;
    }
    if (!plan.templateSource.starts_with("#version") || plan.templateSource.find('\n') == std::string::npos)
        error(Code::TemplateNoVersion, "a template must start with a `#version` line");
    if (countLines(plan.templateSource, "#include <hexc>") != 1)
        error(Code::TemplateNoInclude, "a template must contain the line `#include <hexc>` exactly once (where hexc injects its code)");
    std::vector<TemplateSlot> declared = readTemplateSlots(plan.templateSource, plan.templateName, plan.diagnostics);
    for (Diagnostic& d : checkTemplateFit(declared, material, ref.name)) plan.diagnostics.push_back(std::move(d));
    const MacroExpansion e = boundMacroExpansion(plan.templateSource);
    if (e.line) {
        plan.diagnostics.push_back(Diagnostic::make(Code::TemplateTooLarge, {plan.templateName, e.line, 0}, "",
                                                    "the template's macros expand to more than " + std::to_string(int(kMaxExpandedTokens)) +
                                                        " tokens by this line; hexc refuses it rather than stall the preprocessor"));
    }
    if (e.callsLine)
        plan.diagnostics.push_back(Diagnostic::make(Code::TemplateTooLarge, {plan.templateName, e.callsLine, 0}, "",
                                                    "the template makes more than " + std::to_string(kMaxTemplateCalls) +
                                                        " calls by this line; glslang's call graph and spirv-opt's inliner grow "
                                                        "quadratically with them, so hexc refuses it rather than stall"));
    return !hasErrors(plan.diagnostics);
}

// The slots the template reads (`read`), and those whose texture is bound (`needed`): those read and the
// height maps they blend by.
struct SlotUse {
    std::vector<bool> read, needed;
};

SlotUse slotUse(const Material& material, const std::string& templateSource, bool all) {
    bool readsFirst = containsWord(templateSource, "HEXC_FIRST_SLOT");
    SlotUse use{std::vector<bool>(material.slots.size()), std::vector<bool>(material.slots.size())};
    for (size_t i = 0; i < material.slots.size(); ++i) {
        const Slot& slot = material.slots[i];
        if (!all && !containsWord(templateSource, "hexc_" + slot.name) && !(i == 0 && readsFirst && !material.layers) &&
            !layerSlotRead(material, i, templateSource, readsFirst))
            continue;
        use.read[i] = use.needed[i] = true;
        if (slot.heightBlend)
            for (size_t j = 0; j < material.slots.size(); ++j)
                use.needed[j] = use.needed[j] || material.slots[j].name == slot.heightBlend->slot;
    }
    return use;
}

// A read slot's snippets and features. `all`: without specialisation every feature is emitted, and the values
// decide at run time.
SlotPlan planSlot(const Slot& slot, bool all) {
    const HexTiling& h = slot.hex;
    const bool triplanar = h.projection == Projection::Triplanar;
    SlotPlan sp;
    sp.slot = &slot;
    sp.histogram = h.enabled && h.blend == Blend::Histogram;  // the parser has left it only on colour and scalar slots
    const bool materialx = h.enabled && h.mode == HashMode::MaterialX;
    sp.section = std::string(toString(kindRow(slot.kind).like)) + (!h.enabled     ? ".plain"
                                                                   : materialx    ? ".materialx"
                                                                   : h.taps == 1  ? ".hex1"
                                                                   : sp.histogram ? ".histogram"
                                                                                  : ".hex");
    sp.coordinates = triplanar ? "triplanar" : h.splitCoordinates ? "uv.split" : "uv";
    // A triplanar derivative (normal) slot returns a world-space surface gradient.
    sp.type = triplanar && kindRow(slot.kind).derivative ? "vec3" : kindRow(slot.kind).glslType;
    sp.projection = h.projection;
    sp.explicitGradients = triplanar;
    sp.sharedLod = h.lod == Lod::Shared;
    // Tiles turn in texel-isotropic space (docs/material-format.md#per-tile-transforms); the paper's mode turns st.
    if (h.mode != HashMode::Paper && slot.width > 0 && slot.height > 0) sp.aspect = double(slot.width) / slot.height;
    // One tap needs no falloff metric: it has a single sample to weigh.
    // The histogram blend weighs tiles by the lattice alone: a metric would break the variance its weights keep.
    sp.metric = h.taps != 1 && !sp.histogram && (all || h.falloffcontrast != 0);
    sp.gain = all || h.falloff != 0.5;
    // Whole-number exponents become multiplications: gamma = 7 (the paper's) and the gain at r = 1 - 2^-k
    // (the paper's 0.75 is k = 2) then cost no pow. Like the feature switches, they fix the value in the code, so
    // only for the blend that reads them (hexcBlendWeights): MaterialX mode's Schlick gain reads the falloff itself.
    if (!all && h.exponent == std::floor(h.exponent) && h.exponent <= 16) sp.exponentInt = int(h.exponent);
    double k = std::log2(1.0 / (1.0 - h.falloff));
    if (!all && !materialx && sp.gain && std::fabs(k - std::round(k)) < 1e-12 && k >= 2 && k <= 16) sp.gainInt = int(std::round(k));
    return sp;
}

LatticePlan planLattice(const HexTiling& h, bool all, int repeats) {
    static constexpr auto kMaskLattices = byEnum<Mask::Noise3>({"lattice.stable", "lattice.checker", "lattice.noise", "lattice.noise"});
    LatticePlan l;
    l.section = h.mode == HashMode::Paper       ? "lattice.paper"
                : h.mode == HashMode::MaterialX ? "lattice.materialx"
                                                : kMaskLattices[size_t(h.mask)];
    if (repeats > 0 && l.section == "lattice.stable") {
        // P = round(K A0), A0 = (97/28, -2; 0, 4) stable mode's skew (templates/library/hextiling/lattice.glsl).
        l.section = "lattice.periodic";
        l.repeats = repeats;
        l.period = {int(std::lround(97.0 * repeats / 28.0)), 0, -2 * repeats, 4 * repeats};
    } else if (repeats > 0 && l.section == "lattice.checker") {
        l.section = "lattice.checker.periodic";  // its cells wrapped modulo K maskScale
        l.repeats = repeats;
    }
    l.rotate = all || h.rotation != 0;
    l.transform = h.hasTransforms();
    l.rotationSteps = h.rotationSteps;
    l.offsetSteps = h.offsetSteps;
    l.maskScale = h.maskScale;
    l.triple = h.mask == Mask::Noise3;
    return l;
}

// A slot the template does not read, as a warning; where the template calls a `hexc_<name>` no slot has and the
// unread slot's is the closest, at that call, with "did you mean" (a typo in the template, not an unused slot).
Diagnostic slotNotRead(const Material& material, const Slot& slot, const ShaderPlan& plan) {
    const std::string message = "slot `" + slot.name + "` is not read by template " + plan.templateName + "; it is left out";
    const std::string& text = plan.templateSource;
    std::vector<std::string> names;
    for (const Slot& s : material.slots) names.push_back("hexc_" + s.name);
    for (size_t at = text.find("hexc_"); at != std::string::npos; at = text.find("hexc_", at + 1)) {
        if (at > 0 && (std::isalnum(static_cast<unsigned char>(text[at - 1])) || text[at - 1] == '_')) continue;
        size_t end = at + 5;
        while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_')) ++end;
        const std::string called = text.substr(at, end - at);
        if (std::find(names.begin(), names.end(), called) != names.end() || closestMatch(called, names) != "hexc_" + slot.name) continue;
        const size_t lineStart = text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
        const int line = 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n'));
        return Diagnostic::make(Code::SlotNotRead, {plan.templateName, line, int(at - lineStart) + 1}, "",
                                message + "; the template calls `" + called + "`, which no slot defines",
                                "did you mean `hexc_" + slot.name + "`?");
    }
    // At the slot (its kind, which every slot states), so that an editor shows which one.
    const size_t index = size_t(&slot - material.slots.data());
    return Diagnostic::make(Code::SlotNotRead, {material.sourceFile.string(), slot.line, slot.col}, "/slots/" + std::to_string(index),
                            message);
}

// plan.slots and plan.lattices; a slot joins the first lattice computed from the same settings when sharing.
void planSlots(const Material& material, const CompileOptions& options, ShaderPlan& plan) {
    SlotUse use = slotUse(material, plan.templateSource, plan.functions);
    std::vector<const LatticeSettings*> latticeKeys;
    uint32_t binding = plan.bindings.firstTexture;
    for (size_t i = 0; i < material.slots.size(); ++i) {
        const Slot& slot = material.slots[i];
        if (!use.needed[i]) {
            plan.diagnostics.push_back(slotNotRead(material, slot, plan));
            continue;
        }
        SlotPlan sp;
        sp.slot = &slot;
        sp.heightOnly = !use.read[i];
        if (!sp.heightOnly) {
            sp = planSlot(slot, !options.specialise);
            size_t& l = sp.lattice;
            while (l < latticeKeys.size() && !(options.shareLattice && *latticeKeys[l] == slot.hex.lattice())) ++l;
            if (l == latticeKeys.size()) {
                latticeKeys.push_back(&slot.hex.lattice());
                plan.lattices.push_back(planLattice(slot.hex, !options.specialise, options.periodicRepeats));
            }
        }
        sp.name = sp.heightMapName = slot.name;
        sp.kind = slot.kind;
        sp.flipY = slot.flipY;
        sp.srgb = slot.shaderDecodes();
        sp.luma = slot.hex.lumacoeffs;
        sp.channel = slot.channel;
        sp.taps = slot.hex.taps == 1 ? 1 : slot.hex.maskTaps();
        sp.adaptive = slot.hex.adaptive();
        sp.binding = binding++;
        if (sp.histogram) plan.luts.push_back(plan.slots.size());
        plan.slots.push_back(sp);
    }
    for (SlotPlan& sp : plan.slots) {
        if (sp.heightOnly || !sp.slot->heightBlend) continue;
        for (size_t j = 0; j < plan.slots.size(); ++j)
            if (plan.slots[j].name == sp.slot->heightBlend->slot) {
                sp.heightMap = j;
                sp.heightMapName = plan.slots[j].name;
                sp.heightChannel = plan.slots[j].channel;
            }
    }
}

class ParamBuilder {
public:
    ParamBuilder(ShaderPlan& plan, bool bake) : plan_(plan), bake_(bake) {}

    // `setting` of `slots`, referred to by `ref`: named after the first slot, the others' names its aliases.
    // Per-frame values are always block members, others are baked on request.
    void add(ParamRef& ref, const std::string& setting, std::vector<double> value, const std::vector<std::string>& slots,
             bool integer = false, std::string perFrame = {}) {
        ParamMember m;
        m.name = slots.front() + "_" + setting;
        for (size_t i = 1; i < slots.size(); ++i) m.aliases.push_back(slots[i] + "_" + setting);
        m.type = value.size() == 2 ? (integer ? "ivec2" : "vec2") : (integer ? "int" : "float");
        m.value = std::move(value);
        m.slots = slots;
        m.perFrame = std::move(perFrame);
        place(ref, std::move(m));
    }

    // A float setting of no one slot (the layers' blend), named `name`, read by `slots`.
    void addNamed(ParamRef& ref, const std::string& name, double value, const std::vector<std::string>& slots) {
        ParamMember m;
        m.name = name;
        m.type = "float";
        m.value = {value};
        m.slots = slots;
        place(ref, std::move(m));
    }

    // Block members first, in block order, then the baked constants.
    void finish() {
        plan_.paramBlockSize = (plan_.paramBlockSize + 15) / 16 * 16;
        for (ParamRef* ref : constantRefs_) **ref += plan_.params.size();
        plan_.params.insert(plan_.params.end(), constants_.begin(), constants_.end());
    }

private:
    void place(ParamRef& ref, ParamMember m) {
        if (bake_ && m.perFrame.empty()) {
            m.constantId = nextConstant_;
            nextConstant_ += uint32_t(m.value.size());
            ref = constants_.size();
            constantRefs_.push_back(&ref);
            constants_.push_back(std::move(m));
            return;
        }
        // std140: scalars align to 4, two-component vectors to 8.
        uint32_t size = uint32_t(m.value.size()) * 4;
        m.offset = (plan_.paramBlockSize + size - 1) / size * size;
        plan_.paramBlockSize = m.offset + size;
        ref = plan_.params.size();
        plan_.params.push_back(std::move(m));
    }

    ShaderPlan& plan_;
    bool bake_;
    uint32_t nextConstant_ = 0;
    std::vector<ParamMember> constants_;
    std::vector<ParamRef*> constantRefs_;
};

// A lattice's parameters, read by `users` (the slots computed on it), for the features it emits.
void addLatticeParams(ParamBuilder& params, LatticePlan& l, const HexTiling& h, const std::vector<std::string>& users) {
    params.add(l.tiling, "tiling", {h.tiling[0], h.tiling[1]}, users);
    if (h.projection == Projection::Triplanar) params.add(l.planeSharpness, "planesharpness", {h.planeSharpness}, users);
    if (!h.enabled) return;
    if (l.rotate) params.add(l.rotation, "rotation", {h.rotation}, users);
    if (l.transform) {
        params.add(l.rotationRange, "rotationrange", {h.rotationRange[0], h.rotationRange[1]}, users);
        params.add(l.scaleRange, "scalerange", {h.scaleRange[0], h.scaleRange[1]}, users);
        params.add(l.offset, "offset", {h.offset}, users);
    }
    if (h.splitCoordinates) {
        // Filled per frame by the engine from its double-precision origin (docs/precision.md).
        params.add(l.originCell, "origin_cell", {0, 0}, users, true,
                   "floor(st / (28, 1)) with st = origin_uv * tiling in double, stored modulo 2^32 (hexc/origin.h)");
        params.add(l.originOffset, "origin_offset", {0, 0}, users, false, "st - cell * (28, 1), as float (hexc/origin.h)");
    }
}

// A slot's own parameters, for the features it emits; specialised values are listed in plan.specialised.
void addSlotParams(ParamBuilder& params, SlotPlan& sp, std::vector<ParamMember>& specialised) {
    const HexTiling& h = sp.slot->hex;
    const std::string& n = sp.slot->name;
    auto fixed = [&](const std::string& setting, double value) {
        ParamMember m;
        m.name = n + "_" + setting;
        m.type = "float";
        m.value = {value};
        m.slots = {n};
        specialised.push_back(std::move(m));
    };
    if (sp.gainInt)
        fixed("falloff", h.falloff);
    else if (sp.gain)
        params.add(sp.falloff, "falloff", {h.falloff}, {n});
    if (sp.metric) params.add(sp.falloffContrast, "falloffcontrast", {h.falloffcontrast}, {n});
    if (sp.exponentInt)
        fixed("exponent", h.exponent);
    else
        params.add(sp.exponent, "exponent", {h.exponent}, {n});
    if (sp.slot->heightBlend) params.add(sp.heightWidth, "heightwidth", {sp.slot->heightBlend->width}, {n});
}

// Parameters: each lattice's, then each slot's, only for the features emitted.
void planParams(bool bake, ShaderPlan& plan) {
    ParamBuilder params(plan, bake);
    for (size_t i = 0; i < plan.lattices.size(); ++i) {
        std::vector<std::string> users;
        const HexTiling* settings = nullptr;  // the same for every user
        for (const SlotPlan& sp : plan.slots) {
            if (sp.lattice != i || sp.heightOnly) continue;
            users.push_back(sp.slot->name);
            settings = &sp.slot->hex;
        }
        addLatticeParams(params, plan.lattices[i], *settings, users);
    }
    for (SlotPlan& sp : plan.slots)
        if (sp.slot->hex.enabled && !sp.heightOnly) addSlotParams(params, sp, plan.specialised);
    if (plan.layers && plan.general) {  // read where the weights are filled: with the splat maps
        LayersPlan& lp = *plan.layers;
        std::vector<std::string> splats;
        for (size_t s : lp.splats) splats.push_back(plan.slots[s].name);
        params.addNamed(lp.skipBelowParam, "layer_blend_skip_below", lp.skipBelow, splats);
        if (!lp.heights.empty()) params.addNamed(lp.widthParam, "layer_blend_width", lp.width, splats);
    }
    params.finish();
}

// The functions output's functions take texture coordinates: a triplanar material's take a position and a normal.
void refuseTriplanar(const Material& material, ShaderPlan& plan) {
    if (material.hex.projection == Projection::Triplanar)
        plan.diagnostics.push_back(Diagnostic::make(Code::TargetUnsupported, {material.sourceFile.string()}, "/hextiling/projection",
                                                    "the functions output (--functions, --engine) takes texture coordinates; this "
                                                    "material is projected triplanar",
                                                    "compile it as a shader, or use the uv projection"));
}

}  // namespace

TemplateRef effectiveTemplate(const Material& material, const CompileOptions& options) {
    if (options.functions) return TemplateRef::builtin("functions");
    return options.templateFile.empty() ? material.templ : TemplateRef::parse(options.templateFile.string());
}

Diagnostics checkTemplate(const Material& material, const CompileOptions& options) {
    ShaderPlan plan;
    loadTemplate(material, options, plan);
    return plan.diagnostics;
}

Diagnostics checkTemplateReadsSlots(const Material& material, const CompileOptions& options) {
    ShaderPlan plan;
    if (material.slots.empty() || !loadTemplate(material, options, plan)) return {};  // compile() reports the template's problems
    const bool all = options.functions || plan.templateName == TemplateRef::builtin("functions").path();
    const SlotUse use = slotUse(material, plan.templateSource, all);
    if (std::find(use.read.begin(), use.read.end(), true) != use.read.end()) return {};
    Diagnostics ignored;  // a malformed declaration is compile()'s to report
    return {readsNoSlot(readTemplateSlots(plan.templateSource, plan.templateName, ignored), material, plan.templateName)};
}

ShaderPlan planShader(const Material& material, const CompileOptions& options) {
    ShaderPlan plan;
    plan.materialName = material.name;
    plan.layout = options.layout;
    plan.entryPoint = options.entryPoint.empty() ? defaultEntryPoint(material.name) : options.entryPoint;
    plan.bindings = HexcBindings(options.layout.vulkan);
    plan.general = !options.specialise;
    plan.slotTexturesDecoded = options.slotTexturesDecoded;
    plan.uvBottomLeft = options.uvOrigin == UvOrigin::BottomLeft;
    plan.exrTables = options.exrTables;
    if (!loadTemplate(material, options, plan)) return plan;
    // The built-in `functions` named by a material is the functions output, as with --functions.
    plan.functions = options.functions || plan.templateName == TemplateRef::builtin("functions").path();
    plan.functionArrays = options.functionArrays;
    planSlots(material, options, plan);
    planLayers(material, options.shareLattice, plan);
    if (plan.layers && !options.skipLayers) {  // every layer fetched at every pixel: the worst case is the expected one
        plan.layers->skip = false;
        plan.layers->expectedFetches = plan.layers->worstFetches;
    }
    if (plan.functions) refuseTriplanar(material, plan);
    if (material.pack) planPacks(plan);
    planLayerArrays(material, plan);
    planParams(options.bake, plan);
    return plan;
}

std::vector<EngineFunction> engineFunctions(const ShaderPlan& plan) {
    std::vector<EngineFunction> functions;
    if (plan.layers) {  // an engine calls the roles' blends, not the layers' slots
        const bool color = plan.layers->weights != LayerWeights::Splat;
        for (const LayerRolePlan& r : plan.layers->roles) {
            const SlotPlan* first = &plan.slots[r.slots.front()];
            functions.push_back({"hexc_" + r.name, first, false, r.name, color});
            if (kindRow(r.kind).derivative) functions.push_back({"hexc_" + r.name + "_normal", first, true, r.name, color});
        }
        return functions;
    }
    for (const SlotPlan& sp : plan.slots) {
        if (sp.heightOnly) continue;
        functions.push_back({"hexc_" + sp.slot->name, &sp, false, {}});
        if (kindRow(sp.kind).derivative) functions.push_back({"hexc_" + sp.slot->name + "_normal", &sp, true, {}});
    }
    return functions;
}

}  // namespace hexc
