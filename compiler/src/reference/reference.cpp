// The CPU oracle, from the paper's equations; see reference.h for what it models and where lavapipe may differ.
#include "reference/reference.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace hexc::reference {
namespace {

using std::numbers::pi;
using std::numbers::sqrt3;

// The exact sRGB EOTF, as Vulkan applies it to _SRGB formats before filtering.
double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// a + (b - a) * t rather than a * (1 - t) + b * t: returns a exactly when a == b, so constant textures and
// constant mip levels filter to exactly their value.
double lerp(double a, double b, double t) { return a + (b - a) * t; }

Rgba lerp(const Rgba& a, const Rgba& b, double t) {
    return {lerp(a[0], b[0], t), lerp(a[1], b[1], t), lerp(a[2], b[2], t), lerp(a[3], b[3], t)};
}

// REPEAT addressing of an integer texel coordinate (Vulkan's imod: the result is never negative).
int wrap(double i, int size) {
    const long long m = (long long)i % size;
    return int(m < 0 ? m + size : m);
}

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

// Listing 6: the tile's rotation. R = [[c, -s], [s, c]] rotates by +angle.
struct Rotation {
    double c, s;
    // R^T p: the paper's mul(p, R) with p a row vector, which turns st (and its gradients) into the tile's frame.
    Vec2 toTile(Vec2 p) const { return {c * p[0] + s * p[1], -s * p[0] + c * p[1]}; }
    // R d: the paper's mul(R, d), which brings a derivative sampled in the tile's frame back to st.
    Vec2 fromTile(Vec2 d) const { return {c * d[0] - s * d[1], s * d[0] + c * d[1]}; }
};

// `stable` mode, from its specification in docs/material-format.md (#mode): the lattice scale is 97/28
// instead of 2 sqrt(3), offsets and angles come from pcg3d of the tile id, and the sample point is taken
// relative to the tile centre. Evaluated here in double without the exact reduction the shader does: the
// reduction is an implementation detail this oracle checks, not something it repeats.
constexpr double kStableScale = 97.0 / 28.0;

Vec2 stableCentre(TileId id) { return {(id[0] + 0.5 * id[1]) / kStableScale, id[1] / 4.0}; }

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


double paperAngle(TileId id, double strength) {
    // In double: an int product could overflow for far-away tiles, and the sum is exact here for |id| < 2^26.
    const double x = id[0], y = id[1];
    double angle = std::abs(x * y) + std::abs(x + y) + pi;  // positive, so fmod needs no correction below 0
    angle = std::fmod(angle, 2 * pi);
    if (angle > pi) angle -= 2 * pi;
    return angle * strength;
}

// Listing 9: a tangent-space normal texel (in [0, 1], 0.5 = zero) to the height derivative dH/dst. The third
// component is kept away from 0 so that the derivative stays within [-128, 128]. flipY: green points down.
Vec2 normalToDerivative(const Rgba& texel, bool flipY) {
    const double x = 2 * texel[0] - 1, y = 2 * texel[1] - 1, z = 2 * texel[2] - 1;
    // 1e-20: hexc's guard for a zero vector, which Listing 9 would turn into 0/0.
    const double zm = std::max({std::abs(z), std::max(std::abs(x), std::abs(y)) / 128, 1e-20});
    return {-x / zm, -(flipY ? -y : y) / zm};
}

// Listing 7: each hex tile shows one of three colours, (id.x - id.y) mod 3, with a floor-mod (the listing adds 3
// to the negative results of HLSL's truncating %). A step to a neighbour, (+-1, 0), (0, +-1) or +-(1, -1),
// changes it by +-1 or +-2, never by 3, so neighbouring tiles (and the three tiles of a triangle) always differ.
// This restates the listing's swizzle: its vh/vl choice (on vertex1.x < vertex3.x) gives vertex2 and vertex3
// exactly these indices.
std::array<double, 3> hexColours(const std::array<double, 3>& w, const Triangle& tri) {
    std::array<double, 3> out{};
    // The difference of the 32-bit ids the shader keeps (exact while |id| < 2^31).
    for (int i = 0; i < 3; ++i) out[size_t(floorMod3(int32_t(uint32_t(tri.id[i][0]) - uint32_t(tri.id[i][1]))))] = w[i];
    return out;
}

}  // namespace

SampledTexture::SampledTexture(const Texture& texture) {
    const size_t count = size_t(std::max(texture.width, 0)) * size_t(std::max(texture.height, 0));
    if (count == 0 || (texture.isFloat() ? texture.rgba32f.size() : texture.rgba8.size()) != count * 4)
        throw std::invalid_argument("reference: texture of " + std::to_string(texture.width) + "x" +
                                    std::to_string(texture.height) + " texels has no or the wrong amount of data");

    Level base{texture.width, texture.height, std::vector<Rgba>(count)};
    std::array<double, 256> fromByte;  // 8-bit value -> linear colour channel
    for (int i = 0; i < 256; ++i) fromByte[size_t(i)] = texture.srgb ? srgbToLinear(i / 255.0) : i / 255.0;
    for (size_t i = 0; i < count; ++i) {
        Rgba& t = base.texels[i];
        if (texture.isFloat()) {
            for (size_t c = 0; c < 4; ++c) t[c] = texture.rgba32f[i * 4 + c];
        } else {
            for (size_t c = 0; c < 3; ++c) t[c] = fromByte[texture.rgba8[i * 4 + c]];
            t[3] = texture.rgba8[i * 4 + 3] / 255.0;  // alpha is linear in _SRGB formats
        }
    }
    levels_.push_back(std::move(base));

    // Each level halves (rounding down, at least 1) and averages the 2x2 block it covers; at an odd size the
    // block's second row or column is clamped onto the first.
    while (levels_.back().width > 1 || levels_.back().height > 1) {
        const Level& prev = levels_.back();
        Level next{std::max(1, prev.width / 2), std::max(1, prev.height / 2), {}};
        next.texels.resize(size_t(next.width) * size_t(next.height));
        for (int y = 0; y < next.height; ++y)
            for (int x = 0; x < next.width; ++x) {
                const int x0 = 2 * x, x1 = std::min(2 * x + 1, prev.width - 1);
                const int y0 = 2 * y, y1 = std::min(2 * y + 1, prev.height - 1);
                const auto at = [&](int px, int py) { return prev.texels[size_t(py) * prev.width + px]; };
                Rgba& t = next.texels[size_t(y) * next.width + x];
                for (size_t c = 0; c < 4; ++c)
                    t[c] = (at(x0, y0)[c] + at(x1, y0)[c] + at(x0, y1)[c] + at(x1, y1)[c]) / 4;
            }
        levels_.push_back(std::move(next));
    }
}

const Rgba& SampledTexture::texel(int level, int x, int y) const {
    const Level& l = levels_[size_t(level)];
    return l.texels[size_t(y) * l.width + x];
}

Rgba SampledTexture::bilinear(const Level& level, double s, double t) {
    // Texel centres sit at (i + 0.5) / size.
    const double x = s * level.width - 0.5, y = t * level.height - 0.5;
    const double xf = std::floor(x), yf = std::floor(y);
    const int x0 = wrap(xf, level.width), x1 = wrap(xf + 1, level.width);
    const int y0 = wrap(yf, level.height), y1 = wrap(yf + 1, level.height);
    const auto at = [&](int px, int py) { return level.texels[size_t(py) * level.width + px]; };
    return lerp(lerp(at(x0, y0), at(x1, y0), x - xf), lerp(at(x0, y1), at(x1, y1), x - xf), y - yf);
}

Rgba SampledTexture::sample(double s, double t, double dsdx, double dtdx, double dsdy, double dtdy) const {
    const double w = levels_[0].width, h = levels_[0].height;
    const double rho = std::max(std::hypot(dsdx * w, dtdx * h), std::hypot(dsdy * w, dtdy * h));
    const double lambda = std::min(std::log2(rho), double(levels() - 1));
    if (!(lambda > 0)) return bilinear(levels_[0], s, t);  // magnification (also rho = 0, where log2 is -inf)
    const int lo = int(lambda), hi = std::min(lo + 1, levels() - 1);
    const Rgba a = bilinear(levels_[size_t(lo)], s, t);
    if (hi == lo) return a;  // lambda clamped to the last level
    return lerp(a, bilinear(levels_[size_t(hi)], s, t), lambda - lo);
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
    return {{TileId{baseX + 1, baseY + 1}, TileId{baseX + 1, baseY}, TileId{baseX, baseY + 1}},
            {-z, 1 - fy, 1 - fx}};
}

Vec2 tileOffset(TileId id) {
    const float x = float(id[0]), y = float(id[1]);
    const float r0 = product(127.1f, x) + product(311.7f, y);
    const float r1 = product(269.5f, x) + product(183.3f, y);
    return {fract(product(std::sin(r0), 43758.5453f)), fract(product(std::sin(r1), 43758.5453f))};
}

double gain(double x, double r) {
    const double k = std::log(1 - r) / std::log(0.5);
    return x < 0.5 ? 0.5 * std::pow(2 * x, k) : 1 - 0.5 * std::pow(2 - 2 * x, k);
}

std::array<double, 3> blendWeights(const std::array<double, 3>& barycentric, const std::array<double, 3>& delta,
                                   const HexTiling& hex) {
    std::array<double, 3> w, plain;
    for (size_t i = 0; i < 3; ++i) {
        plain[i] = std::pow(barycentric[i], hex.exponent);
        w[i] = delta[i] * plain[i];
    }
    double sum = w[0] + w[1] + w[2];
    // hexc's guard: when every delta is 0 (falloffcontrast 1 on three black samples, 0/0 in the paper), the
    // metric is ignored.
    if (!(sum > 0)) {
        w = plain;
        sum = w[0] + w[1] + w[2];
    }
    for (double& x : w) x /= sum;
    // As in Listing 3, the gain is skipped at its identity rather than evaluated, so r = 0.5 changes nothing.
    if (hex.falloff != 0.5) {
        for (double& x : w) x = gain(x, hex.falloff);
        sum = w[0] + w[1] + w[2];
        for (double& x : w) x /= sum;
    }
    return w;
}

SlotResult evaluate(const Slot& slot, const SampledTexture& texture, double u, double v, double dudx, double dvdx,
                    double dudy, double dvdy, std::array<uint32_t, 2> pixel) {
    const HexTiling& hex = slot.hex;
    const Vec2 st{u * hex.tiling[0], v * hex.tiling[1]};
    const Vec2 dx{dudx * hex.tiling[0], dvdx * hex.tiling[1]};
    const Vec2 dy{dudy * hex.tiling[0], dvdy * hex.tiling[1]};
    const bool normal = slot.kind == SlotKind::Normal;
    const auto asValue = [](Vec2 d) { return Rgba{d[0], d[1], 0, 1}; };

    if (!hex.enabled) {
        const Rgba x = texture.sample(st[0], st[1], dx[0], dx[1], dy[0], dy[1]);
        const Rgba value = normal ? asValue(normalToDerivative(x, slot.flipY)) : x;
        return {value, {1, 0, 0}, {value, value, value}, {1, 0, 0}};
    }

    const bool paper = hex.mode == HashMode::Paper;
    const Triangle tri = lattice(st, hex.mode);
    std::array<Rgba, 3> samples;
    std::array<double, 3> delta;
    for (size_t i = 0; i < 3; ++i) {
        const TileId id = tri.id[i];
        const TileTransform tile = tileTransform(id, hex);
        const Rotation rot{std::cos(tile.angle), std::sin(tile.angle)};
        const Vec2 c = paper ? tileCentre(id) : stableCentre(id);
        // Rotate st about the tile centre into the tile's frame, then shift by the tile's offset (paper: and
        // back by the centre); the gradients rotate with it (Listings 3 and 4).
        // The texture is scaled by the tile's scale about the tile centre: sample at the local point / scale.
        const Vec2 rotated = rot.toTile({st[0] - c[0], st[1] - c[1]});
        const Vec2 local{rotated[0] / tile.scale, rotated[1] / tile.scale};
        const Vec2 p = paper ? Vec2{local[0] + c[0] + tile.offset[0], local[1] + c[1] + tile.offset[1]}
                             : Vec2{local[0] + tile.offset[0], local[1] + tile.offset[1]};
        Vec2 px = rot.toTile(dx), py = rot.toTile(dy);
        for (Vec2* g : {&px, &py}) *g = {(*g)[0] / tile.scale, (*g)[1] / tile.scale};
        const Rgba x = texture.sample(p[0], p[1], px[0], px[1], py[0], py[1]);

        double metric;
        if (normal) {
            // The sampled slope is in the tile's frame: rotate it back before weighing and blending (Listing 3).
            // Rotated back to st, and over the scale: a tile scaled by s shows H(p / s), of slope dH / s.
            const Vec2 r = rot.fromTile(normalToDerivative(x, slot.flipY));
            const Vec2 d{r[0] / tile.scale, r[1] / tile.scale};
            const double d2 = d[0] * d[0] + d[1] * d[1];
            metric = std::sqrt(d2 / (1 + d2));  // Eq. 3: sine of the normal's angle to +Z
            samples[i] = asValue(d);
        } else {
            metric = slot.kind == SlotKind::Color ? 0.299 * x[0] + 0.587 * x[1] + 0.114 * x[2]  // Eq. 4
                                                  : x[size_t(slot.channel)];
            samples[i] = x;
        }
        // hexc's guard: a negative metric (HDR texels below 0) counts as 0, so no weight turns negative.
        delta[i] = (1 - hex.falloffcontrast) + hex.falloffcontrast * std::max(metric, 0.0);
    }

    if (hex.taps == 1) {
        // One dithered tap: the pixel's hash u in [0, 1) picks the tile whose share of Eq. 1's weights (without
        // the metric, which one sample cannot weigh) covers it; that tile's sample is the result.
        const std::array<double, 3> w = blendWeights(tri.weight, {1, 1, 1}, hex);
        const double u = ditherValue(pixel);
        const size_t pick = u < w[0] ? 0 : u < w[0] + w[1] ? 1 : 2;
        std::array<double, 3> oneHot{};
        oneHot[pick] = 1;
        return {samples[pick], hexColours(oneHot, tri), {samples[pick], samples[pick], samples[pick]}, oneHot};
    }
    const std::array<double, 3> w = blendWeights(tri.weight, delta, hex);
    Rgba value{};
    for (size_t c = 0; c < 4; ++c) value[c] = w[0] * samples[0][c] + w[1] * samples[1][c] + w[2] * samples[2][c];
    if (normal) value = asValue({value[0], value[1]});  // keep (.., .., 0, 1) exact
    return {value, hexColours(w, tri), samples, w};
}

double ditherValue(std::array<uint32_t, 2> pixel) { return (pcg3d({pixel[0], pixel[1], 2u})[0] >> 8) / 16777216.0; }

Triangle lattice(Vec2 st, HashMode mode) {
    return mode == HashMode::Paper ? triangleGrid(st) : triangleInSkewed(kStableScale * st[0] - 2 * st[1], 4 * st[1]);
}

TileTransform tileTransform(TileId id, const HexTiling& hex) {
    if (hex.mode == HashMode::Paper) return {tileOffset(id), paperAngle(id, hex.rotation)};
    // Three numbers in [0, 1) from the top 24 bits of pcg3d(id, 0), a fourth from pcg3d(id, 1).
    const auto h = pcg3d({uint32_t(id[0]), uint32_t(id[1]), 0u});
    const double unit = 1.0 / 16777216.0;
    const double ux = (h[0] >> 8) * unit, uy = (h[1] >> 8) * unit, uz = (h[2] >> 8) * unit;
    if (!hex.hasTransforms()) return {{ux, uy}, (uz * 2 - 1) * pi * hex.rotation};
    auto snap = [](double u, int steps) { return steps > 0 ? std::floor(u * steps) / steps : u; };
    const Vec2 offset{snap(ux, hex.offsetSteps[0]) * hex.offset, snap(uy, hex.offsetSteps[1]) * hex.offset};
    const double a = snap(uz, hex.rotationSteps);
    const double degrees = hex.rotationRange[0] + (hex.rotationRange[1] - hex.rotationRange[0]) * a;
    const double v = (pcg3d({uint32_t(id[0]), uint32_t(id[1]), 1u})[0] >> 8) * unit;
    return {offset, degrees * pi / 180 * hex.rotation, hex.scaleRange[0] + (hex.scaleRange[1] - hex.scaleRange[0]) * v};
}

std::vector<SlotResult> evaluateView(const Slot& slot, const SampledTexture& texture, const View& view) {
    std::vector<SlotResult> out;
    out.reserve(size_t(view.width) * size_t(view.height));
    const auto [u0, v0, u1, v1] = view.uvRect;
    const double dudx = (u1 - u0) / view.width, dvdy = (v1 - v0) / view.height;
    for (int j = 0; j < view.height; ++j)
        for (int i = 0; i < view.width; ++i) {
            const double u = u0 + (i + 0.5) / view.width * (u1 - u0), v = v0 + (j + 0.5) / view.height * (v1 - v0);
            out.push_back(evaluate(slot, texture, u, v, dudx, 0, 0, dvdy, {uint32_t(i), uint32_t(j)}));
        }
    return out;
}

Image render(const Slot& slot, const SampledTexture& texture, const View& view, Output output) {
    Image image;
    image.width = view.width;
    image.height = view.height;
    image.rgba.resize(size_t(view.width) * size_t(view.height) * 4);
    const std::vector<SlotResult> results = evaluateView(slot, texture, view);
    for (size_t p = 0; p < results.size(); ++p) {
        const SlotResult& r = results[p];
        const Rgba out = output == Output::Value ? r.value : Rgba{r.weights[0], r.weights[1], r.weights[2], 1};
        for (size_t c = 0; c < 4; ++c) image.rgba[p * 4 + c] = float(out[c]);
    }
    return image;
}

}  // namespace hexc::reference
