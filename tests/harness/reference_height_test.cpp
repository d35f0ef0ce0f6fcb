// The CPU oracle's height blending against the documented formula and its properties.
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

// --- Height blending ------------------------------------------------------------------------------------------

// A height map whose red is the slot texture's blue: sampled at each tile's point with its gradients, it reads
// exactly the blue of that tile's sample.
Texture blueAsRed() {
    return floatTexture(64, 64, [](double s, double t) {
        const Rgba c = wave(s, t);
        return Rgba{c[2], 0, 0, 1};
    });
}

TEST(ReferenceHeightBlend, IsTheDocumentedFormulaAtEachTilesSample) {
    const SampledTexture tex(floatTexture(64, 64, wave)), heights(blueAsRed());
    std::mt19937 rng(59);
    std::uniform_real_distribution<double> coord(-4, 4);
    for (Mask mask : {Mask::Hex, Mask::Checker, Mask::Noise3})
        for (double width : {0.05, 0.2, 1.0}) {
            Slot plain = maskSlot(SlotKind::Color, mask);
            plain.hex.falloff = 0.7;
            withTransforms(plain.hex);
            Slot blended = plain;
            blended.heightBlend = HeightBlend{"height", width};
            const HeightSource source{&heights, 0, width};
            double largestGain = 0;  // of the highest tile's weight
            for (int k = 0; k < 300; ++k) {
                const Vec2 st{coord(rng), coord(rng)}, dx{0.02, 0.005}, dy{-0.004, 0.02};
                const SlotResult r = evaluateAt(plain, tex, st, dx, dy), h = evaluateAt(blended, tex, st, dx, dy, {0, 0}, &source);
                std::array<double, 3> a, expected;
                for (size_t i = 0; i < 3; ++i) a[i] = r.samples[i][2] * r.blend[i];
                const double top = *std::max_element(a.begin(), a.end());
                double sum = 0;
                for (size_t i = 0; i < 3; ++i) sum += expected[i] = r.blend[i] * std::max(a[i] - top + width, 0.0);
                for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(h.blend[i], expected[i] / sum, 1e-12);
                for (size_t c = 0; c < 4; ++c)
                    EXPECT_NEAR(h.value[c], h.blend[0] * r.samples[0][c] + h.blend[1] * r.samples[1][c] + h.blend[2] * r.samples[2][c],
                                1e-12);
                EXPECT_NEAR(h.blend[0] + h.blend[1] + h.blend[2], 1, 1e-12);
                if (mask == Mask::Checker) {
                    EXPECT_EQ(h.blend[2], 0);
                }
                const size_t highest = size_t(std::max_element(a.begin(), a.end()) - a.begin());
                EXPECT_GE(h.blend[highest], r.blend[highest] - 1e-12);  // the highest tile only gains
                largestGain = std::max(largestGain, h.blend[highest] - r.blend[highest]);
            }
            if (width < 1) {
                EXPECT_GT(largestGain, 0.1);
            }
        }
}

// Heights of 0 everywhere leave every tile within `width` of the highest: the linear blend, at any width.
TEST(ReferenceHeightBlend, FlatHeightsKeepTheLinearBlend) {
    const SampledTexture tex(floatTexture(64, 64, wave)), flat(constantTexture(4, 4, {0, 0, 0, 1}));
    std::mt19937 rng(61);
    std::uniform_real_distribution<double> coord(-4, 4);
    for (double width : {0.2, 1.0}) {
        Slot plain = maskSlot(SlotKind::Color, Mask::Hex);
        Slot blended = plain;
        blended.heightBlend = HeightBlend{"height", width};
        const HeightSource source{&flat, 0, width};
        for (int k = 0; k < 200; ++k) {
            const Vec2 st{coord(rng), coord(rng)};
            const SlotResult r = evaluateAt(plain, tex, st, {0.01, 0}, {0, 0.01}),
                             h = evaluateAt(blended, tex, st, {0.01, 0}, {0, 0.01}, {0, 0}, &source);
            for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(h.blend[i], r.blend[i], 1e-15);
            for (size_t c = 0; c < 4; ++c) EXPECT_NEAR(h.value[c], r.value[c], 1e-15);
        }
    }
}

// A real texture pair: rock albedo blended by the rock roughness as height. Crossing an edge of the hex lattice's
// triangles one tile leaves the blend; its weight reaches 0 there, so the value and Listing 7's weights (one
// colour per tile) are continuous.
TEST(ReferenceHeightBlend, ContinuousAcrossHexTriangleEdges) {
    const SampledTexture tex(loadTestTexture("rock_albedo.png", true)), heights(loadTestTexture("rock_roughness.png", false));
    Slot slot = maskSlot(SlotKind::Color, Mask::Hex);
    slot.hex.falloff = 0.7;
    slot.heightBlend = HeightBlend{"roughness", 0.1};
    const HeightSource source{&heights, 0, 0.1};
    const auto toSt = [](Vec2 skewed) {  // stable mode's skewed coordinates (97/28 s - 2 t, 4 t), inverted
        const double t = skewed[1] / 4;
        return Vec2{(skewed[0] + 2 * t) * 28 / 97, t};
    };
    std::mt19937 rng(67);
    std::uniform_int_distribution<int> vertex(-20, 20);
    std::uniform_real_distribution<double> along(0.1, 0.9);
    for (int k = 0; k < 300; ++k) {
        const double i = vertex(rng), j = vertex(rng), a = along(rng), e = 1e-9;
        // Edges of the three directions and a step across each: x = i, y = j, x + y = i.
        const std::array<std::pair<Vec2, Vec2>, 3> edges{{{{i, j + a}, {e, 0}}, {{i + a, j}, {0, e}}, {{i - a, a}, {e, e}}}};
        const auto& [p, step] = edges[size_t(k % 3)];
        const Vec2 lo = toSt({p[0] - step[0], p[1] - step[1]}), hi = toSt({p[0] + step[0], p[1] + step[1]});
        const SlotResult r0 = evaluateAt(slot, tex, lo, {1e-4, 0}, {0, 1e-4}, {0, 0}, &source);
        const SlotResult r1 = evaluateAt(slot, tex, hi, {1e-4, 0}, {0, 1e-4}, {0, 0}, &source);
        for (size_t c = 0; c < 3; ++c) {
            EXPECT_NEAR(r0.weights[c], r1.weights[c], 1e-6) << k;
            EXPECT_NEAR(r0.value[c], r1.value[c], 1e-6) << k;
        }
    }
}

TEST(ReferenceHeightBlend, NeedsHeightsUnlessOneTap) {
    const SampledTexture tex(floatTexture(16, 16, wave));
    Slot slot = maskSlot(SlotKind::Color, Mask::Hex);
    slot.heightBlend = HeightBlend{"height", 0.2};
    EXPECT_THROW(evaluateAt(slot, tex, {0.3, 0.4}, {0.01, 0}, {0, 0.01}), std::invalid_argument);
    slot.hex.taps = 1;  // one sample has nothing to weigh
    Slot plain = slot;
    plain.heightBlend.reset();
    EXPECT_EQ(evaluateAt(slot, tex, {0.3, 0.4}, {0.01, 0}, {0, 0.01}, {5, 9}).value,
              evaluateAt(plain, tex, {0.3, 0.4}, {0.01, 0}, {0, 0.01}, {5, 9}).value);
}

}  // namespace
