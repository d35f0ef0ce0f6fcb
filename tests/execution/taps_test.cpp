// Execution tests of what a slot fetches: 1-tap dithering against the reference, and the count of fetches each
// variant's shader makes.
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

}  // namespace
