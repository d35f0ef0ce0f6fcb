// Layered materials on lavapipe against the fp64 reference (reference/layers.h): 1, 2, 4 and 8 layers, the example's
// splat map with its hard (left) and soft (right) borders, vertex-colour weights alone and times the splat map (the
// harness's draw gives the vertex colour (1 - x, x, y, 1 - y) over the view), linear and height blends, the height
// blend's width at its edges, and packed layers. Each case prints its error beside the tolerance it is held to, and the share of pixels a blank image would pass.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

#include "hexc/compiler.h"
#include "hexc/material.h"
#include "execution/layer_checks.h"
#include "reference/layers.h"
#include "support.h"
#include "vk/precision.h"
#include "vk/render.h"

using namespace hexc;
using exec::kSoft;
using exec::LayerCase;

namespace {

class LayerCases : public testing::TestWithParam<std::tuple<LayerCase, vk::ExecutedTarget>> {};

TEST_P(LayerCases, MatchTheReference) {
    const auto& [c, target] = GetParam();
    std::string why;
    if (!test::runner(&why)) {
        if (std::getenv("HEXC_REQUIRE_VULKAN")) FAIL() << why;
        GTEST_SKIP() << why;
    }
    const exec::Check check = exec::checkLayers(c, exec::on(target)).check;
    // Not vacuous: the pixels where a blank image (zeros in the colour channels) would pass too, at most 19 in 20.
    std::vector<double> sorted = check.tolerance;
    std::nth_element(sorted.begin(), sorted.begin() + ptrdiff_t(sorted.size() / 2), sorted.end());
    size_t blank = 0;
    for (size_t p = 0; p < check.tolerance.size(); ++p) {
        bool passes = true;
        for (size_t ch = 0; ch < size_t(std::min(check.channels, 3)); ++ch)
            passes &= std::fabs(check.reference.rgba[p * 4 + ch]) <= check.tolerance[p];
        blank += passes;
    }
    const double blankShare = double(blank) / double(check.tolerance.size());
    std::printf(
        "  %-28s max %.5f (%.2f/255)  mean %.6f  >1/255 %.4f  tolerance median %.5f largest %.5f  worst error/tolerance %.2f"
        "  blank passes at %.1f%%\n",
        c.name, check.errors.max, check.errors.max * 255, check.errors.mean, check.errors.overOne255, sorted[sorted.size() / 2],
        check.maxTolerance, check.worstRatio, 100 * blankShare);
    EXPECT_LE(check.worstRatio, 1.0);
    EXPECT_LE(blankShare, 0.95);
}

INSTANTIATE_TEST_SUITE_P(Exec, LayerCases,
                         testing::Combine(testing::ValuesIn(exec::kLayerCases),
                                          testing::Values(vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl)),
                         [](const auto& info) {
                             return std::string(std::get<0>(info.param).name) +
                                    (std::get<1>(info.param) == vk::ExecutedTarget::Spirv ? "_spirv" : "_hlsl");
                         });

// The manifest's `layers.arrays` of the material compiled (docs/cli.md).
nlohmann::json arraysOf(const Material& m) {
    const CompileResult r = compile(m);
    EXPECT_TRUE(r.ok()) << formatAll(r.diagnostics);
    for (const OutputFile& f : r.files)
        if (f.name.ends_with(".manifest.json")) return nlohmann::json::parse(f.contents)["layers"]["arrays"];
    return {};
}

// A role's textures as one array and as separate textures give the same image, bit for bit: a layer of an array is
// sampled as its own texture (an integer layer, its own mip chain), and the code around the fetches is the same.
TEST(LayerArraysOnTheGpu, AnArrayGivesTheImageOfSeparateTextures) {
    std::string why;
    vk::Runner* runner = test::runner(&why);
    if (!runner) {
        if (std::getenv("HEXC_REQUIRE_VULKAN")) FAIL() << why;
        GTEST_SKIP() << why;
    }
    for (const char* role : {"albedo", "normal"}) {
        ParseResult parsed = parseMaterialFile("tests/execution/layers/four_height.json");
        ASSERT_TRUE(parsed.material) << formatAll(parsed.diagnostics);
        Material arrays = vk::layerRoleFirst(*parsed.material, *vk::layerRole(*parsed.material, role));
        Material separate = arrays;
        separate.layers->arrays = false;
        ASSERT_EQ(arraysOf(arrays)[0]["array"], true) << role;
        ASSERT_EQ(arraysOf(separate)[0]["array"], false) << role;
        const Image a = vk::render(*runner, arrays, vk::RenderOutput::Shaded, "", kSoft, vk::ExecutedTarget::Spirv);
        const Image b = vk::render(*runner, separate, vk::RenderOutput::Shaded, "", kSoft, vk::ExecutedTarget::Spirv);
        size_t differ = 0;
        for (size_t i = 0; i < a.rgba.size(); ++i) differ += a.rgba[i] != b.rgba[i];
        std::printf("  %s: %zu of %zu values differ between the array and separate textures\n", role, differ, a.rgba.size());
        EXPECT_EQ(differ, 0u) << role;
    }
    // The sizes case's albedo falls back, its normal role does not.
    ParseResult sizes = parseMaterialFile("tests/execution/layers/four_sizes.json");
    ASSERT_TRUE(sizes.material) << formatAll(sizes.diagnostics);
    const nlohmann::json arrays = arraysOf(*sizes.material);
    EXPECT_EQ(arrays[0]["why_not"].get<std::string>().rfind("sizes differ", 0), 0u) << arrays[0];
    EXPECT_EQ(arrays[1]["array"], true) << arrays[1];
}

// A folder of the textures the height-mode tests draw: a splat map that ramps layer 1's weight from 0 to 1 across 256
// texels (r = 255 - i, g = i), 4 rows, and constant textures c0, c102, c153 and c255 (8 x 4 texels of that grey).
std::filesystem::path rampTextures(const std::string& prefix) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / (prefix + test::testLogName());
    std::filesystem::create_directories(dir);
    auto write = [&](const std::string& name, int width, const std::function<std::array<uint8_t, 4>(int)>& texel) {
        Texture t{width, 4, false, std::vector<uint8_t>(size_t(width) * 16), {}};
        for (int i = 0; i < width * 4; ++i) std::copy_n(texel(i % width).begin(), 4, &t.rgba8[size_t(i) * 4]);
        std::ofstream(dir / name, std::ios::binary) << pngBytes(t);
    };
    write("splat.png", 256, [](int i) { return std::array<uint8_t, 4>{uint8_t(255 - i), uint8_t(i), 0, 0}; });
    for (int v : {0, 102, 153, 255})
        write("c" + std::to_string(v) + ".png", 8, [&](int) { return std::array<uint8_t, 4>{uint8_t(v), uint8_t(v), uint8_t(v), 255}; });
    return dir;
}

// Two layers blended by height over rampTextures' splat map, whose scalar value is 0 (layer a) and 1 (layer b), so
// that the value template shows layer b's final weight; their heights the constant textures c<h0> and c<h1>; `blend`
// the layer_blend's further keys.
Material twoLayers(const std::filesystem::path& dir, int h0, int h1, const std::string& blend) {
    const std::string layer = R"({"name": "%s", "slots": [{"name": "value", "kind": "scalar", "texture": "c%d.png"},
        {"name": "height", "kind": "scalar", "texture": "c%d.png"}]})";
    char a[256], b[256];
    std::snprintf(a, sizeof a, layer.c_str(), "a", 0, h0);
    std::snprintf(b, sizeof b, layer.c_str(), "b", 255, h1);
    std::ofstream(dir / "m.json") << R"({"name": "height_layers", "hextiling": {"tiling": 4}, "layers": [)" << a << "," << b
                                  << R"(], "layer_blend": {"splat": ["splat.png"], "mode": "height", "height": "height", )" << blend
                                  << "}}";
    ParseResult parsed = parseMaterialFile(dir / "m.json");
    if (!parsed.material) throw std::runtime_error(formatAll(parsed.diagnostics));
    Material m = *parsed.material;
    m.templ = TemplateRef::builtin("value");
    return m;
}

// The height blend's width at its edges: two layers whose scalar value is 0 and 1 (so the output is layer 1's final
// weight), with constant heights h0 = 153/255 and h1 = 102/255, and a splat map that ramps layer 1's weight from 0 to 1
// across 256 texels (r = 255 - i, g = i), read at its texel centres (one pixel per texel): at pixel i, s1 = x = i / 255
// and s0 = 1 - x. With a_0 = h0 + 1 - x and a_1 = h1 + x, layer 1's weight is exactly 0 where a_0 - a_1 >= width
// (x <= (1 + h0 - h1 - width) / 2) and exactly 1 where a_1 - a_0 >= width, and between the two follows
// b_1 / (b_0 + b_1). Widths: one 8-bit step (as hard as the splat map resolves), the default 0.2 and the widest, 1,
// whose upper edge lies past x = 1: there only the last pixel, where s0 = 0 drops layer 0 (skip_below), shows layer 1
// alone. And widths below what float resolves: 1e-8 and the smallest allowed, the smallest positive double, which act
// as 2^-22 (what float resolves below 2), a hard border with the tie at pixel 153 (a_0 = a_1 = 1) in between.
TEST(LayerHeightWidth, TheWeightsReachZeroAndOneAtTheWidthsEdges) {
    std::string why;
    vk::Runner* runner = test::runner(&why);
    if (!runner) {
        if (std::getenv("HEXC_REQUIRE_VULKAN")) FAIL() << why;
        GTEST_SKIP() << why;
    }
    const std::filesystem::path dir = rampTextures("hexc_height_width_");
    const double h0 = 153 / 255.0, h1 = 102 / 255.0;
    for (double asked : {1 / 255.0, 0.2, 1.0, 1e-8, std::numeric_limits<double>::denorm_min()}) {
        char w[32];
        std::snprintf(w, sizeof w, "%.17g", asked);
        Material m = twoLayers(dir, 153, 102, std::string(R"("width": )") + w);
        const double width = m.layers->width;  // the width asked for, 2^-22 below it (docs/material-format.md#layers)
        EXPECT_EQ(width, std::max(asked, 0x1p-22));
        const View view{256, 1, {0, 0, 1, 0.25}};  // pixel i at the splat's texel i's centre
        const Image gpu = vk::render(*runner, m, vk::RenderOutput::Shaded, "", view, vk::ExecutedTarget::Spirv);
        const std::vector<reference::LayerResult> ref = reference::evaluateLayersView(m, 0, reference::LayerTextures(m), view);
        // Every input is exact but for float rounding: a splat texel read at its centre (the interpolated uv within a
        // few ulp of it moves the filter by < 1e-4 texel, < 1e-6 of a weight), a constant texture hex-tiled (tile weights
        // summing to 1 within a few ulp). With delta = 1e-5 bounding both, each a_i moves by <= 2 delta, each b_i by
        // <= 4 delta and B = b_0 + b_1 >= width by <= 8 delta, so layer 1's weight b_1 / B by <= 12 delta / width.
        const double delta = 1e-5, tolerance = std::min(12 * delta / width, 1.0);
        int zeros = 0, ones = 0, between = 0;
        double worst = 0;
        for (int i = 0; i < 256; ++i) {
            const double x = i / 255.0, d = (h1 + x) - (h0 + 1 - x), got = gpu.at(i, 0)[0];
            EXPECT_NEAR(ref[size_t(i)].weights[1], ref[size_t(i)].value[0], 1e-12);
            EXPECT_NEAR(got, ref[size_t(i)].value[0], tolerance) << "width " << width << " x " << x;
            worst = std::max(worst, std::fabs(got - ref[size_t(i)].value[0]));
            if (d <= -width - 4 * delta) {  // past the lower edge by more than d's error: layer 1 not fetched
                EXPECT_EQ(got, 0.0) << "width " << width << " x " << x;
                ++zeros;
            } else if (d >= width + 4 * delta || i == 255) {  // past the upper edge (or s0 = 0, dropped): layer 1 alone
                EXPECT_NEAR(got, 1.0, 1e-6) << "width " << width << " x " << x;
                ++ones;
            } else if (width > 8 * delta) {  // a band wider than d's error: strictly between
                EXPECT_GT(got, 0.0) << "width " << width << " x " << x;
                EXPECT_LT(got, 1.0) << "width " << width << " x " << x;
                ++between;
            } else {  // within d's error of the tie: either layer, or a blend of the two, but a weight
                EXPECT_TRUE(got >= 0.0 && got <= 1.0) << "width " << width << " x " << x << ": " << got;
                ++between;
            }
        }
        std::printf("  width %.3g: %d pixels at 0, %d between, %d at 1; largest error %.2e (tolerance %.2e)\n", width, zeros, between, ones,
                    worst, tolerance);
        // The edges, from the definition: x = (1 + h0 - h1 -+ width) / 2, at pixels x * 255.
        EXPECT_EQ(zeros, int(std::floor((1 + h0 - h1 - width) / 2 * 255 + 1e-9)) + 1) << width;
        EXPECT_EQ(ones, std::max(1, 255 - int(std::ceil((1 + h0 - h1 + width) / 2 * 255 - 1e-9)) + 1)) << width;
    }
}

// skip_below in height mode acts on the height blend's shares: a result in [0, 1] moves by at most the shares it drops
// (docs/material-format.md#layers). Layer a of height 0 and value 0, layer b of height 1 and value 1, over the ramp
// (pixel i at texel i's centre: s_b = x = i / 255): a_a = 1 - x, a_b = 1 + x, so layer b is on top (b_b = width) and
// layer a's share is f_a = max(width - 2x, 0) / (width + max(width - 2x, 0)), from about 1/2 down to 0 at x = width / 2.
// Exact (nothing skipped) the value shown is 1 - f_a; where f_a < skip_below, layer a drops and it is 1: off by f_a,
// just under skip_below at the pixels nearest the threshold, the bound's edge. Inputs are exact but for float rounding,
// so (as in the width test) a share moves by at most 12 delta / width: the tolerance, and the band around skip_below
// where either side of the threshold is right. The negative control: skipping on the splat weights before the heights
// (as before) drops layer b where x < skip_below although it is on top (about half the value), which the bound refuses.
TEST(LayerSkipBelow, InHeightModeTheValueMovesByAtMostTheDroppedShares) {
    std::string why;
    vk::Runner* runner = test::runner(&why);
    if (!runner) {
        if (std::getenv("HEXC_REQUIRE_VULKAN")) FAIL() << why;
        GTEST_SKIP() << why;
    }
    const std::filesystem::path dir = rampTextures("hexc_skip_height_");
    const double width = 0.2, delta = 1e-5, tolerance = 12 * delta / width;
    for (double skip : {0.25, 0.1}) {
        char blend[64];
        std::snprintf(blend, sizeof blend, R"("width": 0.2, "skip_below": %.17g)", skip);
        const Material m = twoLayers(dir, 0, 255, blend);
        const Image gpu = vk::render(*runner, m, vk::RenderOutput::Shaded, "", View{256, 1, {0, 0, 1, 0.25}}, vk::ExecutedTarget::Spirv);
        double worst = 0, worstOld = 0;  // the largest error over its bound, the new and the old way
        int dropped = 0;
        for (int i = 1; i < 256; ++i) {  // pixel 0: s_b = 0, layer a alone either way
            const double x = i / 255.0, ba = std::max(width - 2 * x, 0.0), fa = ba / (width + ba), exact = 1 - fa;
            const double bound = (fa < skip + tolerance ? fa : 0) + tolerance, got = gpu.at(i, 0)[0];
            EXPECT_LE(std::fabs(got - exact), bound) << "skip_below " << skip << " x " << x;
            if (std::fabs(fa - skip) > tolerance) {  // not at the threshold: dropped or kept as the reference is
                EXPECT_NEAR(got, fa < skip ? 1.0 : exact, tolerance) << "skip_below " << skip << " x " << x;
            }
            dropped += fa > 0 && fa < skip;
            worst = std::max(worst, std::fabs(got - exact) / skip);
            const double old = x < skip ? 0.0 : exact;  // layer b dropped for its splat weight
            worstOld = std::max(worstOld, std::fabs(old - exact) / bound);
        }
        std::printf(
            "  skip_below %.3g: %d pixels drop layer a's share; largest change %.4f = %.2f x skip_below (bound 1); "
            "skipping before the heights: %.1f x its bound\n",
            skip, dropped, worst * skip, worst, worstOld);
        EXPECT_GT(dropped, 0);
        EXPECT_GT(worst, 0.85) << "the bound is reached within the ramp's step";
        EXPECT_GT(worstOld, 1.0) << "the negative control passes the bound";
    }
}

// A KTX2 array: the 80-byte header and index, one level whose data is the layers' texels one after another (KTX2's
// level 0 of an array), a vkFormat of R8G8B8A8 UNORM (37) or sRGB (43). The fields a reader needs, no more.
void writeKtx2Array(const std::filesystem::path& file, const std::vector<Texture>& layers, bool srgb) {
    std::string b(104, '\0');
    auto put = [&](size_t at, uint64_t v, int bytes) {
        for (int i = 0; i < bytes; ++i) b[at + size_t(i)] = char(v >> (8 * i));
    };
    const char magic[12] = {'\xAB', 'K', 'T', 'X', ' ', '2', '0', '\xBB', '\r', '\n', '\x1A', '\n'};
    b.replace(0, 12, magic, 12);
    put(12, srgb ? 43 : 37, 4);
    put(16, 1, 4);  // typeSize
    put(20, uint64_t(layers[0].width), 4);
    put(24, uint64_t(layers[0].height), 4);
    put(32, layers.size(), 4);  // layerCount
    put(36, 1, 4);              // faceCount
    put(40, 1, 4);              // levelCount
    put(80, 104, 8);            // level 0's byte offset and length
    put(88, layers.size() * layers[0].rgba8.size(), 8);
    for (const Texture& t : layers) b.append(t.rgba8.begin(), t.rgba8.end());
    std::ofstream(file, std::ios::binary) << b;
}

// A layered material whose roles come from KTX2 arrays (`"layer": i`) holding the texels of its separate files renders
// the image of the separate form (whose roles are arrays hexc assembles), bit for bit: the same texels uploaded in the
// same format to the same array layers, read by the same code; and within the reference's bound, which reads each
// slot's layer of the file.
TEST(LayerArraysOnTheGpu, AKtx2ArrayGivesTheImageOfTheSeparateFiles) {
    std::string why;
    vk::Runner* runner = test::runner(&why);
    if (!runner) {
        if (std::getenv("HEXC_REQUIRE_VULKAN")) FAIL() << why;
        GTEST_SKIP() << why;
    }
    const std::filesystem::path source = "tests/execution/layers/four_height.json";
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("hexc_ktx2_layers_" + test::testLogName());
    std::filesystem::create_directories(dir);
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(source));
    std::map<std::string, std::vector<Texture>> roles;  // per role, its layers' texels in layer order
    for (size_t l = 0; l < doc["layers"].size(); ++l)
        for (nlohmann::json& slot : doc["layers"][l]["slots"]) {
            const std::string role = slot["name"];
            roles[role].push_back(loadTexture(source.parent_path() / slot["texture"].get<std::string>(), false));
            slot["texture"] = role + ".ktx2";
            slot["layer"] = l;
        }
    for (const auto& [role, layers] : roles) writeKtx2Array(dir / (role + ".ktx2"), layers, role == "albedo");
    doc["layer_blend"]["splat"][0] =
        std::filesystem::absolute(source.parent_path() / doc["layer_blend"]["splat"][0].get<std::string>()).string();
    std::ofstream(dir / "four_height.json") << doc.dump();
    ParseResult separate = parseMaterialFile(source), ktx2 = parseMaterialFile(dir / "four_height.json");
    ASSERT_TRUE(separate.material) << formatAll(separate.diagnostics);
    ASSERT_TRUE(ktx2.material) << formatAll(ktx2.diagnostics);
    for (const char* role : {"albedo", "normal"}) {
        const Material a = vk::layerRoleFirst(*ktx2.material, *vk::layerRole(*ktx2.material, role));
        const Material b = vk::layerRoleFirst(*separate.material, *vk::layerRole(*separate.material, role));
        const nlohmann::json arrays = arraysOf(a);
        ASSERT_EQ(arrays[0]["file"], std::string(role) + ".ktx2") << arrays[0];
        EXPECT_EQ(compile(a).glsl, compile(b).glsl) << role << ": the same code as the assembled arrays'";
        // The check of the case with the same material, role and view (four_layers_height_soft, four_layers_normal).
        const exec::LayerCase& c = *std::find_if(std::begin(exec::kLayerCases), std::end(exec::kLayerCases), [&](const LayerCase& k) {
            return k.file == source.filename() && k.role == std::string(role) && k.view.uvRect == kSoft.uvRect;
        });
        const exec::Check check = exec::checkLayers(*ktx2.material, c, exec::on(vk::ExecutedTarget::Spirv)).check;
        const Image assembled = vk::render(*runner, b, vk::RenderOutput::Shaded, "", kSoft, vk::ExecutedTarget::Spirv);
        EXPECT_EQ(vk::render(*runner, a, vk::RenderOutput::Shaded, "", kSoft, vk::ExecutedTarget::Spirv).rgba, assembled.rgba) << role;
        std::printf("  %s (%s): the KTX2 arrays' image is the separate files'; largest error %.2e, worst error/tolerance %.3f\n", role,
                    c.name, check.errors.max, check.worstRatio);
        EXPECT_LE(check.worstRatio, 1.0) << role;
    }
}

}  // namespace
