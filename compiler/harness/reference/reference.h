#pragma once
// The CPU oracle: what one texture slot of a material should return at a pixel, computed in double precision
// from the paper's equations (Mikkelsen 2022, "Practical Real-Time Hex-Tiling", Eq. 1-5 and Listings 1-10),
// not from the project's GLSL, so that each can catch the other's mistakes. The execution tests and the bench
// compare lavapipe's renders against render() below.
//
// Everything is double except the tile offset hash of Listing 2, fract(sin(M v) * 43758.5453). That hash is
// chaotic: sin() of an argument in the thousands, scaled by 43758, turns one float32 rounding into a different
// offset, so it is defined by its float32 evaluation and tileOffset() evaluates it the way a GPU does.
//
// Texture sampling follows the Vulkan specification for a sampler with linear min/mag/mip filters, REPEAT
// addressing, no anisotropy, minLod 0 and no lod clamp below the last level:
//   - 8-bit sRGB texels are decoded to linear before filtering; mip level k+1 is the 2x2 box average of level k;
//   - texel centres at (i + 0.5) / size, bilinear within a level;
//   - lambda = log2(max(|(ds/dx, dt/dx) * size|, |(ds/dy, dt/dy) * size|)), Euclidean lengths, clamped to
//     [0, levels - 1]; lambda <= 0 samples level 0, otherwise levels floor(lambda) and the next are lerped.
// Where lavapipe (Mesa llvmpipe's sampler, default settings) may differ; choose views and tolerances with this in
// mind:
//   - lambda = 0.5 * log2(rho^2) with a piecewise-linear log2: exact when rho^2 is a power of two, otherwise up
//     to 0.043 lower, which moves the trilinear blend;
//   - one lambda per 2x2 pixel quad, from its first pixel (GALLIVM_PERF=no_quad_lod gives one per pixel). Rotating
//     gradients leaves rho unchanged on square textures, so this shows only where gradients vary within a quad;
//   - the runner stores each 8-bit mip level rounded to 8 bits (sRGB levels re-encoded), and builds levels of odd
//     size with a linear blit rather than a box average;
//   - sin() in the hash is the GPU's own approximation, not the C library's: an error of 1e-7 in sin moves the
//     tile offset by about 0.004 in st.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "hexc/budgets.h"
#include "hexc/image.h"
#include "hexc/material.h"

namespace hexc::reference {

// hexc render --reference holds the texture in fp64 RGBA with its mips: 32 * 4/3 bytes a texel, 716 MB at 4096x4096.
inline constexpr TexelBudget kReferenceBudget{4096, "--reference", "it holds the texture in fp64 with its mips"};

using Vec2 = std::array<double, 2>;
using Vec3 = std::array<double, 3>;
using Rgba = std::array<double, 4>;
// Integer lattice coordinates of a hex tile centre (Listing 1's vertex). Exact here; the shader keeps them
// in 32 bits, which only the hash and Listing 7's colour index see (both defined on the low 32 bits).
using TileId = std::array<int64_t, 2>;

// A texture as a Vulkan sampler sees it: linear texels in double, with the full mip chain.
class SampledTexture {
public:
    explicit SampledTexture(const Texture& texture);

    // Filtered RGBA at normalised coordinates (s, t) (t = 0 is the top row) for the given screen-space gradients
    // of (s, t), like textureGrad().
    Rgba sample(double s, double t, double dsdx, double dtdx, double dsdy, double dtdy) const;
    // The same at level of detail lambda, like textureLod().
    Rgba sampleLod(double s, double t, double lambda) const;

    int levels() const { return int(levels_.size()); }
    int width(int level) const { return levels_[size_t(level)].width; }
    int height(int level) const { return levels_[size_t(level)].height; }
    // Texel (x, y) of a level, 0 <= x < width(level), 0 <= y < height(level).
    const Rgba& texel(int level, int x, int y) const;

private:
    struct Level {
        int width = 0, height = 0;
        std::vector<Rgba> texels;  // row-major, row 0 at the top
    };
    static Rgba bilinear(const Level& level, double s, double t);
    static Level halve(const Level& prev);

    std::vector<Level> levels_;
};

// Listing 1: the lattice triangle holding st, its three tile ids and st's barycentric weights in it.
struct Triangle {
    std::array<TileId, 3> id;
    std::array<double, 3> weight;  // non-negative, sum to 1; weight[i] belongs to id[i]
};
Triangle triangleGrid(Vec2 st);
// The same from lattice ("skewed") coordinates, where each unit square holds two triangles.
Triangle triangleInSkewed(double kx, double ky);

// Listing 2: the tile's random offset in st, in [0, 1)^2, evaluated in float32 (see the top of this file).
Vec2 tileOffset(TileId id);

// The lattice triangle of st in the given mode (paper: Listing 1; stable: docs/material-format.md#mode).
Triangle lattice(Vec2 st, HashMode mode);

// A tile's random transform: the offset added to its sample point, its rotation angle (radians, already
// scaled by hex.rotation) and the texture's scale in it. Paper: Listings 2 and 6; stable: pcg3d of the id,
// with the per-tile transform settings (docs/material-format.md#per-tile-transforms).
struct TileTransform {
    Vec2 offset;
    double angle;
    double scale = 1;
};
TileTransform tileTransform(TileId id, const HexTiling& hex);

// The value noise of the noise masks (docs/material-format.md#mask) at st, in [0, 1]: maskScale cells per unit of
// st, corner values from pcg3d(cell, salt).x; salt 3 for "noise", 4 + k for noise3's k-th noise.
double valueNoise(Vec2 st, int maskScale, uint32_t salt);

// The 1-tap variant's per-pixel dither value in [0, 1): pcg3d of (column, row, 2), top 24 bits.
double ditherValue(std::array<uint32_t, 2> pixel);

// Listing 7: weights w of tiles `id` as the weights output shows them, tile i in channel (id.x - id.y) mod 3.
std::array<double, 3> hexColours(const std::array<double, 3>& w, const std::array<TileId, 3>& id);

// Eq. 5 (Perlin and Hoffert's gain) with k = log(1 - r) / log(0.5); the identity when r = 0.5.
double gain(double x, double r);

// Eq. 1, then Eq. 5 and renormalisation when falloff != 0.5: the blend weights of the three tiles, from their
// barycentric weights and the metric delta(x_i) of their samples. hex supplies exponent (gamma) and falloff (r).
std::array<double, 3> blendWeights(const std::array<double, 3>& barycentric, const std::array<double, 3>& delta, const HexTiling& hex);

// `"taps": "adaptive"` (docs/material-format.md#taps): which of the three taps are fetched, from the mask's weights
// alone: the heaviest always; the other two when a bound on what skipping them moves the result, known before sampling,
// reaches hex.kAdaptiveError (for values in [0, 1]). A tap not fetched counts with weight 0 in the blend.
std::array<bool, 3> adaptiveTaps(const std::array<double, 3>& barycentric, const HexTiling& hex);

struct SlotResult {
    Rgba value;                     // colour/scalar slots: blended RGBA; normal slots: (dH/ds, dH/dt, 0, 1), or with the
                                    // triplanar projection the world-space surface gradient (x, y, z, 1)
    std::array<double, 3> weights;  // blend weights as the weights output shows them: Listing 7 colours for the hex
                                    // mask, the mask's own order otherwise; (1, 0, 0) without hex-tiling
    // Each tile's sample, in the form of evaluateAt's value (derivatives rotated back to st), and its final weight
    // (mask, Eq. 1, gain, height) in the same order; the checker's third tile repeats its second with weight 0.
    // With the triplanar projection: those of the plane with the largest b_k (the first of equal ones).
    std::array<Rgba, 3> samples;
    std::array<double, 3> blend;
    double heightSum = 1;  // height blending: sum_j W_j max(a_j - max a + width, 0) before normalising (for error bounds)
    Rgba gaussian{};       // the histogram blend: the blended Gaussian value G of each channel, before the inverse
    double lod = 0;        // the histogram blend: the level of detail that picks the inverse's row
    // For error bounds, in the order of `samples`: each tile's weight before height blending, its metric's factor
    // delta in Eq. 1 and the texel it read (filtered, before Listing 9 for a normal map).
    std::array<double, 3> unheighted{};
    std::array<double, 3> delta{1, 1, 1};
    std::array<Rgba, 3> texels{};
    // The triplanar projection: each plane's own result (the planes with b_k > 0) and its weight b_k.
    std::vector<SlotResult> planes{};
    std::vector<double> planeWeights{};
};

// A height-blended slot's heights (docs/material-format.md#height-blending): the height slot's texture and channel,
// and the slot's transition width.
struct HeightSource {
    const SampledTexture* texture = nullptr;
    int channel = 0;
    double width = 0.2;
};

// The heights a slot of `material` blends by, loaded from its height slot's texture (none for a slot without
// height_blend).
class Heights {
public:
    Heights(const Material& material, const Slot& slot);
    const HeightSource* source() const { return texture_ ? &source_ : nullptr; }

private:
    std::unique_ptr<SampledTexture> texture_;
    HeightSource source_;
};

// The slot at st = uv * tiling with screen-space st gradients dx = d(st)/dx, dy = d(st)/dy: the slot's mask
// (docs/material-format.md#mask; hex: Listings 3 and 4) or, when slot.hex.enabled is false, one sample at st.
// Colour slots weigh tiles by luminance (Eq. 4), scalar slots by their channel's value, normal slots by slope
// (Eq. 3) of the derivative (Listing 9, flipped with slot.flipY). The texture's own srgb flag decides decoding; the
// slot's colour space is the caller's to apply when loading. HashMode::Paper follows Listings 1, 2, 5 and 6;
// HashMode::Stable its specification in docs/material-format.md; the checker and noise masks are specified for
// stable mode only (the parser rejects paper mode with them); in those, tiles turn in texel-isotropic space (the
// texture's aspect, docs/material-format.md#per-tile-transforms). `pixel`: the pixel's integer position (column, row),
// which the 1-tap variant's dither hashes. With lod "shared", every fetch samples at the level fetchTile in
// reference.cpp defines (docs/material-format.md#lod) instead of the level of its own gradients. `height`: required when the slot has height_blend (unless taps is 1,
// which cannot height-blend); its width is the one used, not slot.heightBlend's.
//
// The histogram blend (slot.hex.blend, docs/material-format.md#blend): `texture` is the slot's Gaussian texture and
// `lut` its inverse look-up table (hexc/histogram.h), both required. The tiles' Gaussian values are blended with the
// weights W_i / sqrt(sum W_j^2) (Heitz and Neyret 2018, Eq. 12) about the mean 0.5; each channel's G is mapped back by
// the table's row for the level of detail lod = log2 rho of the st gradients (as the sampler defines rho), rows
// interpolated linearly in lod and entries in G; the channels return to RGB with the table's row 0.
//
// `repeats` > 0: the periodic lattice of `hexc bake` (docs/cli.md#hexc-bake) over that many units of st, for a
// stable-mode slot with the hex or checker mask (others are refused).
SlotResult evaluateAt(const Slot& slot, const SampledTexture& texture, Vec2 st, Vec2 dx, Vec2 dy, std::array<uint32_t, 2> pixel = {0, 0},
                      const HeightSource* height = nullptr, const SampledTexture* lut = nullptr, int repeats = 0);

// HashMode::MaterialX (reference/materialx.cpp, docs/materialx.md#materialx-mode): MaterialX 1.39's hextiledimage
// (colour and scalar slots: the colour blended by luma, then the channel) or hextilednormalmap (normal slots: the
// blended surface gradient as (dH/ds, dH/dt, 0, 1)), written from MaterialX's definition of the nodes. Its tile hash
// is defined by its float32 evaluation (like Listing 2's), the rest is double. An sRGB texture is sampled as stored
// (encoded: the caller loads it so, Slot::samplerDecodes), filtered and blended so, and the blend decoded.
SlotResult evaluateMaterialX(const Slot& slot, const SampledTexture& texture, Vec2 st, Vec2 dx, Vec2 dy);

// The sRGB decoding (IEC 61966-2-1) of a stored value in [0, 1].
double decodeSrgb(double c);

// evaluateAt at st = uv * slot.hex.tiling, with uv gradients.
SlotResult evaluate(const Slot& slot, const SampledTexture& texture, double u, double v, double dudx, double dvdx, double dudy, double dvdy,
                    std::array<uint32_t, 2> pixel = {0, 0}, const HeightSource* height = nullptr, const SampledTexture* lut = nullptr,
                    int repeats = 0);

// A surface point for the triplanar projection: world position, normal (any length) and the position's
// screen-space gradients.
struct SurfacePoint {
    Vec3 position, normal, dPdx, dPdy;
};

// The slot with the triplanar projection (docs/material-format.md#triplanar-projection) at a surface point:
// each plane with b_k > 0 evaluated by evaluateAt, colours blended by b_k, normal derivatives turned into a
// world-space surface gradient.
SlotResult evaluateTriplanar(const Slot& slot, const SampledTexture& texture, const SurfacePoint& point,
                             std::array<uint32_t, 2> pixel = {0, 0}, const HeightSource* height = nullptr,
                             const SampledTexture* lut = nullptr);

// The value and weights templates' preview surface for triplanar materials: the unit sphere with u, v as
// longitude and latitude (radians), P = N = (cos v sin u, sin v, cos v cos u); dPdx, dPdy from the uv gradients.
SurfacePoint previewSphere(double u, double v, double dudx, double dvdx, double dudy, double dvdy);

// The histogram blend's way back from blended Gaussian values G at level of detail `lod`, through the slot's look-up
// table (hexc/histogram.h): each channel's inverse, then RGB kept within the texture's range.
Rgba inverseTransform(const SampledTexture& lut, const Rgba& G, double lod, bool scalar);

enum class Output { Value, Weights };  // Weights: (w.x, w.y, w.z, 1) per pixel

// Every pixel of a view, row by row (row 0 at the top), with its details: the slot at the pixel centre's uv, or
// for the triplanar projection at previewSphere of it.
// `repeats`: as evaluateAt's (uv planes only).
std::vector<SlotResult> evaluateView(const Slot& slot, const SampledTexture& texture, const View& view,
                                     const HeightSource* height = nullptr, const SampledTexture* lut = nullptr, int repeats = 0);

Image render(const Slot& slot, const SampledTexture& texture, const View& view, Output output, const HeightSource* height = nullptr,
             const SampledTexture* lut = nullptr, int repeats = 0);

// A slot's textures as the reference samples them: its own, or for the histogram blend its Gaussian texture and
// inverse look-up table, derived by hexc's precomputation (what the compiler writes) from the slot's texture file.
struct SlotTextures {
    explicit SlotTextures(const Slot& slot);
    std::unique_ptr<SampledTexture> texture, lut;  // lut: the histogram blend only
};

}  // namespace hexc::reference
