#pragma once
// What the execution tests share: the tolerances, each derived where it is defined, the views, the fixtures and the
// checks that run a material on lavapipe and compare every pixel with the fp64 CPU reference.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "hexc/histogram.h"
#include "hexc/library.h"
#include "hexc/material.h"
#include "reference/reference.h"
#include "hexc/spirv.h"
#include "vk/precision.h"
#include "vk/render.h"
#include "support.h"

namespace hexc::exec {

using hexc::test::runner;

// ---- Tolerances -------------------------------------------------------------------------------------------
// Lavapipe samples an 8-bit texture with 8-bit bilinear weights: against exact bilinear filtering a sample is
// off by up to half a weight step (0.5/256) per axis on a full-range step, plus the rounding of the result:
// 1.2/255 in all. Each mip level is made by a blit of the level above and stored in 8 bits, which puts it up
// to 1/255 off the exact box average per level (an sRGB level is stored encoded, and the sRGB curve is at
// most 2.4/1.055 = 2.27 times steeper in linear terms). A view whose deepest level is L therefore samples
// within e_s = (1.2 + L * m) / 255, m = 1 (linear) or 2.27 (sRGB).
inline double sampleError(int deepestLevel, bool srgb) { return (1.2 + deepestLevel * (srgb ? 2.27 : 1.0)) / 255.0; }

// The blend R = sum W_j x_j moves with its samples, and also through its weights: W_j is proportional to
// delta_j * w_j^gamma with delta = (1 - beta) + beta * metric >= 1 - beta, so dR/d(delta_j) = W_j (x_j - R) / delta_j
// and a metric error e_m moves R by at most e_m * beta / (1 - beta) * sum_j W_j |x_j - R|. The gain of Eq. 5
// multiplies weight changes by at most its steepest slope, k = log2(1 / (1 - r)) (1 when r <= 0.5). Per pixel,
// with W_j, x_j and R from the reference:
//     |R_gpu - R_ref| <= e_x + e_m * k * beta / (1 - beta) * max_c sum_j W_j |x_jc - R_c|.
// `k`: the gain's steepest slope.
inline double blendTolerance(const reference::SlotResult& r, double ex, double em, double beta, double k, int channels) {
    double spread = 0;
    for (int c = 0; c < channels; ++c) {
        double sum = 0;
        for (size_t j = 0; j < 3; ++j) sum += r.blend[j] * std::fabs(r.samples[j][size_t(c)] - r.value[size_t(c)]);
        spread = std::max(spread, sum);
    }
    return ex + em * k * beta / (1.0 - beta) * spread;
}

// The steepest slope of Eq. 5's gain at falloff r: log2(1 / (1 - r)), 1 when r <= 0.5.
inline double gainSlope(const HexTiling& hex) { return std::max(1.0, std::log2(1.0 / (1.0 - hex.falloff))); }

inline double pixelTolerance(const reference::SlotResult& r, double ex, double em, const HexTiling& hex, int channels) {
    if (!hex.enabled) return ex;
    return blendTolerance(r, ex, em, hex.falloffcontrast, gainSlope(hex), channels);
}

// ---- Fixtures ---------------------------------------------------------------------------------------------

// A material of the given slots (one slot object, or several separated by commas; the first is the one tested)
// and optional material-level hex-tiling settings.
inline Material material(const std::string& slotJson, const std::string& hexJson = "{}") {
    ParseResult r =
        parseMaterial(R"({"name": "exec", "hextiling": )" + hexJson + R"(, "slots": [)" + slotJson + "]}", "materials/exec.json");
    if (!r.material) throw std::runtime_error(formatAll(r.diagnostics));
    return *r.material;
}

using Errors = vk::ImageErrors;
const auto compare = vk::compareImages;

// An error over its tolerance, with NaN on either side infinite: std::max drops a NaN argument, so a NaN value or a
// NaN tolerance (from a NaN reference) would otherwise leave the worst ratio as it was and pass.
inline double errorRatio(double e, double t) {
    if (!(e == e) || !(t == t)) return INFINITY;
    return e == 0 ? 0 : e / t;
}

// Whether every channel of every pixel is finite: a check that compares an image with itself or with a neighbour
// (rather than with the reference) must first rule out NaN, which every comparison with it passes.
inline bool allFinite(const Image& image) {
    for (float v : image.rgba)
        if (!std::isfinite(v)) return false;
    return true;
}

inline reference::SampledTexture sampled(const Slot& slot) {
    return reference::SampledTexture(loadTexture(slot.texturePath, slot.colorSpace == ColorSpace::Srgb, slot.textureLayer));
}

inline Image cpuRender(const Slot& slot, const View& view, reference::Output output) {
    return reference::render(slot, sampled(slot), view, output);
}

// What a texture's own content allows, measured on its level 0 (in linear values, as sampled).
struct TextureBounds {
    double spread = 0;    // largest max - min of a channel: bounds |x_j - R| for a blend of samples
    double step = 0;      // largest difference between horizontally or vertically adjacent texels
    double minZ = 1;      // normal maps: smallest z = 2 b - 1
    double maxDeriv = 0;  // normal maps: largest |dH/du| or |dH/dv| of a texel (Listing 9)
};

inline TextureBounds bounds(const reference::SampledTexture& t) {
    TextureBounds b;
    const int w = t.width(0), h = t.height(0);
    for (int c = 0; c < 3; ++c) {
        double lo = INFINITY, hi = -INFINITY;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                double v = t.texel(0, x, y)[size_t(c)];
                lo = std::min(lo, v);
                hi = std::max(hi, v);
                b.step = std::max(
                    {b.step, std::fabs(v - t.texel(0, (x + 1) % w, y)[size_t(c)]), std::fabs(v - t.texel(0, x, (y + 1) % h)[size_t(c)])});
            }
        b.spread = std::max(b.spread, hi - lo);
    }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const auto& p = t.texel(0, x, y);
            double z = 2 * p[2] - 1;
            b.minZ = std::min(b.minZ, z);
            b.maxDeriv = std::max({b.maxDeriv, std::fabs(2 * p[0] - 1) / z, std::fabs(2 * p[1] - 1) / z});
        }
    return b;
}

// The views: magnified reads mip level 0 only; minified reads exactly level 2 (4 texels per pixel, a power of
// two, so lavapipe's piecewise-linear log2 is exact and no level blend is involved). Textures are 256^2 and
// tiling 4: one uv unit is 1024 texels, tiles are 1 / (2 sqrt 3) = 0.29 st apart, so the magnified view spans
// about 2 x 2 tiles and the minified one 5 x 5, borders included.
const View kMagnified{192, 192, {0.3, 0.45, 0.3 + 192 * 0.75 / 1024, 0.45 + 192 * 0.75 / 1024}};  // 0.75 texel per pixel
const View kMinified{96, 96, {0.3, 0.45, 0.3 + 96.0 * 4 / 1024, 0.45 + 96.0 * 4 / 1024}};         // 4 texels per pixel

// Triplanar materials are shown on the preview sphere (reference::previewSphere) over longitude 0.2..1.0 and
// latitude 0.1..0.9 radians, where all three planes take part. |dP| <= 0.8 / 384 per pixel, so at tiling 1.5 a
// pixel spans at most 0.8 texels of a 256^2 texture: level 0 only, like kMagnified.
const View kSphere{384, 384, {0.2, 0.1, 1.0, 0.9}};
// The same at half the size, for the examples' triplanar slots (checkSlot): a quarter of the pixels to draw, on Dawn too.
const View kSmallSphere{192, 192, {0.2, 0.1, 1.0, 0.9}};

// The paper's hash is fract(sin(x) * 43758.5453): lavapipe's sin and the C library's disagree in the last bits, which
// the factor 43758 turns into different tiles away from the origin (see docs/precision.md). Near the origin, where
// the ids are 0 and 1, both agree: paper-mode cases are seen there, at level 0.
const View kOrigin{192, 192, {0.0, 0.0, 0.02, 0.02}};

struct Check {
    Errors errors;
    double worstRatio = 0;      // max over pixels of error / tolerance: <= 1 passes
    double toleranceAtMax = 0;  // the tolerance of the pixel with the largest error
    double maxTolerance = 0;
    // What the GPU's image was held to: the output drawn, its first `channels` channels of `reference`, each pixel
    // within its `tolerance` (tests/execution/expect.cpp hands them to GPUs these tests do not drive).
    vk::RenderOutput output = vk::RenderOutput::Albedo;
    int channels = 0;
    Image reference;
    std::vector<double> tolerance;
    int toleranceChannels = 1;  // tolerance values a pixel: 1, or one per channel (packed slots: each its own)
};

// Height blending (hexcHeightBlend) reshapes the blend weights W (summing to 1) by the tiles' heights h in [0, 1]:
// W'_i = W_i f_i / S with a_i = h_i W_i, f_i = max(a_i - max_j a_j + width, 0) <= width and S = sum_j W_j f_j. Heights
// off by at most e_h and weights by dW_i, D = sum_i |dW_i| (so |dW_i| <= D / 2: the changes sum to 0), move each a_j
// by <= e_h + D / 2 and each f_i by twice that, so sum_i |d(W_i f_i)| <= width D + 2 e_h + D, and S by at most that
// sum: sum_i |dW'_i| <= 2 (2 e_h + (1 + width) D) / S. The blend, whose weight changes sum to 0, moves by half that
// times `spread`, the largest difference between the tiles' samples in a channel. D comes from the metric's error
// e_m,j at each tile j (metricError): with the metric's factor delta_j (Eq. 1, from the reference) moved by
// <= beta e_m,j, Eq. 1's weights move by dW_i / d(delta_j) = W_i (delta_ij - W_j) / delta_j, so
// D <= sum_j beta e_m,j / delta_j * 2 W_j (1 - W_j) <= beta / 2 sum_j e_m,j / delta_j over the tiles that weigh
// anything, times the gain's slope k (see blendTolerance); 0 when beta is 0.
using MetricError = std::function<double(const reference::SlotResult&, size_t tile)>;

inline double heightTolerance(const reference::SlotResult& r, double eh, const MetricError& em, const Slot& slot, int channels) {
    double spread = 0;
    for (int c = 0; c < channels; ++c) {
        double lo = INFINITY, hi = -INFINITY;
        for (const reference::Rgba& x : r.samples) {
            lo = std::min(lo, x[size_t(c)]);
            hi = std::max(hi, x[size_t(c)]);
        }
        spread = std::max(spread, hi - lo);
    }
    double d = 0;
    for (size_t j = 0; j < 3; ++j)
        if (r.unheighted[j] > 0) d += gainSlope(slot.hex) * slot.hex.falloffcontrast / 2 * em(r, j) / r.delta[j];
    return (2 * eh + (1 + slot.heightBlend->width) * d) * spread / r.heightSum;
}

// A normal slot's metric error at a tile, from its filtered texel n = 2 texel - 1, whose components are each off by
// 2 e_s, so |dn| <= 2 sqrt(3) e_s: the metric sin(theta) = |d| / sqrt(1 + |d|^2) of d = n_xy / (z s) (Listing 9, a tile
// scaled by s >= the smallest scale) moves with |d| at slope (1 + |d|^2)^(-3/2), and |d| with n at |n| / (z^2 s), to
// first order.
inline MetricError normalMetricError(double es, const Slot& slot) {
    return [es, &slot](const reference::SlotResult& r, size_t j) {
        const reference::Rgba& t = r.texels[j];
        const double x = 2 * t[0] - 1, y = 2 * t[1] - 1, z = std::fabs(2 * t[2] - 1);
        const double d2 = r.samples[j][0] * r.samples[j][0] + r.samples[j][1] * r.samples[j][1];
        return std::pow(1 + d2, -1.5) * std::sqrt(x * x + y * y + z * z) / (z * z * slot.hex.scaleRange[0]) * 2 * std::sqrt(3.0) * es;
    };
}

// What draws a material's output on the GPU: hexc's shader on one target, or a shader written by hand. An empty Draw
// draws nothing: the check then only records the reference and the tolerances (Check::reference, Check::tolerance).
using Draw = std::function<Image(const Material& m, vk::RenderOutput output, const View& view)>;

inline Draw on(vk::ExecutedTarget target, const CompileOptions& options = {}) {
    return [=](const Material& m, vk::RenderOutput output, const View& view) {
        std::string why;
        return vk::render(*runner(&why), m, output, "", view, target, 0, nullptr, {}, options);
    };
}

// What `draw` draws, or with no draw a blank image (zeros) of the view's size.
inline Image drawn(const Draw& draw, const Material& m, vk::RenderOutput output, const View& view) {
    return draw ? draw(m, output, view) : Image{view.width, view.height, std::vector<float>(size_t(view.width * view.height) * 4)};
}

// Each pixel's tolerance, from the reference's details of it.
using PixelTolerance = std::function<double(const reference::SlotResult&, size_t pixel)>;

// Runs a one-slot material on the GPU and compares `channels` channels of every pixel with the reference, each pixel
// against its own tolerance. `repeats` > 0: the reference's periodic lattice over that many units of st (hexc bake).
inline Check checkAgainstReference(const Material& m, vk::RenderOutput output, const View& view, const Draw& draw, int channels,
                                   const PixelTolerance& tolerance, int repeats = 0) {
    const Slot& slot = m.slots[0];
    Image gpu = drawn(draw, m, output, view);
    const reference::Heights heights(m, slot);
    const reference::SlotTextures textures(slot);
    std::vector<reference::SlotResult> ref =
        reference::evaluateView(slot, *textures.texture, view, heights.source(), textures.lut.get(), repeats);
    Check check;
    check.output = output;
    check.channels = channels;
    Image cpu = gpu;
    for (size_t p = 0; p < ref.size(); ++p) {
        // Scalar slots show (s, s, s, 1) of the channel they read.
        for (int c = 0; c < channels; ++c)
            cpu.rgba[p * 4 + size_t(c)] = float(ref[p].value[kindRow(slot.kind).oneChannel ? size_t(slot.channel) : size_t(c)]);
        const double t = tolerance(ref[p], p);
        check.tolerance.push_back(t);
        check.maxTolerance = std::max(check.maxTolerance, t);
        for (int c = 0; c < channels; ++c) {
            double e = std::fabs(double(gpu.rgba[p * 4 + size_t(c)]) - double(cpu.rgba[p * 4 + size_t(c)]));
            if (!(e == e)) e = INFINITY;
            if (e > check.errors.max) check.toleranceAtMax = t;
            check.worstRatio = std::max(check.worstRatio, errorRatio(e, t));
        }
    }
    check.errors = compare(gpu, cpu, channels);
    check.reference = std::move(cpu);
    return check;
}

// The falloff blend's tolerance with sample error ex and metric error em: pixelTolerance, or for height blending, whose
// weights' error heightTolerance carries through its height stage, ex plus heightTolerance. The triplanar projection
// blends its planes' results by b_k (exact: from the surface's normal), so it errs by at most sum_k b_k times each
// plane's bound; a normal slot's plane gradient, both components within that, by sqrt(2) times it in length, which the
// projection onto the surface does not lengthen. `level`: the deepest mip level the view reads.
inline Check checkAgainstReference(const Material& m, vk::RenderOutput output, const View& view, int level, const Draw& draw, double ex,
                                   double em, int channels, int repeats = 0) {
    const Slot& slot = m.slots[0];
    // The height map is 8-bit linear data, sampled at the view's levels like the slot, as is a normal map.
    const double eh = sampleError(level, false);
    const bool normal = kindRow(slot.kind).derivative;
    const int blended = kindRow(slot.kind).oneChannel ? 1 : channels;
    // The height stage's metric error: a colour's luminance or a scalar errs by em; a normal map's slope by its tile's.
    const MetricError metric = normal ? normalMetricError(eh, slot) : [em](const reference::SlotResult&, size_t) { return em; };
    const auto blend = [&](const reference::SlotResult& r) {
        return slot.heightBlend ? ex + heightTolerance(r, eh, metric, slot, blended) : pixelTolerance(r, ex, em, slot.hex, blended);
    };
    return checkAgainstReference(
        m, output, view, draw, channels,
        [&](const reference::SlotResult& r, size_t) {
            if (r.planes.empty()) return blend(r);
            double t = 0;
            for (size_t k = 0; k < r.planes.size(); ++k) t += r.planeWeights[k] * blend(r.planes[k]);
            return (normal ? std::sqrt(2.0) : 1.0) * t;
        },
        repeats);
}

inline void report(const char* name, const Check& c) {
    std::printf("  %-30s max %.5f (%.2f/255)  mean %.6f  >1/255 %.4f  tolerance there %.5f  worst error/tolerance %.2f\n", name,
                c.errors.max, c.errors.max * 255, c.errors.mean, c.errors.overOne255, c.toleranceAtMax, c.worstRatio);
}

// A colour or scalar slot (the material's first) against the reference, in a view whose deepest mip level is `level`
// (`repeats`: checkAgainstReference's).
inline Check checkColor(const Material& m, const View& view, int level, const Draw& draw, int repeats = 0) {
    const Slot& slot = m.slots[0];
    // MaterialX mode decodes after filtering the stored texels: their 8-bit linear error, times the sRGB curve's steepest
    // slope (2.4 / 1.055 at 1).
    double es = slot.shaderDecodes() ? 2.4 / 1.055 * sampleError(level, false) : sampleError(level, slot.colorSpace == ColorSpace::Srgb);
    // Colour: the luminance metric errs by at most e_s (its weights sum to 1); scalar: the channel itself.
    return checkAgainstReference(m, vk::RenderOutput::Albedo, view, level, draw, es, es, kindRow(slot.kind).oneChannel ? 1 : 4, repeats);
}

inline Check checkColor(const Material& m, bool minified, const Draw& draw) {
    return checkColor(m, minified ? kMinified : kMagnified, minified ? 2 : 0, draw);
}

inline std::string targetName(vk::ExecutedTarget t) {
    return t == vk::ExecutedTarget::Spirv ? "spirv" : t == vk::ExecutedTarget::Hlsl ? "hlsl" : "glsl";
}

const auto kExecutedTargets = testing::Values(vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl);

// ---- Histogram blend ---------------------------------------------------------------------------------------------

// The largest difference between horizontally or vertically adjacent texels of a level, per channel.
inline std::array<double, 3> adjacentSteps(const reference::SampledTexture& t, int level) {
    std::array<double, 3> step{};
    const int w = t.width(level), h = t.height(level);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (size_t c = 0; c < 3; ++c) {
                const double v = t.texel(level, x, y)[c];
                step[c] =
                    std::max({step[c], std::fabs(v - t.texel(level, (x + 1) % w, y)[c]), std::fabs(v - t.texel(level, x, (y + 1) % h)[c])});
            }
    return step;
}

// The histogram blend's tolerance at a pixel (hexcHistogram; reference.h, evaluateAt), step by step:
// 1. A Gaussian sample: float32 texels, mip levels float averages (exact to 2^-24); lavapipe's bilinear weights taken
//    as coarse as on 8-bit data, half a step of 2^-8 per axis, so a sample errs by e_g <= 2 * 2^-9 * step_k, step_k the
//    largest difference between adjacent texels of channel k at the level read (adjacentSteps), plus 4 * 2^-24.
// 2. The blend G = sum W_i (g_i - 0.5) / |W| + 0.5 moves by sum W_i / |W| <= sqrt(3) (Cauchy-Schwarz) times e_g; the
//    weights' float32 rounding (a few ulp, relative 1e-6, times sum |g_i - 0.5| / |W| <= 3 sqrt(3)) adds 1e-5: e_G.
// 3. The inverse reads entry x = (G - g_0) / s of rows r0 = 1 + floor(lod) and r0 + 1 (g_0 = histogramLutGaussian(0),
//    s the entries' step; lod is exact in both views: 0 is clamped, 2 is a power of two): x moves by e_G / s, so the
//    value by that times D, the largest difference
//    between adjacent entries within reach in either row; the filter's weight steps add 2^-9 D along x and 2^-9 D_v
//    across rows, D_v the largest difference between the rows' entries there.
// 4. Back to RGB, rgb_c = mean_c + sum_k q_k E_ck moves by sum_k |E_ck| e_k, plus float32 rounding (1e-6); the clamp
//    to the texture's range moves nothing further apart.
inline PixelTolerance histogramTolerance(const Slot& slot, const reference::SlotTextures& textures, int level) {
    const reference::SampledTexture& lut = *textures.lut;
    const std::array<double, 3> step = adjacentSteps(*textures.texture, level);
    const size_t channels = kindRow(slot.kind).oneChannel ? 1 : 3;
    return [&lut, step, channels](const reference::SlotResult& r, size_t) {
        const int n = lut.width(0), rows = lut.height(0);
        const int r0 = 1 + int(std::floor(std::clamp(r.lod, 0.0, rows - 2.0))), r1 = std::min(r0 + 1, rows - 1);
        std::array<double, 3> e{};
        for (size_t k = 0; k < channels; ++k) {
            const double eG = std::sqrt(3.0) * (2 * step[k] / 512 + 4 * 0x1p-24) + 1e-5;
            const double g0 = histogramLutGaussian(0), s = histogramLutGaussian(1) - g0;
            const double x = std::clamp((r.gaussian[k] - g0) / s, 0.0, n - 1.0), reach = eG / s + 1;
            double d = 0, dv = 0;
            for (int i = std::max(0, int(std::floor(x - reach))); i <= std::min(n - 1, int(std::ceil(x + reach))); ++i) {
                dv = std::max(dv, std::fabs(lut.texel(0, i, r1)[k] - lut.texel(0, i, r0)[k]));
                if (i + 1 < n)
                    for (int row : {r0, r1}) d = std::max(d, std::fabs(lut.texel(0, i + 1, row)[k] - lut.texel(0, i, row)[k]));
            }
            e[k] = d * (eG / s + 1.0 / 512) + dv / 512;
        }
        if (channels == 1) return e[0] + 1e-6;
        double worst = 0;
        for (size_t c = 0; c < 3; ++c) {
            double sum = 0;
            for (size_t k = 0; k < 3; ++k) sum += std::fabs(lut.texel(0, int(k), 0)[c]) * e[k];
            worst = std::max(worst, sum);
        }
        return worst + 1e-6;
    };
}

// A histogram-blended colour or scalar slot (the material's first) against the reference, in a view whose deepest
// mip level is `level` (`repeats`: checkAgainstReference's).
inline Check checkHistogram(const Material& m, const View& view, int level, const Draw& draw, int repeats = 0) {
    const Slot& slot = m.slots[0];
    const reference::SlotTextures textures(slot);
    return checkAgainstReference(m, vk::RenderOutput::Albedo, view, draw, kindRow(slot.kind).oneChannel ? 1 : 4,
                                 histogramTolerance(slot, textures, level), repeats);
}

// ---- Normal path --------------------------------------------------------------------------------------------
// A normal slot (the material's first) against the reference, as derivatives (`repeats`: checkAgainstReference's).
inline Check checkNormal(const Material& m, const View& view, int level, const Draw& draw, int repeats = 0) {
    const Slot& slot = m.slots[0];
    const bool triplanar = slot.hex.projection == Projection::Triplanar;
    TextureBounds b = bounds(sampled(slot));
    // Listing 9: d = -xy / z with x, y, z = 2 * texel - 1, each off by 2 e_s, so to first order
    // |dd| <= 2 e_s (1 + max|d|) / min z. The slope metric sin(theta) = sqrt(|d|^2 / (1 + |d|^2)) moves by at
    // most the error of |d| (its slope is <= 1), which is <= sqrt(2) |dd|.
    double ed = 2 * sampleError(level, false) * (1 + b.maxDeriv) / b.minZ;
    // Triplanar: the surface gradient (x, y, z) from the planes' (checkAgainstReference; the plane weights' own float32
    // error, ~1e-7, is negligible).
    return checkAgainstReference(m, vk::RenderOutput::Derivative, view, level, draw, ed, std::sqrt(2.0) * ed, triplanar ? 3 : 2, repeats);
}

inline Check checkNormal(const Material& m, bool minified, const Draw& draw) {
    return checkNormal(m, minified ? kMinified : kMagnified, minified ? 2 : 0, draw);
}

// ---- A material file's slots, one at a time -------------------------------------------------------------------

// A material file (rock by default) with only the slot `slotName` and, after it (the first slot is the one checked),
// the slot it height-blends by, their settings as the file gives them.
inline Material slotOf(const std::string& slotName, const std::string& file = "materials/rock.json") {
    ParseResult parsed = parseMaterialFile(file);
    if (!parsed.material) throw std::runtime_error(formatAll(parsed.diagnostics));
    Material one = *parsed.material;
    const auto named = [&](const std::string& name) {
        const auto it = std::find_if(one.slots.begin(), one.slots.end(), [&](const Slot& s) { return s.name == name; });
        if (it == one.slots.end()) throw std::runtime_error(file + " has no slot `" + name + "`");
        return *it;
    };
    const Slot slot = named(slotName);
    std::vector<Slot> slots{slot};
    if (slot.heightBlend && slot.heightBlend->slot != slotName) slots.push_back(named(slot.heightBlend->slot));
    one.slots = std::move(slots);
    return one;
}

// Where a slot is seen: on the preview sphere with the triplanar projection (it needs the surface's position and
// normal), else magnified.
inline const View& slotView(const Slot& slot) { return slot.hex.projection == Projection::Triplanar ? kSmallSphere : kMagnified; }

// The deepest mip level a slot reads in a view: log2 of the texels a pixel spans, rounded up: the view's uv a pixel
// times the tiling times the texture's size, and 1 / s times more in a tile scaled by s. On the preview sphere u and v
// are radians of a unit sphere, so |dP| <= |d(u, v)|, and a plane's projection does not lengthen it.
inline int deepestLevel(const Slot& slot, const View& view) {
    const double uv = std::max((view.uvRect[2] - view.uvRect[0]) / view.width, (view.uvRect[3] - view.uvRect[1]) / view.height);
    const double texels = uv * std::max(slot.hex.tiling[0] * slot.width, slot.hex.tiling[1] * slot.height) / slot.hex.scaleRange[0];
    return std::max(0, int(std::ceil(std::log2(texels))));
}

// Its slot, in its view, against the reference: the derivative rule for a normal map, else the falloff one.
inline Check checkSlot(const Material& one, const Draw& draw) {
    const Slot& slot = one.slots[0];
    const View& view = slotView(slot);
    const int level = deepestLevel(slot, view);
    return kindRow(slot.kind).derivative ? checkNormal(one, view, level, draw) : checkColor(one, view, level, draw);
}

// ---- Cases as data ------------------------------------------------------------------------------------------
// A table of cases is a folder of JSON files (tests/execution/cases/, odd_sizes/, adaptive/, packed/, analytic/): each
// file, on each of its "targets", is one test, "<name>_<target>". Besides "targets" and "why" (why the case is there),
// a file has the keys its table's test reads.
struct ExecCase {
    std::filesystem::path folder;
    std::string name;
    vk::ExecutedTarget target;
};
inline void PrintTo(const ExecCase& c, std::ostream* os) { *os << c.name << "_" << targetName(c.target); }
inline std::string caseTestName(const testing::TestParamInfo<ExecCase>& info) {
    return info.param.name + "_" + targetName(info.param.target);
}

// The case's file; throws on a key that is not "targets", "why" or one of `keys`.
inline nlohmann::json readCase(const ExecCase& c, std::initializer_list<std::string_view> keys) {
    std::ifstream in(c.folder / (c.name + ".json"));
    const nlohmann::json json = nlohmann::json::parse(in);
    for (const auto& [key, value] : json.items())
        if (key != "targets" && key != "why" && std::find(keys.begin(), keys.end(), key) == keys.end())
            throw std::runtime_error(c.name + ".json: unknown key `" + key + "`");
    return json;
}

inline vk::ExecutedTarget executedTarget(const std::string& name) {
    if (name == "spirv") return vk::ExecutedTarget::Spirv;
    if (name == "hlsl") return vk::ExecutedTarget::Hlsl;
    if (name == "glsl") return vk::ExecutedTarget::Glsl;
    throw std::runtime_error("unknown target `" + name + "` (spirv, hlsl or glsl)");
}

// Every case file of `folder` on each of its targets, in file name order.
inline std::vector<ExecCase> execCases(const std::filesystem::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    std::vector<ExecCase> cases;
    for (const std::string& name : names) {
        std::ifstream in(folder / (name + ".json"));
        const nlohmann::json c = nlohmann::json::parse(in);  // held: a range-for over a temporary's member dangles
        for (const std::string target : c.at("targets")) cases.push_back({folder, name, executedTarget(target)});
    }
    return cases;
}

// ---- Weights ----------------------------------------------------------------------------------------------
// With falloffcontrast 0 the weights depend on the lattice alone. The GPU evaluates it in float32 on a uv that
// the rasteriser interpolated, so st and the skewed coordinates carry a few ulps of their size (|skewed| <= 4 |st|):
// the barycentrics are off by dw <= 4 * 4 ulp(|st|), and W_i = w_i^gamma / sum_j w_j^gamma moves by
// |dW_i| <= gamma * sum_j W_i |delta_ij - W_j| |dw_j| / w_j <= 2 gamma dw max_j(W_j / w_j), where W_j / w_j <= 2 for
// the three barycentrics of a triangle (largest at w = (1/2, 1/4, 1/4) for gamma = 7; 1 for gamma = 1).
// With falloffcontrast beta > 0 the metric's error e_m adds |dW_i| <= k * beta / (1 - beta) * e_m * 2 W_i (1 - W_i)
// <= k * beta / (1 - beta) * e_m / 2 (see pixelTolerance).
// The lattice weights of the material's first slot against the reference's, every pixel within one tolerance.
inline Check checkWeights(const Material& m, const View& view, const Draw& draw) {
    const Slot& slot = m.slots[0];
    double stMax = std::max(std::fabs(view.uvRect[2]), std::fabs(view.uvRect[3])) * std::max(slot.hex.tiling[0], slot.hex.tiling[1]);
    double ulp = std::ldexp(1.0, std::ilogb(stMax) - 23);
    double dw = 4 * 4 * ulp;
    double k = std::max(1.0, std::log2(1.0 / (1.0 - slot.hex.falloff)));
    double em = sampleError(0, slot.colorSpace == ColorSpace::Srgb);
    double tolerance = k * (2 * slot.hex.exponent * dw * 2) + k * slot.hex.falloffcontrast / (1 - slot.hex.falloffcontrast) * em / 2;
    Check check;
    check.output = vk::RenderOutput::Weights;
    check.channels = 3;
    check.reference = cpuRender(slot, view, reference::Output::Weights);
    check.tolerance.assign(size_t(view.width * view.height), tolerance);
    if (draw) check.errors = compare(draw(m, vk::RenderOutput::Weights, view), check.reference, 3);
    check.worstRatio = check.errors.max / tolerance;
    check.toleranceAtMax = check.maxTolerance = tolerance;
    return check;
}

// ---- The cases of tests/execution/cases/ --------------------------------------------------------------------
// tests/execution/cases/<name>.json: a material (inline, its paths read from materials/ like the examples'), the view
// it is seen in, the targets it runs on and the tolerance rule it is held to; each file, on each of its targets, is one
// test, "<name>_<target>" (cases_test.cpp). A rule is one of the checks above, with its derivation:
//   falloff     checkColor: a colour or scalar slot, pixelTolerance (heightTolerance when height-blended)
//   histogram   checkHistogram: histogramTolerance
//   derivative  checkNormal: a normal slot's derivatives (or triplanar surface gradient)
//   weights     checkWeights: the blend weights
// A view is one of the named views above (magnified, minified, sphere, origin; the level each reads is fixed there) or
// {"width", "height", "uv": [u0, v0, u1, v1], "level": the deepest mip level it reads}.
inline std::pair<View, int> caseView(const nlohmann::json& v) {
    if (v.is_object()) {
        const std::vector<double> uv = v.at("uv");
        if (uv.size() != 4) throw std::runtime_error("a view's uv is [u0, v0, u1, v1]");
        return {View{v.at("width"), v.at("height"), {uv[0], uv[1], uv[2], uv[3]}}, v.at("level").get<int>()};
    }
    const std::map<std::string, std::pair<View, int>> named = {
        {"magnified", {kMagnified, 0}}, {"minified", {kMinified, 2}}, {"sphere", {kSphere, 0}}, {"origin", {kOrigin, 0}}};
    const auto it = named.find(v.get<std::string>());
    if (it == named.end()) throw std::runtime_error("unknown view " + v.dump() + " (magnified, minified, sphere or origin)");
    return it->second;
}

inline Check checkCase(const nlohmann::json& c, const Material& m, const Draw& draw) {
    const auto [view, level] = caseView(c.at("view"));
    const std::string rule = c.at("rule");
    if (rule == "falloff") return checkColor(m, view, level, draw);
    if (rule == "histogram") return checkHistogram(m, view, level, draw);
    if (rule == "derivative") return checkNormal(m, view, level, draw);
    if (rule == "weights") return checkWeights(m, view, draw);
    throw std::runtime_error("unknown rule `" + rule + "` (falloff, histogram, derivative or weights)");
}

// ---- Feature variants as data ---------------------------------------------------------------------------------
// The tables of odd_sizes/, packed/ and adaptive/ (cases_test.cpp) check a material built from the case's keys; each
// check here is what its lavapipe test runs and what hexc-expect (expect.cpp) runs with nothing drawn.

// What a case is held to: its material (the first slot the one checked, or all of them: packed), the view, the check.
struct CaseCheck {
    Material material;
    View view;
    Check check;
};

// ---- Odd-sized textures -----------------------------------------------------------------------------------
// hexc accepts any texture size. The runner builds each mip level by a linear blit of the one above, which at an odd
// size resamples rather than averages; the reference models it (reference::SampledTexture::halve). Crops of the rock
// albedo (8-bit, linear, so not seamless: GPU and reference wrap alike) at odd and non-square sizes, seen magnified
// (0.75 texel per pixel along the larger axis: level 0) and minified (4 texels per pixel: exactly level 2, or the
// last level when the chain is shorter), with tile rotation off so the footprint stays axis-aligned: lavapipe's
// log2 of the footprint is exact only at a power of two, which a rotated footprint on a non-square texture is not.
// A case: "size" [width, height], "minified", "blend" (histogram: its Gaussian texture has the odd size, its table
// odd levels), "lod" (shared: the level from sqrt(width * height), between two levels here).
inline std::filesystem::path cropOfRock(int width, int height) {
    const Texture rock = loadTexture("materials/textures/rock_albedo.png", false);
    Image out;
    out.width = width;
    out.height = height;
    out.rgba.clear();
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 4; ++c)
                out.rgba.push_back(rock.rgba8[(size_t(y + 40) * size_t(rock.width) + size_t(x + 40)) * 4 + size_t(c)] / 255.0f);
    std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("hexc_odd_" + std::to_string(width) + "x" + std::to_string(height) + ".png");
    writeImage(out, file);
    return file;
}

// A slot's JSON text, its texture "CROP_<w>x<h>" replaced by that crop of the rock albedo (cropOfRock).
inline std::string withCrop(nlohmann::json slot) {
    int width = 0, height = 0;
    if (std::sscanf(slot.at("texture").get<std::string>().c_str(), "CROP_%dx%d", &width, &height) == 2)
        slot["texture"] = cropOfRock(width, height).string();
    return slot.dump();
}

// A view of 96 x 96 pixels at (0.3, 0.45) of a texture `larger` texels across under `tiling`: magnified, 0.75 texel
// per pixel (level 0), or minified, 4 (level 2, or the last level of a shorter chain). Returns it and its level.
inline std::pair<View, int> cropView(int larger, double tiling, bool minified) {
    const double uvPerPixel = (minified ? 4.0 : 0.75) / (tiling * larger);
    const int levels = std::bit_width(unsigned(larger));
    return {View{96, 96, {0.3, 0.45, 0.3 + 96 * uvPerPixel, 0.45 + 96 * uvPerPixel}}, minified ? std::min(2, levels - 1) : 0};
}

inline CaseCheck checkOddSize(const ExecCase& oddSize, const Draw& draw) {
    const nlohmann::json c = readCase(oddSize, {"size", "minified", "blend", "lod"});
    const int width = c.at("size")[0], height = c.at("size")[1];
    const Material m =
        material(withCrop({{"name", "albedo"},
                           {"kind", "color"},
                           {"colorspace", "linear"},
                           {"texture", "CROP_" + std::to_string(width) + "x" + std::to_string(height)},
                           {"hextiling", {{"tiling", 4}, {"rotation", 0}, {"blend", c.at("blend")}, {"lod", c.at("lod")}}}}));
    const auto [view, level] = cropView(std::max(width, height), 4.0, c.at("minified"));
    const double es = sampleError(level, false);
    return {m, view,
            c.at("blend") == "histogram" ? checkHistogram(m, view, level, draw)
                                         : checkAgainstReference(m, vk::RenderOutput::Albedo, view, level, draw, es, es, 4)};
}

// ---- Packed textures ---------------------------------------------------------------------------------------
// "pack": true (docs/material-format.md#pack) under tests/templates/packed.glsl, which reads every slot and shows
// them in one image: `color`'s RGB and `s3` in alpha, or scalars s0..s3 in R..A. The packed texture holds each slot's
// texels byte for byte, so every slot is held to its unpacked tolerance against its own fp64 reference, which samples
// the slot's own texture: an sRGB colour slot's sample error for RGB, the linear one for a scalar in the sRGB texture's
// alpha (alpha stays linear), each slot blended with its own settings from the shared samples.
// A case: "slots", "hextiling" (the material's), "minified".
// Each slot's output channels against its reference, each pixel within the slot's tolerance (pixelTolerance): one
// tolerance a channel.
inline Check checkPacked(const Material& m, const View& view, int level, const Draw& draw) {
    const Image gpu = drawn(draw, m, vk::RenderOutput::Shaded, view);
    Check check;
    check.output = vk::RenderOutput::Shaded;
    check.channels = check.toleranceChannels = 4;
    check.tolerance.assign(gpu.rgba.size(), 0);
    Image cpu = gpu;
    for (const Slot& slot : m.slots) {
        const bool colour = !kindRow(slot.kind).oneChannel;  // normal maps are not packed
        const size_t first = colour ? 0 : size_t(slot.name[1] - '0'), count = colour ? 3 : 1;
        const double es = sampleError(level, slot.colorSpace == ColorSpace::Srgb);
        const std::vector<reference::SlotResult> ref = reference::evaluateView(slot, sampled(slot), view);
        for (size_t p = 0; p < ref.size(); ++p) {
            const double t = pixelTolerance(ref[p], es, es, slot.hex, int(count));
            check.maxTolerance = std::max(check.maxTolerance, t);
            for (size_t c = 0; c < count; ++c) {
                const double want = ref[p].value[colour ? c : size_t(slot.channel)];
                cpu.rgba[p * 4 + first + c] = float(want);
                check.tolerance[p * 4 + first + c] = t;
                double e = std::fabs(double(gpu.rgba[p * 4 + first + c]) - want);
                if (!(e == e)) e = INFINITY;
                if (e > check.errors.max) check.toleranceAtMax = t;
                check.errors.max = std::max(check.errors.max, e);
                check.worstRatio = std::max(check.worstRatio, errorRatio(e, t));
            }
        }
    }
    check.errors = compare(gpu, cpu, 4);
    check.reference = std::move(cpu);
    return check;
}

inline CaseCheck checkPackedCase(const ExecCase& packed, const Draw& draw) {
    const nlohmann::json c = readCase(packed, {"slots", "hextiling", "minified"});
    std::string slots;
    for (const nlohmann::json& slot : c.at("slots")) slots += (slots.empty() ? "" : ", ") + withCrop(slot);
    ParseResult r = parseMaterial(R"({"name": "packed", "template": "../tests/templates/packed.glsl", "pack": true, "hextiling": )" +
                                      c.at("hextiling").dump() + R"(, "slots": [)" + slots + "]}",
                                  "materials/packed.json");
    if (!r.material) throw std::runtime_error(formatAll(r.diagnostics));
    const Material& m = *r.material;
    const auto [view, level] = cropView(std::max(m.slots[0].width, m.slots[0].height), m.slots[0].hex.tiling[0], c.at("minified"));
    return {m, view, checkPacked(m, view, level, draw)};
}

// ---- Adaptive taps ----------------------------------------------------------------------------------------
// "taps": "adaptive" skips a tap when its bound says the result moves by less than e = HexTiling::kAdaptiveError times
// the spread of the taps' values (docs/material-format.md#taps). Three checks per case and target:
// 1. which taps are fetched: the weights output shows a skipped tap's weight as exactly 0, the reference says which it
//    skips. Both decide from the same bound, the GPU in float32, so they may differ only where a bound is within
//    rounding of e: at most 1% of the pixels;
// 2. the value against the adaptive reference: where both fetch the same taps, the same blend of the same samples, so
//    the full blend's tolerance (pixelTolerance); elsewhere each is within e S of its exact 3-tap result, and those
//    within the full blend's tolerance of each other: 2 e S plus that of the exact reference;
// 3. the bound itself, on the GPU: adaptive against exact 3-tap on the same target and view, within e S. S: the spread
//    of the values blended, 1 for 8-bit colour or scalars; a normal slot's derivative components are at most
//    sqrt(2) max|d| in magnitude (a filtered sample's |x| / z is at most its texels' largest, then rotated), so
//    S = 2 sqrt(2) max|d|. The bound is computed in float32 (relative error ~1e-6 on a threshold of 1/255) and the two
//    blends round independently (a few 2^-24): 1e-6 more.
// A case: "slots", its one slot (exact 3-tap; the test adds "taps": "adaptive"), "minified".
struct AdaptiveCase {
    Material adaptive, exact;  // the case's slot with "taps": "adaptive", and as the case gives it
    View view;
    int level;
};

inline AdaptiveCase adaptiveCase(const ExecCase& adaptive) {
    const nlohmann::json c = readCase(adaptive, {"slots", "minified"});
    const auto withTaps = [&](bool adaptiveTaps) {
        nlohmann::json slot = c.at("slots").at(0);
        if (adaptiveTaps) slot["hextiling"]["taps"] = "adaptive";
        return material(withCrop(slot));
    };
    const bool minified = c.at("minified");
    return {withTaps(true), withTaps(false), minified ? kMinified : kMagnified, minified ? 2 : 0};
}

// S: the spread of the values an adaptive slot blends (above).
inline double adaptiveSpread(const Slot& slot) {
    const TextureBounds b = bounds(sampled(slot));
    return kindRow(slot.kind).derivative ? 2 * std::sqrt(2.0) * b.maxDeriv : b.spread;
}

// Check 3's bound: e S, plus 1e-6 for the bound's float32 evaluation and the blends' rounding (above).
inline double adaptiveBound(const Slot& slot) { return HexTiling::kAdaptiveError * adaptiveSpread(slot) + 1e-6; }

// Whether the reference fetches a tap, as the weights output would show it. A fetched tap's weight can lie below
// float32's normal range (exponent 64 and a gain of k = 19 take a weight of 1e-3 to 1e-52): the GPU holds it as 0, so
// the reference's counts as 0 there too.
inline bool fetchedByReference(const reference::SlotResult& r, size_t tap) { return r.weights[tap] >= 0x1p-126; }

// Check 2: the adaptive slot's value against the adaptive reference, each pixel within the full blend's tolerance, or
// where `differs` (check 1: the GPU fetches other taps than the reference) 2 e S plus the exact reference's.
inline Check checkAdaptive(const AdaptiveCase& a, const std::vector<bool>& differs, const Draw& draw) {
    const Slot& slot = a.adaptive.slots[0];
    const bool normal = kindRow(slot.kind).derivative;
    const TextureBounds b = bounds(sampled(slot));
    // As checkColor and checkNormal.
    const double es = sampleError(a.level, slot.colorSpace == ColorSpace::Srgb),
                 ed = 2 * sampleError(a.level, false) * (1 + b.maxDeriv) / b.minZ;
    const double ex = normal ? ed : es, em = normal ? std::sqrt(2.0) * ed : es;
    const int channels = normal ? 2 : kindRow(slot.kind).oneChannel ? 1 : 4;
    const int blended = kindRow(slot.kind).oneChannel ? 1 : channels;
    const std::vector<reference::SlotResult> ref3 = reference::evaluateView(a.exact.slots[0], sampled(slot), a.view);
    const double otherTaps = 2 * HexTiling::kAdaptiveError * adaptiveSpread(slot) + 1e-6;
    const vk::RenderOutput output = normal ? vk::RenderOutput::Derivative : vk::RenderOutput::Albedo;
    return checkAgainstReference(a.adaptive, output, a.view, draw, channels, [&](const reference::SlotResult& r, size_t p) {
        return differs[p] ? otherTaps + pixelTolerance(ref3[p], ex, em, slot.hex, blended) : pixelTolerance(r, ex, em, slot.hex, blended);
    });
}

}  // namespace hexc::exec
