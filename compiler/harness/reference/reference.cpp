// The CPU oracle, from the paper's equations; see reference.h for what it models and where lavapipe may differ.
// The lattice and the masks are in lattice.cpp, texture sampling in texture.cpp.
#include "reference/reference.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "hexc/histogram.h"
#include "reference/internal.h"

namespace hexc::reference {
namespace {

// Listing 6: the tile's rotation. R = [[c, -s], [s, c]] rotates by +angle.
struct Rotation {
    double c, s;
    // The texture's width / height: stable mode turns a tile in texel-isotropic space, where a unit of length spans
    // as many texels along u as along v: q = A st with A = diag(aspect, 1). The paper (aspect 1) turns st itself.
    double aspect = 1;
    // R^T p: the paper's mul(p, R) with p a row vector, which turns a point of that space into the tile's frame.
    Vec2 rotate(Vec2 p) const { return {c * p[0] + s * p[1], -s * p[0] + c * p[1]}; }
    // st (and its gradients) into the tile's frame: A^-1 R^T A, a rotation of the texture's texels.
    Vec2 toTile(Vec2 p) const {
        const Vec2 q = rotate({p[0] * aspect, p[1]});
        return {q[0] / aspect, q[1]};
    }
    // A derivative (dH/dx, dH/dy), y = -v, sampled in the tile's frame, back: the slopes of a normal map are per unit
    // of texel-isotropic space (square texels, as a baker writes them), where the tile reads h(R^T q + c). So the
    // gradient is R grad h (the paper's mul(R, d), for y along +v); with F = diag(1, -1) for y along -v it is
    // F R F = R^T: the same rotation as into the tile, without the aspect.
    Vec2 fromTile(Vec2 d) const { return rotate(d); }
};

// Listing 9: a tangent-space normal texel (in [0, 1], 0.5 = zero) to the height derivative dH/dst. The third
// component is kept away from 0 so that the derivative stays within [-128, 128]. flipY: green points down.
Vec2 normalToDerivative(const Rgba& texel, bool flipY) {
    const double x = 2 * texel[0] - 1, y = 2 * texel[1] - 1, z = 2 * texel[2] - 1;
    // 1e-20: hexc's guard for a zero vector, which Listing 9 would turn into 0/0.
    const double zm = std::max({std::abs(z), std::max(std::abs(x), std::abs(y)) / 128, 1e-20});
    return {-x / zm, -(flipY ? -y : y) / zm};
}

// docs/material-format.md#height-blending: each weight times how far its tile's weighted height comes within
// `width` of the highest, renormalised. `sum`: the sum before renormalising.
std::array<double, 3> heightBlend(const std::array<double, 3>& w, const std::array<double, 3>& h, double width, double& sum) {
    std::array<double, 3> a;
    for (size_t i = 0; i < 3; ++i) a[i] = std::max(h[i], 0.0) * w[i];
    const double top = std::max({a[0], a[1], a[2]});
    std::array<double, 3> out;
    for (size_t i = 0; i < 3; ++i) out[i] = w[i] * std::max(a[i] - top + width, 0.0);
    sum = out[0] + out[1] + out[2];
    for (double& x : out) x /= sum;
    return out;
}

}  // namespace

double gain(double x, double r) {
    const double k = std::log(1 - r) / std::log(0.5);
    return x < 0.5 ? 0.5 * std::pow(2 * x, k) : 1 - 0.5 * std::pow(2 - 2 * x, k);
}

std::array<double, 3> blendWeights(const std::array<double, 3>& barycentric, const std::array<double, 3>& delta, const HexTiling& hex) {
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

std::array<bool, 3> adaptiveTaps(const std::array<double, 3>& barycentric, const HexTiling& hex) {
    const double e = HexTiling::kAdaptiveError, beta = hex.falloffcontrast;
    const bool gained = hex.falloff != 0.5;
    const auto g = [&](double x) { return gained ? gain(x, hex.falloff) : x; };
    std::array<double, 3> p;
    for (size_t i = 0; i < 3; ++i) p[i] = std::pow(barycentric[i], hex.exponent);
    // Tap i's weight before the gain is W_i = delta_i p_i / sum_j delta_j p_j with each delta in [1 - beta, 1] (Eq. 3-4
    // for a metric in [0, 1]): largest with delta_i = 1 and the others 1 - beta, smallest the other way round.
    std::array<double, 3> most, least;
    for (size_t i = 0; i < 3; ++i) {
        const double rest = p[0] + p[1] + p[2] - p[i];
        most[i] = p[i] > 0 ? p[i] / (p[i] + (1 - beta) * rest) : 0;
        least[i] = p[i] > 0 ? (1 - beta) * p[i] / ((1 - beta) * p[i] + rest) : 0;
    }
    // After the gain and its renormalisation: the gained weight of the largest W_i over the gained ones of the others'
    // smallest.
    std::array<double, 3> finalMost, cost;
    for (size_t i = 0; i < 3; ++i) {
        double others = 0;
        for (size_t j = 0; j < 3; ++j)
            if (j != i) others += g(least[j]);
        finalMost[i] = most[i] > 0 ? g(most[i]) / (g(most[i]) + others) : 0;
        // Skipped alone, the two kept taps' weights grow by 1 / (1 - W_i) before the gain: their shares move by at most
        // k/4 ln(1 / (1 - W_i)) (docs/material-format.md#taps).
        const double k = gained ? std::log(1 - hex.falloff) / std::log(0.5) : 0;
        cost[i] = most[i] < 1 ? finalMost[i] + k / 4 * std::log(1 / (1 - most[i])) : INFINITY;
    }
    const size_t top = size_t(std::max_element(barycentric.begin(), barycentric.end()) - barycentric.begin());
    const size_t a = top == 0 ? 1 : 0, b = top == 2 ? 1 : 2;
    std::array<bool, 3> fetched{true, true, true};
    if (finalMost[a] + finalMost[b] < e)
        fetched[a] = fetched[b] = false;
    else if (std::min(cost[a], cost[b]) < e)
        fetched[cost[a] <= cost[b] ? a : b] = false;
    return fetched;
}

// The histogram blend's way back (reference.h, evaluateAt): G of each channel, the level of detail, the table.
Rgba inverseTransform(const SampledTexture& lut, const Rgba& G, double lod, bool scalar) {
    const double width = lut.width(0), rows = lut.height(0);
    // Row 1 + lod, entry x where histogramLutGaussian(x) = G, at texel centres: s = (x + 0.5) / width, t = (y + 0.5) / rows.
    const double t = (1.5 + std::clamp(lod, 0.0, rows - 2)) / rows;
    std::array<double, 3> q{};
    for (size_t k = 0; k < (scalar ? 1 : 3); ++k) {
        const double x = std::clamp((G[k] - 0.5) * 6 / (2 * kHistogramLutSigmas) + 0.5, 0.0, 1.0) * (width - 1);
        q[k] = lut.sample((x + 0.5) / width, t, 0, 0, 0, 0)[k];
    }
    if (scalar) return {q[0], q[0], q[0], q[0]};
    Rgba rgb = lut.texel(0, 3, 0);
    for (size_t k = 0; k < 3; ++k)
        for (size_t c = 0; c < 3; ++c) rgb[c] += q[k] * lut.texel(0, int(k), 0)[c];
    // Within the texture's range, which the sum over the axes may leave.
    for (size_t c = 0; c < 3; ++c) rgb[c] = std::clamp(rgb[c], lut.texel(0, 4, 0)[c], lut.texel(0, 5, 0)[c]);
    rgb[3] = 1;
    return rgb;
}

// Heitz and Neyret's variance-preserving blend of the tiles' Gaussian samples, then the way back.
SlotResult histogramBlend(const SampledTexture& lut, const std::array<Rgba, 3>& samples, const std::array<double, 3>& w, Vec2 dx, Vec2 dy,
                          double size0, double size1, bool scalar) {
    SlotResult r{};
    const double norm = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    for (size_t c = 0; c < 4; ++c)
        r.gaussian[c] = (w[0] * (samples[0][c] - 0.5) + w[1] * (samples[1][c] - 0.5) + w[2] * (samples[2][c] - 0.5)) / norm + 0.5;
    const double rho2 =
        std::max(std::pow(dx[0] * size0, 2) + std::pow(dx[1] * size1, 2), std::pow(dy[0] * size0, 2) + std::pow(dy[1] * size1, 2));
    r.lod = 0.5 * std::log2(std::max(rho2, 1e-30));
    r.value = inverseTransform(lut, r.gaussian, r.lod, scalar);
    r.samples = samples;
    r.blend = w;
    return r;
}

namespace {

// A tile's sample point, its gradients (rotated and scaled with the tile) and the tile's texture scale.
struct Fetch {
    Vec2 p, dx, dy;
    double scale = 1;
};

// A tile's texel from `texture` (docs/material-format.md#lod): filtered with the tile's own gradients, or with lod
// "shared" at one level for the slot: rho, as the sampler defines it, of the unrotated st gradients dx, dy (lengths
// in texels), over the tile's scale (the texture at scale s shows 1/s as many texels per unit of st).
Rgba fetchTile(const SampledTexture& texture, const Fetch& f, const HexTiling& hex, Vec2 dx, Vec2 dy) {
    if (hex.lod == Lod::Gradients) return texture.sample(f.p[0], f.p[1], f.dx[0], f.dx[1], f.dy[0], f.dy[1]);
    const double w = texture.width(0), h = texture.height(0);
    const double rho = std::max(std::hypot(dx[0] * w, dx[1] * h), std::hypot(dy[0] * w, dy[1] * h));
    return texture.sampleLod(f.p[0], f.p[1], std::log2(rho / f.scale));
}

// A derivative as evaluateAt returns it: (dH/ds, dH/dt, 0, 1).
Rgba asValue(Vec2 d) { return Rgba{d[0], d[1], 0, 1}; }

// The slot without hex-tiling: one sample at st.
SlotResult untiled(const Slot& slot, const SampledTexture& texture, Vec2 st, Vec2 dx, Vec2 dy) {
    Rgba x = texture.sample(st[0], st[1], dx[0], dx[1], dy[0], dy[1]);
    // MaterialX mode's sRGB texture is sampled as stored and decoded after filtering, as MaterialX's <image> does.
    for (size_t c = 0; slot.shaderDecodes() && c < 3; ++c) x[c] = decodeSrgb(x[c]);
    const Rgba value = kindRow(slot.kind).derivative ? asValue(normalToDerivative(x, slot.flipY)) : x;
    return {value, {1, 0, 0}, {value, value, value}, {1, 0, 0}};
}

// Listing 7's colours for the hex mask; the other masks show their weights in their own order.
std::array<double, 3> shown(const HexTiling& hex, const Taps& taps, const std::array<double, 3>& w) {
    return hex.mask == Mask::Hex ? hexColours(w, taps.id) : w;
}

// The three tiles, each sampled with its own transform: where it was fetched, its sample in the form of evaluateAt's
// value (a normal slot's derivative rotated back to st) and delta(x_i), its metric's factor in Eq. 1. A tap not
// fetched reads the texel (0, 0, 0, 0).
struct Tiles {
    std::array<Fetch, 3> fetch;
    std::array<Rgba, 3> samples;
    std::array<double, 3> delta;
    std::array<Rgba, 3> texels;
};

Tiles sampleTiles(const Slot& slot, const SampledTexture& texture, const Taps& taps, const std::array<bool, 3>& fetched, Vec2 dx, Vec2 dy) {
    const HexTiling& hex = slot.hex;
    const bool normal = kindRow(slot.kind).derivative;
    Tiles tiles;
    for (size_t i = 0; i < 3; ++i) {
        const TileTransform tile = tileTransform(taps.id[i], hex);
        // The paper's mode turns st as Listing 3 does; stable mode turns the texels (Rotation::aspect).
        const double aspect = hex.mode == HashMode::Paper ? 1 : double(texture.width(0)) / texture.height(0);
        const Rotation rot{std::cos(tile.angle), std::sin(tile.angle), aspect};
        // Rotate into the tile's frame, scale (the texture is scaled by tile.scale: sample at the point / scale),
        // then shift by the tile's offset; the gradients rotate and scale with it (Listings 3 and 4).
        const Vec2 rotated = rot.toTile(taps.local[i]);
        Fetch& f = tiles.fetch[i];
        f.p = {rotated[0] / tile.scale + taps.shift[i][0] + tile.offset[0], rotated[1] / tile.scale + taps.shift[i][1] + tile.offset[1]};
        f.dx = rot.toTile(dx);
        f.dy = rot.toTile(dy);
        for (Vec2* g : {&f.dx, &f.dy}) *g = {(*g)[0] / tile.scale, (*g)[1] / tile.scale};
        f.scale = tile.scale;
        const Rgba x = fetched[i] ? fetchTile(texture, f, hex, dx, dy) : Rgba{};
        tiles.texels[i] = x;

        double metric;
        if (normal) {
            // The sampled slope is in the tile's frame: rotate it back before weighing and blending (Listing 3).
            // Rotated back to st, and over the scale: a tile scaled by s shows H(p / s), of slope dH / s.
            const Vec2 r = rot.fromTile(normalToDerivative(x, slot.flipY));
            const Vec2 d{r[0] / tile.scale, r[1] / tile.scale};
            const double d2 = d[0] * d[0] + d[1] * d[1];
            metric = std::sqrt(d2 / (1 + d2));  // Eq. 3: sine of the normal's angle to +Z
            tiles.samples[i] = asValue(d);
        } else {
            metric = kindRow(slot.kind).oneChannel ? x[size_t(slot.channel)] : 0.299 * x[0] + 0.587 * x[1] + 0.114 * x[2];  // Eq. 4
            tiles.samples[i] = x;
        }
        // hexc's guard: a negative metric (HDR texels below 0) counts as 0, so no weight turns negative.
        tiles.delta[i] = (1 - hex.falloffcontrast) + hex.falloffcontrast * std::max(metric, 0.0);
    }
    return tiles;
}

// One dithered tap: the pixel's hash u in [0, 1) picks the tile whose share of Eq. 1's weights (without
// the metric, which one sample cannot weigh) covers it; that tile's sample is the result. A two-tap mask
// has no third tile: u beyond W_0 + W_1 (by rounding) picks the second.
SlotResult ditheredTap(const HexTiling& hex, const Taps& taps, const std::array<Rgba, 3>& samples, std::array<uint32_t, 2> pixel) {
    const std::array<double, 3> w = blendWeights(taps.weight, {1, 1, 1}, hex);
    const double u = ditherValue(pixel);
    const size_t pick = std::min<size_t>(u < w[0] ? 0 : u < w[0] + w[1] ? 1 : 2, size_t(hex.maskTaps() - 1));
    std::array<double, 3> oneHot{};
    oneHot[pick] = 1;
    return {samples[pick], shown(hex, taps, oneHot), {samples[pick], samples[pick], samples[pick]}, oneHot};
}

// The tiles' samples blended with Eq. 1's weights (and the gain), then, when height-blended, by their heights.
SlotResult blendTiles(const Slot& slot, const Taps& taps, const Tiles& tiles, Vec2 dx, Vec2 dy, bool heightBlended,
                      const HeightSource* height) {
    const HexTiling& hex = slot.hex;
    std::array<double, 3> w = blendWeights(taps.weight, tiles.delta, hex);
    const std::array<double, 3> unheighted = w;
    double heightSum = 1;
    if (heightBlended) {
        // The heights at each tile's own sample point, with its gradients: the tile's transform applies to them too.
        std::array<double, 3> h;
        for (size_t i = 0; i < 3; ++i) {
            h[i] = fetchTile(*height->texture, tiles.fetch[i], hex, dx, dy)[size_t(height->channel)];
        }
        w = heightBlend(w, h, height->width, heightSum);
    }
    const std::array<Rgba, 3>& samples = tiles.samples;
    Rgba value{};
    for (size_t c = 0; c < 4; ++c) value[c] = w[0] * samples[0][c] + w[1] * samples[1][c] + w[2] * samples[2][c];
    if (kindRow(slot.kind).derivative) value = asValue({value[0], value[1]});  // keep (.., .., 0, 1) exact
    return {value, shown(hex, taps, w), samples, w, heightSum, {}, 0, unheighted, tiles.delta, tiles.texels};
}

}  // namespace

SlotResult evaluateAt(const Slot& slot, const SampledTexture& texture, Vec2 st, Vec2 dx, Vec2 dy, std::array<uint32_t, 2> pixel,
                      const HeightSource* height, const SampledTexture* lut, int repeats) {
    const HexTiling& hex = slot.hex;
    if (!hex.enabled) return untiled(slot, texture, st, dx, dy);
    if (hex.mode == HashMode::MaterialX) return evaluateMaterialX(slot, texture, st, dx, dy);
    const bool heightBlended = slot.heightBlend && hex.taps != 1;  // 1 tap cannot height-blend (the parser rejects it)
    if (heightBlended && !height) throw std::invalid_argument("reference: slot " + slot.name + " height-blends but no heights were given");
    const bool histogram = hex.blend == Blend::Histogram;  // the parser leaves it on colour and scalar slots only
    if (histogram && !lut)
        throw std::invalid_argument("reference: slot " + slot.name + " blends histograms but no look-up table was given");

    Taps taps = maskTaps(st, hex, repeats);
    std::array<bool, 3> fetched{true, true, true};
    if (hex.adaptive()) {
        fetched = adaptiveTaps(taps.weight, hex);
        for (size_t i = 0; i < 3; ++i) taps.weight[i] *= fetched[i];  // the blend of the fetched taps alone
    }
    const Tiles tiles = sampleTiles(slot, texture, taps, fetched, dx, dy);

    if (hex.taps == 1) return ditheredTap(hex, taps, tiles.samples, pixel);
    if (histogram) {
        const std::array<double, 3> w = blendWeights(taps.weight, {1, 1, 1}, hex);  // no metric: see hexcHistogram
        SlotResult r = histogramBlend(*lut, tiles.samples, w, dx, dy, texture.width(0), texture.height(0), kindRow(slot.kind).oneChannel);
        r.weights = shown(hex, taps, w);
        return r;
    }
    return blendTiles(slot, taps, tiles, dx, dy, heightBlended, height);
}

SlotTextures::SlotTextures(const Slot& slot) {
    const Texture source = loadTexture(slot.texturePath, slot.samplerDecodes(), slot.textureLayer);
    if (slot.hex.blend != Blend::Histogram) {
        texture = std::make_unique<SampledTexture>(source);
        return;
    }
    const HistogramTransform t = histogramTransform(source, slot);
    texture = std::make_unique<SampledTexture>(t.gaussian);
    lut = std::make_unique<SampledTexture>(t.lut);
}

Heights::Heights(const Material& material, const Slot& slot) {
    if (!slot.heightBlend) return;
    for (const Slot& h : material.slots)
        if (h.name == slot.heightBlend->slot) {
            texture_ = std::make_unique<SampledTexture>(loadTexture(h.texturePath, h.colorSpace == ColorSpace::Srgb, h.textureLayer));
            source_ = {texture_.get(), h.channel, slot.heightBlend->width};
        }
}

SlotResult evaluate(const Slot& slot, const SampledTexture& texture, double u, double v, double dudx, double dvdx, double dudy, double dvdy,
                    std::array<uint32_t, 2> pixel, const HeightSource* height, const SampledTexture* lut, int repeats) {
    const auto [a, b] = slot.hex.tiling;
    return evaluateAt(slot, texture, {u * a, v * b}, {dudx * a, dvdx * b}, {dudy * a, dvdy * b}, pixel, height, lut, repeats);
}

SlotResult evaluateTriplanar(const Slot& slot, const SampledTexture& texture, const SurfacePoint& point, std::array<uint32_t, 2> pixel,
                             const HeightSource* height, const SampledTexture* lut) {
    const Vec3& N = point.normal;
    const double length = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
    const Vec3 n = length > 0 ? Vec3{N[0] / length, N[1] / length, N[2] / length} : Vec3{0, 0, 0};
    std::array<double, 3> b{1.0 / 3, 1.0 / 3, 1.0 / 3};
    if (length > 0) {
        for (size_t k = 0; k < 3; ++k) b[k] = std::pow(std::abs(n[k]), slot.hex.planeSharpness);
        const double sum = b[0] + b[1] + b[2];
        for (double& x : b) x /= sum;
    }
    // Plane k's st axes are the world axes k + 1 and k + 2 (mod 3): (y, z), (z, x), (x, y).
    const auto onPlane = [&](const Vec3& p, size_t k) {
        return Vec2{p[(k + 1) % 3] * slot.hex.tiling[0], p[(k + 2) % 3] * slot.hex.tiling[1]};
    };
    const size_t dominant = size_t(std::max_element(b.begin(), b.end()) - b.begin());
    const bool normal = kindRow(slot.kind).derivative;
    SlotResult out{};
    Vec3 g{};  // normal slots: the blended world-space height gradient
    for (size_t k = 0; k < 3; ++k) {
        if (!(b[k] > 0)) continue;
        const SlotResult r =
            evaluateAt(slot, texture, onPlane(point.position, k), onPlane(point.dPdx, k), onPlane(point.dPdy, k), pixel, height, lut);
        if (normal) {
            g[(k + 1) % 3] += b[k] * r.value[0];
            g[(k + 2) % 3] -= b[k] * r.value[1];  // the plane's t axis is world +, its derivative's y is -t
        } else {
            for (size_t c = 0; c < 4; ++c) out.value[c] += b[k] * r.value[c];
        }
        for (size_t c = 0; c < 3; ++c) out.weights[c] += b[k] * r.weights[c];
        out.planes.push_back(r);
        out.planeWeights.push_back(b[k]);
        if (k == dominant) {
            out.samples = r.samples;
            out.blend = r.blend;
        }
    }
    if (normal) {
        // The surface gradient (Mikkelsen 2020): g without its component along n.
        const double along = g[0] * n[0] + g[1] * n[1] + g[2] * n[2];
        out.value = {g[0] - along * n[0], g[1] - along * n[1], g[2] - along * n[2], 1};
    }
    return out;
}

SurfacePoint previewSphere(double u, double v, double dudx, double dvdx, double dudy, double dvdy) {
    const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
    const Vec3 p{cv * su, sv, cv * cu};
    const Vec3 du{cv * cu, 0, -cv * su}, dv{-sv * su, cv, -sv * cu};  // dP/du, dP/dv
    const auto chain = [&](double a, double b) { return Vec3{du[0] * a + dv[0] * b, du[1] * a + dv[1] * b, du[2] * a + dv[2] * b}; };
    return {p, p, chain(dudx, dvdx), chain(dudy, dvdy)};
}

std::vector<SlotResult> evaluateView(const Slot& slot, const SampledTexture& texture, const View& view, const HeightSource* height,
                                     const SampledTexture* lut, int repeats) {
    std::vector<SlotResult> out;
    out.reserve(size_t(view.width) * size_t(view.height));
    const auto [u0, v0, u1, v1] = view.uvRect;
    const double dudx = (u1 - u0) / view.width, dvdy = (v1 - v0) / view.height;
    const bool triplanar = slot.hex.projection == Projection::Triplanar;
    for (int j = 0; j < view.height; ++j)
        for (int i = 0; i < view.width; ++i) {
            const double u = u0 + (i + 0.5) / view.width * (u1 - u0), v = v0 + (j + 0.5) / view.height * (v1 - v0);
            const std::array<uint32_t, 2> pixel{uint32_t(i), uint32_t(j)};
            out.push_back(triplanar ? evaluateTriplanar(slot, texture, previewSphere(u, v, dudx, 0, 0, dvdy), pixel, height, lut)
                                    : evaluate(slot, texture, u, v, dudx, 0, 0, dvdy, pixel, height, lut, repeats));
        }
    return out;
}

Image render(const Slot& slot, const SampledTexture& texture, const View& view, Output output, const HeightSource* height,
             const SampledTexture* lut, int repeats) {
    Image image;
    image.width = view.width;
    image.height = view.height;
    image.rgba.resize(size_t(view.width) * size_t(view.height) * 4);
    const std::vector<SlotResult> results = evaluateView(slot, texture, view, height, lut, repeats);
    for (size_t p = 0; p < results.size(); ++p) {
        const SlotResult& r = results[p];
        const Rgba out = output == Output::Value ? r.value : Rgba{r.weights[0], r.weights[1], r.weights[2], 1};
        for (size_t c = 0; c < 4; ++c) image.rgba[p * 4 + c] = float(out[c]);
    }
    return image;
}

}  // namespace hexc::reference
