// Execution tests case by case: the cases as data (tests/execution/cases/) and the tables of odd-sized textures,
// adaptive taps and packed textures, each on every executed target against the fp64 CPU reference.
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
#include "execution/checks.h"

using namespace hexc;
using namespace hexc::exec;
using hexc::test::runHexc;
using hexc::test::runner;

namespace {

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

}  // namespace
