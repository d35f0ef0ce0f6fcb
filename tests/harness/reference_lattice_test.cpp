// The CPU oracle's lattice, hash, gain and adaptive taps against the paper's listings written out again and the
// bound docs/material-format.md#taps states.
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

// --- Lattice, hash, gain -------------------------------------------------------------------------------------

TEST(ReferenceLattice, WeightsAreBarycentricInTheNearestThreeCentres) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> coord(-40, 40);
    const auto distance = [](Vec2 a, Vec2 b) { return std::hypot(a[0] - b[0], a[1] - b[1]); };
    for (int k = 0; k < 10000; ++k) {
        const Vec2 st{coord(rng), coord(rng)};
        const Triangle tri = triangleGrid(st);
        double sum = 0, farthest = 0;
        Vec2 recon{0, 0};
        for (size_t i = 0; i < 3; ++i) {
            EXPECT_GE(tri.weight[i], 0);
            sum += tri.weight[i];
            const Vec2 c = centre(tri.id[i]);
            recon = {recon[0] + tri.weight[i] * c[0], recon[1] + tri.weight[i] * c[1]};
            farthest = std::max(farthest, distance(st, c));
        }
        EXPECT_NEAR(sum, 1, 1e-12);
        EXPECT_NEAR(recon[0], st[0], 1e-12);  // st = sum w_i c_i: the weights are barycentric
        EXPECT_NEAR(recon[1], st[1], 1e-12);
        for (const TileId& v : tri.id)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const TileId other{v[0] + dx, v[1] + dy};
                    if (std::find(tri.id.begin(), tri.id.end(), other) != tri.id.end()) continue;
                    EXPECT_LE(farthest, distance(st, centre(other)) + 1e-12) << st[0] << "," << st[1];
                }
    }
}

TEST(ReferenceHash, IsListing2InFloat32) {
    EXPECT_EQ(tileOffset({0, 0}), (Vec2{0, 0}));
    for (int y = -50; y <= 50; y += 7)
        for (int x = -50; x <= 50; x += 3) {
            const Vec2 h = tileOffset({x, y});
            // each product rounded to float on its own (volatile: no FMA contraction, whatever the flags)
            volatile float p[4] = {127.1f * float(x), 311.7f * float(y), 269.5f * float(x), 183.3f * float(y)};
            const float r0 = p[0] + p[1], r1 = p[2] + p[3];
            volatile float q[2] = {std::sin(r0) * 43758.5453f, std::sin(r1) * 43758.5453f};
            const float h0 = q[0], h1 = q[1];
            EXPECT_EQ(h[0], double(h0 - std::floor(h0)));
            EXPECT_EQ(h[1], double(h1 - std::floor(h1)));
            EXPECT_TRUE(h[0] >= 0 && h[0] < 1 && h[1] >= 0 && h[1] < 1);
        }
}

TEST(ReferenceGain, IsEquation5) {
    for (double x = 0; x <= 1; x += 1.0 / 64) {
        EXPECT_NEAR(gain(x, 0.5), x, 1e-15);                                                 // k = 1
        EXPECT_NEAR(gain(x, 0.75), x < 0.5 ? 2 * x * x : 1 - 2 * (1 - x) * (1 - x), 1e-15);  // k = 2
        EXPECT_NEAR(gain(1 - x, 0.9), 1 - gain(x, 0.9), 1e-15);                              // symmetric about (0.5, 0.5)
    }
}

TEST(ReferenceGain, FalloffHalfLeavesWeightsUntouched) {
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int k = 0; k < 1000; ++k) {
        const double a = unit(rng), b = unit(rng) * (1 - a);
        const std::array<double, 3> bary{a, b, 1 - a - b}, delta{unit(rng), unit(rng), unit(rng)};
        HexTiling hex;
        hex.falloff = 0.5;
        // Eq. 1 alone, bit for bit: a gain "applied" at r = 0.5 would still renormalise, which moves the last bits
        std::array<double, 3> expected;
        for (size_t i = 0; i < 3; ++i) expected[i] = delta[i] * std::pow(bary[i], hex.exponent);
        const double sum = expected[0] + expected[1] + expected[2];
        for (double& x : expected) x /= sum;
        ASSERT_EQ(blendWeights(bary, delta, hex), expected);

        hex.falloff = 0.75;  // sharper: the dominant tile gains, the weights still sum to 1
        const std::array<double, 3> sharp = blendWeights(bary, delta, hex);
        const int top = dominant(expected);
        if (expected[size_t(top)] > 0.5) {
            EXPECT_GE(sharp[size_t(top)], expected[size_t(top)]);
        }
        EXPECT_NEAR(sharp[0] + sharp[1] + sharp[2], 1, 1e-15);
    }
}

// --- Adaptive taps ----------------------------------------------------------------------------------------------

// The bound of docs/material-format.md#taps over the corners of the allowed settings (exponent 1 to 64,
// falloffcontrast 0 to just below 1, falloff 0.5 to its largest): wherever adaptiveTaps skips taps, the blend of the
// fetched taps alone moves from the blend of all three by a total variation TV = sum |G - G'| / 2 below e, whatever
// each tap's metric in [1 - beta, 1] (the corners of that box, where TV is largest, and random points inside). The
// value then moves by at most e times the spread of the taps' values. In fp64: what the GPU's float32 bound adds is
// the execution tests' (AdaptiveTaps).
TEST(ReferenceAdaptiveTaps, SkipOnlyTapsThatMoveTheBlendByLessThanE) {
    std::mt19937 rng(33);
    std::uniform_real_distribution<double> unit(0, 1);
    const double e = HexTiling::kAdaptiveError;
    for (double gamma : {1.0, 7.0, 64.0})
        for (double beta : {0.0, 0.6, 0.9, 0.995, 0.999999})
            for (double falloff : {0.5, 0.75, 0.99, 0.999999}) {
                HexTiling hex;
                hex.taps = HexTiling::kAdaptiveTaps, hex.exponent = gamma, hex.falloffcontrast = beta, hex.falloff = falloff;
                double worst = 0, fetches = 0;
                const int points = 4000;
                for (int p = 0; p < points; ++p) {
                    // Barycentric weights, uniform over the triangle, half of them near an edge (one weight < 0.02).
                    double a = unit(rng), b = unit(rng);
                    if (a + b > 1) a = 1 - a, b = 1 - b;
                    std::array<double, 3> w{a, b, 1 - a - b};
                    if (p % 2) w[size_t(p / 2 % 3)] *= 0.02;
                    const double sum = w[0] + w[1] + w[2];
                    for (double& x : w) x /= sum;
                    const std::array<bool, 3> f = adaptiveTaps(w, hex);
                    fetches += f[0] + f[1] + f[2];
                    if (f[0] && f[1] && f[2]) continue;
                    const std::array<double, 3> kept{w[0] * f[0], w[1] * f[1], w[2] * f[2]};
                    for (int corner = 0; corner < 12; ++corner) {
                        std::array<double, 3> d;
                        for (size_t i = 0; i < 3; ++i) d[i] = corner < 8 ? ((corner >> i) & 1 ? 1 : 1 - beta) : 1 - beta * unit(rng);
                        const std::array<double, 3> all = blendWeights(w, d, hex), fetched = blendWeights(kept, d, hex);
                        const double tv =
                            (std::abs(all[0] - fetched[0]) + std::abs(all[1] - fetched[1]) + std::abs(all[2] - fetched[2])) / 2;
                        worst = std::max(worst, tv);
                    }
                }
                std::printf("  exponent %2.0f falloffcontrast %-8g falloff %-8g: fetches %.2f, largest TV %.4f e\n", gamma, beta, falloff,
                            fetches / points, worst / e);
                EXPECT_LT(worst, e) << "exponent " << gamma << " falloffcontrast " << beta << " falloff " << falloff;
            }
}

}  // namespace
