// Execution tests: what hexc emits, run on Vulkan (Mesa lavapipe), against the fp64 CPU reference.
// Every comparison prints its measured error beside the tolerance it is held to.
#include <gtest/gtest.h>

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

using namespace hexc;
using hexc::test::runHexc;
using hexc::test::runner;

namespace {

// ---- Tolerances -------------------------------------------------------------------------------------------
// Lavapipe samples an 8-bit texture with 8-bit bilinear weights: against exact bilinear filtering a sample is
// off by up to half a weight step (0.5/256) per axis on a full-range step, plus the rounding of the result:
// 1.2/255 in all. Each mip level is made by a blit of the level above and stored in 8 bits, which puts it up
// to 1/255 off the exact box average per level (an sRGB level is stored encoded, and the sRGB curve is at
// most 2.4/1.055 = 2.27 times steeper in linear terms). A view whose deepest level is L therefore samples
// within e_s = (1.2 + L * m) / 255, m = 1 (linear) or 2.27 (sRGB).
double sampleError(int deepestLevel, bool srgb) { return (1.2 + deepestLevel * (srgb ? 2.27 : 1.0)) / 255.0; }

// The blend R = sum W_j x_j moves with its samples, and also through its weights: W_j is proportional to
// delta_j * w_j^gamma with delta = (1 - beta) + beta * metric >= 1 - beta, so dR/d(delta_j) = W_j (x_j - R) / delta_j
// and a metric error e_m moves R by at most e_m * beta / (1 - beta) * sum_j W_j |x_j - R|. The gain of Eq. 5
// multiplies weight changes by at most its steepest slope, k = log2(1 / (1 - r)) (1 when r <= 0.5). Per pixel,
// with W_j, x_j and R from the reference:
//     |R_gpu - R_ref| <= e_x + e_m * k * beta / (1 - beta) * max_c sum_j W_j |x_jc - R_c|.
// `k`: the gain's steepest slope.
double blendTolerance(const reference::SlotResult& r, double ex, double em, double beta, double k, int channels) {
    double spread = 0;
    for (int c = 0; c < channels; ++c) {
        double sum = 0;
        for (size_t j = 0; j < 3; ++j) sum += r.blend[j] * std::fabs(r.samples[j][size_t(c)] - r.value[size_t(c)]);
        spread = std::max(spread, sum);
    }
    return ex + em * k * beta / (1.0 - beta) * spread;
}

double pixelTolerance(const reference::SlotResult& r, double ex, double em, const HexTiling& hex, int channels) {
    if (!hex.enabled) return ex;
    return blendTolerance(r, ex, em, hex.falloffcontrast, std::max(1.0, std::log2(1.0 / (1.0 - hex.falloff))), channels);
}

// ---- Fixtures ---------------------------------------------------------------------------------------------

// A material of the given slots (one slot object, or several separated by commas; the first is the one tested)
// and optional material-level hex-tiling settings.
Material material(const std::string& slotJson, const std::string& hexJson = "{}") {
    ParseResult r =
        parseMaterial(R"({"name": "exec", "hextiling": )" + hexJson + R"(, "slots": [)" + slotJson + "]}", "materials/exec.json");
    if (!r.material) throw std::runtime_error(formatAll(r.diagnostics));
    return *r.material;
}

using Errors = vk::ImageErrors;
const auto compare = vk::compareImages;

reference::SampledTexture sampled(const Slot& slot) {
    return reference::SampledTexture(loadTexture(slot.texturePath, slot.colorSpace == ColorSpace::Srgb));
}

Image cpuRender(const Slot& slot, const View& view, reference::Output output) {
    return reference::render(slot, sampled(slot), view, output);
}

// What a texture's own content allows, measured on its level 0 (in linear values, as sampled).
struct TextureBounds {
    double spread = 0;    // largest max - min of a channel: bounds |x_j - R| for a blend of samples
    double step = 0;      // largest difference between horizontally or vertically adjacent texels
    double minZ = 1;      // normal maps: smallest z = 2 b - 1
    double maxDeriv = 0;  // normal maps: largest |dH/du| or |dH/dv| of a texel (Listing 9)
};

TextureBounds bounds(const reference::SampledTexture& t) {
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

// The paper's hash is fract(sin(x) * 43758.5453): lavapipe's sin and the C library's disagree in the last bits, which
// the factor 43758 turns into different tiles away from the origin (see docs/precision.md). Near the origin, where
// the ids are 0 and 1, both agree: paper-mode cases are seen there, at level 0.
const View kOrigin{192, 192, {0.0, 0.0, 0.02, 0.02}};

struct Check {
    Errors errors;
    double worstRatio = 0;      // max over pixels of error / tolerance: <= 1 passes
    double toleranceAtMax = 0;  // the tolerance of the pixel with the largest error
    double maxTolerance = 0;
};

// Height blending (hexcHeightBlend): W'_i = W_i f_i / S with f_i = max(h_i W_i - max_j h_j W_j + width, 0) and
// S = sum_j W_j f_j. Heights off by at most e_h move each a_j = h_j W_j by <= e_h W_j, each f_i by <= 2 e_h and S by
// <= 2 e_h sum_j W_j = 2 e_h, so sum_i |dW'_i| <= (2 e_h + 2 e_h) / S, and the blend, whose weight changes sum to 0,
// by <= sum_i |dW'_i| / 2 * spread = 2 e_h spread / S, spread being the largest difference between the tiles'
// samples in a channel.
double heightTolerance(const reference::SlotResult& r, double eh, int channels) {
    double spread = 0;
    for (int c = 0; c < channels; ++c) {
        double lo = INFINITY, hi = -INFINITY;
        for (const reference::Rgba& x : r.samples) {
            lo = std::min(lo, x[size_t(c)]);
            hi = std::max(hi, x[size_t(c)]);
        }
        spread = std::max(spread, hi - lo);
    }
    return 2 * eh * spread / r.heightSum;
}

// What draws a material's output on the GPU: hexc's shader on one target, or a shader written by hand.
using Draw = std::function<Image(const Material& m, vk::RenderOutput output, const View& view)>;

Draw on(vk::ExecutedTarget target, const CompileOptions& options = {}) {
    return [=](const Material& m, vk::RenderOutput output, const View& view) {
        std::string why;
        return vk::render(*runner(&why), m, output, "", view, target, 0, nullptr, {}, options);
    };
}

// Each pixel's tolerance, from the reference's details of it.
using PixelTolerance = std::function<double(const reference::SlotResult&, size_t pixel)>;

// Runs a one-slot material on the GPU and compares `channels` channels of every pixel with the reference, each pixel
// against its own tolerance.
Check checkAgainstReference(const Material& m, vk::RenderOutput output, const View& view, const Draw& draw, int channels,
                            const PixelTolerance& tolerance) {
    const Slot& slot = m.slots[0];
    Image gpu = draw(m, output, view);
    const reference::Heights heights(m, slot);
    const reference::SlotTextures textures(slot);
    std::vector<reference::SlotResult> ref = reference::evaluateView(slot, *textures.texture, view, heights.source(), textures.lut.get());
    Check check;
    Image cpu = gpu;
    for (size_t p = 0; p < ref.size(); ++p) {
        // Scalar slots show (s, s, s, 1) of the channel they read.
        for (int c = 0; c < channels; ++c)
            cpu.rgba[p * 4 + size_t(c)] = float(ref[p].value[slot.kind == SlotKind::Scalar ? size_t(slot.channel) : size_t(c)]);
        const double t = tolerance(ref[p], p);
        check.maxTolerance = std::max(check.maxTolerance, t);
        for (int c = 0; c < channels; ++c) {
            double e = std::fabs(double(gpu.rgba[p * 4 + size_t(c)]) - double(cpu.rgba[p * 4 + size_t(c)]));
            if (!(e == e)) e = INFINITY;
            if (e > check.errors.max) check.toleranceAtMax = t;
            check.worstRatio = std::max(check.worstRatio, e / t);
        }
    }
    check.errors = compare(gpu, cpu, channels);
    return check;
}

// The falloff blend's tolerance (pixelTolerance, plus heightTolerance for height blending) with sample error ex and
// metric error em. `level`: the deepest mip level the view reads.
Check checkAgainstReference(const Material& m, vk::RenderOutput output, const View& view, int level, const Draw& draw, double ex, double em,
                            int channels) {
    const Slot& slot = m.slots[0];
    // The height map is 8-bit linear data, sampled at the view's levels like the slot.
    const double eh = sampleError(level, false);
    const int blended = slot.kind == SlotKind::Scalar ? 1 : channels;
    return checkAgainstReference(m, output, view, draw, channels, [&](const reference::SlotResult& r, size_t) {
        return pixelTolerance(r, ex, em, slot.hex, blended) + (slot.heightBlend ? heightTolerance(r, eh, blended) : 0.0);
    });
}

void report(const char* name, const Check& c) {
    std::printf("  %-30s max %.5f (%.2f/255)  mean %.6f  >1/255 %.4f  tolerance there %.5f  worst error/tolerance %.2f\n", name,
                c.errors.max, c.errors.max * 255, c.errors.mean, c.errors.overOne255, c.toleranceAtMax, c.worstRatio);
}

// A colour or scalar slot (the material's first) against the reference, in a view whose deepest mip level is `level`.
Check checkColor(const Material& m, const View& view, int level, const Draw& draw) {
    const Slot& slot = m.slots[0];
    // MaterialX mode decodes after filtering the stored texels: their 8-bit linear error, times the sRGB curve's steepest
    // slope (2.4 / 1.055 at 1).
    double es = slot.shaderDecodes() ? 2.4 / 1.055 * sampleError(level, false) : sampleError(level, slot.colorSpace == ColorSpace::Srgb);
    // Colour: the luminance metric errs by at most e_s (its weights sum to 1); scalar: the channel itself.
    return checkAgainstReference(m, vk::RenderOutput::Albedo, view, level, draw, es, es, slot.kind == SlotKind::Scalar ? 1 : 4);
}

Check checkColor(const Material& m, bool minified, const Draw& draw) {
    return checkColor(m, minified ? kMinified : kMagnified, minified ? 2 : 0, draw);
}

std::string targetName(vk::ExecutedTarget t) {
    return t == vk::ExecutedTarget::Spirv ? "spirv" : t == vk::ExecutedTarget::Hlsl ? "hlsl" : "glsl";
}

const auto kExecutedTargets = testing::Values(vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl);

// ---- Histogram blend ---------------------------------------------------------------------------------------------

// The largest difference between horizontally or vertically adjacent texels of a level, per channel.
std::array<double, 3> adjacentSteps(const reference::SampledTexture& t, int level) {
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
PixelTolerance histogramTolerance(const Slot& slot, const reference::SlotTextures& textures, int level) {
    const reference::SampledTexture& lut = *textures.lut;
    const std::array<double, 3> step = adjacentSteps(*textures.texture, level);
    const size_t channels = slot.kind == SlotKind::Scalar ? 1 : 3;
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
// mip level is `level`.
Check checkHistogram(const Material& m, const View& view, int level, const Draw& draw) {
    const Slot& slot = m.slots[0];
    const reference::SlotTextures textures(slot);
    return checkAgainstReference(m, vk::RenderOutput::Albedo, view, draw, slot.kind == SlotKind::Scalar ? 1 : 4,
                                 histogramTolerance(slot, textures, level));
}

// ---- Normal path --------------------------------------------------------------------------------------------
// A normal slot (the material's first) against the reference, as derivatives.
Check checkNormal(const Material& m, const View& view, int level, const Draw& draw) {
    const Slot& slot = m.slots[0];
    const bool triplanar = slot.hex.projection == Projection::Triplanar;
    TextureBounds b = bounds(sampled(slot));
    // Listing 9: d = -xy / z with x, y, z = 2 * texel - 1, each off by 2 e_s, so to first order
    // |dd| <= 2 e_s (1 + max|d|) / min z. The slope metric sin(theta) = sqrt(|d|^2 / (1 + |d|^2)) moves by at
    // most the error of |d| (its slope is <= 1), which is <= sqrt(2) |dd|.
    double ed = 2 * sampleError(level, false) * (1 + b.maxDeriv) / b.minZ;
    // Triplanar: each plane's gradient g_k errs by |(dd_x, dd_y)| <= sqrt(2) ed, so does their convex combination,
    // and the projection onto the surface does not lengthen it: each component of the surface gradient is within
    // sqrt(2) ed. The plane weights' own float32 error (~1e-7) is negligible.
    return triplanar ? checkAgainstReference(m, vk::RenderOutput::Derivative, view, level, draw, std::sqrt(2.0) * ed, 0, 3)
                     : checkAgainstReference(m, vk::RenderOutput::Derivative, view, level, draw, ed, std::sqrt(2.0) * ed, 2);
}

Check checkNormal(const Material& m, bool minified, const Draw& draw) {
    return checkNormal(m, minified ? kMinified : kMagnified, minified ? 2 : 0, draw);
}

// ---- rock's slots, one at a time, from other outputs ---------------------------------------------------------

// A material file (rock by default) with only the slot `slotName`, its settings as the file gives them.
Material rockWith(const std::string& slotName, const std::string& file = "materials/rock.json") {
    ParseResult rock = parseMaterialFile(file);
    if (!rock.material) throw std::runtime_error(formatAll(rock.diagnostics));
    Material one = *rock.material;
    one.slots.erase(std::remove_if(one.slots.begin(), one.slots.end(), [&](const Slot& s) { return s.name != slotName; }), one.slots.end());
    return one;
}

// Its slot, magnified, against the reference: the derivative rule for a normal map, else the falloff one.
Check checkSlot(const Material& one, const Draw& draw) {
    return one.slots[0].kind == SlotKind::Normal ? checkNormal(one, false, draw) : checkColor(one, false, draw);
}

// ---- Debug outputs ------------------------------------------------------------------------------------------

// --debug outputs (unoptimised, hexc's functions kept, #line directives) of each of rock's slots, with rock's
// settings, on every target: the same reference and tolerances as the optimised ones above.
class DebugOutputs : public testing::TestWithParam<vk::ExecutedTarget> {};

TEST_P(DebugOutputs, RocksSlotsMatchTheReference) {
    REQUIRE_VULKAN();
    CompileOptions debug;
    debug.debug = true;
    for (const std::string slot : {"albedo", "normal", "roughness"}) {
        Check check = checkSlot(rockWith(slot), on(GetParam(), debug));
        report(("rock " + slot + " --debug").c_str(), check);
        EXPECT_LE(check.worstRatio, 1.0) << slot;
    }
}

INSTANTIATE_TEST_SUITE_P(Exec, DebugOutputs, testing::Values(vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl),
                         [](const auto& info) { return targetName(info.param); });

// ---- MaterialX documents ---------------------------------------------------------------------------------------

// Each slot of the hand-written MaterialX documents (docs/materialx.md), as hexc reads them, on every executed target:
// the same reference and tolerances as JSON materials. preview_surface reads MaterialX's defaults (tile scales 0.5-2,
// rotations over 0-360 degrees) and plain tiled and normal-mapped images.
class MaterialXDocuments : public testing::TestWithParam<vk::ExecutedTarget> {};

TEST_P(MaterialXDocuments, EverySlotMatchesTheReference) {
    REQUIRE_VULKAN();
    for (const std::string file : {"materials/mtlx/rock.mtlx", "materials/mtlx/preview_surface.mtlx"})
        for (const std::string slot : {"albedo", "normal", "roughness"}) {
            Check check = checkSlot(rockWith(slot, file), on(GetParam()));
            report((std::filesystem::path(file).stem().string() + " " + slot).c_str(), check);
            EXPECT_LE(check.worstRatio, 1.0) << file << " " << slot;
        }
}

INSTANTIATE_TEST_SUITE_P(Exec, MaterialXDocuments,
                         testing::Values(vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl),
                         [](const auto& info) { return targetName(info.param); });

// ---- MaterialX mode -------------------------------------------------------------------------------------------

// MaterialX mode (docs/materialx.md#materialx-mode) against its own reference (reference/materialx.cpp), with rotation,
// scale and offset ranges, falloff, falloff contrast and luma weights all away from their defaults, magnified and
// minified, on every target. Colour: the blend R = sum W_j x_j with W_j proportional to c_j w_j^7, c_j = 1 + beta (l_j
// - 1) >= 1 - beta; a luma error e_m (<= e_s: the weights sum to 1) moves c_j by beta e_m, and R by at most
// e_m beta / (1 - beta) sum_j W_j |x_j - R| (as pixelTolerance), times the steepest slope of Schlick's gain, which is
// max(r / (1 - r), (1 - r) / r) at its ends. Normal: each tile's gradient -R(angle) m / |m_z| errs by the derivative
// rule's e_d per component before the rotation, so by sqrt(2) e_d after it; its weights do not depend on the samples.
double materialxTolerance(const reference::SlotResult& r, double ex, const HexTiling& hex, int channels) {
    const double rr = std::clamp(hex.falloff, 0.001, 0.999), k = hex.falloff == 0.5 ? 1.0 : std::max(rr / (1 - rr), (1 - rr) / rr);
    return blendTolerance(r, ex, ex, hex.falloffcontrast, k, channels);
}

class MaterialXMode : public testing::TestWithParam<vk::ExecutedTarget> {};

TEST_P(MaterialXMode, HextiledimageAndHextilednormalmapMatchTheirReference) {
    REQUIRE_VULKAN();
    const std::string transforms =
        R"("mode": "materialx", "tiling": 4, "rotation": 0.8, "rotationrange": [20, 200], "scalerange": [0.7, 1.6],
        "offset": 0.6, "falloff": 0.7)";
    const Material color = material(R"({"name": "albedo", "kind": "color", "colorspace": "linear", "texture": "textures/rock_albedo.png",
        "hextiling": {)" + transforms +
                                    R"(, "falloffcontrast": 0.4, "lumacoeffs": [0.2126, 0.7152, 0.0722]}})");
    const Material normal = material(R"({"name": "normal", "kind": "normal", "flip_y": true, "texture": "textures/rock_normal.png",
        "hextiling": {)" + transforms +
                                     "}}");
    const TextureBounds b = bounds(sampled(normal.slots[0]));
    for (bool minified : {false, true}) {
        const View& view = minified ? kMinified : kMagnified;
        // A tile scaled by s shows 1 / s as many texels per pixel: 0.75 / 0.7 (magnified) and 4 / 0.7 (minified) read
        // levels up to 1 and 3.
        const int level = int(std::ceil(std::log2((minified ? 4.0 : 0.75) / color.slots[0].hex.scaleRange[0])));
        const double es = sampleError(level, false), ed = 2 * es * (1 + b.maxDeriv) / b.minZ;
        Check c =
            checkAgainstReference(color, vk::RenderOutput::Albedo, view, on(GetParam()), 4,
                                  [&](const reference::SlotResult& r, size_t) { return materialxTolerance(r, es, color.slots[0].hex, 4); });
        report(minified ? "materialx color minified" : "materialx color", c);
        EXPECT_LE(c.worstRatio, 1.0);
        if (!minified) {
            EXPECT_LE(c.errors.max, 2.0 / 255);  // MaterialX's own shader agrees with hexc's modes to 2/255 magnified
        }
        Check n = checkAgainstReference(normal, vk::RenderOutput::Derivative, view, on(GetParam()), 2,
                                        [&](const reference::SlotResult&, size_t) { return std::sqrt(2.0) * ed; });
        report(minified ? "materialx normal minified" : "materialx normal", n);
        EXPECT_LE(n.worstRatio, 1.0);
    }
}

INSTANTIATE_TEST_SUITE_P(Exec, MaterialXMode, kExecutedTargets, [](const auto& info) { return targetName(info.param); });

// Falloffs 1 - 2^-k (0.75, 0.875), whose gain stable mode multiplies out (k whole): in both modes the gain is the one
// the reference applies, Perlin's in stable mode, Schlick's in MaterialX mode (which has no such shortcut), colour and
// normal, magnified, on every target, with the tolerances above.
class IntegerGain : public testing::TestWithParam<vk::ExecutedTarget> {};

TEST_P(IntegerGain, EachModeAppliesItsGain) {
    REQUIRE_VULKAN();
    for (const std::string mode : {"stable", "materialx"})
        for (const std::string falloff : {"0.75", "0.875"}) {
            const std::string hex = R"("mode": ")" + mode + R"(", "tiling": 4, "rotation": 0.5, "falloff": )" + falloff;
            const Material color =
                material(R"({"name": "albedo", "kind": "color", "colorspace": "linear", "texture": "textures/rock_albedo.png",
                "hextiling": {)" +
                         hex + R"(, "falloffcontrast": 0.4}})");
            const Material normal =
                material(R"({"name": "normal", "kind": "normal", "texture": "textures/rock_normal.png", "hextiling": {)" + hex + "}}");
            const std::string name = mode + " falloff " + falloff;
            Check c, n;
            if (mode == "stable") {
                c = checkColor(color, false, on(GetParam()));
                n = checkNormal(normal, false, on(GetParam()));
            } else {
                const double es = sampleError(0, false),
                             ed = 2 * es * (1 + bounds(sampled(normal.slots[0])).maxDeriv) / bounds(sampled(normal.slots[0])).minZ;
                c = checkAgainstReference(
                    color, vk::RenderOutput::Albedo, kMagnified, on(GetParam()), 4,
                    [&](const reference::SlotResult& r, size_t) { return materialxTolerance(r, es, color.slots[0].hex, 4); });
                n = checkAgainstReference(normal, vk::RenderOutput::Derivative, kMagnified, on(GetParam()), 2,
                                          [&](const reference::SlotResult&, size_t) { return std::sqrt(2.0) * ed; });
            }
            report((name + " color").c_str(), c);
            report((name + " normal").c_str(), n);
            EXPECT_LE(c.worstRatio, 1.0) << name;
            EXPECT_LE(n.worstRatio, 1.0) << name;
        }
}

INSTANTIATE_TEST_SUITE_P(Exec, IntegerGain, kExecutedTargets, [](const auto& info) { return targetName(info.param); });

// An sRGB colour slot in MaterialX mode: the texture is bound linear (UNORM) and its stored texels filtered, blended
// and then decoded, as MaterialX does (the reference likewise); filtering decoded texels was 17/255 off magnified and
// 9/255 minified. falloffcontrast 0, so the weights do not depend on the samples: the encoded blend errs by the
// sampling error e_s of 8-bit linear data (sampleError), and decoding multiplies an error by at most the sRGB curve's
// steepest slope, 2.4 / 1.055 = 2.27 (at 1).
class MaterialXSrgb : public testing::TestWithParam<vk::ExecutedTarget> {};

TEST_P(MaterialXSrgb, FiltersTheStoredTexelsAndDecodesTheBlend) {
    REQUIRE_VULKAN();
    const Material m = material(R"({"name": "albedo", "kind": "color", "colorspace": "srgb", "texture": "textures/rock_albedo.png",
        "hextiling": {"mode": "materialx", "tiling": 4, "rotation": 0.5, "scalerange": [0.7, 1.6], "falloff": 0.75, "falloffcontrast": 0}})");
    for (bool minified : {false, true}) {
        const double es = sampleError(minified ? 3 : 1, false);  // levels up to 3 minified and 1 magnified (scales from 0.7)
        Check c = checkAgainstReference(m, vk::RenderOutput::Albedo, minified ? kMinified : kMagnified, on(GetParam()), 3,
                                        [&](const reference::SlotResult&, size_t) { return 2.4 / 1.055 * es; });
        report(minified ? "materialx srgb minified" : "materialx srgb", c);
        EXPECT_LE(c.worstRatio, 1.0);
    }
}

INSTANTIATE_TEST_SUITE_P(Exec, MaterialXSrgb, kExecutedTargets, [](const auto& info) { return targetName(info.param); });

// ---- GLSL versions ------------------------------------------------------------------------------------------

// Every OpenGL GLSL version hexc emits, executed (compiled again by glslang, as the Glsl target above) on rock's
// albedo and normal slots: the same reference and tolerances. GLSL 330 and ES 3.00 bind by name; one slot has one
// block and one texture unit, where glslang's auto-mapping puts them (render.cpp).
TEST(GlslVersions, EachMatchesTheReference) {
    REQUIRE_VULKAN();
    for (auto [version, es] : {std::pair{460u, false}, {330u, false}, {310u, true}, {300u, true}}) {
        CompileOptions options;
        options.glslVersion = version;
        options.glslEs = es;
        for (const std::string slot : {"albedo", "normal"}) {
            Check check = checkSlot(rockWith(slot), on(vk::ExecutedTarget::Glsl, options));
            const std::string name = "rock " + slot + " GLSL " + std::to_string(version) + (es ? " es" : "");
            report(name.c_str(), check);
            EXPECT_LE(check.worstRatio, 1.0) << name;
        }
    }
}

// ---- The library for hand-written shaders ------------------------------------------------------------------------

// materials/library/<file> with its `#include "hexc_hextiling.<ext>"` line replaced by `hexc library`'s file, as
// an include path would give it.
std::string withLibrary(const std::string& file, Target target) {
    std::ifstream in("materials/library/" + file);
    std::string text(std::istreambuf_iterator<char>(in), {});
    const OutputFile library = hexcLibrary({target}).front();
    const std::string line = "#include \"" + library.name + "\"";
    const size_t at = text.find(line);
    if (at == std::string::npos) throw std::runtime_error(file + " does not include " + library.name);
    return text.replace(at, line.size(), library.contents);
}

// The hand-written shaders' Settings block (std140, which the HLSL cbuffer's packing matches): tiling, rotation,
// falloff, falloffContrast, exponent of the slot.
std::vector<uint8_t> settingsBlock(const Slot& slot) {
    const HexTiling& h = slot.hex;
    const float values[] = {float(h.tiling[0]), float(h.tiling[1]),       float(h.rotation),
                            float(h.falloff),   float(h.falloffcontrast), float(h.exponent)};
    std::vector<uint8_t> bytes(sizeof(values));
    std::memcpy(bytes.data(), values, sizeof(values));
    return bytes;
}

// A hand-written shader, bound as its source declares: the block at binding 0, the texture at `firstTexture`, the
// sampler at `sampler` (unread when combined), all in set 0.
Draw handWritten(const std::vector<uint32_t>& spirv, uint32_t firstTexture, uint32_t sampler, bool combined) {
    return [=](const Material& m, vk::RenderOutput, const View& view) {
        const Slot& slot = m.slots[0];
        const Texture texture = loadTexture(slot.texturePath, slot.colorSpace == ColorSpace::Srgb);
        vk::RenderRequest request;
        request.fragmentSpirv = spirv;
        request.uniformData = settingsBlock(slot);
        request.textures = {&texture};
        request.combinedSamplers = combined;
        request.paramsBinding = 0;
        request.samplerBinding = sampler;
        request.firstTextureBinding = firstTexture;
        std::string why;
        return vk::renderFragment(*runner(&why), request, view);
    };
}

// materials/library/hextiled_color.hlsl with the HLSL library, through glslang's HLSL front end, on rock's albedo
// (sRGB, rotation 1, falloff 0.75): the reference and tolerances of the falloff rule, magnified and minified.
TEST(Library, AHandWrittenHlslShaderMatchesTheReference) {
    REQUIRE_VULKAN();
    SpirvResult front = compileToSpirv(withLibrary("hextiled_color.hlsl", Target::Hlsl), ShaderStage::Fragment, "hextiled_color.hlsl",
                                       SourceLanguage::Hlsl, "main");
    ASSERT_FALSE(front.words.empty()) << formatAll(front.diagnostics);
    SpirvResult legal = optimizeSpirv(front.words, false, true);
    ASSERT_FALSE(legal.words.empty()) << formatAll(legal.diagnostics);
    const Draw draw = handWritten(legal.words, kHlslTextureShift, kHlslSamplerShift, false);
    for (bool minified : {false, true}) {
        Check check = checkColor(rockWith("albedo"), minified, draw);
        report(minified ? "hand-written HLSL, minified" : "hand-written HLSL", check);
        EXPECT_LE(check.worstRatio, 1.0);
    }
}

// materials/library/hextiled_normal.glsl with the OpenGL GLSL library, through glslang, on rock's normal map: the
// reference and tolerances of the derivative rule.
TEST(Library, AHandWrittenGlslShaderMatchesTheReference) {
    REQUIRE_VULKAN();
    SpirvResult front = compileToSpirv(withLibrary("hextiled_normal.glsl", Target::Glsl), ShaderStage::Fragment, "hextiled_normal.glsl",
                                       SourceLanguage::OpenGlGlsl);
    ASSERT_FALSE(front.words.empty()) << formatAll(front.diagnostics);
    SpirvResult optimized = optimizeSpirv(front.words);
    ASSERT_FALSE(optimized.words.empty()) << formatAll(optimized.diagnostics);
    const Draw draw = handWritten(optimized.words, kGlTextureShift, kGlDefaultBlockBinding + 1, true);
    for (bool minified : {false, true}) {
        Check check = checkNormal(rockWith("normal"), minified, draw);
        report(minified ? "hand-written GLSL, minified" : "hand-written GLSL", check);
        EXPECT_LE(check.worstRatio, 1.0);
    }
}

// ---- The bench's paper listing ------------------------------------------------------------------------------------

// bench/paper-listing.glsl, the baseline of the bench's "x paper listing" (Listings 1-10 as written, per slot), must
// compute what hexc's paper mode (exactly Listings 1, 2, 5 and 6) computes on the same material, or the bench would
// time unlike shaders. Near the origin, where the paper's hash agrees between implementations (see kOrigin). Its
// normal map is a flat float texel, (0.5, 0.5, 1) -> (0, 0, 1) exactly, against hexc's material without one: Listing 3
// as written rotates derivatives back by R(+angle), right for a y-down map only (DESIGN.md), where hexc honours the
// map's convention, so the two normal paths time the same work but agree only on a flat map. What remains differs by
// float32 rounding in the order of operations: each output, about 1 here, by a few of its ulps (2^-23 ~ 1.2e-7); the
// bound 1e-5 leaves a factor of ~80, far below the 1/255 of one texel step an actual difference of the maths makes.
TEST(PaperListing, TheBenchBaselineComputesWhatPaperModeComputes) {
    REQUIRE_VULKAN();
    std::ifstream in("bench/paper-listing.glsl", std::ios::binary);
    const std::string source((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    SpirvResult front = compileToSpirv(source, ShaderStage::Fragment, "bench/paper-listing.glsl");
    ASSERT_FALSE(front.words.empty()) << formatAll(front.diagnostics);
    SpirvResult optimized = optimizeSpirv(front.words);
    ASSERT_FALSE(optimized.words.empty()) << formatAll(optimized.diagnostics);
    // The bench's full-quality material in paper mode: tiling 4, rotation 1, falloff 0.75 on every slot.
    ParseResult m = parseMaterial(
        R"({"name": "listing", "hextiling": {"tiling": 4, "mode": "paper", "rotation": 1, "falloff": 0.75}, "slots": [
            {"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png"},
            {"name": "roughness", "kind": "scalar", "texture": "textures/rock_roughness.png"}]})",
        "materials/listing.json");
    ASSERT_TRUE(m.material) << formatAll(m.diagnostics);
    const View view{128, 128, {0.0, 0.0, 0.05, 0.05}};
    std::string why;
    const Image hexc = vk::render(*runner(&why), *m.material, vk::RenderOutput::Shaded, "", view);
    const Texture albedo = loadTexture(m.material->slots[0].texturePath, true);
    const Texture roughness = loadTexture(m.material->slots[1].texturePath, false);
    const Texture flat{1, 1, false, {}, {0.5f, 0.5f, 1.0f, 1.0f}};
    vk::RenderRequest request;
    request.fragmentSpirv = optimized.words;
    request.textures = {&albedo, &flat, &roughness};
    const Errors e = compare(hexc, vk::renderFragment(*runner(&why), request, view), 3);
    std::printf("  paper listing against hexc's paper mode: max %.2e, mean %.2e\n", e.max, e.mean);
    EXPECT_LE(e.max, 1e-5);
}

// ---- Odd-sized textures -----------------------------------------------------------------------------------
// hexc accepts any texture size. The runner builds each mip level by a linear blit of the one above, which at an odd
// size resamples rather than averages; the reference models it (reference::SampledTexture::halve). Crops of the rock
// albedo (8-bit, linear, so not seamless: GPU and reference wrap alike) at odd and non-square sizes, seen magnified
// (0.75 texel per pixel along the larger axis: level 0) and minified (4 texels per pixel: exactly level 2, or the
// last level when the chain is shorter), with tile rotation off so the footprint stays axis-aligned: lavapipe's
// log2 of the footprint is exact only at a power of two, which a rotated footprint on a non-square texture is not.
struct OddSize {
    const char* name;
    int width, height;
    bool minified;
    bool histogram = false;  // "blend": "histogram": its Gaussian texture has the odd size, its table odd levels
    bool sharedLod = false;  // "lod": "shared": the level from sqrt(width * height), between two levels here
};
void PrintTo(const OddSize& c, std::ostream* os) { *os << c.name; }

std::filesystem::path cropOfRock(int width, int height) {
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

class OddSizes : public testing::TestWithParam<std::tuple<OddSize, vk::ExecutedTarget>> {};

TEST_P(OddSizes, MatchReference) {
    REQUIRE_VULKAN();
    const auto& [c, target] = GetParam();
    const std::filesystem::path file = cropOfRock(c.width, c.height);
    Material m = material(R"({"name": "albedo", "kind": "color", "colorspace": "linear", "texture": ")" + file.string() +
                          R"(", "hextiling": {"tiling": 4, "rotation": 0, "blend": ")" + (c.histogram ? "histogram" : "falloff") +
                          R"(", "lod": ")" + (c.sharedLod ? "shared" : "gradients") + R"("}})");
    const int larger = std::max(c.width, c.height), levels = std::bit_width(unsigned(larger));
    const double uvPerPixel = (c.minified ? 4.0 : 0.75) / (4.0 * larger);
    const View view{96, 96, {0.3, 0.45, 0.3 + 96 * uvPerPixel, 0.45 + 96 * uvPerPixel}};
    const int level = c.minified ? std::min(2, levels - 1) : 0;
    const double es = sampleError(level, false);
    Check check = c.histogram ? checkHistogram(m, view, level, on(target))
                              : checkAgainstReference(m, vk::RenderOutput::Albedo, view, level, on(target), es, es, 4);
    report(c.name, check);
    EXPECT_LE(check.worstRatio, 1.0);
}

INSTANTIATE_TEST_SUITE_P(
    Exec, OddSizes,
    testing::Combine(testing::Values(OddSize{"127x80", 127, 80, false}, OddSize{"127x80_minified", 127, 80, true},
                                     OddSize{"1x64", 1, 64, false}, OddSize{"1x64_minified", 1, 64, true}, OddSize{"3x3", 3, 3, false},
                                     OddSize{"3x3_minified", 3, 3, true}, OddSize{"127x127_minified", 127, 127, true},
                                     OddSize{"127x80_histogram", 127, 80, false, true},
                                     OddSize{"127x80_histogram_minified", 127, 80, true, true},
                                     OddSize{"3x3_histogram_minified", 3, 3, true, true},
                                     OddSize{"127x80_shared_lod_minified", 127, 80, true, false, true},
                                     OddSize{"1x64_shared_lod_minified", 1, 64, true, false, true}),
                     testing::Values(vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl)),
    [](const auto& info) { return std::string(std::get<0>(info.param).name) + "_" + targetName(std::get<1>(info.param)); });

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
struct AdaptiveCase {
    const char* name;
    const char* slot;  // "TAPS" stands for the taps setting, "TEXTURE" for an odd-sized crop of the rock albedo
    bool minified;
};
void PrintTo(const AdaptiveCase& c, std::ostream* os) { *os << c.name; }

const AdaptiveCase kAdaptiveCases[] = {
    {"color_full_quality",
     R"({"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 4, "falloff": 0.75TAPS}})",
     false},
    {"color_full_quality_minified",
     R"({"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 4, "falloff": 0.75TAPS}})",
     true},
    {"color_no_gain",
     R"({"name": "albedo", "kind": "color", "texture": "textures/tiles_albedo.png", "hextiling": {"tiling": 4, "exponent": 4TAPS}})",
     false},
    {"color_checker",
     R"({"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 4, "mask": "checker", "maskscale": 3, "falloff": 0.7TAPS}})",
     false},
    {"color_odd_127x80",
     R"({"name": "albedo", "kind": "color", "colorspace": "linear", "texture": "TEXTURE", "hextiling": {"tiling": 4, "rotation": 0, "falloff": 0.75TAPS}})",
     false},
    {"scalar_roughness",
     R"({"name": "roughness", "kind": "scalar", "texture": "textures/rock_roughness.png", "hextiling": {"tiling": 4, "falloff": 0.75TAPS}})",
     false},
    {"scalar_roughness_shared_lod_minified",
     R"({"name": "roughness", "kind": "scalar", "texture": "textures/rock_roughness.png", "hextiling": {"tiling": 4, "falloff": 0.75, "lod": "shared"TAPS}})",
     true},
    {"normal_full_quality",
     R"({"name": "normal", "kind": "normal", "texture": "textures/rock_normal.png", "hextiling": {"tiling": 4, "falloff": 0.75TAPS}})",
     false},
    {"normal_flip_y_minified",
     R"({"name": "normal", "kind": "normal", "flip_y": true, "texture": "textures/rock_normal.png", "hextiling": {"tiling": 4, "falloff": 0.75TAPS}})",
     true},
    // The corners of the settings: exponent 64 (w^64 down to 3e-31 at a lattice vertex), falloffcontrast near 1 and the
    // gain near its step (falloff 0.99, exponent k = 6.6). The last case's settings are exact in float32 (1 - 2^-20 and
    // 1 - 2^-19, k = 19): the gain raises a weight to the 19th power, so float32's rounding of 0.999999 (1.3% on 1 - r)
    // would move its bounds by a quarter, and the GPU's choice of taps away from the reference's, for that reason alone.
    {"color_exponent64_contrast0995_falloff099",
     R"({"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 4, "exponent": 64, "falloffcontrast": 0.995, "falloff": 0.99TAPS}})",
     false},
    {"color_exponent64_contrast09_falloff09_minified",
     R"({"name": "albedo", "kind": "color", "texture": "textures/tiles_albedo.png", "hextiling": {"tiling": 4, "exponent": 64, "falloffcontrast": 0.9, "falloff": 0.9TAPS}})",
     true},
    {"normal_exponent64_contrast_1_minus_2_20_falloff_1_minus_2_19",
     R"({"name": "normal", "kind": "normal", "texture": "textures/rock_normal.png", "hextiling": {"tiling": 4, "exponent": 64, "falloffcontrast": 0.99999904632568359375, "falloff": 0.999998092651367188TAPS}})",
     false},
};

Material adaptiveMaterial(const AdaptiveCase& c, bool adaptive) {
    std::string slot = c.slot;
    auto replace = [&](const std::string& what, const std::string& with) {
        if (size_t at = slot.find(what); at != std::string::npos) slot.replace(at, what.size(), with);
    };
    replace("TAPS", adaptive ? R"(, "taps": "adaptive")" : "");
    if (slot.find("TEXTURE") != std::string::npos) replace("TEXTURE", cropOfRock(127, 80).string());
    return material(slot);
}

class AdaptiveTaps : public testing::TestWithParam<std::tuple<AdaptiveCase, vk::ExecutedTarget>> {};

TEST_P(AdaptiveTaps, FetchLikeTheReferenceAndStayWithinTheBoundOfThreeTaps) {
    REQUIRE_VULKAN();
    const auto& [c, target] = GetParam();
    const Material m = adaptiveMaterial(c, true), exact = adaptiveMaterial(c, false);
    const Slot& slot = m.slots[0];
    const bool normal = slot.kind == SlotKind::Normal;
    const View view = c.minified ? kMinified : kMagnified;
    const int level = c.minified ? 2 : 0;
    const reference::SampledTexture tex = sampled(slot);
    const TextureBounds b = bounds(tex);
    const double e = HexTiling::kAdaptiveError, spread = normal ? 2 * std::sqrt(2.0) * b.maxDeriv : b.spread;
    // As checkColor and checkNormal.
    const double es = sampleError(level, slot.colorSpace == ColorSpace::Srgb),
                 ed = 2 * sampleError(level, false) * (1 + b.maxDeriv) / b.minZ;
    const double ex = normal ? ed : es, em = normal ? std::sqrt(2.0) * ed : es;
    const int channels = normal ? 2 : slot.kind == SlotKind::Scalar ? 1 : 4;

    // 1. The taps fetched.
    const Image weights = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Weights, "", view, target);
    const std::vector<reference::SlotResult> ref = reference::evaluateView(slot, tex, view);
    const std::vector<reference::SlotResult> ref3 = reference::evaluateView(exact.slots[0], tex, view);
    std::vector<bool> differs(ref.size());
    size_t gpuFetches = 0, refFetches = 0, different = 0;
    for (size_t p = 0; p < ref.size(); ++p)
        for (size_t ch = 0; ch < 3; ++ch) {
            // A fetched tap's weight can lie below float32's normal range (exponent 64 and a gain of k = 19 take a
            // weight of 1e-3 to 1e-52): the GPU holds it as 0, so the reference's counts as 0 there too.
            const bool gpu = weights.rgba[p * 4 + ch] > 0, cpu = ref[p].weights[ch] >= 0x1p-126;
            gpuFetches += gpu;
            refFetches += ref[p].blend[ch] >= 0x1p-126;
            if (gpu != cpu && !differs[p]) differs[p] = true, ++different;
        }
    const double n = double(ref.size());
    std::printf("  %-28s %-5s: fetches per pixel %.3f (reference %.3f), %zu pixels fetch other taps\n", c.name, targetName(target).c_str(),
                gpuFetches / n, refFetches / n, different);
    EXPECT_LE(different, ref.size() / 100);
    EXPECT_LT(gpuFetches / n, 3.0);  // something is skipped

    // 2. The value against the adaptive reference.
    const int blended = slot.kind == SlotKind::Scalar ? 1 : channels;
    const vk::RenderOutput output = normal ? vk::RenderOutput::Derivative : vk::RenderOutput::Albedo;
    Check check = checkAgainstReference(m, output, view, on(target), channels, [&](const reference::SlotResult& r, size_t p) {
        return differs[p] ? 2 * e * spread + pixelTolerance(ref3[p], ex, em, slot.hex, blended) + 1e-6
                          : pixelTolerance(r, ex, em, slot.hex, blended);
    });
    report(c.name, check);
    EXPECT_LE(check.worstRatio, 1.0);

    // 3. Against exact 3-tap on the GPU.
    const Image adaptive = on(target)(m, output, view), full = on(target)(exact, output, view);
    const Errors moved = compare(adaptive, full, channels == 1 ? 1 : normal ? 2 : 3);
    const double bound = e * spread + 1e-6;
    std::printf("  %-28s %-5s: adaptive against 3 taps max %.2e (%.2f/255), bound %.2e\n", c.name, targetName(target).c_str(), moved.max,
                moved.max * 255, bound);
    EXPECT_LE(moved.max, bound);
}

INSTANTIATE_TEST_SUITE_P(Exec, AdaptiveTaps, testing::Combine(testing::ValuesIn(kAdaptiveCases), kExecutedTargets), [](const auto& info) {
    return std::string(std::get<0>(info.param).name) + "_" + targetName(std::get<1>(info.param));
});

// ---- Packed textures ---------------------------------------------------------------------------------------
// "pack": true (docs/material-format.md#pack) under tests/templates/packed.glsl, which reads every slot and shows
// them in one image: `color`'s RGB and `s3` in alpha, or scalars s0..s3 in R..A. The packed texture holds each slot's
// texels byte for byte, so every slot is held to its unpacked tolerance against its own fp64 reference, which samples
// the slot's own texture: an sRGB colour slot's sample error for RGB, the linear one for a scalar in the sRGB texture's
// alpha (alpha stays linear), each slot blended with its own settings from the shared samples.
struct PackedCase {
    const char* name;
    const char* slots;  // slot JSON objects; null: a colour slot and a scalar one on an odd-sized crop (packedOddCrop)
    bool minified;
    const char* hextiling = R"({"tiling": 4})";
};
void PrintTo(const PackedCase& c, std::ostream* os) { *os << c.name; }

const char* const kPackedAlbedoRoughness =
    R"({"name": "color", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"falloff": 0.75}},
       {"name": "s3", "kind": "scalar", "texture": "textures/rock_roughness.png", "hextiling": {"falloff": 0.75}})";
// Four scalars with blends of their own: each slot's weights come from its own channel of the shared samples.
const char* const kPackedScalars =
    R"({"name": "s0", "kind": "scalar", "texture": "textures/rock_roughness.png", "hextiling": {"falloff": 0.75}},
       {"name": "s1", "kind": "scalar", "texture": "textures/rock_height.png", "hextiling": {"falloffcontrast": 0.3}},
       {"name": "s2", "kind": "scalar", "channel": "g", "texture": "textures/rock_albedo.png", "hextiling": {"exponent": 3}},
       {"name": "s3", "kind": "scalar", "channel": "b", "texture": "textures/rock_albedo.png", "hextiling": {"falloff": 0.9}})";

std::string packedOddCrop() {
    const std::string crop = cropOfRock(127, 80).string();
    return R"({"name": "color", "kind": "color", "colorspace": "linear", "texture": ")" + crop + R"("},
              {"name": "s3", "kind": "scalar", "channel": "g", "texture": ")" +
           crop + R"("})";
}

// Each slot's output channels against its reference, each pixel within the slot's tolerance (pixelTolerance).
Check checkPacked(const Material& m, const View& view, int level, const Draw& draw) {
    const Image gpu = draw(m, vk::RenderOutput::Shaded, view);
    Check check;
    Image cpu = gpu;
    for (const Slot& slot : m.slots) {
        const bool colour = slot.kind == SlotKind::Color;
        const size_t first = colour ? 0 : size_t(slot.name[1] - '0'), count = colour ? 3 : 1;
        const double es = sampleError(level, slot.colorSpace == ColorSpace::Srgb);
        const std::vector<reference::SlotResult> ref = reference::evaluateView(slot, sampled(slot), view);
        for (size_t p = 0; p < ref.size(); ++p) {
            const double t = pixelTolerance(ref[p], es, es, slot.hex, int(count));
            check.maxTolerance = std::max(check.maxTolerance, t);
            for (size_t c = 0; c < count; ++c) {
                const double want = ref[p].value[colour ? c : size_t(slot.channel)];
                cpu.rgba[p * 4 + first + c] = float(want);
                double e = std::fabs(double(gpu.rgba[p * 4 + first + c]) - want);
                if (!(e == e)) e = INFINITY;
                if (e > check.errors.max) check.toleranceAtMax = t;
                check.errors.max = std::max(check.errors.max, e);
                check.worstRatio = std::max(check.worstRatio, e / t);
            }
        }
    }
    check.errors = compare(gpu, cpu, 4);
    return check;
}

class PackedPath : public testing::TestWithParam<std::tuple<PackedCase, vk::ExecutedTarget>> {};

TEST_P(PackedPath, EverySlotMatchesItsReference) {
    REQUIRE_VULKAN();
    const auto& [c, target] = GetParam();
    ParseResult r = parseMaterial(R"({"name": "packed", "template": "../tests/templates/packed.glsl", "pack": true, "hextiling": )" +
                                      std::string(c.hextiling) + R"(, "slots": [)" + (c.slots ? c.slots : packedOddCrop()) + "]}",
                                  "materials/packed.json");
    ASSERT_TRUE(r.material) << formatAll(r.diagnostics);
    const Material& m = *r.material;
    // Packed indeed: one texture for all slots.
    CompileOptions spirvOnly;
    spirvOnly.targets = {Target::Spirv};
    const CompileResult compiled = compile(m, spirvOnly);
    ASSERT_TRUE(compiled.ok()) << formatAll(compiled.diagnostics);
    const auto manifest = nlohmann::json::parse(std::find_if(compiled.files.begin(), compiled.files.end(), [](const OutputFile& f) {
                                                    return f.name.ends_with(".json");
                                                })->contents);
    ASSERT_EQ(manifest["packed_textures"].size(), 1u);
    EXPECT_EQ(manifest["packed_textures"][0]["slots"].size(), m.slots.size());
    const int larger = std::max(m.slots[0].width, m.slots[0].height), levels = std::bit_width(unsigned(larger));
    const double tiling = m.slots[0].hex.tiling[0];
    const double uvPerPixel = (c.minified ? 4.0 : 0.75) / (tiling * larger);
    const View view{96, 96, {0.3, 0.45, 0.3 + 96 * uvPerPixel, 0.45 + 96 * uvPerPixel}};
    Check check = checkPacked(m, view, c.minified ? std::min(2, levels - 1) : 0, on(target));
    report(c.name, check);
    EXPECT_LE(check.worstRatio, 1.0);
}

INSTANTIATE_TEST_SUITE_P(
    Exec, PackedPath,
    testing::Combine(testing::Values(PackedCase{"albedo_roughness", kPackedAlbedoRoughness, false},
                                     PackedCase{"albedo_roughness_minified", kPackedAlbedoRoughness, true},
                                     PackedCase{"four_scalars", kPackedScalars, false},
                                     PackedCase{"four_scalars_minified", kPackedScalars, true},
                                     // Odd size, rotation off as in OddSizes.
                                     PackedCase{"odd_127x80", nullptr, false, R"({"tiling": 4, "rotation": 0})"},
                                     PackedCase{"odd_127x80_minified", nullptr, true, R"({"tiling": 4, "rotation": 0})"}),
                     testing::Values(vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl)),
    [](const auto& info) { return std::string(std::get<0>(info.param).name) + "_" + targetName(std::get<1>(info.param)); });

// ---- Weights ----------------------------------------------------------------------------------------------
// With falloffcontrast 0 the weights depend on the lattice alone. The GPU evaluates it in float32 on a uv that
// the rasteriser interpolated, so st and the skewed coordinates carry a few ulps of their size (|skewed| <= 4 |st|):
// the barycentrics are off by dw <= 4 * 4 ulp(|st|), and W_i = w_i^gamma / sum_j w_j^gamma moves by
// |dW_i| <= gamma * sum_j W_i |delta_ij - W_j| |dw_j| / w_j <= 2 gamma dw max_j(W_j / w_j), where W_j / w_j <= 2 for
// the three barycentrics of a triangle (largest at w = (1/2, 1/4, 1/4) for gamma = 7; 1 for gamma = 1).
// With falloffcontrast beta > 0 the metric's error e_m adds |dW_i| <= k * beta / (1 - beta) * e_m * 2 W_i (1 - W_i)
// <= k * beta / (1 - beta) * e_m / 2 (see pixelTolerance).
// The lattice weights of the material's first slot against the reference's, every pixel within one tolerance.
Check checkWeights(const Material& m, const View& view, const Draw& draw) {
    const Slot& slot = m.slots[0];
    double stMax = std::max(std::fabs(view.uvRect[2]), std::fabs(view.uvRect[3])) * std::max(slot.hex.tiling[0], slot.hex.tiling[1]);
    double ulp = std::ldexp(1.0, std::ilogb(stMax) - 23);
    double dw = 4 * 4 * ulp;
    double k = std::max(1.0, std::log2(1.0 / (1.0 - slot.hex.falloff)));
    double em = sampleError(0, slot.colorSpace == ColorSpace::Srgb);
    double tolerance = k * (2 * slot.hex.exponent * dw * 2) + k * slot.hex.falloffcontrast / (1 - slot.hex.falloffcontrast) * em / 2;
    Check check;
    check.errors = compare(draw(m, vk::RenderOutput::Weights, view), cpuRender(slot, view, reference::Output::Weights), 3);
    check.worstRatio = check.errors.max / tolerance;
    check.toleranceAtMax = check.maxTolerance = tolerance;
    return check;
}

// ---- Cases as data ------------------------------------------------------------------------------------------
// tests/execution/cases/<name>.json: a material (inline, its paths read from materials/ like the examples'), the view
// it is seen in, the targets it runs on and the tolerance rule it is held to; each file, on each of its targets, is one
// test, "<name>_<target>". A rule is one of the checks above, with its derivation:
//   falloff     checkColor: a colour or scalar slot, pixelTolerance (+ heightTolerance when height-blended)
//   histogram   checkHistogram: histogramTolerance
//   derivative  checkNormal: a normal slot's derivatives (or triplanar surface gradient)
//   weights     checkWeights: the blend weights
// A view is one of the named views above (magnified, minified, sphere, origin; the level each reads is fixed there) or
// {"width", "height", "uv": [u0, v0, u1, v1], "level": the deepest mip level it reads}.
const std::filesystem::path kCases = "tests/execution/cases";

struct ExecCase {
    std::string name;
    vk::ExecutedTarget target;
};
void PrintTo(const ExecCase& c, std::ostream* os) { *os << c.name << "_" << targetName(c.target); }

nlohmann::json readCase(const std::string& name) {
    std::ifstream in(kCases / (name + ".json"));
    return nlohmann::json::parse(in);
}

vk::ExecutedTarget executedTarget(const std::string& name) {
    if (name == "spirv") return vk::ExecutedTarget::Spirv;
    if (name == "hlsl") return vk::ExecutedTarget::Hlsl;
    if (name == "glsl") return vk::ExecutedTarget::Glsl;
    throw std::runtime_error("unknown target `" + name + "` (spirv, hlsl or glsl)");
}

// Every case file on each of its targets, in file name order.
std::vector<ExecCase> execCases() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(kCases))
        if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    std::vector<ExecCase> cases;
    for (const std::string& name : names) {
        const nlohmann::json c = readCase(name);
        for (const std::string target : c.at("targets")) cases.push_back({name, executedTarget(target)});
    }
    return cases;
}

std::pair<View, int> caseView(const nlohmann::json& v) {
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

Check checkCase(const nlohmann::json& c, const Material& m, vk::ExecutedTarget target) {
    const auto [view, level] = caseView(c.at("view"));
    const std::string rule = c.at("rule");
    if (rule == "falloff") return checkColor(m, view, level, on(target));
    if (rule == "histogram") return checkHistogram(m, view, level, on(target));
    if (rule == "derivative") return checkNormal(m, view, level, on(target));
    if (rule == "weights") return checkWeights(m, view, on(target));
    throw std::runtime_error("unknown rule `" + rule + "` (falloff, histogram, derivative or weights)");
}

class ExecutionCase : public testing::TestWithParam<ExecCase> {};

TEST_P(ExecutionCase, MatchesTheReferenceWithinItsRule) {
    REQUIRE_VULKAN();
    const ExecCase& param = GetParam();
    const nlohmann::json c = readCase(param.name);
    for (const auto& [key, value] : c.items())
        ASSERT_TRUE(key == "rule" || key == "view" || key == "targets" || key == "why" || key == "material") << "unknown key " << key;
    ParseResult r = parseMaterial(c.at("material").dump(), "materials/" + param.name + ".json");
    ASSERT_TRUE(r.material) << formatAll(r.diagnostics);
    const Check check = checkCase(c, *r.material, param.target);
    report(param.name.c_str(), check);
    EXPECT_LE(check.worstRatio, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Exec, ExecutionCase, testing::ValuesIn(execCases()),
                         [](const auto& info) { return info.param.name + "_" + targetName(info.param.target); });

// ---- 1-tap dithered hex tiling ---------------------------------------------------------------------------
// Each pixel samples one tile, picked by comparing its dither value u with the cumulative weights. Where u
// lies within the weights' own float32 error of a boundary (see checkWeights), GPU and reference may pick
// different tiles; those pixels are counted and left out. Everywhere else the same tile must be picked and
// its sample match within the single sample's filtering error.
TEST(OneTap, PicksTheSameTileAndSampleAsTheReference) {
    REQUIRE_VULKAN();
    struct OneTapCase {
        const char* name;
        const char* slot;
    };
    const OneTapCase cases[] = {
        {"color",
         R"({"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 4, "taps": 1, "falloff": 0.7}})"},
        {"normal",
         R"({"name": "normal", "kind": "normal", "texture": "textures/rock_normal.png", "hextiling": {"tiling": 4, "taps": 1, "exponent": 3}})"},
    };
    for (const OneTapCase& c : cases)
        for (auto target : {vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl}) {
            Material m = material(c.slot);
            const Slot& slot = m.slots[0];
            const bool normal = slot.kind == SlotKind::Normal;
            const View view = kMagnified;
            Image value =
                vk::render(*runner(&whyNoVulkan), m, normal ? vk::RenderOutput::Derivative : vk::RenderOutput::Albedo, "", view, target);
            Image weights = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Weights, "", view, target);
            reference::SampledTexture tex = sampled(slot);
            std::vector<reference::SlotResult> ref = reference::evaluateView(slot, tex, view);
            TextureBounds b = bounds(tex);
            double es = sampleError(0, slot.colorSpace == ColorSpace::Srgb);
            double tolerance = normal ? 2 * sampleError(0, false) * (1 + b.maxDeriv) / b.minZ : es;
            double stMax = std::max(view.uvRect[2], view.uvRect[3]) * slot.hex.tiling[0];
            double k = std::max(1.0, std::log2(1.0 / (1.0 - slot.hex.falloff)));
            double epsilon = k * 2 * slot.hex.exponent * 16 * std::ldexp(1.0, std::ilogb(stMax) - 23) * 2;
            size_t ambiguous = 0, compared = 0;
            double worst = 0;
            for (int j = 0; j < view.height; ++j)
                for (int i = 0; i < view.width; ++i) {
                    size_t p = size_t(j) * view.width + i;
                    double u = view.uvRect[0] + (i + 0.5) / view.width * (view.uvRect[2] - view.uvRect[0]);
                    double v = view.uvRect[1] + (j + 0.5) / view.height * (view.uvRect[3] - view.uvRect[1]);
                    reference::Triangle tri = reference::lattice({u * slot.hex.tiling[0], v * slot.hex.tiling[1]}, slot.hex.mode);
                    auto W = reference::blendWeights(tri.weight, {1, 1, 1}, slot.hex);
                    double d = reference::ditherValue({uint32_t(i), uint32_t(j)});
                    if (std::min(std::fabs(d - W[0]), std::fabs(d - W[0] - W[1])) < epsilon) {
                        ++ambiguous;
                        continue;
                    }
                    ++compared;
                    for (int ch = 0; ch < 3; ++ch)
                        ASSERT_EQ(weights.rgba[p * 4 + ch], float(ref[p].weights[size_t(ch)])) << c.name << " pixel " << i << "," << j;
                    for (int ch = 0; ch < (normal ? 2 : 3); ++ch)
                        worst = std::max(worst, std::fabs(value.rgba[p * 4 + ch] - ref[p].value[size_t(ch)]) / tolerance);
                }
            std::printf("  1-tap %-6s %-5s: %zu pixels compared, %zu at a dither boundary left out; worst error/tolerance %.2f\n", c.name,
                        targetName(target).c_str(), compared, ambiguous, worst);
            EXPECT_LE(worst, 1.0);
            EXPECT_LT(ambiguous, compared / 100);
        }
}

// Texture fetches in the first slot's `value` shader, counted in its SPIR-V.
size_t fetches(Material m) {
    m.templ = TemplateRef::builtin("value");
    CompileResult r = compile(m);
    if (!r.ok()) throw std::runtime_error(formatAll(r.diagnostics));
    return size_t(countOps(disassemble(r.spirv)).textureSamples);
}

TEST(OneTap, SamplesOncePerSlot) {
    EXPECT_EQ(fetches(material(R"({"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"taps": 1}})")),
              1u);
}

// Adaptive taps: each of the three fetches sits in a block that a conditional branch leads to, so a GPU with real
// branches skips it; the optimiser must not have turned the branches into selects around unconditional fetches.
TEST(AdaptiveTaps, EachFetchIsBehindABranch) {
    for (const char* kind : {"color", "normal"}) {
        Material m = material(std::string(R"({"name": "s", "kind": ")") + kind + R"(", "texture": "textures/rock_)" +
                              (kind == std::string("color") ? "albedo" : "normal") + R"(.png", "hextiling": {"taps": "adaptive"}})");
        m.templ = TemplateRef::builtin("value");
        CompileResult r = compile(m);
        ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
        std::istringstream text(disassemble(r.spirv));
        std::string line, block;
        std::set<std::string> branchedTo;
        std::vector<std::string> sampledIn;
        while (std::getline(text, line)) {
            std::istringstream words(line);
            std::string first, second, third;
            words >> first >> second >> third;
            if (third == "OpLabel") block = first;
            if (first == "OpBranchConditional") {
                std::string other;
                words >> other;
                branchedTo.insert(third);
                branchedTo.insert(other);
            }
            if (line.find("OpImageSample") != std::string::npos) sampledIn.push_back(block);
        }
        EXPECT_EQ(sampledIn.size(), 3u) << kind;
        for (const std::string& b : sampledIn)
            EXPECT_TRUE(branchedTo.count(b)) << kind << ": a fetch in block " << b << " runs unconditionally";
    }
}

// What each variant fetches per pixel, counted in the SPIR-V: the checker mask's two taps, the height map's
// fetch per tap, three planes of three taps for triplanar.
TEST(Variants, FetchWhatTheyDocument) {
    const std::string albedo = R"({"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": )";
    const std::string height = R"(, {"name": "height", "kind": "scalar", "texture": "textures/rock_height.png"})";
    struct Expect {
        std::string slots, hextiling;
        size_t samples;
    };
    const Expect cases[] = {
        {albedo + R"({"mask": "checker"}})", "{}", 2},
        {albedo + R"({"mask": "checker", "taps": 1}})", "{}", 1},
        {albedo + R"({"mask": "noise3"}})", "{}", 3},
        {albedo + R"({}, "height_blend": {"slot": "height"}})" + height, "{}", 6},
        {albedo + R"({"mask": "checker"}, "height_blend": {"slot": "height"}})" + height, "{}", 4},
        {albedo + "{}}", R"({"projection": "triplanar"})", 9},
    };
    for (const Expect& e : cases) EXPECT_EQ(fetches(material(e.slots, e.hextiling)), e.samples) << e.slots << " " << e.hextiling;
}

// ---- Properties of the GPU output ----------------------------------------------------------------------------
// The final weights are a normalisation W_i = a_i / (a_1 + a_2 + a_3): the sum and the division each round once
// (2^-24 relative), so |sum_i W_i - 1| <= 3 * 2 * 2^-24 for the three quotients plus 2 * 2^-24 for adding them up.
// Lavapipe divides with a reciprocal refined to full precision; 8 * 2^-24 = 4.8e-7 is the bound.
TEST(Properties, WeightsAreFiniteNonNegativeAndSumToOne) {
    REQUIRE_VULKAN();
    const char* settings[] = {R"({"tiling": 4})",
                              R"({"tiling": 4, "falloff": 0.01})",
                              R"({"tiling": 4, "falloff": 0.99})",
                              R"({"tiling": 4, "exponent": 1})",
                              R"({"tiling": 4, "exponent": 64})",
                              R"({"tiling": 4, "falloffcontrast": 0.9})",
                              R"({"tiling": 4, "rotation": 20})",  // the largest accepted: 20 x 180 degrees = 3600
                              R"({"tiling": 4, "mode": "paper", "falloff": 0.8})"};
    const double bound = 8 * std::ldexp(1.0, -24);
    double worst = 0;
    for (const char* h : settings) {
        Material m =
            material(std::string(R"({"name": "a", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": )") + h + "}");
        Image w = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Weights, "", {128, 128, {0.1, 0.2, 0.6, 0.7}});
        for (size_t i = 0; i < w.rgba.size(); i += 4) {
            const float* p = &w.rgba[i];
            ASSERT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) << h;
            ASSERT_TRUE(p[0] >= 0 && p[1] >= 0 && p[2] >= 0) << h;
            worst = std::max(worst, std::fabs(double(p[0]) + p[1] + p[2] - 1.0));
        }
    }
    std::printf("  weights: largest |sum - 1| %.2e, bound %.2e\n", worst, bound);
    EXPECT_LE(worst, bound);
}

// No seams: between neighbouring pixels the colour may change only as much as the texture's own content and the
// weights allow. Each tile's sample moves by s texels (s = texels per pixel; rotation keeps lengths), which
// changes a bilinear sample by at most step * s * sqrt(2) (step: the largest difference of adjacent texels). The
// weights change by dW (measured on the GPU's weights output of the same view), which moves the blend by at most
// sum_j |dW_j| / 2 * spread (the dW sum to 0). Each pixel also carries its own filtering error e_s.
// A seam (a wrong mip level or offset at a tile border) breaks this.
TEST(Properties, NoSeamsBetweenNeighbouringPixels) {
    REQUIRE_VULKAN();
    for (const char* tex : {"textures/rock_albedo.png", "textures/tiles_albedo.png"}) {
        Material m = material(std::string(R"({"name": "albedo", "kind": "color", "colorspace": "linear", "texture": ")") + tex +
                              R"(", "hextiling": {"tiling": 4, "falloff": 0.8}})");
        const View view{128, 128, {0.2, 0.3, 0.2 + 128.0 / 1024, 0.3 + 128.0 / 1024}};  // s = 1 texel per pixel
        Image c = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Albedo, "", view);
        Image w = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Weights, "", view);
        TextureBounds b = bounds(sampled(m.slots[0]));
        double es = sampleError(0, false), worstRatio = 0;
        for (int y = 0; y < view.height; ++y)
            for (int x = 0; x < view.width; ++x)
                for (auto [nx, ny] : {std::pair{x + 1, y}, std::pair{x, y + 1}}) {
                    if (nx >= view.width || ny >= view.height) continue;
                    double dW = 0, dC = 0;
                    for (int i = 0; i < 3; ++i) {
                        dW += std::fabs(double(w.at(x, y)[i]) - w.at(nx, ny)[i]);
                        dC = std::max(dC, std::fabs(double(c.at(x, y)[i]) - c.at(nx, ny)[i]));
                    }
                    double allowed = b.step * 1.0 * std::sqrt(2.0) + dW / 2 * b.spread + 2 * es;
                    worstRatio = std::max(worstRatio, dC / allowed);
                }
        std::printf("  %s: largest neighbour difference / allowed %.2f (step %.3f, spread %.3f)\n", tex, worstRatio, b.step, b.spread);
        EXPECT_LE(worstRatio, 1.0) << tex;
    }
}

// r = 0.5 is the gain's identity. Against r = 0.5 + 2^-20: k - 1 = log2(1 / (1 - r)) - 1 ~ 2^-20 * 2 / ln 2 = 2.8e-6,
// and |d g / d k| = |0.5 (2x)^k ln(2x)| <= 0.5 / e, so each weight moves by <= 0.18 * 2.8e-6 = 5e-7, doubled by the
// renormalisation, and the blend of values in [0, 1] by <= 3e-6. The gain's own float32 rounding (pow, division)
// adds a few ulps of 1; 1e-5 bounds both.
TEST(Properties, GainAtOneHalfChangesNothing) {
    REQUIRE_VULKAN();
    const View view{96, 96, {0.3, 0.45, 0.4, 0.55}};
    auto albedo = [&](double r) {
        char slot[256];
        std::snprintf(
            slot, sizeof slot,
            R"({"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 4, "falloff": %.17g}})",
            r);
        return vk::render(*runner(&whyNoVulkan), material(slot), vk::RenderOutput::Albedo, "", view);
    };
    Errors e = compare(albedo(0.5), albedo(0.5 + std::ldexp(1.0, -20)), 4);
    std::printf("  r = 0.5 against r = 0.5 + 2^-20: max %.2e, bound 1e-5\n", e.max);
    EXPECT_LE(e.max, 1e-5);
    EXPECT_GT(compare(albedo(0.5), albedo(0.75), 4).max, 1.0 / 255);  // and the gain does act when asked
}

// A ramp normal map: every texel encodes the same derivative (a, b) = (dH/du, dH/dy), y = -v (a green-up map), the
// height field H = a u - b v. Inside a tile rotated by theta (sample point R^T (uv - c) + offset) the height seen is
// H(R^T uv + ...), whose (u, v) gradient is R (a, -b); in (u, y) that is F R F (a, b) = R^T (a, b) with
// F = diag(1, -1): the blended derivative must be (a, b) rotated by minus the tile's angle. Checked where one tile's weight
// exceeds 0.999 (the others can move the result by at most 2 * 0.001 * |(a, b)|), with theta from the mode's
// definition (reference::tileTransform). Stored as float texels: sampling adds no error.
TEST(Properties, RampNormalMapRotatesWithEachTile) {
    REQUIRE_VULKAN();
    const double a = 0.5, b = -0.25;
    std::filesystem::path file = std::filesystem::temp_directory_path() / "hexc_ramp_normal.pfm";
    Image ramp;
    ramp.width = ramp.height = 16;
    ramp.rgba.clear();
    for (int i = 0; i < 16 * 16; ++i) ramp.rgba.insert(ramp.rgba.end(), {float(0.5 - 0.25 * a), float(0.5 - 0.25 * b), 0.75f, 1.0f});
    writeImage(ramp, file);  // n = (-a, -b, 1) / 2 encoded n * 0.5 + 0.5: Listing 9 reads back d = (a, b)
    // Per-tile scale s: the tile shows H(p / s), so its slope is R(-theta)(a, b) / s.
    for (const char* mode :
         {R"("mode": "stable")", R"("mode": "paper")", R"("scalerange": [0.5, 2], "rotationrange": [0, 360], "rotationsteps": 6)"}) {
        Material m = material(std::string(R"({"name": "normal", "kind": "normal", "texture": ")") + file.string() +
                              R"(", "hextiling": {"tiling": 1, )" + mode + "}}");
        const View view{128, 128, {0.0, 0.0, 1.0, 1.0}};
        Image d = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Derivative, "", view);
        std::vector<reference::SlotResult> ref = reference::evaluateView(m.slots[0], sampled(m.slots[0]), view);
        double worst = 0;
        size_t checked = 0;
        for (int j = 0; j < view.height; ++j)
            for (int i = 0; i < view.width; ++i) {
                const reference::SlotResult& r = ref[size_t(j) * view.width + i];
                reference::Triangle tri = reference::lattice({(i + 0.5) / view.width, (j + 0.5) / view.height}, m.slots[0].hex.mode);
                size_t dominant = std::max_element(r.blend.begin(), r.blend.end()) - r.blend.begin();
                if (r.blend[dominant] < 0.999) continue;
                reference::TileTransform tile = reference::tileTransform(tri.id[dominant], m.slots[0].hex);
                double theta = tile.angle;
                double ex = (std::cos(theta) * a + std::sin(theta) * b) / tile.scale,
                       ey = (-std::sin(theta) * a + std::cos(theta) * b) / tile.scale;
                worst = std::max({worst, std::fabs(d.at(i, j)[0] - ex), std::fabs(d.at(i, j)[1] - ey)});
                ++checked;
            }
        // The other tiles' share (< 0.001) moves the result by at most 0.001 times the largest difference of two
        // tiles' slopes, 2 |(a, b)| / min scale; 1e-5: float32 sin/cos and products.
        double bound = 2 * 0.001 * std::hypot(a, b) / m.slots[0].hex.scaleRange[0] + 1e-5;
        std::printf("  ramp (%s): %zu pixels inside tiles, largest |d - R(-theta)(a, b)| %.2e, bound %.2e\n", mode, checked, worst, bound);
        EXPECT_GT(checked, size_t(view.width * view.height / 4));
        EXPECT_LE(worst, bound) << mode;
    }
}

// An analytic height field h(s, t) (periodic, slopes up to about 1.2), given as a height texture and as normal maps
// in both green conventions, each with its documented flip_y. Inside the tiles, the blended derivative must be the
// derivative of the hex-tiled height (the same lattice and weights: falloffcontrast 0), whatever the tile's
// rotation, and the two conventions must give one image. Derivatives are (dH/du, dH/dy) with y up the texture
// (y = -v), the convention of a green-up map and of the tangent frame the templates use.
namespace analytic {
const double kTwoPi = 2 * 3.14159265358979323846;
double h(double s, double t) { return (0.6 * std::sin(kTwoPi * s) * std::cos(kTwoPi * t) + 0.3 * std::sin(kTwoPi * (s + 2 * t))) / kTwoPi; }
double hs(double s, double t) { return 0.6 * std::cos(kTwoPi * s) * std::cos(kTwoPi * t) + 0.3 * std::cos(kTwoPi * (s + 2 * t)); }
double ht(double s, double t) { return -0.6 * std::sin(kTwoPi * s) * std::sin(kTwoPi * t) + 0.6 * std::cos(kTwoPi * (s + 2 * t)); }

// texel(s, t) at each texel centre (row 0 at t = 0, the top), written as a width x height float texture.
std::filesystem::path write(const std::string& name, int width, int height,
                            const std::function<std::array<float, 4>(double, double)>& texel) {
    Image image;
    image.width = width;
    image.height = height;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            auto v = texel((x + 0.5) / width, (y + 0.5) / height);
            image.rgba.insert(image.rgba.end(), v.begin(), v.end());
        }
    std::filesystem::path file = std::filesystem::temp_directory_path() / name;
    writeImage(image, file);
    return file;
}

// A width x height normal map of h whose green axis points up the texture (greenUp) or down it, encoded n * 0.5 + 0.5
// with n = (-dh/dx, -dh/dy, 1) / 2 (Listing 9 divides by z, so n need not be unit length). Its slopes are per unit of
// texel-isotropic space, x = s * width / height and y = t, as a baker writes them with square texels.
std::filesystem::path normalMap(bool greenUp, int width, int height) {
    const std::string name =
        std::string(greenUp ? "hexc_analytic_green_up_" : "hexc_analytic_green_down_") + std::to_string(width) + ".pfm";
    const double aspect = double(width) / height;
    return write(name, width, height, [&](double s, double t) {
        double dy = greenUp ? -ht(s, t) : ht(s, t);
        return std::array<float, 4>{float(0.5 - 0.25 * hs(s, t) / aspect), float(0.5 - 0.25 * dy), 0.75f, 1.0f};
    });
}
}  // namespace analytic

struct AnalyticCase {
    const char* name;
    const char* settings;
    int width = 256, height = 256;  // of the textures
};

class AnalyticNormals : public testing::TestWithParam<std::tuple<AnalyticCase, vk::ExecutedTarget>> {};

TEST_P(AnalyticNormals, MatchTheDerivativeOfTheHexTiledHeight) {
    REQUIRE_VULKAN();
    const auto [which, target] = GetParam();
    const char* settings = which.settings;
    const int tw = which.width, th = which.height;
    const double aspect = double(tw) / th;
    std::filesystem::path height = analytic::write("hexc_analytic_height_" + std::to_string(tw) + ".pfm", tw, th, [](double s, double t) {
        float v = float(analytic::h(s, t));
        return std::array<float, 4>{v, v, v, 1.0f};
    });
    const std::string hex = std::string(R"("hextiling": {"tiling": 1, "falloffcontrast": 0, )") + settings + "}";
    auto slot = [&](const char* kind, const std::filesystem::path& file, const char* extra) {
        return material(std::string(R"({"name": "s", "kind": ")") + kind + R"(", "colorspace": "linear", "texture": ")" + file.string() +
                        "\", " + extra + hex + "}");
    };
    // One texel a pixel over two texture periods.
    const View view{2 * tw, 2 * th, {0.0, 0.0, 2.0, 2.0}};
    vk::Runner& gpu = *runner(&whyNoVulkan);
    Image up = vk::render(gpu, slot("normal", analytic::normalMap(true, tw, th), R"("flip_y": false, )"), vk::RenderOutput::Derivative, "",
                          view, target);
    Image down = vk::render(gpu, slot("normal", analytic::normalMap(false, tw, th), R"("flip_y": true, )"), vk::RenderOutput::Derivative,
                            "", view, target);
    Image H = vk::render(gpu, slot("scalar", height, ""), vk::RenderOutput::Albedo, "", view, target);
    Image W = vk::render(gpu, slot("scalar", height, ""), vk::RenderOutput::Weights, "", view, target);
    // Both conventions decode to the same derivative up to the float32 rounding of their texels: 0.5 - x and 0.5 + x
    // round with different ulps (2^-25 below 0.5, 2^-24 above), so the decoded greens differ by up to 2 * 2^-24 +
    // 2^-23 = 2.4e-7, and d = -n / z with z = 0.5 doubles it; filtering is a convex combination (no growth), and the
    // rotation and blend add a few float32 ulps of |d| <= 1.5. 1e-6.
    EXPECT_LE(compare(up, down, 2).max, 1e-6);
    // The derivative is in texel-isotropic space (x = s * aspect, y = -t), where the tiles turn: compared with H's
    // gradient there, (dH/ds / aspect, -dH/dt). Checked at pixels where one tile's weight is >= 0.9999 there and at the
    // four neighbours the central difference reads. Tolerance, per component, T = a texel (and a pixel step) in that
    // space, 1 / height (whose derivatives of h are those in st or, along x, smaller by the aspect); for T = 1/256:
    // - H is filtered bilinearly: its slope at a point is that of the interpolant, off by at most (T / 2) max|h''|, and
    //   max|h''| = 2 pi * 1.8 (h_tt), so 11.3 / 512 = 0.022 (the central difference averages it but, in a rotated
    //   tile, need not cancel it);
    // - lavapipe quantises bilinear weights to 8 bits (error <= 1/512 per axis, two axes) of texel differences
    //   <= T max|h'| = 1.5 T: H is off by <= 1.2e-5 T per sample, its central difference by <= 0.0025;
    // - the normal map's filtered slopes: (T^2 / 8) max|h'''| (118) = 2.3e-4, and the 8-bit weights 2 * 11.3 T / 512 =
    //   1.7e-4;
    // - the other tiles (weights <= 1e-4 at all five pixels): in H's difference <= 2 * 1e-4 * 2 max|h| (0.29) / 2T =
    //   0.0074, in the derivative <= 1e-4 * 2 max|grad h| (3.0) = 3e-4;
    // - float32 H (ulp 1.5e-8) over 2T: 4e-6.
    // Sum 0.033, plus 0.002.
    const double T = 1.0 / th;
    const double bound =
        T / 2 * 11.3 + 0.0025 + T * T / 8 * 118 + 2 * 11.3 * T / 512 + 0.0074 / (256 * T) + 3e-4 + 4e-6 / (256 * T) + 0.002;
    const double stepS = 2.0 / view.width, stepT = 2.0 / view.height;
    auto pure = [&](int i, int j, int c) { return W.at(i, j)[c] >= 0.9999f; };
    std::vector<double> errors;
    for (int j = 1; j + 1 < view.height; ++j)
        for (int i = 1; i + 1 < view.width; ++i) {
            const float* w = W.at(i, j);
            int c = int(std::max_element(w, w + 3) - w);
            if (!pure(i, j, c) || !pure(i - 1, j, c) || !pure(i + 1, j, c) || !pure(i, j - 1, c) || !pure(i, j + 1, c)) continue;
            double du = (H.at(i + 1, j)[0] - H.at(i - 1, j)[0]) / (2 * stepS), dv = (H.at(i, j + 1)[0] - H.at(i, j - 1)[0]) / (2 * stepT);
            errors.push_back(std::max(std::fabs(up.at(i, j)[0] - du / aspect), std::fabs(up.at(i, j)[1] + dv)));
        }
    ASSERT_GT(errors.size(), size_t(view.width * view.height / 8));
    std::sort(errors.begin(), errors.end());
    std::printf("  %s: %zu pixels inside tiles, |d - grad H|: median %.4f, max %.4f (bound %.3f)\n", settings, errors.size(),
                errors[errors.size() / 2], errors.back(), bound);
    EXPECT_LE(errors.back(), bound);
}

INSTANTIATE_TEST_SUITE_P(
    Exec, AnalyticNormals,
    testing::Combine(testing::Values(AnalyticCase{"stable", R"("mode": "stable", "rotation": 1)"},
                                     AnalyticCase{"paper", R"("mode": "paper", "rotation": 1)"},
                                     AnalyticCase{"unrotated", R"("mode": "stable", "rotation": 0)"},
                                     AnalyticCase{"checker2taps", R"("mode": "stable", "rotation": 1, "mask": "checker", "taps": 2)"},
                                     // Non-square: the tiles turn its texels (the paper's mode turns st and would shear it).
                                     AnalyticCase{"stable_300x170", R"("mode": "stable", "rotation": 1)", 300, 170},
                                     AnalyticCase{"turned_60_to_120_300x170", R"("rotationrange": [60, 120])", 300, 170}),
                     testing::Values(vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl)),
    [](const auto& info) { return std::string(std::get<0>(info.param).name) + "_" + targetName(std::get<1>(info.param)); });

// ---- hexc render and hexc preview, run as a user would ------------------------------------------------------

TEST(RenderCommand, WritesWhatTheLibraryRenders) {
    REQUIRE_VULKAN();
    std::filesystem::path dir = std::filesystem::temp_directory_path();
    ASSERT_EQ(
        runHexc("render materials/rock.json --output derivative --size 40x24 --uv-rect 0.1,0.2,0.3,0.35 -o " + (dir / "r.pfm").string()),
        0);
    ASSERT_EQ(runHexc("render materials/rock.json --output derivative --size 40x24 --uv-rect 0.1,0.2,0.3,0.35 --reference -o " +
                      (dir / "c.pfm").string()),
              0);
    Material rock = *parseMaterialFile("materials/rock.json").material;
    const View view{40, 24, {0.1, 0.2, 0.3, 0.35}};
    Image lib = vk::render(*runner(&whyNoVulkan), rock, vk::RenderOutput::Derivative, "", view);
    Texture gpu = loadTexture(dir / "r.pfm", false), cpu = loadTexture(dir / "c.pfm", false);
    ASSERT_EQ(gpu.width, 40);
    ASSERT_EQ(gpu.height, 24);
    Image ref = reference::render(rock.slots[1], sampled(rock.slots[1]), view, reference::Output::Value);
    for (size_t i = 0; i < lib.rgba.size(); i += 4)
        for (size_t c = 0; c < 3; ++c) {  // PFM holds RGB
            ASSERT_EQ(gpu.rgba32f[i + c], lib.rgba[i + c]) << i;
            ASSERT_EQ(cpu.rgba32f[i + c], ref.rgba[i + c]) << i;
        }
}

TEST(RenderCommand, Errors) {
    std::string err;
    EXPECT_EQ(runHexc("render materials/rock.json --slot bark -o /tmp/x.png", &err), 2);
    EXPECT_EQ(runHexc("render materials/rock.json --output albedo --slot bark -o /tmp/x.png", &err), 1);
    EXPECT_EQ(err, "hexc: material `rock` has no slot `bark`\n");
    EXPECT_EQ(runHexc("render materials/rock.json --output derivative --slot albedo -o /tmp/x.png", &err), 1);
    EXPECT_EQ(err, "hexc: slot `albedo` is of kind color; this output needs a normal slot\n");
    EXPECT_EQ(runHexc("render materials/rock.json --size 0x5 -o /tmp/x.png", &err), 2);
    EXPECT_EQ(runHexc("render materials/rock.json --uv-rect 0,0,1 -o /tmp/x.png", &err), 2);
    EXPECT_EQ(err, "hexc: --uv-rect expects 4 finite numbers, got `0,0,1`\n");
    EXPECT_EQ(runHexc("render materials/rock.json --uv-rect 0,0,1,nan -o /tmp/x.png", &err), 2);
    EXPECT_EQ(err, "hexc: --uv-rect expects 4 finite numbers, got `0,0,1,nan`\n");
    EXPECT_EQ(runHexc("render materials/rock.json --output albedoo -o /tmp/x.png", &err), 2);
    EXPECT_EQ(err, "hexc: --output: albedoo not in {shaded,albedo,normal,derivative,weights} (see hexc render --help)\n");
    EXPECT_EQ(runHexc("preview materials/rock.json --cell 10 -o /tmp/x.png", &err), 2);
    EXPECT_EQ(err, "hexc: --cell: Value 10 not in range 32 to 2048 (see hexc preview --help)\n");
    EXPECT_EQ(runHexc("render materials/rock.json -o /tmp/x.tiff", &err), 2);  // refused before rendering
    EXPECT_EQ(err, "hexc: -o /tmp/x.tiff: hexc render writes .pfm or .png\n");
    EXPECT_EQ(runHexc("render materials/invalid/falloff_zero.json -o /tmp/x.png", &err), 1);
    EXPECT_EQ(runHexc("render materials/rock_triplanar.json --output normal -o /tmp/x.png", &err), 1);
    EXPECT_EQ(err, "hexc: slot `normal` is triplanar: it returns a world-space surface gradient; use the derivative output\n");
    // A template with resources of its own cannot be drawn without them (it crashed lavapipe): shaded with the
    // built-in lit, named in a note (tests/cli/preview_test.cpp); its slots as they are.
    EXPECT_EQ(runHexc("render materials/engine_rock.json --size 16x16 -o /tmp/x.png", &err), 0);
    EXPECT_NE(err.find("declares resources of its own (Frame, Object, Push, shadowMap"), std::string::npos) << err;
    EXPECT_EQ(runHexc("render materials/engine_rock.json --output albedo --size 16x16 -o /tmp/x.png", &err), 0) << err;
}

// A PNG whose header and chunks are sound (so the material validates and compiles) but whose image data does not
// decode: render reports the texture, exit 1 (bad input), and writes nothing.
TEST(RenderCommand, ATextureThatDoesNotDecodeIsBadInput) {
    std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_bad_texture";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::ifstream in("materials/textures/rock_albedo.png", std::ios::binary);
    std::string png((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t idat = png.find("IDAT");
    ASSERT_NE(idat, std::string::npos);
    std::fill(png.begin() + long(idat + 14), png.begin() + long(idat + 2014), '\xff');  // inside the deflate stream
    std::ofstream(dir / "bad.png", std::ios::binary) << png;
    std::ofstream(dir / "m.json")
        << R"({"name": "bad", "template": "unlit", "slots": [{"name": "albedo", "kind": "color", "texture": "bad.png"}]})";
    std::string err;
    EXPECT_EQ(runHexc((dir / "m.json").string() + " -q -o " + (dir / "out").string(), &err), 0) << err;
    EXPECT_EQ(runHexc("render " + (dir / "m.json").string() + " -o " + (dir / "x.png").string(), &err), 1) << err;
    EXPECT_NE(err.find("bad.png: "), std::string::npos) << err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

// No Vulkan device (the loader pointed at a driver manifest that does not exist) is its own exit code, 4, for
// render and preview alike, and nothing is written.
TEST(RenderCommand, NoVulkanDeviceExitsFour) {
    const std::string noDriver = "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json";
    std::filesystem::path out = std::filesystem::temp_directory_path() / "hexc_no_vulkan.png";
    std::filesystem::remove(out);
    std::string err;
    EXPECT_EQ(runHexc("render materials/rock.json -o " + out.string(), &err, noDriver), 4) << err;
    EXPECT_NE(err.find("hexc: no Vulkan device: "), std::string::npos) << err;
    EXPECT_EQ(runHexc("preview materials/rock.json -o " + out.string(), &err, noDriver), 4) << err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

// The reference of a height-blended slot reads its height slot (without it, the reference refuses to evaluate).
TEST(RenderCommand, ReferenceOfAHeightBlendedSlot) {
    std::filesystem::path file = std::filesystem::temp_directory_path() / "hb_cpu.pfm";
    ASSERT_EQ(
        runHexc("render materials/rock_blend.json --output albedo --size 32x32 --uv-rect 0.1,0.2,0.2,0.3 --reference -o " + file.string()),
        0);
    Material m = *parseMaterialFile("materials/rock_blend.json").material;
    const reference::Heights heights(m, m.slots[0]);
    ASSERT_NE(heights.source(), nullptr);
    Image ref =
        reference::render(m.slots[0], sampled(m.slots[0]), {32, 32, {0.1, 0.2, 0.2, 0.3}}, reference::Output::Value, heights.source());
    Texture cpu = loadTexture(file, false);
    for (size_t i = 0; i < ref.rgba.size(); i += 4)
        for (size_t c = 0; c < 3; ++c) ASSERT_EQ(cpu.rgba32f[i + c], ref.rgba[i + c]) << i;  // PFM holds RGB
}

TEST(PreviewCommand, WritesALabelledSheet) {
    REQUIRE_VULKAN();
    std::filesystem::path out = std::filesystem::temp_directory_path() / "hexc_preview.png";
    std::filesystem::remove(out);
    ASSERT_EQ(runHexc("preview materials/rock.json --cell 64 -o " + out.string()), 0);
    Texture sheet = loadTexture(out, false);
    EXPECT_EQ(sheet.width, 4 * 64);  // plain, falloff, histogram, weights
    EXPECT_EQ(sheet.height, 2 * (64 + 28));
}

}  // namespace
