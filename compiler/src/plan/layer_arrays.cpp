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

constexpr const char* kResize = "resize them to one size";

// Why slot `s` cannot be a layer of the array whose layer 0 is `first`, and how to make it one; empty when it can: one
// texture, one sampler and one full mip chain must serve every layer alike (the manifest's `sampler`: the same state
// for all textures).
struct Unlike {
    std::string why, fix;
};

Unlike unlike(const Slot& first, const Slot& s) {
    const std::string pair = "`" + first.name + "` and `" + s.name + "`";
    if (s.width != first.width || s.height != first.height)
        return {"sizes differ: " + pair + " are " + size(first) + " and " + size(s) + " texels", kResize};
    if (format(s) != format(first))
        return {"formats differ: " + pair + " are " + format(first) + " and " + format(s), "store them in one format"};
    if (s.channelNames != first.channelNames)
        return {"channels differ: " + pair + " have " + first.channelNames + " and " + s.channelNames, "give them the same channels"};
    if (s.samplerDecodes() != first.samplerDecodes())
        return {"colour spaces differ: " + pair + " are bound as " + (first.samplerDecodes() ? "sRGB" : "linear") + " and " +
                    (s.samplerDecodes() ? "sRGB" : "linear"),
                "give them one `colorspace`"};
    return {};
}

// Why slot `sp` is read in a way the array forms of the library do not cover, or empty.
std::string unreadable(const SlotPlan& sp) {
    if (!sp.slot->file) return "slot `" + sp.name + "` has no texture file to assemble the array from";
    if (sp.pack) return "slot `" + sp.name + "` reads a packed texture";
    return {};
}

// a.refused: why the role's slots stay separate textures, or empty when they make one array (a KTX2 array's role: one
// array even with one layer, as the file is). Where the settings expect an array (`arrays` "auto", specialised shader
// code, not the functions output), also a.fix and a.unlike: how to get one, and the slot that refuses it.
void refuse(const Layers& layers, const ShaderPlan& plan, LayerArrayPlan& a) {
    const std::vector<size_t>& slots = a.slots;
    if (!layers.arrays)
        a.refused = "layer_blend.arrays is \"off\"";
    else if (slots.size() < 2 && a.ktx2.empty())
        a.refused = "one layer: there is nothing to share";
    else if (plan.general)
        a.refused = "--no-specialise: the library's general functions read 2D textures";
    else if (plan.functions && plan.functionArrays == FunctionArrays::None)
        a.refused = "the functions output (engine packages) binds one texture per slot (docs/engines.md)";
    if (!a.refused.empty()) return;
    const Slot& first = *plan.slots[slots.front()].slot;
    if (plan.functions && plan.functionArrays == FunctionArrays::Linear && first.samplerDecodes()) {
        a.refused = "the engine package has no sRGB array texture: an sRGB role binds one texture per slot (docs/engines.md)";
        return;
    }
    for (size_t i : slots) {
        Unlike u{unreadable(plan.slots[i]), plan.slots[i].pack ? "leave `pack` off" : ""};
        if (u.why.empty()) u = unlike(first, *plan.slots[i].slot);
        if (u.why.empty()) continue;
        a.refused = u.why;
        a.fix = u.fix;
        a.unlike = i;
        return;
    }
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
                const bool follows = a.refused.empty();  // this array follows its height maps' refusal, else they follow it
                LayerArrayPlan& refused = follows ? a : *heights;
                const LayerArrayPlan* cause = follows ? heights : &a;
                refused.refused = "slot `" + sp.name + "` height-blends its tiles by `" + plan.slots[*sp.heightMap].name +
                                  "`, and the two are read alike: as arrays or as separate textures";
                refused.fix = cause && !cause->fix.empty() ? "make role `" + cause->role + "` one array" : "";
                refused.unlike = refused.slots.front();
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

// The JSON pointer of plan slot `i`: /slots/<n> in a material without layers; a layer's slot's under /layers (a layer's
// slots follow each other in Material::slots in the order its `slots` lists them).
std::string slotPointer(const Material& material, const ShaderPlan& plan, size_t i) {
    const size_t index = size_t(plan.slots[i].slot - material.slots.data());
    if (!material.layers) return "/slots/" + std::to_string(index);
    const std::vector<Layers::Layer>& layers = material.layers->layers;
    for (size_t l = 0; l < layers.size(); ++l) {
        const std::vector<size_t>& slots = layers[l].slots;
        if (std::find(slots.begin(), slots.end(), index) != slots.end())
            return "/layers/" + std::to_string(l) + "/slots/" + std::to_string(index - *std::min_element(slots.begin(), slots.end()));
    }
    return "/layers";
}

// A role whose settings expect one array and whose textures refuse it (HX129, at the slot that differs): what it costs
// (a texture unit per layer) and how to get the array. Sizes are listed for every layer, the usual cause.
void notArrayed(const Material& material, ShaderPlan& plan, const LayerArrayPlan& a) {
    std::string why = a.refused;
    if (a.fix == kResize) {
        why = "sizes differ:";
        for (size_t layer = 0; layer < a.slots.size(); ++layer)
            why += std::string(layer == 0 ? " " : ", ") + "layer `" + material.layers->layers[layer].name + "` " +
                   size(*plan.slots[a.slots[layer]].slot);
    }
    const Slot& at = *plan.slots[a.unlike].slot;
    plan.diagnostics.push_back(Diagnostic::make(
        Code::NotArrayed, {material.sourceFile.string(), at.line, at.col}, slotPointer(material, plan, a.unlike),
        "role `" + a.role + "` is " + std::to_string(a.slots.size()) + " textures, one per layer, not one texture array (" +
            std::to_string(a.slots.size()) + " texture units instead of 1): " + why,
        a.fix + " for one array, or set layer_blend.arrays to \"off\" for separate textures"));
}

// Where a layered material's textures over the limit are reported, and what binds fewer: one array per role where a
// role's layers are apart (at the first slot that keeps them apart), else packing or fewer roles (at the first layer slot).
std::pair<size_t, std::string> layeredFewer(const ShaderPlan& plan) {
    std::string apart;
    size_t at = plan.layers->roles.front().slots.front();
    for (const LayerArrayPlan& a : plan.layers->arrays) {
        if (a.refused.empty()) continue;
        apart += (apart.empty() ? "" : "; ") + ("role `" + a.role + "` (" + a.refused + (a.fix.empty() ? "" : ": " + a.fix) + ")");
        if (!a.fix.empty()) at = a.unlike;
    }
    if (apart.empty()) return {at, "pack a layer's scalar maps into one texture's channels (`channel`) or drop a role"};
    return {at, "bind each role's layers as one texture array, one texture instead of one per layer: " + apart};
}

// The textures the shader binds, as they are bound: a role's array once, a packed texture once, a histogram slot's
// table besides its texture, every other slot its own. At most 16, Vulkan's guaranteed minimum of sampled images per
// stage (a material's own slots are held to it when parsed, its tables are not); over it, HX110 with what binds fewer:
// in a material without layers only the tables can take it over, so at its first histogram slot.
void refuseTooManyTextures(const Material& material, ShaderPlan& plan) {
    size_t bound = 0;
    for (size_t i = 0; i < plan.textureCount(); ++i) bound += plan.textureBound(i);
    if (bound <= kMaxTextures) return;
    const auto [at, hint] = plan.layers
                                ? layeredFewer(plan)
                                : std::pair<size_t, std::string>{
                                      plan.luts.front(), "blend a slot by falloff: a histogram slot binds its table besides its texture"};
    const Slot& slot = *plan.slots[at].slot;
    plan.diagnostics.push_back(Diagnostic::make(Code::WrongCount, {material.sourceFile.string(), slot.line, slot.col},
                                                slotPointer(material, plan, at),
                                                "the shader binds " + std::to_string(bound) +
                                                    " textures (a texture array or a packed texture counted once, a histogram "
                                                    "slot's table too); expected at most " +
                                                    std::to_string(kMaxTextures),
                                                hint));
}

}  // namespace

void planLayerArrays(const Material& material, ShaderPlan& plan) {
    if (!plan.layers) return refuseTooManyTextures(material, plan);
    const Layers& layers = *material.layers;
    std::vector<LayerArrayPlan> arrays;
    for (size_t r = 0; r < layers.roles.size(); ++r) {
        LayerArrayPlan a;
        a.role = layers.roles[r].name;
        a.ktx2 = layers.roles[r].ktx2Array;
        for (const Layers::Layer& l : layers.layers) a.slots.push_back(planIndex(plan, l.slots[r], material));
        if (std::count(a.slots.begin(), a.slots.end(), std::string::npos) != 0) continue;  // a role the shader does not read
        refuse(layers, plan, a);
        arrays.push_back(std::move(a));
    }
    matchHeightMaps(plan, arrays);
    for (const LayerArrayPlan& a : arrays) {
        if (!a.ktx2.empty() && !a.refused.empty() && !plan.slotTexturesDecoded)
            unsplittable(material, plan, a);
        else if (!a.fix.empty())
            notArrayed(material, plan, a);
    }
    for (const LayerArrayPlan& a : arrays) {
        if (!a.refused.empty()) continue;
        for (size_t layer = 0; layer < a.slots.size(); ++layer) {
            plan.slots[a.slots[layer]].array = "hexcArr_" + a.role;
            plan.slots[a.slots[layer]].arrayLayer = int(layer);
        }
    }
    plan.layers->arrays = std::move(arrays);
    refuseTooManyTextures(material, plan);
}

}  // namespace hexc
