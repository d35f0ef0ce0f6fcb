// SampledTexture (reference.h): a texture as a Vulkan sampler sees it, with its mip chain as the runner builds it.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "reference/internal.h"

namespace hexc::reference {
namespace {

// The exact sRGB EOTF, as Vulkan applies it to _SRGB formats before filtering.
double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// REPEAT addressing of an integer texel coordinate (Vulkan's imod: the result is never negative).
int wrap(double i, int size) {
    const long long m = (long long)i % size;
    return int(m < 0 ? m + size : m);
}

}  // namespace

SampledTexture::SampledTexture(const Texture& texture) {
    const size_t count = size_t(std::max(texture.width, 0)) * size_t(std::max(texture.height, 0));
    if (count == 0 || (texture.isFloat() ? texture.rgba32f.size() : texture.rgba8.size()) != count * 4)
        throw std::invalid_argument("reference: texture of " + std::to_string(texture.width) + "x" + std::to_string(texture.height) +
                                    " texels has no or the wrong amount of data");

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

    while (levels_.back().width > 1 || levels_.back().height > 1) levels_.push_back(halve(levels_.back()));
}

// The next mip level as the runner builds it, by vkCmdBlitImage with VK_FILTER_LINEAR from the level above: the size
// halves (rounding down, at least 1), and each texel is the bilinear sample of the level above at its centre mapped
// into it, (i + 0.5) * size / next size, clamped to the edge. At an even size that is the 2x2 average; at an odd one
// the texels are resampled (127 -> 63 texels reads at steps of 2.016).
SampledTexture::Level SampledTexture::halve(const Level& prev) {
    Level next{std::max(1, prev.width / 2), std::max(1, prev.height / 2), {}};
    struct Tap {
        int i0, i1;
        double f;  // weight of i1
    };
    const auto taps = [](int dst, int src, int i) {
        const double x = (i + 0.5) * src / dst - 0.5;
        const int x0 = int(std::floor(x));
        return Tap{std::clamp(x0, 0, src - 1), std::clamp(x0 + 1, 0, src - 1), x - x0};
    };
    next.texels.resize(size_t(next.width) * size_t(next.height));
    const auto at = [&](int px, int py) { return prev.texels[size_t(py) * prev.width + px]; };
    for (int y = 0; y < next.height; ++y) {
        const Tap ty = taps(next.height, prev.height, y);
        for (int x = 0; x < next.width; ++x) {
            const Tap tx = taps(next.width, prev.width, x);
            const Rgba top = lerp(at(tx.i0, ty.i0), at(tx.i1, ty.i0), tx.f), bottom = lerp(at(tx.i0, ty.i1), at(tx.i1, ty.i1), tx.f);
            next.texels[size_t(y) * next.width + x] = lerp(top, bottom, ty.f);
        }
    }
    return next;
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
    return sampleLod(s, t, std::log2(rho));
}

Rgba SampledTexture::sampleLod(double s, double t, double lambda) const {
    lambda = std::min(lambda, double(levels() - 1));
    if (!(lambda > 0)) return bilinear(levels_[0], s, t);  // magnification (also rho = 0, where log2 is -inf)
    const int lo = int(lambda), hi = std::min(lo + 1, levels() - 1);
    const Rgba a = bilinear(levels_[size_t(lo)], s, t);
    if (hi == lo) return a;  // lambda clamped to the last level
    return lerp(a, bilinear(levels_[size_t(hi)], s, t), lambda - lo);
}

}  // namespace hexc::reference
