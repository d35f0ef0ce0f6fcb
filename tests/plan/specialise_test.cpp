// Skipping what a material does not need: the SPIR-V holds only the code each slot's settings use, slots
// with the same lattice share it, baked settings fold away, and none of it changes a pixel.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "hexc/compiler.h"
#include "hexc/spirv.h"
#include "support.h"
#include "vk/precision.h"
#include "vk/render.h"

using namespace hexc;
using hexc::test::runner;

namespace {

Material oneSlot(const std::string& kind, const std::string& texture, const std::string& hextiling, const std::string& templ = "value") {
    ParseResult r = parseMaterial(R"({"name": "m", "template": ")" + templ + R"(", "slots": [{"name": "s", "kind": ")" + kind +
                                      R"(", "texture": ")" + texture + R"(", "hextiling": {)" + hextiling + "}}]}",
                                  "materials/m.json");
    if (!r.material) throw std::runtime_error(formatAll(r.diagnostics));
    return *r.material;
}

// How often an instruction (e.g. "OpImageSampleExplicitLod", or "Sin" for GLSL.std.450 Sin) appears.
size_t count(const std::vector<uint32_t>& spirv, const std::string& op) {
    std::string text = disassemble(spirv);
    std::string needle = op.rfind("Op", 0) == 0 ? " " + op + " " : " " + op + " ";
    size_t n = 0;
    for (size_t p = 0; (p = text.find(needle, p)) != std::string::npos; ++p) ++n;
    return n;
}

std::vector<uint32_t> spirv(const Material& m, const CompileOptions& options = {}) {
    CompileResult r = compile(m, options);
    EXPECT_TRUE(r.ok()) << formatAll(r.diagnostics);
    return r.spirv;
}

CompileOptions general() {
    CompileOptions o;
    o.specialise = false;
    return o;
}

const std::string kAlbedo = "textures/rock_albedo.png", kNormal = "textures/rock_normal.png";

TEST(Specialise, RotationOffHasNoTrigonometry) {
    auto on = spirv(oneSlot("color", kAlbedo, R"("rotation": 1)")), off = spirv(oneSlot("color", kAlbedo, R"("rotation": 0)"));
    EXPECT_EQ(count(on, "Sin"), 3u);  // one per tile
    EXPECT_EQ(count(on, "Cos"), 3u);
    EXPECT_EQ(count(off, "Sin") + count(off, "Cos"), 0u);
    EXPECT_EQ(count(spirv(oneSlot("color", kAlbedo, R"("rotation": 0)"), general()), "Sin"), 3u);  // the general shader keeps it
}

TEST(Specialise, GainAtOneHalfIsLeftOut) {
    // Eq. 5's exponent k = log(1 - r) / log(1/2) is the only Log; the gain adds three Pow to the weights' three.
    auto gain = spirv(oneSlot("color", kAlbedo, R"("falloff": 0.7)")), none = spirv(oneSlot("color", kAlbedo, R"("falloff": 0.5)"));
    EXPECT_EQ(count(gain, "Log"), 1u);  // log(1 - r); log(1/2) folds
    EXPECT_EQ(count(none, "Log"), 0u);
    EXPECT_LT(count(none, "Pow"), count(gain, "Pow"));
}

TEST(Specialise, NoFalloffMetricAtFalloffContrastZero) {
    // The normal path's metric is sqrt(|d|^2 / (1 + |d|^2)) of the three tiles.
    auto metric = spirv(oneSlot("normal", kNormal, R"("falloffcontrast": 0.6)")),
         none = spirv(oneSlot("normal", kNormal, R"("falloffcontrast": 0)"));
    EXPECT_EQ(count(metric, "Sqrt"), 1u);  // one vec3 Sqrt for the three tiles
    EXPECT_EQ(count(none, "Sqrt"), 0u);
}

TEST(Specialise, WholeNumberExponentsAreMultipliedOut) {
    // gamma = 7 and the gain at falloff 0.75 (k = 2): no pow, no log, and neither is a parameter.
    CompileResult r = compile(oneSlot("color", kAlbedo, R"("falloff": 0.75, "exponent": 7)"));
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(count(r.spirv, "Pow") + count(r.spirv, "Log") + count(r.spirv, "Exp2"), 0u);
    EXPECT_GT(count(spirv(oneSlot("color", kAlbedo, R"("falloff": 0.75, "exponent": 7.5)")), "Pow"), 0u);
    std::string manifest;
    for (const auto& f : r.files)
        if (f.name.ends_with(".manifest.json")) manifest = f.contents;
    auto m = nlohmann::json::parse(manifest);
    EXPECT_EQ(m["specialised"].size(), 2u);
    for (const auto& p : m["parameters"]["members"]) EXPECT_TRUE(p["name"] != "s_exponent" && p["name"] != "s_falloff");
}

TEST(Specialise, PlainSlotSamplesOnce) {
    EXPECT_EQ(count(spirv(oneSlot("color", kAlbedo, R"("enabled": false)")), "OpImageSampleImplicitLod"), 1u);
    EXPECT_EQ(count(spirv(oneSlot("color", kAlbedo, R"("enabled": false)")), "OpImageSampleExplicitLod"), 0u);
    EXPECT_EQ(count(spirv(oneSlot("color", kAlbedo, "")), "OpImageSampleExplicitLod"), 3u);
}

TEST(Specialise, WeightsOnlyWhenAsked) {
    // Integer remainders: each tap's tile centre modulo the texture's period (hexcStableCentreInPeriod) is one; the
    // weights output adds Listing 7's colour index.
    const auto remainders = [](const std::vector<uint32_t>& code) { return count(code, "OpSMod") + count(code, "OpSRem"); };
    const size_t value = remainders(spirv(oneSlot("color", kAlbedo, "", "value")));
    EXPECT_EQ(value, 3u);
    EXPECT_GT(remainders(spirv(oneSlot("color", kAlbedo, "", "weights"))), value);
}

TEST(Specialise, UnusedSettingsAreNotParameters) {
    CompileResult r = compile(oneSlot("color", kAlbedo, R"("rotation": 0, "falloff": 0.5, "falloffcontrast": 0, "exponent": 7.5)"));
    ASSERT_TRUE(r.ok());
    std::string manifest;
    for (const auto& f : r.files)
        if (f.name.ends_with(".manifest.json")) manifest = f.contents;
    auto members = nlohmann::json::parse(manifest)["parameters"]["members"];
    std::vector<std::string> names;
    for (const auto& m : members) names.push_back(m["name"]);
    EXPECT_EQ(names, (std::vector<std::string>{"s_tiling", "s_exponent"}));
}

TEST(SharedLattice, OneLatticeForSlotsWithTheSameTilingAndRotation) {
    Material rock = *parseMaterialFile("materials/rock.json").material;
    CompileOptions perSlot;
    perSlot.shareLattice = false;
    auto shared = spirv(rock), separate = spirv(rock, perSlot);
    std::printf("  rock.json: %zu SPIR-V words with a shared lattice, %zu with one per slot; Sin %zu vs %zu\n", shared.size(),
                separate.size(), count(shared, "Sin"), count(separate, "Sin"));
    EXPECT_EQ(count(shared, "Sin"), 3u);                       // three tiles, once
    EXPECT_EQ(count(separate, "Sin"), 9u);                     // three tiles for each of three slots
    EXPECT_EQ(count(shared, "OpImageSampleExplicitLod"), 9u);  // the fetches stay per slot
    EXPECT_LT(shared.size(), separate.size());
}

TEST(Bake, SettingsFoldIntoTheCode) {
    Material rock = *parseMaterialFile("materials/rock.json").material;
    CompileOptions baked;
    baked.bake = true;
    CompileResult r = compile(rock, baked);
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    EXPECT_EQ(count(r.spirv, "OpSpecConstant"), 0u);  // frozen
    EXPECT_EQ(count(r.spirv, "Log"), 0u);             // the gain's exponent is a constant now
    std::string manifest;
    for (const auto& f : r.files)
        if (f.name.ends_with(".manifest.json")) manifest = f.contents;
    auto m = nlohmann::json::parse(manifest);
    EXPECT_EQ(m["parameters"]["members"].size(), 0u);
    EXPECT_EQ(m["baked_constants"].size() + m["specialised"].size(), 10u);  // whole-number exponents are specialised either way
    EXPECT_LT(r.spirv.size(), spirv(rock).size());
}

// ---- The skips change no pixel ---------------------------------------------------------------------------
struct Variant {
    const char* name;
    const char* kind;
    const char* hextiling;
};

TEST(Specialise, SpecialisedAndGeneralShadersRenderTheSameImage) {
    REQUIRE_VULKAN();
    // exponent 7.5 keeps the weights' pow in both shaders, so only the switch under test differs.
    const Variant variants[] = {
        {"rotation off", "color", R"("tiling": 4, "exponent": 7.5, "rotation": 0)"},
        {"gain off", "color", R"("tiling": 4, "exponent": 7.5, "falloff": 0.5)"},
        {"metric off", "color", R"("tiling": 4, "exponent": 7.5, "falloffcontrast": 0)"},
        {"all off", "color", R"("tiling": 4, "exponent": 7.5, "rotation": 0, "falloff": 0.5, "falloffcontrast": 0)"},
        {"normal, rotation and metric off", "normal", R"("tiling": 4, "exponent": 7.5, "rotation": 0, "falloffcontrast": 0)"},
        {"paper, rotation off", "color", R"("tiling": 4, "exponent": 7.5, "rotation": 0, "mode": "paper")"},
        {"plain tiling", "color", R"("tiling": 4, "enabled": false)"},
        {"whole-number exponents", "color", R"("tiling": 4, "exponent": 7, "falloff": 0.75)"},
    };
    const View view{96, 96, {0.2, 0.3, 0.6, 0.7}};
    for (const Variant& v : variants) {
        Material m = oneSlot(v.kind, std::string(v.kind) == "normal" ? kNormal : kAlbedo, v.hextiling);
        auto value = std::string(v.kind) == "normal" ? vk::RenderOutput::Derivative : vk::RenderOutput::Albedo;
        for (auto output : {value, vk::RenderOutput::Weights}) {
            Image specialised = vk::render(*runner(&whyNoVulkan), m, output, "", view);
            Image all = vk::render(*runner(&whyNoVulkan), m, output, "", view, vk::ExecutedTarget::Spirv, 0, nullptr, {}, general());
            auto e = vk::compareImages(specialised, all, 4);
            std::printf("  %-32s %-7s specialised against general: max difference %.2e\n", v.name,
                        output == vk::RenderOutput::Weights ? "weights" : "value", e.max);
            // A skipped feature is an exact no-op: rotating by cos 0 = 1, sin 0 = 0, mixing with weight 0,
            // skipping the gain at r = 0.5 all leave the float bits as they were. One exception: without the
            // rotation, the paper's sample point (st - c) + c + hash lets the driver (llvmpipe compiles with
            // fast-math) simplify (st - c) + c to st, an ulp of st (2^-22 here, st < 4) off, which moves a
            // bilinear sample by at most that times 256 texels times the largest texel step (1).
            double bound = std::string(v.hextiling).find("paper") != std::string::npos ? std::ldexp(1.0, -22) * 256 : 0.0;
            // Multiplying out w^7 and x^2 (k = 2) against pow: the Vulkan spec lets pow be exp2(y log2 x) with
            // log2 off by 2^-21 absolute and exp2 by 3 + 2|y log2 x| ulp; for gamma = 7 and the dominant weights
            // (w >= 1/3) that is a relative error of 7 ln2 2^-21 + (3 + 14 log2 3) 2^-23 = 5.3e-6 on w^gamma,
            // at most twice that on a normalised weight, and the blend of values in [0, 1] moves by no more.
            if (std::string(v.name) == "whole-number exponents")
                bound = 2 * (7 * std::log(2.0) * std::ldexp(1.0, -21) + (3 + 14 * std::log2(3.0)) * std::ldexp(1.0, -23));
            EXPECT_LE(e.max, bound) << v.name;
        }
    }
}

TEST(SharedLattice, SharingAndBakingChangeNoPixel) {
    REQUIRE_VULKAN();
    Material rock = *parseMaterialFile("materials/rock.json").material;
    const View view{128, 128, {0.2, 0.3, 0.6, 0.7}};
    CompileOptions perSlot, baked;
    perSlot.shareLattice = false;
    baked.bake = true;
    Image shared = vk::render(*runner(&whyNoVulkan), rock, vk::RenderOutput::Shaded, "", view);
    Image separate =
        vk::render(*runner(&whyNoVulkan), rock, vk::RenderOutput::Shaded, "", view, vk::ExecutedTarget::Spirv, 0, nullptr, {}, perSlot);
    Image folded =
        vk::render(*runner(&whyNoVulkan), rock, vk::RenderOutput::Shaded, "", view, vk::ExecutedTarget::Spirv, 0, nullptr, {}, baked);
    EXPECT_EQ(vk::compareImages(shared, separate, 4).max, 0.0);  // the same arithmetic, done once
    // Folding constants may reassociate a few float operations: a handful of roundings of values near 1.
    double e = vk::compareImages(shared, folded, 4).max;
    std::printf("  baked against uniform settings: max difference %.2e\n", e);
    EXPECT_LE(e, 16 * std::ldexp(1.0, -24));
}

// Without shared lattices each layer's slot computes its own tiles (plan_test.cpp: Layers.*): the layers' blend draws the
// same pixels.
TEST(SharedLattice, ALayersTilesSharedOrPerSlotChangeNoPixel) {
    REQUIRE_VULKAN();
    Material terrain = *parseMaterialFile("materials/terrain/terrain.json").material;
    CompileOptions perSlot;
    perSlot.shareLattice = false;
    const View view{64, 64, {0.2, 0.3, 0.3, 0.4}};
    Image a = vk::render(*runner(&whyNoVulkan), terrain, vk::RenderOutput::Shaded, "", view);
    Image b =
        vk::render(*runner(&whyNoVulkan), terrain, vk::RenderOutput::Shaded, "", view, vk::ExecutedTarget::Spirv, 0, nullptr, {}, perSlot);
    EXPECT_EQ(vk::compareImages(a, b, 4).max, 0.0);  // the same tiles, computed once or per slot
}

}  // namespace
