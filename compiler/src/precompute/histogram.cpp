// The histogram-preserving blend's precomputation (hexc/histogram.h), written from Heitz and Neyret 2018 (Section 1.3,
// the Gaussianisation T and its inverse) and Deliot and Heitz 2019 (the decorrelated colour space, the inverse as a
// look-up table per level of detail).
//
// Memory: the texels are read from the source as they are needed, never converted into a copy. Beside the source and
// the Gaussian texture it returns (16 bytes per texel), one channel is worked on at a time: its sort keys (8 bytes per
// texel) and the first box-filtered level of its mip chain (1 byte per texel, the rest filtered in place), so about
// 25 bytes per texel in all.
#include "hexc/histogram.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <vector>

namespace hexc {
namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;  // m[row][column]

constexpr double kSigma = 1.0 / 6.0;  // the Gaussian's standard deviation: mean +- 3 sigma spans [0, 1]

double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// The texels as linear values, one at a time: RGB for a colour slot, the slot's channel (in [0]) for a scalar one.
class LinearTexels {
public:
    LinearTexels(const Texture& t, const Slot& slot) : t_(t), slot_(slot) {
        for (int v = 0; v < 256; ++v) decoded_[size_t(v)] = t.srgb ? srgbToLinear(v / 255.0) : v / 255.0;
    }
    size_t size() const { return size_t(t_.width) * size_t(t_.height); }
    Vec3 operator()(size_t i) const {
        auto channel = [&](size_t c) {
            if (!t_.isFloat()) return c < 3 ? decoded_[t_.rgba8[i * 4 + c]] : t_.rgba8[i * 4 + c] / 255.0;
            const double v = t_.rgba32f[i * 4 + c];
            return t_.srgb && c < 3 ? srgbToLinear(v) : v;
        };
        if (kindRow(slot_.kind).oneChannel) return {channel(size_t(slot_.channel)), 0, 0};
        return {channel(0), channel(1), channel(2)};
    }

private:
    const Texture& t_;
    const Slot& slot_;
    std::array<double, 256> decoded_;  // an 8-bit value's linear value
};

// The standard normal CDF and its inverse: Acklam's rational approximation (relative error 1.2e-9), then one Halley
// step on the CDF, which takes it to double precision.
double normalCdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

double inverseNormalCdf(double p) {
    static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,  -2.759285104469687e+02,
                               1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
    static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02, 6.680131188771972e+01,
                               -1.328068155288572e+01};
    static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                               -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
    static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00, 3.754408661907416e+00};
    const double low = 0.02425;
    double x;
    if (p < low || p > 1 - low) {
        const double q = std::sqrt(-2 * std::log(p < low ? p : 1 - p));
        x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) / ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
        if (p > 1 - low) x = -x;
    } else {
        const double q = p - 0.5, r = q * q;
        x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
            (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1);
    }
    const double e = normalCdf(x) - p, u = e * std::sqrt(2 * M_PI) * std::exp(x * x / 2);
    return x - u / (1 + x * u / 2);
}

// The eigenvectors of a symmetric 3x3 matrix (cyclic Jacobi rotations), as columns ordered by decreasing eigenvalue,
// each with its largest component positive so that the basis does not depend on rounding.
Mat3 principalAxes(Mat3 m) {
    Mat3 v{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    for (int sweep = 0; sweep < 50; ++sweep)
        for (size_t p = 0; p < 2; ++p)
            for (size_t q = p + 1; q < 3; ++q) {
                if (std::fabs(m[p][q]) < 1e-300) continue;
                const double theta = (m[q][q] - m[p][p]) / (2 * m[p][q]);
                const double t = (theta >= 0 ? 1 : -1) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
                const double c = 1 / std::sqrt(t * t + 1), s = t * c;
                for (size_t k = 0; k < 3; ++k) {  // m = J^T m J, v = v J
                    const double mkp = m[k][p], mkq = m[k][q];
                    m[k][p] = c * mkp - s * mkq, m[k][q] = s * mkp + c * mkq;
                }
                for (size_t k = 0; k < 3; ++k) {
                    const double mpk = m[p][k], mqk = m[q][k];
                    m[p][k] = c * mpk - s * mqk, m[q][k] = s * mpk + c * mqk;
                }
                for (size_t k = 0; k < 3; ++k) {
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq, v[k][q] = s * vkp + c * vkq;
                }
            }
    std::array<size_t, 3> order{0, 1, 2};
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return m[a][a] > m[b][b]; });
    Mat3 axes{};
    for (size_t j = 0; j < 3; ++j) {
        size_t big = 0;
        for (size_t k = 1; k < 3; ++k)
            if (std::fabs(v[k][order[j]]) > std::fabs(v[big][order[j]])) big = k;
        const double sign = v[big][order[j]] < 0 ? -1 : 1;
        for (size_t k = 0; k < 3; ++k) axes[k][j] = sign * v[k][order[j]];
    }
    return axes;
}

// A float's bits as an unsigned integer of the same order (negative values below positive ones), and back.
uint32_t orderedBits(float f) {
    uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b & 0x80000000u ? ~b : b | 0x80000000u;
}

float fromOrderedBits(uint32_t b) {
    b = b & 0x80000000u ? b & 0x7fffffffu : ~b;
    float f;
    std::memcpy(&f, &b, sizeof f);
    return f;
}

// A bijection of 32-bit texel indices (Wellons' lowbias32) and its inverse. Texture loading keeps a texture below 2^32
// texels (stb's and the containers' limits), so every index has its own hash.
uint32_t scramble(uint32_t x) {
    x ^= x >> 16, x *= 0x7feb352du, x ^= x >> 15, x *= 0x846ca68bu, x ^= x >> 16;
    return x;
}

uint32_t unscramble(uint32_t x) {
    x ^= x >> 16, x *= 0x43021123u, x ^= x >> 15 ^ x >> 30, x *= 0x1d69e2a5u, x ^= x >> 16;
    return x;
}

// One decorrelated channel, sorted: a texel's key holds its value (float32, as orderedBits) above scramble(its index).
// Equal values are so ordered by a hash of their position: deterministic and without spatial structure (the raster
// order would paint a ramp into the Gaussian texture of a few-valued texture); the index comes back from the key.
struct Channel {
    std::vector<uint64_t> keys;
    double value(size_t r) const { return fromOrderedBits(uint32_t(keys[r] >> 32)); }
    size_t texel(size_t r) const { return unscramble(uint32_t(keys[r])); }
    // The value at Gaussian value y: the quantile of Phi((y - 0.5) / sigma), linear between order statistics whose
    // ranks (r + 0.5) / n are the probabilities T gave them.
    double quantile(double y) const {
        const double n = double(keys.size());
        const double x = std::clamp(normalCdf((y - 0.5) / kSigma) * n - 0.5, 0.0, n - 1);
        const size_t i = std::min(size_t(x), keys.size() - 1), j = std::min(i + 1, keys.size() - 1);
        return value(i) + (x - double(i)) * (value(j) - value(i));
    }
};

// Sorts the values value(i) of texels 0 .. n - 1 into `ch` and writes T of each, rank r of n becoming
// 0.5 + sigma Phi^-1((r + 0.5) / n), into channels [first, last) of the Gaussian texture.
template <class Value>
void gaussianise(size_t n, const Value& value, Channel& ch, Texture& gaussian, size_t first, size_t last) {
    ch.keys.resize(n);
    // + 0.0f turns -0 into +0, which sorts it among the zeros.
    for (size_t i = 0; i < n; ++i) ch.keys[i] = uint64_t(orderedBits(float(value(i)) + 0.0f)) << 32 | scramble(uint32_t(i));
    std::sort(ch.keys.begin(), ch.keys.end());
    for (size_t r = 0; r < n; ++r) {
        const float g = float(0.5 + kSigma * inverseNormalCdf((double(r) + 0.5) / double(n)));
        for (size_t c = first; c < last; ++c) gaussian.rgba32f[ch.texel(r) * 4 + c] = g;
    }
}

// The number of levels of a w x h full mip chain, each level max(1, size / 2) of the one above.
size_t mipLevels(int w, int h) {
    size_t levels = 1;
    for (; w > 1 || h > 1; ++levels) w = std::max(1, w / 2), h = std::max(1, h / 2);
    return levels;
}

double variance(size_t n, const std::function<double(size_t)>& at) {
    double mean = 0, squares = 0;
    for (size_t i = 0; i < n; ++i) mean += at(i);
    mean /= double(n);
    for (size_t i = 0; i < n; ++i) squares += (at(i) - mean) * (at(i) - mean);
    return squares / double(n);
}

// The variance of each level of the full mip chain of channel c of the Gaussian texture, each level the 2x2 box
// average of the one above (the last row or column of an odd size dropped: an estimate of the GPU's linear resample
// there). Level 1 is filtered from the texture into `level`, every further one in place: output texel (x, y) reads
// from (2x, 2y) on, at an index no smaller than any output written before it.
std::vector<double> levelVariances(const Texture& t, size_t c) {
    int w = t.width, h = t.height;
    std::vector<double> out{variance(size_t(w) * size_t(h), [&](size_t i) { return double(t.rgba32f[i * 4 + c]); })};
    std::vector<float> level(size_t(std::max(1, w / 2)) * size_t(std::max(1, h / 2)));
    for (bool fromTexture = true; w > 1 || h > 1; fromTexture = false) {
        const auto above = [&](int x, int y) {
            const size_t i = size_t(std::min(y, h - 1)) * size_t(w) + size_t(std::min(x, w - 1));
            return fromTexture ? t.rgba32f[i * 4 + c] : level[i];
        };
        const int w2 = std::max(1, w / 2), h2 = std::max(1, h / 2);
        for (int y = 0; y < h2; ++y)
            for (int x = 0; x < w2; ++x)
                level[size_t(y) * size_t(w2) + size_t(x)] =
                    (above(2 * x, 2 * y) + above(2 * x + 1, 2 * y) + above(2 * x, 2 * y + 1) + above(2 * x + 1, 2 * y + 1)) / 4;
        w = w2, h = h2;
        out.push_back(variance(size_t(w) * size_t(h), [&](size_t i) { return double(level[i]); }));
    }
    return out;
}

// E[Q(Y)], Y ~ N(y, s^2): the trapezoid rule over +-4 s in 64 steps with normalised Gaussian weights (exact at s = 0).
double expectedQuantile(const Channel& ch, double y, double s) {
    if (!(s > 0)) return ch.quantile(y);
    constexpr int kSteps = 64;
    double sum = 0, weights = 0;
    for (int i = 0; i <= kSteps; ++i) {
        const double e = (double(i) / kSteps * 2 - 1) * 4;
        const double w = std::exp(-e * e / 2) * (i == 0 || i == kSteps ? 0.5 : 1);
        sum += w * ch.quantile(y + e * s);
        weights += w;
    }
    return sum / weights;
}

// A float RGBA texture of the given size, alpha 1.
Texture floatTexture(int width, int height) {
    Texture t;
    t.width = width, t.height = height;
    t.rgba32f.assign(size_t(width) * size_t(height) * 4, 0.0f);
    for (size_t i = 3; i < t.rgba32f.size(); i += 4) t.rgba32f[i] = 1.0f;
    return t;
}

// The mean, the principal axes (identity and mean 0 for a scalar slot: q is the value itself) and the range of the
// texels' linear values.
struct ColourSpace {
    Mat3 axes{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    Vec3 mean{}, lowest{INFINITY, INFINITY, INFINITY}, highest{-INFINITY, -INFINITY, -INFINITY};
};

ColourSpace colourSpace(const LinearTexels& texels, bool colour) {
    ColourSpace s;
    const size_t n = texels.size();
    for (size_t i = 0; i < n; ++i) {
        const Vec3 t = texels(i);
        for (size_t c = 0; c < 3; ++c)
            s.mean[c] += t[c] / double(n), s.lowest[c] = std::min(s.lowest[c], t[c]), s.highest[c] = std::max(s.highest[c], t[c]);
    }
    if (!colour) {
        s.mean = {0, 0, 0};
        return s;
    }
    Mat3 cov{};
    for (size_t i = 0; i < n; ++i) {
        const Vec3 t = texels(i);
        for (size_t a = 0; a < 3; ++a)
            for (size_t b = 0; b < 3; ++b) cov[a][b] += (t[a] - s.mean[a]) * (t[b] - s.mean[b]) / double(n);
    }
    s.axes = principalAxes(cov);
    return s;
}

}  // namespace

double histogramLutGaussian(int entry) { return 0.5 + kSigma * kHistogramLutSigmas * (2.0 * entry / (kHistogramLutWidth - 1) - 1); }

HistogramTransform histogramTransform(const Texture& source, const Slot& slot) {
    const LinearTexels texels(source, slot);
    const size_t n = texels.size(), channels = kindRow(slot.kind).oneChannel ? 1 : 3;
    const ColourSpace space = colourSpace(texels, channels == 3);
    HistogramTransform out{floatTexture(source.width, source.height),
                           floatTexture(kHistogramLutWidth, int(1 + mipLevels(source.width, source.height)))};
    auto lutTexel = [&](size_t x, size_t row) { return &out.lut.rgba32f[(row * kHistogramLutWidth + x) * 4]; };
    for (size_t c = 0; c < 3; ++c) {
        for (size_t j = 0; j < 3; ++j) lutTexel(j, 0)[c] = float(space.axes[c][j]);
        lutTexel(3, 0)[c] = float(space.mean[c]);
        lutTexel(4, 0)[c] = float(space.lowest[c]);
        lutTexel(5, 0)[c] = float(space.highest[c]);
    }
    Channel ch;  // one channel at a time, its keys' memory reused
    for (size_t k = 0; k < channels; ++k) {
        const auto q = [&](size_t i) {
            const Vec3 t = texels(i);
            double v = 0;
            for (size_t c = 0; c < 3; ++c) v += space.axes[c][k] * (t[c] - space.mean[c]);
            return v;
        };
        gaussianise(n, q, ch, out.gaussian, k, channels == 1 ? 3 : k + 1);
        const std::vector<double> variances = levelVariances(out.gaussian, k);
        for (size_t l = 0; l < variances.size(); ++l) {
            const double s = std::sqrt(std::max(0.0, variances[0] - variances[l]));
            for (int x = 0; x < kHistogramLutWidth; ++x)
                lutTexel(size_t(x), 1 + l)[k] = float(expectedQuantile(ch, histogramLutGaussian(x), s));
        }
    }
    return out;
}

std::string histogramFileName(const std::string& material, const std::string& slot, const char* which, bool exr) {
    return material + "." + slot + "." + which + (exr ? ".exr" : ".pfm");
}

}  // namespace hexc
