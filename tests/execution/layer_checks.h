#pragma once
// The layered materials' check (tests/execution/layers/, layers_test.cpp), shared with hexc-expect (expect.cpp): each
// case's material, view and per-pixel tolerance against the fp64 reference (reference/layers.h).
#include <algorithm>
#include <cmath>
#include <string>

#include "execution/checks.h"
#include "reference/layers.h"

namespace hexc::exec {

// The tolerances, per pixel, from the reference's details of it. Lavapipe's 8-bit sampling puts a filtered sample
// within e_s = (1.2 + L * m) / 255 of the exact one at deepest mip level L (m = 1 linear, 2.27 sRGB: the derivation is
// sampleError's in execution_test.cpp). The layers' hex-tiling runs with falloffcontrast 0 and falloff 0.5, so its
// tile weights come from the lattice alone and a layer's value errs by at most its samples' e_x.
//   - Each splat weight s_i errs by e_w (linear 8-bit); w_i = s_i / S moves by |ds_i| / S + s_i |dS| / S^2, so
//     sum_i |dw_i| <= 2 n e_w / S, and the blend, whose weight changes sum to 0, by <= n e_w spread / S, spread being
//     the largest difference between the layers' values in a channel.
//   - A layer whose s_i is within e_w of skip_below may be kept on one side and dropped on the other: its weight,
//     <= (skip + e_w) / S, times spread.
//   - Height mode: b_i = max(h_i + w_i - top + width, 0) with h_i off by e_x (linear) and w_i by e_n = 2 n e_w / S:
//     each b_i moves by <= 2 (e_x + e_n), B = sum b_i by <= 2 n (e_x + e_n), so sum_i |d(b_i / B)| <= 4 n (e_x + e_n) / B
//     and the blend by half that times spread.
inline double layerTolerance(const reference::LayerResult& r, const Layers& layers, double ex, double eh, double ew) {
    const double n = double(r.splat.size());
    double S = 0, spread = 0;
    for (double s : r.splat) S += s >= layers.skipBelow ? s : 0;
    S = std::max(S, 1e-3);  // an unpainted texel shows layer 0 alone; its neighbours' weights then count against 1e-3
    for (size_t c = 0; c < 4; ++c) {
        double lo = INFINITY, hi = -INFINITY;
        for (const reference::SlotResult& l : r.layers) lo = std::min(lo, l.value[c]), hi = std::max(hi, l.value[c]);
        spread = std::max(spread, hi - lo);
    }
    double t = ex + n * ew * spread / S;
    for (double s : r.splat)
        if (std::fabs(s - layers.skipBelow) <= ew) t += (layers.skipBelow + ew) / S * spread;
    if (layers.heightRole) t += 2 * n * (eh + 2 * n * ew / S) * spread / r.heightSum;
    return t;
}

struct LayerCase {
    const char* name;
    const char* file;  // under tests/execution/layers/
    const char* role;  // the role shown (the value template shows the first; the case puts this one first)
    View view;
    int level;       // the deepest mip level the layers' textures are read at
    int splatLevel;  // and the splat map's
};

// Over the whole splat map (256 texels across 128 pixels: level 1) so that its hard left and soft right borders are
// both in view; the layers tile 4 times (8 texels a pixel: level 3).
inline const View kWhole{128, 128, {0, 0, 1, 1}};
// A magnified corner: the splat map's soft border region, the layers at 0.5 texel a pixel (level 0).
inline const View kSoft{96, 96, {0.55, 0.35, 0.55 + 96 * 0.5 / 1024, 0.35 + 96 * 0.5 / 1024}};

inline const LayerCase kLayerCases[] = {
    {"one_layer", "one.json", "albedo", kWhole, 3, 1},
    {"two_layers_linear", "two.json", "albedo", kWhole, 3, 1},
    {"two_layers_linear_soft", "two.json", "albedo", kSoft, 0, 0},
    {"four_layers_linear", "four.json", "albedo", kWhole, 3, 1},
    {"four_layers_height", "four_height.json", "albedo", kWhole, 3, 1},
    {"four_layers_height_soft", "four_height.json", "albedo", kSoft, 0, 0},
    {"four_layers_height_narrow", "four_height_narrow.json", "albedo", kSoft, 0, 0},
    {"four_layers_height_wide", "four_height_wide.json", "albedo", kSoft, 0, 0},
    {"four_layers_normal", "four_height.json", "normal", kSoft, 0, 0},
    {"four_layers_packed", "four_packed.json", "height", kSoft, 0, 0},
    {"eight_layers", "eight.json", "albedo", kWhole, 3, 1},
    {"two_layers_vertex", "two_vertex.json", "albedo", kWhole, 3, 1},
    {"four_layers_vertex", "four_vertex.json", "albedo", kWhole, 3, 1},
    {"two_layers_both", "two_both.json", "albedo", kWhole, 3, 1},
    {"four_layers_both_height", "four_both_height.json", "albedo", kSoft, 0, 0},
    // Each role an array (the default) above; here one texture per slot, and the albedo role falling back as one of
    // its layers differs in size (37x23 texels) while the normal role stays an array.
    {"four_layers_separate", "four_separate.json", "albedo", kWhole, 3, 1},
    {"four_layers_sizes", "four_sizes.json", "albedo", kWhole, 3, 1},
    {"four_layers_sizes_normal", "four_sizes.json", "normal", kSoft, 0, 0},
};

// The error of a layer's weight before keeping. A splat weight errs by e_w (above); the vertex colour by e_c: lavapipe
// interpolates it in float32 from per-vertex values in [-1, 2] (ulp 2.4e-7), a few roundings, under 1e-6, so 1e-5
// bounds it. A product s * c with s, c in [0, 1] errs by at most |ds| c + s |dc| <= e_w + e_c.
inline double weightError(const Layers& layers, double ew) {
    const double ec = 1e-5;
    return layers.weights == LayerWeights::Splat ? ew : layers.weights == LayerWeights::Vertex ? ec : ew + ec;
}

// The case's role, drawn, against the reference: each pixel within its tolerance (layerTolerance).
inline CaseCheck checkLayers(const LayerCase& c, const Draw& draw) {
    ParseResult parsed = parseMaterialFile(std::string("tests/execution/layers/") + c.file);
    if (!parsed.material) throw std::runtime_error(formatAll(parsed.diagnostics));
    const Material m = vk::layerRoleFirst(*parsed.material, *vk::layerRole(*parsed.material, c.role));
    const Layers& layers = *m.layers;
    const Slot& first = m.slots[layers.layers[0].slots[0]];
    Check check;
    check.output = vk::RenderOutput::Shaded;
    check.channels = first.kind == SlotKind::Scalar ? 1 : first.kind == SlotKind::Normal ? 2 : 4;
    const Image gpu = drawn(draw, m, vk::RenderOutput::Shaded, c.view);
    const reference::LayerTextures textures(m);
    const std::vector<reference::LayerResult> ref = reference::evaluateLayersView(m, 0, textures, c.view);
    const double ex = (1.2 + c.level * (first.colorSpace == ColorSpace::Srgb ? 2.27 : 1.0)) / 255;
    const double eh = (1.2 + c.level) / 255, ew = weightError(layers, (1.2 + c.splatLevel) / 255);
    Image cpu = gpu;
    for (size_t p = 0; p < ref.size(); ++p) {
        const double t = layerTolerance(ref[p], layers, ex, eh, ew);
        check.tolerance.push_back(t);
        check.maxTolerance = std::max(check.maxTolerance, t);
        for (size_t ch = 0; ch < size_t(check.channels); ++ch) {
            cpu.rgba[p * 4 + ch] = float(ref[p].value[ch]);
            const double e = std::fabs(double(gpu.rgba[p * 4 + ch]) - ref[p].value[ch]);
            check.worstRatio = std::max(check.worstRatio, e == e ? e / t : INFINITY);
        }
    }
    check.errors = compare(gpu, cpu, check.channels);
    check.reference = std::move(cpu);
    return {m, c.view, check};
}

}  // namespace hexc::exec
