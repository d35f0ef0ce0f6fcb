#pragma once
// The texture generator's hashing, noise and image helpers (generate.cpp, terrain.cpp): exact integer hashes and
// + - * / sqrt only, so the PNGs are byte-identical everywhere (generate.cpp says how).
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace gen {

constexpr int kSize = 256;  // texels per side; every lattice period divides it

// ---- hashing and noise ---------------------------------------------------------------------

// "lowbias32" integer finaliser (Chris Wellons' hash-prospector): good avalanche, exact everywhere.
inline uint32_t mix32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

inline uint32_t hash3(int32_t x, int32_t y, uint32_t seed) {
    return mix32(static_cast<uint32_t>(x) ^ mix32(static_cast<uint32_t>(y) ^ mix32(seed)));
}

// Uniform in [0, 1): the top 24 bits of the hash, exact in a double.
inline double hash01(int32_t x, int32_t y, uint32_t seed) { return static_cast<double>(hash3(x, y, seed) >> 8) / 16777216.0; }

inline int wrap(int i, int period) {
    const int m = i % period;
    return m < 0 ? m + period : m;
}

inline double quintic(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
inline double lerp(double a, double b, double t) { return a + (b - a) * t; }
inline double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }
inline double smoothstep(double e0, double e1, double x) {
    const double t = clamp01((x - e0) / (e1 - e0));
    return t * t * (3.0 - 2.0 * t);
}

// Periodic 2D gradient noise. (x, y) are in lattice cells; the lattice repeats every (px, py) cells.
// Gradients come from a fixed set of 8 directions (no trigonometry). Result is roughly in [-0.7, 0.7].
inline double gradientNoise(double x, double y, int px, int py, uint32_t seed) {
    static constexpr double s = 0.70710678118654752;
    static constexpr double gx[8] = {1, -1, 0, 0, s, -s, s, -s};
    static constexpr double gy[8] = {0, 0, 1, -1, s, s, -s, -s};
    const double fx0 = std::floor(x), fy0 = std::floor(y);
    const int x0 = static_cast<int>(fx0), y0 = static_cast<int>(fy0);
    const double tx = x - fx0, ty = y - fy0;
    auto corner = [&](int dx, int dy) {
        const uint32_t g = hash3(wrap(x0 + dx, px), wrap(y0 + dy, py), seed) & 7u;
        return gx[g] * (tx - dx) + gy[g] * (ty - dy);
    };
    const double u = quintic(tx), v = quintic(ty);
    return lerp(lerp(corner(0, 0), corner(1, 0), u), lerp(corner(0, 1), corner(1, 1), u), v);
}

// Fractal sum of isotropic gradient noise over the image: `cells` lattice cells across the image at
// the first octave, doubling per octave, amplitude halving. (x, y) are in texels.
inline double fbm(double x, double y, int cells, int octaves, uint32_t seed) {
    double sum = 0.0, amplitude = 1.0, norm = 0.0;
    for (int o = 0; o < octaves; ++o) {
        const double scale = static_cast<double>(cells) / kSize;  // power of two: exact
        sum += amplitude * gradientNoise(x * scale, y * scale, cells, cells, seed + 101u * o);
        norm += amplitude;
        amplitude *= 0.5;
        cells *= 2;
    }
    return sum / norm;
}

// ---- image helpers -------------------------------------------------------------------------

inline uint8_t toByte(double v) { return static_cast<uint8_t>(std::floor(clamp01(v) * 255.0 + 0.5)); }

struct Rgb {
    double r, g, b;
};
inline Rgb mix(Rgb a, Rgb b, double t) { return {lerp(a.r, b.r, t), lerp(a.g, b.g, t), lerp(a.b, b.b, t)}; }
inline Rgb scale(Rgb a, double k) { return {a.r * k, a.g * k, a.b * k}; }

inline bool writePng(const std::filesystem::path& file, int channels, const std::vector<uint8_t>& pixels) {
    if (!stbi_write_png(file.string().c_str(), kSize, kSize, channels, pixels.data(), kSize * channels)) {
        std::fprintf(stderr, "hexc-gen-textures: cannot write %s\n", file.string().c_str());
        return false;
    }
    return true;
}

// A normal map of a periodic height field (kSize x kSize, row 0 at the top), OpenGL convention (+Y = green points
// towards the top of the image as displayed). Image rows go down, so with H the height, n ~ (-dH/dx, +dH/drow, 1).
// Central differences with wrapped neighbours keep the map tileable, and because the height is periodic the slopes
// average to zero, so the mean normal is +Z (a tilted mean would show once tiles are rotated). `bump`: height units
// -> texels, larger means steeper slopes.
inline std::vector<uint8_t> normalMap(const std::vector<double>& height, double bump) {
    auto H = [&](int x, int y) { return height[wrap(y, kSize) * kSize + wrap(x, kSize)]; };
    std::vector<uint8_t> normal(kSize * kSize * 3);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double dHdx = bump * 0.5 * (H(x + 1, y) - H(x - 1, y));
            const double dHdrow = bump * 0.5 * (H(x, y + 1) - H(x, y - 1));
            const double nx = -dHdx, ny = dHdrow, nz = 1.0;
            const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
            uint8_t* p = &normal[(y * kSize + x) * 3];
            p[0] = toByte(nx / len * 0.5 + 0.5);
            p[1] = toByte(ny / len * 0.5 + 0.5);
            p[2] = toByte(nz / len * 0.5 + 0.5);  // nz > 0, so blue >= 128
        }
    return normal;
}

}  // namespace gen

// The terrain example's layers and splat map (terrain.cpp).
bool writeTerrain(const std::filesystem::path& dir);
