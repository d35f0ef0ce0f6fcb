// The CPU oracle's colour, scalar and normal slots against analytic textures whose hex-tiled result is known in
// closed form, plain tiling and the shared level of detail.
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

// --- Colour and scalar slots ---------------------------------------------------------------------------------

TEST(ReferenceColour, ConstantTextureGivesItsColourEverywhere) {
    const Rgba colour{0.2, 0.45, 0.7, 0.9};
    const SampledTexture tex(constantTexture(16, 16, colour));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coord(-5, 5);
    for (double rotation : {0.0, 1.0, 2.5})
        for (double falloff : {0.5, 0.75, 0.3})
            for (double tiling : {1.0, 3.0}) {
                Slot slot = hexSlot(SlotKind::Color);
                slot.hex.rotation = rotation;
                slot.hex.falloff = falloff;
                slot.hex.tiling = {tiling, 2 * tiling};
                for (int k = 0; k < 100; ++k) {
                    const double g = std::exp2(coord(rng)) / 16;  // magnified to minified
                    const SlotResult r = evaluate(slot, tex, coord(rng), coord(rng), g, 0.3 * g, -0.2 * g, g);
                    for (size_t c = 0; c < 4; ++c) EXPECT_NEAR(r.value[c], float(colour[c]), 1e-12);  // the texture stores float32
                    EXPECT_NEAR(r.weights[0] + r.weights[1] + r.weights[2], 1, 1e-12);
                    for (double w : r.weights) EXPECT_GE(w, 0);
                }
            }
}

TEST(ReferenceColour, MatchesClosedFormTexture) {
    const SampledTexture tex(floatTexture(256, 256, wave));
    Slot slot = hexSlot(SlotKind::Color);
    slot.hex.rotation = 1;
    slot.hex.falloff = 0.75;
    slot.hex.falloffcontrast = 0.6;
    slot.hex.exponent = 7;
    slot.hex.tiling = {3, 2};
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> coord(-2, 2);
    for (int k = 0; k < 500; ++k) {
        const double u = coord(rng), v = coord(rng);
        const Vec2 st{u * 3, v * 2};
        const Triangle tri = triangleGrid(st);
        std::array<Rgba, 3> x;
        std::array<double, 3> w;
        for (size_t i = 0; i < 3; ++i) {
            const Vec2 c = centre(tri.id[i]), h = tileOffset(tri.id[i]);
            const Vec2 local = rowTimesRotation({st[0] - c[0], st[1] - c[1]}, angle(tri.id[i], 1));
            x[i] = wave(local[0] + c[0] + h[0], local[1] + c[1] + h[1]);
            const double delta = 0.4 + 0.6 * (0.299 * x[i][0] + 0.587 * x[i][1] + 0.114 * x[i][2]);
            w[i] = delta * std::pow(tri.weight[i], 7);
        }
        double sum = w[0] + w[1] + w[2];
        for (double& a : w) a /= sum;
        for (double& a : w) a = a < 0.5 ? 2 * a * a : 1 - 2 * (1 - a) * (1 - a);  // Eq. 5, r = 0.75: k = 2
        sum = w[0] + w[1] + w[2];
        const SlotResult r = evaluate(slot, tex, u, v, 1e-7, 0, 0, 1e-7);  // magnified: level 0
        for (size_t c = 0; c < 4; ++c)
            EXPECT_NEAR(r.value[c], (w[0] * x[0][c] + w[1] * x[1][c] + w[2] * x[2][c]) / sum, 1e-3)
                << "uv " << u << "," << v << " channel " << c;
    }
}

TEST(ReferenceScalar, WeighsTilesByItsChannel) {
    // Scalar slot on alpha = p versus colour slot on grey (p, p, p), whose luminance is p: same weights.
    const auto p = [](double s, double t) { return 0.5 + 0.4 * std::sin(2 * kPi * s) * std::cos(4 * kPi * t); };
    const auto q = [](double s, double t) { return 0.5 + 0.4 * std::cos(6 * kPi * s + 2 * kPi * t); };
    const SampledTexture scalarTex(floatTexture(32, 32, [&](double s, double t) { return Rgba{q(s, t), q(s, t), q(s, t), p(s, t)}; }));
    const SampledTexture greyTex(floatTexture(32, 32, [&](double s, double t) { return Rgba{p(s, t), p(s, t), p(s, t), 1}; }));
    Slot scalar = hexSlot(SlotKind::Scalar), colour = hexSlot(SlotKind::Color);
    scalar.channel = 3;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coord(-3, 3);
    double largestChange = 0;  // how far the weights move when the scalar slot reads red (q) instead
    for (int k = 0; k < 500; ++k) {
        const double u = coord(rng), v = coord(rng);
        scalar.channel = 3;
        const SlotResult a = evaluate(scalar, scalarTex, u, v, 1e-3, 0, 0, 1e-3);
        const SlotResult b = evaluate(colour, greyTex, u, v, 1e-3, 0, 0, 1e-3);
        for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(a.weights[i], b.weights[i], 1e-12);
        EXPECT_NEAR(a.value[3], b.value[0], 1e-12);
        scalar.channel = 0;
        const SlotResult c = evaluate(scalar, scalarTex, u, v, 1e-3, 0, 0, 1e-3);
        for (size_t i = 0; i < 3; ++i) largestChange = std::max(largestChange, std::abs(c.weights[i] - a.weights[i]));
    }
    EXPECT_GT(largestChange, 0.01);
}

// --- Normal slots --------------------------------------------------------------------------------------------

// Deep inside tile v, that tile's height field is H(st) = (a, -b) . R^T (st - c) in (u, v), whose gradient is
// R (a, -b); in (u, y) that is F R F (a, b) = R^T (a, b) with F = diag(1, -1): the blended derivative must be the
// slope rotated by minus the tile's angle.
TEST(ReferenceNormal, RampSlopeTurnsWithEachTile) {
    const SampledTexture tex(rampNormalMap());
    for (bool flipY : {false, true})
        for (double strength : {1.0, 0.5}) {
            Slot slot = hexSlot(SlotKind::Normal);
            slot.flipY = flipY;
            slot.hex.rotation = strength;
            const double b = flipY ? -kB : kB;  // green read as pointing down
            for (TileId v : {TileId{0, 0}, TileId{1, 0}, TileId{3, 5}, TileId{-4, 7}, TileId{-13, -2}, TileId{25, -31}})
                for (int k = 0; k < 6; ++k) {
                    const double phi = 0.3 + k * kPi / 3;  // one point in each of the tile's six triangles
                    const Vec2 c = centre(v);
                    const double u = c[0] + 0.003 * std::cos(phi), w = c[1] + 0.003 * std::sin(phi);
                    const SlotResult r = evaluate(slot, tex, u, w, 1e-3, 0, 0, 1e-3);
                    ASSERT_GT(*std::max_element(r.weights.begin(), r.weights.end()), 0.999);
                    const double theta = angle(v, strength);
                    EXPECT_NEAR(r.value[0], std::cos(theta) * kA + std::sin(theta) * b, 1e-9);
                    EXPECT_NEAR(r.value[1], -std::sin(theta) * kA + std::cos(theta) * b, 1e-9);
                    EXPECT_EQ(r.value[2], 0);
                    EXPECT_EQ(r.value[3], 1);
                }
        }
}

TEST(ReferenceNormal, MatchesClosedFormNormalMap) {
    const double k = 4;  // vM = (-a, -b, 1) / k stays inside [-1, 1]
    const SampledTexture tex(floatTexture(256, 256, [&](double s, double t) {
        const Vec2 d = slope(s, t);
        return Rgba{0.5 - 0.5 * d[0] / k, 0.5 - 0.5 * d[1] / k, 0.5 + 0.5 / k, 1};
    }));
    Slot slot = hexSlot(SlotKind::Normal);
    slot.hex.rotation = 1;
    slot.hex.falloffcontrast = 0.6;
    slot.hex.falloff = 0.5;
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> coord(-4, 4);
    for (int n = 0; n < 500; ++n) {
        const Vec2 st{coord(rng), coord(rng)};
        const Triangle tri = triangleGrid(st);
        std::array<Vec2, 3> d;
        std::array<double, 3> w;
        for (size_t i = 0; i < 3; ++i) {
            const double theta = angle(tri.id[i], 1);
            const Vec2 c = centre(tri.id[i]), h = tileOffset(tri.id[i]);
            const Vec2 local = rowTimesRotation({st[0] - c[0], st[1] - c[1]}, theta);
            const Vec2 m = slope(local[0] + c[0] + h[0], local[1] + c[1] + h[1]);
            d[i] = {std::cos(theta) * m[0] + std::sin(theta) * m[1], -std::sin(theta) * m[0] + std::cos(theta) * m[1]};  // R^T m
            const double d2 = d[i][0] * d[i][0] + d[i][1] * d[i][1];
            w[i] = (0.4 + 0.6 * std::sqrt(d2 / (1 + d2))) * std::pow(tri.weight[i], 7);
        }
        const double sum = w[0] + w[1] + w[2];
        const SlotResult r = evaluate(slot, tex, st[0], st[1], 1e-7, 0, 0, 1e-7);
        for (size_t c = 0; c < 2; ++c)
            EXPECT_NEAR(r.value[c], (w[0] * d[0][c] + w[1] * d[1][c] + w[2] * d[2][c]) / sum, 2e-3) << "st " << st[0] << "," << st[1];
    }
}

TEST(ReferenceNormal, WithoutRotationTheSlopeIsKeptEverywhere) {
    const SampledTexture tex(rampNormalMap());
    Slot slot = hexSlot(SlotKind::Normal);
    slot.hex.rotation = 0;
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> coord(-10, 10);
    for (int k = 0; k < 2000; ++k) {
        const SlotResult r = evaluate(slot, tex, coord(rng), coord(rng), 0.01, 0, 0, 0.01);
        EXPECT_NEAR(r.value[0], kA, 1e-12);
        EXPECT_NEAR(r.value[1], kB, 1e-12);
    }
    slot.hex.enabled = false;  // plain tiling reads the same slope
    const SlotResult plain = evaluate(slot, tex, 0.3, 0.6, 0.01, 0, 0, 0.01);
    EXPECT_EQ(plain.value, (Rgba{kA, kB, 0, 1}));
    EXPECT_EQ(plain.weights, (std::array<double, 3>{1, 0, 0}));
}

TEST(ReferencePlain, IsOneSampleAtTiledUv) {
    const SampledTexture tex(floatTexture(32, 16, wave));
    Slot slot = hexSlot(SlotKind::Color);
    slot.hex.enabled = false;
    slot.hex.tiling = {3, 2};
    std::mt19937 rng(19);
    std::uniform_real_distribution<double> coord(-3, 3);
    for (int k = 0; k < 200; ++k) {
        const double u = coord(rng), v = coord(rng), g = std::exp2(coord(rng)) / 32;
        const SlotResult r = evaluate(slot, tex, u, v, g, 0.5 * g, -0.25 * g, g);
        EXPECT_EQ(r.value, tex.sample(3 * u, 2 * v, 3 * g, 2 * 0.5 * g, 3 * -0.25 * g, 2 * g));
        EXPECT_EQ(r.weights, (std::array<double, 3>{1, 0, 0}));
    }
}

// Each tile samples with the view's gradients rotated into its frame. On a non-square texture that changes the
// level of detail: 64x4 columns alternating 0 and 1, two texels per pixel along u. Unrotated, that is level 1,
// where the columns average to 0.5; a rotated tile reads between levels 0 and 1.
TEST(ReferenceColour, GradientsTurnWithEachTile) {
    const SampledTexture tex(floatTexture(64, 4, [](double s, double) {
        const double column = std::floor(s * 64);
        return Rgba{std::fmod(column, 2), 0, 0, 1};
    }));
    const Slot slot = hexSlot(SlotKind::Color);
    const double g = 2.0 / 64;
    double largestChange = 0;  // against sampling with the unrotated gradients
    for (TileId v : {TileId{0, 0}, TileId{1, 0}, TileId{3, 5}, TileId{-4, 7}, TileId{-13, -2}, TileId{25, -31}}) {
        const Vec2 c = centre(v), h = tileOffset(v), st{c[0] + 0.002, c[1] + 0.001};
        const double theta = angle(v, 1);
        const Vec2 local = rowTimesRotation({st[0] - c[0], st[1] - c[1]}, theta);
        const Vec2 p{local[0] + c[0] + h[0], local[1] + c[1] + h[1]};
        const Vec2 dx = rowTimesRotation({g, 0}, theta), dy = rowTimesRotation({0, g}, theta);
        const SlotResult r = evaluate(slot, tex, st[0], st[1], g, 0, 0, g);
        ASSERT_GT(*std::max_element(r.weights.begin(), r.weights.end()), 0.999);
        EXPECT_NEAR(r.value[0], tex.sample(p[0], p[1], dx[0], dx[1], dy[0], dy[1])[0], 1e-9);
        largestChange = std::max(largestChange, std::abs(r.value[0] - tex.sample(p[0], p[1], g, 0, 0, g)[0]));
    }
    EXPECT_GT(largestChange, 0.02);
}

// lod "shared" against per-tap gradients, over random points, gradient sizes (0.3 to 40 texels per pixel) and
// directions, anisotropic footprints included, with rotation and the gain, on textures with detail at every level
// and at the highest frequency (a one-texel checkerboard, one-texel columns and rows, white noise), square,
// non-square and odd: stable mode turns tiles in texel-isotropic space, which keeps every gradient's length in texels,
// so the shared level is each tap's own level and every fetch and the blend agree to rounding.
TEST(ReferenceSharedLod, IsEachTapsLevelOnAnyTexture) {
    using Texels = std::function<Rgba(int x, int y, int w, int h)>;
    const auto noise = [](int x, int y, int c) {
        return ((uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^ uint32_t(c) * 83492791u) * 2654435761u >> 8) / 16777216.0;
    };
    const std::pair<const char*, Texels> textures[] = {
        {"smooth",
         [](int x, int y, int w, int h) {
             const double s = (x + 0.5) / w, t = (y + 0.5) / h;
             return Rgba{0.5 + 0.5 * std::sin(40 * s) * std::cos(23 * t), 0.5 + 0.5 * std::sin(57 * s * t), 0.3, 1};
         }},
        {"checker",
         [](int x, int y, int, int) {
             return Rgba{double((x + y) % 2), double((x + y + 1) % 2), 0.5, 1};
         }},
        {"columns",
         [](int x, int, int, int) {
             return Rgba{double(x % 2), 0.5, 0.5, 1};
         }},
        {"rows",
         [](int, int y, int, int) {
             return Rgba{double(y % 2), 0.5, 0.5, 1};
         }},
        {"noise",
         [&](int x, int y, int, int) {
             return Rgba{noise(x, y, 0), noise(x, y, 1), noise(x, y, 2), 1};
         }},
    };
    Slot gradients = hexSlot(SlotKind::Color);
    gradients.hex.mode = HashMode::Stable;
    gradients.hex.falloff = 0.75;
    Slot shared = gradients;
    shared.hex.lod = Lod::Shared;
    for (auto [w, h] : {std::pair{128, 128}, std::pair{128, 64}, std::pair{90, 45}, std::pair{128, 32}}) {
        double worstBlend = 0;
        for (const auto& [name, texels] : textures) {
            Texture t;
            t.width = w, t.height = h;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    for (double v : texels(x, y, w, h)) t.rgba32f.push_back(float(v));
            const SampledTexture tex(t);
            std::mt19937 rng(7);
            std::uniform_real_distribution<double> unit(0, 1);
            double largest = 0, largestFetch = 0, sum = 0;
            const int n = 3000;
            for (int i = 0; i < n; ++i) {
                const Vec2 st{unit(rng) * 8, unit(rng) * 8};
                const double size = 0.3 * std::pow(2.0, unit(rng) * 7), a = unit(rng) * 2 * kPi, aniso = 1 + 3 * unit(rng);
                const double g = size / std::sqrt(double(w) * h);
                const Vec2 dx{g * std::cos(a), g * std::sin(a)}, dy{-g / aniso * std::sin(a), g / aniso * std::cos(a)};
                const SlotResult one = evaluateAt(shared, tex, st, dx, dy), all = evaluateAt(gradients, tex, st, dx, dy);
                for (size_t c = 0; c < 3; ++c) {
                    const double d = std::abs(one.value[c] - all.value[c]);
                    largest = std::max(largest, d);
                    sum += d / 3;
                    for (size_t tap = 0; tap < 3; ++tap)
                        largestFetch = std::max(largestFetch, std::abs(one.samples[tap][c] - all.samples[tap][c]));
                }
            }
            std::printf("  %3dx%-3d %-7s: a fetch moves by at most %.2g/255, the blend by %.2g/255 (mean %.2g/255)\n", w, h, name,
                        largestFetch * 255, largest * 255, sum / n * 255);
            EXPECT_LT(largestFetch, 1e-12) << name << " " << w << "x" << h;
            worstBlend = std::max(worstBlend, largest);
        }
        EXPECT_LT(worstBlend, 1e-12) << w << "x" << h;
    }
}

}  // namespace
