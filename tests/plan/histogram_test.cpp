// The histogram blend's precomputation (hexc/histogram.h): T maps a texture's histogram to the Gaussian, the look-up
// table inverts it within its resolution, the colour space decorrelates, and what hexc writes is that, byte for byte.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "hexc/histogram.h"
#include "hexc/image.h"
#include "support.h"

using namespace hexc;
using hexc::test::runHexc;

namespace {

namespace fs = std::filesystem;

// An odd-sized 8-bit texture unlike the example textures: two correlated sine waves plus a hashed grain, with ties.
Texture oddTexture(bool srgb) {
    Texture t;
    t.width = 97, t.height = 61, t.srgb = srgb;
    uint32_t h = 12345;
    for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width; ++x) {
            h = h * 1664525u + 1013904223u;
            const double grain = double(h >> 24) / 255.0, wave = 0.5 + 0.3 * std::sin(x * 0.31) * std::cos(y * 0.17);
            const double rgb[3] = {wave, 0.6 * wave + 0.4 * grain, 0.2 + 0.5 * grain * grain};
            for (double c : rgb) t.rgba8.push_back(uint8_t(std::lround(std::clamp(c, 0.0, 1.0) * 255)));
            t.rgba8.push_back(255);
        }
    return t;
}

Slot slotOf(SlotKind kind, int channel = 0) {
    Slot s;
    s.kind = kind;
    s.channel = channel;
    s.hex.blend = Blend::Histogram;
    return s;
}

double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// The texels' decorrelated values q_k = E^T (rgb - mean), with the axes and mean the table's row 0 holds.
std::vector<std::array<double, 3>> decorrelated(const Texture& t, const HistogramTransform& h, const Slot& slot) {
    auto lut = [&](int x, size_t c) { return double(h.lut.rgba32f[size_t(x) * 4 + c]); };
    std::vector<std::array<double, 3>> out;
    for (size_t i = 0; i < size_t(t.width) * size_t(t.height); ++i) {
        double v[4];
        for (size_t c = 0; c < 4; ++c) v[c] = t.srgb && c < 3 ? srgbToLinear(t.rgba8[i * 4 + c] / 255.0) : t.rgba8[i * 4 + c] / 255.0;
        if (slot.kind == SlotKind::Scalar) {
            out.push_back({v[slot.channel], 0, 0});
            continue;
        }
        std::array<double, 3> q{};
        for (size_t k = 0; k < 3; ++k)
            for (size_t c = 0; c < 3; ++c) q[k] += lut(int(k), c) * (v[c] - lut(3, c));
        out.push_back(q);
    }
    return out;
}

double normalCdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// T's values of each channel are the Gaussian's quantiles at (r + 0.5) / n, so their empirical CDF is within 0.5 / n
// of the Gaussian's everywhere (the Kolmogorov-Smirnov distance), whatever the texture's histogram, ties included.
TEST(Histogram, TMapsEachChannelToTheGaussian) {
    for (bool srgb : {true, false}) {
        const Texture t = oddTexture(srgb);
        const HistogramTransform h = histogramTransform(t, slotOf(SlotKind::Color));
        const size_t n = size_t(t.width) * size_t(t.height);
        for (size_t k = 0; k < 3; ++k) {
            std::vector<double> g;
            for (size_t i = 0; i < n; ++i) g.push_back(h.gaussian.rgba32f[i * 4 + k]);
            std::sort(g.begin(), g.end());
            double ks = 0;
            for (size_t r = 0; r < n; ++r) {
                const double cdf = normalCdf((g[r] - 0.5) * 6);
                ks = std::max({ks, std::fabs(cdf - double(r) / double(n)), std::fabs(cdf - double(r + 1) / double(n))});
            }
            // 0.5 / n from the ranks, 1e-6 for storing the values in float32 (the CDF's slope is at most 6 / sqrt(2 pi)).
            EXPECT_LE(ks, 0.5 / double(n) + 1e-6) << "channel " << k << (srgb ? " srgb" : " linear");
        }
    }
}

// The principal axes are orthonormal and the texels' coordinates on them uncorrelated.
TEST(Histogram, TheColourSpaceDecorrelates) {
    const Texture t = oddTexture(true);
    const Slot slot = slotOf(SlotKind::Color);
    const HistogramTransform h = histogramTransform(t, slot);
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
            double dot = 0;
            for (size_t c = 0; c < 3; ++c) dot += double(h.lut.rgba32f[size_t(a) * 4 + c]) * h.lut.rgba32f[size_t(b) * 4 + c];
            EXPECT_NEAR(dot, a == b ? 1 : 0, 1e-6) << a << "," << b;  // float32 storage
        }
    const auto q = decorrelated(t, h, slot);
    std::array<std::array<double, 3>, 3> cov{};
    for (const auto& v : q)
        for (size_t a = 0; a < 3; ++a)
            for (size_t b = 0; b < 3; ++b) cov[a][b] += v[a] * v[b] / double(q.size());
    // Off the diagonal, what float32 axes leave: |dE| <= 6e-8 per component times the variances.
    for (size_t a = 0; a < 3; ++a)
        for (size_t b = a + 1; b < 3; ++b)
            EXPECT_LE(std::fabs(cov[a][b]), 1e-6 * std::sqrt(cov[a][a] * cov[b][b]) + 1e-12) << a << "," << b;
    EXPECT_GE(cov[0][0], cov[1][1]);
    EXPECT_GE(cov[1][1], cov[2][2]);
}

// T^-1(T(x)) = x within the table's resolution: a texel's Gaussian value g lies between entries i and i + 1 of the
// level-0 row, and T^-1 is monotone, so the value read back lies between those entries, as does the texel's own
// (float32 storage aside). Texels beyond +-3 standard deviations (g outside [0, 1]) are clamped to the end entries.
TEST(Histogram, TheInverseUndoesTWithinTheTablesResolution) {
    for (const Slot& slot : {slotOf(SlotKind::Color), slotOf(SlotKind::Scalar, 1)}) {
        const Texture t = oddTexture(true);
        const HistogramTransform h = histogramTransform(t, slot);
        const auto q = decorrelated(t, h, slot);
        const int n = kHistogramLutWidth;
        auto entry = [&](int x, size_t k) { return double(h.lut.rgba32f[(size_t(n) + size_t(x)) * 4 + k]); };  // row 1
        size_t clamped = 0, total = 0;
        double worst = 0, widest = 0;
        for (size_t i = 0; i < q.size(); ++i)
            for (size_t k = 0; k < (slot.kind == SlotKind::Scalar ? 1 : 3); ++k, ++total) {
                const double g = h.gaussian.rgba32f[i * 4 + k];
                if (g < 0 || g > 1) {
                    ++clamped;
                    continue;
                }
                const double x = g * (n - 1);
                const int i0 = std::min(int(x), n - 2);
                const double lo = entry(i0, k), hi = entry(i0 + 1, k), back = lo + (x - i0) * (hi - lo);
                const double slack = 1e-6 * (std::fabs(q[i][k]) + 1);  // float32 entries and values
                EXPECT_LE(lo, q[i][k] + slack);
                EXPECT_GE(hi, q[i][k] - slack);
                worst = std::max(worst, std::fabs(back - q[i][k]));
                widest = std::max(widest, hi - lo);
            }
        EXPECT_LE(worst, widest + 1e-6);
        // P(|Z| > 3) = 0.0027 of the ranks, plus one rank at each end for rounding.
        EXPECT_LE(double(clamped), 0.0027 * double(total) + 2 * (slot.kind == SlotKind::Scalar ? 1 : 3));
        std::printf("  %s: T^-1(T(x)) within %.5f, widest entry step %.5f, %zu of %zu values beyond 3 sigma\n",
                    slot.kind == SlotKind::Scalar ? "scalar" : "colour", worst, widest, clamped, total);
    }
}

// Every row is monotone, and the last level (one texel, variance 0) averages T^-1 over the whole Gaussian: at its
// centre that is the channel's mean (the trapezoid rule over +-4 sigma leaves out 6e-5 of the mass).
TEST(Histogram, EachLevelsRowAveragesTheInverse) {
    const Texture t = oddTexture(true);
    const Slot slot = slotOf(SlotKind::Color);
    const HistogramTransform h = histogramTransform(t, slot);
    const auto q = decorrelated(t, h, slot);
    const int n = h.lut.width, rows = h.lut.height;
    EXPECT_EQ(rows, 1 + 7);  // 97 x 61: levels 97, 48, 24, 12, 6, 3, 1
    auto entry = [&](int x, int row, size_t k) { return double(h.lut.rgba32f[(size_t(row) * size_t(n) + size_t(x)) * 4 + k]); };
    for (size_t k = 0; k < 3; ++k) {
        double lo = INFINITY, hi = -INFINITY, mean = 0;
        for (const auto& v : q) lo = std::min(lo, v[k]), hi = std::max(hi, v[k]), mean += v[k] / double(q.size());
        for (int row = 1; row < rows; ++row)
            for (int x = 0; x + 1 < n; ++x) ASSERT_LE(entry(x, row, k), entry(x + 1, row, k) + 1e-7) << "row " << row;
        const double centre = (entry(n / 2 - 1, rows - 1, k) + entry(n / 2, rows - 1, k)) / 2;
        EXPECT_NEAR(centre, mean, 1e-3 * (hi - lo)) << "channel " << k;
        // Deeper rows are flatter: the inverse averaged over a wider Gaussian.
        EXPECT_LT(entry(n - 1, rows - 1, k) - entry(0, rows - 1, k), entry(n - 1, 1, k) - entry(0, 1, k));
    }
}

Texture readBack(const fs::path& file) { return loadTexture(file, false); }

std::string bytesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writePng(const Texture& t, const fs::path& file) {
    Image image{t.width, t.height, {}};
    for (uint8_t b : t.rgba8) image.rgba.push_back(b / 255.0f);
    writeImage(image, file);
}

// hexc writes the transform (PFM drops alpha, which is 1), the same bytes every time; a build runs the precomputation
// again when the texture's bytes change, and only then: a material changed otherwise takes it from the cache.
TEST(Histogram, HexcWritesTheTransformAndRebuildsWhenTheTexturesBytesChange) {
    const fs::path dir = fs::temp_directory_path() / "hexc_histogram_cli";
    fs::remove_all(dir);
    fs::create_directories(dir);
    writePng(oddTexture(true), dir / "odd.png");
    auto writeMaterial = [&](double tiling) {
        std::ofstream(dir / "m.json") << R"({"name": "m", "template": "unlit", "hextiling": {"blend": "histogram", "tiling": )" << tiling
                                      << R"(}, "slots": [{"name": "albedo", "kind": "color", "texture": "odd.png"}]})";
    };
    writeMaterial(4);
    std::string err;
    const std::string build = (dir / "m.json").string() + " -v --cache-dir " + (dir / "cache").string() + " -o ";
    for (const char* out : {"out", "again"}) ASSERT_EQ(runHexc(build + (dir / out).string(), &err), 0) << err;
    const HistogramTransform h = histogramTransform(loadTexture(dir / "odd.png", true), slotOf(SlotKind::Color));
    const Texture lut = readBack(dir / "out" / "m.albedo.lut.pfm");
    EXPECT_EQ(readBack(dir / "out" / "m.albedo.gaussian.pfm").rgba32f, h.gaussian.rgba32f);
    EXPECT_EQ(lut.rgba32f, h.lut.rgba32f);
    for (const char* file : {"m.albedo.gaussian.pfm", "m.albedo.lut.pfm"})
        EXPECT_EQ(bytesOf(dir / "out" / file), bytesOf(dir / "again" / file));
    // A build system learns of them from the depfile, up to date or not.
    ASSERT_EQ(runHexc(build + (dir / "out").string() + " --depfile " + (dir / "m.d").string(), &err), 0) << err;
    EXPECT_NE(err.find("0 compiled, 1 up to date"), std::string::npos) << err;
    const std::string depfile = bytesOf(dir / "m.d"), targets = depfile.substr(0, depfile.find(':'));
    for (const char* file : {"m.albedo.gaussian.pfm", "m.albedo.lut.pfm"}) EXPECT_NE(targets.find(file), std::string::npos) << targets;

    // Another tiling: the material compiles again, its shader code (tiling is a uniform) and its tables come from the cache.
    writeMaterial(3);
    ASSERT_EQ(runHexc(build + (dir / "out").string(), &err), 0) << err;
    EXPECT_NE(err.find("1 compiled, 0 up to date"), std::string::npos) << err;
    EXPECT_NE(err.find("shader code: 0 compiled, 2 from the cache"), std::string::npos) << err;
    // Other pixels, the same size: the shader code is the same, the derived textures are computed again.
    Texture other = oddTexture(false);
    for (uint8_t& b : other.rgba8) b = uint8_t(255 - b);
    writePng(other, dir / "odd.png");
    ASSERT_EQ(runHexc(build + (dir / "out").string(), &err), 0) << err;
    EXPECT_NE(err.find("1 compiled, 0 up to date"), std::string::npos) << err;
    EXPECT_NE(err.find("shader code: 1 compiled, 1 from the cache"), std::string::npos) << err;
    EXPECT_NE(readBack(dir / "out" / "m.albedo.lut.pfm").rgba32f, lut.rgba32f);
}

}  // namespace
