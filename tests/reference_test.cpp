// The CPU oracle against facts derived independently of it: texel values a Vulkan sampler must return, lattice
// geometry, analytic textures whose hex-tiled result is known in closed form, and the paper's listings
// transcribed literally where the oracle restates them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "reference/reference.h"

using namespace hexc;
using namespace hexc::reference;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSqrt3 = std::numbers::sqrt3;

Texture floatTexture(int width, int height, const std::function<Rgba(double s, double t)>& f) {
    Texture tex;
    tex.width = width;
    tex.height = height;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Rgba c = f((x + 0.5) / width, (y + 0.5) / height);  // the texel centre's value
            for (double v : c) tex.rgba32f.push_back(float(v));
        }
    return tex;
}

Texture constantTexture(int width, int height, Rgba colour) {
    return floatTexture(width, height, [&](double, double) { return colour; });
}

Slot hexSlot(SlotKind kind) {
    Slot slot;
    slot.name = "test";
    slot.kind = kind;
    slot.hex.mode = HashMode::Paper;  // the mode the oracle models
    return slot;
}

// Tile geometry written out again from the listings, to check the oracle's composition of them.
Vec2 centre(TileId v) { return {(v[0] + 0.5 * v[1]) / (2 * kSqrt3), (v[1] * kSqrt3 / 2) / (2 * kSqrt3)}; }

double angle(TileId v, double strength) {  // Listing 6
    double a = std::abs(double(v[0]) * v[1]) + std::abs(double(v[0]) + v[1]) + kPi;
    a = std::fmod(a, 2 * kPi);
    if (a > kPi) a -= 2 * kPi;
    return a * strength;
}

// mul(p, R) with p a row vector and R = float2x2(cs, -si, si, cs) filled by rows.
Vec2 rowTimesRotation(Vec2 p, double a) {
    const double r00 = std::cos(a), r01 = -std::sin(a), r10 = std::sin(a), r11 = std::cos(a);
    return {p[0] * r00 + p[1] * r10, p[0] * r01 + p[1] * r11};
}

// Listing 7, transcribed.
std::array<double, 3> listing7(std::array<double, 3> W, TileId vertex1, TileId vertex3) {
    int v1 = (vertex1[0] - vertex1[1]) % 3;
    if (v1 < 0) v1 += 3;
    const int vh = v1 < 2 ? (v1 + 1) : 0;
    const int vl = v1 > 0 ? (v1 - 1) : 2;
    const int v2 = vertex1[0] < vertex3[0] ? vl : vh;
    const int v3 = vertex1[0] < vertex3[0] ? vh : vl;
    return {v3 == 0 ? W[2] : (v2 == 0 ? W[1] : W[0]), v3 == 1 ? W[2] : (v2 == 1 ? W[1] : W[0]),
            v3 == 2 ? W[2] : (v2 == 2 ? W[1] : W[0])};
}

int dominant(const std::array<double, 3>& w) { return int(std::max_element(w.begin(), w.end()) - w.begin()); }

// Eq. 1 without gain, for a metric that is the same for all three tiles.
std::array<double, 3> powerWeights(const std::array<double, 3>& bary, double gamma) {
    std::array<double, 3> w;
    for (size_t i = 0; i < 3; ++i) w[i] = std::pow(bary[i], gamma);
    const double sum = w[0] + w[1] + w[2];
    for (double& x : w) x /= sum;
    return w;
}

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
    EXPECT_NEAR(tex.sample(0.125, 0, 1e-6, 0, 0, 1e-6)[0], (tex.texel(0, 0, 0)[0] + tex.texel(0, 0, 3)[0]) / 2,
                1e-15);
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
        return (level0(2 * x, 2 * y, c) + level0(2 * x + 1, 2 * y, c) + level0(2 * x, 2 * y + 1, c) +
                level0(2 * x + 1, 2 * y + 1, c)) / 4;
    };
    const auto bilinear = [](const std::function<double(int, int)>& texel, int size, double s, double t) {
        const double x = s * size - 0.5, y = t * size - 0.5;
        const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
        const double a = x - x0, b = y - y0;
        const auto at = [&](int i, int j) { return texel(((i % size) + size) % size, ((j % size) + size) % size); };
        return (1 - a) * (1 - b) * at(x0, y0) + a * (1 - b) * at(x0 + 1, y0) + (1 - a) * b * at(x0, y0 + 1) +
               a * b * at(x0 + 1, y0 + 1);
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
    EXPECT_NEAR(c[0], 0.50289, 1e-5);  // ((188/255 + 0.055) / 1.055)^2.4
    EXPECT_NEAR(c[3], 188 / 255.0, 1e-15);  // alpha stays linear
    // halfway between 188 and 0: the mean of the linear values, not the decoded mean of the encoded ones
    EXPECT_NEAR(tex.sample(0.5, 0.5, 1e-6, 0, 0, 1e-6)[0], 0.50289 / 2, 1e-5);
    t.srgb = false;
    EXPECT_NEAR(SampledTexture(t).sample(0.25, 0.5, 1e-6, 0, 0, 1e-6)[0], 188 / 255.0, 1e-15);
}

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
        EXPECT_NEAR(gain(x, 0.5), x, 1e-15);                          // k = 1
        EXPECT_NEAR(gain(x, 0.75), x < 0.5 ? 2 * x * x : 1 - 2 * (1 - x) * (1 - x), 1e-15);  // k = 2
        EXPECT_NEAR(gain(1 - x, 0.9), 1 - gain(x, 0.9), 1e-15);     // symmetric about (0.5, 0.5)
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
                    for (size_t c = 0; c < 4; ++c)
                        EXPECT_NEAR(r.value[c], float(colour[c]), 1e-12);  // the texture stores float32
                    EXPECT_NEAR(r.weights[0] + r.weights[1] + r.weights[2], 1, 1e-12);
                    for (double w : r.weights) EXPECT_GE(w, 0);
                }
            }
}

// A smooth periodic texture with a closed form: the hex-tiled result is Eq. 1 over the closed form at each tile's
// sample point, up to bilinear reconstruction error (about 2e-4 at 256x256). Checks sample positions (rotation
// about the centre, direction, offset), tiling, the luminance metric and the gain together.
Rgba wave(double s, double t) {
    return {0.5 + 0.3 * std::sin(2 * kPi * (s + 2 * t)), 0.5 + 0.3 * std::cos(2 * kPi * (2 * s - t)),
            0.5 + 0.3 * std::sin(2 * kPi * (3 * s + t)), 1};
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
    const SampledTexture scalarTex(floatTexture(32, 32, [&](double s, double t) {
        return Rgba{q(s, t), q(s, t), q(s, t), p(s, t)};
    }));
    const SampledTexture greyTex(floatTexture(32, 32, [&](double s, double t) {
        return Rgba{p(s, t), p(s, t), p(s, t), 1};
    }));
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

// A constant slope (dH/ds, dH/dt) = (a, b) = (0.5, 0.25): tangent-space normal along (-a, -b, 1), stored
// unnormalised as 0.5 * n + 0.5 = (0.25, 0.375, 1), exact in float32 (Listing 9 divides by z, so the length
// does not matter).
constexpr double kA = 0.5, kB = 0.25;
Texture rampNormalMap() { return constantTexture(8, 8, {0.5 - 0.5 * kA, 0.5 - 0.5 * kB, 1, 1}); }

// Deep inside tile v, that tile's height field is H(st) = (a, b) . R^T (st - c), whose gradient is R (a, b):
// the blended derivative must be the slope rotated by the tile's angle.
TEST(ReferenceNormal, RampSlopeTurnsWithEachTile) {
    const SampledTexture tex(rampNormalMap());
    for (bool flipY : {false, true})
        for (double strength : {1.0, 0.5}) {
            Slot slot = hexSlot(SlotKind::Normal);
            slot.flipY = flipY;
            slot.hex.rotation = strength;
            const double b = flipY ? -kB : kB;  // green read as pointing down
            for (TileId v : {TileId{0, 0}, TileId{1, 0}, TileId{3, 5}, TileId{-4, 7}, TileId{-13, -2},
                             TileId{25, -31}})
                for (int k = 0; k < 6; ++k) {
                    const double phi = 0.3 + k * kPi / 3;  // one point in each of the tile's six triangles
                    const Vec2 c = centre(v);
                    const double u = c[0] + 0.003 * std::cos(phi), w = c[1] + 0.003 * std::sin(phi);
                    const SlotResult r = evaluate(slot, tex, u, w, 1e-3, 0, 0, 1e-3);
                    ASSERT_GT(*std::max_element(r.weights.begin(), r.weights.end()), 0.999);
                    const double theta = angle(v, strength);
                    EXPECT_NEAR(r.value[0], std::cos(theta) * kA - std::sin(theta) * b, 1e-9);
                    EXPECT_NEAR(r.value[1], std::sin(theta) * kA + std::cos(theta) * b, 1e-9);
                    EXPECT_EQ(r.value[2], 0);
                    EXPECT_EQ(r.value[3], 1);
                }
        }
}

// A varying slope (a, b)(s, t) stored with a constant third component: Listing 9 then turns bilinear filtering
// of the texels into bilinear interpolation of (a, b) itself, so the closed form holds up to reconstruction
// error (about 2e-4 at 256x256). Checks Eq. 3's metric and the blend of rotated-back derivatives everywhere,
// not only deep inside tiles.
Vec2 slope(double s, double t) { return {1.5 * std::sin(2 * kPi * (s + t)), std::cos(2 * kPi * (2 * s - t))}; }

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
            d[i] = {std::cos(theta) * m[0] - std::sin(theta) * m[1], std::sin(theta) * m[0] + std::cos(theta) * m[1]};
            const double d2 = d[i][0] * d[i][0] + d[i][1] * d[i][1];
            w[i] = (0.4 + 0.6 * std::sqrt(d2 / (1 + d2))) * std::pow(tri.weight[i], 7);
        }
        const double sum = w[0] + w[1] + w[2];
        const SlotResult r = evaluate(slot, tex, st[0], st[1], 1e-7, 0, 0, 1e-7);
        for (size_t c = 0; c < 2; ++c)
            EXPECT_NEAR(r.value[c], (w[0] * d[0][c] + w[1] * d[1][c] + w[2] * d[2][c]) / sum, 2e-3)
                << "st " << st[0] << "," << st[1];
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
        const SlotResult r = evaluate(slot, tex, c[0] + 0.02 * std::cos(phi), c[1] + 0.02 * std::sin(phi), 0.01,
                                      0, 0, 0.01);
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
