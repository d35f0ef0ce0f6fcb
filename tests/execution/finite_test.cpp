// Every output finite and in range at the accepted extremes of every hex-tiling setting, in every mode that accepts
// them (docs/precision.md): the validator's bounds are what keeps float32 finite, so each bound is rendered here.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "hexc/image.h"
#include "hexc/material.h"
#include "reference/reference.h"
#include "vk/render.h"
#include "support.h"

using namespace hexc;

namespace {

// One setting at one end of its accepted range (docs/material-format.md, the settings table), as hextiling keys.
const std::vector<std::string> kExtremes = {
    R"("tiling": 5.9604644775390625e-8)",
    R"("tiling": 16777216)",
    R"("tiling": [5.9604644775390625e-8, 16777216])",
    R"("rotation": 0)",
    R"("rotation": 20)",  // 20 x 180 degrees: the largest angle accepted, 3600
    R"("rotation": 1, "rotationrange": [-3600, 3600])",
    R"("rotationrange": [3600, 3600], "rotationsteps": 360)",
    R"("scalerange": [0.01, 0.01])",
    R"("scalerange": [100, 100])",
    R"("scalerange": [0.01, 100])",
    R"("offset": 0)",
    R"("offset": 1, "offsetsteps": [4096, 4096])",
    R"("falloff": 0.000001)",
    R"("falloff": 0.999999)",
    R"("falloffcontrast": 0)",
    R"("falloffcontrast": 1)",
    R"("falloffcontrast": 1, "falloff": 0.999999)",
    R"("exponent": 1)",
    R"("exponent": 64)",
    R"("exponent": 64, "falloff": 0.999999, "falloffcontrast": 1)",
    R"("taps": 1)",
    R"("taps": "adaptive", "falloff": 0.999999, "falloffcontrast": 0.999)",
    R"("mask": "checker", "maskscale": 64)",
    R"("mask": "noise3", "maskscale": 1)",
    R"("lod": "shared", "scalerange": [0.01, 100])",
    R"("blend": "histogram", "falloff": 0.999999)",
    R"("lumacoeffs": [0, 0, 0], "falloffcontrast": 1)",
    R"("lumacoeffs": [1, 1, 1], "falloffcontrast": 1)",
};

// The textures each setting is rendered with: a photograph, all black (every luma 0: falloffcontrast 1 leaves no
// weight) and, for normal maps, texels of exactly (0.5, 0.5, 0.5) (float, zero length after decoding). The flat ones
// are written as PFM, which loads as 32-bit floats.
std::filesystem::path flatTexture(const std::string& name, float value) {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / ("hexc_finite_" + name + ".pfm");
    Image image;
    image.width = image.height = 8;
    image.rgba.assign(8 * 8 * 4, value);
    for (size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 1;
    writeImage(image, file);
    return file;
}

struct Case {
    std::string slot;  // the slot's JSON, without hextiling
    bool normal;
};

std::vector<Case> cases() {
    const std::string black = flatTexture("black", 0).string(), grey = flatTexture("grey", 0.5f).string();
    return {{R"("kind": "color", "colorspace": "srgb", "texture": "textures/rock_albedo.png")", false},
            {R"("kind": "color", "colorspace": "linear", "texture": ")" + black + R"(")", false},
            {R"("kind": "normal", "texture": "textures/rock_normal.png")", true},
            {R"("kind": "normal", "texture": ")" + grey + R"(")", true}};
}

// A 48x48 view over the execution tests' magnified area (about 2 texels per pixel at tiling 4).
const View kView{48, 48, {0.3, 0.45, 0.3 + 192 * 0.75 / 1024, 0.45 + 192 * 0.75 / 1024}};

// The largest |(x, y)| / z of a normal map's texels, x, y, z = 2 b - 1 (z > 0 on every texel of the maps used): a
// filtered texel's ratio lies within its texels' (a mediant of ratios with positive z), a rotation keeps a length,
// and the blends are convex; a tile scaled by s divides a slope by at most min(1, s).
double largestSlope(const Slot& slot) {
    const reference::SampledTexture t(loadTexture(slot.texturePath, false));
    double worst = 0;
    for (int y = 0; y < t.height(0); ++y)
        for (int x = 0; x < t.width(0); ++x) {
            const auto& p = t.texel(0, x, y);
            const double z = 2 * p[2] - 1;
            if (z > 0) worst = std::max(worst, std::hypot(2 * p[0] - 1, 2 * p[1] - 1) / z);
        }
    return worst;
}

TEST(Finite, EveryAcceptedExtremeInEveryMode) {
    REQUIRE_VULKAN();
    int rendered = 0;
    for (const std::string& extreme : kExtremes) {
        int accepted = 0;
        for (const std::string mode : {"stable", "paper", "materialx"})
            for (const Case& c : cases()) {
                const std::string doc = R"({"name": "finite", "slots": [{"name": "s", )" + c.slot + R"(, "hextiling": {"mode": ")" + mode +
                                        R"(", )" + extreme + "}}]}";
                ParseResult r = parseMaterial(doc, "materials/finite.json");
                if (!r.material) continue;  // not accepted in this mode (or by this kind): nothing to render
                ++accepted, ++rendered;
                const Slot& slot = r.material->slots[0];
                std::string why;
                const Image image =
                    vk::render(*hexc::test::runner(&why), *r.material, c.normal ? vk::RenderOutput::Derivative : vk::RenderOutput::Albedo,
                               "", kView, vk::ExecutedTarget::Spirv);
                // Colour: a convex blend of texels in [0, 1], plus float32 rounding of a few ulp (4 x 2^-24). Normal:
                // the slope bound above, relative rounding 1e-5.
                const double bound = c.normal ? largestSlope(slot) / std::min(1.0, slot.hex.scaleRange[0]) * (1 + 1e-5) : 1 + 0x1p-22;
                double worst = 0, lowest = 0;
                bool finite = true;
                for (size_t p = 0; p < image.rgba.size(); p += 4) {
                    for (size_t k = 0; k < 4; ++k) {
                        finite = finite && std::isfinite(image.rgba[p + k]);
                        if (!c.normal) worst = std::max(worst, double(image.rgba[p + k]));
                        if (!c.normal) lowest = std::min(lowest, double(image.rgba[p + k]));
                    }
                    if (c.normal) worst = std::max(worst, std::hypot(double(image.rgba[p]), double(image.rgba[p + 1])));
                }
                EXPECT_TRUE(finite) << mode << " " << extreme << " " << c.slot;
                EXPECT_LE(worst, bound) << mode << " " << extreme << " " << c.slot;
                EXPECT_GE(lowest, -0x1p-22) << mode << " " << extreme << " " << c.slot;
            }
        EXPECT_GT(accepted, 0) << extreme << " is accepted in no mode";
    }
    std::printf("  %d renders of %zu extremes\n", rendered, kExtremes.size());
}

}  // namespace
