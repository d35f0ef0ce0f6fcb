// Execution tests of `hexc library`'s files in hand-written shaders and of the bench's paper listing, on lavapipe
// against the fp64 CPU reference.
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

// ---- The library for hand-written shaders ------------------------------------------------------------------------

// materials/library/<file> with its `#include "hexc_hextiling.<ext>"` line replaced by `hexc library`'s file, as
// an include path would give it.
std::string withLibrary(const std::string& file, Target target) {
    std::ifstream in("materials/library/" + file);
    std::string text(std::istreambuf_iterator<char>(in), {});
    const OutputFile library = hexcLibrary({target}).front();
    const std::string line = "#include \"" + library.name + "\"";
    const size_t at = text.find(line);
    if (at == std::string::npos) throw std::runtime_error(file + " does not include " + library.name);
    return text.replace(at, line.size(), library.contents);
}

// The hand-written shaders' Settings block (std140, which the HLSL cbuffer's packing matches): tiling, rotation,
// falloff, falloffContrast, exponent of the slot.
std::vector<uint8_t> settingsBlock(const Slot& slot) {
    const HexTiling& h = slot.hex;
    const float values[] = {float(h.tiling[0]), float(h.tiling[1]),       float(h.rotation),
                            float(h.falloff),   float(h.falloffcontrast), float(h.exponent)};
    std::vector<uint8_t> bytes(sizeof(values));
    std::memcpy(bytes.data(), values, sizeof(values));
    return bytes;
}

// A hand-written shader, bound as its source declares: the block at binding 0, the texture at `firstTexture`, the
// sampler at `sampler` (unread when combined), all in set 0.
Draw handWritten(const std::vector<uint32_t>& spirv, uint32_t firstTexture, uint32_t sampler, bool combined) {
    return [=](const Material& m, vk::RenderOutput, const View& view) {
        const Slot& slot = m.slots[0];
        const Texture texture = loadTexture(slot.texturePath, slot.colorSpace == ColorSpace::Srgb);
        vk::RenderRequest request;
        request.fragmentSpirv = spirv;
        request.uniformData = settingsBlock(slot);
        request.textures = {&texture};
        request.combinedSamplers = combined;
        request.paramsBinding = 0;
        request.samplerBinding = sampler;
        request.firstTextureBinding = firstTexture;
        std::string why;
        return vk::renderFragment(*runner(&why), request, view);
    };
}

// materials/library/hextiled_color.hlsl with the HLSL library, through glslang's HLSL front end, on rock's albedo
// (sRGB, rotation 1, falloff 0.75): the reference and tolerances of the falloff rule, magnified and minified.
TEST(Library, AHandWrittenHlslShaderMatchesTheReference) {
    REQUIRE_VULKAN();
    SpirvResult front = compileToSpirv(withLibrary("hextiled_color.hlsl", Target::Hlsl), ShaderStage::Fragment, "hextiled_color.hlsl",
                                       SourceLanguage::Hlsl, "main");
    ASSERT_FALSE(front.words.empty()) << formatAll(front.diagnostics);
    SpirvResult legal = optimizeSpirv(front.words, false, true);
    ASSERT_FALSE(legal.words.empty()) << formatAll(legal.diagnostics);
    const Draw draw = handWritten(legal.words, kHlslTextureShift, kHlslSamplerShift, false);
    for (bool minified : {false, true}) {
        Check check = checkColor(slotOf("albedo"), minified, draw);
        report(minified ? "hand-written HLSL, minified" : "hand-written HLSL", check);
        EXPECT_LE(check.worstRatio, 1.0);
    }
}

// materials/library/hextiled_normal.glsl with the OpenGL GLSL library, through glslang, on rock's normal map: the
// reference and tolerances of the derivative rule.
TEST(Library, AHandWrittenGlslShaderMatchesTheReference) {
    REQUIRE_VULKAN();
    SpirvResult front = compileToSpirv(withLibrary("hextiled_normal.glsl", Target::Glsl), ShaderStage::Fragment, "hextiled_normal.glsl",
                                       SourceLanguage::OpenGlGlsl);
    ASSERT_FALSE(front.words.empty()) << formatAll(front.diagnostics);
    SpirvResult optimized = optimizeSpirv(front.words);
    ASSERT_FALSE(optimized.words.empty()) << formatAll(optimized.diagnostics);
    const Draw draw = handWritten(optimized.words, kGlTextureShift, kGlDefaultBlockBinding + 1, true);
    for (bool minified : {false, true}) {
        Check check = checkNormal(slotOf("normal"), minified, draw);
        report(minified ? "hand-written GLSL, minified" : "hand-written GLSL", check);
        EXPECT_LE(check.worstRatio, 1.0);
    }
}

// ---- The bench's paper listing ------------------------------------------------------------------------------------

// bench/paper-listing.glsl, the baseline of the bench's "x paper listing" (Listings 1-10 as written, per slot), must
// compute what hexc's paper mode (exactly Listings 1, 2, 5 and 6) computes on the same material, or the bench would
// time unlike shaders. Near the origin, where the paper's hash agrees between implementations (see kOrigin). Its
// normal map is a flat float texel, (0.5, 0.5, 1) -> (0, 0, 1) exactly, against hexc's material without one: Listing 3
// as written rotates derivatives back by R(+angle), right for a y-down map only (DESIGN.md), where hexc honours the
// map's convention, so the two normal paths time the same work but agree only on a flat map. What remains differs by
// float32 rounding in the order of operations: each output, about 1 here, by a few of its ulps (2^-23 ~ 1.2e-7); the
// bound 1e-5 leaves a factor of ~80, far below the 1/255 of one texel step an actual difference of the maths makes.
TEST(PaperListing, TheBenchBaselineComputesWhatPaperModeComputes) {
    REQUIRE_VULKAN();
    std::ifstream in("bench/paper-listing.glsl", std::ios::binary);
    const std::string source((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    SpirvResult front = compileToSpirv(source, ShaderStage::Fragment, "bench/paper-listing.glsl");
    ASSERT_FALSE(front.words.empty()) << formatAll(front.diagnostics);
    SpirvResult optimized = optimizeSpirv(front.words);
    ASSERT_FALSE(optimized.words.empty()) << formatAll(optimized.diagnostics);
    // The bench's full-quality material in paper mode: tiling 4, rotation 1, falloff 0.75 on every slot.
    ParseResult m = parseMaterial(
        R"({"name": "listing", "hextiling": {"tiling": 4, "mode": "paper", "rotation": 1, "falloff": 0.75}, "slots": [
            {"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png"},
            {"name": "roughness", "kind": "scalar", "texture": "textures/rock_roughness.png"}]})",
        "materials/listing.json");
    ASSERT_TRUE(m.material) << formatAll(m.diagnostics);
    const View view{128, 128, {0.0, 0.0, 0.05, 0.05}};
    std::string why;
    const Image hexc = vk::render(*runner(&why), *m.material, vk::RenderOutput::Shaded, "", view);
    const Texture albedo = loadTexture(m.material->slots[0].texturePath, true);
    const Texture roughness = loadTexture(m.material->slots[1].texturePath, false);
    const Texture flat{1, 1, false, {}, {0.5f, 0.5f, 1.0f, 1.0f}};
    vk::RenderRequest request;
    request.fragmentSpirv = optimized.words;
    request.textures = {&albedo, &flat, &roughness};
    const Errors e = compare(hexc, vk::renderFragment(*runner(&why), request, view), 3);
    std::printf("  paper listing against hexc's paper mode: max %.2e, mean %.2e\n", e.max, e.mean);
    EXPECT_LE(e.max, 1e-5);
}

}  // namespace
