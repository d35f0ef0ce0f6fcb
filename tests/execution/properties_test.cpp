// Execution tests of properties the GPU output must have whatever the reference says (finite weights summing to
// one, no seams, the gain at one half) and of normal maps against analytic derivatives.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <nlohmann/json.hpp>

#include "hexc/histogram.h"
#include "hexc/library.h"
#include "hexc/material.h"
#include "reference/reference.h"
#include "hexc/spirv.h"
#include "vk/precision.h"
#include "vk/render.h"
#include "support.h"
#include "execution/checks.h"

using namespace hexc;
using namespace hexc::exec;
using hexc::test::runHexc;
using hexc::test::runner;

namespace {

// ---- Properties of the GPU output ----------------------------------------------------------------------------
// The final weights are a normalisation W_i = a_i / (a_1 + a_2 + a_3): the sum and the division each round once
// (2^-24 relative), so |sum_i W_i - 1| <= 3 * 2 * 2^-24 for the three quotients plus 2 * 2^-24 for adding them up.
// Lavapipe divides with a reciprocal refined to full precision; 8 * 2^-24 = 4.8e-7 is the bound.
TEST(Properties, WeightsAreFiniteNonNegativeAndSumToOne) {
    REQUIRE_VULKAN();
    const char* settings[] = {R"({"tiling": 4})",
                              R"({"tiling": 4, "falloff": 0.01})",
                              R"({"tiling": 4, "falloff": 0.99})",
                              R"({"tiling": 4, "exponent": 1})",
                              R"({"tiling": 4, "exponent": 64})",
                              R"({"tiling": 4, "falloffcontrast": 0.9})",
                              R"({"tiling": 4, "rotation": 20})",  // the largest accepted: 20 x 180 degrees = 3600
                              R"({"tiling": 4, "mode": "paper", "falloff": 0.8})"};
    const double bound = 8 * std::ldexp(1.0, -24);
    double worst = 0;
    for (const char* h : settings) {
        Material m =
            material(std::string(R"({"name": "a", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": )") + h + "}");
        Image w = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Weights, "", {128, 128, {0.1, 0.2, 0.6, 0.7}});
        for (size_t i = 0; i < w.rgba.size(); i += 4) {
            const float* p = &w.rgba[i];
            ASSERT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) << h;
            ASSERT_TRUE(p[0] >= 0 && p[1] >= 0 && p[2] >= 0) << h;
            worst = std::max(worst, std::fabs(double(p[0]) + p[1] + p[2] - 1.0));
        }
    }
    std::printf("  weights: largest |sum - 1| %.2e, bound %.2e\n", worst, bound);
    EXPECT_LE(worst, bound);
}

// The checks' own arithmetic: a NaN value or a NaN tolerance (a NaN reference) is never a pass, where std::max
// would keep the worst ratio seen before it; an exact value under a zero tolerance is.
TEST(Properties, ANanIsNeverWithinItsTolerance) {
    EXPECT_EQ(errorRatio(NAN, 1.0), INFINITY);
    EXPECT_EQ(errorRatio(0.5, NAN), INFINITY);
    EXPECT_EQ(errorRatio(0.0, 0.0), 0.0);
    EXPECT_EQ(errorRatio(0.5, 1.0), 0.5);
    Image image{2, 1, {0, 0, 0, 1, 0, NAN, 0, 1}};
    EXPECT_FALSE(allFinite(image));
    image.rgba[5] = 0;
    EXPECT_TRUE(allFinite(image));
}

// No seams: between neighbouring pixels the colour may change only as much as the texture's own content and the
// weights allow. Each tile's sample moves by s texels (s = texels per pixel; rotation keeps lengths), which
// changes a bilinear sample by at most step * s * sqrt(2) (step: the largest difference of adjacent texels). The
// weights change by dW (measured on the GPU's weights output of the same view), which moves the blend by at most
// sum_j |dW_j| / 2 * spread (the dW sum to 0). Each pixel also carries its own filtering error e_s.
// A seam (a wrong mip level or offset at a tile border) breaks this.
TEST(Properties, NoSeamsBetweenNeighbouringPixels) {
    REQUIRE_VULKAN();
    for (const char* tex : {"textures/rock_albedo.png", "textures/tiles_albedo.png"}) {
        Material m = material(std::string(R"({"name": "albedo", "kind": "color", "colorspace": "linear", "texture": ")") + tex +
                              R"(", "hextiling": {"tiling": 4, "falloff": 0.8}})");
        const View view{128, 128, {0.2, 0.3, 0.2 + 128.0 / 1024, 0.3 + 128.0 / 1024}};  // s = 1 texel per pixel
        Image c = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Albedo, "", view);
        Image w = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Weights, "", view);
        ASSERT_TRUE(allFinite(c) && allFinite(w)) << tex;
        TextureBounds b = bounds(sampled(m.slots[0]));
        double es = sampleError(0, false), worstRatio = 0;
        for (int y = 0; y < view.height; ++y)
            for (int x = 0; x < view.width; ++x)
                for (auto [nx, ny] : {std::pair{x + 1, y}, std::pair{x, y + 1}}) {
                    if (nx >= view.width || ny >= view.height) continue;
                    double dW = 0, dC = 0;
                    for (int i = 0; i < 3; ++i) {
                        dW += std::fabs(double(w.at(x, y)[i]) - w.at(nx, ny)[i]);
                        dC = std::max(dC, std::fabs(double(c.at(x, y)[i]) - c.at(nx, ny)[i]));
                    }
                    double allowed = b.step * 1.0 * std::sqrt(2.0) + dW / 2 * b.spread + 2 * es;
                    worstRatio = std::max(worstRatio, dC / allowed);
                }
        std::printf("  %s: largest neighbour difference / allowed %.2f (step %.3f, spread %.3f)\n", tex, worstRatio, b.step, b.spread);
        EXPECT_LE(worstRatio, 1.0) << tex;
    }
}

// r = 0.5 is the gain's identity. Against r = 0.5 + 2^-20: k - 1 = log2(1 / (1 - r)) - 1 ~ 2^-20 * 2 / ln 2 = 2.8e-6,
// and |d g / d k| = |0.5 (2x)^k ln(2x)| <= 0.5 / e, so each weight moves by <= 0.18 * 2.8e-6 = 5e-7, doubled by the
// renormalisation, and the blend of values in [0, 1] by <= 3e-6. The gain's own float32 rounding (pow, division)
// adds a few ulps of 1; 1e-5 bounds both.
TEST(Properties, GainAtOneHalfChangesNothing) {
    REQUIRE_VULKAN();
    const View view{96, 96, {0.3, 0.45, 0.4, 0.55}};
    auto albedo = [&](double r) {
        char slot[256];
        std::snprintf(
            slot, sizeof slot,
            R"({"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 4, "falloff": %.17g}})",
            r);
        return vk::render(*runner(&whyNoVulkan), material(slot), vk::RenderOutput::Albedo, "", view);
    };
    Errors e = compare(albedo(0.5), albedo(0.5 + std::ldexp(1.0, -20)), 4);
    std::printf("  r = 0.5 against r = 0.5 + 2^-20: max %.2e, bound 1e-5\n", e.max);
    EXPECT_LE(e.max, 1e-5);
    const Image acted = albedo(0.75);
    ASSERT_TRUE(allFinite(acted));
    EXPECT_GT(compare(albedo(0.5), acted, 4).max, 1.0 / 255);  // and the gain does act when asked
}

// A ramp normal map: every texel encodes the same derivative (a, b) = (dH/du, dH/dy), y = -v (a green-up map), the
// height field H = a u - b v. Inside a tile rotated by theta (sample point R^T (uv - c) + offset) the height seen is
// H(R^T uv + ...), whose (u, v) gradient is R (a, -b); in (u, y) that is F R F (a, b) = R^T (a, b) with
// F = diag(1, -1): the blended derivative must be (a, b) rotated by minus the tile's angle. Checked where one tile's weight
// exceeds 0.999 (the others can move the result by at most 2 * 0.001 * |(a, b)|), with theta from the mode's
// definition (reference::tileTransform). Stored as float texels: sampling adds no error.
TEST(Properties, RampNormalMapRotatesWithEachTile) {
    REQUIRE_VULKAN();
    const double a = 0.5, b = -0.25;
    std::filesystem::path file = std::filesystem::temp_directory_path() / "hexc_ramp_normal.pfm";
    Image ramp;
    ramp.width = ramp.height = 16;
    ramp.rgba.clear();
    for (int i = 0; i < 16 * 16; ++i) ramp.rgba.insert(ramp.rgba.end(), {float(0.5 - 0.25 * a), float(0.5 - 0.25 * b), 0.75f, 1.0f});
    writeImage(ramp, file);  // n = (-a, -b, 1) / 2 encoded n * 0.5 + 0.5: Listing 9 reads back d = (a, b)
    // Per-tile scale s: the tile shows H(p / s), so its slope is R(-theta)(a, b) / s.
    for (const char* mode :
         {R"("mode": "stable")", R"("mode": "paper")", R"("scalerange": [0.5, 2], "rotationrange": [0, 360], "rotationsteps": 6)"}) {
        Material m = material(std::string(R"({"name": "normal", "kind": "normal", "texture": ")") + file.string() +
                              R"(", "hextiling": {"tiling": 1, )" + mode + "}}");
        const View view{128, 128, {0.0, 0.0, 1.0, 1.0}};
        Image d = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Derivative, "", view);
        std::vector<reference::SlotResult> ref = reference::evaluateView(m.slots[0], sampled(m.slots[0]), view);
        double worst = 0;
        size_t checked = 0;
        for (int j = 0; j < view.height; ++j)
            for (int i = 0; i < view.width; ++i) {
                const reference::SlotResult& r = ref[size_t(j) * view.width + i];
                reference::Triangle tri = reference::lattice({(i + 0.5) / view.width, (j + 0.5) / view.height}, m.slots[0].hex.mode);
                size_t dominant = std::max_element(r.blend.begin(), r.blend.end()) - r.blend.begin();
                if (r.blend[dominant] < 0.999) continue;
                reference::TileTransform tile = reference::tileTransform(tri.id[dominant], m.slots[0].hex);
                double theta = tile.angle;
                double ex = (std::cos(theta) * a + std::sin(theta) * b) / tile.scale,
                       ey = (-std::sin(theta) * a + std::cos(theta) * b) / tile.scale;
                worst = std::max({worst, std::fabs(d.at(i, j)[0] - ex), std::fabs(d.at(i, j)[1] - ey)});
                ++checked;
            }
        // The other tiles' share (< 0.001) moves the result by at most 0.001 times the largest difference of two
        // tiles' slopes, 2 |(a, b)| / min scale; 1e-5: float32 sin/cos and products.
        double bound = 2 * 0.001 * std::hypot(a, b) / m.slots[0].hex.scaleRange[0] + 1e-5;
        std::printf("  ramp (%s): %zu pixels inside tiles, largest |d - R(-theta)(a, b)| %.2e, bound %.2e\n", mode, checked, worst, bound);
        EXPECT_GT(checked, size_t(view.width * view.height / 4));
        EXPECT_LE(worst, bound) << mode;
    }
}

// An analytic height field h(s, t) (periodic, slopes up to about 1.2), given as a height texture and as normal maps
// in both green conventions, each with its documented flip_y. Inside the tiles, the blended derivative must be the
// derivative of the hex-tiled height (the same lattice and weights: falloffcontrast 0), whatever the tile's
// rotation, and the two conventions must give one image. Derivatives are (dH/du, dH/dy) with y up the texture
// (y = -v), the convention of a green-up map and of the tangent frame the templates use.
namespace analytic {
const double kTwoPi = 2 * 3.14159265358979323846;
double h(double s, double t) { return (0.6 * std::sin(kTwoPi * s) * std::cos(kTwoPi * t) + 0.3 * std::sin(kTwoPi * (s + 2 * t))) / kTwoPi; }
double hs(double s, double t) { return 0.6 * std::cos(kTwoPi * s) * std::cos(kTwoPi * t) + 0.3 * std::cos(kTwoPi * (s + 2 * t)); }
double ht(double s, double t) { return -0.6 * std::sin(kTwoPi * s) * std::sin(kTwoPi * t) + 0.6 * std::cos(kTwoPi * (s + 2 * t)); }

// texel(s, t) at each texel centre (row 0 at t = 0, the top), written as a width x height float texture.
std::filesystem::path write(const std::string& name, int width, int height,
                            const std::function<std::array<float, 4>(double, double)>& texel) {
    Image image;
    image.width = width;
    image.height = height;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            auto v = texel((x + 0.5) / width, (y + 0.5) / height);
            image.rgba.insert(image.rgba.end(), v.begin(), v.end());
        }
    std::filesystem::path file = std::filesystem::temp_directory_path() / name;
    writeImage(image, file);
    return file;
}

// A width x height normal map of h whose green axis points up the texture (greenUp) or down it, encoded n * 0.5 + 0.5
// with n = (-dh/dx, -dh/dy, 1) / 2 (Listing 9 divides by z, so n need not be unit length). Its slopes are per unit of
// texel-isotropic space, x = s * width / height and y = t, as a baker writes them with square texels.
std::filesystem::path normalMap(bool greenUp, int width, int height) {
    const std::string name =
        std::string(greenUp ? "hexc_analytic_green_up_" : "hexc_analytic_green_down_") + std::to_string(width) + ".pfm";
    const double aspect = double(width) / height;
    return write(name, width, height, [&](double s, double t) {
        double dy = greenUp ? -ht(s, t) : ht(s, t);
        return std::array<float, 4>{float(0.5 - 0.25 * hs(s, t) / aspect), float(0.5 - 0.25 * dy), 0.75f, 1.0f};
    });
}
}  // namespace analytic

// A case (tests/execution/analytic/): "size", the textures' [width, height], and "hextiling", the settings besides
// tiling 1 and falloffcontrast 0.
class AnalyticNormals : public testing::TestWithParam<ExecCase> {};

TEST_P(AnalyticNormals, MatchTheDerivativeOfTheHexTiledHeight) {
    REQUIRE_VULKAN();
    const nlohmann::json c = readCase(GetParam(), {"size", "hextiling"});
    const vk::ExecutedTarget target = GetParam().target;
    const std::string settings = c.at("hextiling").dump();
    const int tw = c.at("size")[0], th = c.at("size")[1];
    const double aspect = double(tw) / th;
    std::filesystem::path height = analytic::write("hexc_analytic_height_" + std::to_string(tw) + ".pfm", tw, th, [](double s, double t) {
        float v = float(analytic::h(s, t));
        return std::array<float, 4>{v, v, v, 1.0f};
    });
    nlohmann::json hextiling = c.at("hextiling");
    hextiling["tiling"] = 1;
    hextiling["falloffcontrast"] = 0;
    const std::string hex = R"("hextiling": )" + hextiling.dump();
    auto slot = [&](const char* kind, const std::filesystem::path& file, const char* extra) {
        return material(std::string(R"({"name": "s", "kind": ")") + kind + R"(", "colorspace": "linear", "texture": ")" + file.string() +
                        "\", " + extra + hex + "}");
    };
    // One texel a pixel over two texture periods.
    const View view{2 * tw, 2 * th, {0.0, 0.0, 2.0, 2.0}};
    vk::Runner& gpu = *runner(&whyNoVulkan);
    Image up = vk::render(gpu, slot("normal", analytic::normalMap(true, tw, th), R"("flip_y": false, )"), vk::RenderOutput::Derivative, "",
                          view, target);
    Image down = vk::render(gpu, slot("normal", analytic::normalMap(false, tw, th), R"("flip_y": true, )"), vk::RenderOutput::Derivative,
                            "", view, target);
    Image H = vk::render(gpu, slot("scalar", height, ""), vk::RenderOutput::Albedo, "", view, target);
    Image W = vk::render(gpu, slot("scalar", height, ""), vk::RenderOutput::Weights, "", view, target);
    // Both conventions decode to the same derivative up to the float32 rounding of their texels: 0.5 - x and 0.5 + x
    // round with different ulps (2^-25 below 0.5, 2^-24 above), so the decoded greens differ by up to 2 * 2^-24 +
    // 2^-23 = 2.4e-7, and d = -n / z with z = 0.5 doubles it; filtering is a convex combination (no growth), and the
    // rotation and blend add a few float32 ulps of |d| <= 1.5. 1e-6.
    EXPECT_LE(compare(up, down, 2).max, 1e-6);
    // The derivative is in texel-isotropic space (x = s * aspect, y = -t), where the tiles turn: compared with H's
    // gradient there, (dH/ds / aspect, -dH/dt). Checked at pixels where one tile's weight is >= 0.9999 there and at the
    // four neighbours the central difference reads. Tolerance, per component, T = a texel (and a pixel step) in that
    // space, 1 / height (whose derivatives of h are those in st or, along x, smaller by the aspect); for T = 1/256:
    // - H is filtered bilinearly: its slope at a point is that of the interpolant, off by at most (T / 2) max|h''|, and
    //   max|h''| = 2 pi * 1.8 (h_tt), so 11.3 / 512 = 0.022 (the central difference averages it but, in a rotated
    //   tile, need not cancel it);
    // - lavapipe quantises bilinear weights to 8 bits (error <= 1/512 per axis, two axes) of texel differences
    //   <= T max|h'| = 1.5 T: H is off by <= 1.2e-5 T per sample, its central difference by <= 0.0025;
    // - the normal map's filtered slopes: (T^2 / 8) max|h'''| (118) = 2.3e-4, and the 8-bit weights 2 * 11.3 T / 512 =
    //   1.7e-4;
    // - the other tiles (weights <= 1e-4 at all five pixels): in H's difference <= 2 * 1e-4 * 2 max|h| (0.29) / 2T =
    //   0.0074, in the derivative <= 1e-4 * 2 max|grad h| (3.0) = 3e-4;
    // - float32 H (ulp 1.5e-8) over 2T: 4e-6.
    // Sum 0.033, plus 0.002.
    const double T = 1.0 / th;
    const double bound =
        T / 2 * 11.3 + 0.0025 + T * T / 8 * 118 + 2 * 11.3 * T / 512 + 0.0074 / (256 * T) + 3e-4 + 4e-6 / (256 * T) + 0.002;
    const double stepS = 2.0 / view.width, stepT = 2.0 / view.height;
    auto pure = [&](int i, int j, int c) { return W.at(i, j)[c] >= 0.9999f; };
    std::vector<double> errors;
    for (int j = 1; j + 1 < view.height; ++j)
        for (int i = 1; i + 1 < view.width; ++i) {
            const float* w = W.at(i, j);
            int c = int(std::max_element(w, w + 3) - w);
            if (!pure(i, j, c) || !pure(i - 1, j, c) || !pure(i + 1, j, c) || !pure(i, j - 1, c) || !pure(i, j + 1, c)) continue;
            double du = (H.at(i + 1, j)[0] - H.at(i - 1, j)[0]) / (2 * stepS), dv = (H.at(i, j + 1)[0] - H.at(i, j - 1)[0]) / (2 * stepT);
            errors.push_back(std::max(std::fabs(up.at(i, j)[0] - du / aspect), std::fabs(up.at(i, j)[1] + dv)));
        }
    ASSERT_GT(errors.size(), size_t(view.width * view.height / 8));
    std::sort(errors.begin(), errors.end());
    std::printf("  %s: %zu pixels inside tiles, |d - grad H|: median %.4f, max %.4f (bound %.3f)\n", settings.c_str(), errors.size(),
                errors[errors.size() / 2], errors.back(), bound);
    EXPECT_LE(errors.back(), bound);
}

INSTANTIATE_TEST_SUITE_P(Exec, AnalyticNormals, testing::ValuesIn(execCases("tests/execution/analytic")), caseTestName);

}  // namespace
