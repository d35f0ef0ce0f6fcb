// Numerical stability: precision far from the origin, split coordinates, parameter and input extremes, and
// the same tiles on every target. Run on Vulkan (lavapipe) against the fp64 reference.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "hexc/material.h"
#include "reference/reference.h"
#include "vk/precision.h"
#include "vk/render.h"
#include "support.h"

using namespace hexc;
using hexc::test::runHexc;
using hexc::test::runner;

namespace {

// Tests run from the source root (tests/CMakeLists.txt).
const vk::ProbeTextures kProbe{"materials/textures/rock_albedo.png", "materials/textures/rock_normal.png"};
const std::filesystem::path kWork = std::filesystem::temp_directory_path() / "hexc_stress";

// Stable mode's error must not grow with |uv|: the lattice is reduced exactly and the hash is integer, so the
// only float32 error left is the ulps of the reduced coordinate. With float textures (no 8-bit filtering
// error), 1/255 is the requirement up to |uv| = 1e6.
TEST(Precision, StableModeStaysWithinOne255UpTo1e6) {
    REQUIRE_VULKAN();
    auto stable = vk::measurePrecision(*runner(&whyNoVulkan), kProbe, kWork, HashMode::Stable, vk::Placement::Direct,
                                       {1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7});
    auto paper = vk::measurePrecision(*runner(&whyNoVulkan), kProbe, kWork, HashMode::Paper, vk::Placement::Direct,
                                      {1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7});
    std::vector<vk::PrecisionRow> all = stable;
    all.insert(all.end(), paper.begin(), paper.end());
    std::printf("%s", vk::precisionTable(all).c_str());  // paper mode is reported, not required
    for (const auto& r : stable)
        if (r.magnitude <= 1e6) {
            EXPECT_LE(r.errors.max, 1.0 / 255) << r.path << " at |uv| " << r.magnitude;
        }
}

TEST(Precision, SplitCoordinatesStayWithinOne255UpToAnOriginOf1e9) {
    REQUIRE_VULKAN();
    auto rows = vk::measurePrecision(*runner(&whyNoVulkan), kProbe, kWork, HashMode::Stable, vk::Placement::Split, {0, 1e3, 1e6, 1e9});
    std::printf("%s", vk::precisionTable(rows).c_str());
    for (const auto& r : rows) EXPECT_LE(r.errors.max, 1.0 / 255) << r.path << " at origin " << r.magnitude;
}

// Stable mode reduces st.x by 28 kx, kx = floor(st.x / 28): exact while 7 kx < 2^24, i.e. |st.x| < 2^26 =
// 67,108,864 (|uv| < 2^24 at tiling 4); st.y is reduced by an integer, exact up to the int conversion (2^31).
// Aligned views sample mip level 0 (one-texel gradients) at float32 points one ulp apart, so a wrong tile is a
// wrong texel: up to 2^26 every pixel holds 1/255, and just past it the tiles go wrong (documented limit,
// docs/precision.md; the compiler warns when a tiling brings it near, material_test.cpp).
TEST(Precision, StableModeIsExactUpToStOf2To26AndNotBeyond) {
    REQUIRE_VULKAN();
    const double limitUv = std::ldexp(1.0, 26) / 4;  // tiling 4
    for (auto target : {vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl}) {
        const char* name = target == vk::ExecutedTarget::Spirv ? "spirv" : target == vk::ExecutedTarget::Hlsl ? "hlsl" : "glsl";
        auto rows = vk::measurePrecision(*runner(&whyNoVulkan), kProbe, kWork, HashMode::Stable, vk::Placement::Aligned,
                                         {1e3, 1e5, 1e6, 1e7, limitUv - 128, limitUv * 1.02, limitUv * 1.5}, target);
        std::printf("%s\n%s", name, vk::precisionTable(rows).c_str());
        for (const auto& r : rows) {
            if (r.magnitude < limitUv) {
                EXPECT_LE(r.errors.max, 1.0 / 255) << r.path << " at |uv| " << r.magnitude << ", " << name;
            } else {
                // Past the limit a quarter or more of the values are off: the stated limit is the real one.
                EXPECT_GE(r.errors.overOne255, 0.25) << r.path << " at |uv| " << r.magnitude << ", " << name;
            }
        }
    }
}

// ---- Extremes ---------------------------------------------------------------------------------------------
// Inputs and settings at and beyond what a material should use. Every output must be finite; weights
// non-negative and normalised (|sum - 1| <= 8 * 2^-24, the roundings of one normalisation, see
// checks.h); the colour a convex blend of filtered texels, so within the texture's [min, max] per
// channel, up to the float32 rounding of filtering and blending (16 roundings of the largest magnitude).
Image floatTexture(int size, const std::function<std::array<float, 4>(int, int)>& texel) {
    Image image;
    image.width = image.height = size;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            auto t = texel(x, y);
            image.rgba.insert(image.rgba.end(), t.begin(), t.end());
        }
    return image;
}

struct Input {
    const char* name;
    const char* kind;
    std::filesystem::path file;
};

std::vector<Input> extremeInputs() {
    std::filesystem::create_directories(kWork);
    auto write = [](const char* name, const Image& image) {
        std::filesystem::path p = kWork / (std::string(name) + ".pfm");
        writeImage(image, p);
        return p;
    };
    auto hash = [](int x, int y) { return float((uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u) % 1000) / 1000.0f; };
    return {
        {"black", "color",
         write("black", floatTexture(16,
                                     [](int, int) {
                                         return std::array<float, 4>{0, 0, 0, 1};
                                     }))},
        {"white", "color",
         write("white", floatTexture(16,
                                     [](int, int) {
                                         return std::array<float, 4>{1, 1, 1, 1};
                                     }))},
        {"hdr", "color",
         write("hdr", floatTexture(16,
                                   [&](int x, int y) {
                                       float h = hash(x, y);
                                       return std::array<float, 4>{h * 1e4f - 50.0f, (x % 2 ? -3.0f : 1e4f), h, 1};
                                   }))},
        {"rock", "color", "materials/textures/rock_albedo.png"},
        {"normal_rock", "normal", "materials/textures/rock_normal.png"},
        // n * 0.5 + 0.5 with z <= 0 (pointing into the surface), the zero vector, and non-unit vectors.
        {"normal_z_negative", "normal",
         write("normal_z_negative", floatTexture(16,
                                                 [&](int x, int y) {
                                                     return std::array<float, 4>{hash(x, y), 0.5f, y % 2 ? 0.5f : 0.2f, 1};
                                                 }))},
        {"normal_zero", "normal",
         write("normal_zero", floatTexture(16,
                                           [](int, int) {
                                               return std::array<float, 4>{0.5f, 0.5f, 0.5f, 1};
                                           }))},
        {"normal_non_unit", "normal",
         write("normal_non_unit",
               floatTexture(16,
                            [&](int x, int y) {
                                float s = x % 2 ? 3.0f : 0.01f;
                                return std::array<float, 4>{0.5f + s * (hash(x, y) - 0.5f), 0.5f + s * 0.1f, 0.5f + s * 0.4f, 1};
                            }))},
    };
}

const char* kExtremeSettings[] = {
    R"("falloff": 0.000001)",  R"("falloff": 0.01)",
    R"("falloff": 0.5)",       R"("falloff": 0.99)",
    R"("falloff": 0.999999)",  R"("exponent": 1)",
    R"("exponent": 7)",        R"("exponent": 64)",
    R"("falloffcontrast": 0)", R"("falloffcontrast": 1)",
    R"("rotation": 0)",        R"("rotation": 1)",
    R"("rotation": 20)",       R"("falloffcontrast": 1, "exponent": 64, "falloff": 0.999999)",  // rotation: the largest accepted
};

// Views: ordinary, zero gradients (a zero-size rectangle), huge gradients (1e4 uv across 32 pixels).
const View kViews[] = {{32, 32, {0.1, 0.2, 0.6, 0.7}}, {32, 32, {0.3, 0.3, 0.3, 0.3}}, {32, 32, {0, 0, 1e4, 1e4}}};

TEST(Extremes, OutputsStayFiniteNormalisedAndInRange) {
    REQUIRE_VULKAN();
    const double eps = std::ldexp(1.0, -24);
    size_t renders = 0;
    double worstSum = 0, worstRange = 0;
    for (const Input& in : extremeInputs()) {
        Texture t = loadTexture(in.file, false);
        // Texture range per channel, in the values the sampler returns.
        std::array<double, 4> lo, hi;
        lo.fill(INFINITY);
        hi.fill(-INFINITY);
        for (size_t i = 0; i < size_t(t.width) * t.height * 4; ++i) {
            double v = t.isFloat() ? t.rgba32f[i] : t.rgba8[i] / 255.0;
            lo[i % 4] = std::min(lo[i % 4], v);
            hi[i % 4] = std::max(hi[i % 4], v);
        }
        const bool normal = std::string(in.kind) == "normal";
        for (const char* setting : kExtremeSettings)
            for (const View& view : kViews) {
                std::string slot = std::string(R"({"name": "s", "kind": ")") + in.kind + R"(", "colorspace": "linear", "texture": ")" +
                                   std::filesystem::absolute(in.file).string() + R"(", "hextiling": {"tiling": 4, )" + setting + "}}";
                ParseResult parsed = parseMaterial(R"({"name": "extreme", "slots": [)" + slot + "]}", kWork / "extreme.json");
                ASSERT_TRUE(parsed.material) << formatAll(parsed.diagnostics);
                const Material& m = *parsed.material;
                Image value =
                    vk::render(*runner(&whyNoVulkan), m, normal ? vk::RenderOutput::Derivative : vk::RenderOutput::Albedo, "", view);
                Image weights = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Weights, "", view);
                renders += 2;
                for (size_t p = 0; p < value.rgba.size(); p += 4) {
                    const float* v = &value.rgba[p];
                    const float* w = &weights.rgba[p];
                    for (int c = 0; c < 4; ++c) {
                        ASSERT_TRUE(std::isfinite(v[c])) << in.name << " " << setting << " channel " << c;
                        ASSERT_TRUE(std::isfinite(w[c])) << in.name << " " << setting;
                    }
                    ASSERT_TRUE(w[0] >= 0 && w[1] >= 0 && w[2] >= 0) << in.name << " " << setting;
                    worstSum = std::max(worstSum, std::fabs(double(w[0]) + w[1] + w[2] - 1));
                    if (!normal)
                        for (int c = 0; c < 3; ++c) {
                            double slack = 16 * eps * std::max(std::fabs(lo[c]), std::fabs(hi[c]));
                            worstRange = std::max({worstRange, (lo[c] - v[c]) - slack, (v[c] - hi[c]) - slack});
                            ASSERT_GE(v[c], lo[c] - slack) << in.name << " " << setting;
                            ASSERT_LE(v[c], hi[c] + slack) << in.name << " " << setting;
                        }
                }
            }
    }
    std::printf("  %zu renders: largest |sum of weights - 1| %.2e (bound %.2e); colour never left its texture's range\n", renders, worstSum,
                8 * eps);
    EXPECT_LE(worstSum, 8 * eps);
}

// ---- The same tiles everywhere ----------------------------------------------------------------------------
// Stable mode is integer hashing and exact reduction: the emitted HLSL and GLSL, re-compiled, must place the
// same tiles with the same offsets as the SPIR-V, far from the origin too. The weights (which tile is where)
// must agree exactly and the colour to float32 rounding of the blend (8 roundings of 1).
TEST(CrossTarget, StableModePicksTheSameTilesOnEveryTarget) {
    REQUIRE_VULKAN();
    Material m =
        *parseMaterial(
             R"({"name": "x", "slots": [{"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 4, "falloff": 0.7}}]})",
             "materials/x.json")
             .material;
    for (double x : {0.0, 1e3, 1e5, 1e6}) {
        View view{48, 48, {x, x, x + 0.2, x + 0.2}};
        Image w0 = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Weights, "", view, vk::ExecutedTarget::Spirv);
        Image c0 = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Albedo, "", view, vk::ExecutedTarget::Spirv);
        for (auto target : {vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl}) {
            Image w = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Weights, "", view, target);
            Image c = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Albedo, "", view, target);
            // compareImages counts a NaN on either side as an infinite difference (std::max would drop it).
            const double dw = vk::compareImages(w0, w, 4).max, dc = vk::compareImages(c0, c, 4).max;
            std::printf("  |uv| %.0e, %s against spirv: weights differ by %.2e, colour by %.2e\n", x,
                        target == vk::ExecutedTarget::Hlsl ? "hlsl" : "glsl", dw, dc);
            EXPECT_LE(dw, 8 * std::ldexp(1.0, -24));
            EXPECT_LE(dc, 8 * std::ldexp(1.0, -24));
        }
    }
}

}  // namespace
