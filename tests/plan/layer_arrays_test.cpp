// Texture arrays of layered materials (docs/material-format.md#texture-arrays): the plan binds a role's textures across
// layers as one 2D array texture when one sampler reads them alike, else one texture per slot with the reason; the
// shader reads each layer through the array at a constant layer; the manifest says which.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "hexc/compiler.h"
#include "plan/plan.h"
#include "support.h"

using namespace hexc;
using hexc::test::exampleTerrain;
using hexc::test::loadMaterial;

namespace {

const LayerArrayPlan& arrayOf(const ShaderPlan& plan, const std::string& role) {
    for (const LayerArrayPlan& a : plan.layers->arrays)
        if (a.role == role) return a;
    throw std::logic_error("no array plan for role " + role);
}

// The slot of role `role` (0 albedo, 1 normal, 2 height) in layer `layer` of the terrain.
Slot& slotOf(Material& m, size_t layer, size_t role) { return m.slots[m.layers->layers[layer].slots[role]]; }

TEST(LayerArrays, RolesWhoseTexturesMatchAreOneArrayWithALayerPerLayer) {
    const ShaderPlan plan = planShader(exampleTerrain(), {});
    ASSERT_TRUE(plan.layers);
    ASSERT_EQ(plan.layers->arrays.size(), 3u);  // lit reads albedo and normal; the height blend reads the heights
    for (const char* role : {"albedo", "normal", "height"}) {
        const LayerArrayPlan& a = arrayOf(plan, role);
        EXPECT_EQ(a.refused, "") << role;
        ASSERT_EQ(a.slots.size(), 4u);
        for (size_t layer = 0; layer < 4; ++layer) {
            const SlotPlan& sp = plan.slots[a.slots[layer]];
            EXPECT_EQ(sp.array, "hexcArr_" + std::string(role));
            EXPECT_EQ(sp.arrayLayer, int(layer));
            EXPECT_EQ(plan.textureBound(a.slots[layer]), layer == 0) << "one binding per array: its first layer's";
        }
        EXPECT_EQ(plan.textureName(a.slots[0]), std::string(role) + ".array");
    }
}

TEST(LayerArrays, ASizeFormatChannelsOrColourSpaceThatDiffersKeepsTheRolesTexturesSeparate) {
    struct Change {
        const char* what;
        std::function<void(Slot&)> apply;
        const char* reason;
    };
    const Change changes[] = {
        {"size", [](Slot& s) { s.width = 128; }, "sizes differ: `grass_albedo` and `pebbles_albedo` are 256x256 and 128x256 texels"},
        {"format", [](Slot& s) { s.eightBit = false; }, "formats differ: `grass_albedo` and `pebbles_albedo` are 8-bit and float"},
        {"channels", [](Slot& s) { s.channelNames = "rgba"; }, "channels differ: `grass_albedo` and `pebbles_albedo` have rgb and rgba"},
        {"colour space", [](Slot& s) { s.colorSpace = ColorSpace::Linear; },
         "colour spaces differ: `grass_albedo` and `pebbles_albedo` are bound as sRGB and linear"},
    };
    for (const Change& c : changes) {
        Material m = exampleTerrain();
        c.apply(slotOf(m, 2, 0));
        const ShaderPlan plan = planShader(m, {});
        const LayerArrayPlan& albedo = arrayOf(plan, "albedo");
        EXPECT_EQ(albedo.refused, c.reason) << c.what;
        for (size_t i : albedo.slots) {
            EXPECT_EQ(plan.slots[i].array, "") << c.what;
            EXPECT_TRUE(plan.textureBound(i)) << c.what;
        }
        EXPECT_EQ(arrayOf(plan, "normal").refused, "") << c.what << ": another role's array is not affected";
    }
}

TEST(LayerArrays, OffOneLayerGeneralCodeAndTheFunctionsOutputKeepSeparateTextures) {
    Material off = exampleTerrain();
    off.layers->arrays = false;
    EXPECT_EQ(arrayOf(planShader(off, {}), "albedo").refused, "layer_blend.arrays is \"off\"");
    CompileOptions general;
    general.specialise = false;
    EXPECT_EQ(arrayOf(planShader(exampleTerrain(), general), "albedo").refused,
              "--no-specialise: the library's general functions read 2D textures");
    CompileOptions functions;
    functions.functions = true;
    EXPECT_EQ(arrayOf(planShader(exampleTerrain(), functions), "albedo").refused,
              "the functions output (engine packages) binds one texture per slot (docs/engines.md)");
    // An engine package that binds arrays: as a whole shader.
    functions.functionArrays = FunctionArrays::All;
    EXPECT_EQ(arrayOf(planShader(exampleTerrain(), functions), "albedo").refused, "");
    const Material one = loadMaterial("tests/execution/layers/one.json");
    const ShaderPlan plan = planShader(one, {});
    ASSERT_FALSE(plan.layers->arrays.empty());
    EXPECT_EQ(plan.layers->arrays.front().refused, "one layer: there is nothing to share");
}

// The plan's HX129 warnings, formatted.
// The plan's diagnostics of one code, formatted.
std::vector<std::string> withCode(const ShaderPlan& plan, Code code) {
    std::vector<std::string> out;
    for (const Diagnostic& d : plan.diagnostics)
        if (d.code == code) out.push_back(d.format());
    return out;
}

std::vector<std::string> notArrayed(const ShaderPlan& plan) { return withCode(plan, Code::NotArrayed); }

TEST(LayerArrays, ARoleKeptApartByItsTexturesIsAWarningNamingTheLayersAndHowToGetOneArray) {
    Material sizes = exampleTerrain();
    slotOf(sizes, 2, 0).width = slotOf(sizes, 2, 0).height = 128;
    EXPECT_EQ(notArrayed(planShader(sizes, {})),
              std::vector<std::string>{
                  "materials/terrain/terrain.json:15:34: warning[HX129]: /layers/2/slots/0: role `albedo` is 4 textures, one per "
                  "layer, not one texture array (4 texture units instead of 1): sizes differ: layer `grass` 256x256, layer `sand` "
                  "256x256, layer `pebbles` 128x128, layer `snow` 256x256 (resize them to one size for one array, or set "
                  "layer_blend.arrays to \"off\" for separate textures)"});
    const std::pair<std::function<void(Slot&)>, const char*> others[] = {
        {[](Slot& s) { s.eightBit = false; },
         "formats differ: `grass_normal` and `sand_normal` are 8-bit and float (store them in one format"},
        {[](Slot& s) { s.channelNames = "rgba"; },
         "channels differ: `grass_normal` and `sand_normal` have rgb and rgba (give them the same"},
    };
    for (const auto& [apply, says] : others) {
        Material m = exampleTerrain();
        apply(slotOf(m, 1, 1));
        const std::vector<std::string> warnings = notArrayed(planShader(m, {}));
        ASSERT_EQ(warnings.size(), 1u) << says;
        EXPECT_NE(warnings[0].find("/layers/1/slots/1: role `normal` is 4 textures"), std::string::npos) << warnings[0];
        EXPECT_NE(warnings[0].find(says), std::string::npos) << warnings[0];
    }
    // Where the settings ask for separate textures, or there is one layer, nothing to warn of.
    Material off = sizes;
    off.layers->arrays = false;
    CompileOptions general, functions;
    general.specialise = false;
    functions.functions = true;
    EXPECT_TRUE(notArrayed(planShader(off, {})).empty());
    EXPECT_TRUE(notArrayed(planShader(sizes, general)).empty());
    EXPECT_TRUE(notArrayed(planShader(sizes, functions)).empty());
    EXPECT_TRUE(notArrayed(planShader(exampleTerrain(), {})).empty());
    EXPECT_TRUE(notArrayed(planShader(loadMaterial("tests/execution/layers/one.json"), {})).empty());
}

// tests/execution/layers/eight.json (8 layers of albedo, two splat maps) with a second role, roughness, in every layer:
// 18 slots, which bind 4 textures with arrays (one per role, and the splat maps). Texture paths made absolute, so
// that the material is written anywhere.
Material eightWithTwoRoles(const std::string& arrays, const std::filesystem::path& file) {
    const std::filesystem::path source = std::filesystem::absolute("tests/execution/layers/eight.json");
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(source));
    auto absolute = [&](nlohmann::json& path) { path = (source.parent_path() / path.get<std::string>()).lexically_normal().string(); };
    for (nlohmann::json& layer : doc["layers"]) {
        absolute(layer["slots"][0]["texture"]);
        layer["slots"].push_back(
            {{"name", "roughness"}, {"kind", "scalar"}, {"channel", "a"}, {"texture", "../../../materials/textures/terrain_grass_rh.png"}});
        absolute(layer["slots"][1]["texture"]);
    }
    for (nlohmann::json& splat : doc["layer_blend"]["splat"]) absolute(splat);
    doc["layer_blend"]["arrays"] = arrays;
    std::ofstream(file) << doc.dump(2);
    return loadMaterial(file);
}

std::vector<std::string> tooMany(const ShaderPlan& plan) { return withCode(plan, Code::WrongCount); }

// The 16 textures a shader may bind are counted as they are bound: 8 layers of two roles are 18 slots but 4 textures
// with arrays, and compile; with arrays off, or where the roles' textures refuse an array, 18 are refused (HX110) with
// the hint that helps: the arrays, and what keeps each role's apart.
TEST(LayerArrays, TheTextureLimitCountsAnArrayOnce) {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / ("hexc_eight_roles_" + test::testLogName() + ".json");
    const Material arrayed = eightWithTwoRoles("auto", file);
    ASSERT_EQ(arrayed.slots.size(), 18u);
    const ShaderPlan plan = planShader(arrayed, {});
    EXPECT_TRUE(tooMany(plan).empty()) << tooMany(plan)[0];
    size_t bound = 0;
    for (size_t i = 0; i < plan.slots.size(); ++i) bound += plan.textureBound(i);
    EXPECT_EQ(bound, 4u);
    const CompileResult r = compile(arrayed);
    EXPECT_TRUE(r.ok()) << formatAll(r.diagnostics);

    const std::vector<std::string> off = tooMany(planShader(eightWithTwoRoles("off", file), {}));
    ASSERT_EQ(off.size(), 1u);
    EXPECT_NE(off[0].find(": error[HX110]: /layers/0/slots/0: the shader binds 18 textures (a texture array or a packed texture "
                          "counted once, a histogram slot's table too); expected at most 16 (bind each role's layers as one texture array, "
                          "one texture instead "
                          "of one per layer: role `albedo` (layer_blend.arrays is \"off\"); role `roughness` (layer_blend.arrays "
                          "is \"off\"))"),
              std::string::npos)
        << off[0];
    // Sizes that differ in both roles: the hint names the fix, located at the slot that differs.
    Material sizes = arrayed;
    for (size_t role : {0, 1}) slotOf(sizes, 5, role).width = 128;
    const std::vector<std::string> apart = tooMany(planShader(sizes, {}));
    ASSERT_EQ(apart.size(), 1u);
    EXPECT_NE(apart[0].find("error[HX110]: /layers/5/slots/1: the shader binds 18 textures"), std::string::npos) << apart[0];
    EXPECT_NE(apart[0].find("role `roughness` (sizes differ: `grass_roughness` and `tiles_roughness` are 256x256 and 128x256 "
                            "texels: resize them to one size)"),
              std::string::npos)
        << apart[0];
    // One role apart binds 8 + 1 + 2 = 11: within the limit.
    Material one = arrayed;
    slotOf(one, 5, 0).width = 128;
    EXPECT_TRUE(tooMany(planShader(one, {})).empty());
    std::filesystem::remove(file);
}

// A histogram slot's table is a texture the shader binds too: 16 slots, one of them blended by histogram, bind 17 in the
// functions output (which reads every slot) and are refused (HX110) at that slot; 15 slots bind 16.
TEST(LayerArrays, TheTextureLimitCountsAHistogramSlotsTable) {
    nlohmann::json doc = {{"name", "sixteen"}, {"slots", nlohmann::json::array()}};
    for (int i = 0; i < 16; ++i)
        doc["slots"].push_back({{"name", "s" + std::to_string(i)},
                                {"kind", "scalar"},
                                {"texture", std::filesystem::absolute("materials/textures/rock_roughness.png").string()}});
    doc["slots"][3]["hextiling"] = {{"blend", "histogram"}};
    const std::filesystem::path file = std::filesystem::temp_directory_path() / ("hexc_sixteen_" + test::testLogName() + ".json");
    std::ofstream(file) << doc.dump(2);
    CompileOptions functions;
    functions.functions = true;
    const std::vector<std::string> over = tooMany(planShader(loadMaterial(file), functions));
    ASSERT_EQ(over.size(), 1u);
    EXPECT_NE(over[0].find("error[HX110]: /slots/3: the shader binds 17 textures"), std::string::npos) << over[0];
    EXPECT_NE(over[0].find("(blend a slot by falloff: a histogram slot binds its table besides its texture)"), std::string::npos)
        << over[0];
    doc["slots"].erase(15);
    std::ofstream(file) << doc.dump(2);
    EXPECT_TRUE(tooMany(planShader(loadMaterial(file), functions)).empty());
    std::filesystem::remove(file);
}

TEST(LayerArrays, TheShaderReadsEachLayerThroughTheArrayAtAConstantLayer) {
    Material m = exampleTerrain();
    m.templ = TemplateRef::builtin("lit");
    const CompileResult r = compile(m);
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    EXPECT_NE(r.glsl.find("uniform texture2DArray hexcArr_albedo;"), std::string::npos);
    EXPECT_EQ(r.glsl.find("uniform texture2D hexcTex_sand_albedo;"), std::string::npos);
    EXPECT_NE(r.glsl.find("#define HEXC_HAS_sand_albedo 1"), std::string::npos);
    // Layer 2 (pebbles) of the albedo array, a literal the specialiser and spirv-opt fold: not a parameter.
    EXPECT_NE(r.glsl.find("sampler2DArray(tex, samp), vec3(p.st, 2.0)"), std::string::npos) << r.glsl;
}

TEST(LayerArrays, TheManifestSaysWhichSlotsAreWhichArrayAndWhyNot) {
    Material m = exampleTerrain();
    slotOf(m, 1, 1).width = 64;  // the normal role falls back
    CompileOptions options;
    options.targets = {Target::Spirv, Target::Hlsl};
    const CompileResult r = compile(m, options);
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    nlohmann::json manifest;
    for (const OutputFile& f : r.files)
        if (f.name.ends_with(".manifest.json")) manifest = nlohmann::json::parse(f.contents);
    const nlohmann::json& arrays = manifest["layers"]["arrays"];
    ASSERT_EQ(arrays.size(), 3u);
    EXPECT_EQ(arrays[0]["role"], "albedo");
    EXPECT_EQ(arrays[0]["array"], true);
    EXPECT_EQ(arrays[0]["slots"], nlohmann::json({"grass_albedo", "sand_albedo", "pebbles_albedo", "snow_albedo"}));
    EXPECT_EQ(arrays[0]["size"], nlohmann::json({256, 256, 4}));
    EXPECT_EQ(arrays[0]["colorspace"], "srgb");
    EXPECT_EQ(arrays[0]["binding"]["texture"], "albedo.array");
    EXPECT_EQ(arrays[0]["binding"]["type"], "texture2DArray");
    EXPECT_EQ(arrays[1]["array"], false);
    EXPECT_EQ(arrays[1]["why_not"], "sizes differ: `grass_normal` and `sand_normal` are 256x256 and 64x256 texels");
    for (const nlohmann::json& s : manifest["slots"]) {
        if (s["name"] == "pebbles_albedo") {
            EXPECT_EQ(s["array"], nlohmann::json({{"texture", "albedo.array"}, {"layer", 2}}));
        }
        if (s["name"] == "sand_normal") {
            EXPECT_FALSE(s.contains("array"));
        }
    }
    for (const char* target : {"spirv", "hlsl"}) {
        const nlohmann::json& textures = manifest["targets"][target]["textures"];
        EXPECT_TRUE(textures.contains("albedo.array")) << target;
        EXPECT_FALSE(textures.contains("sand_albedo")) << target << ": an array's later layers have no binding";
        EXPECT_TRUE(textures.contains("sand_normal")) << target;
    }
}

}  // namespace
