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

// ---- Adaptive taps (checks.h, adaptiveCase) -----------------------------------------------------------------
class AdaptiveTaps : public testing::TestWithParam<ExecCase> {};

TEST_P(AdaptiveTaps, FetchLikeTheReferenceAndStayWithinTheBoundOfThreeTaps) {
    REQUIRE_VULKAN();
    const vk::ExecutedTarget target = GetParam().target;
    const char* name = GetParam().name.c_str();
    const AdaptiveCase a = adaptiveCase(GetParam());
    const Slot& slot = a.adaptive.slots[0];

    // 1. The taps fetched.
    const Image weights = vk::render(*runner(&whyNoVulkan), a.adaptive, vk::RenderOutput::Weights, "", a.view, target);
    const std::vector<reference::SlotResult> ref = reference::evaluateView(slot, sampled(slot), a.view);
    std::vector<bool> differs(ref.size());
    size_t gpuFetches = 0, refFetches = 0, different = 0;
    for (size_t p = 0; p < ref.size(); ++p)
        for (size_t ch = 0; ch < 3; ++ch) {
            const bool gpu = weights.rgba[p * 4 + ch] > 0;
            gpuFetches += gpu;
            refFetches += ref[p].blend[ch] >= 0x1p-126;
            if (gpu != fetchedByReference(ref[p], ch) && !differs[p]) differs[p] = true, ++different;
        }
    const double n = double(ref.size());
    std::printf("  %-28s %-5s: fetches per pixel %.3f (reference %.3f), %zu pixels fetch other taps\n", name, targetName(target).c_str(),
                gpuFetches / n, refFetches / n, different);
    EXPECT_LE(different, ref.size() / 100);
    EXPECT_LT(gpuFetches / n, 3.0);  // something is skipped

    // 2. The value against the adaptive reference.
    const Check check = checkAdaptive(a, differs, on(target));
    report(name, check);
    EXPECT_LE(check.worstRatio, 1.0);

    // 3. Against exact 3-tap on the GPU.
    const Image adaptive = on(target)(a.adaptive, check.output, a.view), full = on(target)(a.exact, check.output, a.view);
    const Errors moved = compare(adaptive, full, std::min(check.channels, 3));
    const double bound = adaptiveBound(slot);
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
