// The CPU oracle in stable mode: the checker and noise masks and the per-tile transforms, against closed forms and
// the properties the documentation promises.
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

// --- Masks (docs/material-format.md#mask; stable mode) -----------------------------------------------------

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

}  // namespace
