// The CPU oracle's weights output (Listing 7) and render(), which evaluates a view pixel by pixel.
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

// --- Weights visualisation -----------------------------------------------------------------------------------

TEST(ReferenceWeights, AreListing7OfTheBlendWeights) {
    const SampledTexture tex(constantTexture(4, 4, {0.3, 0.3, 0.3, 1}));  // equal metric: W = w^7 normalised
    const Slot slot = hexSlot(SlotKind::Color);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> coord(-20, 20);
    for (int k = 0; k < 2000; ++k) {
        const double u = coord(rng), v = coord(rng);
        const Triangle tri = triangleGrid({u, v});
        const std::array<double, 3> W = powerWeights(tri.weight, slot.hex.exponent);
        const SlotResult r = evaluate(slot, tex, u, v, 0.01, 0, 0, 0.01);
        const std::array<double, 3> expected = listing7(W, tri.id[0], tri.id[2]);
        for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(r.weights[i], expected[i], 1e-12);
        std::array<double, 3> a = r.weights, b = W;  // a permutation of W
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], 1e-12);
    }
}

TEST(ReferenceWeights, EachTileKeepsOneColourAndNeighboursDiffer) {
    const SampledTexture tex(constantTexture(4, 4, {0.3, 0.3, 0.3, 1}));
    const Slot slot = hexSlot(SlotKind::Color);
    const auto colourNear = [&](TileId v, double phi) {
        const Vec2 c = centre(v);
        const SlotResult r = evaluate(slot, tex, c[0] + 0.02 * std::cos(phi), c[1] + 0.02 * std::sin(phi), 0.01, 0, 0, 0.01);
        return dominant(r.weights);
    };
    for (TileId v : {TileId{0, 0}, TileId{2, -1}, TileId{-7, -3}, TileId{10, 4}}) {
        const int own = colourNear(v, 0.3);
        for (int k = 1; k < 6; ++k) EXPECT_EQ(colourNear(v, 0.3 + k * kPi / 3), own);  // all six triangles
        for (TileId d : {TileId{1, 0}, TileId{-1, 0}, TileId{0, 1}, TileId{0, -1}, TileId{1, -1}, TileId{-1, 1}})
            EXPECT_NE(colourNear({v[0] + d[0], v[1] + d[1]}, 0.3), own);
    }
}

// --- render() -----------------------------------------------------------------------------------------------

TEST(ReferenceRender, MapsPixelCentresToUv) {
    Slot slot = hexSlot(SlotKind::Color);
    slot.hex.enabled = false;

    // 4x1 ramp, red = u at each texel centre. Two pixels across: du/dx = 0.5 is two texels per pixel, so the
    // sampler reads level 1, whose texels (0.25 and 0.75) sit exactly at the pixel centres.
    const SampledTexture ramp(floatTexture(4, 1, [](double s, double) { return Rgba{s, 0, 0, 1}; }));
    const Image row = render(slot, ramp, {2, 1, {0, 0, 1, 1}}, Output::Value);
    ASSERT_EQ(row.width, 2);
    ASSERT_EQ(row.height, 1);
    EXPECT_FLOAT_EQ(row.at(0, 0)[0], 0.25f);
    EXPECT_FLOAT_EQ(row.at(1, 0)[0], 0.75f);

    // Rows: 4x4 texture, red = u, green = v; row 0 is v = 0, at the top.
    const SampledTexture uvTex(floatTexture(4, 4, [](double s, double t) { return Rgba{s, t, 0, 1}; }));
    const Image image = render(slot, uvTex, {2, 2, {0, 0, 1, 1}}, Output::Value);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            EXPECT_FLOAT_EQ(image.at(i, j)[0], 0.25f + 0.5f * i);
            EXPECT_FLOAT_EQ(image.at(i, j)[1], 0.25f + 0.5f * j);
        }
    const Image weights = render(slot, uvTex, {2, 2, {0, 0, 1, 1}}, Output::Weights);
    EXPECT_EQ(std::vector<float>(weights.at(1, 1), weights.at(1, 1) + 4), (std::vector<float>{1, 0, 0, 1}));
}

TEST(ReferenceRender, IsEvaluateAtEachPixelCentre) {
    const SampledTexture tex(floatTexture(32, 32, wave));
    Slot slot = hexSlot(SlotKind::Color);
    slot.hex.tiling = {2, 3};
    const View view{5, 3, {0.2, -0.3, 1.7, 0.9}};
    const Image value = render(slot, tex, view, Output::Value);
    const Image weights = render(slot, tex, view, Output::Weights);
    ASSERT_EQ(value.width, 5);
    ASSERT_EQ(value.height, 3);
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 5; ++i) {
            const double u = 0.2 + (i + 0.5) / 5 * 1.5, v = -0.3 + (j + 0.5) / 3 * 1.2;
            const SlotResult r = evaluate(slot, tex, u, v, 1.5 / 5, 0, 0, 1.2 / 3);
            for (size_t c = 0; c < 4; ++c) EXPECT_EQ(value.at(i, j)[c], float(r.value[c]));
            for (size_t c = 0; c < 3; ++c) EXPECT_EQ(weights.at(i, j)[c], float(r.weights[c]));
        }
}

}  // namespace
