// The command line, run as a user would: outputs, messages, usage errors, option spellings (one spelling of the target
// option everywhere, suggestions for mistyped options) and what is up to date.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "hexc/compiler.h"
#include "hexc/engines.h"
#include "hexc/library.h"
#include "support.h"

using namespace hexc;
using hexc::test::readFile;
using hexc::test::runHexc;

namespace {

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
    // `--targets` is an alias of `--target`, whose name the message uses.
    EXPECT_EQ(runHexc("materials/rock.json -o x --targets hlsl,dxil", &err), 2);
    std::string targets;  // the target table's names (a new target adds its own)
    for (const std::string& name : targetNames()) targets += (targets.empty() ? "" : ",") + name;
    EXPECT_EQ(err, "hexc: --target: dxil not in {" + targets + "} (see hexc --help)\n");
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
                               "--no-specialise", "--no-shared-lattice", "--depfile", "--variant", "--quiet", "--verbose", "--no-warnings",
                               "--force", "--jobs", "--version", "Exit codes"})
        EXPECT_NE(help.find(option), std::string::npos) << option;
}

// The names of `names` that `help` leaves out (each must appear as a word: `msl` is not found in `mslx`).
std::vector<std::string> leftOut(const std::string& help, const std::vector<std::string>& names) {
    std::vector<std::string> out;
    const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; };
    for (const std::string& n : names) {
        bool found = false;
        for (size_t at = help.find(n); !found && at != std::string::npos; at = help.find(n, at + 1))
            found = (at == 0 || !word(help[at - 1])) && (at + n.size() == help.size() || !word(help[at + n.size()]));
        if (!found) out.push_back(n);
    }
    return out;
}

// --help lists every target, its file, every `hexc library` target and every engine from their tables.
TEST(Cli, HelpListsEveryTargetAndEngineOfTheTables) {
    const std::string help = hexc::test::runHexcStdout("--help");
    std::vector<std::string> names = targetNames();
    for (const std::string& n : targetNames()) names.push_back(shaderFileName("", *targetNamed(n)));
    for (const std::string& n : libraryTargetNames()) names.push_back(n);
    for (std::string_view n : engineNames()) names.emplace_back(n);
    EXPECT_EQ(leftOut(help, names), std::vector<std::string>{}) << help;
    // The check fails on a help that leaves a target out.
    std::string without = help;
    for (size_t at; (at = without.find("wgsl")) != std::string::npos;) without.replace(at, 4, "w-g-s-l");
    EXPECT_EQ(leftOut(without, {"wgsl"}), std::vector<std::string>{"wgsl"});
}

// The docs' rows that list the engines (the command line's, the C API's, the Python module's) name every engine of
// the table, in backticks.
TEST(Cli, DocsListEveryEngineOfTheTable) {
    std::vector<std::string> quoted;
    for (std::string_view n : engineNames()) quoted.push_back("`" + std::string(n) + "`");
    for (const auto& [file, start] : {std::pair<const char*, const char*>{"docs/cli.md", "| `--engine LIST` |"},
                                      {"docs/c-api.md", "| `engines` |"},
                                      {"docs/python.md", "| `engines` |"}}) {
        std::ifstream in(file);
        std::string row;
        while (std::getline(in, row) && !row.starts_with(start)) {
        }
        ASSERT_TRUE(row.starts_with(start)) << file;
        EXPECT_EQ(leftOut(row, quoted), std::vector<std::string>{}) << file << ": " << row;
        EXPECT_EQ(leftOut(row, {"`godot5`"}), std::vector<std::string>{"`godot5`"});  // the check fails on an engine the row lacks
    }
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

// A template whose bytes are not UTF-8 is refused at the byte, before anything is written: its comments go into the
// manifest, which is JSON (a byte 0x84 in the stage inputs' comment once stopped the compile with an exception).
TEST(Cli, ATemplateThatIsNotUtf8IsLocated) {
    const std::filesystem::path dir = freshDir("hexc_cli_utf8"), glsl = dir / "t.glsl";
    std::filesystem::create_directories(dir);
    std::string text = readFile("templates/builtin/weights.glsl");
    const size_t at = text.find("// Stage inputs:");
    ASSERT_NE(at, std::string::npos);
    text.insert(at + 3, "\x84");
    std::ofstream(glsl, std::ios::binary) << text;
    const std::string before = text.substr(0, at);
    const std::string line = std::to_string(std::count(before.begin(), before.end(), '\n') + 1);
    std::string err;
    EXPECT_EQ(runHexc("materials/rock.json --template " + glsl.string() + " -o " + (dir / "out").string(), &err), 1);
    EXPECT_NE(err.find(glsl.string() + ":" + line + ":4: error[HX201]: the template is not UTF-8 (byte 0x84)"), std::string::npos) << err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

// -q drops the summary but keeps warnings, --no-warnings drops them, -v says what happened to each job; a scene
// pass with its own template and no slot list leaves slots out by design, which only -v reports.
TEST(Cli, WarningsAndVerbosity) {
    std::string err;
    const std::string weights = "materials/rock.json --template templates/builtin/weights.glsl -o ";
    EXPECT_EQ(runHexc(weights + freshDir("hexc_cli_q").string() + " -q", &err), 0);
    EXPECT_NE(err.find("warning[HX204]: /slots/1: slot `normal` is not read"), std::string::npos) << err;
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
    EXPECT_NE(err.find("warning[HX204]: /slots/1: slot `normal` is not read by template templates/builtin/weights.glsl"), std::string::npos)
        << err;
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

// A material whose template reads none of its slots (a slot named for what it is, not for what `lit` reads) has no
// picture to show: render and preview say so at the slot, with what the template reads and what to do, exit 1 (bad
// input), before any Vulkan device is needed, and write nothing.
TEST(Cli, RenderAndPreviewOfATemplateThatReadsNoSlotSayWhatItReads) {
    const std::filesystem::path dir = freshDir("hexc_reads_no_slot");
    std::filesystem::create_directories(dir);
    std::filesystem::create_directory_symlink(std::filesystem::absolute("materials/textures"), dir / "textures");
    std::ofstream(dir / "x.json")
        << R"({"name":"x","template":"lit","slots":[{"name":"paint","texture":"textures/rock_albedo.png","kind":"color"}]})";
    const std::string expected =
        (dir / "x.json").string() +
        ":1:99: error[HX208]: /slots/0: template `templates/builtin/lit.glsl` reads none of this material's slots (`paint`), so its "
        "picture would show nothing of the material: a template reads a slot by its name (`hexc_<name>`), and this one reads "
        "`albedo` (color), `normal` (normal) and `roughness` (scalar) (rename `paint` to `albedo`, which it reads, pass "
        "--template with a template that reads `paint`, or show it alone with `hexc render --output albedo --slot paint`)\n";
    for (const char* command : {"render", "preview"}) {
        std::string err;
        EXPECT_EQ(runHexc(std::string(command) + " " + (dir / "x.json").string() + " -q -o " + (dir / "x.png").string(), &err), 1)
            << command << ": " << err;
        EXPECT_EQ(err, expected) << command;
        EXPECT_FALSE(std::filesystem::exists(dir / "x.png")) << command;
    }
    std::filesystem::remove_all(dir);
}

// The banner names the material file: renaming the file, its content unchanged, compiles again. In a folder of its own
// (mkdtemp), so that two runs of the suite at once (release and sanitizer builds) do not rename each other's file.
TEST(Cli, ARenamedMaterialFileIsNotUpToDate) {
    std::string name = (std::filesystem::temp_directory_path() / "hexc_renamed_XXXXXX").string();
    ASSERT_NE(mkdtemp(name.data()), nullptr) << name;
    const std::filesystem::path dir = name;
    std::filesystem::create_directories(dir / "m");
    std::filesystem::create_directory_symlink(std::filesystem::absolute("materials/textures"), dir / "m" / "textures");
    std::filesystem::copy_file("materials/rock.json", dir / "m" / "a.json");
    std::string err;
    ASSERT_EQ(runHexc((dir / "m" / "a.json").string() + " -o " + (dir / "out").string(), &err), 0) << err;
    std::filesystem::rename(dir / "m" / "a.json", dir / "m" / "b.json");
    ASSERT_EQ(runHexc((dir / "m" / "b.json").string() + " -o " + (dir / "out").string(), &err), 0) << err;
    EXPECT_NE(err.find("1 compiled, 0 up to date"), std::string::npos) << err;
    EXPECT_NE(readFile(dir / "out" / "rock.frag.hlsl").find("from b.json"), std::string::npos);
    std::filesystem::remove_all(dir);
}

// --target and --targets are one option in compile mode, as in render and library.
TEST(Cli, TargetAndTargetsAreOneOption) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_target_spelling";
    std::filesystem::remove_all(dir);
    std::string err;
    ASSERT_EQ(runHexc("materials/rock.json -q --no-cache --target hlsl -o " + (dir / "a").string(), &err), 0) << err;
    ASSERT_EQ(runHexc("materials/rock.json -q --no-cache --targets hlsl,msl -o " + (dir / "b").string(), &err), 0) << err;
    EXPECT_TRUE(std::filesystem::exists(dir / "a" / "rock.frag.hlsl"));
    EXPECT_FALSE(std::filesystem::exists(dir / "a" / "rock.frag.spv"));
    EXPECT_TRUE(std::filesystem::exists(dir / "b" / "rock.frag.metal"));
    EXPECT_EQ(runHexc("library --targets glsl -o " + (dir / "lib").string(), &err), 0) << err;
    EXPECT_TRUE(std::filesystem::exists(dir / "lib" / "hexc_hextiling.glsl"));
}

// An unknown option names the closest known one of the same command; a word far from all of them gets no guess.
TEST(Cli, UnknownOptionsGetADidYouMean) {
    std::string err;
    EXPECT_EQ(runHexc("materials/rock.json -o /tmp/hexc_never --vertx", &err), 2);
    EXPECT_EQ(err, "hexc: The following argument was not expected: --vertx; did you mean `--vertex`? (see hexc --help)\n");
    EXPECT_EQ(runHexc("render materials/rock.json -o /tmp/x.png --uv-rec=0,0,1,1", &err), 2);
    EXPECT_EQ(err, "hexc: The following argument was not expected: --uv-rec=0,0,1,1; did you mean `--uv-rect`? (see hexc render --help)\n");
    EXPECT_EQ(runHexc("preview materials/rock.json -o /tmp/x.png --encodng srgb", &err), 2);
    EXPECT_EQ(err,
              "hexc: The following arguments were not expected: srgb --encodng; did you mean `--encoding`? (see hexc preview --help)\n");
    EXPECT_EQ(runHexc("materials/rock.json -o /tmp/hexc_never --frobnicate", &err), 2);
    EXPECT_EQ(err, "hexc: The following argument was not expected: --frobnicate (see hexc --help)\n");
    EXPECT_FALSE(std::filesystem::exists("/tmp/hexc_never"));
}

// A run's diagnostics come sorted by position in their file, whatever order the checks found them in (the parser
// reports unknown keys in key order: `zeta` before... `alpha`).
TEST(Cli, DiagnosticsAreSortedByPosition) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_sorted";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "m.json") << "{\"name\": \"m\", \"zeta\": 1,\n \"slots\": [],\n \"alpha\": 2}\n";
    std::string err;
    EXPECT_EQ(runHexc((dir / "m.json").string() + " -o " + (dir / "out").string(), &err), 1);
    const std::string file = (dir / "m.json").string();
    const size_t zeta = err.find(file + ":1:15: error[HX103]: /zeta"), alpha = err.find(file + ":3:2: error[HX103]: /alpha");
    ASSERT_NE(zeta, std::string::npos) << err;
    ASSERT_NE(alpha, std::string::npos) << err;
    EXPECT_LT(zeta, alpha) << err;
}

// A template that calls `hexc_rougness` reads no slot `roughness`: the warning that the slot is left out points at
// the call and suggests the slot's function, beside glslang's error for the undefined function.
TEST(Cli, ATemplateTypoNamesTheSlotItMeant) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_template_typo";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "t.glsl") << "#version 450\n#include <hexc>\nlayout(location = 0) in vec2 v_uv;\n"
                                     "layout(location = 0) out vec4 o_color;\n"
                                     "void main() { o_color = hexc_albedo(v_uv) * hexc_rougness(v_uv); }\n";
    std::ofstream(dir / "m.json") << R"({"name": "m", "template": "t.glsl", "slots": [
        {"name": "albedo", "kind": "color", "texture": ")"
                                  << std::filesystem::absolute("materials/textures/rock_albedo.png").string() << R"("},
        {"name": "roughness", "kind": "scalar", "texture": ")"
                                  << std::filesystem::absolute("materials/textures/rock_roughness.png").string() << R"("}]})";
    std::string err;
    EXPECT_EQ(runHexc((dir / "m.json").string() + " -o " + (dir / "out").string(), &err), 1);
    const std::string templ = (dir / "t.glsl").string();
    EXPECT_NE(err.find(templ + ":5:45: warning[HX204]: slot `roughness` is not read by template " + templ +
                       "; it is left out; the template calls `hexc_rougness`, which no slot defines (did you mean `hexc_roughness`?)\n"),
              std::string::npos)
        << err;
}

// A material with an error of its own and a template it does not fit: both in one run, in position order.
TEST(Cli, TemplateFitErrorsComeWithTheMaterialsOwn) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_template_fit_at_once";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "t.glsl") << "#version 450\n// hexc slot albedo normal\n#include <hexc>\nlayout(location = 0) in vec2 v_uv;\n"
                                     "layout(location = 0) out vec4 o_color;\n"
                                     "void main() { o_color = vec4(hexc_albedo(v_uv), 0.0, 1.0); }\n";
    std::ofstream(dir / "m.json") << R"({"name": "m", "template": "t.glsl", "slots": [
        {"name": "albedo", "kind": "color", "hextiling": {"falloff": 2}, "texture": ")"
                                  << std::filesystem::absolute("materials/textures/rock_albedo.png").string() << R"("}]})";
    std::string err;
    EXPECT_EQ(runHexc((dir / "m.json").string() + " -o " + (dir / "out").string(), &err), 1);
    const std::string m = (dir / "m.json").string();
    EXPECT_EQ(err, m + ":2:36: error[HX208]: /slots/0/kind: template `" + (dir / "t.glsl").string() +
                       "` reads `albedo` as a normal slot; this one is `color`\n" + m +
                       ":2:70: error[HX106]: /slots/0/hextiling/falloff: expected a number in [0.000001, 0.999999] (0.5 = off), got 2\n"
                       "hexc: nothing written\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

// The library for hand-written shaders carries its settings' documentation on every text target: each struct's
// comment, and each field's default (the neutral constructor's value) and meaning, which says when a pow is left in.
TEST(Cli, TheLibraryDocumentsItsSettings) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_library_docs";
    std::filesystem::remove_all(dir);
    std::string err;
    ASSERT_EQ(runHexc("library --target hlsl,glsl,msl -o " + dir.string(), &err), 0) << err;
    for (const char* name : {"hexc_hextiling.hlsl", "hexc_hextiling.glsl", "hexc_hextiling.metal"}) {
        std::ifstream in(dir / name);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_NE(
            text.find("    int exponentInt;  // = 0; literal: > 0, gamma is this whole number (multiplied out); 0: a pow per pixel\n"),
            std::string::npos)
            << name;
        EXPECT_NE(
            text.find("// How a slot weighs its tiles' samples, filled by each generated slot function from hexcBlend() (the neutral\n"),
            std::string::npos)
            << name;
        EXPECT_NE(text.find("  // = 0.5; r of Eq. 5 / Listing 8\n"), std::string::npos) << name;  // falloff
    }
}

}  // namespace

// Running naga in Node.js (HEXC_NAGA=node, or a build without naga built in) without Node.js on PATH, the wgsl target
// fails with what to install and writes nothing; every other target works.
TEST(Cli, WgslWithoutNodeSaysWhatToInstall) {
    const auto out = std::filesystem::temp_directory_path() / "hexc_wgsl_without_node";
    std::filesystem::remove_all(out);
    std::string err;
    const std::string noNode = "HEXC_NAGA=node PATH=/nonexistent";
    EXPECT_EQ(runHexc("materials/rock.json -o " + out.string() + " --targets wgsl,spirv", &err, noNode), 1);
    EXPECT_NE(err.find("error[HX300]: cannot run `node`"), std::string::npos) << err;
    EXPECT_NE(err.find("npm install naga-wasm@30.1.0"), std::string::npos) << err;
    EXPECT_FALSE(std::filesystem::exists(out / "rock.frag.spv"));
    EXPECT_EQ(runHexc("materials/rock.json -o " + out.string(), &err, noNode), 0) << err;
    for (const char* file : {"rock.frag.spv", "rock.frag.hlsl", "rock.frag.glsl", "rock.frag.metal"})
        EXPECT_TRUE(std::filesystem::exists(out / file)) << file;
}

// What WGSL does not have is refused at the template line that declares it, before naga is asked (so without Node).
TEST(Cli, WgslRefusesCombinedSamplersAndPushConstantsWhereDeclared) {
    const auto out = std::filesystem::temp_directory_path() / "hexc_wgsl_refused";
    std::string err;
    EXPECT_EQ(runHexc("materials/engine_rock.json -o " + out.string() + " --targets wgsl", &err, "PATH=/nonexistent"), 1);
    EXPECT_NE(err.find("templates/engine.glsl:15:30: error[HX300]: the wgsl target cannot translate the template's `shadowMap`: a "
                       "combined image sampler"),
              std::string::npos)
        << err;
    EXPECT_NE(err.find("templates/engine.glsl:20:23: error[HX300]: the wgsl target cannot translate the template's `Push`: a "
                       "push-constant block"),
              std::string::npos)
        << err;
}
