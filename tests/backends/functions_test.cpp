// The functions output (--functions, docs/engines.md): each slot's function by name on every target, no entry point
// or stage variables left, and the text compiles again once a consumer's main calls every function, as an engine's
// material would.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cctype>
#include <fstream>
#include <sstream>

#include "engines/table.h"
#include "hexc/compiler.h"
#include "hexc/engines.h"
#include "hexc/image.h"
#include "hexc/spirv.h"
#include "support.h"

using namespace hexc;

namespace {

CompileResult compileFunctions(const std::string& name, UvOrigin origin = UvOrigin::TopLeft) {
    ParseResult p = parseMaterialFile("materials/" + name + ".json");
    if (!p.material) throw std::runtime_error(formatAll(p.diagnostics));
    CompileOptions options;
    options.functions = true;
    options.uvOrigin = origin;
    options.targets = {Target::Hlsl, Target::Glsl, Target::Msl};
    CompileResult r = compile(*p.material, options);
    EXPECT_TRUE(r.ok()) << formatAll(r.diagnostics);
    return r;
}

std::string contents(const CompileResult& r, const std::string& name) {
    for (const OutputFile& f : r.files)
        if (f.name == name) return f.contents;
    ADD_FAILURE() << "no " << name;
    return "";
}

// `sum` accumulating every function's value at `uv`: what an engine's material reads.
std::string calls(const nlohmann::json& functions) {
    static const std::map<std::string, std::string> swizzle = {{"vec4", ""}, {"vec3", ".xyz"}, {"vec2", ".xy"}, {"float", ".x"}};
    std::string out;
    for (const auto& f : functions) out += "    sum" + swizzle.at(f["returns"]) + " += " + f["name"].get<std::string>() + "(uv);\n";
    return out;
}

class Functions : public testing::TestWithParam<const char*> {};

TEST_P(Functions, EachSlotsFunctionCompilesInAConsumersShader) {
    const std::string name = GetParam();
    CompileResult r = compileFunctions(name);
    ASSERT_TRUE(r.ok());
    const auto manifest = nlohmann::json::parse(contents(r, name + ".manifest.json"));
    ASSERT_FALSE(manifest["functions"].empty());
    EXPECT_FALSE(manifest["targets"].contains("spirv"));
    for (const char* file : {".functions.glsl", ".functions.hlsl", ".functions.metal"}) {
        const std::string text = contents(r, name + file);
        for (const auto& f : manifest["functions"])
            EXPECT_NE(text.find(" " + f["name"].get<std::string>() + "("), std::string::npos) << file;
        for (const char* gone : {"void main()", "frag_main", "fragment ", "SPIRV_Cross_Input", "hexcEngine", "#version"})
            EXPECT_EQ(text.find(gone), std::string::npos) << file << " keeps " << gone;
    }
    const std::string sum = calls(manifest["functions"]);
    const std::string glsl =
        "#version 450\n" + contents(r, name + ".functions.glsl") +
        "\nlayout(location = 0) in vec2 uv;\nlayout(location = 0) out vec4 sum;\nvoid main() {\n    sum = vec4(0.0);\n" + sum + "}\n";
    SpirvResult g = compileToSpirv(glsl, ShaderStage::Fragment, "consumer.glsl", SourceLanguage::OpenGlGlsl);
    EXPECT_FALSE(g.words.empty()) << formatAll(g.diagnostics);
    const std::string hlsl = contents(r, name + ".functions.hlsl") +
                             "\nfloat4 consumer(float2 uv : TEXCOORD0) : SV_Target {\n    float4 sum = 0.0f;\n" + sum +
                             "    return sum;\n}\n";
    SpirvResult h = compileToSpirv(hlsl, ShaderStage::Fragment, "consumer.hlsl", SourceLanguage::Hlsl, "consumer");
    EXPECT_FALSE(h.words.empty()) << formatAll(h.diagnostics);
}

INSTANTIATE_TEST_SUITE_P(Examples, Functions, testing::Values("rock", "tiles", "rock_normal"));

TEST(Functions, BottomLeftOriginSamplesTheFlippedCoordinate) {
    const std::string top = contents(compileFunctions("rock"), "rock.functions.glsl");
    const std::string bottom = contents(compileFunctions("rock", UvOrigin::BottomLeft), "rock.functions.glsl");
    EXPECT_EQ(top.find("1.0 - uv.y"), std::string::npos);
    EXPECT_NE(bottom.find("vec2(uv.x, 1.0 - uv.y)"), std::string::npos);
}

TEST(Functions, TriplanarMaterialsAreRefused) {
    ParseResult p = parseMaterialFile("materials/rock_triplanar.json");
    ASSERT_TRUE(p.material);
    CompileOptions options;
    options.functions = true;
    options.targets = {Target::Glsl};
    CompileResult r = compile(*p.material, options);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(formatAll(r.diagnostics).find("/hextiling/projection: the functions output"), std::string::npos) << formatAll(r.diagnostics);
    EXPECT_TRUE(r.files.empty());
}

// WGSL's functions (naga): each engine function by its name, taking the uv by pointer, without the entry point, its
// body or the stage's variables, the resources at their @group and @binding; a module naga validates.
TEST(Functions, WgslKeepsTheFunctionsAndTheirResources) {
    REQUIRE_NAGA();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_functions_wgsl";
    std::filesystem::remove_all(dir);
    std::string err;
    ASSERT_EQ(hexc::test::runHexc("materials/rock.json --functions --targets wgsl,glsl -o " + dir.string(), &err, naga), 0) << err;
    const std::string wgsl = hexc::test::readFile(dir / "rock.functions.wgsl");
    for (const char* expected :
         {"fn hexc_albedo(", ": ptr<function, vec2<f32>>) -> vec4<f32> {", "fn hexc_normal(", "fn hexc_normal_normal(",
          "@group(0) @binding(2) var hexcTex_albedo: texture_2d<f32>;", "@group(0) @binding(1) var hexcSampler: sampler;"})
        EXPECT_NE(wgsl.find(expected), std::string::npos) << expected << "\n" << wgsl.substr(0, 800);
    for (const char* cut : {"@fragment", "var<private>", "rock_frag", "hexcEngine"}) EXPECT_EQ(wgsl.find(cut), std::string::npos) << cut;
    const nlohmann::json manifest = nlohmann::json::parse(hexc::test::readFile(dir / "rock.manifest.json"));
    EXPECT_EQ(manifest["targets"]["wgsl"]["file"], "rock.functions.wgsl");
    EXPECT_FALSE(manifest["targets"]["wgsl"].contains("entry_point"));
    EXPECT_EQ(std::system((naga + " node tests/backends/wgsl_check.mjs " + (dir / "rock.functions.wgsl").string()).c_str()), 0);
}

TEST(Functions, SpirvIsRefused) {
    ParseResult p = parseMaterialFile("materials/rock.json");
    CompileOptions options;
    options.functions = true;
    CompileResult r = compile(*p.material, options);  // the default targets include SPIR-V
    EXPECT_FALSE(r.ok());
    EXPECT_NE(formatAll(r.diagnostics).find("not SPIR-V"), std::string::npos);
}

}  // namespace

namespace {

// The first source file of `material`'s package for `engine` (its functions').
std::string package(const Material& material, Engine engine, Diagnostics* diagnostics = nullptr) {
    CompileResult r = compileForEngine(material, engine, {});
    EXPECT_TRUE(r.ok()) << formatAll(r.diagnostics);
    if (diagnostics) *diagnostics = r.diagnostics;
    const std::string dir(toString(engine));
    for (const OutputFile& f : r.files)
        if (f.name.starts_with(dir + "/" + material.name + ".") && !f.name.ends_with(".json") && !f.name.ends_with(".png"))
            return f.contents;
    ADD_FAILURE() << "no package source";
    return "";
}

std::string package(const std::string& name, Engine engine, Diagnostics* diagnostics = nullptr) {
    ParseResult p = parseMaterialFile("materials/" + name + ".json");
    return package(*p.material, engine, diagnostics);
}

// The data of a web package's module, as hexc wrote it.
nlohmann::json moduleData(const std::filesystem::path& module) {
    const std::string text = hexc::test::readFile(module);
    const size_t start = text.find("const hexc = ") + 13;
    return nlohmann::json::parse(text.substr(start, text.find(";\n", start) - start));
}

// --targets wgsl gives Babylon.js's package its WGSL form (naga's functions in the module's data, beside the GLSL);
// the engines without one (all but three.js WebGPU's, which is WGSL) refuse it, saying which engines take it.
TEST(EnginePackages, OnlyBabylonAndWebgpuTakeWgsl) {
    ParseResult p = parseMaterialFile("materials/rock.json");
    CompileOptions options;
    options.targets = {Target::Wgsl};
    EXPECT_TRUE(engineRow(Engine::Babylon).wgsl && engineRow(Engine::ThreejsWebgpu).wgsl);
    for (size_t i = 0; i < kEngineCount; ++i) {  // every other engine of the table, one added included
        const Engine engine = Engine(i);
        if (engine == Engine::Babylon || engine == Engine::ThreejsWebgpu) continue;
        CompileResult r = compileForEngine(*p.material, engine, options);
        EXPECT_FALSE(r.ok());
        EXPECT_TRUE(r.files.empty());
        EXPECT_NE(formatAll(r.diagnostics).find("error[HX300]: the " + std::string(toString(engine)) + " package has no WGSL form"),
                  std::string::npos)
            << formatAll(r.diagnostics);
    }
    REQUIRE_NAGA();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_babylon_wgsl";
    std::filesystem::remove_all(dir);
    std::string err;
    ASSERT_EQ(hexc::test::runHexc("materials/rock.json --engine babylon --targets wgsl -o " + dir.string(), &err, naga), 0) << err;
    const nlohmann::json data = moduleData(dir / "babylon" / "rock.babylon.js");
    EXPECT_NE(data["wgsl"].get<std::string>().find("fn hexc_albedo("), std::string::npos);
    EXPECT_NE(data["glsl"].get<std::string>().find("vec4 hexc_albedo(highp vec2 uv)"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir / "babylon" / "rock.functions.wgsl"));  // the module holds it
}

// three.js WebGPU's package holds the functions in WGSL only (naga's, without --targets), with the textures and each
// slot's input as three.js's WebGL 2 package has them, and carries a layered material: its roles' functions and the
// splat map's texture.
TEST(EnginePackages, ThreejsWebgpuHoldsWgslAndCarriesLayers) {
    REQUIRE_NAGA();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_threejs_webgpu";
    std::filesystem::remove_all(dir);
    std::string err;
    ASSERT_EQ(
        hexc::test::runHexc("materials/rock.json materials/terrain/terrain.json --engine threejs-webgpu -o " + dir.string(), &err, naga), 0)
        << err;
    const nlohmann::json rock = moduleData(dir / "threejs-webgpu" / "rock.three-webgpu.js");
    EXPECT_NE(rock["wgsl"].get<std::string>().find("fn hexc_albedo(uv"), std::string::npos);
    EXPECT_FALSE(rock.contains("glsl"));
    EXPECT_EQ(rock["uv_origin"], "top-left");
    EXPECT_EQ(rock["slots"][0], nlohmann::json::parse(R"j({"name": "albedo", "role": "albedo", "call": "hexc_albedo(UV)",
                                                            "uniform": "hexcTex_albedo"})j"));
    EXPECT_EQ(rock["textures"][0],
              nlohmann::json::parse(R"j({"file": "rock.albedo.png", "uniform": "hexcTex_albedo", "colorspace": "srgb"})j"));
    const nlohmann::json terrain = moduleData(dir / "threejs-webgpu" / "terrain.three-webgpu.js");
    EXPECT_EQ(terrain["slots"][0]["call"], "hexc_albedo(UV)");
    EXPECT_NE(terrain["wgsl"].get<std::string>().find("var hexcTex_splat0_: texture_2d<f32>;"), std::string::npos);  // naga's name
    EXPECT_TRUE(std::filesystem::exists(dir / "threejs-webgpu" / "terrain.splat0.png"));
}

TEST(EnginePackages, GodotGetsItsDialectAndItsInputs) {
    for (Engine engine : {Engine::Godot3, Engine::Godot4}) {
        const std::string text = package("rock", engine);
        EXPECT_TRUE(text.starts_with("shader_type spatial;"));
        // Godot's shading language has no layout qualifiers, uint literals or fma, and declares the textures itself.
        for (const char* refused : {"layout(", "fma(", "97u", "#version"}) EXPECT_EQ(text.find(refused), std::string::npos) << refused;
        EXPECT_NE(text.find("ALBEDO = (hexc_albedo(UV)).rgb;"), std::string::npos);
        EXPECT_NE(text.find("ROUGHNESS = hexc_roughness(UV);"), std::string::npos);
        EXPECT_NE(text.find(engine == Engine::Godot3 ? "NORMALMAP = hexc_normal_normal(UV)" : "NORMAL_MAP = hexc_normal_normal(UV)"),
                  std::string::npos);
        EXPECT_NE(text.find(engine == Engine::Godot3 ? "uniform sampler2D hexcTex_albedo : hint_albedo;" : "hexcTex_albedo : source_color"),
                  std::string::npos);
    }
}

// Unity's and Unreal's functions take each texture they read, with a sampler of its own, as parameters and declare no
// global resource (a Custom node's include file cannot); Unity's read every texture at (s, -t) (spirv/textures.h),
// Unreal's as they are.
TEST(EnginePackages, HlslPackagesPassTexturesInAndUnityFlipsEveryRead) {
    for (Engine engine : {Engine::Unity, Engine::Unreal}) {
        const std::string text = package(hexc::test::exampleTerrain(), engine);
        EXPECT_EQ(text.find("register("), std::string::npos) << toString(engine);
        EXPECT_NE(text.find("float hexc_height(float2 uv, Texture2DArray<float4> hexcArr_height, SamplerState _hexcArr_height_sampler, "
                            "Texture2D<float4> hexcTex_splat0, SamplerState _hexcTex_splat0_sampler)"),
                  std::string::npos)
            << toString(engine);
        size_t reads = 0, flipped = 0;
        for (size_t at = text.find(".SampleGrad("); at != std::string::npos; at = text.find(".SampleGrad(", at + 1)) {
            ++reads;
            const std::string call = text.substr(at, text.find(";\n", at) - at);
            flipped +=
                call.find("* float2(1.0f, -1.0f)") != std::string::npos || call.find("* float3(1.0f, -1.0f, 1.0f)") != std::string::npos;
        }
        EXPECT_GT(reads, 10u) << toString(engine);
        EXPECT_EQ(flipped, engine == Engine::Unity ? reads : 0) << toString(engine);
    }
}

// --debug's #line directives stay out of the GLSL engines' packages: Godot 3's language has no preprocessor.
TEST(EnginePackages, GlslPackagesHoldNoLineDirectivesUnderDebug) {
    ParseResult p = parseMaterialFile("materials/rock.json");
    CompileOptions debug;
    debug.debug = true;
    for (size_t i = 0; i < kEngineCount; ++i) {  // every engine of the GLSL family, one added included
        const Engine engine = Engine(i);
        if (engineRow(engine).write != glslPackage) continue;
        CompileResult r = compileForEngine(*p.material, engine, debug);
        ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
        const auto source = std::find_if(r.files.begin(), r.files.end(), [](const OutputFile& f) { return !f.name.ends_with(".json"); });
        ASSERT_NE(source, r.files.end());
        EXPECT_EQ(source->contents.find("#line"), std::string::npos) << source->name;
        EXPECT_NE(source->contents.find("hexc_albedo("), std::string::npos) << source->name;
    }
}

// A histogram slot's Gaussian texture and table come into an engine package as OpenEXR, which the engines import
// (none reads PFM), holding the floats of the PFM files a shader compile writes, alpha 1.
TEST(EnginePackages, HistogramTablesAreExrAndUnityFetchesTheirRowsFlipped) {
    ParseResult p = parseMaterialFile("tests/golden/materials/histogram.json");
    ASSERT_TRUE(p.material) << formatAll(p.diagnostics);
    const CompileResult shader = compile(*p.material, {});
    const CompileResult godot = compileForEngine(*p.material, Engine::Godot3, {});
    ASSERT_TRUE(shader.ok() && godot.ok()) << formatAll(godot.diagnostics);
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_histogram_exr";
    std::filesystem::create_directories(dir);
    auto texels = [&](const CompileResult& r, const std::string& name) {
        const auto f = std::find_if(r.files.begin(), r.files.end(), [&](const OutputFile& o) { return o.name == name; });
        if (f == r.files.end()) return std::vector<float>{};
        const std::filesystem::path file = dir / std::filesystem::path(name).filename();
        std::ofstream(file, std::ios::binary) << f->contents;
        return loadTexture(file, false).rgba32f;
    };
    for (const char* which : {"gaussian", "lut"}) {
        const std::vector<float> pfm = texels(shader, std::string("histogram.albedo.") + which + ".pfm");
        const std::vector<float> exr = texels(godot, std::string("godot3/histogram.albedo.") + which + ".exr");
        ASSERT_FALSE(pfm.empty()) << which;
        ASSERT_EQ(exr.size(), pfm.size()) << which << ": no EXR file, or another size";
        EXPECT_EQ(exr, pfm) << which;  // PFM's alpha reads as 1, as EXR's holds
    }
    const auto manifest =
        std::find_if(godot.files.begin(), godot.files.end(), [](const OutputFile& f) { return f.name.ends_with(".json"); });
    const nlohmann::json lut = nlohmann::json::parse(manifest->contents)["slots"][0]["histogram"]["lut"];
    EXPECT_EQ(lut["file"], "histogram.albedo.lut.exr");
    EXPECT_EQ(lut["format"]["container"], "exr");
    // Unity's too: its functions fetch the table's row h - 1 - y (it stores the bottom row first), asking its height.
    const CompileResult unity = compileForEngine(*p.material, Engine::Unity, {});
    ASSERT_TRUE(unity.ok()) << formatAll(unity.diagnostics);
    EXPECT_EQ(texels(unity, "unity/histogram.albedo.lut.exr"), texels(godot, "godot3/histogram.albedo.lut.exr"));
    const auto hlsl =
        std::find_if(unity.files.begin(), unity.files.end(), [](const OutputFile& f) { return f.name.ends_with(".hexc.hlsl"); });
    ASSERT_NE(hlsl, unity.files.end());
    EXPECT_NE(hlsl->contents.find("spvTextureSize(hexcLut_albedo"), std::string::npos);
    std::filesystem::remove_all(dir);
}

// SPIRV-Cross writes an undefined value (tiles.json's, with rotation 0) as a global without an initialiser, which
// Godot's language refuses ("Expected initialization of constant"): Godot's packages make it a constant.
TEST(EnginePackages, GodotDeclaresEveryGlobalAsAConstant) {
    for (Engine engine : {Engine::Godot3, Engine::Godot4}) {
        const std::string text = package("tiles", engine);
        EXPECT_NE(text.find("\nconst uint _"), std::string::npos) << "tiles.json's undefined value is no longer written";
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);) {
            if (!line.empty() && std::isalpha(static_cast<unsigned char>(line[0])) && line.ends_with(";")) {
                EXPECT_TRUE(line.starts_with("const ") || line.starts_with("uniform ") || line.starts_with("shader_type ")) << line;
            }
        }
    }
}

// An sRGB slot the shader decodes itself (MaterialX mode: `"decode": "shader"` in the manifest) is bound linear by
// every package (docs/bind-a-manifest.md, step 3): an sRGB hint would decode its texels a second time.
TEST(EnginePackages, ASlotTheShaderDecodesIsBoundLinear) {
    ParseResult p = parseMaterialFile("materials/rock.json");
    for (Slot& s : p.material->slots) s.hex.mode = HashMode::MaterialX;
    auto source = [&](Engine engine, const std::string& suffix) {
        CompileResult r = compileForEngine(*p.material, engine, {});
        EXPECT_TRUE(r.ok()) << formatAll(r.diagnostics);
        for (const OutputFile& f : r.files)
            if (f.name.ends_with(suffix)) return f.contents;
        ADD_FAILURE() << "no " << suffix;
        return std::string();
    };
    EXPECT_NE(source(Engine::Godot3, ".shader").find("uniform sampler2D hexcTex_albedo;"), std::string::npos);
    EXPECT_NE(source(Engine::Godot4, ".gdshader").find("uniform sampler2D hexcTex_albedo : filter_linear_mipmap"), std::string::npos);
    const std::string module = source(Engine::Threejs, ".three.js");
    const size_t start = module.find("const hexc = ") + 13;
    const nlohmann::json data = nlohmann::json::parse(module.substr(start, module.find(";\n", start) - start));
    for (const nlohmann::json& t : data["textures"]) EXPECT_EQ(t["colorspace"], "linear") << t["uniform"];
}

// The web packages' GLSL goes inside the engine's own shader: no #version, no default precision statement (it would
// change the engine's code after it), each declaration with its own precision.
TEST(EnginePackages, WebGlslHasNoHeaderAndEachDeclarationItsPrecision) {
    for (Engine engine : {Engine::Threejs, Engine::Babylon}) {
        const std::string module = package("terrain/terrain", engine);
        const size_t start = module.find("const hexc = ") + 13;
        const std::string glsl = nlohmann::json::parse(module.substr(start, module.find(";\n", start) - start))["glsl"];
        EXPECT_EQ(glsl.find("#version"), std::string::npos) << toString(engine);
        EXPECT_EQ(glsl.find("precision "), std::string::npos) << toString(engine);
        EXPECT_NE(glsl.find("uniform highp sampler2DArray hexcArr_normal;"), std::string::npos) << toString(engine);
        EXPECT_NE(glsl.find("highp vec4 hexc_albedo(highp vec2 uv"), std::string::npos) << toString(engine);
    }
}

TEST(EnginePackages, FilamentReadsMaterialParamsAndSetsTheNormalFirst) {
    const std::string text = package("rock", Engine::Filament);
    EXPECT_NE(text.find("{ type : sampler2d, name : hexcTex_albedo }"), std::string::npos);
    EXPECT_NE(text.find("materialParams_hexcTex_albedo"), std::string::npos);
    EXPECT_EQ(text.find("uniform "), std::string::npos);
    const size_t normal = text.find("material.normal = hexc_normal_normal(uv);"), prepare = text.find("prepareMaterial(material);");
    ASSERT_NE(normal, std::string::npos);
    EXPECT_LT(normal, prepare);
    EXPECT_GT(text.find("material.baseColor = hexc_albedo(uv);"), prepare);
    // matc flips v by default; hexc's uv origin alone says where uv (0, 0) is (docs/conventions.md).
    EXPECT_NE(text.find("    flipUV : false,\n"), std::string::npos);
}

TEST(EnginePackages, ASlotWithoutAnEngineInputIsReported) {
    Diagnostics d;
    const std::string text = package("rock_blend", Engine::Godot3, &d);  // `height`: no Godot input has its name
    EXPECT_NE(formatAll(d).find("warning[HX204]: /slots/2: slot `height` has no godot3 input"), std::string::npos) << formatAll(d);
    EXPECT_NE(text.find("float hexc_height(vec2 uv)"), std::string::npos);  // kept for the user to call
}

// A layered material's package (Filament's) feeds the engine its roles' blends, reports the role without an input at
// its first layer's slot. Every engine's package carries it: engine_package_paths writes the terrain's for each.
TEST(EnginePackages, ALayeredMaterialFeedsTheBlendOfEachRole) {
    ParseResult p = parseMaterialFile("materials/terrain/terrain.json");
    ASSERT_TRUE(p.material) << formatAll(p.diagnostics);
    CompileResult r = compileForEngine(*p.material, Engine::Filament, {});
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    const std::string all = formatAll(r.diagnostics);
    EXPECT_NE(all.find("warning[HX204]: /slots/2: slot `grass_height` has no filament input"), std::string::npos) << all;
    EXPECT_EQ(all.find("grass_albedo"), std::string::npos) << all;  // a layer's slot is not an engine function
    const auto shader = std::find_if(r.files.begin(), r.files.end(), [](const OutputFile& f) { return f.name == "filament/terrain.mat"; });
    ASSERT_NE(shader, r.files.end());
    EXPECT_NE(shader->contents.find("material.baseColor = hexc_albedo(uv);"), std::string::npos);
    EXPECT_NE(shader->contents.find("material.normal = hexc_normal_normal(uv);"), std::string::npos);
    EXPECT_NE(shader->contents.find("{ type : sampler2d, name : hexcTex_splat0 }"), std::string::npos);
    EXPECT_EQ(shader->contents.find("hexc_grass_albedo("), std::string::npos);
    const auto manifest = nlohmann::json::parse(std::find_if(r.files.begin(), r.files.end(), [](const OutputFile& f) {
                                                    return f.name == "filament/terrain.manifest.json";
                                                })->contents);
    EXPECT_EQ(manifest["functions"][0], nlohmann::json::parse(R"({"name": "hexc_albedo", "role": "albedo", "parameters": "vec2 uv",
                                                                   "returns": "vec4", "value": "RGBA, linear"})"));
}

// Godot 4, Unity and Unreal bind a layered role's textures as one texture array where the plan can, and a texture per
// slot where it cannot (here: `arrays` "off"); Godot 3 and Filament a texture per slot (docs/engines.md#layered-materials).
TEST(EnginePackages, ALayeredRoleIsATextureArrayWhereTheEngineBindsThem) {
    ParseResult p = parseMaterialFile("materials/terrain/terrain.json");
    ASSERT_TRUE(p.material) << formatAll(p.diagnostics);
    Material off = *p.material;
    off.layers->arrays = false;
    const std::map<Engine, std::pair<std::string, std::string>> declared = {
        {Engine::Godot4,
         {"uniform sampler2DArray hexcArr_albedo : source_color, filter_linear_mipmap, repeat_enable;",
          "uniform sampler2D hexcTex_grass_albedo : source_color, filter_linear_mipmap, repeat_enable;"}},
        {Engine::Unity, {"hexc_albedo: UV (Vector 2), hexcArr_albedo (Texture 2D Array)", "hexcTex_grass_albedo (Texture 2D)"}},
        {Engine::Unreal, {"hexcArr_albedo (Texture2DArray)", ", hexcTex_grass_albedo, "}},
        {Engine::Godot3,
         {"uniform sampler2D hexcTex_grass_albedo : hint_albedo;", "uniform sampler2D hexcTex_grass_albedo : hint_albedo;"}},
        {Engine::Filament, {"name : hexcTex_grass_albedo }", "name : hexcTex_grass_albedo }"}}};
    for (const auto& [engine, texts] : declared) {
        const std::string arrays = package(*p.material, engine), separate = package(off, engine);
        const bool binds = texts.first != texts.second;
        EXPECT_NE(arrays.find(texts.first), std::string::npos) << toString(engine) << arrays;
        EXPECT_EQ(arrays.find("hexcTex_grass_albedo") == std::string::npos, binds) << toString(engine);
        EXPECT_NE(separate.find(texts.second), std::string::npos) << toString(engine) << separate;
        EXPECT_EQ(separate.find("hexcArr_"), std::string::npos) << toString(engine);
    }
}

// Godot 3.2's shading language has no array copies or array parameters and takes `for` loops only with one increment
// (docs/engines.md#layered-materials): its package of a layered material has the weights' loops unrolled and their
// arrays made scalars, where Filament's keeps both.
TEST(EnginePackages, Godot3GetsALayeredMaterialWithoutLoopsOrArrays) {
    const std::string godot = package("terrain/terrain", Engine::Godot3), filament = package("terrain/terrain", Engine::Filament);
    for (const char* refused : {"for (", "[8]"}) {
        EXPECT_EQ(godot.find(refused), std::string::npos) << refused;
        EXPECT_NE(filament.find(refused), std::string::npos) << refused;  // what the unrolling removes
    }
    EXPECT_NE(godot.find("ALBEDO = (hexc_albedo(UV)).rgb;"), std::string::npos);
    EXPECT_NE(godot.find("NORMALMAP = hexc_normal_normal(UV) * 0.5 + 0.5;"), std::string::npos);
    EXPECT_NE(godot.find("uniform sampler2D hexcTex_splat0;"), std::string::npos);  // weights: linear, no hint_albedo
}

// The web packages read a layered role's textures as one array where a shader would (the manifest's `layers.arrays`
// says so): three.js every role (sRGB ones too), Babylon.js the linear ones only (its 2D arrays have no sRGB format),
// its sRGB albedo a texture per layer. Each array lists its layers' files, copied beside the module, in layer order.
TEST(EnginePackages, WebPackagesReadLayeredRolesAsArrays) {
    const std::string three = package("terrain/terrain", Engine::Threejs), babylon = package("terrain/terrain", Engine::Babylon);
    for (const char* array : {"sampler2DArray hexcArr_albedo;", "sampler2DArray hexcArr_normal;", "sampler2DArray hexcArr_height;"})
        EXPECT_NE(three.find(array), std::string::npos) << array;
    EXPECT_NE(three.find(R"("layers": [
        "terrain.grass_albedo.png",
        "terrain.sand_albedo.png",
        "terrain.pebbles_albedo.png",
        "terrain.snow_albedo.png"
      ],)"),
              std::string::npos);
    EXPECT_NE(babylon.find("sampler2DArray hexcArr_normal;"), std::string::npos);
    EXPECT_EQ(babylon.find("hexcArr_albedo"), std::string::npos);
    EXPECT_NE(babylon.find("sampler2D hexcTex_grass_albedo;"), std::string::npos);
}

}  // namespace

namespace {

// A slot reaches its engine input by its `role` as well as by its name; a slot no input takes is reported at the slot,
// naming it and the engine, in every engine's package.
TEST(EnginePackages, SlotsReachInputsByRoleAndTheRestAreReported) {
    ParseResult p = parseMaterial(R"({"name": "r", "slots": [
        {"name": "base", "kind": "color", "texture": "textures/rock_albedo.png", "role": "albedo"},
        {"name": "bumps", "kind": "normal", "texture": "textures/rock_normal.png"},
        {"name": "gloss", "kind": "scalar", "texture": "textures/rock_roughness.png", "role": "roughness"},
        {"name": "height", "kind": "scalar", "texture": "textures/rock_height.png"}]})",
                                  "materials/r.json");
    ASSERT_TRUE(p.material) << formatAll(p.diagnostics);
    const std::map<Engine, std::pair<std::string, std::vector<std::string>>> expected = {
        {Engine::Godot3,
         {"godot3/r.shader", {"ALBEDO = (hexc_base(UV)).rgb;", "ROUGHNESS = hexc_gloss(UV);", "NORMALMAP = hexc_bumps_normal(UV)"}}},
        {Engine::Filament, {"filament/r.mat", {"material.baseColor = hexc_base(uv);", "material.roughness = hexc_gloss(uv);"}}},
        {Engine::Threejs, {"threejs/r.three.js", {"\"call\": \"hexc_base(UV)\"", "\"role\": \"roughness\""}}},
        {Engine::Unity, {"unity/r.shader", {"surface.albedo = (hexc_base(uv, ", "surface.smoothness = 1.0 - hexc_gloss(uv, "}}},
        {Engine::Unreal,
         {"unreal/r.ush", {"Base Color <- CMOT Float 4 (UV, hexcTex_base): return hexc_base(", "Roughness <- CMOT Float 1"}}}};
    for (const auto& [engine, file] : expected) {
        CompileResult r = compileForEngine(*p.material, engine, {});
        ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
        const auto source =
            std::find_if(r.files.begin(), r.files.end(), [&name = file.first](const OutputFile& f) { return f.name == name; });
        ASSERT_NE(source, r.files.end()) << file.first;
        for (const std::string& text : file.second) EXPECT_NE(source->contents.find(text), std::string::npos) << file.first << ": " << text;
        const std::string all = formatAll(r.diagnostics);
        EXPECT_NE(all.find("materials/r.json:5:36: warning[HX204]: /slots/3: slot `height` has no " +
                           std::string(engine == Engine::Threejs ? "three.js" : toString(engine)) + " input"),
                  std::string::npos)
            << all;
        EXPECT_EQ(r.diagnostics.size(), 1u) << all;  // base and gloss reach their inputs by role
    }
}

TEST(EnginePackages, ARoleTakesItsKindOfSlot) {
    ParseResult wrong = parseMaterial(R"({"name": "r", "slots": [
        {"name": "base", "kind": "scalar", "texture": "textures/rock_height.png", "role": "albedo"}]})",
                                      "materials/r.json");
    EXPECT_NE(formatAll(wrong.diagnostics).find("/slots/0/role: role `albedo` takes a slot of kind `color`, this one is `scalar`"),
              std::string::npos)
        << formatAll(wrong.diagnostics);
    ParseResult misspelled = parseMaterial(R"({"name": "r", "slots": [
        {"name": "base", "kind": "scalar", "texture": "textures/rock_height.png", "role": "rougness"}]})",
                                           "materials/r.json");
    EXPECT_NE(formatAll(misspelled.diagnostics).find("/slots/0/role"), std::string::npos) << formatAll(misspelled.diagnostics);
    EXPECT_NE(formatAll(misspelled.diagnostics).find("roughness"), std::string::npos) << formatAll(misspelled.diagnostics);
}

}  // namespace
