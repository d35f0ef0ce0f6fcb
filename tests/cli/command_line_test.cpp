// The command line as a user types it: one spelling of the target option everywhere, suggestions for mistyped
// options.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support.h"

namespace hexc {
namespace {

using hexc::test::runHexc;

// --target and --targets are one option in compile mode, as in render and library.
TEST(CommandLine, TargetAndTargetsAreOneOption) {
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
TEST(CommandLine, UnknownOptionsGetADidYouMean) {
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
TEST(CommandLine, DiagnosticsAreSortedByPosition) {
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
TEST(CommandLine, ATemplateTypoNamesTheSlotItMeant) {
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
TEST(CommandLine, TemplateFitErrorsComeWithTheMaterialsOwn) {
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
TEST(CommandLine, TheLibraryDocumentsItsSettings) {
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
}  // namespace hexc
