// The histogram blend's precomputation (hexc/histogram.h): T maps a texture's histogram to the Gaussian, the look-up
// table inverts it within its resolution, the colour space decorrelates, and what hexc writes is that, byte for byte.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>

#include "hexc/histogram.h"
#include "hexc/image.h"
#include "reference/reference.h"
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
// (float32 storage aside). The row spans +-6.5 standard deviations, so every texel is within it, the extreme ones
// included: the end entries are the channel's smallest and largest value (the tails are kept).
TEST(Histogram, TheInverseUndoesTWithinTheTablesResolution) {
    for (const Slot& slot : {slotOf(SlotKind::Color), slotOf(SlotKind::Scalar, 1)}) {
        const Texture t = oddTexture(true);
        const HistogramTransform h = histogramTransform(t, slot);
        const auto q = decorrelated(t, h, slot);
        const int n = kHistogramLutWidth;
        const double g0 = histogramLutGaussian(0), step = histogramLutGaussian(1) - g0;
        auto entry = [&](int x, size_t k) { return double(h.lut.rgba32f[(size_t(n) + size_t(x)) * 4 + k]); };  // row 1
        const size_t channels = slot.kind == SlotKind::Scalar ? 1 : 3;
        double worst = 0, widest = 0;
        for (size_t k = 0; k < channels; ++k) {
            double lowest = INFINITY, highest = -INFINITY;
            for (size_t i = 0; i < q.size(); ++i) {
                const double x = (h.gaussian.rgba32f[i * 4 + k] - g0) / step;
                ASSERT_GT(x, 0);
                ASSERT_LT(x, n - 1);
                const int i0 = int(x);
                const double lo = entry(i0, k), hi = entry(i0 + 1, k), back = lo + (x - i0) * (hi - lo);
                const double slack = 1e-6 * (std::fabs(q[i][k]) + 1);  // float32 entries and values
                EXPECT_LE(lo, q[i][k] + slack);
                EXPECT_GE(hi, q[i][k] - slack);
                worst = std::max(worst, std::fabs(back - q[i][k]));
                widest = std::max(widest, hi - lo);
                lowest = std::min(lowest, q[i][k]), highest = std::max(highest, q[i][k]);
            }
            EXPECT_NEAR(entry(0, k), lowest, 1e-6);
            EXPECT_NEAR(entry(n - 1, k), highest, 1e-6);
        }
        EXPECT_LE(worst, widest + 1e-6);
        std::printf("  %s: T^-1(T(x)) within %.5f, widest entry step %.5f\n", slot.kind == SlotKind::Scalar ? "scalar" : "colour", worst,
                    widest);
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

namespace {
namespace edge {

// Textures at the histogram blend's edges, unlike the repository's: odd sizes, 8-bit, linear.
uint32_t hash(uint32_t x, uint32_t y, uint32_t salt) {
    uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ salt * 0xcb1ab31fu;
    h ^= h >> 16, h *= 0x7feb352du, h ^= h >> 15, h *= 0x846ca68bu, h ^= h >> 16;
    return h;
}
double unit(uint32_t x, uint32_t y, uint32_t salt) { return (hash(x, y, salt) >> 8) / 16777216.0; }

// Smooth value noise of period `cell` texels, in [0, 1].
double valueNoise(int x, int y, int cell, uint32_t salt) {
    const double fx = double(x) / cell, fy = double(y) / cell;
    const int ix = int(fx), iy = int(fy);
    const double sx = (fx - ix) * (fx - ix) * (3 - 2 * (fx - ix)), sy = (fy - iy) * (fy - iy) * (3 - 2 * (fy - iy));
    const auto at = [&](int i, int j) { return unit(uint32_t(ix + i), uint32_t(iy + j), salt); };
    return (at(0, 0) * (1 - sx) + at(1, 0) * sx) * (1 - sy) + (at(0, 1) * (1 - sx) + at(1, 1) * sx) * sy;
}

Texture texture(int w, int h, const std::function<std::array<double, 3>(int, int)>& rgb) {
    Texture t;
    t.width = w, t.height = h;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            for (double c : rgb(x, y)) t.rgba8.push_back(uint8_t(std::lround(std::clamp(c, 0.0, 1.0) * 255)));
            t.rgba8.push_back(255);
        }
    return t;
}

// Slate: six grey levels in patches about 9 texels wide (few values, each shared by thousands of texels).
Texture slate() {
    return texture(523, 389, [](int x, int y) {
        const double level = std::floor(std::min(5.999, 6 * valueNoise(x, y, 9, 1)));
        const double v = (40 + 22 * level) / 255;
        return std::array<double, 3>{v, v, 1.02 * v};
    });
}

// Leaf: saturated greens with dark veins and rare yellow-white highlights: a colour distribution far from a box, so
// the sum over the principal axes can leave the texture's range.
Texture leaf() {
    return texture(453, 357, [](int x, int y) {
        const double n = valueNoise(x, y, 7, 2), vein = std::abs(std::sin(0.45 * x + 0.8 * valueNoise(x, y, 13, 3) * 6));
        if (unit(uint32_t(x), uint32_t(y), 4) < 0.004) return std::array<double, 3>{1.0, 1.0, 0.75};
        const double dark = vein < 0.08 ? 0.15 : 1.0;
        return std::array<double, 3>{dark * (0.05 + 0.25 * n), dark * (0.35 + 0.5 * n), dark * 0.04 * n};
    });
}

// Granite: a grey mean with heavy (Cauchy) tails: most texels near 0.45, a few percent anywhere up to 0 and 1.
Texture granite() {
    return texture(509, 403, [](int x, int y) {
        const double c = std::tan(std::numbers::pi * (unit(uint32_t(x), uint32_t(y), 5) - 0.5));
        const double v = 0.45 + 0.04 * c + 0.05 * (valueNoise(x, y, 5, 6) - 0.5);
        return std::array<double, 3>{v * 1.05, v, v * 0.95};
    });
}

// Slate in bands: the same six levels in cleavage layers 24 texels long and 6 high (few values, anisotropic patches).
Texture slateBands() {
    return texture(517, 397, [](int x, int y) {
        const double level = std::floor(std::min(5.999, 6 * valueNoise(x, 4 * y, 24, 7)));
        const double v = (40 + 22 * level) / 255;
        return std::array<double, 3>{1.02 * v, v, v};
    });
}

// Crystal granite: grains of four minerals (pale quartz, pink feldspar, black biotite, dark green hornblende), each
// the cell of the nearest of a jittered grid's points 6 texels apart, with a little noise inside a grain: a few
// colour clusters far apart, in blocks the size of a far pixel.
Texture crystalGranite() {
    static constexpr std::array<std::array<double, 3>, 4> minerals{
        {{0.78, 0.76, 0.72}, {0.80, 0.52, 0.45}, {0.06, 0.05, 0.05}, {0.12, 0.20, 0.14}}};
    return texture(511, 401, [](int x, int y) {
        constexpr int cell = 6;
        double best = INFINITY;
        uint32_t grain = 0;
        for (int j = y / cell - 1; j <= y / cell + 1; ++j)
            for (int i = x / cell - 1; i <= x / cell + 1; ++i) {
                const uint32_t ui = uint32_t(i), uj = uint32_t(j);
                const double px = (i + unit(ui, uj, 8)) * cell, py = (j + unit(ui, uj, 9)) * cell;
                const double d = (px - x) * (px - x) + (py - y) * (py - y);
                if (d < best) best = d, grain = hash(ui, uj, 10);
            }
        const double pick = (grain >> 8) / 16777216.0, jitter = 0.06 * (unit(uint32_t(x), uint32_t(y), 11) - 0.5);
        const auto& m = minerals[pick < 0.35 ? 0 : pick < 0.7 ? 1 : pick < 0.9 ? 2 : 3];
        return std::array<double, 3>{m[0] + jitter, m[1] + jitter, m[2] + jitter};
    });
}

// High contrast: near-black ground with near-white blotches (a quarter of the texels), two values only.
Texture blotches() {
    return texture(505, 409, [](int x, int y) {
        const double v = valueNoise(x, y, 11, 12) > 0.64 ? 0.98 : 0.02;
        return std::array<double, 3>{v, v, v};
    });
}

// Low variance: a flat grey with +-2/255 of noise, five 8-bit values (a plaster or a concrete seen close up).
Texture flatGrey() {
    return texture(503, 401, [](int x, int y) {
        const double v = 0.5 + (std::round(4 * valueNoise(x, y, 4, 13)) - 2) / 255;
        return std::array<double, 3>{v, v, v * 0.98};
    });
}

// Noise of a power spectrum: value noise octaves of cells 2 to 64 texels, each of amplitude cell^slope (0: white-ish,
// every octave alike; 1: pink, 1/f; 2: brown, the large scales dominating), scaled to [0.1, 0.9] from its own extremes.
Texture spectrum(int w, int h, double slope, uint32_t salt) {
    std::vector<double> v(size_t(w) * size_t(h), 0.0);
    for (int cell = 2; cell <= 64; cell *= 2)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                v[size_t(y) * size_t(w) + size_t(x)] += std::pow(cell, slope) * valueNoise(x, y, cell, salt + uint32_t(cell));
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    const double low = *lo, range = *hi - *lo;
    return texture(w, h, [&](int x, int y) {
        const double g = 0.1 + 0.8 * (v[size_t(y) * size_t(w) + size_t(x)] - low) / range;
        return std::array<double, 3>{g, 0.95 * g, 0.9 * g};
    });
}

// White noise: each texel its own uniform value (no spatial correlation at all).
Texture whiteNoise() {
    return texture(507, 399, [](int x, int y) {
        const double v = 0.1 + 0.8 * unit(uint32_t(x), uint32_t(y), 14);
        return std::array<double, 3>{v, v, v};
    });
}

// Sparse granite: a dark ground of fine noise with 1.5 % of isolated pale specks (feldspar in a dark granite): rare
// extremes, one texel each, far from the mean.
Texture sparseGranite() {
    return texture(513, 405, [](int x, int y) {
        if (unit(uint32_t(x), uint32_t(y), 15) < 0.015) return std::array<double, 3>{0.92, 0.86, 0.84};
        const double v = 0.18 + 0.08 * valueNoise(x, y, 3, 16);
        return std::array<double, 3>{v, v, 1.05 * v};
    });
}

// Coarse granite: heavy (Cauchy) tails as granite(), wider (0.10 instead of 0.04), without its smooth term: specks
// everywhere at every size of deviation. Of four seeds (41-44) the one whose far variance kept is the largest, 1.77 (the
// others 1.16-1.20 at 29.3 texels per pixel): the set's edge.
Texture coarseGranite() {
    return texture(501, 407, [](int x, int y) {
        const double c = std::tan(std::numbers::pi * (unit(uint32_t(x), uint32_t(y), 44) - 0.5));
        const double v = 0.5 + 0.10 * c;
        return std::array<double, 3>{v, 0.97 * v, 0.94 * v};
    });
}

// Glyphs: dark strokes on pale paper, a character per 8 x 12 cell: per cell a few of eight strokes (the sides, the
// middles and the diagonals of a 6 x 10 box), one texel wide. Thin high-contrast lines on a flat ground.
Texture glyphs() {
    return texture(504, 408, [](int x, int y) {
        const int cx = x / 8, cy = y / 12, u = x % 8 - 1, v = y % 12 - 1;
        const uint32_t strokes = hash(uint32_t(cx), uint32_t(cy), 18);
        const bool inBox = u >= 0 && u < 6 && v >= 0 && v < 10;
        const bool on =
            inBox && (((strokes & 1) && u == 0) || ((strokes & 2) && u == 5) || ((strokes & 4) && v == 0) || ((strokes & 8) && v == 9) ||
                      ((strokes & 16) && v == 4) || ((strokes & 32) && u == 2) || ((strokes & 64) && std::abs(v - u * 9 / 5) == 0) ||
                      ((strokes & 128) && std::abs(v - (5 - u) * 9 / 5) == 0));
        const double ink = 0.06, paper = 0.88 + 0.03 * (unit(uint32_t(x), uint32_t(y), 19) - 0.5);
        return std::array<double, 3>{on ? ink : paper, on ? ink : 0.97 * paper, on ? 1.5 * ink : 0.9 * paper};
    });
}

struct Stats {
    double variance = 0;  // summed over r, g, b
    std::array<double, 3> lowest{INFINITY, INFINITY, INFINITY}, highest{-INFINITY, -INFINITY, -INFINITY};
};

Stats stats(const Image& image) {
    Stats s;
    const size_t n = size_t(image.width) * size_t(image.height);
    for (size_t c = 0; c < 3; ++c) {
        double mean = 0, squares = 0;
        for (size_t i = 0; i < n; ++i) mean += image.rgba[i * 4 + c] / double(n);
        for (size_t i = 0; i < n; ++i) {
            const double v = image.rgba[i * 4 + c];
            squares += (v - mean) * (v - mean) / double(n);
            s.lowest[c] = std::min(s.lowest[c], v), s.highest[c] = std::max(s.highest[c], v);
        }
        s.variance += squares;
    }
    return s;
}

// The round trip through the table: each texel's Gaussian value read back through level 0's row (T^-1(T(x)), as the
// shader does it magnified), against the texel, in 8-bit units of linear value: the largest error and the share of
// texels off by more than half a step (that would round to another 8-bit value).
struct RoundTrip {
    double worst = 0, shareOff = 0;
};

RoundTrip roundTrip(const Texture& t, const HistogramTransform& h, const reference::SampledTexture& lut) {
    RoundTrip r;
    const size_t n = size_t(t.width) * size_t(t.height);
    for (size_t i = 0; i < n; ++i) {
        const reference::Rgba G{h.gaussian.rgba32f[i * 4], h.gaussian.rgba32f[i * 4 + 1], h.gaussian.rgba32f[i * 4 + 2], 1};
        const reference::Rgba back = reference::inverseTransform(lut, G, 0, false);
        double error = 0;
        for (size_t c = 0; c < 3; ++c) error = std::max(error, std::fabs(back[c] * 255 - t.rgba8[i * 4 + c]));
        r.worst = std::max(r.worst, error);
        r.shareOff += error > 0.5 ? 1.0 / double(n) : 0;
    }
    return r;
}

// The texture's distinct RGB texels, sorted, and the largest gap between adjacent values of one channel among them.
std::vector<std::array<uint8_t, 3>> distinctTexels(const Texture& t) {
    std::vector<std::array<uint8_t, 3>> out;
    for (size_t i = 0; i < t.rgba8.size(); i += 4) out.push_back({t.rgba8[i], t.rgba8[i + 1], t.rgba8[i + 2]});
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

double largestGap(const std::vector<std::array<uint8_t, 3>>& texels) {
    double gap = 0;
    for (size_t c = 0; c < 3; ++c) {
        std::vector<int> values;
        for (const auto& t : texels) values.push_back(t[c]);
        std::sort(values.begin(), values.end());
        for (size_t i = 1; i < values.size(); ++i) gap = std::max(gap, double(values[i] - values[i - 1]));
    }
    return gap;
}

}  // namespace edge
}  // namespace

// The histogram blend at its edges, on a named set of textures unlike the repository's (edge:: above): few-valued
// (slate, slate in bands, flat grey), heavy-tailed (granite, sparse and coarse granite), clustered colours in
// far-pixel-sized grains (crystal granite), high contrast (blotches: two values; glyphs: thin strokes), saturated with
// rare highlights (leaf), and noise of three spectra (white, pink 1/f, brown). Close (0.75 texel per pixel)
// and far (7.37 and 29.3 texels per pixel, about levels 3 and 5), the share of the plain texture's variance each
// blend keeps, rendered the same way, the range the result stays in, and the table's round trip. The textures are
// large enough (about 500 x 400) that level 5 still holds some 200 texels, and the far distances are not whole
// numbers of texels per pixel, so that the plain render's pixels meet its texels at every bilinear phase, as the
// tiles' random offsets do: at 8 and 32 texels per pixel every pixel of the plain render sits at one phase, and its
// variance, the measure's denominator, moved with the view's origin. docs/material-format.md#blend states these
// bounds over this set; the figures of each texture are printed.
TEST(HistogramEdges, KeepContrastAndStayInTheTexturesRange) {
    struct Case {
        const char* name;
        Texture texture;
    };
    const Case cases[] = {{"slate", edge::slate()},
                          {"slate-bands", edge::slateBands()},
                          {"flat-grey", edge::flatGrey()},
                          {"granite", edge::granite()},
                          {"crystal", edge::crystalGranite()},
                          {"blotches", edge::blotches()},
                          {"leaf", edge::leaf()},
                          {"white-noise", edge::whiteNoise()},
                          {"pink-noise", edge::spectrum(509, 401, 1, 20)},
                          {"brown-noise", edge::spectrum(503, 397, 2, 30)},
                          {"sparse-granite", edge::sparseGranite()},
                          {"coarse-granite", edge::coarseGranite()},
                          {"glyphs", edge::glyphs()}};
    double lowest = INFINITY, highest = 0;  // far away, the variance kept over the set
    for (const Case& c : cases) {
        Slot falloff;
        falloff.name = c.name, falloff.kind = SlotKind::Color, falloff.colorSpace = ColorSpace::Linear;
        Slot plain = falloff, histogram = falloff;
        plain.hex.enabled = false;
        histogram.hex.blend = Blend::Histogram;
        const reference::SampledTexture source(c.texture);
        const HistogramTransform h = histogramTransform(c.texture, histogram);
        const reference::SampledTexture gaussian(h.gaussian), lut(h.lut);
        const edge::Stats texels = edge::stats(Image{c.texture.width, c.texture.height, [&] {
                                                         std::vector<float> v;
                                                         for (uint8_t b : c.texture.rgba8) v.push_back(b / 255.0f);
                                                         return v;
                                                     }()});
        const edge::RoundTrip trip = edge::roundTrip(c.texture, h, lut);
        // T^-1(T(x)) between two table entries is their interpolation. A texture of d distinct texels has d - 1 jumps,
        // and where one falls between two entries, the texels whose Gaussian value lies in that interval read a value
        // between the two sides: off by at most the jump (the largest gap between adjacent values of a channel), on at
        // most the Gaussian's share of one interval, 13 / 511 standard deviations x phi(0) = 1.015%, per jump.
        const std::vector<std::array<uint8_t, 3>> distinct = edge::distinctTexels(c.texture);
        std::printf("  %-11s round trip: worst %.2f/255, %.3f%% of texels off by more than 0.5/255 (%zu distinct texels)\n", c.name,
                    trip.worst, 100 * trip.shareOff, distinct.size());
        if (distinct.size() <= 8) {
            EXPECT_LE(trip.shareOff, double(distinct.size() - 1) * 13.0 / 511 / std::sqrt(2 * std::numbers::pi)) << c.name;
            EXPECT_LE(trip.worst, edge::largestGap(distinct) + 1e-3) << c.name;  // 1e-3: float32 table entries
        } else {
            // The rest of the set: docs/material-format.md#blend's bound over it (the computation is deterministic, in
            // fp64 but for the float32 tables: the figures reproduce to far below the bound's rounding). White noise is
            // the edge (19.2 %: 204 values spread evenly, each within a step of an interval's end).
            EXPECT_LE(trip.shareOff, 0.20) << c.name;
        }
        for (double texelsPerPixel : {0.75, 7.37, 29.3}) {
            const int pixels = texelsPerPixel < 1 ? 96 : texelsPerPixel < 10 ? 48 : 32;
            const double span = pixels * texelsPerPixel / c.texture.width;
            const View view{pixels, pixels, {0.31, 0.17, 0.31 + span, 0.17 + span * c.texture.width / c.texture.height}};
            const edge::Stats p = edge::stats(reference::render(plain, source, view, reference::Output::Value));
            const edge::Stats f = edge::stats(reference::render(falloff, source, view, reference::Output::Value));
            const edge::Stats g = edge::stats(reference::render(histogram, gaussian, view, reference::Output::Value, nullptr, &lut));
            const double kept = g.variance / p.variance, keptFalloff = f.variance / p.variance;
            std::printf("  %-11s %5.2f texels/pixel: variance kept: histogram %.2f, falloff %.2f, histogram / falloff %.2f\n", c.name,
                        texelsPerPixel, kept, keptFalloff, kept / keptFalloff);
            for (size_t k = 0; k < 3; ++k) {  // 1e-6: the range is stored in float32
                EXPECT_GE(g.lowest[k], texels.lowest[k] - 1e-6) << c.name;
                EXPECT_LE(g.highest[k], texels.highest[k] + 1e-6) << c.name;
            }
            // Far away, docs/material-format.md#blend's bounds over the set (the measured extremes rounded outwards to
            // 0.05; deterministic, as above): 0.35 (blotches) to 1.77 (coarse granite) of the plain texture's variance,
            // 0.36 to 1.65 of the falloff blend's, at least as much as it on the few-valued slates (measured 1.00 to 1.05).
            if (texelsPerPixel > 1) {
                lowest = std::min(lowest, kept), highest = std::max(highest, kept);
                EXPECT_GE(kept, 0.30) << c.name << " at " << texelsPerPixel;
                EXPECT_LE(kept, 1.80) << c.name << " at " << texelsPerPixel;
                EXPECT_GE(kept / keptFalloff, 0.35) << c.name << " at " << texelsPerPixel;
                EXPECT_LE(kept / keptFalloff, 1.70) << c.name << " at " << texelsPerPixel;
                if (std::string(c.name).starts_with("slate")) {
                    EXPECT_GE(kept / keptFalloff, 1.0) << c.name << " at " << texelsPerPixel;
                }
            } else if (c.name == std::string("granite")) {
                EXPECT_LT(kept, keptFalloff);  // close up, specks filtered in Gaussian space fade
            }
        }
    }
    // The bounds are the set's edges: its extremes lie within 0.05 of them, and past the band the docs stated before the
    // heavy-tailed and thin-stroked textures joined the set (0.30 to 1.55), which these would not have held.
    std::printf("  far away, the variance kept over the set: %.3f to %.3f\n", lowest, highest);
    EXPECT_LE(lowest, 0.35);
    EXPECT_GE(highest, 1.75);
}
