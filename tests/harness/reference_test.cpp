// The CPU oracle against facts derived independently of it: texel values a Vulkan sampler must return, lattice
// geometry, analytic textures whose hex-tiled result is known in closed form, and the paper's listings
// transcribed literally where the oracle restates them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>

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
    return {v3 == 0 ? W[2] : (v2 == 0 ? W[1] : W[0]), v3 == 1 ? W[2] : (v2 == 1 ? W[1] : W[0]), v3 == 2 ? W[2] : (v2 == 2 ? W[1] : W[0])};
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

// A constant slope (dH/du, dH/dy) = (a, b) = (0.5, 0.25), y = -v up the texture (a green-up map): tangent-space
// normal along (-a, -b, 1), stored
// unnormalised as 0.5 * n + 0.5 = (0.25, 0.375, 1), exact in float32 (Listing 9 divides by z, so the length
// does not matter).
constexpr double kA = 0.5, kB = 0.25;
Texture rampNormalMap() { return constantTexture(8, 8, {0.5 - 0.5 * kA, 0.5 - 0.5 * kB, 1, 1}); }

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

// --- Masks (docs/material-format.md#mask; stable mode) -----------------------------------------------------

Slot maskSlot(SlotKind kind, Mask mask, int maskScale = 3) {
    Slot slot;
    slot.name = "test";
    slot.kind = kind;
    slot.hex.mask = mask;
    slot.hex.maskScale = maskScale;
    return slot;
}

// Per-tile rotation, scale and offset at once, so that sample points and gradients are checked with all three.
void withTransforms(HexTiling& hex) {
    hex.scaleRange = {0.5, 2};
    hex.offset = 0.75;
}

Texture loadTestTexture(const char* name, bool srgb) {  // the tests run from the source root
    return loadTexture(std::string("materials/textures/") + name, srgb);
}

double luminance(const Rgba& c) { return 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]; }

// pcg3d as Jarzynski and Olano (2020) print it, and the docs' random number: a word's top 24 bits over 2^24.
std::array<uint32_t, 3> pcg3d(std::array<uint32_t, 3> v) {
    for (uint32_t& x : v) x = x * 1664525u + 1013904223u;
    v[0] += v[1] * v[2];
    v[1] += v[2] * v[0];
    v[2] += v[0] * v[1];
    for (uint32_t& x : v) x ^= x >> 16u;
    v[0] += v[1] * v[2];
    v[1] += v[2] * v[0];
    v[2] += v[0] * v[1];
    return v;
}
double random24(uint32_t word) { return (word >> 8) / 16777216.0; }

// The docs' checker cell of grid 0 (A) or 1 (B) that holds st: its tile id and st's position f in it.
struct Cell {
    TileId id;
    Vec2 f;
};
Cell checkerCell(Vec2 st, int maskScale, int grid) {
    const double kx = std::floor(st[0]), ky = std::floor(st[1]);
    const double qx = (st[0] - kx) * maskScale + 0.5 * grid, qy = (st[1] - ky) * maskScale + 0.5 * grid;
    const TileId cell{maskScale * int64_t(kx) + int64_t(std::floor(qx)), maskScale * int64_t(ky) + int64_t(std::floor(qy))};
    return {{2 * cell[0] + grid, 2 * cell[1] + grid}, {qx - std::floor(qx), qy - std::floor(qy)}};
}
double taper(Vec2 f) { return std::min({f[0], 1 - f[0], f[1], 1 - f[1]}); }

// Where a tile (or noise copy) samples on a square texture: the point turned into its frame, divided by its scale,
// plus the point it turns about modulo 1 (`centre`, docs/material-format.md#per-tile-transforms) and its offset.
Vec2 tilePoint(Vec2 local, const TileTransform& tile, Vec2 centre = {0, 0}) {
    const Vec2 r = rowTimesRotation(local, tile.angle);
    const auto inPeriod = [](double x) { return x - std::floor(x); };
    return {r[0] / tile.scale + inPeriod(centre[0]) + tile.offset[0], r[1] / tile.scale + inPeriod(centre[1]) + tile.offset[1]};
}

// Eq. 1 with the luminance metric and Eq. 5 at r = 0.75 (k = 2), over the mask weights of colour samples x.
template <size_t N>
std::array<double, N> blendClosedForm(const std::array<double, N>& mask, const std::array<Rgba, N>& x, double gamma) {
    std::array<double, N> w;
    for (size_t i = 0; i < N; ++i) w[i] = (0.4 + 0.6 * luminance(x[i])) * std::pow(mask[i], gamma);
    double sum = 0;
    for (double a : w) sum += a;
    for (double& a : w) a = a / sum < 0.5 ? 2 * (a / sum) * (a / sum) : 1 - 2 * (1 - a / sum) * (1 - a / sum);
    sum = 0;
    for (double a : w) sum += a;
    for (double& a : w) a /= sum;
    return w;
}

TEST(ReferenceChecker, MatchesClosedFormTexture) {
    const SampledTexture tex(floatTexture(256, 256, wave));
    Slot slot = maskSlot(SlotKind::Color, Mask::Checker);
    slot.hex.falloff = 0.75;
    withTransforms(slot.hex);
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> coord(-5, 5);
    for (int k = 0; k < 500; ++k) {
        const Vec2 st{coord(rng), coord(rng)};
        std::array<Rgba, 2> x;
        std::array<double, 2> mask;
        for (int grid = 0; grid < 2; ++grid) {
            const Cell cell = checkerCell(st, 3, grid);
            const Vec2 local{(cell.f[0] - 0.5) / 3, (cell.f[1] - 0.5) / 3};
            const Vec2 p = tilePoint(local, tileTransform(cell.id, slot.hex), {st[0] - local[0], st[1] - local[1]});
            x[size_t(grid)] = wave(p[0], p[1]);
            mask[size_t(grid)] = taper(cell.f) + 0x1p-24;
        }
        const std::array<double, 2> w = blendClosedForm(mask, x, 7);
        const SlotResult r = evaluateAt(slot, tex, st, {1e-7, 0}, {0, 1e-7});  // magnified: level 0
        for (size_t c = 0; c < 4; ++c) EXPECT_NEAR(r.value[c], w[0] * x[0][c] + w[1] * x[1][c], 1e-3) << st[0] << "," << st[1];
        EXPECT_NEAR(r.weights[0], w[0], 1e-3);  // (W_A, W_B, 0)
        EXPECT_NEAR(r.weights[1], w[1], 1e-3);
        EXPECT_EQ(r.weights[2], 0);
        EXPECT_EQ(r.blend, r.weights);
        EXPECT_EQ(r.samples[2], r.samples[1]);  // two taps: the third repeats the second
    }
}

// At a cell's centre its grid has all the weight (the other grid is at its border), so the result is that tile's
// sample at the centre (modulo 1) plus its offset, with the view's gradients turned into the tile in texel-isotropic
// space and divided by its scale. The texture is the 16:1 one of GradientsTurnWithEachTile: turning st there (the
// paper's way) would change the level of detail, turning its texels keeps it.
TEST(ReferenceChecker, CellCentresShowTheirTileWithTurnedGradients) {
    const SampledTexture tex(floatTexture(64, 4, [](double s, double) { return Rgba{std::fmod(std::floor(s * 64), 2), 0, 0, 1}; }));
    Slot slot = maskSlot(SlotKind::Color, Mask::Checker);
    withTransforms(slot.hex);
    const double g = 2.0 / 64, aspect = 16;
    // v turned by the tile's angle with u counted in texel heights: (u * aspect, v), turned, back.
    const auto turnTexels = [&](Vec2 v, double angle) {
        const Vec2 r = rowTimesRotation({v[0] * aspect, v[1]}, angle);
        return Vec2{r[0] / aspect, r[1]};
    };
    double largestChange = 0;  // against sampling with the gradients turned in st
    for (int grid = 0; grid < 2; ++grid)
        for (TileId c : {TileId{0, 0}, TileId{1, 0}, TileId{4, 5}, TileId{-4, 7}, TileId{-13, -2}, TileId{25, -31}}) {
            // A's cell c is centred at (c + 0.5) / 3, B's at c / 3; their ids are 2c and 2c + (1, 1).
            const Vec2 st{(c[0] + 0.5 * (1 - grid)) / 3, (c[1] + 0.5 * (1 - grid)) / 3};
            const TileTransform tile = tileTransform({2 * c[0] + grid, 2 * c[1] + grid}, slot.hex);
            const Vec2 p{st[0] - std::floor(st[0]) + tile.offset[0], st[1] - std::floor(st[1]) + tile.offset[1]};
            const Vec2 dx = turnTexels({g / tile.scale, 0}, tile.angle), dy = turnTexels({0, g / tile.scale}, tile.angle);
            const SlotResult r = evaluateAt(slot, tex, st, {g, 0}, {0, g});
            ASSERT_GT(r.weights[size_t(grid)], 0.999999);
            EXPECT_NEAR(r.value[0], tex.sample(p[0], p[1], dx[0], dx[1], dy[0], dy[1])[0], 1e-9);
            const Vec2 sx = rowTimesRotation({g / tile.scale, 0}, tile.angle), sy = rowTimesRotation({0, g / tile.scale}, tile.angle);
            largestChange = std::max(largestChange, std::abs(r.value[0] - tex.sample(p[0], p[1], sx[0], sx[1], sy[0], sy[1])[0]));
        }
    EXPECT_GT(largestChange, 0.02);
}

// Each grid's weight is 0 on its own cell borders, where its tile changes, so the blend is continuous across them
// (away from the points where a border of the other grid crosses).
TEST(ReferenceChecker, WeightsVanishOnTheirOwnBordersSoTheValueIsContinuous) {
    const SampledTexture tex(floatTexture(256, 256, wave));
    Slot slot = maskSlot(SlotKind::Color, Mask::Checker);
    slot.hex.falloff = 0.75;
    withTransforms(slot.hex);
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> coord(-4, 4);
    std::uniform_int_distribution<int> border(-12, 12);
    int checked = 0;
    for (int k = 0; k < 400; ++k) {
        const int grid = k % 2;
        const size_t axis = size_t(k / 2 % 2);
        Vec2 st{coord(rng), coord(rng)};
        st[axis] = (border(rng) + 0.5 * grid) / 3;                   // on a border of `grid` across `axis`
        if (taper(checkerCell(st, 3, 1 - grid).f) < 0.05) continue;  // near a crossing
        Vec2 lo = st, hi = st;
        lo[axis] -= 1e-7;
        hi[axis] += 1e-7;
        ASSERT_NE(checkerCell(lo, 3, grid).id, checkerCell(hi, 3, grid).id);  // a different tile on each side
        const SlotResult a = evaluateAt(slot, tex, lo, {1e-7, 0}, {0, 1e-7}), b = evaluateAt(slot, tex, hi, {1e-7, 0}, {0, 1e-7});
        EXPECT_LT(a.weights[size_t(grid)], 1e-12);
        EXPECT_LT(b.weights[size_t(grid)], 1e-12);
        for (size_t c = 0; c < 4; ++c) EXPECT_NEAR(a.value[c], b.value[c], 1e-5) << st[0] << "," << st[1];
        ++checked;
    }
    EXPECT_GT(checked, 200);
}

// Where borders of A and B cross, both weights are 2^-24: an equal blend, not 0/0, even at the largest exponent.
TEST(ReferenceChecker, BorderCrossingsBlendEqually) {
    const SampledTexture tex(constantTexture(4, 4, {0.2, 0.4, 0.6, 1}));
    Slot slot = maskSlot(SlotKind::Color, Mask::Checker, 2);
    slot.hex.exponent = 64;
    for (Vec2 st : {Vec2{1, 0.75}, Vec2{-2.25, 3}, Vec2{0.5, 0.25}}) {  // q = 2 r: A's f and B's f both on a border
        const SlotResult r = evaluateAt(slot, tex, st, {0.01, 0}, {0, 0.01});
        EXPECT_NEAR(r.weights[0], 0.5, 1e-12) << st[0] << "," << st[1];
        EXPECT_NEAR(r.weights[1], 0.5, 1e-12);
        EXPECT_NEAR(r.value[0], 0.2, 1e-7);
    }
}

TEST(ReferenceChecker, OneTapPicksAWeightedTileByItsShare) {
    const SampledTexture tex(floatTexture(64, 64, wave));
    Slot one = maskSlot(SlotKind::Color, Mask::Checker);
    one.hex.taps = 1;
    one.hex.falloff = 0.7;
    Slot all = one;  // the same without the metric: the weights the pick uses
    all.hex.taps = 0;
    all.hex.falloffcontrast = 0;
    std::mt19937 rng(37);
    std::uniform_real_distribution<double> coord(-6, 6);
    std::uniform_int_distribution<uint32_t> pixelIndex(0, 4095);
    const Vec2 dx{0.01, 0}, dy{0, 0.01};
    for (int k = 0; k < 2000; ++k) {
        const Vec2 st{coord(rng), coord(rng)};
        const std::array<uint32_t, 2> pixel{pixelIndex(rng), pixelIndex(rng)};
        const SlotResult r = evaluateAt(one, tex, st, dx, dy, pixel), w = evaluateAt(all, tex, st, dx, dy, pixel);
        const int pick = dominant(r.weights);
        ASSERT_EQ(r.weights[size_t(pick)], 1);
        ASSERT_LT(pick, 2);  // never the checker's empty third tap
        EXPECT_GT(w.blend[size_t(pick)], 0);
        EXPECT_EQ(pick, ditherValue(pixel) < w.blend[0] ? 0 : 1);
        EXPECT_EQ(r.value, w.samples[size_t(pick)]);
    }
    // Over many pixels at one point, tile A is picked with its weight's probability.
    Vec2 st;
    SlotResult w;
    do {
        st = {coord(rng), coord(rng)};
        w = evaluateAt(all, tex, st, dx, dy);
    } while (w.blend[0] < 0.2 || w.blend[0] > 0.8);
    int picksA = 0;
    for (uint32_t j = 0; j < 100; ++j)
        for (uint32_t i = 0; i < 100; ++i) picksA += evaluateAt(one, tex, st, dx, dy, {i, j}).weights[0] == 1;
    EXPECT_NEAR(picksA / 10000.0, w.blend[0], 0.02);  // 4 standard deviations
}

// The checker's cells are whole numbers per unit of st and its ids are 32-bit: 2 * maskscale * shift = 2^32 in st
// gives the same tiles, with the same local coordinates.
TEST(ReferenceChecker, TileIdsWrapAt32Bits) {
    const SampledTexture tex(floatTexture(64, 64, wave));
    for (int maskScale : {2, 4}) {
        const Slot slot = maskSlot(SlotKind::Color, Mask::Checker, maskScale);
        const double period = 0x1p32 / (2 * maskScale);
        for (Vec2 st : {Vec2{0.375, -0.8125}, Vec2{-3.1875, 2.0625}}) {
            const Rgba base = evaluateAt(slot, tex, st, {0.01, 0}, {0, 0.01}).value;
            EXPECT_EQ(evaluateAt(slot, tex, {st[0] + period, st[1]}, {0.01, 0}, {0, 0.01}).value, base);
            EXPECT_EQ(evaluateAt(slot, tex, {st[0], st[1] - period}, {0.01, 0}, {0, 0.01}).value, base);
            EXPECT_NE(evaluateAt(slot, tex, {st[0] + period / 2, st[1]}, {0.01, 0}, {0, 0.01}).value, base);
        }
    }
}

TEST(ReferenceNoise, ValueNoiseIsHashedAtCellCornersWithAQuinticFade) {
    const auto corner = [](int64_t x, int64_t y, uint32_t salt) { return random24(pcg3d({uint32_t(x), uint32_t(y), salt})[0]); };
    for (int maskScale : {1, 2, 5})
        for (uint32_t salt : {3u, 4u, 6u})
            for (int64_t y = -7; y <= 7; y += 2)
                for (int64_t x = -9; x <= 9; x += 3) {
                    const double ms = maskScale;
                    EXPECT_NEAR(valueNoise({x / ms, y / ms}, maskScale, salt), corner(x, y, salt), 1e-12) << x << "," << y;
                    // Halfway the fade is 1/2: the mean of the cell's corners; at a quarter it is 0.103515625.
                    const double mean =
                        (corner(x, y, salt) + corner(x + 1, y, salt) + corner(x, y + 1, salt) + corner(x + 1, y + 1, salt)) / 4;
                    EXPECT_NEAR(valueNoise({(x + 0.5) / ms, (y + 0.5) / ms}, maskScale, salt), mean, 1e-12);
                    EXPECT_NEAR(valueNoise({(x + 0.25) / ms, y / ms}, maskScale, salt),
                                corner(x, y, salt) + 0.103515625 * (corner(x + 1, y, salt) - corner(x, y, salt)), 1e-12);
                }
    // Cells are 32-bit: maskscale * shift = 2^32 in st is the same noise.
    for (Vec2 st : {Vec2{0.375, -0.8125}, Vec2{-3.1875, 2.0625}}) {
        EXPECT_EQ(valueNoise({st[0] + 0x1p31, st[1]}, 2, 3), valueNoise(st, 2, 3));
        EXPECT_EQ(valueNoise({st[0], st[1] + 0x1p30}, 4, 5), valueNoise(st, 4, 5));
    }
}

// With exponent 1, no metric and no gain, the weights are the mask's own: three bands of the noise.
TEST(ReferenceNoise, BandsSplitOneNoiseIntoThreeCopies) {
    const SampledTexture tex(floatTexture(64, 64, wave));
    Slot slot = maskSlot(SlotKind::Color, Mask::Noise);
    slot.hex.exponent = 1;
    slot.hex.falloffcontrast = 0;
    std::mt19937 rng(41);
    std::uniform_real_distribution<double> coord(-6, 6);
    int pureFirst = 0, pureLast = 0, mixed = 0;
    for (int k = 0; k < 3000; ++k) {
        const Vec2 st{coord(rng), coord(rng)};
        const double n = valueNoise(st, 3, 3);
        const SlotResult r = evaluateAt(slot, tex, st, {0.01, 0}, {0, 0.01});
        const double p = std::clamp(4 * n - 1, 0.0, 2.0);
        for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(r.weights[i], std::max(0.0, 1 - std::abs(p - double(i))), 1e-12);
        EXPECT_EQ(r.blend, r.weights);
        EXPECT_NEAR(r.weights[0] + r.weights[1] + r.weights[2], 1, 1e-12);
        EXPECT_EQ(r.weights[0] * r.weights[2], 0);  // neighbouring bands only
        if (n < 0.25) {
            EXPECT_EQ(r.weights, (std::array<double, 3>{1, 0, 0}));
            ++pureFirst;
        } else if (n > 0.75) {
            EXPECT_EQ(r.weights, (std::array<double, 3>{0, 0, 1}));
            ++pureLast;
        } else {
            ++mixed;
        }
    }
    EXPECT_GT(pureFirst, 30);
    EXPECT_GT(pureLast, 30);
    EXPECT_GT(mixed, 300);
}

// Three copies, each turned, scaled and shifted about the st origin, blended by Eq. 1 over the mask's weights.
TEST(ReferenceNoise, MatchesClosedFormTexture) {
    const SampledTexture tex(floatTexture(256, 256, wave));
    for (Mask mask : {Mask::Noise, Mask::Noise3}) {
        Slot slot = maskSlot(SlotKind::Color, mask, 2);
        slot.hex.falloff = 0.75;
        withTransforms(slot.hex);
        std::mt19937 rng(43);
        std::uniform_real_distribution<double> coord(-3, 3);
        for (int k = 0; k < 300; ++k) {
            const Vec2 st{coord(rng), coord(rng)};
            std::array<double, 3> weight;
            if (mask == Mask::Noise) {
                const double p = std::clamp(4 * valueNoise(st, 2, 3) - 1, 0.0, 2.0);
                for (size_t i = 0; i < 3; ++i) weight[i] = std::max(0.0, 1 - std::abs(p - double(i)));
            } else {
                const std::array<double, 3> n{valueNoise(st, 2, 4), valueNoise(st, 2, 5), valueNoise(st, 2, 6)};
                for (size_t i = 0; i < 3; ++i) weight[i] = n[i] / std::max({n[0], n[1], n[2], 0x1p-24});
            }
            std::array<Rgba, 3> x;
            for (size_t i = 0; i < 3; ++i) {
                const Vec2 p = tilePoint(st, tileTransform({int64_t(i), 0}, slot.hex));
                x[i] = wave(p[0], p[1]);
            }
            const std::array<double, 3> w = blendClosedForm(weight, x, 7);
            const SlotResult r = evaluateAt(slot, tex, st, {1e-7, 0}, {0, 1e-7});
            for (size_t c = 0; c < 4; ++c)
                EXPECT_NEAR(r.value[c], w[0] * x[0][c] + w[1] * x[1][c] + w[2] * x[2][c], 1e-3) << st[0] << "," << st[1];
            for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(r.weights[i], w[i], 1e-3);  // copy k in channel k
        }
    }
}

// Noise cells (including the unit borders, where the cell count restarts at maskscale * k) join without a seam.
TEST(ReferenceNoise, WeightsAreContinuousAcrossCellBorders) {
    const SampledTexture tex(floatTexture(256, 256, wave));
    for (Mask mask : {Mask::Noise, Mask::Noise3}) {
        Slot slot = maskSlot(SlotKind::Color, mask);
        slot.hex.falloff = 0.75;
        std::mt19937 rng(47);
        std::uniform_real_distribution<double> coord(-4, 4);
        std::uniform_int_distribution<int> border(-9, 9);
        for (int k = 0; k < 300; ++k) {
            const size_t axis = size_t(k % 2);
            Vec2 st{coord(rng), coord(rng)};
            st[axis] = border(rng) / 3.0;
            Vec2 lo = st, hi = st;
            lo[axis] -= 1e-10;
            hi[axis] += 1e-10;
            const SlotResult a = evaluateAt(slot, tex, lo, {1e-7, 0}, {0, 1e-7}), b = evaluateAt(slot, tex, hi, {1e-7, 0}, {0, 1e-7});
            for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(a.weights[i], b.weights[i], 1e-6) << st[0] << "," << st[1];
            for (size_t c = 0; c < 4; ++c) EXPECT_NEAR(a.value[c], b.value[c], 1e-6);
        }
    }
}

TEST(ReferenceMask, WeightsAreNonNegativeAndSumToOne) {
    const SampledTexture colour(floatTexture(64, 64, wave));
    const SampledTexture normalMap(rampNormalMap());
    std::mt19937 rng(53);
    std::uniform_real_distribution<double> near(-4, 4), far(-1e4, 1e4);
    for (Mask mask : {Mask::Hex, Mask::Checker, Mask::Noise, Mask::Noise3})
        for (SlotKind kind : {SlotKind::Color, SlotKind::Normal})
            for (int taps : {0, 1}) {
                Slot slot = maskSlot(kind, mask);
                slot.hex.taps = taps;
                slot.hex.falloff = 0.8;
                const SampledTexture& tex = kind == SlotKind::Color ? colour : normalMap;
                for (int k = 0; k < 200; ++k) {
                    const Vec2 st = k % 2 ? Vec2{near(rng), near(rng)} : Vec2{far(rng), far(rng)};
                    const SlotResult r = evaluateAt(slot, tex, st, {0.01, 0}, {0, 0.01}, {uint32_t(k), 7});
                    for (const auto& w : {r.weights, r.blend}) {
                        for (double x : w) EXPECT_GE(x, 0);
                        EXPECT_NEAR(w[0] + w[1] + w[2], 1, 1e-12);
                    }
                    if (mask == Mask::Hex) {  // the hex lattice has a fixed size: maskscale changes nothing
                        Slot other = slot;
                        other.hex.maskScale = 7;
                        EXPECT_EQ(evaluateAt(other, tex, st, {0.01, 0}, {0, 0.01}, {uint32_t(k), 7}).value, r.value);
                    }
                }
            }
}

// --- Tile transforms (stable mode; docs/material-format.md#per-tile-transforms) ------------------------------

// A 128x128 texture of 4x4 copies of one 32x32 cell whose texels all differ. Offset 0 without rotation or scale reads
// the plain texture, and offsetsteps [4, 4] shift it by whole cells only: in every mask, near the origin and far from
// it (st up to 2^24, inside the stable range). The tile centre each tap turns about is added back modulo 1.
TEST(ReferenceTransforms, OffsetZeroAndOffsetStepsKeepAGridTextureAligned) {
    const SampledTexture tex(floatTexture(128, 128, [](double s, double t) {
        const double x = std::fmod(s * 4, 1), y = std::fmod(t * 4, 1);
        return Rgba{x, y, 0.5 + 0.5 * std::sin(17 * x + 5 * y * y), 1};
    }));
    std::mt19937 rng(41);
    std::uniform_real_distribution<double> unit(0, 1);
    double largest = 0;
    for (Mask mask : {Mask::Hex, Mask::Checker, Mask::Noise, Mask::Noise3})
        for (bool steps : {false, true}) {
            Slot slot = maskSlot(SlotKind::Color, mask);
            slot.hex.falloff = 0.75;
            slot.hex.rotation = 0;
            slot.hex.offset = steps ? 1 : 0;
            if (steps) slot.hex.offsetSteps = {4, 4};
            for (double far : {0.0, 1e3, 16777216.0}) {
                for (int k = 0; k < 200; ++k) {
                    const Vec2 st{far + unit(rng) * 8 - 4, far + unit(rng) * 8 - 4};
                    const Vec2 dx{unit(rng) / 64, 0}, dy{0, unit(rng) / 64};  // up to two texels a pixel
                    const double d =
                        std::abs(evaluateAt(slot, tex, st, dx, dy).value[2] - tex.sample(st[0], st[1], dx[0], dx[1], dy[0], dy[1])[2]);
                    largest = std::max(largest, d);
                }
            }
        }
    // The sample points differ from st by whole texture periods and cells plus double rounding: at |st| = 2^24 an ulp
    // is 2^-28 st, 2^-21 of a texel, times a slope of at most 1 per texel (the cells' edges) is 5e-7.
    EXPECT_LT(largest, 1e-6);
}

// Stable mode turns each tile in texel-isotropic space: on a 300x170 ramp (red = s, green = t), two points of one
// tile read points whose distance in texels is theirs, whatever the angle, and at 90 degrees the texel vector turned by
// -90 degrees (the tile's frame). Turning st itself would stretch the distance by up to 300 / 170.
TEST(ReferenceTransforms, TilesTurnTheTexelsOfANonSquareTexture) {
    const double w = 300, h = 170;
    // Blue and alpha: the ramps shifted by half a period, which tell a read of the red and green ramps' linear part
    // from one within a texel of their wrap (where bilinear filtering mixes 1 and 0).
    const auto half = [](double x) { return x < 0.5 ? x + 0.5 : x - 0.5; };
    const SampledTexture ramp(floatTexture(300, 170, [&](double s, double t) { return Rgba{s, t, half(s), half(t)}; }));
    std::mt19937 rng(43);
    std::uniform_real_distribution<double> unit(0, 1);
    int checked = 0;
    for (bool quarter : {false, true}) {
        Slot slot = maskSlot(SlotKind::Color, Mask::Hex);
        slot.hex.mode = HashMode::Stable;
        slot.hex.rotationRange = quarter ? std::array<double, 2>{90, 90} : std::array<double, 2>{-180, 180};
        for (int k = 0; k < 300; ++k) {
            // Near a tile's centre (a lattice vertex, weight 1), two points 0.01 apart in st.
            const double ix = std::floor(unit(rng) * 200 - 100), iy = std::floor(unit(rng) * 200 - 100);
            const Vec2 c{(ix + 0.5 * iy) / (97.0 / 28), iy / 4};
            const Vec2 a{c[0] + 0.003, c[1] - 0.002}, delta{0.01 * (unit(rng) - 0.5), 0.01 * (unit(rng) - 0.5)};
            const Rgba ra = evaluateAt(slot, ramp, a, {1e-6, 0}, {0, 1e-6}).value;
            const Rgba rb = evaluateAt(slot, ramp, {a[0] + delta[0], a[1] + delta[1]}, {1e-6, 0}, {0, 1e-6}).value;
            // Away from the ramp's wrap (its jump from 1 to 0) the bilinear ramp reads the sample point itself.
            const auto inside = [&](const Rgba& r) {
                return r[0] > 0.02 && r[0] < 0.98 && r[1] > 0.02 && r[1] < 0.98 && std::abs(half(r[2]) - r[0]) < 1e-6 &&
                       std::abs(half(r[3]) - r[1]) < 1e-6;
            };
            if (!inside(ra) || !inside(rb)) continue;
            // The texels hold the ramp in float32: each read is off by up to half an ulp of 1 (6e-8), a difference of two
            // by 1.2e-7, which is 3.6e-5 of the 300 texels. Turning st instead misreads lengths of 1.5 texels by up to 40%.
            const double tolerance = 4e-5;
            const Vec2 read{(rb[0] - ra[0]) * w, (rb[1] - ra[1]) * h}, texels{delta[0] * w, delta[1] * h};
            EXPECT_NEAR(std::hypot(read[0], read[1]), std::hypot(texels[0], texels[1]), tolerance);
            if (quarter) {
                EXPECT_NEAR(read[0], texels[1], tolerance);  // R^T (x, y) at 90 degrees: (y, -x)
                EXPECT_NEAR(read[1], -texels[0], tolerance);
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, 300);
}

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

// --- Triplanar projection -----------------------------------------------------------------------------------

// The docs' planes written out: plane k samples at (P[kPlane[k][0]], P[kPlane[k][1]]) * tiling, and its derivative
// (d.x, d.y) is the world gradient with d.x on axis kPlane[k][0] and d.y on kPlane[k][1]: x (P.y, P.z) and
// (0, d.x, d.y); y (P.z, P.x) and (d.y, 0, d.x); z (P.x, P.y) and (d.x, d.y, 0).
constexpr std::array<std::array<size_t, 2>, 3> kPlane{{{1, 2}, {2, 0}, {0, 1}}};

Slot triplanarSlot(SlotKind kind, Mask mask = Mask::Hex) {
    Slot slot = maskSlot(kind, mask);
    slot.hex.projection = Projection::Triplanar;
    slot.hex.tiling = {2, 3};
    return slot;
}

std::array<double, 3> planeWeights(Vec3 n, double sharpness) {
    std::array<double, 3> b;
    for (size_t k = 0; k < 3; ++k) b[k] = std::pow(std::abs(n[k]), sharpness);
    const double sum = b[0] + b[1] + b[2];
    for (double& x : b) x /= sum;
    return b;
}

TEST(ReferenceTriplanar, AxisNormalsAreTheUvEvaluationOfTheirPlane) {
    const SampledTexture colour(floatTexture(64, 64, wave)), normalMap(loadTestTexture("rock_normal.png", false));
    std::mt19937 rng(71);
    std::uniform_real_distribution<double> coord(-3, 3), grad(-0.01, 0.01);
    for (SlotKind kind : {SlotKind::Color, SlotKind::Normal})
        for (Mask mask : {Mask::Hex, Mask::Checker}) {
            const Slot slot = triplanarSlot(kind, mask);
            const SampledTexture& tex = kind == SlotKind::Color ? colour : normalMap;
            for (int k = 0; k < 60; ++k) {
                const size_t axis = size_t(k % 3);
                const Vec3 P{coord(rng), coord(rng), coord(rng)}, dPdx{grad(rng), grad(rng), grad(rng)},
                    dPdy{grad(rng), grad(rng), grad(rng)};
                Vec3 N{0, 0, 0};
                N[axis] = k % 2 ? 2.5 : -0.5;  // any length, either side
                const auto [s, t] = kPlane[axis];
                const SlotResult r = evaluateTriplanar(slot, tex, {P, N, dPdx, dPdy}, {3, 4});
                const SlotResult e = evaluate(slot, tex, P[s], P[t], dPdx[s], dPdx[t], dPdy[s], dPdy[t], {3, 4});
                if (kind == SlotKind::Color) {
                    EXPECT_EQ(r.value, e.value);
                } else {
                    Rgba gradient{0, 0, 0, 1};
                    gradient[s] = e.value[0];
                    gradient[t] = -e.value[1];  // the derivative's y runs up the texture, along -t
                    EXPECT_EQ(r.value, gradient);
                }
                EXPECT_EQ(r.weights, e.weights);
                EXPECT_EQ(r.samples, e.samples);  // the only plane is the dominant one
                EXPECT_EQ(r.blend, e.blend);
            }
        }
}

// A linear ramp (red = s, green = t) without hex-tiling reads each plane's st back: the colour is the plane weights'
// mix of the three planes' coordinates.
TEST(ReferenceTriplanar, PlaneWeightsFollowTheNormal) {
    const SampledTexture ramp(floatTexture(256, 256, [](double s, double t) { return Rgba{s, t, 0, 1}; }));
    Slot slot = triplanarSlot(SlotKind::Color);
    slot.hex.enabled = false;
    slot.hex.tiling = {1, 1};
    std::mt19937 rng(73);
    std::uniform_real_distribution<double> inside(0.1, 0.9), direction(-1, 1);
    for (double sharpness : {1.0, 4.0, 9.5}) {
        slot.hex.planeSharpness = sharpness;
        for (int k = 0; k < 200; ++k) {
            const Vec3 P{inside(rng), inside(rng), inside(rng)}, N{direction(rng), direction(rng), direction(rng)};
            const double length = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
            const std::array<double, 3> b = planeWeights({N[0] / length, N[1] / length, N[2] / length}, sharpness);
            const SlotResult r = evaluateTriplanar(slot, ramp, {P, N, {1e-6, 0, 0}, {0, 1e-6, 0}});
            double red = 0, green = 0;
            for (size_t p = 0; p < 3; ++p) {
                red += b[p] * P[kPlane[p][0]];
                green += b[p] * P[kPlane[p][1]];
            }
            EXPECT_NEAR(r.value[0], red, 1e-6);
            EXPECT_NEAR(r.value[1], green, 1e-6);
            EXPECT_NEAR(r.value[3], 1, 1e-12);  // the plane weights sum to 1
            EXPECT_NEAR(r.weights[0], 1, 1e-12);
        }
    }
    // A zero normal weighs the planes equally.
    const Vec3 P{0.2, 0.3, 0.7};
    const SlotResult r = evaluateTriplanar(slot, ramp, {P, {0, 0, 0}, {1e-6, 0, 0}, {0, 1e-6, 0}});
    EXPECT_NEAR(r.value[0], (0.3 + 0.7 + 0.2) / 3, 1e-6);
    EXPECT_NEAR(r.value[1], (0.7 + 0.2 + 0.3) / 3, 1e-6);
}

// The surface gradient of the planes' world gradients: tangent to the surface, and the plane gradients as written.
TEST(ReferenceTriplanar, SurfaceGradientIsTangentToTheSurface) {
    const SampledTexture tex(loadTestTexture("rock_normal.png", false));
    for (Mask mask : {Mask::Hex, Mask::Noise}) {
        const Slot slot = triplanarSlot(SlotKind::Normal, mask);
        std::mt19937 rng(79);
        std::uniform_real_distribution<double> coord(-2, 2), direction(-1, 1), grad(-1e-3, 1e-3);
        for (int k = 0; k < 200; ++k) {
            const Vec3 P{coord(rng), coord(rng), coord(rng)}, N{direction(rng), direction(rng), direction(rng)};
            const Vec3 dPdx{grad(rng), grad(rng), grad(rng)}, dPdy{grad(rng), grad(rng), grad(rng)};
            const SlotResult r = evaluateTriplanar(slot, tex, {P, N, dPdx, dPdy});
            const double length = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
            const Vec3 n{N[0] / length, N[1] / length, N[2] / length};
            EXPECT_NEAR(r.value[0] * n[0] + r.value[1] * n[1] + r.value[2] * n[2], 0, 1e-12);
            EXPECT_EQ(r.value[3], 1);
            const std::array<double, 3> b = planeWeights(n, slot.hex.planeSharpness);
            Vec3 g{0, 0, 0};
            for (size_t p = 0; p < 3; ++p) {
                const auto [s, t] = kPlane[p];
                const SlotResult e = evaluate(slot, tex, P[s], P[t], dPdx[s], dPdx[t], dPdy[s], dPdy[t]);
                g[s] += b[p] * e.value[0];
                g[t] -= b[p] * e.value[1];
            }
            const double along = g[0] * n[0] + g[1] * n[1] + g[2] * n[2];
            for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(r.value[c], g[c] - along * n[c], 1e-12);
        }
    }
}

// The planes' weights and gradients do not see the normal's sign: the face opposite shows the same (mirrored) texture.
TEST(ReferenceTriplanar, OppositeFacesMatch) {
    const SampledTexture albedo(loadTestTexture("rock_albedo.png", true)), normalMap(loadTestTexture("rock_normal.png", false));
    std::mt19937 rng(83);
    std::uniform_real_distribution<double> coord(-2, 2), direction(-1, 1);
    for (SlotKind kind : {SlotKind::Color, SlotKind::Normal}) {
        const Slot slot = triplanarSlot(kind, Mask::Checker);
        const SampledTexture& tex = kind == SlotKind::Color ? albedo : normalMap;
        for (int k = 0; k < 100; ++k) {
            const Vec3 P{coord(rng), coord(rng), coord(rng)};
            const Vec3 N = k < 10 ? Vec3{0, 0, 1} : Vec3{direction(rng), direction(rng), direction(rng)};
            const SurfacePoint front{P, N, {0.01, 0, 0}, {0, 0.01, 0}}, back{P, {-N[0], -N[1], -N[2]}, front.dPdx, front.dPdy};
            const SlotResult a = evaluateTriplanar(slot, tex, front), b = evaluateTriplanar(slot, tex, back);
            EXPECT_EQ(a.value, b.value);
            EXPECT_EQ(a.weights, b.weights);
        }
    }
}

TEST(ReferenceTriplanar, PreviewSphereIsTheUnitSphereWithItsGradients) {
    const auto near = [](const Vec3& a, const Vec3& b, double tolerance) {
        for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], tolerance);
    };
    // u = 0, v = 0 faces +z; u = pi/2 turns to +x; v = pi/2 is the north pole, +y.
    near(previewSphere(0, 0, 0, 0, 0, 0).position, {0, 0, 1}, 1e-15);
    near(previewSphere(kPi / 2, 0, 0, 0, 0, 0).position, {1, 0, 0}, 1e-15);
    near(previewSphere(0.7, kPi / 2, 0, 0, 0, 0).position, {0, 1, 0}, 1e-15);
    std::mt19937 rng(89);
    std::uniform_real_distribution<double> angle(-3, 3), grad(-0.1, 0.1);
    for (int k = 0; k < 200; ++k) {
        const double u = angle(rng), v = angle(rng) / 2, dudx = grad(rng), dvdx = grad(rng), dudy = grad(rng), dvdy = grad(rng);
        const SurfacePoint p = previewSphere(u, v, dudx, dvdx, dudy, dvdy);
        EXPECT_NEAR(p.position[0] * p.position[0] + p.position[1] * p.position[1] + p.position[2] * p.position[2], 1, 1e-15);
        EXPECT_EQ(p.normal, p.position);
        near(p.position, {std::cos(v) * std::sin(u), std::sin(v), std::cos(v) * std::cos(u)}, 1e-15);
        // Central differences along the screen directions.
        const double h = 1e-5;
        const auto diff = [&](double du, double dv) {
            const Vec3 a = previewSphere(u + h * du, v + h * dv, 0, 0, 0, 0).position,
                       b = previewSphere(u - h * du, v - h * dv, 0, 0, 0, 0).position;
            return Vec3{(a[0] - b[0]) / (2 * h), (a[1] - b[1]) / (2 * h), (a[2] - b[2]) / (2 * h)};
        };
        near(p.dPdx, diff(dudx, dvdx), 1e-9);
        near(p.dPdy, diff(dudy, dvdy), 1e-9);
    }
}

TEST(ReferenceTriplanar, ViewEvaluatesThePreviewSphereAtEachPixel) {
    const SampledTexture tex(floatTexture(64, 64, wave));
    Slot slot = triplanarSlot(SlotKind::Color, Mask::Checker);
    slot.hex.taps = 1;  // the dither sees the pixel
    const View view{6, 4, {-3, -1.4, 3, 1.4}};
    const std::vector<SlotResult> results = evaluateView(slot, tex, view);
    const Image weights = render(slot, tex, view, Output::Weights);
    ASSERT_EQ(results.size(), 24u);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 6; ++i) {
            const double u = -3 + (i + 0.5) / 6 * 6, v = -1.4 + (j + 0.5) / 4 * 2.8;
            const SlotResult e = evaluateTriplanar(slot, tex, previewSphere(u, v, 1, 0, 0, 0.7), {uint32_t(i), uint32_t(j)});
            EXPECT_EQ(results[size_t(j * 6 + i)].value, e.value);
            for (size_t c = 0; c < 3; ++c) EXPECT_EQ(weights.at(i, j)[c], float(e.weights[c]));
        }
}

}  // namespace

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
