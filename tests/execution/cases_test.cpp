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

// ---- Odd-sized textures (checks.h, checkOddSize) ----------------------------------------------------------------
class OddSizes : public testing::TestWithParam<ExecCase> {};

TEST_P(OddSizes, MatchReference) {
    REQUIRE_VULKAN();
    const CaseCheck r = checkOddSize(GetParam(), on(GetParam().target));
    report(GetParam().name.c_str(), r.check);
    EXPECT_LE(r.check.worstRatio, 1.0);
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

// ---- Packed textures (checks.h, checkPackedCase) ----------------------------------------------------------------
class PackedPath : public testing::TestWithParam<ExecCase> {};

TEST_P(PackedPath, EverySlotMatchesItsReference) {
    REQUIRE_VULKAN();
    const CaseCheck r = checkPackedCase(GetParam(), on(GetParam().target));
    const Material& m = r.material;
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
    report(GetParam().name.c_str(), r.check);
    EXPECT_LE(r.check.worstRatio, 1.0);
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
