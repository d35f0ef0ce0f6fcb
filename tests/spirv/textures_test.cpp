// The HLSL engines' rewrites of a module's texture reads (spirv/textures.h): the textures as the functions'
// parameters, and Unity's row flip, drawn on the GPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>

#include "compile.h"
#include "hexc/histogram.h"
#include "hexc/spirv.h"
#include "spirv/combined.h"
#include "spirv/textures.h"
#include "support.h"
#include "vk/render.h"

using namespace hexc;

namespace {

// The terrain's functions module, compiled as the HLSL engines compile it (roles as texture arrays).
CompiledMaterial terrainFunctions() {
    CompileOptions options;
    options.functions = true;
    options.targets = {Target::Hlsl};
    options.functionArrays = FunctionArrays::All;
    CompiledMaterial c = compileMaterial(test::exampleTerrain(), options);
    if (!c.result.ok()) throw std::runtime_error(formatAll(c.result.diagnostics));
    return c;
}

TEST(TexturesAsParameters, EachFunctionTakesWhatItReadsItselfOrThroughItsCalls) {
    const CompiledMaterial c = terrainFunctions();
    const TextureParameters p = texturesAsParameters(combineSamplers(c.result.spirv, c.plan));
    EXPECT_EQ(validationErrors(p.words), "");
    const auto& t = p.textures;
    ASSERT_TRUE(t.count("hexc_albedo") && t.count("hexc_normal") && t.count("hexc_normal_normal") && t.count("hexc_height"));
    // The height blend reads the heights' array for every role; each role reads the splat map.
    for (const char* name : {"hexc_albedo", "hexc_normal", "hexc_height"}) {
        const std::vector<std::string>& taken = t.at(name);
        EXPECT_TRUE(std::count(taken.begin(), taken.end(), "hexcTex_splat0")) << name;
        EXPECT_TRUE(std::count(taken.begin(), taken.end(), "hexcArr_height")) << name;
        EXPECT_EQ(std::count(taken.begin(), taken.end(), "hexcArr_albedo"), std::string(name) == "hexc_albedo") << name;
    }
    // hexc_normal_normal reads nothing itself: it calls hexc_normal and passes its textures on.
    EXPECT_EQ(t.at("hexc_normal_normal"), t.at("hexc_normal"));
}

// An asymmetric texture (no flip or turn maps it onto itself): red rises down the rows, green along them, and blue marks
// a block in the top-left quarter only.
Texture asymmetric(bool bottomRowFirst) {
    Texture t{256, 256, false, std::vector<uint8_t>(256 * 256 * 4), {}};
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) {
            uint8_t* p = &t.rgba8[(size_t(bottomRowFirst ? 255 - y : y) * 256 + size_t(x)) * 4];
            p[0] = uint8_t(y), p[1] = uint8_t(x), p[2] = x < 96 && y < 64 ? 255 : 0, p[3] = 255;
        }
    return t;
}

// The value of a material of one albedo slot (`slot`: its JSON) drawn with `textures` bound in the manifest's order; its
// reads flipped with `flip`.
Image drawnSlot(const View& view, const std::string& slot, const std::vector<const Texture*>& textures, bool flip) {
    ParseResult parsed = parseMaterial(R"({"name": "rows", "slots": [)" + slot + "]}", "materials/rows.json");
    if (!parsed.material) throw std::runtime_error(formatAll(parsed.diagnostics));
    const Material m = vk::renderedMaterial(*parsed.material, vk::RenderOutput::Albedo, "");
    CompileOptions options;
    options.targets = {Target::Spirv};
    const CompiledMaterial c = compileMaterial(m, options);
    if (!c.result.ok()) throw std::runtime_error(formatAll(c.result.diagnostics));
    vk::RenderRequest request;
    request.fragmentSpirv = flip ? flipRows(c.result.spirv) : c.result.spirv;
    request.fragmentEntry = c.manifest["targets"]["spirv"]["entry_point"];
    request.uniformData = vk::packParameters(c.manifest);
    request.textures = textures;
    std::string why;
    return vk::renderFragment(*test::runner(&why), request, view);
}

// One slot of that texture, hex-tiled, its value drawn with `texture` bound; its reads flipped with `flip`.
Image drawn(const View& view, const Texture& texture, bool flip) {
    return drawnSlot(view, R"({"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png", "colorspace": "linear",
        "hextiling": {"tiling": 4, "rotation": 1, "falloff": 0.75}})",
                     {&texture}, flip);
}

double maxDifference(const Image& a, const Image& b) {
    double worst = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i) worst = std::max(worst, double(std::fabs(a.rgba[i] - b.rgba[i])));
    return worst;
}

// `draw(view, bottomFirst, flip)`: a shader drawn from its textures as they are or stored bottom row first, its reads
// flipped or not. The flipped shader on the bottom-first textures must draw what the shader draws from the textures as
// they are, magnified (level 0) and minified (level 2, gradients and level choice); the negative controls, the flipped
// shader on the textures as they are and the shader on the bottom-first ones, must not. Bound: the flipped read is the
// mirror image of the read (row r at t, row h - 1 - r at -t; a fetch row h - 1 - r exactly), so the same texels at the
// same weights, but for the 8-bit bilinear weight, which lavapipe rounds from the mirrored fraction and may round the
// other way: one weight step (1/256) of a full-range texel step, per axis, 2/256 < 2/255 in all.
void expectFlippedReadsMatch(const std::function<Image(const View&, bool, bool)>& draw, const char* what) {
    const View magnified{128, 128, {0.3, 0.45, 0.3 + 128 * 0.75 / 1024, 0.45 + 128 * 0.75 / 1024}};
    const View minified{64, 64, {0.3, 0.45, 0.3 + 64.0 * 4 / 1024, 0.45 + 64.0 * 4 / 1024}};
    for (const View& view : {magnified, minified}) {
        const Image expected = draw(view, false, false);
        const double flipped = maxDifference(draw(view, true, true), expected);
        EXPECT_LE(flipped, 2.0 / 255) << what << ", " << view.width << " px";
        EXPECT_GT(maxDifference(draw(view, false, true), expected), 0.25) << what;
        EXPECT_GT(maxDifference(draw(view, true, false), expected), 0.25) << what;
        std::printf("flip rows of %s, %d px: max difference %.2f/255\n", what, view.width, flipped * 255);
    }
}

// Unity's reads of a hex-tiled slot's texture.
TEST(FlipRowsOnTheGpu, AFlippedShaderReadsABottomFirstTextureAsTheShaderReadsTheTexture) {
    REQUIRE_VULKAN();
    const Texture asIs = asymmetric(false), bottomFirst = asymmetric(true);
    expectFlippedReadsMatch(
        [&](const View& view, bool flipTexture, bool flipReads) { return drawn(view, flipTexture ? bottomFirst : asIs, flipReads); },
        "a hex-tiled slot");
}

// `t` stored bottom row first: its rows in reverse order.
Texture bottomRowFirst(Texture t) {
    const size_t row = size_t(t.width) * 4;
    for (int y = 0; y < t.height / 2; ++y)
        for (size_t k = 0; k < row; ++k) {
            const size_t a = size_t(y) * row + k, b = size_t(t.height - 1 - y) * row + k;
            if (t.isFloat())
                std::swap(t.rgba32f[a], t.rgba32f[b]);
            else
                std::swap(t.rgba8[a], t.rgba8[b]);
        }
    return t;
}

// A histogram-blended slot of the asymmetric texture: its Gaussian texture and look-up table, derived from it and bound
// as they are or stored bottom row first; the shader's reads flipped with `flip`. The table is read by texel fetches
// (row 0: the axes, the mean, the range) and by samples at level 0 (a row per mip level).
Image drawnHistogram(const View& view, bool bottomFirst, bool flip) {
    const std::filesystem::path png = std::filesystem::temp_directory_path() / "hexc_flip_rows_histogram.png";
    std::ofstream(png, std::ios::binary) << pngBytes(asymmetric(false));
    const std::string slot = R"({"name": "albedo", "kind": "color", "texture": ")" + png.string() +
                             R"(", "colorspace": "linear", "hextiling": {"tiling": 4, "rotation": 1, "blend": "histogram"}})";
    const ParseResult parsed = parseMaterial(R"({"name": "rows", "slots": [)" + slot + "]}", "materials/rows.json");
    HistogramTransform h = histogramTransform(loadTexture(png, false), parsed.material->slots.front());
    const Texture gaussian = bottomFirst ? bottomRowFirst(h.gaussian) : h.gaussian, lut = bottomFirst ? bottomRowFirst(h.lut) : h.lut;
    return drawnSlot(view, slot, {&gaussian, &lut}, flip);  // the manifest's order: the slot's texture, then its table
}

// The same for texel fetches: the histogram blend's shader reads its table by texel fetches and level-0 samples.
TEST(FlipRowsOnTheGpu, FlippedFetchesReadATableStoredBottomFirstAsTheShaderReadsTheTable) {
    REQUIRE_VULKAN();
    expectFlippedReadsMatch(drawnHistogram, "a histogram slot");
}

}  // namespace
