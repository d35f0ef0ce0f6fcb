// The oracle's lattice and masks (reference.h): tile centres, the tile ids' hashes (Listing 2, pcg3d), the masks'
// taps, Listing 7's colours and each tile's random transform.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

#include "reference/internal.h"

namespace hexc::reference {
namespace {

using std::numbers::pi;
using std::numbers::sqrt3;

int floorMod3(int x) {
    const int m = x % 3;  // C++ truncates toward zero, like HLSL's %
    return m < 0 ? m + 3 : m;
}

// Float32 product rounded on its own: the volatile store keeps the compiler from fusing it with the following
// addition into an FMA, which a GPU evaluating Listing 2 as written does not do.
float product(float a, float b) {
    volatile float p = a * b;
    return p;
}

float fract(float x) { return x - std::floor(x); }

// Listing 5: the tile centre in st, ((x + y/2) / (2 sqrt(3)), (y sqrt(3)/2) / (2 sqrt(3)) = y/4). Listing 1's skew
// maps st to lattice coordinates (2 sqrt(3) s - 2 t, 4 t); this is its inverse at the integer point id.
Vec2 tileCentre(TileId id) { return {(id[0] + 0.5 * id[1]) / (2 * sqrt3), id[1] / 4.0}; }

// `stable` mode, from its specification in docs/material-format.md (#mode): the lattice scale is 97/28
// instead of 2 sqrt(3), offsets and angles come from pcg3d of the tile id, and the tile centre is added back modulo
// the texture's period. Evaluated here in double without the exact reduction the shader does: the
// reduction is an implementation detail this oracle checks, not something it repeats.
constexpr double kStableScale = 97.0 / 28.0;

Vec2 stableCentre(TileId id) { return {(id[0] + 0.5 * id[1]) / kStableScale, id[1] / 4.0}; }

// The same centre modulo the texture's period 1, which is what stable mode adds back to a tile's sample point: c.x is
// (28 id.x + 14 id.y) / 97 and c.y is id.y / 4, so their fractions are integer remainders, exact for any id.
Vec2 stableCentreInPeriod(TileId id) {
    const auto floorMod = [](int64_t a, int64_t m) { return double(((a % m) + m) % m); };
    return {floorMod(28 * id[0] + 14 * id[1], 97) / 97, floorMod(id[1], 4) / 4};
}

// pcg3d (Jarzynski and Olano 2020), 32-bit unsigned arithmetic with wrap-around.
std::array<uint32_t, 3> pcg3d(std::array<uint32_t, 3> v) {
    for (uint32_t& x : v) x = x * 1664525u + 1013904223u;
    auto mix = [&v] {
        v[0] += v[1] * v[2];
        v[1] += v[2] * v[0];
        v[2] += v[0] * v[1];
    };
    mix();
    for (uint32_t& x : v) x ^= x >> 16u;
    mix();
    return v;
}

// 2^-24: the step of the random numbers below, and the masks' floor under a weight or a maximum.
constexpr double kTiny = 1.0 / 16777216.0;

// A random number in [0, 1): the top 24 bits of a pcg3d word.
double random24(uint32_t word) { return (word >> 8) * kTiny; }

double paperAngle(TileId id, double strength) {
    // In double: an int product could overflow for far-away tiles, and the sum is exact here for |id| < 2^26.
    const double x = id[0], y = id[1];
    double angle = std::abs(x * y) + std::abs(x + y) + pi;  // positive, so fmod needs no correction below 0
    angle = std::fmod(angle, 2 * pi);
    if (angle > pi) angle -= 2 * pi;
    return angle * strength;
}

Taps hexTaps(Vec2 st, HashMode mode) {
    const Triangle tri = lattice(st, mode);
    const bool paper = mode == HashMode::Paper;
    Taps taps{tri.id, {}, {}, tri.weight};
    for (size_t i = 0; i < 3; ++i) {
        const Vec2 c = paper ? tileCentre(tri.id[i]) : stableCentre(tri.id[i]);
        taps.local[i] = {st[0] - c[0], st[1] - c[1]};
        taps.shift[i] = paper ? c : stableCentreInPeriod(tri.id[i]);
    }
    return taps;
}

// The checker and noise masks' cells: st = (kx, ky) + r and q = r * scale, so that the cell holding st + shift / scale
// is scale * (kx, ky) + floor(q + shift), with the same integers however far st is from the origin.
struct MaskFrame {
    std::array<int64_t, 2> base;  // scale * (kx, ky)
    Vec2 q;
};

MaskFrame maskFrame(Vec2 st, int scale) {
    const double kx = std::floor(st[0]), ky = std::floor(st[1]);
    return {{scale * int64_t(kx), scale * int64_t(ky)}, {(st[0] - kx) * scale, (st[1] - ky) * scale}};
}

// Two square grids, B shifted by half a cell; each cell is a tile with its own transform, sampled about its centre.
// `repeats` > 0 (hexc bake): a cell's index is taken modulo K scale before it makes the id, so that cells K units of st
// apart share their transform.
Taps checkerTaps(Vec2 st, int scale, int repeats) {
    const MaskFrame frame = maskFrame(st, scale);
    Taps taps{};
    for (int64_t grid = 0; grid < 2; ++grid) {
        const double shift = 0.5 * double(grid);
        const Vec2 corner{std::floor(frame.q[0] + shift), std::floor(frame.q[1] + shift)};
        const Vec2 f{frame.q[0] + shift - corner[0], frame.q[1] + shift - corner[1]};
        // 2A and 2B + (1, 1): the grids never share an id. TileId is wider than the shader's 32 bits; the hash
        // reads its low 32 bits, which is the shader's wrap-around.
        std::array<int64_t, 2> cell{frame.base[0] + int64_t(corner[0]), frame.base[1] + int64_t(corner[1])};
        if (repeats > 0)
            for (int64_t& c : cell) c = ((c % (repeats * scale)) + repeats * scale) % (repeats * scale);
        taps.id[size_t(grid)] = {2 * cell[0] + grid, 2 * cell[1] + grid};
        taps.local[size_t(grid)] = {(f[0] - 0.5) / scale, (f[1] - 0.5) / scale};
        // The cell's centre, corner + 1/2 - shift in q, modulo 1 in st (the frame's base is whole st units).
        const Vec2 centre{(corner[0] + 0.5 - shift) / scale, (corner[1] + 0.5 - shift) / scale};
        taps.shift[size_t(grid)] = {centre[0] - std::floor(centre[0]), centre[1] - std::floor(centre[1])};
        taps.weight[size_t(grid)] = std::min({f[0], 1 - f[0], f[1], 1 - f[1]}) + kTiny;
    }
    taps.id[2] = taps.id[1];
    taps.local[2] = taps.local[1];
    taps.shift[2] = taps.shift[1];
    // Over the larger weight: the same after Eq. 1 normalises, but w^gamma cannot underflow where both weights are
    // near 2^-24 (the points where borders of A and B cross) for any exponent up to 64.
    const double top = std::max(taps.weight[0], taps.weight[1]);
    for (size_t i = 0; i < 2; ++i) taps.weight[i] /= top;
    return taps;
}

// Three copies of the texture, each with one transform drawn like a tile's, about the st origin.
Taps noiseTaps(Vec2 st, const HexTiling& hex) {
    Taps taps{{TileId{0, 0}, TileId{1, 0}, TileId{2, 0}}, {st, st, st}, {}, {}};
    if (hex.mask == Mask::Noise) {
        // Three bands of one noise: pure copy 0 below 1/4, 1 at 1/2, 2 above 3/4.
        const double p = std::clamp(4 * valueNoise(st, hex.maskScale, 3) - 1, 0.0, 2.0);
        for (size_t i = 0; i < 3; ++i) taps.weight[i] = std::max(0.0, 1 - std::abs(p - double(i)));
    } else {
        std::array<double, 3> n;
        for (size_t k = 0; k < 3; ++k) n[k] = valueNoise(st, hex.maskScale, uint32_t(4 + k));
        const double top = std::max({n[0], n[1], n[2], kTiny});
        for (size_t k = 0; k < 3; ++k) taps.weight[k] = n[k] / top;
    }
    return taps;
}

// `hexc bake`'s periodic lattice (docs/cli.md#hexc-bake): stable mode's skew A0 = (97/28, -2; 0, 4) replaced by
// A = P / K, P = round(K A0), so that st + K e maps to skewed + P e. The triangle and centres come from the unwrapped
// ids (the texture repeats with period 1 and K is whole, so a tile K units away samples the same); the transform from
// the id reduced modulo P's lattice: id - P floor(P^-1 id), in exact integers.
Taps periodicTaps(Vec2 st, int repeats) {
    const int64_t k = repeats, a = std::llround(kStableScale * double(k)), b = -2 * k, d = 4 * k;  // P = (a, b; 0, d)
    const Triangle tri = triangleInSkewed((double(a) * st[0] + double(b) * st[1]) / double(k), double(d) * st[1] / double(k));
    const auto floorDiv = [](int64_t x, int64_t m) { return x / m - (x % m != 0 && x < 0); };  // m > 0
    Taps taps{{}, {}, {}, tri.weight};
    for (size_t i = 0; i < 3; ++i) {
        const TileId id = tri.id[i];
        // P^-1 id = (d x - b y, a y) / (a d): q = its floor, the lattice vector P q taken off.
        const int64_t det = a * d, fx = d * id[0] - b * id[1], fy = a * id[1];
        const int64_t qx = floorDiv(fx, det), qy = floorDiv(fy, det);
        taps.id[i] = {id[0] - (a * qx + b * qy), id[1] - d * qy};
        const Vec2 c{double(k * fx) / double(det), double(k * fy) / double(det)};  // A^-1 id = K P^-1 id
        taps.local[i] = {st[0] - c[0], st[1] - c[1]};
        taps.shift[i] = c;
    }
    return taps;
}

}  // namespace

Taps maskTaps(Vec2 st, const HexTiling& hex, int repeats) {
    switch (hex.mask) {
        case Mask::Hex:
            if (repeats > 0) return periodicTaps(st, repeats);
            return hexTaps(st, hex.mode);
        case Mask::Checker:
            return checkerTaps(st, hex.maskScale, repeats);
        case Mask::Noise:
        case Mask::Noise3:
            return noiseTaps(st, hex);
    }
    throw std::invalid_argument("reference: unknown mask");
}

// Listing 7: each hex tile shows one of three colours, (id.x - id.y) mod 3, with a floor-mod (the listing adds 3
// to the negative results of HLSL's truncating %). A step to a neighbour, (+-1, 0), (0, +-1) or +-(1, -1),
// changes it by +-1 or +-2, never by 3, so neighbouring tiles (and the three tiles of a triangle) always differ.
// This restates the listing's swizzle: its vh/vl choice (on vertex1.x < vertex3.x) gives vertex2 and vertex3
// exactly these indices.
std::array<double, 3> hexColours(const std::array<double, 3>& w, const std::array<TileId, 3>& id) {
    std::array<double, 3> out{};
    // The difference of the 32-bit ids the shader keeps (exact while |id| < 2^31).
    for (int i = 0; i < 3; ++i) out[size_t(floorMod3(int32_t(uint32_t(id[i][0]) - uint32_t(id[i][1]))))] = w[i];
    return out;
}

Triangle triangleGrid(Vec2 st) {
    // Scale so that neighbouring tile centres are 1 / (2 sqrt(3)) apart in st, then skew the triangle lattice
    // onto the integer grid: each unit square of the skewed space holds two lattice triangles.
    const double sx = st[0] * 2 * sqrt3, sy = st[1] * 2 * sqrt3;
    return triangleInSkewed(sx - sy / sqrt3, sy * (2 / sqrt3));
}

Triangle triangleInSkewed(double kx, double ky) {
    const double bx = std::floor(kx), by = std::floor(ky);
    const double fx = kx - bx, fy = ky - by;
    const int64_t baseX = int64_t(bx), baseY = int64_t(by);
    const double z = 1 - fx - fy;
    if (z > 0)  // lower triangle: corners base, base + (0, 1), base + (1, 0)
        return {{TileId{baseX, baseY}, TileId{baseX, baseY + 1}, TileId{baseX + 1, baseY}}, {z, fy, fx}};
    // upper triangle: corners base + (1, 1), base + (1, 0), base + (0, 1)
    return {{TileId{baseX + 1, baseY + 1}, TileId{baseX + 1, baseY}, TileId{baseX, baseY + 1}}, {-z, 1 - fy, 1 - fx}};
}

Vec2 tileOffset(TileId id) {
    const float x = float(id[0]), y = float(id[1]);
    const float r0 = product(127.1f, x) + product(311.7f, y);
    const float r1 = product(269.5f, x) + product(183.3f, y);
    return {fract(product(std::sin(r0), 43758.5453f)), fract(product(std::sin(r1), 43758.5453f))};
}

double valueNoise(Vec2 st, int maskScale, uint32_t salt) {
    const MaskFrame frame = maskFrame(st, maskScale);
    const Vec2 corner{std::floor(frame.q[0]), std::floor(frame.q[1])};
    // The cell in 32-bit unsigned arithmetic, as the shader has it (conversion to uint32_t is modulo 2^32).
    const uint32_t cx = uint32_t(frame.base[0] + int64_t(corner[0])), cy = uint32_t(frame.base[1] + int64_t(corner[1]));
    const auto h = [&](uint32_t i, uint32_t j) { return random24(pcg3d({cx + i, cy + j, salt})[0]); };
    const auto fade = [](double f) { return f * f * f * (f * (6 * f - 15) + 10); };  // quintic: C2 across cells
    const double sx = fade(frame.q[0] - corner[0]), sy = fade(frame.q[1] - corner[1]);
    return lerp(lerp(h(0, 0), h(1, 0), sx), lerp(h(0, 1), h(1, 1), sx), sy);
}

double ditherValue(std::array<uint32_t, 2> pixel) { return random24(pcg3d({pixel[0], pixel[1], 2u})[0]); }

Triangle lattice(Vec2 st, HashMode mode) {
    return mode == HashMode::Paper ? triangleGrid(st) : triangleInSkewed(kStableScale * st[0] - 2 * st[1], 4 * st[1]);
}

TileTransform tileTransform(TileId id, const HexTiling& hex) {
    if (hex.mode == HashMode::Paper) return {tileOffset(id), paperAngle(id, hex.rotation)};
    // Three numbers in [0, 1) from the top 24 bits of pcg3d(id, 0), a fourth from pcg3d(id, 1).
    const auto h = pcg3d({uint32_t(id[0]), uint32_t(id[1]), 0u});
    const double ux = random24(h[0]), uy = random24(h[1]), uz = random24(h[2]);
    if (!hex.hasTransforms()) return {{ux, uy}, (uz * 2 - 1) * pi * hex.rotation};
    auto snap = [](double u, int steps) { return steps > 0 ? std::floor(u * steps) / steps : u; };
    const Vec2 offset{snap(ux, hex.offsetSteps[0]) * hex.offset, snap(uy, hex.offsetSteps[1]) * hex.offset};
    const double a = snap(uz, hex.rotationSteps);
    const double degrees = hex.rotationRange[0] + (hex.rotationRange[1] - hex.rotationRange[0]) * a;
    const double v = random24(pcg3d({uint32_t(id[0]), uint32_t(id[1]), 1u})[0]);
    return {offset, degrees * pi / 180 * hex.rotation, hex.scaleRange[0] + (hex.scaleRange[1] - hex.scaleRange[0]) * v};
}

}  // namespace hexc::reference
