// The layers' blend, from docs/material-format.md#layers.
#include "reference/layers.h"

#include <algorithm>

namespace hexc::reference {

LayerTextures::LayerTextures(const Material& material) : textures_(material.slots.size()), heights_(material.slots.size()) {
    const Layers& layers = *material.layers;
    auto load = [&](size_t slot) {
        textures_[slot] = std::make_unique<SlotTextures>(material.slots[slot]);
        heights_[slot] = std::make_unique<Heights>(material, material.slots[slot]);
    };
    for (size_t s : layers.splats) load(s);
    for (const Layers::Layer& l : layers.layers)
        for (size_t s : l.slots) load(s);
}

namespace {

// Drops the weights below the bound and renormalises the others; all dropped: layer 0 alone.
void keep(std::vector<double>& w, double skip) {
    double sum = 0;
    for (double& x : w) sum += (x = x >= skip ? x : 0);
    if (sum <= 0) w[0] = sum = 1;
    for (double& x : w) x /= sum;
}

}  // namespace

LayerResult evaluateLayers(const Material& material, size_t role, const LayerTextures& textures, double u, double v, double dudx,
                           double dvdx, double dudy, double dvdy) {
    const Layers& layers = *material.layers;
    const size_t n = layers.layers.size();
    // Evaluates slot `s` of the layers at this pixel.
    auto at = [&](size_t s) {
        const Slot& slot = material.slots[s];
        return evaluate(slot, *textures.of(s).texture, u, v, dudx, dvdx, dudy, dvdy, {0, 0}, textures.heights(s), textures.of(s).lut.get());
    };
    LayerResult r;
    for (size_t i = 0; i < n; ++i) r.splat.push_back(at(layers.splats[i / 4]).value[i % 4]);
    r.weights = r.splat;
    keep(r.weights, layers.skipBelow);
    if (layers.heightRole) {
        r.heights.assign(n, 0.0);
        double top = -2;
        for (size_t i = 0; i < n; ++i) {
            if (r.weights[i] <= 0) continue;
            const Slot& h = material.slots[layers.layers[i].slots[*layers.heightRole]];
            r.heights[i] = at(layers.layers[i].slots[*layers.heightRole]).value[size_t(h.channel)];
            top = std::max(top, r.heights[i] + r.weights[i]);
        }
        r.heightSum = 0;
        for (size_t i = 0; i < n; ++i) {
            r.weights[i] = r.weights[i] > 0 ? std::max(r.heights[i] + r.weights[i] - top + layers.width, 0.0) : 0.0;
            r.heightSum += r.weights[i];
        }
        for (double& w : r.weights) w /= r.heightSum;
    }
    r.layers.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const Slot& slot = material.slots[layers.layers[i].slots[role]];
        r.layers[i] = at(layers.layers[i].slots[role]);
        if (r.weights[i] <= 0) continue;
        // A scalar role blends each layer's own channel, shown as (s, s, s, 1) as the value template shows a scalar.
        for (size_t c = 0; c < 4; ++c)
            r.value[c] += r.weights[i] * (!kindRow(slot.kind).oneChannel ? r.layers[i].value[c]
                                          : c == 3                       ? 1.0
                                                                         : r.layers[i].value[size_t(slot.channel)]);
    }
    return r;
}

std::vector<LayerResult> evaluateLayersView(const Material& material, size_t role, const LayerTextures& textures, const View& view) {
    const double du = (view.uvRect[2] - view.uvRect[0]) / view.width, dv = (view.uvRect[3] - view.uvRect[1]) / view.height;
    std::vector<LayerResult> out;
    out.reserve(size_t(view.width) * size_t(view.height));
    for (int j = 0; j < view.height; ++j)
        for (int i = 0; i < view.width; ++i)
            out.push_back(
                evaluateLayers(material, role, textures, view.uvRect[0] + (i + 0.5) * du, view.uvRect[1] + (j + 0.5) * dv, du, 0, 0, dv));
    return out;
}

}  // namespace hexc::reference
