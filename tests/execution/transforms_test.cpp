// Execution tests of the per-tile transforms (docs/material-format.md#per-tile-transforms) on every executed target:
// offset 0 and offsetsteps keep a grid texture aligned in every mask, and a non-square texture keeps its shape in
// tiles turned by 90 degrees.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <random>
#include <string>

#include "hexc/image.h"
#include "hexc/material.h"
#include "reference/reference.h"
#include "support.h"
#include "vk/precision.h"
#include "vk/render.h"

using namespace hexc;

namespace {

const auto kTargets = testing::Values(vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl);
const char* kTargetNames[] = {"spirv", "hlsl", "glsl"};

// A float texture of texel(x, y) at each texel (x, y), written to a temporary file.
std::filesystem::path writeTexture(const std::string& name, int width, int height,
                                   const std::function<std::array<float, 4>(int, int)>& texel) {
    Image image;
    image.width = width;
    image.height = height;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::array<float, 4> v = texel(x, y);
            image.rgba.insert(image.rgba.end(), v.begin(), v.end());
        }
    const std::filesystem::path file = std::filesystem::temp_directory_path() / name;
    writeImage(image, file);
    return file;
}

// A one-slot colour material of `file` with the given hex-tiling settings.
Material colourMaterial(const std::filesystem::path& file, const std::string& hextiling) {
    const ParseResult r =
        parseMaterial(R"({"name": "exec", "slots": [{"name": "albedo", "kind": "color", "colorspace": "linear", "texture": ")" +
                          file.string() + R"(", "hextiling": )" + hextiling + "}]}",
                      "materials/exec.json");
    if (!r.material) throw std::runtime_error(formatAll(r.diagnostics));
    return *r.material;
}

// The largest difference between neighbouring texels of a texture, in any channel.
double largestStep(const std::function<std::array<float, 4>(int, int)>& texel, int width, int height) {
    double step = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (size_t c = 0; c < 3; ++c) {
                step = std::max(step, double(std::fabs(texel(x, y)[c] - texel((x + 1) % width, y)[c])));
                step = std::max(step, double(std::fabs(texel(x, y)[c] - texel(x, (y + 1) % height)[c])));
            }
    return step;
}

struct GridCase {
    const char* name;
    const char* mask;
};

class GridAlignment : public testing::TestWithParam<std::tuple<GridCase, vk::ExecutedTarget>> {};

// A 128x128 texture of 4x4 copies of one smooth, asymmetric 32x32 cell. Without rotation, `"offset": 0` and
// `"offsetsteps": [4, 4]` (with the full offset) must read the plain texture: every tile shows it where it is, or
// moved by whole cells.
TEST_P(GridAlignment, OffsetZeroAndOffsetStepsReadThePlainTexture) {
    REQUIRE_VULKAN();
    const auto [which, target] = GetParam();
    const double kTwoPi = 6.283185307179586;
    const auto cell = [&](int x, int y) {
        const double u = (x % 32 + 0.5) / 32, v = (y % 32 + 0.5) / 32;
        return std::array<float, 4>{float(0.5 + 0.25 * std::sin(kTwoPi * u) + 0.2 * std::sin(kTwoPi * (u + 2 * v))),
                                    float(0.5 + 0.4 * std::cos(kTwoPi * v)), float(0.3 + 0.2 * std::sin(kTwoPi * (2 * u - v))), 1.0f};
    };
    const std::filesystem::path file = writeTexture("hexc_grid_4x4.pfm", 128, 128, cell);
    // One texel a pixel over two texture periods, in a corner away from the origin.
    const View view{256, 256, {3.0, 5.0, 5.0, 7.0}};
    vk::Runner& gpu = *hexc::test::runner(&whyNoVulkan);
    const Image plain =
        vk::render(gpu, colourMaterial(file, R"({"enabled": false, "tiling": 1})"), vk::RenderOutput::Albedo, "", view, target);
    // The tiles sample the plain texture's points up to float32 rounding (|st - c| < 28: 2e-6 st, 2.4e-4 of a texel),
    // which may move lavapipe's 8-bit bilinear weight by one step of 1/256 on each axis: 2 / 256 of the largest
    // step between neighbouring texels. The blend of equal samples is that sample (weights sum to 1, 1e-6 in float32).
    const double tolerance = 2.0 / 256 * largestStep(cell, 128, 128) + 1e-6;
    for (const char* settings : {R"("offset": 0)", R"("offsetsteps": [4, 4])"}) {
        const std::string hex = std::string(R"({"tiling": 1, "rotation": 0, "mask": ")") + which.mask + R"(", )" + settings + "}";
        const Image tiled = vk::render(gpu, colourMaterial(file, hex), vk::RenderOutput::Albedo, "", view, target);
        const vk::ImageErrors e = vk::compareImages(tiled, plain, 3);
        std::printf("  %s, %s: against the plain texture max %.5f (%.2f/255), tolerance %.5f\n", which.mask, settings, e.max, e.max * 255,
                    tolerance);
        EXPECT_LE(e.max, tolerance) << settings;
    }
}

INSTANTIATE_TEST_SUITE_P(Exec, GridAlignment,
                         testing::Combine(testing::Values(GridCase{"hex", "hex"}, GridCase{"checker", "checker"},
                                                          GridCase{"noise", "noise"}, GridCase{"noise3", "noise3"}),
                                          kTargets),
                         [](const auto& info) {
                             return std::string(std::get<0>(info.param).name) + "_" + kTargetNames[int(std::get<1>(info.param))];
                         });

// The x/y gradient energy of an image's first channel: sum of squared differences between horizontal neighbours
// over the same between vertical ones.
double gradientEnergyRatio(const Image& image) {
    double ex = 0, ey = 0;
    for (int y = 0; y + 1 < image.height; ++y)
        for (int x = 0; x + 1 < image.width; ++x) {
            ex += std::pow(image.at(x + 1, y)[0] - image.at(x, y)[0], 2);
            ey += std::pow(image.at(x, y + 1)[0] - image.at(x, y)[0], 2);
        }
    return ex / ey;
}

class NonSquareShape : public testing::TestWithParam<vk::ExecutedTarget> {};

// Round blobs on a 300x170 texture, one texel a pixel: tiles turned by 90 degrees show them round, as unturned tiles
// do. Turning st instead stretches them 300 / 170 = 1.76 times along one axis and squeezes them along the other,
// which moves the x/y gradient-energy ratio by a factor of about 1.76^4 = 9.7 inside the tiles.
TEST_P(NonSquareShape, TilesTurnedNinetyDegreesKeepRoundBlobsRound) {
    REQUIRE_VULKAN();
    const vk::ExecutedTarget target = GetParam();
    const int w = 300, h = 170;
    // 60 Gaussian blobs of radius sigma = 4 texels at random texel positions (wrapping), brightness 1 at their centres.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<std::array<double, 2>> centres(60);
    for (auto& c : centres) c = {unit(rng) * w, unit(rng) * h};
    const auto blobs = [&](int x, int y) {
        double v = 0;
        for (const auto& c : centres) {
            const double dx = std::remainder(x + 0.5 - c[0], double(w)), dy = std::remainder(y + 0.5 - c[1], double(h));
            v += std::exp(-(dx * dx + dy * dy) / (2 * 16.0));
        }
        const float f = float(std::min(v, 1.0));
        return std::array<float, 4>{f, f, f, 1.0f};
    };
    const std::filesystem::path file = writeTexture("hexc_blobs_300x170.pfm", w, h, blobs);
    const View view{600, 340, {0.0, 0.0, 2.0, 2.0}};
    vk::Runner& gpu = *hexc::test::runner(&whyNoVulkan);
    const auto ratio = [&](const char* range, Image* out) {
        // No falloff metric and no gain: the blend weights are the lattice's alone, the same in both renders.
        const std::string hex = std::string(R"({"tiling": 1, "falloffcontrast": 0, "rotationrange": )") + range + "}";
        *out = vk::render(gpu, colourMaterial(file, hex), vk::RenderOutput::Albedo, "", view, target);
        return gradientEnergyRatio(*out);
    };
    Image unturned, turned;
    const double r0 = ratio("[0, 0]", &unturned), r90 = ratio("[90, 90]", &turned);
    // The reference, from its own definition of the rule, renders the turned tiles as the GPU does: lavapipe's 8-bit
    // bilinear weights put a sample within 2 * 0.5 / 256 of the largest neighbour step; float32 coordinates and weights
    // add well under 1e-4.
    const Material m = colourMaterial(file, R"({"tiling": 1, "falloffcontrast": 0, "rotationrange": [90, 90]})");
    const Image cpu = reference::render(m.slots[0], reference::SampledTexture(loadTexture(file, false)), view, reference::Output::Value);
    const double tolerance = largestStep(blobs, w, h) / 256 + 1e-4;
    const vk::ImageErrors e = vk::compareImages(turned, cpu, 3);
    // Both renders show round blobs; the texture's own ratio (about 1) decides both, so they agree to the spread of
    // which blobs the tiles show: 15% (the renders hold about 500 blobs each; a blob's ratio varies with its overlaps).
    std::printf("  x/y gradient energy: unturned %.3f, turned 90 degrees %.3f; turned against the reference max %.5f, tolerance %.5f\n", r0,
                r90, e.max, tolerance);
    EXPECT_LE(e.max, tolerance);
    EXPECT_NEAR(std::log(r90 / r0), 0.0, std::log(1.15));
}

INSTANTIATE_TEST_SUITE_P(Exec, NonSquareShape, kTargets, [](const auto& info) { return std::string(kTargetNames[int(info.param)]); });

}  // namespace
