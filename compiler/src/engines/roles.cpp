#include "engines/roles.h"

#include <algorithm>
#include <array>

#include "common/by_enum.h"
#include "material/names.h"

namespace hexc {
namespace {

// One row per role: the slot names that take it without a `role`, and each engine's input (null: the engine has
// none). GLSL engines and Unity: the statement that sets the input from `%`; Unreal: the material pin; three.js (both
// renderers) and Babylon.js: the role, which their module's template wires.
struct RoleRow {
    const char* role;
    std::vector<std::string> names;
    std::array<const char*, kEngineCount> inputs;  // in Engine order
};

// One input per engine, in Engine order: a missing one does not compile.
template <size_t N>
std::array<const char*, kEngineCount> I(const char* const (&inputs)[N]) {
    return byEnum<kLastEngine, const char*>(inputs);
}

const std::vector<RoleRow>& roleRows() {
    static const std::vector<RoleRow> rows = {
        {"albedo",
         {"albedo", "basecolor", "base_color", "diffuse"},
         I({"ALBEDO = (%).rgb;", "ALBEDO = (%).rgb;", "material.baseColor = %;", "albedo", "albedo", "surface.albedo = (%).rgb;",
            "Base Color", "albedo"})},
        {"normal",
         {},
         I({"NORMALMAP = % * 0.5 + 0.5;", "NORMAL_MAP = % * 0.5 + 0.5;", "material.normal = %;", "normal", "normal",
            "surface.normalTS = %;", "Normal", "normal"})},
        {"roughness",
         {"roughness"},
         I({"ROUGHNESS = %;", "ROUGHNESS = %;", "material.roughness = %;", "roughness", "roughness", "surface.smoothness = 1.0 - %;",
            "Roughness", "roughness"})},
        {"metallic",
         {"metallic", "metalness"},
         I({"METALLIC = %;", "METALLIC = %;", "material.metallic = %;", "metallic", nullptr, "surface.metallic = %;", "Metallic",
            "metallic"})},
        {"ao",
         {"ao", "occlusion"},
         I({"AO = %;", "AO = %;", "material.ambientOcclusion = %;", "ao", nullptr, "surface.occlusion = %;", "Ambient Occlusion", "ao"})},
        {"emission",
         {"emission", "emissive"},
         I({"EMISSION = (%).rgb;", "EMISSION = (%).rgb;", "material.emissive = vec4((%).rgb, 0.0);", "emission", nullptr,
            "surface.emission = (%).rgb;", "Emissive Color", "emission"})},
    };
    return rows;
}

// The role a slot or a layered material's role of this name and kind takes.
std::string roleNamed(const std::string& name, SlotKind kind) {
    if (kindRow(kind).derivative) return "normal";
    for (const RoleRow& r : roleRows())
        if (std::find(r.names.begin(), r.names.end(), name) != r.names.end()) return roleKind(r.role) == kind ? r.role : "";
    return "";
}

const char* inputOf(const std::string& role, Engine engine) {
    for (const RoleRow& r : roleRows())
        if (role == r.role) return r.inputs[size_t(engine)];
    return nullptr;
}

Diagnostic unusedSlot(const Material& material, const Slot& slot, std::string_view engine, const std::string& function) {
    const size_t index = size_t(&slot - material.slots.data());
    return Diagnostic::make(Code::SlotNotRead, {material.sourceFile.string(), slot.line, slot.col}, "/slots/" + std::to_string(index),
                            "slot `" + slot.name + "` has no " + std::string(engine) +
                                " input (docs/engines.md#slots-and-engine-inputs); its function `" + function +
                                "` is in the package but not called",
                            "give it a `role` the engine has an input for, or call its function yourself");
}

}  // namespace

std::string slotRole(const Slot& slot) { return slot.role.empty() ? roleNamed(slot.name, slot.kind) : slot.role; }

std::vector<WiredFunction> wire(const Material& material, const std::vector<EngineFunction>& functions, const EngineRow& engine,
                                Diagnostics& diagnostics) {
    std::vector<WiredFunction> out;
    std::vector<std::string> taken;  // each input takes one function: the first of its role
    for (const EngineFunction& f : functions) {
        const Slot& slot = *f.slot->slot;
        WiredFunction w{f, f.role.empty() ? slotRole(slot) : roleNamed(f.role, slot.kind)};
        const bool derivative = kindRow(slot.kind).derivative && !f.tangentNormal;
        if (!derivative && std::find(taken.begin(), taken.end(), w.role) == taken.end()) w.input = inputOf(w.role, engine.engine);
        if (w.input)
            taken.push_back(w.role);
        else if (!derivative)
            diagnostics.push_back(unusedSlot(material, slot, engine.shown, f.name));
        out.push_back(std::move(w));
    }
    return out;
}

std::string filled(std::string pattern, const std::string& value) {
    const size_t at = pattern.find('%');
    return at == std::string::npos ? pattern : pattern.replace(at, 1, value);
}

}  // namespace hexc
