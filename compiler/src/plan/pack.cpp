#include "plan/pack.h"

#include <algorithm>

#include "hexc/budgets.h"
#include "hexc/image.h"

namespace hexc {
namespace {

void notPacked(ShaderPlan& plan, size_t i, const std::string& why) {
    plan.diagnostics.push_back(Diagnostic::make(Code::NotPacked, {plan.slots[i].slot->texturePath.string()}, "",
                                                "slot `" + plan.slots[i].slot->name + "` is not packed: " + why));
}

// The channels a slot takes in a packed texture: 3 (a colour slot's RGB), 1 (a scalar's channel), or 0 when it cannot
// be packed. Packing copies 8-bit texels, so the packed texture samples exactly as the slots' own would: float and
// block-compressed textures are not packed. A colour slot returns its texture's alpha, so only an opaque one leaves
// alpha free. Normal slots blend derivatives of 2-3 channels on their own path, and the histogram blend, height
// blending, one tap, triplanar planes and MaterialX mode fetch on paths of their own.
int packChannels(ShaderPlan& plan, size_t i) {
    const SlotPlan& sp = plan.slots[i];
    const Slot& s = *sp.slot;
    const HexTiling& h = s.hex;
    if (sp.heightOnly || !kindRow(s.kind).mayPack || !h.enabled || h.taps == 1 || sp.histogram || s.heightBlend ||
        h.projection == Projection::Triplanar || h.mode == HashMode::MaterialX)
        return 0;
    for (const SlotPlan& other : plan.slots)
        if (other.heightMap == i) return 0;
    if (int64_t(s.width) * s.height > kPackingBudget.texels()) {
        notPacked(
            plan, i,
            "its texture is " + std::to_string(s.width) + "x" + std::to_string(s.height) + "; packing takes " + kPackingBudget.text());
        return 0;
    }
    // The header decides where it can: an 8-bit scalar takes its channel, and an 8-bit colour file without alpha
    // leaves alpha free. Otherwise the texels do: float ones do not pack, and a colour texture's alpha must be opaque.
    if (s.eightBit && kindRow(s.kind).oneChannel) return 1;
    if (s.eightBit && s.channelNames.find('a') == std::string::npos) return 3;
    Texture t;
    try {
        t = decodeTexture(*s.file, false, s.textureLayer);
    } catch (const std::exception&) {
        return 0;  // not decoded here (block-compressed): the texture is bound as it is
    }
    if (t.isFloat()) return 0;
    if (kindRow(s.kind).oneChannel) return 1;
    for (size_t p = 3; p < t.rgba8.size(); p += 4)
        if (t.rgba8[p] != 255) return 0;
    return 3;
}

// Packs of one lattice's slots `group` (declaration order, one texture size): each colour slot with the next linear
// scalar in alpha, then the remaining linear scalars four at a time. A pack of one slot is no pack.
void packGroup(ShaderPlan& plan, const std::vector<size_t>& group, const std::vector<int>& channels) {
    std::vector<size_t> scalars;
    for (size_t i : group) {
        if (channels[i] == 3) continue;
        if (plan.slots[i].slot->colorSpace == ColorSpace::Srgb && group.size() > 1)
            notPacked(plan, i, "an sRGB scalar would not be decoded in a packed texture's alpha or in a linear one");
        else if (plan.slots[i].slot->colorSpace == ColorSpace::Linear)
            scalars.push_back(i);
    }
    auto add = [&](PackPlan p) {
        if (p.slots.size() < 2) return;
        const Slot& first = *plan.slots[p.slots.front()].slot;
        p.width = first.width, p.height = first.height;
        for (size_t k = 0; k < p.slots.size(); ++k) {
            SlotPlan& sp = plan.slots[p.slots[k]];
            sp.section = std::string(toString(kindRow(sp.slot->kind).like)) + ".packed";
            sp.packedChannel = p.channels[k] == "rgb" ? 0 : int(std::string("rgba").find(p.channels[k]));
            sp.channel = sp.packedChannel;
            sp.texture = "hexcTex_" + plan.slots[p.slots.front()].name;
        }
        plan.packs.push_back(std::move(p));
    };
    size_t next = 0;
    for (size_t i : group) {
        if (channels[i] != 3) continue;
        PackPlan p{{i}, {"rgb"}, plan.slots[i].slot->colorSpace == ColorSpace::Srgb};
        if (next < scalars.size()) p.slots.push_back(scalars[next++]), p.channels.push_back("a");
        add(std::move(p));
    }
    for (; next < scalars.size(); next += 4) {
        PackPlan p;
        for (size_t k = next; k < std::min(next + 4, scalars.size()); ++k)
            p.slots.push_back(scalars[k]), p.channels.push_back(std::string(1, "rgba"[k - next]));
        add(std::move(p));
    }
}

}  // namespace

void planPacks(ShaderPlan& plan) {
    std::vector<int> channels(plan.slots.size());
    for (size_t i = 0; i < plan.slots.size(); ++i) channels[i] = packChannels(plan, i);
    std::vector<bool> done(plan.slots.size());
    for (size_t i = 0; i < plan.slots.size(); ++i) {
        if (!channels[i] || done[i]) continue;
        const Slot& first = *plan.slots[i].slot;
        std::vector<size_t> group;
        for (size_t j = i; j < plan.slots.size(); ++j) {
            const Slot& s = *plan.slots[j].slot;
            // The lattice and how the taps fetch (lod): what the shared samples are.
            if (!channels[j] || done[j] || first.hex.lattice() != s.hex.lattice() || s.hex.lod != first.hex.lod) continue;
            if (s.width != first.width || s.height != first.height) {
                notPacked(plan, j,
                          "its texture is " + std::to_string(s.width) + "x" + std::to_string(s.height) + ", slot `" + first.name + "`'s " +
                              std::to_string(first.width) + "x" + std::to_string(first.height) + " (a packed texture has one size)");
                continue;
            }
            group.push_back(j);
            done[j] = true;
        }
        packGroup(plan, group, channels);
    }
    std::sort(plan.packs.begin(), plan.packs.end(), [](const PackPlan& a, const PackPlan& b) { return a.slots < b.slots; });
    for (size_t k = 0; k < plan.packs.size(); ++k)
        for (size_t i : plan.packs[k].slots) plan.slots[i].pack = k;
}

}  // namespace hexc
