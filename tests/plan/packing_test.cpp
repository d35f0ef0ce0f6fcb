// Channel packing ("pack": true, docs/material-format.md#pack): which slots pack and why the others do not, the packed
// texture's bytes (deterministic, the slots' texels in their channels), the manifest's entries, and one set of fetches.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "hexc/compiler.h"
#include "hexc/image.h"
#include "hexc/spirv.h"
#include "plan/plan.h"
#include "support.h"

using namespace hexc;
using hexc::test::outputFile;

namespace {

const std::string kAlbedoSlot = R"({"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png"})";
const std::string kRoughnessSlot = R"({"name": "roughness", "kind": "scalar", "texture": "textures/rock_roughness.png"})";
const std::string kHeight = R"({"name": "height", "kind": "scalar", "texture": "textures/rock_height.png"})";
const std::string kNormalSlot = R"({"name": "normal", "kind": "normal", "texture": "textures/rock_normal.png"})";

// A packing material of the given slots under a template that reads them all (tests/templates/packed.glsl reads slots
// named color and s0..s3; `lit` reads albedo, normal and roughness).
Material packed(const std::string& slots, const std::string& templ = "lit", const std::string& hex = R"({"tiling": 4})") {
    ParseResult r = parseMaterial(
        R"({"name": "p", "template": ")" + templ + R"(", "pack": true, "hextiling": )" + hex + R"(, "slots": [)" + slots + "]}",
        "materials/p.json");
    if (!r.material) throw std::runtime_error(formatAll(r.diagnostics));
    return *r.material;
}

// The plan points into its material, which must outlive it.
ShaderPlan plan(const Material& m) { return planShader(m, CompileOptions{}); }

// The slots of each pack, by name, and the channels each reads.
std::vector<std::vector<std::string>> packsOf(const ShaderPlan& p) {
    std::vector<std::vector<std::string>> out;
    for (const PackPlan& pack : p.packs) {
        out.emplace_back();
        for (size_t k = 0; k < pack.slots.size(); ++k) out.back().push_back(p.slots[pack.slots[k]].slot->name + ":" + pack.channels[k]);
    }
    return out;
}

bool warnsNotPacked(const ShaderPlan& p, const std::string& slot) {
    return std::any_of(p.diagnostics.begin(), p.diagnostics.end(), [&](const Diagnostic& d) {
        return d.code == Code::NotPacked && d.message.find("`" + slot + "`") != std::string::npos;
    });
}

int samples(const std::vector<uint32_t>& spirv) { return countOps(disassemble(spirv)).textureSamples; }

}  // namespace

TEST(Packing, AColourSlotTakesTheScalarInItsAlpha) {
    const Material m = packed(kAlbedoSlot + "," + kNormalSlot + "," + kRoughnessSlot);
    const ShaderPlan p = plan(m);
    EXPECT_EQ(packsOf(p), (std::vector<std::vector<std::string>>{{"albedo:rgb", "roughness:a"}}));
    ASSERT_EQ(p.packs.size(), 1u);
    EXPECT_TRUE(p.packs[0].srgb);   // the albedo is sRGB: the texture is, and its alpha stays linear
    EXPECT_FALSE(p.slots[1].pack);  // normal maps are never packed
    EXPECT_EQ(p.textureName(0), "albedo.packed");
    EXPECT_FALSE(p.textureBound(2));  // the roughness's own binding is unused
}

TEST(Packing, ScalarsPackFourToALinearTexture) {
    const std::string s = R"({"name": "s%", "kind": "scalar", "channel": "#", "texture": "textures/rock_albedo.png"})";
    std::string slots;
    for (int i = 0; i < 4; ++i) {
        std::string one = s;
        one.replace(one.find('%'), 1, std::to_string(i));
        one.replace(one.find('#'), 1, std::string(1, "rgbr"[i]));
        slots += (i ? "," : "") + one;
    }
    const Material m = packed(slots, "../tests/templates/packed.glsl");
    const ShaderPlan p = plan(m);
    EXPECT_EQ(packsOf(p), (std::vector<std::vector<std::string>>{{"s0:r", "s1:g", "s2:b", "s3:a"}}));
    EXPECT_FALSE(p.packs[0].srgb);
}

TEST(Packing, WhatDoesNotPack) {
    // Another lattice (tiling): not packed, no warning (the slots share nothing).
    const std::string ownTiling =
        R"({"name": "roughness", "kind": "scalar", "texture": "textures/rock_roughness.png", "hextiling": {"tiling": 2}})";
    EXPECT_TRUE(plan(packed(kAlbedoSlot + "," + ownTiling)).packs.empty());
    // Packing is opt-in.
    Material off = packed(kAlbedoSlot + "," + kRoughnessSlot);
    off.pack = false;
    EXPECT_TRUE(plan(off).packs.empty());
    // Another texture size: warning HX124 with the sizes.
    Material sizes = packed(kAlbedoSlot + "," + kRoughnessSlot);
    sizes.slots[1].width = 128;
    const ShaderPlan p = plan(sizes);
    EXPECT_TRUE(p.packs.empty());
    EXPECT_TRUE(warnsNotPacked(p, "roughness"));
    // An sRGB scalar would not be decoded in a packed texture: warning.
    const std::string srgb = R"({"name": "roughness", "kind": "scalar", "colorspace": "srgb", "texture": "textures/rock_roughness.png"})";
    const Material srgbMaterial = packed(kAlbedoSlot + "," + srgb);
    const ShaderPlan q = plan(srgbMaterial);
    EXPECT_TRUE(q.packs.empty());
    EXPECT_TRUE(warnsNotPacked(q, "roughness"));
    // One tap and the histogram blend fetch on their own paths; height blending reads the height map at every tap.
    for (const char* hex : {R"({"tiling": 4, "taps": 1})", R"({"tiling": 4, "blend": "histogram"})"})
        EXPECT_TRUE(plan(packed(kAlbedoSlot + "," + kRoughnessSlot, "lit", hex)).packs.empty()) << hex;
    const std::string heightBlended =
        R"({"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png", "height_blend": {"slot": "roughness"}})";
    EXPECT_TRUE(plan(packed(heightBlended + "," + kRoughnessSlot)).packs.empty());
    // A colour texture with alpha: the slot returns it, so alpha is not free (materials/textures has none with alpha: a
    // crop of rock's albedo with a translucent texel).
    Texture rock = loadTexture("materials/textures/rock_albedo.png", false);
    Image withAlpha{rock.width, rock.height, std::vector<float>(rock.rgba8.begin(), rock.rgba8.end())};
    for (float& v : withAlpha.rgba) v /= 255.0f;
    withAlpha.rgba[3] = 0.5f;
    const std::filesystem::path translucent = std::filesystem::temp_directory_path() / "hexc_packing_translucent.png";
    writeImage(withAlpha, translucent);
    const std::string alphaSlot = R"({"name": "albedo", "kind": "color", "texture": ")" + translucent.string() + R"("})";
    EXPECT_TRUE(plan(packed(alphaSlot + "," + kRoughnessSlot)).packs.empty());
}

TEST(Packing, ALinearColourSlotPacksIntoALinearTexture) {
    const std::string color = R"({"name": "color", "kind": "color", "colorspace": "linear", "texture": "textures/tiles_albedo.png"})";
    const std::string s3 = R"({"name": "s3", "kind": "scalar", "texture": "textures/rock_roughness.png"})";
    const Material m = packed(color + "," + s3, "../tests/templates/packed.glsl");
    const ShaderPlan p = plan(m);
    EXPECT_EQ(packsOf(p), (std::vector<std::vector<std::string>>{{"color:rgb", "s3:a"}}));
    EXPECT_FALSE(p.packs[0].srgb);
}

// The plan packs from the facts the parser read in each texture's header (8-bit, its channels): an RGB albedo and a
// grey roughness pack with no texel decoded, so files replaced by ones that do not decode after parsing change nothing
// in the plan; the compile, which copies the texels, then names the file instead of reading past it.
TEST(Packing, TheHeaderDecidesWithoutDecodingAndTheCompileChecksTheTexels) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_packing_header";
    std::filesystem::create_directories(dir);
    for (const char* name : {"rock_albedo.png", "rock_roughness.png"})
        std::filesystem::copy_file(std::string("materials/textures/") + name, dir / name,
                                   std::filesystem::copy_options::overwrite_existing);
    const std::string albedo = R"({"name": "albedo", "kind": "color", "texture": ")" + (dir / "rock_albedo.png").string() + R"("})";
    const std::string roughness =
        R"({"name": "roughness", "kind": "scalar", "texture": ")" + (dir / "rock_roughness.png").string() + R"("})";
    const Material m = packed(albedo + "," + roughness);
    EXPECT_EQ(m.slots[0].channelNames, "rgb");
    EXPECT_EQ(m.slots[1].channelNames, "r");
    // The albedo becomes a 1x1 PNG (decodes, but not to the header's size); the roughness, bytes that are no image.
    writeImage(Image{1, 1, {0.5f, 0.5f, 0.5f, 1}}, dir / "rock_albedo.png");
    std::ofstream(dir / "rock_roughness.png", std::ios::binary) << "not a PNG";
    EXPECT_EQ(packsOf(plan(m)), (std::vector<std::vector<std::string>>{{"albedo:rgb", "roughness:a"}}));
    // The compile takes the texels the parser read, not the files now on disk: it packs what the plan packed.
    const CompileResult r = compile(m);
    EXPECT_TRUE(r.ok()) << formatAll(r.diagnostics);
    std::filesystem::remove_all(dir);
}

TEST(Packing, ThePackedTextureHoldsTheSlotsTexelsAndIsDeterministic) {
    const Material m = packed(kAlbedoSlot + "," + kNormalSlot + "," + kRoughnessSlot);
    const CompileResult a = compile(m), b = compile(m);
    ASSERT_TRUE(a.ok()) << formatAll(a.diagnostics);
    const OutputFile& png = outputFile(a, ".packed.png");
    EXPECT_EQ(png.name, "p.albedo.packed.png");
    EXPECT_EQ(png.contents, outputFile(b, ".packed.png").contents);
    const Texture t = decodeTexture(png.contents, true);
    const Texture albedo = loadTexture("materials/textures/rock_albedo.png", true);
    const Texture roughness = loadTexture("materials/textures/rock_roughness.png", false);
    ASSERT_EQ(t.rgba8.size(), albedo.rgba8.size());
    for (size_t i = 0; i < t.rgba8.size(); i += 4) {
        ASSERT_EQ(0, std::memcmp(&t.rgba8[i], &albedo.rgba8[i], 3)) << "texel " << i / 4;
        ASSERT_EQ(t.rgba8[i + 3], roughness.rgba8[i]) << "texel " << i / 4;
    }
}

TEST(Packing, TheManifestListsThePackedTextureAndWhatEachSlotReads) {
    const CompileResult r = compile(packed(kAlbedoSlot + "," + kNormalSlot + "," + kRoughnessSlot));
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    const nlohmann::json m = nlohmann::json::parse(outputFile(r, ".manifest.json").contents);
    ASSERT_EQ(m["packed_textures"].size(), 1u);
    const nlohmann::json& p = m["packed_textures"][0];
    EXPECT_EQ(p["name"], "albedo.packed");
    EXPECT_EQ(p["file"], "p.albedo.packed.png");
    EXPECT_EQ(p["colorspace"], "srgb");
    EXPECT_EQ(p["slots"], (nlohmann::json{{"albedo", "rgb"}, {"roughness", "a"}}));
    EXPECT_EQ(m["slots"][0]["packed"], (nlohmann::json{{"texture", "albedo.packed"}, {"channels", "rgb"}}));
    EXPECT_EQ(m["slots"][2]["packed"], (nlohmann::json{{"texture", "albedo.packed"}, {"channels", "a"}}));
    EXPECT_FALSE(m["slots"][1].contains("packed"));
    // Every target binds the packed texture where the albedo's was, and no texture for the roughness.
    for (const char* t : {"spirv", "hlsl", "glsl", "msl"}) {
        const nlohmann::json& textures = m["targets"][t]["textures"];
        EXPECT_TRUE(textures.contains("albedo.packed")) << t;
        EXPECT_TRUE(textures.contains("normal")) << t;
        EXPECT_FALSE(textures.contains("roughness")) << t;
        EXPECT_FALSE(textures.contains("albedo")) << t;
    }
    EXPECT_EQ(m["targets"]["spirv"]["textures"]["albedo.packed"]["binding"], 2);
    EXPECT_EQ(m["targets"]["spirv"]["textures"]["normal"]["binding"], 3);
}

// The packed slots share one set of fetches: 3 per tap set instead of 3 per slot.
// With lod "shared" too, whose level the slots compute from the same texture's size.
TEST(Packing, ThePackedSlotsFetchOnce) {
    for (const char* hex : {R"({"tiling": 4})", R"({"tiling": 4, "lod": "shared"})"}) {
        Material m = packed(kAlbedoSlot + "," + kNormalSlot + "," + kRoughnessSlot, "lit", hex);
        CompileOptions spirv;
        spirv.targets = {Target::Spirv};
        const CompileResult on = compile(m, spirv);
        m.pack = false;
        const CompileResult off = compile(m, spirv);
        ASSERT_TRUE(on.ok() && off.ok());
        EXPECT_EQ(samples(off.spirv), 9) << hex;
        EXPECT_EQ(samples(on.spirv), 6) << hex;
    }
}

// An engine's template that samples its own combined samplers (texture, textureLod on a sampler2D) beside the packed
// slots: those samples are left as they are, the packed slots' three taps are shared.
TEST(Packing, AnEngineTemplatesOwnSamplesStayBesidePackedOnes) {
    Material m = packed(kAlbedoSlot + "," + kRoughnessSlot, "templates/engine.glsl");
    CompileOptions spirv;
    spirv.targets = {Target::Spirv};
    const CompileResult on = compile(m, spirv);
    ASSERT_TRUE(on.ok()) << formatAll(on.diagnostics);
    m.pack = false;
    const CompileResult off = compile(m, spirv);
    ASSERT_TRUE(off.ok()) << formatAll(off.diagnostics);
    EXPECT_EQ(samples(off.spirv) - samples(on.spirv), 3);
}

// The command line writes the packed texture beside the shaders and names it in the depfile as an output; a texture
// whose pixels change makes the material out of date (its texels are in the packed texture).
TEST(Packing, TheCommandLineWritesAndDeclaresThePackedTexture) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "hexc_packing_cli";
    fs::remove_all(dir);
    fs::create_directories(dir / "textures");
    for (const char* t : {"rock_albedo.png", "rock_roughness.png"}) fs::copy_file(fs::path("materials/textures") / t, dir / "textures" / t);
    std::ofstream(dir / "m.json") << R"({"name": "m", "pack": true, "slots": [)" << kAlbedoSlot << "," << kRoughnessSlot << "]}";
    const std::string args =
        (dir / "m.json").string() + " -o " + (dir / "out").string() + " --no-cache --depfile " + (dir / "m.d").string();
    ASSERT_EQ(hexc::test::runHexc(args), 0);
    ASSERT_TRUE(fs::exists(dir / "out" / "m.albedo.packed.png"));
    std::ifstream depfile(dir / "m.d");
    const std::string deps(std::istreambuf_iterator<char>(depfile), {});
    EXPECT_LT(deps.find("m.albedo.packed.png"), deps.find(':')) << deps;
    const auto before = fs::last_write_time(dir / "out" / "m.albedo.packed.png");
    // New roughness pixels, same size: the packed texture is written again.
    Texture r = loadTexture(dir / "textures" / "rock_roughness.png", false);
    Image flipped{r.width, r.height, std::vector<float>(r.rgba8.rbegin(), r.rgba8.rend())};
    for (float& v : flipped.rgba) v /= 255.0f;
    writeImage(flipped, dir / "textures" / "rock_roughness.png");
    ASSERT_EQ(hexc::test::runHexc(args), 0);
    const Texture packed = loadTexture(dir / "out" / "m.albedo.packed.png", false);
    const Texture now = loadTexture(dir / "textures" / "rock_roughness.png", false);
    EXPECT_EQ(packed.rgba8[3], now.rgba8[0]);
    EXPECT_NE(fs::last_write_time(dir / "out" / "m.albedo.packed.png"), before);
}
