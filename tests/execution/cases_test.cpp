// Execution tests case by case, each table of cases a folder of data (checks.h, "Cases as data"): the cases of
// tests/execution/cases/, odd-sized textures (odd_sizes/), adaptive taps (adaptive/) and packed textures (packed/),
// each on its targets against the fp64 CPU reference.
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
// A case: "size" [width, height], "minified", "blend" (histogram: its Gaussian texture has the odd size, its table
// odd levels), "lod" (shared: the level from sqrt(width * height), between two levels here).
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

// A slot's JSON text, its texture "CROP_<w>x<h>" replaced by that crop of the rock albedo (cropOfRock).
std::string withCrop(nlohmann::json slot) {
    int width = 0, height = 0;
    if (std::sscanf(slot.at("texture").get<std::string>().c_str(), "CROP_%dx%d", &width, &height) == 2)
        slot["texture"] = cropOfRock(width, height).string();
    return slot.dump();
}

// A view of 96 x 96 pixels at (0.3, 0.45) of a texture `larger` texels across under `tiling`: magnified, 0.75 texel
// per pixel (level 0), or minified, 4 (level 2, or the last level of a shorter chain). Returns it and its level.
std::pair<View, int> cropView(int larger, double tiling, bool minified) {
    const double uvPerPixel = (minified ? 4.0 : 0.75) / (tiling * larger);
    const int levels = std::bit_width(unsigned(larger));
    return {View{96, 96, {0.3, 0.45, 0.3 + 96 * uvPerPixel, 0.45 + 96 * uvPerPixel}}, minified ? std::min(2, levels - 1) : 0};
}

class OddSizes : public testing::TestWithParam<ExecCase> {};

TEST_P(OddSizes, MatchReference) {
    REQUIRE_VULKAN();
    const nlohmann::json c = readCase(GetParam(), {"size", "minified", "blend", "lod"});
    const int width = c.at("size")[0], height = c.at("size")[1];
    const bool histogram = c.at("blend") == "histogram";
    const Material m =
        material(withCrop({{"name", "albedo"},
                           {"kind", "color"},
                           {"colorspace", "linear"},
                           {"texture", "CROP_" + std::to_string(width) + "x" + std::to_string(height)},
                           {"hextiling", {{"tiling", 4}, {"rotation", 0}, {"blend", c.at("blend")}, {"lod", c.at("lod")}}}}));
    const auto [view, level] = cropView(std::max(width, height), 4.0, c.at("minified"));
    const double es = sampleError(level, false);
    const vk::ExecutedTarget target = GetParam().target;
    Check check = histogram ? checkHistogram(m, view, level, on(target))
                            : checkAgainstReference(m, vk::RenderOutput::Albedo, view, level, on(target), es, es, 4);
    report(GetParam().name.c_str(), check);
    EXPECT_LE(check.worstRatio, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Exec, OddSizes, testing::ValuesIn(execCases("tests/execution/odd_sizes")), caseTestName);

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
Material adaptiveMaterial(const nlohmann::json& c, bool adaptive) {
    nlohmann::json slot = c.at("slots").at(0);
    if (adaptive) slot["hextiling"]["taps"] = "adaptive";
    return material(withCrop(slot));
}

class AdaptiveTaps : public testing::TestWithParam<ExecCase> {};

TEST_P(AdaptiveTaps, FetchLikeTheReferenceAndStayWithinTheBoundOfThreeTaps) {
    REQUIRE_VULKAN();
    const nlohmann::json c = readCase(GetParam(), {"slots", "minified"});
    const vk::ExecutedTarget target = GetParam().target;
    const char* name = GetParam().name.c_str();
    const Material m = adaptiveMaterial(c, true), exact = adaptiveMaterial(c, false);
    const Slot& slot = m.slots[0];
    const bool normal = kindRow(slot.kind).derivative;
    const bool minified = c.at("minified");
    const View view = minified ? kMinified : kMagnified;
    const int level = minified ? 2 : 0;
    const reference::SampledTexture tex = sampled(slot);
    const TextureBounds b = bounds(tex);
    const double e = HexTiling::kAdaptiveError, spread = normal ? 2 * std::sqrt(2.0) * b.maxDeriv : b.spread;
    // As checkColor and checkNormal.
    const double es = sampleError(level, slot.colorSpace == ColorSpace::Srgb),
                 ed = 2 * sampleError(level, false) * (1 + b.maxDeriv) / b.minZ;
    const double ex = normal ? ed : es, em = normal ? std::sqrt(2.0) * ed : es;
    const int channels = normal ? 2 : kindRow(slot.kind).oneChannel ? 1 : 4;

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
    std::printf("  %-28s %-5s: fetches per pixel %.3f (reference %.3f), %zu pixels fetch other taps\n", name, targetName(target).c_str(),
                gpuFetches / n, refFetches / n, different);
    EXPECT_LE(different, ref.size() / 100);
    EXPECT_LT(gpuFetches / n, 3.0);  // something is skipped

    // 2. The value against the adaptive reference.
    const int blended = kindRow(slot.kind).oneChannel ? 1 : channels;
    const vk::RenderOutput output = normal ? vk::RenderOutput::Derivative : vk::RenderOutput::Albedo;
    Check check = checkAgainstReference(m, output, view, on(target), channels, [&](const reference::SlotResult& r, size_t p) {
        return differs[p] ? 2 * e * spread + pixelTolerance(ref3[p], ex, em, slot.hex, blended) + 1e-6
                          : pixelTolerance(r, ex, em, slot.hex, blended);
    });
    report(name, check);
    EXPECT_LE(check.worstRatio, 1.0);

    // 3. Against exact 3-tap on the GPU.
    const Image adaptive = on(target)(m, output, view), full = on(target)(exact, output, view);
    const Errors moved = compare(adaptive, full, channels == 1 ? 1 : normal ? 2 : 3);
    const double bound = e * spread + 1e-6;
    std::printf("  %-28s %-5s: adaptive against 3 taps max %.2e (%.2f/255), bound %.2e\n", name, targetName(target).c_str(), moved.max,
                moved.max * 255, bound);
    EXPECT_LE(moved.max, bound);
}

INSTANTIATE_TEST_SUITE_P(Exec, AdaptiveTaps, testing::ValuesIn(execCases("tests/execution/adaptive")), caseTestName);

// ---- Packed textures ---------------------------------------------------------------------------------------
// "pack": true (docs/material-format.md#pack) under tests/templates/packed.glsl, which reads every slot and shows
// them in one image: `color`'s RGB and `s3` in alpha, or scalars s0..s3 in R..A. The packed texture holds each slot's
// texels byte for byte, so every slot is held to its unpacked tolerance against its own fp64 reference, which samples
// the slot's own texture: an sRGB colour slot's sample error for RGB, the linear one for a scalar in the sRGB texture's
// alpha (alpha stays linear), each slot blended with its own settings from the shared samples.
// A case: "slots", "hextiling" (the material's), "minified".
// Each slot's output channels against its reference, each pixel within the slot's tolerance (pixelTolerance).
Check checkPacked(const Material& m, const View& view, int level, const Draw& draw) {
    const Image gpu = draw(m, vk::RenderOutput::Shaded, view);
    Check check;
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

class PackedPath : public testing::TestWithParam<ExecCase> {};

TEST_P(PackedPath, EverySlotMatchesItsReference) {
    REQUIRE_VULKAN();
    const nlohmann::json c = readCase(GetParam(), {"slots", "hextiling", "minified"});
    std::string slots;
    for (const nlohmann::json& slot : c.at("slots")) slots += (slots.empty() ? "" : ", ") + withCrop(slot);
    ParseResult r = parseMaterial(R"({"name": "packed", "template": "../tests/templates/packed.glsl", "pack": true, "hextiling": )" +
                                      c.at("hextiling").dump() + R"(, "slots": [)" + slots + "]}",
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
    const auto [view, level] = cropView(std::max(m.slots[0].width, m.slots[0].height), m.slots[0].hex.tiling[0], c.at("minified"));
    Check check = checkPacked(m, view, level, on(GetParam().target));
    report(GetParam().name.c_str(), check);
    EXPECT_LE(check.worstRatio, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Exec, PackedPath, testing::ValuesIn(execCases("tests/execution/packed")), caseTestName);

class ExecutionCase : public testing::TestWithParam<ExecCase> {};

TEST_P(ExecutionCase, MatchesTheReferenceWithinItsRule) {
    REQUIRE_VULKAN();
    const ExecCase& param = GetParam();
    const nlohmann::json c = readCase(param, {"rule", "view", "material"});
    ParseResult r = parseMaterial(c.at("material").dump(), "materials/" + param.name + ".json");
    ASSERT_TRUE(r.material) << formatAll(r.diagnostics);
    const Check check = checkCase(c, *r.material, on(param.target));
    report(param.name.c_str(), check);
    EXPECT_LE(check.worstRatio, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Exec, ExecutionCase, testing::ValuesIn(execCases("tests/execution/cases")), caseTestName);

}  // namespace
