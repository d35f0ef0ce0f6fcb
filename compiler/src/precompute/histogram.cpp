// The histogram-preserving blend's precomputation (hexc/histogram.h), written from Heitz and Neyret 2018 (Section 1.3,
// the Gaussianisation T and its inverse) and Deliot and Heitz 2019 (the decorrelated colour space, the inverse as a
// look-up table per level of detail).
#include "hexc/histogram.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace hexc {
namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;  // m[row][column]

constexpr double kSigma = 1.0 / 6.0;  // the Gaussian's standard deviation: mean +- 3 sigma spans [0, 1]

double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// The texels as linear values: RGB for a colour slot, the slot's channel (in [0]) for a scalar one.
std::vector<Vec3> linearTexels(const Texture& t, const Slot& slot) {
    const size_t n = size_t(t.width) * size_t(t.height);
    std::vector<Vec3> out(n);
    for (size_t i = 0; i < n; ++i) {
        double rgba[4];
        for (size_t c = 0; c < 4; ++c) {
            const double v = t.isFloat() ? double(t.rgba32f[i * 4 + c]) : t.rgba8[i * 4 + c] / 255.0;
            rgba[c] = t.srgb && c < 3 ? srgbToLinear(v) : v;
        }
        out[i] = slot.kind == SlotKind::Scalar ? Vec3{rgba[slot.channel], 0, 0} : Vec3{rgba[0], rgba[1], rgba[2]};
    }
    return out;
}

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

// One decorrelated channel: its values sorted, which is its empirical CDF and quantile function.
struct Channel {
    std::vector<double> sorted;
    // The value at Gaussian value y: the quantile of Phi((y - 0.5) / sigma), linear between order statistics whose
    // ranks (r + 0.5) / n are the probabilities T gave them.
    double quantile(double y) const {
        const double n = double(sorted.size());
        const double x = std::clamp(normalCdf((y - 0.5) / kSigma) * n - 0.5, 0.0, n - 1);
        const size_t i = std::min(size_t(x), sorted.size() - 1), j = std::min(i + 1, sorted.size() - 1);
        return sorted[i] + (x - double(i)) * (sorted[j] - sorted[i]);
    }
};

// T applied to every value: rank r of n (ties by position, so equal texels spread over the Gaussian and T^-1 maps
// them all back) becomes 0.5 + sigma Phi^-1((r + 0.5) / n). `sorted` receives the values in order.
std::vector<double> gaussianise(const std::vector<double>& values, std::vector<double>& sorted) {
    std::vector<size_t> order(values.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return values[a] < values[b] || (values[a] == values[b] && a < b); });
    std::vector<double> g(values.size());
    sorted.resize(values.size());
    for (size_t r = 0; r < order.size(); ++r) {
        g[order[r]] = 0.5 + kSigma * inverseNormalCdf((double(r) + 0.5) / double(values.size()));
        sorted[r] = values[order[r]];
    }
    return g;
}

// The variance of each level of the full mip chain of a w x h channel, each level the 2x2 box average of the one
// above (the last row or column of an odd size dropped: an estimate of the GPU's linear resample there).
std::vector<double> levelVariances(std::vector<double> level, int w, int h) {
    std::vector<double> out;
    for (;;) {
        double mean = 0, squares = 0;
        for (double x : level) mean += x;
        mean /= double(level.size());
        for (double x : level) squares += (x - mean) * (x - mean);
        out.push_back(squares / double(level.size()));
        if (w == 1 && h == 1) return out;
        const int w2 = std::max(1, w / 2), h2 = std::max(1, h / 2);
        std::vector<double> next(size_t(w2) * size_t(h2));
        for (int y = 0; y < h2; ++y)
            for (int x = 0; x < w2; ++x) {
                const int x0 = std::min(2 * x, w - 1), x1 = std::min(2 * x + 1, w - 1), y0 = std::min(2 * y, h - 1),
                          y1 = std::min(2 * y + 1, h - 1);
                next[size_t(y) * size_t(w2) + size_t(x)] =
                    (level[size_t(y0) * size_t(w) + size_t(x0)] + level[size_t(y0) * size_t(w) + size_t(x1)] +
                     level[size_t(y1) * size_t(w) + size_t(x0)] + level[size_t(y1) * size_t(w) + size_t(x1)]) /
                    4;
            }
        level = std::move(next);
        w = w2, h = h2;
    }
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

Texture floatTexture(int width, int height) {
    Texture t;
    t.width = width, t.height = height;
    t.rgba32f.assign(size_t(width) * size_t(height) * 4, 0.0f);
    return t;
}

}  // namespace

HistogramTransform histogramTransform(const Texture& source, const Slot& slot) {
    const std::vector<Vec3> texels = linearTexels(source, slot);
    const size_t n = texels.size(), channels = slot.kind == SlotKind::Scalar ? 1 : 3;
    Vec3 mean{};
    for (const Vec3& t : texels)
        for (size_t c = 0; c < 3; ++c) mean[c] += t[c] / double(n);
    Mat3 axes{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    if (channels == 3) {
        Mat3 cov{};
        for (const Vec3& t : texels)
            for (size_t i = 0; i < 3; ++i)
                for (size_t j = 0; j < 3; ++j) cov[i][j] += (t[i] - mean[i]) * (t[j] - mean[j]) / double(n);
        axes = principalAxes(cov);
    } else {
        mean = {0, 0, 0};  // a scalar slot keeps its values: q is the value itself
    }

    HistogramTransform out{floatTexture(source.width, source.height), {}};
    std::vector<Channel> decorrelated(channels);
    std::vector<std::vector<double>> variances(channels);
    for (size_t k = 0; k < channels; ++k) {
        std::vector<double> q(n);
        for (size_t i = 0; i < n; ++i)
            for (size_t c = 0; c < 3; ++c) q[i] += axes[c][k] * (texels[i][c] - mean[c]);
        const std::vector<double> g = gaussianise(q, decorrelated[k].sorted);
        for (size_t i = 0; i < n; ++i)
            for (size_t c = k; c < (channels == 1 ? 3 : k + 1); ++c) out.gaussian.rgba32f[i * 4 + c] = float(g[i]);
        variances[k] = levelVariances(g, source.width, source.height);
    }
    for (size_t i = 0; i < n; ++i) out.gaussian.rgba32f[i * 4 + 3] = 1.0f;

    const size_t levels = variances[0].size();
    out.lut = floatTexture(kHistogramLutWidth, int(1 + levels));
    auto lutTexel = [&](size_t x, size_t row) { return &out.lut.rgba32f[(row * kHistogramLutWidth + x) * 4]; };
    for (size_t j = 0; j < 3; ++j)
        for (size_t c = 0; c < 3; ++c) lutTexel(j, 0)[c] = float(axes[c][j]);
    for (size_t c = 0; c < 3; ++c) lutTexel(3, 0)[c] = float(mean[c]);
    for (size_t l = 0; l < levels; ++l)
        for (size_t k = 0; k < channels; ++k) {
            const double s = std::sqrt(std::max(0.0, variances[k][0] - variances[k][l]));
            for (size_t x = 0; x < size_t(kHistogramLutWidth); ++x)
                lutTexel(x, 1 + l)[k] = float(expectedQuantile(decorrelated[k], double(x) / (kHistogramLutWidth - 1), s));
        }
    for (size_t i = 0; i < out.lut.rgba32f.size(); i += 4) out.lut.rgba32f[i + 3] = 1.0f;
    return out;
}

std::string histogramFileName(const std::string& material, const std::string& slot, const char* which) {
    return material + "." + slot + "." + which + ".pfm";
}

}  // namespace hexc
