// The compiler end to end: every example to every target, golden outputs, determinism, the emitted
// HLSL and GLSL re-compiled by glslang, template errors located in the template, and the CLI contract.
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
using hexc::test::runHexc;

namespace {

const char* kExamples[] = {"rock", "tiles", "rock_normal"};

std::string readFile(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

Material load(const std::string& path) {
    ParseResult r = parseMaterialFile(path);
    if (!r.material) throw std::runtime_error(formatAll(r.diagnostics));
    return *r.material;
}

CompileResult compileExample(const std::string& name, const CompileOptions& options = {}) {
    CompileResult r = compile(load("materials/" + name + ".json"), options);
    EXPECT_TRUE(r.ok()) << formatAll(r.diagnostics);
    return r;
}

const OutputFile& file(const CompileResult& r, const std::string& suffix) {
    for (const OutputFile& f : r.files)
        if (f.name.ends_with(suffix)) return f;
    throw std::runtime_error("no output ending in " + suffix);
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
    auto manifest = nlohmann::json::parse(file(r, ".manifest.json").contents);
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
        EXPECT_NE(file(r, ".hlsl").contents.find("SPIRV_Cross_Output " + name + "(SPIRV_Cross_Input stage_input)"), std::string::npos);
        EXPECT_NE(file(r, ".metal").contents.find("fragment " + name + "_out " + name + "("), std::string::npos);
        EXPECT_NE(file(r, ".glsl").contents.find("void main()"), std::string::npos);
        auto manifest = nlohmann::json::parse(file(r, ".manifest.json").contents);
        // The HLSL compiles again from the entry point the manifest names.
        SpirvResult back = compileToSpirv(file(r, ".hlsl").contents, ShaderStage::Fragment, "rock.frag.hlsl", SourceLanguage::Hlsl,
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
        SpirvResult back = compileToSpirv(file(r, ".hlsl").contents, ShaderStage::Fragment, "emitted.hlsl", SourceLanguage::Hlsl,
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
        const std::string& source = file(r, ".glsl").contents;
        EXPECT_EQ(source.substr(0, source.find('\n')), "#version " + std::to_string(v.number) + (v.es ? " es" : ""));  // then the banner
        SpirvResult back = compileToSpirv(source, ShaderStage::Fragment, "emitted.glsl", SourceLanguage::OpenGlGlsl);
        EXPECT_FALSE(back.words.empty()) << v.number << "\n" << formatAll(back.diagnostics) << source;
    }
}

INSTANTIATE_TEST_SUITE_P(Materials, Example, testing::ValuesIn(kExamples));

TEST(Compile, HlslPackOffsetsMatchTheManifest) {
    // An engine fills the block by the manifest's offsets; the HLSL cbuffer must agree byte for byte.
    CompileResult r = compileExample("rock");
    auto manifest = nlohmann::json::parse(file(r, ".manifest.json").contents);
    SpirvResult back = compileToSpirv(file(r, ".hlsl").contents, ShaderStage::Fragment, "emitted.hlsl", SourceLanguage::Hlsl, "rock_frag");
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
    CompileResult r = compile(load("materials/tiles.json"), options);
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
    Material m = load("materials/rock.json");
    m.templateName = "pbr";
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
        CompileResult r = compile(load("materials/tiles.json"), options);
        ASSERT_FALSE(r.ok()) << body;
        EXPECT_EQ(
            r.diagnostics[0].format(),
            t.string() + ": error[HX203]: a template must contain the line `#include <hexc>` exactly once (where hexc injects its code)");
    }
}

TEST(Compile, SlotsTheTemplateDoesNotReadAreLeftOutWithAWarning) {
    Material m = load("materials/rock.json");
    m.templateName = "unlit";
    CompileResult r = compile(m);
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    ASSERT_EQ(r.diagnostics.size(), 2u);
    EXPECT_EQ(r.diagnostics[0].format(),
              "materials/rock.json: warning[HX204]: slot `normal` is not read by template templates/unlit.glsl; it is left out");
    auto manifest = nlohmann::json::parse(file(r, ".manifest.json").contents);
    EXPECT_EQ(manifest["slots"].size(), 1u);
    EXPECT_EQ(manifest["targets"]["spirv"]["textures"].size(), 1u);
}

TEST(Compile, WeightsTemplateUsesTheFirstSlot) {
    Material m = load("materials/rock.json");
    m.templateName = "weights";
    CompileResult r = compile(m);
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    auto manifest = nlohmann::json::parse(file(r, ".manifest.json").contents);
    ASSERT_EQ(manifest["slots"].size(), 1u);
    EXPECT_EQ(manifest["slots"][0]["name"], "albedo");
}

TEST(Compile, TargetSubset) {
    CompileOptions options;
    options.targets = {Target::Msl, Target::Spirv};
    CompileResult r = compileExample("tiles", options);
    ASSERT_EQ(r.files.size(), 3u);
    auto manifest = nlohmann::json::parse(file(r, ".manifest.json").contents);
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
        const CompileResult a = compile(load(std::string("materials/") + name + ".json"), alone);
        const CompileResult b = compile(load(std::string("materials/") + name + ".json"), atOnce);
        EXPECT_EQ(formatAll(a.diagnostics), formatAll(b.diagnostics)) << name;
        ASSERT_EQ(a.files.size(), b.files.size()) << name;
        for (size_t i = 0; i < a.files.size(); ++i) {
            EXPECT_EQ(a.files[i].name, b.files[i].name);
            EXPECT_TRUE(a.files[i].contents == b.files[i].contents) << a.files[i].name;
        }
    }
    EXPECT_FALSE(compile(load("materials/rock.json"), noSpace).ok());
}

// The command line, run as a user would.
std::filesystem::path freshDir(const std::string& name) {
    std::filesystem::path d = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(d);
    return d;
}

TEST(Cli, WritesAllOutputsAndRunsAreByteIdentical) {
    auto a = freshDir("hexc_cli_a"), b = freshDir("hexc_cli_b");
    ASSERT_EQ(runHexc("materials/rock.json materials/tiles.json -o " + a.string()), 0);
    ASSERT_EQ(runHexc("materials/rock.json materials/tiles.json -o " + b.string()), 0);
    size_t files = 0;
    for (const auto& e : std::filesystem::directory_iterator(a)) {
        if (e.path().filename().string()[0] == '.') continue;  // incremental-build stamps
        ++files;
        EXPECT_TRUE(readFile(e.path()) == readFile(b / e.path().filename())) << e.path();
    }
    EXPECT_EQ(files, 10u);
}

TEST(Cli, BrokenMaterialWritesNothing) {
    auto out = freshDir("hexc_cli_broken");
    std::string err;
    EXPECT_EQ(runHexc("materials/rock.json materials/invalid/falloff_zero.json -o " + out.string(), &err), 1);
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_NE(err.find("materials/invalid/falloff_zero.json:6:16: error[HX106]: /hextiling/falloff:"), std::string::npos) << err;
    EXPECT_NE(err.find("nothing written"), std::string::npos);
}

TEST(Cli, UsageErrors) {
    std::string err;
    EXPECT_EQ(runHexc("materials/rock.json", &err), 2);
    EXPECT_EQ(err, "hexc: no output folder given: use -o DIR (see hexc --help)\n");
    EXPECT_EQ(runHexc("materials/rock.json -o x --targets hlsl,dxil", &err), 2);
    EXPECT_EQ(err, "hexc: --targets: dxil not in {spirv,hlsl,glsl,msl} (see hexc --help)\n");
    EXPECT_EQ(runHexc("--frobnicate", &err), 2);
    EXPECT_EQ(err, "hexc: The following argument was not expected: --frobnicate (see hexc --help)\n");
    EXPECT_EQ(runHexc("materials/rock.json -o x --hlsl-sm 52", &err), 2);
    EXPECT_EQ(err, "hexc: --hlsl-sm: `52` is not a shader model hexc emits: 50, 51, 60 ... 66 (or 5.0, 6_0 ...) (see hexc --help)\n");
    EXPECT_EQ(runHexc("materials/rock.json -o x --template lit.txt", &err), 2);
    EXPECT_EQ(err, "hexc: --template: expected a .glsl file, got lit.txt (see hexc --help)\n");
    EXPECT_EQ(runHexc("--help"), 0);
    EXPECT_EQ(runHexc("--version"), 0);
}

// CLI11 parses the usual spellings: --opt=value, -oDIR, options after the inputs, a repeatable --variant that
// takes one value each time, and generated help listing every option.
TEST(Cli, OptionSpellings) {
    std::string err;
    for (const char* spelling : {"--out=", "-o", "-o "}) {
        std::filesystem::path dir = freshDir("hexc_cli_spelling");
        EXPECT_EQ(runHexc("materials/rock.json -q --targets=hlsl,glsl " + std::string(spelling) + dir.string(), &err), 0)
            << spelling << err;
        EXPECT_TRUE(std::filesystem::exists(dir / "rock.frag.hlsl")) << spelling;
        EXPECT_TRUE(std::filesystem::exists(dir / "rock.frag.glsl")) << spelling;
        EXPECT_FALSE(std::filesystem::exists(dir / "rock.frag.spv")) << spelling;
    }
    // --variant takes one value; the next word is an input again (here a second scene-less input: an error of
    // the inputs, exit 1, not of the command line).
    EXPECT_EQ(runHexc("materials/rock.json --variant rock.lit materials/rock.json -o " + freshDir("hexc_cli_variant").string(), &err), 1);
    EXPECT_NE(err.find("--variant rock.lit: no scene given"), std::string::npos) << err;
    std::string help = hexc::test::runHexcStdout("--help");
    for (const char* option : {"--out", "--targets", "--template", "--hlsl-sm", "--glsl-version", "--msl-version", "--bake",
                               "--no-specialize", "--no-shared-lattice", "--depfile", "--variant", "--quiet", "--verbose", "--no-warnings",
                               "--force", "--jobs", "--version", "Exit codes"})
        EXPECT_NE(help.find(option), std::string::npos) << option;
}

// --version names the build (the hash the stamps use) and the shader tool chain.
TEST(Cli, VersionNamesTheBuildAndTheToolChain) {
    std::string v = hexc::test::runHexcStdout("--version");
    EXPECT_EQ(v.rfind(std::string("hexc ") + version() + " (build ", 0), 0u) << v;
    EXPECT_EQ(v.find(") (build"), std::string::npos) << v;
    for (const char* tool : {"\nglslang 1", "\nSPIRV-Tools v", "\nSPIRV-Cross "}) EXPECT_NE(v.find(tool), std::string::npos) << v;
    EXPECT_EQ(v.find("SPIRV-Cross unknown"), std::string::npos) << v;
}

TEST(Cli, MissingMaterialFile) {
    std::string err;
    EXPECT_EQ(runHexc("materials/nope.json -o " + freshDir("hexc_cli_none").string(), &err), 1);
    EXPECT_EQ(err, "materials/nope.json: error[HX100]: cannot read material file: No such file or directory\nhexc: nothing written\n");
}

TEST(Cli, MessagesSayWhatHappened) {
    std::string err;
    EXPECT_EQ(runHexc("materials -o " + freshDir("hexc_cli_dir").string(), &err), 1);
    EXPECT_EQ(err, "materials: error[HX100]: cannot read material file: is a directory\nhexc: nothing written\n");
    // An output path that is a file is refused before anything is compiled, and left as it was.
    auto file = freshDir("hexc_cli_afile");
    std::ofstream(file) << "mine";
    EXPECT_EQ(runHexc("materials/tiles.json -o " + file.string(), &err), 3);
    EXPECT_EQ(err, "hexc: cannot write to " + file.string() + ": it is a file, not a folder\nhexc: nothing written\n");
    std::ifstream in(file);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "mine");
}

// -q drops the summary but keeps warnings, --no-warnings drops them, -v says what happened to each job; a scene
// pass with its own template and no slot list leaves slots out by design, which only -v reports.
TEST(Cli, WarningsAndVerbosity) {
    std::string err;
    const std::string weights = "materials/rock.json --template templates/builtin/weights.glsl -o ";
    EXPECT_EQ(runHexc(weights + freshDir("hexc_cli_q").string() + " -q", &err), 0);
    EXPECT_NE(err.find("warning[HX204]: slot `normal` is not read"), std::string::npos) << err;
    EXPECT_EQ(err.find("compiled"), std::string::npos) << err;
    EXPECT_EQ(runHexc(weights + freshDir("hexc_cli_nw").string() + " --no-warnings", &err), 0);
    EXPECT_EQ(err.find("warning"), std::string::npos) << err;
    EXPECT_NE(err.find("hexc: 1 compiled, 0 up to date"), std::string::npos) << err;

    const std::string scene = "materials/scenes/forest.json -o " + freshDir("hexc_cli_scene").string();
    EXPECT_EQ(runHexc(scene, &err), 0);
    EXPECT_EQ(err.find("HX204"), std::string::npos) << err;
    EXPECT_EQ(runHexc(scene + " -v", &err), 0);
    EXPECT_NE(err.find("hexc: rock.weights: up to date"), std::string::npos) << err;
    EXPECT_EQ(runHexc("materials/scenes/forest.json -v -o " + freshDir("hexc_cli_scene_v").string(), &err), 0);
    EXPECT_NE(err.find("warning[HX204]: slot `normal` is not read by template templates/weights.glsl"), std::string::npos) << err;
    EXPECT_NE(err.find("hexc: rock_normal.depth: compiled (no stamp"), std::string::npos) << err;
    EXPECT_NE(err.find("hexc: tiles.depth: compiled (no stamp from an earlier build matches its inputs, options and hexc); its shader "
                       "code is identical to rock.depth's"),
              std::string::npos)
        << err;
    EXPECT_EQ(runHexc(scene + " -v -q", &err), 2);
}

// The progress line is for a terminal (here a pseudo-terminal from script(1)); a pipe or a log gets none.
TEST(Cli, ProgressOnlyOnATerminal) {
    if (std::system("command -v script > /dev/null") != 0) GTEST_SKIP() << "script(1) is not installed";
    auto log = freshDir("hexc_cli_tty.txt");
    const std::string build = std::string(HEXC_EXE) + " materials/tiles.json materials/rock.json -o " + freshDir("hexc_cli_tty").string();
    ASSERT_EQ(std::system(("script -qec '" + build + "' /dev/null > " + log.string()).c_str()), 0);
    std::ifstream in(log);
    std::string tty(std::istreambuf_iterator<char>(in), {});
    EXPECT_NE(tty.find("hexc: [2/2] compiling "), std::string::npos) << tty;
    EXPECT_NE(tty.find("\r\033[Khexc: 2 compiled"), std::string::npos) << tty;  // cleared before the summary
    std::string err;
    EXPECT_EQ(runHexc("materials/tiles.json -o " + freshDir("hexc_cli_pipe").string(), &err), 0);
    EXPECT_EQ(err.find("[1/1]"), std::string::npos) << err;
}

// Templates declare the slots they read (`// hexc slot <name> <kind> [required]`); a material that does not fit gets
// a diagnostic at its own slot instead of a glslang error inside the template.
CompileResult compileText(const std::string& material) {
    ParseResult parsed = parseMaterial(material, "materials/fit.json");
    if (!parsed.material) throw std::runtime_error(formatAll(parsed.diagnostics));
    return compile(*parsed.material);
}

TEST(TemplateFit, ASlotOfAnotherKindIsAnErrorAtItsKind) {
    CompileResult r = compileText(
        "{\"name\": \"fit\", \"template\": \"lit\",\n \"slots\": [{\"name\": \"albedo\", \"kind\": \"normal\", "
        "\"texture\": \"textures/rock_normal.png\"}]}");
    ASSERT_FALSE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u) << formatAll(r.diagnostics);
    EXPECT_EQ(r.diagnostics[0].format(),
              "materials/fit.json:2:39: error[HX208]: /slots/0/kind: template `lit` reads `albedo` as a color slot; this one is `normal`");
    EXPECT_TRUE(r.files.empty());
}

TEST(TemplateFit, ARequiredSlotThatIsMissingIsAnError) {
    CompileResult r = compileText(
        R"({"name": "fit", "template": "unlit", "slots": [{"name": "base", "kind": "color", "texture": "textures/rock_albedo.png"}]})");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(formatAll(r.diagnostics).find("/slots: template `unlit` needs a color slot named `albedo`"), std::string::npos)
        << formatAll(r.diagnostics);
    // No raw glslang output (the template's own #error) reaches the user.
    EXPECT_EQ(formatAll(r.diagnostics).find("#error"), std::string::npos) << formatAll(r.diagnostics);
}

TEST(TemplateFit, AMalformedDeclarationIsAnErrorAtItsLine) {
    std::filesystem::path templ = std::filesystem::temp_directory_path() / "hexc_fit_template.glsl";
    std::ifstream in("templates/builtin/unlit.glsl");
    std::string text(std::istreambuf_iterator<char>(in), {});
    const std::string declared = "// hexc slot albedo color required";
    size_t at = text.find(declared);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, declared.size(), "// hexc slot albedo colour");
    std::ofstream(templ) << text;
    CompileResult r = compileText(R"({"name": "fit", "template": ")" + templ.string() +
                                  R"(", "slots": [{"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png"}]})");
    ASSERT_FALSE(r.ok());
    int line = 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n'));
    ASSERT_EQ(r.diagnostics.size(), 1u) << formatAll(r.diagnostics);
    EXPECT_EQ(r.diagnostics[0].loc.file, templ.string());
    EXPECT_EQ(r.diagnostics[0].loc.line, line);
    EXPECT_NE(r.diagnostics[0].message.find("expected `// hexc slot <name> <color|scalar|normal> [required]`"), std::string::npos);
}

TEST(TemplateFit, FittingMaterialsCompileAsBefore) {
    for (const char* m : {"materials/rock.json", "materials/tiles.json", "materials/rock_normal.json"}) {
        ParseResult parsed = parseMaterialFile(m);
        ASSERT_TRUE(parsed.material) << formatAll(parsed.diagnostics);
        EXPECT_TRUE(compile(*parsed.material).ok()) << m;
    }
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
        const std::vector<uint32_t> vert = spirvWords(file(r, ".vert.spv").contents);
        EXPECT_EQ(interface(vert, false), interface(r.spirv, true));
        const std::string entry = std::string(name) + "_vert";
        EXPECT_NE(disassemble(vert).find("OpEntryPoint Vertex %" + entry), std::string::npos);
        // HLSL and OpenGL GLSL compile again; each fragment input's semantic / MSL user location is written.
        SpirvResult hlsl = compileToSpirv(file(r, ".vert.hlsl").contents, ShaderStage::Vertex, "v.hlsl", SourceLanguage::Hlsl, entry);
        EXPECT_FALSE(hlsl.words.empty()) << formatAll(hlsl.diagnostics);
        SpirvResult glsl = compileToSpirv(file(r, ".vert.glsl").contents, ShaderStage::Vertex, "v.glsl", SourceLanguage::OpenGlGlsl);
        EXPECT_FALSE(glsl.words.empty()) << formatAll(glsl.diagnostics);
        auto manifest = nlohmann::json::parse(file(r, ".manifest.json").contents);
        const auto& inputs = manifest["targets"]["hlsl"]["inputs"];
        ASSERT_EQ(manifest["vertex"]["attributes"].size(), inputs.size() + 1);
        for (const auto& in : inputs) {
            const std::string loc = std::to_string(in["location"].get<int>());
            EXPECT_NE(file(r, ".vert.hlsl").contents.find(in["name"].get<std::string>() + " : TEXCOORD" + loc), std::string::npos);
            EXPECT_NE(file(r, ".vert.metal").contents.find("[[user(locn" + loc + ")]]"), std::string::npos);
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

TEST(Cli, ShaderModelAndTargetSpellingsOtherToolsUse) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_spellings";
    for (const char* sm : {"6.0", "6_0", "60"}) {
        std::filesystem::remove_all(dir);
        std::string err;
        ASSERT_EQ(runHexc("materials/rock.json --targets hlsl,metal --hlsl-sm " + std::string(sm) + " -o " + dir.string(), &err), 0) << err;
        auto manifest = nlohmann::json::parse(readFile(dir / "rock.manifest.json"));
        EXPECT_EQ(manifest["targets"]["hlsl"]["shader_model"], "6_0") << sm;
        EXPECT_TRUE(std::filesystem::exists(dir / "rock.frag.metal"));  // `metal` is msl
        EXPECT_FALSE(std::filesystem::exists(dir / "rock.frag.spv"));
    }
    std::string err;
    EXPECT_EQ(runHexc("materials/rock.json --hlsl-sm 6.9 -o " + dir.string(), &err), 2);
    EXPECT_NE(err.find("--hlsl-sm: `6.9` is not a shader model"), std::string::npos) << err;
}

// Every text output starts with the banner: hexc's version, the material file, the settings.
TEST(Readable, EveryTextOutputSaysWhoWroteItFromWhatAndHow) {
    CompileOptions options;
    options.vertex = true;
    options.hlslShaderModel = 51;
    CompileResult r = compileExample("rock", options);
    const std::string first =
        std::string("// Generated by hexc ") + version() + " from rock.json (material rock, template templates/lit.glsl).";
    for (const OutputFile& f : r.files) {
        if (f.name.ends_with(".spv") || f.name.ends_with(".json")) continue;           // binary; JSON has no comments
        const size_t top = f.name.ends_with(".glsl") ? f.contents.find('\n') + 1 : 0;  // after GLSL's #version line
        EXPECT_EQ(f.contents.compare(top, first.size(), first), 0) << f.name << ":\n" << f.contents.substr(0, 300);
        EXPECT_EQ(withoutBanner(f.contents).find("// Generated by hexc"), std::string::npos) << f.name;
        EXPECT_NE(f.contents.find("// Settings: hlsl sm 5.1, glsl 450, msl 2.0; optimised; layout vulkan 0/0"), std::string::npos)
            << f.name;
    }
}

// --debug keeps hexc's functions by name on every target, with #line references into the library and template;
// the optimised default has neither, and keeps none of the library's function definitions.
TEST(Readable, DebugOutputsKeepHexcsFunctionsAndLines) {
    CompileOptions debug;
    debug.debug = true;
    debug.emitGenerated = true;
    CompileResult r = compileExample("rock", debug), release = compileExample("rock");
    const std::string hlsl = file(r, ".frag.hlsl").contents, glsl = file(r, ".frag.glsl").contents, msl = file(r, ".frag.metal").contents;
    for (const std::string* text : {&hlsl, &glsl, &msl}) {
        EXPECT_NE(text->find("hexc_albedo("), std::string::npos);
        EXPECT_NE(text->find("hexcAt_normal("), std::string::npos);
        EXPECT_NE(text->find("hexcColor("), std::string::npos);
        EXPECT_NE(text->find("#line 1"), std::string::npos);
        EXPECT_NE(text->find("\"hexc/hextiling.glsl\""), std::string::npos);
        EXPECT_NE(text->find("debug (unoptimised, line directives: functions)"), std::string::npos);
    }
    EXPECT_NE(hlsl.find("float4 hexcColor(Texture2D<float4> tex, SamplerState samp"), std::string::npos);
    for (const std::string& text : {file(release, ".frag.hlsl").contents, file(release, ".frag.glsl").contents}) {
        EXPECT_EQ(text.find("#line"), std::string::npos);
        EXPECT_EQ(text.find("hexcColor("), std::string::npos);
    }
    // The generated Vulkan GLSL, beside them, is what glslang compiled: it compiles again to the same SPIR-V.
    const std::string generated = file(r, ".generated.frag").contents;
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
    ASSERT_EQ(runHexc("library --target hlsl -o " + (dir / "again").string(), &err), 0) << err;
    EXPECT_EQ(readFile(dir / "again" / "hexc_hextiling.hlsl"), hlsl);
}

TEST(Library, CommandLineErrors) {
    std::string err;
    EXPECT_EQ(runHexc("library -o /tmp/hexc_library_errors", &err), 2);
    EXPECT_NE(err.find("--target is required"), std::string::npos) << err;
    EXPECT_EQ(runHexc("library --target wgsl -o /tmp/hexc_library_errors", &err), 2);
    EXPECT_NE(err.find("wgsl"), std::string::npos) << err;
    EXPECT_EQ(runHexc("library --target hlsl -o /dev/null/x", &err), 3);
    EXPECT_NE(err.find("/dev/null/x"), std::string::npos) << err;
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
    EXPECT_NE(all.find("glslang produced invalid SPIR-V"), std::string::npos) << all;
    EXPECT_NE(all.find("shade"), std::string::npos) << all;
}

// --manifest-paths: the manifest says where each input was, relative to the output folder, so a tool reading the
// manifest finds the textures; without it the manifest does not depend on where it was built.
TEST(Cli, ManifestPathsSayWhereTheInputsWere) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_manifest_paths";
    std::filesystem::remove_all(dir);
    std::string err;
    ASSERT_EQ(runHexc("materials/engine_rock.json --manifest-paths --layout materials/layouts/engine.json --hlsl-sm 51 -o " +
                          (dir / "out").string(),
                      &err),
              0)
        << err;
    const auto source = nlohmann::json::parse(readFile(dir / "out" / "engine_rock.manifest.json"))["source"];
    for (const auto& [key, path] : {std::pair{"material", "materials/engine_rock.json"},
                                    {"template", "materials/templates/engine.glsl"},
                                    {"layout", "materials/layouts/engine.json"}})
        EXPECT_TRUE(std::filesystem::equivalent(dir / "out" / source[key].get<std::string>(), path)) << key << " " << source[key];
    EXPECT_TRUE(
        std::filesystem::equivalent(dir / "out" / source["textures"]["albedo"].get<std::string>(), "materials/textures/rock_albedo.png"));
    EXPECT_EQ(source["relative_to"], "this manifest's folder");
    // The option is in the stamp: without it the manifest is written again, without "source".
    ASSERT_EQ(runHexc("materials/engine_rock.json --layout materials/layouts/engine.json --hlsl-sm 51 -o " + (dir / "out").string(), &err),
              0)
        << err;
    EXPECT_FALSE(nlohmann::json::parse(readFile(dir / "out" / "engine_rock.manifest.json")).contains("source"));
}

// The banner names the material file: renaming the file, its content unchanged, compiles again.
TEST(Cli, ARenamedMaterialFileIsNotUpToDate) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_renamed_material";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "m");
    std::filesystem::create_directory_symlink(std::filesystem::absolute("materials/textures"), dir / "m" / "textures");
    std::filesystem::copy_file("materials/rock.json", dir / "m" / "a.json");
    std::string err;
    ASSERT_EQ(runHexc((dir / "m" / "a.json").string() + " -o " + (dir / "out").string(), &err), 0) << err;
    std::filesystem::rename(dir / "m" / "a.json", dir / "m" / "b.json");
    ASSERT_EQ(runHexc((dir / "m" / "b.json").string() + " -o " + (dir / "out").string(), &err), 0) << err;
    EXPECT_NE(err.find("1 compiled, 0 up to date"), std::string::npos) << err;
    EXPECT_NE(readFile(dir / "out" / "rock.frag.hlsl").find("from b.json"), std::string::npos);
}

// --debug keeps functions that take a texture and a sampler apart: combined samplers are refused, with the reason.
TEST(Readable, DebugAndCombinedSamplersAreRefusedTogether) {
    CompileOptions options;
    options.debug = true;
    options.layout.vulkan.combined = 1;
    CompileResult r = compile(load("materials/rock.json"), options);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(formatAll(r.diagnostics).find("--debug: error[HX300]: --debug keeps hexc's functions"), std::string::npos)
        << formatAll(r.diagnostics);
    EXPECT_TRUE(r.files.empty());
}
