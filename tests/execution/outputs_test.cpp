// Execution tests of the examples' slots, one at a time, of rock's in other outputs than the optimised default (--debug,
// each OpenGL GLSL version) and of MaterialX documents and mode, on lavapipe against the fp64 CPU reference, under the
// tolerances of checks.h.
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

// ---- The examples ---------------------------------------------------------------------------------------------

// Each slot of each example (materials/NAME.json), alone with the slot it height-blends by (slotOf), in its view
// (checkSlot), on every target: rock; height blending between slots, with the falloff metric on (rock_blend); a normal
// map alone (rock_normal); the triplanar projection with a checker mask, on the preview sphere (rock_triplanar); tiles
// unrotated (tiles) and with stepped rotations and offsets (tiles_stepped). tests/wgsl/wgsl_test.py draws the same on
// Dawn.
class ExampleSlots : public testing::TestWithParam<std::tuple<std::string, vk::ExecutedTarget>> {};

TEST_P(ExampleSlots, EachMatchesTheReference) {
    REQUIRE_VULKAN();
    const auto& [example, target] = GetParam();
    const std::string file = "materials/" + example + ".json";
    const ParseResult parsed = parseMaterialFile(file);
    ASSERT_TRUE(parsed.material) << formatAll(parsed.diagnostics);
    for (const Slot& slot : parsed.material->slots) {
        Check check = checkSlot(slotOf(slot.name, file), on(target));
        report((example + " " + slot.name).c_str(), check);
        EXPECT_LE(check.worstRatio, 1.0) << slot.name;
    }
}

INSTANTIATE_TEST_SUITE_P(Exec, ExampleSlots,
                         testing::Combine(testing::Values("rock", "rock_blend", "rock_normal", "rock_triplanar", "tiles", "tiles_stepped"),
                                          kExecutedTargets),
                         [](const auto& info) { return std::get<0>(info.param) + "_" + targetName(std::get<1>(info.param)); });

// ---- Debug outputs ------------------------------------------------------------------------------------------

// --debug outputs (unoptimised, hexc's functions kept, #line directives) of each of rock's slots, with rock's
// settings, on every target: the same reference and tolerances as the optimised ones (ExampleSlots).
class DebugOutputs : public testing::TestWithParam<vk::ExecutedTarget> {};

TEST_P(DebugOutputs, RocksSlotsMatchTheReference) {
    REQUIRE_VULKAN();
    CompileOptions debug;
    debug.debug = true;
    for (const std::string slot : {"albedo", "normal", "roughness"}) {
        Check check = checkSlot(slotOf(slot), on(GetParam(), debug));
        report(("rock " + slot + " --debug").c_str(), check);
        EXPECT_LE(check.worstRatio, 1.0) << slot;
    }
}

INSTANTIATE_TEST_SUITE_P(Exec, DebugOutputs, testing::Values(vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl),
                         [](const auto& info) { return targetName(info.param); });

// ---- MaterialX documents ---------------------------------------------------------------------------------------

// Each slot of the hand-written MaterialX documents (docs/materialx.md), as hexc reads them, on every executed target:
// the same reference and tolerances as JSON materials. preview_surface reads MaterialX's defaults (tile scales 0.5-2,
// rotations over 0-360 degrees) and plain tiled and normal-mapped images.
class MaterialXDocuments : public testing::TestWithParam<vk::ExecutedTarget> {};

TEST_P(MaterialXDocuments, EverySlotMatchesTheReference) {
    REQUIRE_VULKAN();
    for (const std::string file : {"materials/mtlx/rock.mtlx", "materials/mtlx/preview_surface.mtlx"})
        for (const std::string slot : {"albedo", "normal", "roughness"}) {
            Check check = checkSlot(slotOf(slot, file), on(GetParam()));
            report((std::filesystem::path(file).stem().string() + " " + slot).c_str(), check);
            EXPECT_LE(check.worstRatio, 1.0) << file << " " << slot;
        }
}

INSTANTIATE_TEST_SUITE_P(Exec, MaterialXDocuments,
                         testing::Values(vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl),
                         [](const auto& info) { return targetName(info.param); });

// ---- MaterialX mode -------------------------------------------------------------------------------------------

// MaterialX mode (docs/materialx.md#materialx-mode) against its own reference (reference/materialx.cpp), with rotation,
// scale and offset ranges, falloff, falloff contrast and luma weights all away from their defaults, magnified and
// minified, on every target. Colour: the blend R = sum W_j x_j with W_j proportional to c_j w_j^7, c_j = 1 + beta (l_j
// - 1) >= 1 - beta; a luma error e_m (<= e_s: the weights sum to 1) moves c_j by beta e_m, and R by at most
// e_m beta / (1 - beta) sum_j W_j |x_j - R| (as pixelTolerance), times the steepest slope of Schlick's gain, which is
// max(r / (1 - r), (1 - r) / r) at its ends. Normal: each tile's gradient -R(angle) m / |m_z| errs by the derivative
// rule's e_d per component before the rotation, so by sqrt(2) e_d after it; its weights do not depend on the samples.
double materialxTolerance(const reference::SlotResult& r, double ex, const HexTiling& hex, int channels) {
    const double rr = std::clamp(hex.falloff, 0.001, 0.999), k = hex.falloff == 0.5 ? 1.0 : std::max(rr / (1 - rr), (1 - rr) / rr);
    return blendTolerance(r, ex, ex, hex.falloffcontrast, k, channels);
}

class MaterialXMode : public testing::TestWithParam<vk::ExecutedTarget> {};

TEST_P(MaterialXMode, HextiledimageAndHextilednormalmapMatchTheirReference) {
    REQUIRE_VULKAN();
    const std::string transforms =
        R"("mode": "materialx", "tiling": 4, "rotation": 0.8, "rotationrange": [20, 200], "scalerange": [0.7, 1.6],
        "offset": 0.6, "falloff": 0.7)";
    const Material color = material(R"({"name": "albedo", "kind": "color", "colorspace": "linear", "texture": "textures/rock_albedo.png",
        "hextiling": {)" + transforms +
                                    R"(, "falloffcontrast": 0.4, "lumacoeffs": [0.2126, 0.7152, 0.0722]}})");
    const Material normal = material(R"({"name": "normal", "kind": "normal", "flip_y": true, "texture": "textures/rock_normal.png",
        "hextiling": {)" + transforms +
                                     "}}");
    const TextureBounds b = bounds(sampled(normal.slots[0]));
    for (bool minified : {false, true}) {
        const View& view = minified ? kMinified : kMagnified;
        // A tile scaled by s shows 1 / s as many texels per pixel: 0.75 / 0.7 (magnified) and 4 / 0.7 (minified) read
        // levels up to 1 and 3.
        const int level = int(std::ceil(std::log2((minified ? 4.0 : 0.75) / color.slots[0].hex.scaleRange[0])));
        const double es = sampleError(level, false), ed = 2 * es * (1 + b.maxDeriv) / b.minZ;
        Check c =
            checkAgainstReference(color, vk::RenderOutput::Albedo, view, on(GetParam()), 4,
                                  [&](const reference::SlotResult& r, size_t) { return materialxTolerance(r, es, color.slots[0].hex, 4); });
        report(minified ? "materialx color minified" : "materialx color", c);
        EXPECT_LE(c.worstRatio, 1.0);
        if (!minified) {
            EXPECT_LE(c.errors.max, 2.0 / 255);  // MaterialX's own shader agrees with hexc's modes to 2/255 magnified
        }
        Check n = checkAgainstReference(normal, vk::RenderOutput::Derivative, view, on(GetParam()), 2,
                                        [&](const reference::SlotResult&, size_t) { return std::sqrt(2.0) * ed; });
        report(minified ? "materialx normal minified" : "materialx normal", n);
        EXPECT_LE(n.worstRatio, 1.0);
    }
}

INSTANTIATE_TEST_SUITE_P(Exec, MaterialXMode, kExecutedTargets, [](const auto& info) { return targetName(info.param); });

// Falloffs 1 - 2^-k (0.75, 0.875), whose gain stable mode multiplies out (k whole): in both modes the gain is the one
// the reference applies, Perlin's in stable mode, Schlick's in MaterialX mode (which has no such shortcut), colour and
// normal, magnified, on every target, with the tolerances above.
class IntegerGain : public testing::TestWithParam<vk::ExecutedTarget> {};

TEST_P(IntegerGain, EachModeAppliesItsGain) {
    REQUIRE_VULKAN();
    for (const std::string mode : {"stable", "materialx"})
        for (const std::string falloff : {"0.75", "0.875"}) {
            const std::string hex = R"("mode": ")" + mode + R"(", "tiling": 4, "rotation": 0.5, "falloff": )" + falloff;
            const Material color =
                material(R"({"name": "albedo", "kind": "color", "colorspace": "linear", "texture": "textures/rock_albedo.png",
                "hextiling": {)" +
                         hex + R"(, "falloffcontrast": 0.4}})");
            const Material normal =
                material(R"({"name": "normal", "kind": "normal", "texture": "textures/rock_normal.png", "hextiling": {)" + hex + "}}");
            const std::string name = mode + " falloff " + falloff;
            Check c, n;
            if (mode == "stable") {
                c = checkColor(color, false, on(GetParam()));
                n = checkNormal(normal, false, on(GetParam()));
            } else {
                const double es = sampleError(0, false),
                             ed = 2 * es * (1 + bounds(sampled(normal.slots[0])).maxDeriv) / bounds(sampled(normal.slots[0])).minZ;
                c = checkAgainstReference(
                    color, vk::RenderOutput::Albedo, kMagnified, on(GetParam()), 4,
                    [&](const reference::SlotResult& r, size_t) { return materialxTolerance(r, es, color.slots[0].hex, 4); });
                n = checkAgainstReference(normal, vk::RenderOutput::Derivative, kMagnified, on(GetParam()), 2,
                                          [&](const reference::SlotResult&, size_t) { return std::sqrt(2.0) * ed; });
            }
            report((name + " color").c_str(), c);
            report((name + " normal").c_str(), n);
            EXPECT_LE(c.worstRatio, 1.0) << name;
            EXPECT_LE(n.worstRatio, 1.0) << name;
        }
}

INSTANTIATE_TEST_SUITE_P(Exec, IntegerGain, kExecutedTargets, [](const auto& info) { return targetName(info.param); });

// An sRGB colour slot in MaterialX mode: the texture is bound linear (UNORM) and its stored texels filtered, blended
// and then decoded, as MaterialX does (the reference likewise); filtering decoded texels was 17/255 off magnified and
// 9/255 minified. falloffcontrast 0, so the weights do not depend on the samples: the encoded blend errs by the
// sampling error e_s of 8-bit linear data (sampleError), and decoding multiplies an error by at most the sRGB curve's
// steepest slope, 2.4 / 1.055 = 2.27 (at 1).
class MaterialXSrgb : public testing::TestWithParam<vk::ExecutedTarget> {};

TEST_P(MaterialXSrgb, FiltersTheStoredTexelsAndDecodesTheBlend) {
    REQUIRE_VULKAN();
    const Material m = material(R"({"name": "albedo", "kind": "color", "colorspace": "srgb", "texture": "textures/rock_albedo.png",
        "hextiling": {"mode": "materialx", "tiling": 4, "rotation": 0.5, "scalerange": [0.7, 1.6], "falloff": 0.75, "falloffcontrast": 0}})");
    for (bool minified : {false, true}) {
        const double es = sampleError(minified ? 3 : 1, false);  // levels up to 3 minified and 1 magnified (scales from 0.7)
        Check c = checkAgainstReference(m, vk::RenderOutput::Albedo, minified ? kMinified : kMagnified, on(GetParam()), 3,
                                        [&](const reference::SlotResult&, size_t) { return 2.4 / 1.055 * es; });
        report(minified ? "materialx srgb minified" : "materialx srgb", c);
        EXPECT_LE(c.worstRatio, 1.0);
    }
}

INSTANTIATE_TEST_SUITE_P(Exec, MaterialXSrgb, kExecutedTargets, [](const auto& info) { return targetName(info.param); });

// ---- GLSL versions ------------------------------------------------------------------------------------------

// Every OpenGL GLSL version hexc emits, executed (compiled again by glslang, as the Glsl target above) on rock's
// albedo and normal slots: the same reference and tolerances. GLSL 330 and ES 3.00 bind by name; one slot has one
// block and one texture unit, where glslang's auto-mapping puts them (render.cpp).
TEST(GlslVersions, EachMatchesTheReference) {
    REQUIRE_VULKAN();
    for (auto [version, es] : {std::pair{460u, false}, {330u, false}, {310u, true}, {300u, true}}) {
        CompileOptions options;
        options.glslVersion = version;
        options.glslEs = es;
        for (const std::string slot : {"albedo", "normal"}) {
            Check check = checkSlot(slotOf(slot), on(vk::ExecutedTarget::Glsl, options));
            const std::string name = "rock " + slot + " GLSL " + std::to_string(version) + (es ? " es" : "");
            report(name.c_str(), check);
            EXPECT_LE(check.worstRatio, 1.0) << name;
        }
    }
}

}  // namespace
