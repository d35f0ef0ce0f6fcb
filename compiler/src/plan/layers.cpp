// Material::layers -> ShaderPlan::layers, and the fetches per pixel of the layers' blend.
#include "plan/layers.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <string_view>

#include "common/text.h"
#include "hexc/budgets.h"
#include "hexc/image.h"

namespace hexc {
namespace {

bool roleRead(const Layers& layers, size_t role, const std::string& templateSource, bool readsFirst) {
    return containsWord(templateSource, "hexc_" + layers.roles[role].name) || (role == 0 && readsFirst);
}

bool anyRoleRead(const Layers& layers, const std::string& templateSource, bool readsFirst) {
    for (size_t r = 0; r < layers.roles.size(); ++r)
        if (roleRead(layers, r, templateSource, readsFirst)) return true;
    return false;
}

// Its index in plan.slots.
size_t planIndex(const Material& material, size_t slot, const ShaderPlan& plan) {
    const Slot* s = &material.slots[slot];
    return size_t(std::find_if(plan.slots.begin(), plan.slots.end(), [&](const SlotPlan& sp) { return sp.slot == s; }) -
                  plan.slots.begin());
}

// Fetches of one read of a slot: its taps (every tap for adaptive taps: the worst case, and the bound the expected
// figure uses, since a tap's skip depends on the texels), one when plain tiled or dithered.
double fetches(const SlotPlan& sp) {
    if (!sp.slot->hex.enabled || sp.slot->hex.taps == 1) return 1;
    return sp.taps;
}

// Per layer, the fraction of the splat maps' texels where its weight is at least `skip_below` (hexcLayerKeep keeps it;
// in height mode above 0, where the layer's height is fetched, its shares dropping after the height blend), and
// for layer 0 also where every layer's is below it (an unpainted texel: layer 0 shows), counted over the first map's
// texels (another map's read at the same place). A splat map over its budget is an error in `diagnostics`, refused from
// its header before it is decoded.
std::vector<double> coverage(const Material& material, const Layers& layers, Diagnostics& diagnostics) {
    std::vector<double> out(layers.layers.size(), 1.0);
    bool countable = !layers.splats.empty();
    for (size_t s : layers.splats)
        if (std::optional<Diagnostic> over = overTexelBudget(material, material.slots[s], kSplatBudget)) {
            diagnostics.push_back(*over);
            countable = false;
        }
    std::vector<Texture> maps;
    for (size_t k = 0; countable && k < layers.splats.size(); ++k) {
        const Slot& splat = material.slots[layers.splats[k]];
        maps.push_back(splat.eightBit ? decodeTexture(*splat.file, false) : Texture{});
        countable = !maps.back().rgba8.empty();  // float or block-compressed weights: every layer everywhere, undecoded
    }
    if (!countable) return out;
    const Texture& first = maps[0];
    std::vector<size_t> kept(out.size(), 0);
    for (int y = 0; y < first.height; ++y)
        for (int x = 0; x < first.width; ++x) {
            bool painted = false;
            for (size_t l = 0; l < out.size(); ++l) {
                const Texture& t = maps[l / 4];
                // In 64 bits: a side is up to 65536 texels (a 1 x 50000 splat map is within its budget), so y * height
                // overflows an int.
                const size_t at =
                    size_t(int64_t(y) * t.height / first.height) * size_t(t.width) + size_t(int64_t(x) * t.width / first.width);
                const uint8_t weight = t.rgba8[4 * at + l % 4];
                const bool keeps = layers.heightRole ? weight > 0 : weight / 255.0 >= layers.skipBelow;
                kept[l] += keeps;
                painted = painted || keeps;
            }
            kept[0] += !painted;
        }
    for (size_t l = 0; l < out.size(); ++l) out[l] = double(kept[l]) / (double(first.width) * double(first.height));
    return out;
}

// The location of a stage input declared at `at` (`layout(location = N) [flat|smooth|noperspective|centroid ...]in`),
// or -1.
int inputLocation(std::string_view text, size_t at) {
    const auto skip = [&](std::string_view token) {
        while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
        if (!text.substr(at).starts_with(token)) return false;
        at += token.size();
        return true;
    };
    if (!skip("layout") || !skip("(") || !skip("location") || !skip("=")) return -1;
    while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
    const size_t digits = at;
    while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at]))) ++at;
    if (at == digits || at - digits > 4 || !skip(")")) return -1;
    const int location = std::stoi(std::string(text.substr(digits, at - digits)));
    for (bool qualifier = true; qualifier;) {
        qualifier = false;
        for (std::string_view q : {"flat", "smooth", "noperspective", "centroid"}) {
            const size_t before = at;
            if (skip(q) && at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) {
                qualifier = true;
                break;
            }
            at = before;
        }
    }
    return skip("in") && (at == text.size() || !isIdentifierChar(text[at])) ? location : -1;
}

// The vertex colour's stage input: the lowest location from 4 up that none of the template's own inputs takes
// (hexc's built-in templates and the harness's full-screen draw use 0-3: uv, normal, tangent, position).
int vertexColorLocation(const std::string& templateSource) {
    std::set<int> used;
    for (size_t at = templateSource.find("layout"); at != std::string::npos; at = templateSource.find("layout", at + 1))
        if (const int location = inputLocation(templateSource, at); location >= 0) used.insert(location);
    int location = 4;
    while (used.count(location)) ++location;
    return location;
}

// Where the weights come from (without splat maps every layer covers everything: coverage() gives 1). A shader reads the
// vertex colour as a stage input; the functions output's functions take it as a parameter (codegen/layers.cpp).
void planWeights(const Material& material, LayersPlan& lp, ShaderPlan& plan) {
    lp.weights = material.layers->weights;
    if (lp.weights != LayerWeights::Splat && !plan.functions) lp.vertexColorLocation = vertexColorLocation(plan.templateSource);
}

// Each hex-tiled slot the layers read takes the tiles of its lattice (LayersPlan::lattices), shared by every slot of
// the same LatticePlan and texture aspect: the tiles depend on nothing else. Lattices in the order of their first slot,
// as codegen names the tiles' functions after it.
void shareLattices(LayersPlan& lp, ShaderPlan& plan) {
    std::vector<std::pair<size_t, size_t>> read;  // (slot, layer)
    for (size_t l = 0; l < lp.count; ++l) {
        if (!lp.heights.empty()) read.emplace_back(lp.heights[l], l);
        for (const LayerRolePlan& r : lp.roles) read.emplace_back(r.slots[l], l);
    }
    std::sort(read.begin(), read.end());
    for (const auto& [i, layer] : read) {
        SlotPlan& sp = plan.slots[i];
        if (!sp.slot->hex.enabled) continue;
        auto same = std::find_if(lp.lattices.begin(), lp.lattices.end(), [&](const LayerLatticePlan& k) {
            return plan.slots[k.slot].lattice == sp.lattice && plan.slots[k.slot].aspect == sp.aspect;
        });
        if (same == lp.lattices.end()) same = lp.lattices.insert(same, {i, {}});
        sp.layerLattice = size_t(same - lp.lattices.begin());
        if (std::find(same->layers.begin(), same->layers.end(), layer) == same->layers.end()) same->layers.push_back(layer);
    }
    for (LayerLatticePlan& k : lp.lattices) std::sort(k.layers.begin(), k.layers.end());
}

}  // namespace

bool layerSlotRead(const Material& material, size_t index, const std::string& templateSource, bool readsFirst) {
    if (!material.layers) return false;
    const Layers& layers = *material.layers;
    const bool any = anyRoleRead(layers, templateSource, readsFirst);
    if (std::find(layers.splats.begin(), layers.splats.end(), index) != layers.splats.end()) return any;
    for (const Layers::Layer& l : layers.layers)
        for (size_t r = 0; r < l.slots.size(); ++r)
            if (l.slots[r] == index) return roleRead(layers, r, templateSource, readsFirst) || (any && layers.heightRole == r);
    return false;
}

void planLayers(const Material& material, bool shareTiles, ShaderPlan& plan) {
    if (!material.layers) return;
    const Layers& layers = *material.layers;
    // The functions output reads every role: each is an engine function.
    const bool readsFirst = containsWord(plan.templateSource, "HEXC_FIRST_SLOT");
    const auto read = [&](size_t r) { return plan.functions || roleRead(layers, r, plan.templateSource, readsFirst); };
    if (!plan.functions && !anyRoleRead(layers, plan.templateSource, readsFirst)) return;
    LayersPlan lp;
    lp.count = layers.layers.size();
    lp.blend = layers.blend;
    lp.width = layers.width;
    lp.skipBelow = layers.skipBelow;
    lp.coverage = coverage(material, layers, plan.diagnostics);
    planWeights(material, lp, plan);
    for (size_t s : layers.splats) {
        lp.splats.push_back(planIndex(material, s, plan));
        plan.slots[lp.splats.back()].explicitGradients = true;  // read by the roles' shared fill, behind a non-uniform test
    }
    // One layer's slot read in every pixel where the layer is kept: its share of the figures.
    auto add = [&](size_t layer, SlotPlan& sp) {
        sp.explicitGradients = true;  // read inside the layer's branch: plain tiling's fetch takes the role's gradients
        lp.worstFetches += fetches(sp);
        lp.expectedFetches += fetches(sp) * lp.coverage[layer];
    };
    for (size_t r = 0; r < layers.roles.size(); ++r) {
        if (!read(r)) continue;
        LayerRolePlan role{layers.roles[r].name, layers.roles[r].kind, {}, {}};
        for (size_t l = 0; l < lp.count; ++l) {
            role.slots.push_back(planIndex(material, layers.layers[l].slots[r], plan));
            add(l, plan.slots[role.slots.back()]);
        }
        role.type = plan.slots[role.slots.front()].type;
        lp.roles.push_back(std::move(role));
    }
    // The weights, shared by the roles (templates/library/layers.glsl): the splat maps, and in height mode every kept
    // layer's height, read once per pixel.
    for (size_t l = 0; layers.heightRole && l < lp.count; ++l) {
        lp.heights.push_back(planIndex(material, layers.layers[l].slots[*layers.heightRole], plan));
        add(l, plan.slots[lp.heights.back()]);
    }
    lp.worstFetches += double(lp.splats.size());
    lp.expectedFetches += double(lp.splats.size());
    if (shareTiles) shareLattices(lp, plan);
    plan.layers = std::move(lp);
}

}  // namespace hexc
