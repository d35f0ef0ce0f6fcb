// The layers' blend, from docs/material-format.md#layers.
#include "reference/layers.h"

#include <algorithm>
#include <functional>

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

// Per layer its weight before keeping: splat map i / 4's channel i % 4, vertex colour channel i clamped to [0, 1], or
// their product (docs/material-format.md#layers).
std::vector<double> rawWeights(const Layers& layers, const Rgba& vertexColor, const std::function<Rgba(size_t)>& splat) {
    std::vector<double> w;
    for (size_t i = 0; i < layers.layers.size(); ++i) {
        const double s = layers.weights == LayerWeights::Vertex ? 1.0 : splat(i / 4)[i % 4];
        const double c = layers.weights == LayerWeights::Splat ? 1.0 : std::clamp(vertexColor[i], 0.0, 1.0);
        w.push_back(s * c);
    }
    return w;
}

}  // namespace

Rgba vertexColorAt(const View& view, int i, int j) {
    const double x = (i + 0.5) / view.width, y = (j + 0.5) / view.height;
    return {1 - x, x, y, 1 - y};
}

LayerResult evaluateLayers(const Material& material, size_t role, const LayerTextures& textures, double u, double v, double dudx,
                           double dvdx, double dudy, double dvdy, const Rgba& vertexColor) {
    const Layers& layers = *material.layers;
    const size_t n = layers.layers.size();
    // Evaluates slot `s` of the layers at this pixel.
    auto at = [&](size_t s) {
        const Slot& slot = material.slots[s];
        return evaluate(slot, *textures.of(s).texture, u, v, dudx, dvdx, dudy, dvdy, {0, 0}, textures.heights(s), textures.of(s).lut.get());
    };
    LayerResult r;
    r.splat = rawWeights(layers, vertexColor, [&](size_t k) { return at(layers.splats[k]).value; });
    r.weights = r.splat;
    keep(r.weights, layers.heightRole ? 0.0 : layers.skipBelow);  // height mode skips on the blend's shares, below
    if (layers.heightRole) {
        r.heights.assign(n, 0.0);
        double top = -2;
        for (size_t i = 0; i < n; ++i) {
            const Slot& h = material.slots[layers.layers[i].slots[*layers.heightRole]];
            r.heights[i] = at(layers.layers[i].slots[*layers.heightRole]).value[size_t(h.channel)];
            if (r.weights[i] > 0) top = std::max(top, r.heights[i] + r.weights[i]);
        }
        r.heightSum = 0;
        for (size_t i = 0; i < n; ++i) {
            r.weights[i] = r.weights[i] > 0 ? std::max(r.heights[i] + r.weights[i] - top + layers.width, 0.0) : 0.0;
            r.heightSum += r.weights[i];
        }
        for (double& w : r.weights) w /= r.heightSum;
        r.shares = r.weights;
        keep(r.weights, std::min(layers.skipBelow, *std::max_element(r.shares.begin(), r.shares.end())));
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
            out.push_back(evaluateLayers(material, role, textures, view.uvRect[0] + (i + 0.5) * du, view.uvRect[1] + (j + 0.5) * dv, du, 0,
                                         0, dv, vertexColorAt(view, i, j)));
    return out;
}

}  // namespace hexc::reference
