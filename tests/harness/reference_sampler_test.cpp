// The CPU oracle's sampler against texel values a Vulkan sampler must return: texel centres, filtering, wrapping,
// mip levels made by blits, the level of detail, sRGB decoding.
#include <gtest/gtest.h>

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>

#include "harness/reference_support.h"
#include "reference/reference.h"

using namespace hexc;
using namespace hexc::reference;
using namespace hexc::reference::oracle;

namespace {

// --- Sampler -------------------------------------------------------------------------------------------------

Texture fourByFour() {  // distinct texels: value = (x + 4y) / 16 in red, 1 - that in green
    return floatTexture(4, 4, [](double s, double t) {
        const double i = (s * 4 - 0.5) + 4 * (t * 4 - 0.5);
        return Rgba{i / 16, 1 - i / 16, 0.25, 1};
    });
}

TEST(ReferenceSampler, TexelCentresReturnTexels) {
    const SampledTexture tex(fourByFour());
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            const Rgba c = tex.sample((x + 0.5) / 4, (y + 0.5) / 4, 1e-6, 0, 0, 1e-6);
            EXPECT_EQ(c, tex.texel(0, x, y)) << x << "," << y;
            EXPECT_NEAR(c[0], (x + 4 * y) / 16.0, 1e-7);  // the texture stores float32
        }
}

TEST(ReferenceSampler, HalfwayBetweenTexelsIsTheirMean) {
    const SampledTexture tex(fourByFour());
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 3; ++x) {
            const Rgba c = tex.sample((x + 1) / 4.0, (y + 0.5) / 4, 1e-6, 0, 0, 1e-6);
            EXPECT_NEAR(c[0], (tex.texel(0, x, y)[0] + tex.texel(0, x + 1, y)[0]) / 2, 1e-15);
        }
}

TEST(ReferenceSampler, RepeatBlendsFirstAndLastTexel) {
    const SampledTexture tex(fourByFour());
    for (int y = 0; y < 4; ++y) {
        const double t = (y + 0.5) / 4;
        const double expected = (tex.texel(0, 0, y)[0] + tex.texel(0, 3, y)[0]) / 2;
        EXPECT_NEAR(tex.sample(0, t, 1e-6, 0, 0, 1e-6)[0], expected, 1e-15);
        EXPECT_NEAR(tex.sample(1, t, 1e-6, 0, 0, 1e-6)[0], expected, 1e-15);
        EXPECT_NEAR(tex.sample(-3, t, 1e-6, 0, 0, 1e-6)[0], expected, 1e-15);
    }
    // and vertically: t = 0 lies between the bottom and the top row
    EXPECT_NEAR(tex.sample(0.125, 0, 1e-6, 0, 0, 1e-6)[0], (tex.texel(0, 0, 0)[0] + tex.texel(0, 0, 3)[0]) / 2, 1e-15);
}

TEST(ReferenceSampler, ConstantTextureAtEveryLod) {
    for (auto [w, h] : {std::pair{64, 32}, std::pair{5, 3}, std::pair{1, 7}}) {
        Texture t;
        t.width = w;
        t.height = h;
        for (int i = 0; i < w * h; ++i) t.rgba8.insert(t.rgba8.end(), {51, 102, 153, 204});
        const SampledTexture tex(t);
        EXPECT_EQ(tex.levels(), int(std::bit_width(unsigned(std::max(w, h)))));
        for (double lambda = -2; lambda < 9; lambda += 0.37) {
            const double g = std::exp2(lambda) / std::max(w, h);
            const Rgba c = tex.sample(0.3, -1.7, g * 0.6, g * 0.8, 0, g * 0.5);
            EXPECT_NEAR(c[0], 0.2, 1e-15);
            EXPECT_NEAR(c[1], 0.4, 1e-15);
            EXPECT_NEAR(c[2], 0.6, 1e-15);
            EXPECT_NEAR(c[3], 0.8, 1e-15);
        }
    }
}

// Odd sizes resample as a linear blit does: 5 -> 2 texels read the level above at (i + 0.5) * 5 / 2 - 0.5 = 0.75
// and 3.25; 3 -> 1 reads the middle texel; a size of 1 stays and reads its one texel.
TEST(ReferenceSampler, OddLevelsAreLinearBlitsOfTheLevelAbove) {
    Texture t;
    t.width = 5;
    t.height = 3;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) t.rgba32f.insert(t.rgba32f.end(), {float(x), float(10 * y), 0.0f, 1.0f});
    const SampledTexture tex(t);
    ASSERT_EQ(tex.levels(), 3);
    ASSERT_EQ(tex.width(1), 2);
    ASSERT_EQ(tex.height(1), 1);
    EXPECT_DOUBLE_EQ(tex.texel(1, 0, 0)[0], 0.75);
    EXPECT_DOUBLE_EQ(tex.texel(1, 1, 0)[0], 3.25);
    EXPECT_DOUBLE_EQ(tex.texel(1, 0, 0)[1], 10.0);  // the middle row
    // 2 -> 1: the average, at the centre 1.0 of the level above.
    EXPECT_DOUBLE_EQ(tex.texel(2, 0, 0)[0], (0.75 + 3.25) / 2);
}

TEST(ReferenceSampler, LodFollowsTheEuclideanGradientLength) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0, 1);
    Texture t;
    t.width = t.height = 64;
    for (int i = 0; i < 64 * 64 * 4; ++i) t.rgba32f.push_back(float(unit(rng)));
    const SampledTexture tex(t);
    ASSERT_EQ(tex.levels(), 7);

    // Level 1 and bilinear filtering, computed here from the texture data.
    const auto level0 = [&](int x, int y, int c) { return double(t.rgba32f[size_t(y * 64 + x) * 4 + c]); };
    const auto level1 = [&](int x, int y, int c) {
        return (level0(2 * x, 2 * y, c) + level0(2 * x + 1, 2 * y, c) + level0(2 * x, 2 * y + 1, c) + level0(2 * x + 1, 2 * y + 1, c)) / 4;
    };
    const auto bilinear = [](const std::function<double(int, int)>& texel, int size, double s, double t) {
        const double x = s * size - 0.5, y = t * size - 0.5;
        const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
        const double a = x - x0, b = y - y0;
        const auto at = [&](int i, int j) { return texel(((i % size) + size) % size, ((j % size) + size) % size); };
        return (1 - a) * (1 - b) * at(x0, y0) + a * (1 - b) * at(x0 + 1, y0) + (1 - a) * b * at(x0, y0 + 1) + a * b * at(x0 + 1, y0 + 1);
    };

    for (int k = 0; k < 200; ++k) {
        const double s = unit(rng) * 4 - 2, tt = unit(rng) * 4 - 2, dir = unit(rng) * 2 * kPi;
        for (int c = 0; c < 4; ++c) {
            const double l0 = bilinear([&](int x, int y) { return level0(x, y, c); }, 64, s, tt);
            const double l1 = bilinear([&](int x, int y) { return level1(x, y, c); }, 32, s, tt);
            // 2 texels per pixel in any direction (a max(|ds|, |dt|) rule would pick a lower level off-axis)
            const double g = 2.0 / 64;
            EXPECT_NEAR(tex.sample(s, tt, g * std::cos(dir), g * std::sin(dir), 0, 0)[c], l1, 1e-12);
            EXPECT_NEAR(tex.sample(s, tt, 0, 0, g * std::sin(dir), g * std::cos(dir))[c], l1, 1e-12);
            // sqrt(2) texels per pixel: lambda = 0.5, halfway between levels 0 and 1
            EXPECT_NEAR(tex.sample(s, tt, std::sqrt(2.0) / 64, 0, 0, 0)[c], (l0 + l1) / 2, 1e-12);
            // below one texel per pixel: level 0 only
            EXPECT_NEAR(tex.sample(s, tt, 0.7 / 64, 0, 0, 0.7 / 64)[c], l0, 1e-12);
        }
    }
    // far beyond the last level: the 1x1 level, the mean of all texels
    double mean = 0;
    for (int i = 0; i < 64 * 64; ++i) mean += t.rgba32f[size_t(i) * 4] / 4096.0;
    EXPECT_NEAR(tex.sample(0.1, 0.2, 1000, 0, 0, 0)[0], mean, 1e-12);
}

TEST(ReferenceSampler, SrgbDecodesBeforeFiltering) {
    Texture t;
    t.width = 2;
    t.height = 1;
    t.srgb = true;
    t.rgba8 = {188, 188, 188, 188, 0, 0, 0, 0};
    const SampledTexture tex(t);
    const Rgba c = tex.sample(0.25, 0.5, 1e-6, 0, 0, 1e-6);
    EXPECT_NEAR(c[0], 0.50289, 1e-5);       // ((188/255 + 0.055) / 1.055)^2.4
    EXPECT_NEAR(c[3], 188 / 255.0, 1e-15);  // alpha stays linear
    // halfway between 188 and 0: the mean of the linear values, not the decoded mean of the encoded ones
    EXPECT_NEAR(tex.sample(0.5, 0.5, 1e-6, 0, 0, 1e-6)[0], 0.50289 / 2, 1e-5);
    t.srgb = false;
    EXPECT_NEAR(SampledTexture(t).sample(0.25, 0.5, 1e-6, 0, 0, 1e-6)[0], 188 / 255.0, 1e-15);
}

}  // namespace
