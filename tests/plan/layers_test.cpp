// Layered materials (docs/material-format.md#layers): the layers become slots <layer>_<role>, the template reads the
// blend per role, a layer of weight 0 is behind a branch, and the plan counts fetches per pixel.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>

#include "hexc/compiler.h"
#include "hexc/spirv.h"
#include "plan/plan.h"
#include "support.h"

using namespace hexc;
using hexc::test::exampleTerrain;
using hexc::test::loadMaterial;

namespace {

CompileResult compiled(Material m, const std::string& templ = "lit") {
    m.templ = TemplateRef::builtin(templ);
    CompileResult r = compile(m);
    EXPECT_TRUE(r.ok()) << formatAll(r.diagnostics);
    return r;
}

nlohmann::json manifestOf(const CompileResult& r) {
    for (const OutputFile& f : r.files)
        if (f.name.ends_with(".manifest.json")) return nlohmann::json::parse(f.contents);
    return {};
}

TEST(Layers, EachLayersSlotIsASlotNamedAfterItsLayerAndRole) {
    const Material m = exampleTerrain();
    ASSERT_TRUE(m.layers);
    ASSERT_EQ(m.layers->layers.size(), 4u);
    ASSERT_EQ(m.layers->roles.size(), 3u);
    EXPECT_EQ(m.layers->roles[0].name, "albedo");
    EXPECT_EQ(m.layers->roles[1].kind, SlotKind::Normal);
    ASSERT_EQ(m.slots.size(), 13u);  // 4 layers x 3 roles + the splat map
    EXPECT_EQ(m.slots[m.layers->layers[1].slots[0]].name, "sand_albedo");
    EXPECT_EQ(m.slots[m.layers->layers[1].slots[0]].hex.tiling[0], 6);  // the layer's hextiling over the material's 8
    EXPECT_EQ(m.slots[m.layers->layers[0].slots[0]].hex.tiling[0], 8);
    ASSERT_EQ(m.layers->splats.size(), 1u);
    const Slot& splat = m.slots[m.layers->splats[0]];
    EXPECT_EQ(splat.name, "splat0");
    EXPECT_FALSE(splat.hex.enabled);
    EXPECT_EQ(splat.colorSpace, ColorSpace::Linear);
    EXPECT_EQ(m.layers->blend, LayerBlend::Height);
    EXPECT_EQ(m.layers->heightRole, 2u);
}

TEST(Layers, TheTemplateReadsTheBlendPerRoleAndEachLayerIsBehindABranch) {
    const CompileResult r = compiled(exampleTerrain());
    EXPECT_NE(r.glsl.find("vec4 hexc_albedo(vec2 uv, out vec3 weights)"), std::string::npos);
    EXPECT_NE(r.glsl.find("vec2 hexc_normal(vec2 uv, out vec3 weights)"), std::string::npos);
    EXPECT_NE(r.glsl.find("#define HEXC_HAS_albedo 1"), std::string::npos);
    // lit reads no `height`: no role function for it, but the height blend reads every layer's height slot.
    EXPECT_EQ(r.glsl.find("hexc_height(vec2 uv"), std::string::npos);
    for (const char* layer : {"grass", "sand", "pebbles", "snow"})
        EXPECT_NE(r.glsl.find("hexcAt_" + std::string(layer) + "_height(st"), std::string::npos) << layer;
    EXPECT_NE(r.glsl.find("if (w[3] > 0.0) {"), std::string::npos);
}

TEST(Layers, TheManifestCountsWorstAndExpectedFetchesPerPixel) {
    const nlohmann::json layers = manifestOf(compiled(exampleTerrain()))["layers"];
    ASSERT_TRUE(layers.is_object());
    EXPECT_EQ(layers["mode"], "height");
    EXPECT_EQ(layers["roles"].size(), 2u);  // lit reads albedo and normal
    // Once per pixel, shared by the roles: the splat map (1) and per layer (4) its height (3 taps); per role read (2)
    // and layer, its slot (3 taps).
    EXPECT_EQ(layers["fetches_per_pixel"]["worst"], 1 + 4 * 3 + 2 * 4 * 3);
    double expected = 1;
    for (const auto& c : layers["coverage"]) expected += (3 + 2 * 3) * c.get<double>();
    EXPECT_NEAR(layers["fetches_per_pixel"]["expected"].get<double>(), expected, 1e-9);  // summed in another order
    EXPECT_LT(expected, layers["fetches_per_pixel"]["worst"].get<double>());
}

// CompileOptions::skipLayers off (the bench's naive per-layer baseline): no layer's fetches sit behind its weight, and
// the manifest's expected fetches are the worst case.
TEST(Layers, WithoutSkippingEveryLayerIsFetchedEverywhere) {
    Material m = exampleTerrain();
    CompileOptions options;
    options.skipLayers = false;
    const CompileResult r = compile(m, options);
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    for (const std::string i : {"0", "1", "2", "3"}) {
        EXPECT_EQ(r.glsl.find("if (w[" + i + "] > 0.0) {"), std::string::npos) << i;   // a role's layer
        EXPECT_EQ(r.glsl.find("if (w[" + i + "] > 0.0) h["), std::string::npos) << i;  // a layer's height
    }
    EXPECT_NE(r.glsl.find("if (true) h[3]"), std::string::npos);
    const nlohmann::json fetches = manifestOf(r)["layers"]["fetches_per_pixel"];
    EXPECT_EQ(fetches["expected"], fetches["worst"]);
    EXPECT_EQ(fetches["worst"], manifestOf(compiled(exampleTerrain()))["layers"]["fetches_per_pixel"]["worst"]);
}

// The manifest's worst case counts what the code does. Each fetch of the optimised shader sits in straight code or in
// one layer's branch, and runs once when every branch is taken, but for the shared weights' fetches (the splat maps and
// the heights): every role read holds them behind the test that only the pixel's first read passes. So with one role
// read the shader's fetches are the worst case, and with more they are at most the worst case plus the shared fetches
// once more per later read (fewer where the optimiser merges a later read's fetch with the first's, e.g. the splat map's,
// whose first read dominates). A role function that fetched the splat map or the heights outside that test, or a layer
// outside its branch, would break the bounds.
TEST(Layers, TheWorstFetchesAreTheShadersFetches) {
    for (const char* path : {"materials/terrain/terrain.json", "tests/golden/materials/layers_linear.json"}) {
        ParseResult parsed = parseMaterialFile(path);
        ASSERT_TRUE(parsed.material) << formatAll(parsed.diagnostics);
        for (const char* templ : {"lit", "value"}) {
            Material m = *parsed.material;
            m.templ = TemplateRef::builtin(templ);
            CompileOptions options;
            options.targets = {Target::Spirv};
            const CompileResult r = compile(m, options);
            ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
            const nlohmann::json layers = manifestOf(r)["layers"];
            const double worst = layers["fetches_per_pixel"]["worst"].get<double>();
            const double heights = layers.contains("heights") ? double(layers["heights"].size()) : 0;
            const double shared = double(layers["splat_maps"].size()) + 3 * heights;  // a height: 3 taps
            const double later = double(layers["roles"].size() - 1);
            const double fetches = countOps(disassemble(r.spirv)).textureSamples;
            EXPECT_GE(fetches, worst) << path << " " << templ;
            EXPECT_LE(fetches, worst + later * shared) << path << " " << templ;
            if (later == 0) {
                EXPECT_EQ(fetches, worst) << path << " " << templ;
            }
            // One call of the fill, behind the test.
            EXPECT_EQ(r.glsl.find("hexcLayerFill(st"), r.glsl.rfind("hexcLayerFill(st"));
            EXPECT_NE(r.glsl.find("if (!hexcLayersFilled || st != hexcLayersSt) {\n        hexcLayerFill(st"), std::string::npos);
        }
    }
}

// Packing does not merge a layered material's fetches: each role reads its own slot of a packed texture in its own
// function (hexc_albedo the albedo's rgb, hexc_height the height's a), so the packed texture is fetched once per read,
// which is once per slot it serves, as the figures count it. A packed texture fetched once for its two slots would
// put the shader's fetches below the worst case.
TEST(Layers, APackedTextureIsCountedOncePerRead) {
    ParseResult parsed = parseMaterialFile("tests/execution/layers/four_packed.json");
    ASSERT_TRUE(parsed.material) << formatAll(parsed.diagnostics);
    Material m = *parsed.material;
    m.templ = TemplateRef::parse("tests/templates/layers_packed.glsl");
    CompileOptions options;
    options.targets = {Target::Spirv};
    const CompileResult r = compile(m, options);
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    const nlohmann::json manifest = manifestOf(r);
    ASSERT_EQ(manifest["packed_textures"].size(), 4u);  // each layer's height in its albedo's alpha
    const double worst = manifest["layers"]["fetches_per_pixel"]["worst"].get<double>();
    EXPECT_EQ(worst, 4 * 2 * 3 + 1);  // 4 layers, 2 roles, 3 taps, and the splat map
    const double fetches = countOps(disassemble(r.spirv)).textureSamples;
    EXPECT_GE(fetches, worst);
    EXPECT_LE(fetches, worst + 1);  // the splat map once more for the later role read (TheWorstFetchesAreTheShadersFetches)
}

// One lattice per distinct tiling and lattice settings, shared by the layers and roles: terrain's grass and pebbles
// (tiling 8, layers 0 and 2) read one, sand (6) and snow (4) their own. Each lattice's tiles are computed at one place,
// in the fill of the pixel's weights (which runs once per pixel: TheWorstFetchesAreTheShadersFetches), where one of
// its layers is kept, and every slot of the lattice reads them; not once per layer and role read (12 for terrain).
TEST(Layers, EachDistinctLatticesTilesAreComputedOncePerPixel) {
    const std::regex computed(R"(hexcTilesStable_(\w+)\(st, dx, dy, cell\))");
    const char* const kept[] = {"w[0] > 0.0 || w[2] > 0.0", "w[1] > 0.0", "w[3] > 0.0"};
    for (const char* templ : {"lit", "value"}) {
        const CompileResult r = compiled(exampleTerrain(), templ);
        std::vector<std::string> lattices;
        for (auto it = std::sregex_iterator(r.glsl.begin(), r.glsl.end(), computed); it != std::sregex_iterator(); ++it)
            lattices.push_back((*it)[1].str());
        EXPECT_EQ(lattices, (std::vector<std::string>{"grass_albedo", "sand_albedo", "snow_albedo"})) << templ;
        for (size_t k = 0; k < 3; ++k) {
            const std::string i = std::to_string(k), call = "hexcLayerTiles" + i + "(st * ";
            const size_t at = r.glsl.find(call);
            EXPECT_NE(r.glsl.find("if (" + std::string(kept[k]) + ") hexcLatticeTiles" + i + " = " + call), std::string::npos) << templ;
            EXPECT_EQ(at, r.glsl.rfind(call)) << templ << " " << k;  // one call
            EXPECT_GT(at, r.glsl.find("void hexcLayerFill(")) << templ << " " << k;
        }
        // The layers' slots read the shared tiles: pebbles grass's, in each role and for the heights.
        for (const char* role : {"albedo", "height"})
            EXPECT_NE(r.glsl.find("hexcColor_pebbles_" + std::string(role) + "(hexcArr_" + role + ", hexcSampler, hexcLatticeTiles0, "),
                      std::string::npos)
                << templ << " " << role;
    }
}

TEST(Layers, TheValueTemplateShowsTheFirstRole) {
    const CompileResult r = compiled(exampleTerrain(), "value");
    EXPECT_NE(r.glsl.find("#define HEXC_FIRST_SLOT hexc_albedo"), std::string::npos);
    EXPECT_NE(r.glsl.find("#define HEXC_FIRST_KIND_color 1"), std::string::npos);
}

// Vertex weights: the colour is a stage input the manifest locates (the lowest location from 4 up the template leaves
// free), its channel i weighs layer i, and the expected fetches are unknown without splat maps.
TEST(Layers, VertexWeightsAreAStageInputTheManifestLocates) {
    const CompileResult r = compiled(loadMaterial("tests/execution/layers/two_vertex.json"), "value");
    EXPECT_NE(r.glsl.find("layout(location = 4) in vec4 hexcVertexColor;"), std::string::npos);
    EXPECT_NE(r.glsl.find("w[1] = clamp(hexcVertexColor[1], 0.0, 1.0);"), std::string::npos);
    const nlohmann::json manifest = manifestOf(r);
    const nlohmann::json layers = manifest["layers"];
    EXPECT_EQ(layers["weights"], "vertex");
    EXPECT_EQ(layers["vertex_color"], (nlohmann::json{{"input", "hexcVertexColor"}, {"location", 4}, {"type", "vec4"}}));
    EXPECT_TRUE(layers["splat_maps"].empty());
    EXPECT_EQ(layers["fetches_per_pixel"]["worst"], 2 * 3);  // two layers of 3 taps, no splat map
    EXPECT_TRUE(layers["fetches_per_pixel"]["expected"].is_null());
    bool listed = false;  // the SPIR-V's reflection lists the input where the manifest says
    for (const auto& input : manifest["targets"]["spirv"]["inputs"]) listed |= input["name"] == "hexcVertexColor" && input["location"] == 4;
    EXPECT_TRUE(listed) << manifest["targets"]["spirv"]["inputs"].dump();
}

TEST(Layers, TheVertexColourTakesALocationTheTemplateLeavesFree) {
    const std::filesystem::path templ = std::filesystem::temp_directory_path() / "hexc_vertex_location.glsl";
    std::ofstream(templ) << "#version 450\nlayout(location = 0) in vec2 v_uv;\nlayout(location = 4) flat in int v_id;\n"
                            "layout(location = 5) in vec4 v_extra;\nlayout(location = 0) out vec4 o_color;\n#include <hexc>\n"
                            "void main() { o_color = hexc_albedo(v_uv) + v_extra * float(v_id); }\n";
    CompileOptions options;
    options.templateFile = templ;
    const CompileResult r = compile(loadMaterial("tests/execution/layers/two_both.json"), options);
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    EXPECT_NE(r.glsl.find("layout(location = 6) in vec4 hexcVertexColor;"), std::string::npos);
    EXPECT_NE(r.glsl.find("w[1] = splat0[1] * clamp(hexcVertexColor[1], 0.0, 1.0);"), std::string::npos);
    const nlohmann::json layers = manifestOf(r)["layers"];
    EXPECT_EQ(layers["vertex_color"]["location"], 6);
    // Both: counted over the splat map, an upper bound (the clamped colour only lowers a weight).
    EXPECT_TRUE(layers["fetches_per_pixel"]["expected"].is_number());
    EXPECT_LT(layers["fetches_per_pixel"]["expected"].get<double>(), layers["fetches_per_pixel"]["worst"].get<double>());
}

// The functions output's role functions take the vertex colour after uv (no stage input), and the manifest says so: in
// each function's parameters and as the layers' vertex_color, so that an engine layer passes its own.
TEST(Layers, TheFunctionsOutputTakesTheVertexColourAsAParameter) {
    CompileOptions options;
    options.functions = true;
    options.targets = {Target::Glsl, Target::Hlsl};
    const CompileResult r = compile(loadMaterial("tests/execution/layers/two_vertex.json"), options);
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    EXPECT_EQ(r.glsl.find("hexcVertexColor"), std::string::npos);
    std::map<std::string, std::string> files;
    for (const OutputFile& f : r.files) files[f.name] = f.contents;
    EXPECT_NE(files["layers_two_vertex.functions.glsl"].find("vec4 hexc_albedo(vec2 uv, vec4 color)"), std::string::npos);
    EXPECT_NE(files["layers_two_vertex.functions.hlsl"].find("float4 hexc_albedo(float2 uv, float4 color)"), std::string::npos);
    const nlohmann::json manifest = manifestOf(r);
    EXPECT_EQ(manifest["functions"][0]["parameters"], "vec2 uv, vec4 color");
    EXPECT_EQ(manifest["layers"]["vertex_color"], (nlohmann::json{{"parameter", "color"}, {"type", "vec4"}}));
}

}  // namespace

// The expected fetches count layer 0 where a splat texel is unpainted (every layer's weight below skip_below, so layer 0
// shows), as where its own weight is kept: over a 4 x 4 splat map with 5 texels unpainted, 3 of layer 0 and 8 of the
// others, layer 0 covers 8 of 16 texels (3 of its own, 5 unpainted; before, 3), the others theirs.
TEST(Layers, TheExpectedFetchesCountLayerZeroWhereNothingIsPainted) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("hexc_unpainted_" + test::testLogName());
    std::filesystem::create_directories(dir);
    Texture splat{4, 4, false, std::vector<uint8_t>(64, 0), {}};
    const int layerOf[16] = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, -1, -1, -1, -1, -1};  // -1: unpainted
    for (int i = 0; i < 16; ++i)
        if (layerOf[i] >= 0) splat.rgba8[size_t(4 * i + layerOf[i])] = 255;
    std::ofstream(dir / "splat.png", std::ios::binary) << pngBytes(splat);
    std::ofstream(dir / "grey.png", std::ios::binary) << pngBytes(Texture{1, 1, false, {128, 128, 128, 255}, {}});
    std::string layers;
    for (const char* name : {"a", "b", "c", "d"})
        layers += std::string(layers.empty() ? "" : ",") + R"({"name": ")" + name +
                  R"(", "slots": [{"name": "albedo", "kind": "color", "texture": "grey.png"}]})";
    std::ofstream(dir / "m.json") << R"({"name": "unpainted", "layers": [)" << layers << R"(], "layer_blend": {"splat": ["splat.png"]}})";
    const nlohmann::json manifest = manifestOf(compiled(loadMaterial(dir / "m.json")))["layers"];
    EXPECT_EQ(manifest["coverage"], nlohmann::json({8 / 16.0, 3 / 16.0, 3 / 16.0, 2 / 16.0}));
    // One splat fetch, and per kept layer its albedo's 3 taps.
    EXPECT_NEAR(manifest["fetches_per_pixel"]["expected"].get<double>(), 1 + 3 * (8 + 3 + 3 + 2) / 16.0, 1e-12);
    std::filesystem::remove_all(dir);
}
