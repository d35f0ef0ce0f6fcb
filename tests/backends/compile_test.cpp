// The compiler end to end: every example to every target, determinism, the emitted HLSL and GLSL re-compiled by
// glslang, template errors located in the template, the vertex stage, readable outputs and the library files.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <spirv_cross.hpp>

#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <tuple>
#include <fstream>
#include <sstream>

#include "hexc/compiler.h"
#include "hexc/spirv.h"
#include "support.h"

using namespace hexc;
using hexc::test::loadMaterial;
using hexc::test::outputFile;
using hexc::test::readFile;
using hexc::test::runHexc;

namespace {

const char* kExamples[] = {"rock", "tiles", "rock_normal"};

CompileResult compileExample(const std::string& name, const CompileOptions& options = {}) {
    CompileResult r = compile(loadMaterial("materials/" + name + ".json"), options);
    EXPECT_TRUE(r.ok()) << formatAll(r.diagnostics);
    return r;
}

class Example : public testing::TestWithParam<const char*> {};

TEST_P(Example, WritesEveryTargetAndAManifest) {
    CompileResult r = compileExample(GetParam());
    std::string n = GetParam();
    std::vector<std::string> names;
    for (const OutputFile& f : r.files) names.push_back(f.name);
    EXPECT_EQ(names,
              (std::vector<std::string>{n + ".frag.glsl", n + ".frag.hlsl", n + ".frag.metal", n + ".frag.spv", n + ".manifest.json"}));
    for (const OutputFile& f : r.files) EXPECT_GT(f.contents.size(), 500u) << f.name;
    auto manifest = nlohmann::json::parse(outputFile(r, ".manifest.json").contents);
    EXPECT_EQ(manifest["material"], n);
    for (const char* t : {"spirv", "hlsl", "glsl", "msl"}) EXPECT_TRUE(manifest["targets"].contains(t)) << t;
    // Named after the material on every target OpenGL allows, so materials can share one metallib or HLSL library.
    for (const char* t : {"spirv", "hlsl", "msl"}) EXPECT_EQ(manifest["targets"][t]["entry_point"], n + "_frag") << t;
    EXPECT_EQ(manifest["targets"]["glsl"]["entry_point"], "main");
    EXPECT_EQ(manifest["targets"]["hlsl"]["params"]["register"], "b0");
}

TEST(EntryPoint, EveryTargetDefinesTheNameTheManifestGives) {
    for (const std::string& entry : {std::string(), std::string("terrainPS")}) {
        CompileOptions options;
        options.entryPoint = entry;
        CompileResult r = compileExample("rock", options);
        ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
        const std::string name = entry.empty() ? "rock_frag" : entry;
        EXPECT_NE(disassemble(r.spirv).find("OpEntryPoint Fragment %" + name + " \"" + name + "\""), std::string::npos) << name;
        EXPECT_NE(outputFile(r, ".hlsl").contents.find("SPIRV_Cross_Output " + name + "(SPIRV_Cross_Input stage_input)"),
                  std::string::npos);
        EXPECT_NE(outputFile(r, ".metal").contents.find("fragment " + name + "_out " + name + "("), std::string::npos);
        EXPECT_NE(outputFile(r, ".glsl").contents.find("void main()"), std::string::npos);
        auto manifest = nlohmann::json::parse(outputFile(r, ".manifest.json").contents);
        // The HLSL compiles again from the entry point the manifest names.
        SpirvResult back = compileToSpirv(outputFile(r, ".hlsl").contents, ShaderStage::Fragment, "rock.frag.hlsl", SourceLanguage::Hlsl,
                                          manifest["targets"]["hlsl"]["entry_point"]);
        EXPECT_FALSE(back.words.empty()) << formatAll(back.diagnostics);
    }
}

TEST(EntryPoint, DefaultNamesAreIdentifiersAndBadOnesAreRefused) {
    EXPECT_EQ(defaultEntryPoint("rock"), "rock_frag");
    EXPECT_EQ(defaultEntryPoint("rock-2.depth"), "rock_2_depth_frag");
    EXPECT_EQ(defaultEntryPoint("2rock"), "m2rock_frag");
    for (const char* bad : {"", "2x", "gl_Main", "a-b", "float", "main0", "__x"}) EXPECT_FALSE(isEntryPointName(bad)) << bad;
    for (const char* good : {"main", "rock_frag", "PSMain", "_x"}) EXPECT_TRUE(isEntryPointName(good)) << good;
    std::string err;
    EXPECT_EQ(runHexc("materials/rock.json -o /tmp/hexc_entry_bad --entry 2x", &err), 2);
    EXPECT_NE(err.find("expected an identifier"), std::string::npos) << err;
}

TEST_P(Example, IsDeterministic) {
    CompileResult a = compileExample(GetParam());
    CompileResult b = compileExample(GetParam());
    ASSERT_EQ(a.files.size(), b.files.size());
    for (size_t i = 0; i < a.files.size(); ++i) EXPECT_TRUE(a.files[i].contents == b.files[i].contents) << a.files[i].name;
}

TEST_P(Example, EmittedHlslCompilesWithGlslangHlslFrontEnd) {
    for (uint32_t sm : {50u, 60u}) {
        CompileOptions options;
        options.hlslShaderModel = sm;
        CompileResult r = compileExample(GetParam(), options);
        SpirvResult back = compileToSpirv(outputFile(r, ".hlsl").contents, ShaderStage::Fragment, "emitted.hlsl", SourceLanguage::Hlsl,
                                          std::string(GetParam()) + "_frag");
        ASSERT_FALSE(back.words.empty()) << "SM " << sm << "\n" << formatAll(back.diagnostics);
        EXPECT_FALSE(optimizeSpirv(back.words, false, true).words.empty());
    }
}

TEST_P(Example, EmittedGlslCompilesWithGlslang) {
    struct Version {
        uint32_t number;
        bool es;
    };
    for (Version v : {Version{460, false}, Version{450, false}, Version{330, false}, Version{310, true}, Version{300, true}}) {
        CompileOptions options;
        options.glslVersion = v.number;
        options.glslEs = v.es;
        CompileResult r = compileExample(GetParam(), options);
        const std::string& source = outputFile(r, ".glsl").contents;
        EXPECT_EQ(source.substr(0, source.find('\n')), "#version " + std::to_string(v.number) + (v.es ? " es" : ""));  // then the banner
        SpirvResult back = compileToSpirv(source, ShaderStage::Fragment, "emitted.glsl", SourceLanguage::OpenGlGlsl);
        EXPECT_FALSE(back.words.empty()) << v.number << "\n" << formatAll(back.diagnostics) << source;
    }
}

INSTANTIATE_TEST_SUITE_P(Materials, Example, testing::ValuesIn(kExamples));

TEST(Compile, HlslPackOffsetsMatchTheManifest) {
    // An engine fills the block by the manifest's offsets; the HLSL cbuffer must agree byte for byte.
    CompileResult r = compileExample("rock");
    auto manifest = nlohmann::json::parse(outputFile(r, ".manifest.json").contents);
    SpirvResult back =
        compileToSpirv(outputFile(r, ".hlsl").contents, ShaderStage::Fragment, "emitted.hlsl", SourceLanguage::Hlsl, "rock_frag");
    ASSERT_FALSE(back.words.empty());
    spirv_cross::Compiler c(back.words);
    auto ubos = c.get_shader_resources().uniform_buffers;
    ASSERT_EQ(ubos.size(), 1u);
    EXPECT_EQ(c.get_decoration(ubos[0].id, spv::DecorationBinding), 0u);
    const auto& type = c.get_type(ubos[0].base_type_id);
    const auto& members = manifest["parameters"]["members"];
    ASSERT_EQ(type.member_types.size(), members.size());
    for (uint32_t i = 0; i < members.size(); ++i) EXPECT_EQ(c.type_struct_member_offset(type, i), members[i]["offset"].get<uint32_t>());
    // tiling (vec2) and rotation of the shared lattice; albedo falloffcontrast; normal falloffcontrast; roughness
    // falloffcontrast (falloff 0.75 and exponent 7 are multiplied out): 24 bytes, rounded up to 16.
    EXPECT_EQ(manifest["parameters"]["size"], 32);
}

TEST(Compile, OneSamplerServesEverySlot) {
    CompileResult r = compileExample("rock");
    spirv_cross::Compiler c(r.spirv);
    auto res = c.get_shader_resources();
    EXPECT_EQ(res.separate_samplers.size(), 1u);
    EXPECT_EQ(res.separate_images.size(), 3u);
    for (const auto& img : res.separate_images) EXPECT_GE(c.get_decoration(img.id, spv::DecorationBinding), 2u);
}

TEST(Compile, TemplateErrorsPointIntoTheTemplate) {
    std::filesystem::path t = std::filesystem::temp_directory_path() / "hexc_bad_template.glsl";
    std::ofstream(t) << "#version 450\nlayout(location = 0) in vec2 v_uv;\nlayout(location = 0) out vec4 o;\n#include <hexc>\n"
                        "void main() {\n    o = hexc_albedo(v_uv) + undefined_thing;\n}\n";
    CompileOptions options;
    options.templateFile = t;
    CompileResult r = compile(loadMaterial("materials/tiles.json"), options);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.files.empty());
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(r.diagnostics[0].loc.file, t.string());
    EXPECT_EQ(r.diagnostics[0].loc.line, 6);
    EXPECT_NE(r.diagnostics[0].message.find("undefined_thing"), std::string::npos) << r.diagnostics[0].message;
}

// A library user may build a Material in code, skipping the parser's template check: compile() still answers
// with a diagnostic, not an exception.
TEST(Compile, UnknownBuiltinTemplateInACodeBuiltMaterialIsADiagnostic) {
    Material m = loadMaterial("materials/rock.json");
    m.templ = TemplateRef::builtin("pbr");
    CompileResult r;
    ASSERT_NO_THROW(r = compile(m));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.files.empty());
    EXPECT_NE(formatAll(r.diagnostics).find("no built-in template `pbr`"), std::string::npos) << formatAll(r.diagnostics);
}

TEST(Compile, TemplateWithoutInjectionPointIsRejected) {
    std::filesystem::path t = std::filesystem::temp_directory_path() / "hexc_no_include.glsl";
    // None, two on adjacent lines (CRLF), and one only inside a longer line: each is refused.
    for (const char* body : {"", "#include <hexc>\r\n#include <hexc>\r\n", "// #include <hexc>\n"}) {
        std::ofstream(t) << "#version 450\n" << body << "layout(location = 0) out vec4 o;\nvoid main() { o = vec4(1.0); }\n";
        CompileOptions options;
        options.templateFile = t;
        CompileResult r = compile(loadMaterial("materials/tiles.json"), options);
        ASSERT_FALSE(r.ok()) << body;
        EXPECT_EQ(
            r.diagnostics[0].format(),
            t.string() + ": error[HX203]: a template must contain the line `#include <hexc>` exactly once (where hexc injects its code)");
    }
}

TEST(Compile, SlotsTheTemplateDoesNotReadAreLeftOutWithAWarning) {
    Material m = loadMaterial("materials/rock.json");
    m.templ = TemplateRef::builtin("unlit");
    CompileResult r = compile(m);
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    ASSERT_EQ(r.diagnostics.size(), 2u);
    EXPECT_EQ(r.diagnostics[0].format(),
              "materials/rock.json:20:15: warning[HX204]: /slots/1: slot `normal` is not read by template templates/builtin/unlit.glsl; it "
              "is left out");
    auto manifest = nlohmann::json::parse(outputFile(r, ".manifest.json").contents);
    EXPECT_EQ(manifest["slots"].size(), 1u);
    EXPECT_EQ(manifest["targets"]["spirv"]["textures"].size(), 1u);
}

TEST(Compile, WeightsTemplateUsesTheFirstSlot) {
    Material m = loadMaterial("materials/rock.json");
    m.templ = TemplateRef::builtin("weights");
    CompileResult r = compile(m);
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    auto manifest = nlohmann::json::parse(outputFile(r, ".manifest.json").contents);
    ASSERT_EQ(manifest["slots"].size(), 1u);
    EXPECT_EQ(manifest["slots"][0]["name"], "albedo");
}

TEST(Compile, TargetSubset) {
    CompileOptions options;
    options.targets = {Target::Msl, Target::Spirv};
    CompileResult r = compileExample("tiles", options);
    ASSERT_EQ(r.files.size(), 3u);
    auto manifest = nlohmann::json::parse(outputFile(r, ".manifest.json").contents);
    EXPECT_EQ(manifest["targets"].size(), 2u);
}

// The HLSL, GLSL and MSL targets emitted at once (each on a thread) give the files and diagnostics of one at a time:
// every example, and a compile whose HLSL target fails (a register space shader model 5.0 does not have).
TEST(Compile, TargetsEmittedAtOnceMatchOneAtATime) {
    CompileOptions noSpace;
    noSpace.hlslShaderModel = 50;
    noSpace.layout.hlsl.space = 1;
    for (const auto& [name, base] : {std::pair{"rock", CompileOptions{}}, std::pair{"tiles", CompileOptions{}},
                                     std::pair{"rock_normal", CompileOptions{}}, std::pair{"rock", noSpace}}) {
        CompileOptions alone = base, atOnce = base;
        alone.concurrentTargets = false;
        atOnce.concurrentTargets = true;
        const CompileResult a = compile(loadMaterial(std::string("materials/") + name + ".json"), alone);
        const CompileResult b = compile(loadMaterial(std::string("materials/") + name + ".json"), atOnce);
        EXPECT_EQ(formatAll(a.diagnostics), formatAll(b.diagnostics)) << name;
        ASSERT_EQ(a.files.size(), b.files.size()) << name;
        for (size_t i = 0; i < a.files.size(); ++i) {
            EXPECT_EQ(a.files[i].name, b.files[i].name);
            EXPECT_TRUE(a.files[i].contents == b.files[i].contents) << a.files[i].name;
        }
    }
    EXPECT_FALSE(compile(loadMaterial("materials/rock.json"), noSpace).ok());
}

}  // namespace

namespace {

// (location, SPIR-V type id's vector size and base type) of each user stage variable, sorted.
std::set<std::tuple<uint32_t, uint32_t, int>> interface(const std::vector<uint32_t>& spirv, bool inputs) {
    spirv_cross::Compiler c(spirv);
    std::set<std::tuple<uint32_t, uint32_t, int>> out;
    auto res = c.get_shader_resources();
    for (const auto& r : inputs ? res.stage_inputs : res.stage_outputs) {
        const auto& type = c.get_type(r.type_id);
        out.emplace(c.get_decoration(r.id, spv::DecorationLocation), type.vecsize, int(type.basetype));
    }
    return out;
}

}  // namespace

TEST(Vertex, FeedsEveryFragmentInputOnEveryTarget) {
    for (const char* name : {"rock", "rock_triplanar", "engine_rock"}) {
        SCOPED_TRACE(name);
        CompileOptions options;
        options.vertex = true;
        CompileResult r = compileExample(name, options);
        ASSERT_EQ(r.files.size(), 9u);
        const std::vector<uint32_t> vert = spirvWords(outputFile(r, ".vert.spv").contents);
        EXPECT_EQ(interface(vert, false), interface(r.spirv, true));
        const std::string entry = std::string(name) + "_vert";
        EXPECT_NE(disassemble(vert).find("OpEntryPoint Vertex %" + entry), std::string::npos);
        // HLSL and OpenGL GLSL compile again; each fragment input's semantic / MSL user location is written.
        SpirvResult hlsl = compileToSpirv(outputFile(r, ".vert.hlsl").contents, ShaderStage::Vertex, "v.hlsl", SourceLanguage::Hlsl, entry);
        EXPECT_FALSE(hlsl.words.empty()) << formatAll(hlsl.diagnostics);
        SpirvResult glsl = compileToSpirv(outputFile(r, ".vert.glsl").contents, ShaderStage::Vertex, "v.glsl", SourceLanguage::OpenGlGlsl);
        EXPECT_FALSE(glsl.words.empty()) << formatAll(glsl.diagnostics);
        auto manifest = nlohmann::json::parse(outputFile(r, ".manifest.json").contents);
        const auto& inputs = manifest["targets"]["hlsl"]["inputs"];
        ASSERT_EQ(manifest["vertex"]["attributes"].size(), inputs.size() + 1);
        for (const auto& in : inputs) {
            const std::string loc = std::to_string(in["location"].get<int>());
            EXPECT_NE(outputFile(r, ".vert.hlsl").contents.find(in["name"].get<std::string>() + " : TEXCOORD" + loc), std::string::npos);
            EXPECT_NE(outputFile(r, ".vert.metal").contents.find("[[user(locn" + loc + ")]]"), std::string::npos);
        }
        EXPECT_EQ(manifest["vertex"]["msl"]["entry_point"], entry);
        EXPECT_EQ(manifest["vertex"]["glsl"]["file"], std::string(name) + ".vert.glsl");
    }
}

TEST(Vertex, CommandLineWritesDeclaresAndRemovesIt) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_vertex_cli";
    std::filesystem::remove_all(dir);
    std::string err;
    ASSERT_EQ(runHexc("materials/rock.json --vertex -o " + dir.string() + " --depfile " + (dir / "rock.d").string(), &err), 0) << err;
    for (const char* ext : {"spv", "hlsl", "glsl", "metal"}) EXPECT_TRUE(std::filesystem::exists(dir / (std::string("rock.vert.") + ext)));
    EXPECT_NE(readFile(dir / "rock.d").find("rock.vert.metal"), std::string::npos);
    // Without --vertex the stamp no longer matches, and the vertex files hexc wrote are removed.
    ASSERT_EQ(runHexc("materials/rock.json -o " + dir.string(), &err), 0) << err;
    EXPECT_FALSE(std::filesystem::exists(dir / "rock.vert.spv"));
    EXPECT_TRUE(std::filesystem::exists(dir / "rock.frag.spv"));
}

// Every text output starts with the banner: hexc's version, the material file, the settings.
TEST(Readable, EveryTextOutputSaysWhoWroteItFromWhatAndHow) {
    CompileOptions options;
    options.vertex = true;
    options.hlslShaderModel = 51;
    CompileResult r = compileExample("rock", options);
    const std::string first =
        std::string("// Generated by hexc ") + version() + " from rock.json (material rock, template templates/builtin/lit.glsl).";
    for (const OutputFile& f : r.files) {
        if (f.name.ends_with(".spv") || f.name.ends_with(".json")) continue;           // binary; JSON has no comments
        const size_t top = f.name.ends_with(".glsl") ? f.contents.find('\n') + 1 : 0;  // after GLSL's #version line
        EXPECT_EQ(f.contents.compare(top, first.size(), first), 0) << f.name << ":\n" << f.contents.substr(0, 300);
        EXPECT_EQ(withoutBanner(f.contents).find("// Generated by hexc"), std::string::npos) << f.name;
        EXPECT_NE(f.contents.find("// Settings: hlsl sm 5.1, glsl 450, msl 2.0; optimised; layout vulkan 0/0"), std::string::npos)
            << f.name;
    }
}

// --debug keeps hexc's functions by name on every target, with #line references into the library and template: each
// slot's, with its settings folded in (`<function>_<slot>`); the optimised default has neither, and keeps none of the
// library's function definitions.
TEST(Readable, DebugOutputsKeepHexcsFunctionsAndLines) {
    CompileOptions debug;
    debug.debug = true;
    debug.emitGenerated = true;
    CompileResult r = compileExample("rock", debug), release = compileExample("rock");
    const std::string hlsl = outputFile(r, ".frag.hlsl").contents, glsl = outputFile(r, ".frag.glsl").contents,
                      msl = outputFile(r, ".frag.metal").contents;
    for (const std::string* text : {&hlsl, &glsl, &msl}) {
        EXPECT_NE(text->find("hexc_albedo("), std::string::npos);
        EXPECT_NE(text->find("hexcAt_normal("), std::string::npos);
        EXPECT_NE(text->find("hexcColor_albedo("), std::string::npos);
        EXPECT_NE(text->find("hexcDeriv_normal("), std::string::npos);
        EXPECT_NE(text->find("#line 1"), std::string::npos);
        EXPECT_NE(text->find("\"hexc/hextiling.glsl\""), std::string::npos);
        EXPECT_NE(text->find("debug (unoptimised, line directives: functions)"), std::string::npos);
    }
    EXPECT_NE(hlsl.find("float4 hexcColor_albedo(Texture2D<float4> tex, SamplerState samp"), std::string::npos);
    for (const std::string& text : {outputFile(release, ".frag.hlsl").contents, outputFile(release, ".frag.glsl").contents}) {
        EXPECT_EQ(text.find("#line"), std::string::npos);
        EXPECT_EQ(text.find("hexcColor_albedo("), std::string::npos);
    }
    // The generated Vulkan GLSL, beside them, is what glslang compiled: it compiles again to the same SPIR-V.
    const std::string generated = outputFile(r, ".generated.frag").contents;
    EXPECT_EQ(withoutBanner(generated), r.glsl);
    SpirvResult again = compileToSpirv(generated, ShaderStage::Fragment, "rock.generated.frag", SourceLanguage::Glsl, "rock_frag", {},
                                       "rock.generated.frag");
    EXPECT_FALSE(again.words.empty()) << formatAll(again.diagnostics);
}

TEST(Readable, DebugAndGeneratedFromTheCommandLine) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_debug_cli";
    std::filesystem::remove_all(dir);
    std::string err;
    ASSERT_EQ(runHexc("materials/rock.json --debug --emit-generated -o " + dir.string(), &err), 0) << err;
    EXPECT_NE(readFile(dir / "rock.frag.hlsl").find("hexc_albedo("), std::string::npos);
    EXPECT_TRUE(std::filesystem::exists(dir / "rock.generated.frag"));
    // The options are part of the stamp: without them the outputs are compiled again, optimised.
    ASSERT_EQ(runHexc("materials/rock.json -o " + dir.string(), &err), 0) << err;
    EXPECT_EQ(readFile(dir / "rock.frag.hlsl").find("hexc_albedo("), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir / "rock.generated.frag"));
}

// GLSL ES 3.00 is checked by glslang's ES 3.00 rules before it is compiled as ES 3.10: what 3.10 added is refused.
TEST(Compile, GlslEs300IsCheckedAsEs300) {
    const std::string body =
        "precision highp float;\nlayout(location = 0) out vec4 c;\nvoid main() { c = vec4(float(bitfieldExtract(7u, 0, 2))); }\n";
    EXPECT_FALSE(compileToSpirv("#version 310 es\n" + body, ShaderStage::Fragment, "f.glsl", SourceLanguage::OpenGlGlsl).words.empty());
    SpirvResult es300 = compileToSpirv("#version 300 es\n" + body, ShaderStage::Fragment, "f.glsl", SourceLanguage::OpenGlGlsl);
    EXPECT_TRUE(es300.words.empty());
    EXPECT_NE(formatAll(es300.diagnostics).find("f.glsl:4:0: error[HX205]: 'bitfieldExtract'"), std::string::npos)
        << formatAll(es300.diagnostics);
}

// `hexc library`: one include file per target, the same bytes every run; every public function on every target
// with as many parameters as in the GLSL it comes from (OpenGL GLSL: a texture and its sampler are one parameter).
TEST(Library, WritesAnIncludeFilePerTarget) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_library";
    std::filesystem::remove_all(dir);
    std::string err;
    ASSERT_EQ(runHexc("library --target hlsl,glsl --target metal,spirv-asm -o " + dir.string(), &err), 0) << err;
    const std::map<std::string, std::string> signatures = {
        {"hexcColor",
         "(Texture2D<float4> tex, SamplerState samp, HexcTiles t, HexcBlend b, float4 luma, Texture2D<float4> heightTex, out float3 "
         "weights)"},
        {"hexcDeriv",
         "(Texture2D<float4> tex, SamplerState samp, HexcTiles t, HexcBlend b, bool flipY, Texture2D<float4> heightTex, out float3 "
         "weights)"},
        {"hexcTilesStable", "(float2 st, float2 dSTdx, float2 dSTdy, int2 cell, HexcLattice l)"}};
    const std::string hlsl = readFile(dir / "hexc_hextiling.hlsl"), glsl = readFile(dir / "hexc_hextiling.glsl");
    const std::string msl = readFile(dir / "hexc_hextiling.metal"), spvasm = readFile(dir / "hexc_hextiling.spvasm");
    for (const auto& [name, parameters] : signatures) EXPECT_NE(hlsl.find(name + parameters + "\n{"), std::string::npos) << name;
    EXPECT_NE(glsl.find("vec4 hexcColor(HexcTiles t, HexcBlend b, vec4 luma, out vec3 weights, sampler2D tex, sampler2D heightTex)"),
              std::string::npos);
    EXPECT_NE(msl.find("float4 hexcColor(texture2d<float> tex, sampler samp, thread const HexcTiles& t"), std::string::npos);
    for (const char* name : {"hexcLattice()", "hexcBlend()", "hexcTilesPaper(", "hexcTilesChecker(", "hexcTilesNoise(", "hexcColor1(",
                             "hexcDeriv1(", "hexcDerivToNormal(", "hexcChannel("})
        for (const std::string* text : {&hlsl, &glsl, &msl}) EXPECT_NE(text->find(name), std::string::npos) << name;
    // The entry point that keeps them and its resources are cut away; nothing of a material is left.
    for (const std::string* text : {&hlsl, &glsl, &msl}) {
        EXPECT_EQ(text->find("hexcLib"), std::string::npos);
        EXPECT_EQ(text->find("main"), std::string::npos);
        EXPECT_EQ(text->find("#version"), std::string::npos);
    }
    EXPECT_NE(spvasm.find("OpFunction"), std::string::npos);
    // The banner names the library's source, the folder of its parts (each file's own banner, its first two lines),
    // and what wrote the file from SPIR-V.
    for (const std::string* text : {&hlsl, &glsl, &msl})
        EXPECT_NE(text->substr(0, text->find("Do not edit"))
                      .find("\n// templates/library/hextiling/ (its parts, joined in order) through "
                            "glslang and SPIRV-Cross."),
                  std::string::npos)
            << text->substr(0, 200);
    EXPECT_NE(spvasm.find("\n; templates/library/hextiling/ (its parts, joined in order) through glslang and SPIRV-Tools' disassembler."),
              std::string::npos)
        << spvasm.substr(0, 200);
    ASSERT_EQ(runHexc("library --target hlsl -o " + (dir / "again").string(), &err), 0) << err;
    EXPECT_EQ(readFile(dir / "again" / "hexc_hextiling.hlsl"), hlsl);
}

// Each library file is an include: it compiles on its own under a consumer's empty main, and declares no resource (a
// stray global such as an unused `uniform sampler2D _3133;` is refused by Filament's matc and by Godot).
TEST(Library, EachFileCompilesAloneAndDeclaresNoResource) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_library_alone";
    std::filesystem::remove_all(dir);
    std::string err;
    ASSERT_EQ(runHexc("library --target hlsl,glsl,msl -o " + dir.string(), &err), 0) << err;
    const std::string glsl = readFile(dir / "hexc_hextiling.glsl"), hlsl = readFile(dir / "hexc_hextiling.hlsl");
    for (const std::string& line : {std::string("\nuniform "), std::string("\nlayout(")})
        EXPECT_EQ(glsl.find(line), std::string::npos) << line;
    for (const char* global : {"\nTexture2D", "\nSamplerState", "\ncbuffer"}) EXPECT_EQ(hlsl.find(global), std::string::npos) << global;
    for (const char* global : {"\ntexture2d", "\nsampler "})
        EXPECT_EQ(readFile(dir / "hexc_hextiling.metal").find(global), std::string::npos) << global;
    SpirvResult g = compileToSpirv("#version 450\n" + glsl + "\nvoid main() {}\n", ShaderStage::Fragment, "hexc_hextiling.glsl",
                                   SourceLanguage::OpenGlGlsl);
    EXPECT_FALSE(g.words.empty()) << formatAll(g.diagnostics);
    SpirvResult h = compileToSpirv(hlsl + "\nfloat4 consumer() : SV_Target { return 0.0f; }\n", ShaderStage::Fragment,
                                   "hexc_hextiling.hlsl", SourceLanguage::Hlsl, "consumer");
    EXPECT_FALSE(h.words.empty()) << formatAll(h.diagnostics);
}

TEST(Library, CommandLineErrors) {
    std::string err;
    EXPECT_EQ(runHexc("library -o /tmp/hexc_library_errors", &err), 2);
    EXPECT_NE(err.find("--target is required"), std::string::npos) << err;
    // Running naga in Node.js without Node.js, the wgsl library says what to install and writes nothing.
    EXPECT_EQ(runHexc("library --target wgsl,hlsl -o /tmp/hexc_library_errors/wgsl", &err, "HEXC_NAGA=node PATH=/nonexistent"), 1);
    EXPECT_NE(err.find("error[HX300]: cannot run `node`"), std::string::npos) << err;
    EXPECT_NE(err.find("npm install naga-wasm@30.1.0"), std::string::npos) << err;
    EXPECT_FALSE(std::filesystem::exists("/tmp/hexc_library_errors/wgsl"));
    EXPECT_EQ(runHexc("library --target hlsl -o /dev/null/x", &err), 3);
    EXPECT_NE(err.find("/dev/null/x"), std::string::npos) << err;
}

// WGSL's library through naga: the public functions under their names (naga appends `_` to a name ending in a digit),
// each struct's documentation, no entry point, stage variable or resource of its own, and a module naga validates.
TEST(Library, WgslIsAModuleOfTheFunctions) {
    REQUIRE_NAGA();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_library_wgsl";
    std::filesystem::remove_all(dir);
    std::string err;
    ASSERT_EQ(runHexc("library --target wgsl -o " + dir.string(), &err, naga), 0) << err;
    const std::string wgsl = readFile(dir / "hexc_hextiling.wgsl");
    EXPECT_NE(wgsl.find("through glslang and naga. Do not edit."), std::string::npos);
    EXPECT_NE(wgsl.find("fn hexcColor(tex_7: texture_2d<f32>, samp_7: sampler, t_7: ptr<function, HexcTiles>"), std::string::npos);
    for (const char* name : {"fn hexcLattice(", "fn hexcBlend(", "fn hexcTilesPaper(", "fn hexcTilesChecker(", "fn hexcTilesNoise(",
                             "fn hexcColor1_(", "fn hexcDeriv1_(", "fn hexcDeriv(", "fn hexcDerivToNormal(", "fn hexcChannel("})
        EXPECT_NE(wgsl.find(name), std::string::npos) << name;
    EXPECT_NE(wgsl.find("    rotation: f32,  // = 0.0; "), std::string::npos) << wgsl.substr(0, 1200);
    for (const char* cut : {"hexcLib", "@fragment", "var<private>", "@group", "fn main"})
        EXPECT_EQ(wgsl.find(cut), std::string::npos) << cut;
    EXPECT_EQ(std::system((naga + " node tests/backends/wgsl_check.mjs " + (dir / "hexc_hextiling.wgsl").string()).c_str()), 0);
}

// Modules are validated without friendly names (a fifth of a compile); a failure is reported with them.
TEST(Compile, AnInvalidModuleIsReportedWithNames) {
    SpirvResult front = compileToSpirv("#version 450\nlayout(location = 0) out vec4 shade;\nvoid main() { shade = vec4(1.0); }\n",
                                       ShaderStage::Fragment, "tiny.frag");
    ASSERT_FALSE(front.words.empty()) << formatAll(front.diagnostics);
    EXPECT_FALSE(optimizeSpirv(front.words).words.empty());
    std::vector<uint32_t> broken = front.words;
    for (size_t at = 5; at < broken.size(); at += broken[at] >> 16)
        if ((broken[at] & 0xffff) == 62) std::swap(broken[at + 1], broken[at + 2]);  // OpStore: pointer and object swapped
    SpirvResult r = optimizeSpirv(broken);
    EXPECT_TRUE(r.words.empty());
    const std::string all = formatAll(r.diagnostics);
    EXPECT_NE(all.find("invalid SPIR-V before optimisation"), std::string::npos) << all;
    EXPECT_NE(all.find("shade"), std::string::npos) << all;
}

// --debug keeps functions that take a texture and a sampler apart: combined samplers are refused, with the reason.
TEST(Readable, DebugAndCombinedSamplersAreRefusedTogether) {
    CompileOptions options;
    options.debug = true;
    options.layout.vulkan.combined = 1;
    CompileResult r = compile(loadMaterial("materials/rock.json"), options);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(formatAll(r.diagnostics).find("--debug: error[HX300]: --debug keeps hexc's functions"), std::string::npos)
        << formatAll(r.diagnostics);
    EXPECT_TRUE(r.files.empty());
}
