#pragma once
// The layered materials' check (tests/execution/layers/, layers_test.cpp), shared with hexc-expect (expect.cpp): each
// case's material, view and per-pixel tolerance against the fp64 reference (reference/layers.h).
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

#include "execution/checks.h"
#include "reference/layers.h"

namespace hexc::exec {

// The tolerances, per pixel, from the reference's details of it. Lavapipe's 8-bit sampling puts a filtered sample
// within e_s = (1.2 + L * m) / 255 of the exact one at deepest mip level L (m = 1 linear, 2.27 sRGB: the derivation is
// sampleError's in execution_test.cpp). The layers' hex-tiling runs with falloffcontrast 0 and falloff 0.5, so its
// tile weights come from the lattice alone and a layer's value errs by at most its samples' e_x (a normal role's
// derivative: checkNormal's). The GPU's result is a blend of its layers' values with weights summing to 1, so it errs
// by e_x plus what the weights' changes dw do: |sum_i dw_i v_i| <= (sum_i |dw_i| / 2) * spread, spread being the
// largest difference, in a channel, between the values of the layers whose weight may change (their dw sum to 0).
//   - Each splat weight s_i errs by e_w (linear 8-bit); a layer is kept where s_i >= skip_below. Where its weight is 0
//     on both (`zero`: no painted texel near, unpaintedLayers) it is dropped on both; where s_i is further than e_w
//     from the bound, kept or dropped alike on both (the sure set, k layers); within e_w it is ambiguous (a of them):
//     kept on one side and dropped on the other, with s_i <= skip + 2 e_w on either.
//   - So the kept weights' sum S moves by <= dS = k e_w + a (skip + 2 e_w), and is >= S_lo = sum_sure s_i - k e_w on
//     both sides. Linear: w_i = s_i / S: a sure weight moves by <= (e_w + w_i dS) / S_lo, an ambiguous one's is
//     <= (skip + 2 e_w) / S_lo, so sum_i |dw_i| <= 2 dS / S_lo and the blend by dS / S_lo times their spread. One sure
//     layer and none ambiguous keeps weight 1: e_x alone, inside a painted area. None kept on either: layer 0 alone.
//   - Height: a_i = h_i + w_i, h_i off by e_h, so a sure a_i by e_i = e_h + (e_w + w_i dS) / S_lo and the sure layers'
//     top by E = max e_i. An ambiguous layer's a_i is at most h_i + e_h + (skip + 2 e_w) / S_lo: where that may reach
//     top - E it may become the top, and the pixel is held to the blend's own range, e_x + spread over every layer.
//     Else b_i = max(a_i - top + width, 0) moves by <= e_i + E for a sure layer, not at all where
//     a_i - top + width <= -(e_i + E) on both sides, and for an ambiguous one by <= its largest b. With D the sum of
//     those over the layers that may move (A), the weights b_i / B move by sum |d(b_i / B)| <= (sum |db_i| + |dB|) / B
//     <= 2 D / B (B >= width on both: the top layer's b is width), and the blend by D spread_A / B. One active layer
//     keeps weight 1: e_x alone, inside a layer's top. In height mode the splat weights are kept above 0 (skip 0 in
//     the above), and then the b_i below skip_below * B drop (their share of the blend below skip_below): the result is
//     the blend of the kept b_i, so the bound above holds with the kept b_i (their sum B_K >= width: the top is kept),
//     and a layer kept on one side and dropped on the other (crossing: b_i - skip B moves by at most m_i + skip D, so
//     within that of 0) moves by at most b_i + m_i: D grows by its b_i.
inline double layerTolerance(const reference::LayerResult& r, const Layers& layers, const std::vector<bool>& zero, double ex, double eh,
                             double ew) {
    const size_t n = r.splat.size();
    const double skip = layers.heightRole ? 0.0 : layers.skipBelow;
    std::vector<bool> sure(n), ambiguous(n);
    double sureSum = 0, k = 0, a = 0;
    for (size_t i = 0; i < n; ++i) {
        ambiguous[i] = !zero[i] && std::fabs(r.splat[i] - skip) <= ew;
        sure[i] = !ambiguous[i] && r.splat[i] >= skip;
        if (sure[i]) sureSum += r.splat[i], ++k;
        a += ambiguous[i];
    }
    // The largest difference in a channel between the values of the layers `in` takes.
    auto spread = [&](const std::function<bool(size_t)>& in) {
        double out = 0;
        for (size_t c = 0; c < 4; ++c) {
            double lo = INFINITY, hi = -INFINITY;
            for (size_t i = 0; i < n; ++i)
                if (in(i)) lo = std::min(lo, r.layers[i].value[c]), hi = std::max(hi, r.layers[i].value[c]);
            out = std::max(out, hi - lo);
        }
        return out;
    };
    const double whole = ex + spread([](size_t) { return true; });
    if (k == 0 && a == 0) return ex;
    const double Slo = sureSum - k * ew, dS = k * ew + a * (skip + 2 * ew), ambiguousW = (skip + 2 * ew) / Slo;
    if (Slo <= 0) return whole;
    if (!layers.heightRole) return ex + dS / Slo * spread([&](size_t i) { return sure[i] || ambiguous[i]; });
    const double S = std::accumulate(r.splat.begin(), r.splat.end(), 0.0);
    std::vector<double> e(n), moves(n, 0.0);
    double top = -INFINITY, E = 0;
    for (size_t i = 0; i < n; ++i)
        if (sure[i]) {
            e[i] = eh + (ew + r.splat[i] / S * dS) / Slo;
            top = std::max(top, r.heights[i] + r.splat[i] / S), E = std::max(E, e[i]);
        }
    for (size_t i = 0; i < n; ++i) {
        if (sure[i] && r.heights[i] + r.splat[i] / S - top + layers.width > -(e[i] + E)) moves[i] = e[i] + E;
        if (!ambiguous[i]) continue;
        const double aMax = r.heights[i] + eh + ambiguousW;
        if (aMax >= top - E) return whole;
        moves[i] = std::max(aMax - (top - E) + layers.width, 0.0);
    }
    // The shares below skip_below drop after the blend: b_i is kept where b_i >= min(skip B, width) (B = heightSum).
    const double D0 = std::accumulate(moves.begin(), moves.end(), 0.0), B = r.heightSum;
    const double skipB = std::min(layers.skipBelow * B, layers.width);  // the threshold, at most the top's b
    double D = D0, kept = 0;
    std::vector<bool> crossing(n, false);
    for (size_t i = 0; i < n; ++i) {
        const double b = r.shares[i] * B;
        crossing[i] = (b > 0 || moves[i] > 0) && std::fabs(b - skipB) <= moves[i] + layers.skipBelow * D0;
        if (crossing[i]) D += b;
        if (r.weights[i] > 0) kept += b;
    }
    return ex + D / kept * spread([&](size_t i) { return moves[i] > 0 || crossing[i]; });
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
// A magnified corner where three layers' splat weights overlap (texels 234-245, 218-229: r, g, b about 0.52, 0.31,
// 0.17 at its centre), so that each blend mixes layers there, the layers at 0.5 texel a pixel (level 0).
inline const View kSoft{96, 96, {234.0 / 256, 218.0 / 256, 234.0 / 256 + 96 * 0.5 / 1024, 218.0 / 256 + 96 * 0.5 / 1024}};

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

// Per layer, whether its weight at pixel (i, j) of `view` is exactly 0 on the GPU as in the reference: its splat
// channel is 0 at every texel within 2 of the sample point at every mip level up to one past the deepest read (the
// GPU's filter reads texels within 1 of it, at a level its own LOD picks; 0 texels give 0 at every level and filter
// weight). Vertex-colour weights alone are never taken as 0 (their error is e_c, not a texel's).
inline std::vector<bool> unpaintedLayers(const Material& m, const reference::LayerTextures& textures, const View& view, int i, int j,
                                         int splatLevel) {
    const Layers& layers = *m.layers;
    std::vector<bool> zero(layers.layers.size(), false);
    if (layers.weights == LayerWeights::Vertex) return zero;
    const double u = view.uvRect[0] + (i + 0.5) * (view.uvRect[2] - view.uvRect[0]) / view.width;
    const double v = view.uvRect[1] + (j + 0.5) * (view.uvRect[3] - view.uvRect[1]) / view.height;
    for (size_t l = 0; l < zero.size(); ++l) {
        const reference::SampledTexture& t = *textures.of(layers.splats[l / 4]).texture;
        bool allZero = true;
        for (int level = 0; level <= std::min(splatLevel + 1, t.levels() - 1) && allZero; ++level) {
            const int w = t.width(level), h = t.height(level);
            const int x0 = int(std::floor(u * w - 0.5)), y0 = int(std::floor(v * h - 0.5));
            for (int y = y0 - 2; y <= y0 + 3; ++y)
                for (int x = x0 - 2; x <= x0 + 3; ++x) allZero &= t.texel(level, ((x % w) + w) % w, ((y % h) + h) % h)[l % 4] == 0;
        }
        zero[l] = allZero;
    }
    return zero;
}

// The case's role of `material` (the case's file, or a form of it), drawn, against the reference: each pixel within its
// tolerance (layerTolerance).
inline CaseCheck checkLayers(const Material& material, const LayerCase& c, const Draw& draw) {
    const Material m = vk::layerRoleFirst(material, *vk::layerRole(material, c.role));
    const Layers& layers = *m.layers;
    const Slot& first = m.slots[layers.layers[0].slots[0]];
    Check check;
    check.output = vk::RenderOutput::Shaded;
    check.channels = first.kind == SlotKind::Scalar ? 1 : first.kind == SlotKind::Normal ? 2 : 4;
    const Image gpu = drawn(draw, m, vk::RenderOutput::Shaded, c.view);
    const reference::LayerTextures textures(m);
    const std::vector<reference::LayerResult> ref = reference::evaluateLayersView(m, 0, textures, c.view);
    double ex = sampleError(c.level, first.colorSpace == ColorSpace::Srgb);
    if (first.kind == SlotKind::Normal)  // each layer's derivative as checkNormal bounds it, the largest
        for (const Layers::Layer& layer : layers.layers) {
            const TextureBounds b = bounds(sampled(m.slots[layer.slots[0]]));
            ex = std::max(ex, 2 * sampleError(c.level, false) * (1 + b.maxDeriv) / b.minZ);
        }
    const double eh = sampleError(c.level, false), ew = weightError(layers, sampleError(c.splatLevel, false));
    Image cpu = gpu;
    for (size_t p = 0; p < ref.size(); ++p) {
        const int i = int(p % size_t(c.view.width)), j = int(p / size_t(c.view.width));
        const double t = layerTolerance(ref[p], layers, unpaintedLayers(m, textures, c.view, i, j, c.splatLevel), ex, eh, ew);
        check.tolerance.push_back(t);
        check.maxTolerance = std::max(check.maxTolerance, t);
        for (size_t ch = 0; ch < size_t(check.channels); ++ch) {
            cpu.rgba[p * 4 + ch] = float(ref[p].value[ch]);
            const double e = std::fabs(double(gpu.rgba[p * 4 + ch]) - ref[p].value[ch]);
            check.worstRatio = std::max(check.worstRatio, errorRatio(e, t));
        }
    }
    check.errors = compare(gpu, cpu, check.channels);
    check.reference = std::move(cpu);
    return {m, c.view, check};
}

// The case as its file under tests/execution/layers/ gives it.
inline CaseCheck checkLayers(const LayerCase& c, const Draw& draw) {
    ParseResult parsed = parseMaterialFile(std::string("tests/execution/layers/") + c.file);
    if (!parsed.material) throw std::runtime_error(formatAll(parsed.diagnostics));
    return checkLayers(*parsed.material, c, draw);
}

}  // namespace hexc::exec
