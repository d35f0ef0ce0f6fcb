// LayersPlan::arrays: which roles' textures across layers are bound as one 2D array texture, and why the others are not.
#include "plan/layer_arrays.h"

#include <algorithm>

#include "hexc/image.h"

namespace hexc {
namespace {

std::string size(const Slot& s) { return std::to_string(s.width) + "x" + std::to_string(s.height); }

std::string format(const Slot& s) {
    if (!s.file->info.format.empty()) return s.file->info.format;
    return s.eightBit ? "8-bit" : "float";
}

// Why slot `s` cannot be a layer of the array whose layer 0 is `first`, or empty when it can: one texture, one sampler
// and one full mip chain must serve every layer alike (the manifest's `sampler`: the same state for all textures).
std::string unlike(const Slot& first, const Slot& s) {
    const std::string pair = "`" + first.name + "` and `" + s.name + "`";
    if (s.width != first.width || s.height != first.height)
        return "sizes differ: " + pair + " are " + size(first) + " and " + size(s) + " texels";
    if (format(s) != format(first)) return "formats differ: " + pair + " are " + format(first) + " and " + format(s);
    if (s.channelNames != first.channelNames) return "channels differ: " + pair + " have " + first.channelNames + " and " + s.channelNames;
    if (s.samplerDecodes() != first.samplerDecodes())
        return "colour spaces differ: " + pair + " are bound as " + (first.samplerDecodes() ? "sRGB" : "linear") + " and " +
               (s.samplerDecodes() ? "sRGB" : "linear");
    return {};
}

// Why slot `sp` is read in a way the array forms of the library do not cover, or empty.
std::string unreadable(const SlotPlan& sp) {
    if (!sp.slot->file) return "slot `" + sp.name + "` has no texture file to assemble the array from";
    if (sp.pack) return "slot `" + sp.name + "` reads a packed texture";
    return {};
}

// Why the role's slots stay separate textures, or empty when they make one array (a KTX2 array's role: one array even
// with one layer, as the file is).
std::string refusal(const Layers& layers, const ShaderPlan& plan, const LayerArrayPlan& a) {
    const std::vector<size_t>& slots = a.slots;
    if (!layers.arrays) return "layer_blend.arrays is \"off\"";
    if (slots.size() < 2 && a.ktx2.empty()) return "one layer: there is nothing to share";
    if (plan.general) return "--no-specialise: the library's general functions read 2D textures";
    if (plan.functions) return "the functions output (engine packages) binds one texture per slot (docs/engines.md)";
    const Slot& first = *plan.slots[slots.front()].slot;
    for (size_t i : slots) {
        if (std::string why = unreadable(plan.slots[i]); !why.empty()) return why;
        if (std::string why = unlike(first, *plan.slots[i].slot); !why.empty()) return why;
    }
    return {};
}

// Slot `i`'s index in plan.slots of the material slot, or npos when the shader does not read it.
size_t planIndex(const ShaderPlan& plan, size_t materialSlot, const Material& material) {
    const Slot* s = &material.slots[materialSlot];
    for (size_t i = 0; i < plan.slots.size(); ++i)
        if (plan.slots[i].slot == s && !plan.slots[i].heightOnly) return i;
    return std::string::npos;
}

// A slot that height-blends its tiles by another slot's texture passes both to one library function, which reads them
// alike: as layer i of two arrays, or as two separate textures. Where they differ, the array is refused, until none does.
void matchHeightMaps(const ShaderPlan& plan, std::vector<LayerArrayPlan>& arrays) {
    auto holding = [&](size_t slot, size_t layer) -> LayerArrayPlan* {
        for (LayerArrayPlan& a : arrays)
            if (a.slots[layer] == slot) return &a;
        return nullptr;
    };
    for (bool changed = true; changed;) {
        changed = false;
        for (LayerArrayPlan& a : arrays) {
            for (size_t layer = 0; layer < a.slots.size(); ++layer) {
                const SlotPlan& sp = plan.slots[a.slots[layer]];
                if (!sp.heightMap || *sp.heightMap == a.slots[layer]) continue;
                LayerArrayPlan* heights = holding(*sp.heightMap, layer);
                if (a.refused.empty() == (heights && heights->refused.empty())) continue;
                (a.refused.empty() ? a : *heights).refused = "slot `" + sp.name + "` height-blends its tiles by `" +
                                                             plan.slots[*sp.heightMap].name +
                                                             "`, and the two are read alike: as arrays or as separate textures";
                changed = true;
            }
        }
    }
}

// A KTX2 array is bound as the file is: a role that would need a texture per slot cannot read one.
void unsplittable(const Material& material, ShaderPlan& plan, const LayerArrayPlan& a) {
    const Slot& first = *plan.slots[a.slots.front()].slot;
    const auto role =
        std::find_if(material.layers->roles.begin(), material.layers->roles.end(), [&](const Layers::Role& r) { return r.name == a.role; });
    plan.diagnostics.push_back(Diagnostic::make(Code::TextureArray, {material.sourceFile.string(), first.line, first.col},
                                                role->ktx2ArrayPointer,
                                                "role `" + a.role + "` reads the KTX2 array " + a.ktx2 +
                                                    ", bound as one array texture, and this shader needs a texture per slot: " + a.refused,
                                                "give each layer's `" + a.role + "` a 2D texture file of its own"));
}

}  // namespace

void planLayerArrays(const Material& material, ShaderPlan& plan) {
    if (!plan.layers) return;
    const Layers& layers = *material.layers;
    std::vector<LayerArrayPlan> arrays;
    for (size_t r = 0; r < layers.roles.size(); ++r) {
        LayerArrayPlan a{layers.roles[r].name, {}, {}, layers.roles[r].ktx2Array};
        for (const Layers::Layer& l : layers.layers) a.slots.push_back(planIndex(plan, l.slots[r], material));
        if (std::count(a.slots.begin(), a.slots.end(), std::string::npos) != 0) continue;  // a role the shader does not read
        a.refused = refusal(layers, plan, a);
        arrays.push_back(std::move(a));
    }
    matchHeightMaps(plan, arrays);
    for (const LayerArrayPlan& a : arrays)
        if (!a.ktx2.empty() && !a.refused.empty() && !plan.slotTexturesDecoded) unsplittable(material, plan, a);
    for (const LayerArrayPlan& a : arrays) {
        if (!a.refused.empty()) continue;
        for (size_t layer = 0; layer < a.slots.size(); ++layer) {
            plan.slots[a.slots[layer]].array = "hexcArr_" + a.role;
            plan.slots[a.slots[layer]].arrayLayer = int(layer);
        }
    }
    plan.layers->arrays = std::move(arrays);
}

}  // namespace hexc
