#pragma once
// What the CPU oracle's tests share: textures made from a function, a hex-tiled slot in the mode the oracle models,
// and the paper's listings written out again, independently of the oracle.
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>

#include "reference/reference.h"

namespace hexc::reference::oracle {

constexpr double kPi = std::numbers::pi;
constexpr double kSqrt3 = std::numbers::sqrt3;

inline Texture floatTexture(int width, int height, const std::function<Rgba(double s, double t)>& f) {
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

inline Texture constantTexture(int width, int height, Rgba colour) {
    return floatTexture(width, height, [&](double, double) { return colour; });
}

inline Slot hexSlot(SlotKind kind) {
    Slot slot;
    slot.name = "test";
    slot.kind = kind;
    slot.hex.mode = HashMode::Paper;  // the mode the oracle models
    return slot;
}

// Tile geometry written out again from the listings, to check the oracle's composition of them.
inline Vec2 centre(TileId v) { return {(v[0] + 0.5 * v[1]) / (2 * kSqrt3), (v[1] * kSqrt3 / 2) / (2 * kSqrt3)}; }

inline double angle(TileId v, double strength) {  // Listing 6
    double a = std::abs(double(v[0]) * v[1]) + std::abs(double(v[0]) + v[1]) + kPi;
    a = std::fmod(a, 2 * kPi);
    if (a > kPi) a -= 2 * kPi;
    return a * strength;
}

// mul(p, R) with p a row vector and R = float2x2(cs, -si, si, cs) filled by rows.
inline Vec2 rowTimesRotation(Vec2 p, double a) {
    const double r00 = std::cos(a), r01 = -std::sin(a), r10 = std::sin(a), r11 = std::cos(a);
    return {p[0] * r00 + p[1] * r10, p[0] * r01 + p[1] * r11};
}

// Listing 7, transcribed.
inline std::array<double, 3> listing7(std::array<double, 3> W, TileId vertex1, TileId vertex3) {
    int v1 = (vertex1[0] - vertex1[1]) % 3;
    if (v1 < 0) v1 += 3;
    const int vh = v1 < 2 ? (v1 + 1) : 0;
    const int vl = v1 > 0 ? (v1 - 1) : 2;
    const int v2 = vertex1[0] < vertex3[0] ? vl : vh;
    const int v3 = vertex1[0] < vertex3[0] ? vh : vl;
    return {v3 == 0 ? W[2] : (v2 == 0 ? W[1] : W[0]), v3 == 1 ? W[2] : (v2 == 1 ? W[1] : W[0]), v3 == 2 ? W[2] : (v2 == 2 ? W[1] : W[0])};
}

inline int dominant(const std::array<double, 3>& w) { return int(std::max_element(w.begin(), w.end()) - w.begin()); }

// Eq. 1 without gain, for a metric that is the same for all three tiles.
inline std::array<double, 3> powerWeights(const std::array<double, 3>& bary, double gamma) {
    std::array<double, 3> w;
    for (size_t i = 0; i < 3; ++i) w[i] = std::pow(bary[i], gamma);
    const double sum = w[0] + w[1] + w[2];
    for (double& x : w) x /= sum;
    return w;
}

// A slot in stable mode with a mask (docs/material-format.md#mask).
inline Slot maskSlot(SlotKind kind, Mask mask, int maskScale = 3) {
    Slot slot;
    slot.name = "test";
    slot.kind = kind;
    slot.hex.mask = mask;
    slot.hex.maskScale = maskScale;
    return slot;
}

// Per-tile rotation, scale and offset at once, so that sample points and gradients are checked with all three.
inline void withTransforms(HexTiling& hex) {
    hex.scaleRange = {0.5, 2};
    hex.offset = 0.75;
}

inline Texture loadTestTexture(const char* name, bool srgb) {  // the tests run from the source root
    return loadTexture(std::string("materials/textures/") + name, srgb);
}

// A smooth periodic texture with a closed form: the hex-tiled result is Eq. 1 over the closed form at each tile's
// sample point, up to bilinear reconstruction error (about 2e-4 at 256x256). Checks sample positions (rotation
// about the centre, direction, offset), tiling, the luminance metric and the gain together.
inline Rgba wave(double s, double t) {
    return {0.5 + 0.3 * std::sin(2 * kPi * (s + 2 * t)), 0.5 + 0.3 * std::cos(2 * kPi * (2 * s - t)),
            0.5 + 0.3 * std::sin(2 * kPi * (3 * s + t)), 1};
}

// A constant slope (dH/du, dH/dy) = (a, b) = (0.5, 0.25), y = -v up the texture (a green-up map): tangent-space
// normal along (-a, -b, 1), stored
// unnormalised as 0.5 * n + 0.5 = (0.25, 0.375, 1), exact in float32 (Listing 9 divides by z, so the length
// does not matter).
constexpr double kA = 0.5, kB = 0.25;
inline Texture rampNormalMap() { return constantTexture(8, 8, {0.5 - 0.5 * kA, 0.5 - 0.5 * kB, 1, 1}); }

// A varying slope (a, b)(s, t) stored with a constant third component: Listing 9 then turns bilinear filtering
// of the texels into bilinear interpolation of (a, b) itself, so the closed form holds up to reconstruction
// error (about 2e-4 at 256x256). Checks Eq. 3's metric and the blend of rotated-back derivatives everywhere,
// not only deep inside tiles.
inline Vec2 slope(double s, double t) { return {1.5 * std::sin(2 * kPi * (s + t)), std::cos(2 * kPi * (2 * s - t))}; }

}  // namespace hexc::reference::oracle
