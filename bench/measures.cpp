#include "measures.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hexc::bench {

ErrorStats compareRgb(const Image& image, const Image& reference) {
    ErrorStats s;
    double sum = 0, sumSquares = 0;
    size_t n = 0;
    for (size_t i = 0; i < image.rgba.size() && i < reference.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const double e = std::abs(double(image.rgba[i]) - double(reference.rgba[i]));
        s.max = std::max(s.max, e);
        sum += e;
        sumSquares += e * e;
        ++n;
    }
    s.mean = n ? sum / double(n) : 0;
    s.psnrDb = sumSquares > 0 ? 10 * std::log10(double(n) / sumSquares) : std::numeric_limits<double>::infinity();
    return s;
}

double luminance(double r, double g, double b) { return 0.299 * r + 0.587 * g + 0.114 * b; }

std::vector<double> luminances(const Image& image) {
    std::vector<double> out;
    out.reserve(image.rgba.size() / 4);
    for (size_t i = 0; i + 3 < image.rgba.size(); i += 4) out.push_back(luminance(image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]));
    return out;
}

namespace {

double variance(const std::vector<double>& v) {
    double mean = 0, squares = 0;
    for (double x : v) mean += x;
    mean /= double(v.size());
    for (double x : v) squares += (x - mean) * (x - mean);
    return squares / double(v.size());
}

constexpr int kBins = 64;

std::vector<double> cumulativeHistogram(const std::vector<double>& v) {
    std::vector<double> h(kBins, 0.0);
    for (double x : v) h[size_t(std::clamp(int(x * kBins), 0, kBins - 1))] += 1.0 / double(v.size());
    for (int i = 1; i < kBins; ++i) h[i] += h[i - 1];
    return h;
}

}  // namespace

Contrast contrast(const std::vector<double>& rendered, const std::vector<double>& source) {
    Contrast c;
    c.varianceRatio = variance(rendered) / variance(source);
    // In one dimension the earth mover's distance is the L1 distance between the cumulative histograms.
    const std::vector<double> a = cumulativeHistogram(rendered), b = cumulativeHistogram(source);
    for (int i = 0; i < kBins; ++i) c.histogramEmd += std::abs(a[i] - b[i]) / kBins;
    return c;
}

}  // namespace hexc::bench
