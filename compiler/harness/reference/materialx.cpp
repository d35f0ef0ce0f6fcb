// The reference of hexc's MaterialX mode (reference.h, evaluateMaterialX), written from MaterialX 1.39's definition of
// <hextiledimage> and <hextilednormalmap> (docs/materialx.md#materialx-mode), not from templates/library/materialx.glsl.
#include <algorithm>
#include <cmath>

#include "reference/reference.h"

namespace hexc::reference {
namespace {

constexpr double kPi = 3.14159265358979323846;

// MaterialX's hash of a tile id, in float32 as MaterialX's shader computes it: every step a float operation, so that a
// rounding near a wrap of fract lands where the GPU's does.
Vec2 tileRandom(TileId id) {
    auto fract = [](float x) { return x - std::floor(x); };
    const float px = float(id[0]) + 0.12345f, py = float(id[1]) + 0.12345f;
    float a = fract(px * 0.1031f), b = fract(py * 0.1030f), c = fract(px * 0.0973f);
    const float d = a * (b + 33.33f) + b * (c + 33.33f) + c * (a + 33.33f);
    a += d, b += d, c += d;
    return {fract((a + b) * c), fract((a + c) * b)};
}

// The tile centre of lattice id (Listing 5): the inverse of the skew, over 2 sqrt(3).
Vec2 centre(TileId id) {
    const double s = 2 * std::sqrt(3.0);
    return {(double(id[0]) + 0.5 * double(id[1])) / s, double(id[1]) * std::sqrt(3.0) / 2 / s};
}

// R(+angle) v.
Vec2 rotate(Vec2 v, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * v[0] - s * v[1], s * v[0] + c * v[1]};
}

// Schlick's gain with r clamped to [0.001, 0.999].
double schlick(double x, double r) {
    const double rr = std::clamp(r, 0.001, 0.999), a = (1 / rr - 2) * (1 - 2 * x);
    return x < 0.5 ? x / (a + 1) : (a - x) / (a - 1);
}

// luma_i w_i^7 normalised, then (falloff != 0.5) each through the gain and normalised again. Every luma 0 (MaterialX:
// 0 / 0): the weights of luma 1, the limit as the three lumas fall to 0 together.
std::array<double, 3> weights(const std::array<double, 3>& luma, const std::array<double, 3>& w, double falloff) {
    std::array<double, 3> W;
    for (size_t i = 0; i < 3; ++i) W[i] = luma[i] * std::pow(w[i], 7);
    if (W[0] + W[1] + W[2] == 0) return weights({1, 1, 1}, w, falloff);
    for (int pass = 0; pass < (falloff != 0.5 ? 2 : 1); ++pass) {
        if (pass == 1)
            for (double& x : W) x = schlick(x, falloff);
        const double sum = W[0] + W[1] + W[2];
        for (double& x : W) x /= sum;
    }
    return W;
}

}  // namespace

double decodeSrgb(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

namespace {

struct Tile {
    Vec2 p, dx, dy;
    double angle;
};

// A tile's sample point and gradients: angle mix(rotationrange, r.x) * rotation, scale mix(scalerange, r.y),
// offset r * offset; the point (st - c) R(+angle) / scale + c + offset.
Tile place(TileId id, Vec2 st, Vec2 dx, Vec2 dy, const HexTiling& hex) {
    const Vec2 r = tileRandom(id), c = centre(id);
    const double angle = (hex.rotationRange[0] + (hex.rotationRange[1] - hex.rotationRange[0]) * r[0]) * kPi / 180 * hex.rotation;
    const double scale = hex.scaleRange[0] + (hex.scaleRange[1] - hex.scaleRange[0]) * r[1];
    const Vec2 q = rotate({st[0] - c[0], st[1] - c[1]}, angle), gx = rotate(dx, angle), gy = rotate(dy, angle);
    return {{q[0] / scale + c[0] + r[0] * hex.offset, q[1] / scale + c[1] + r[1] * hex.offset},
            {gx[0] / scale, gx[1] / scale},
            {gy[0] / scale, gy[1] / scale},
            angle};
}

}  // namespace

SlotResult evaluateMaterialX(const Slot& slot, const SampledTexture& texture, Vec2 st, Vec2 dx, Vec2 dy) {
    const HexTiling& hex = slot.hex;
    const Triangle tri = triangleGrid(st);
    // sRGB: the texture is sampled as stored (encoded, Slot::shaderDecodes), filtered and blended so, then decoded.
    const bool srgb = slot.shaderDecodes(), normal = kindRow(slot.kind).derivative;
    SlotResult out;
    std::array<double, 3> luma{1, 1, 1};
    for (size_t i = 0; i < 3; ++i) {
        const Tile t = place(tri.id[i], st, dx, dy, hex);
        Rgba x = texture.sample(t.p[0], t.p[1], t.dx[0], t.dx[1], t.dy[0], t.dy[1]);
        if (normal) {
            // MaterialX's tangent frame turned about N by -angle: the normal's xy by R(+angle); its surface gradient.
            const Vec2 m = rotate({2 * x[0] - 1, (slot.flipY ? 1 - x[1] : x[1]) * 2 - 1}, t.angle);
            // A zero-length texel (MaterialX: NaN) is the flat normal, gradient 0.
            const double z = 2 * x[2] - 1, length = std::sqrt(m[0] * m[0] + m[1] * m[1] + z * z);
            const double g = std::max(1e-8, std::fabs(z / length)) * length;
            out.samples[i] = length > 0 ? Rgba{-m[0] / g, -m[1] / g, 0, 1} : Rgba{0, 0, 0, 1};
            continue;
        }
        out.samples[i] = x;
        const double l = hex.lumacoeffs[0] * x[0] + hex.lumacoeffs[1] * x[1] + hex.lumacoeffs[2] * x[2];
        luma[i] = 1 + (l - 1) * hex.falloffcontrast;
    }
    const std::array<double, 3> W = weights(normal ? std::array<double, 3>{1, 1, 1} : luma, tri.weight, hex.falloff);
    const std::array<double, 3> A = weights({1, 1, 1}, tri.weight, hex.falloff);
    for (size_t c = 0; c < 4; ++c) {
        const std::array<double, 3>& w = c == 3 ? A : W;
        out.value[c] = w[0] * out.samples[0][c] + w[1] * out.samples[1][c] + w[2] * out.samples[2][c];
        if (srgb && !normal && c < 3) out.value[c] = decodeSrgb(out.value[c]);
    }
    if (normal) out.value = {out.value[0], out.value[1], 0, 1};
    out.blend = W;
    out.weights = hexColours(W, tri.id);
    return out;
}

}  // namespace hexc::reference
