// File names and paths are the user's file system's, not validated like the names inside a material: any byte but
// NUL (and `/` within a name). Wherever hexc writes one into text another tool parses (a shader's banner, --debug's
// `#line` names, an engine package, the MaterialX export's comment, the depfile), a line break in it must not end
// the comment or string that holds it and make the rest of the name code.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "hexc/spirv.h"
#include "hostile.h"
#include "support.h"

namespace fs = std::filesystem;
using namespace hexc::test::hostile;

namespace {

// What the hostile names carry: each piece would be a line of code if a line break ended the comment before it.
constexpr const char* kMarker = "injected";

// The lines of `text` (ended by LF or CR, as C preprocessors, GLSL and HLSL compilers end them) that hold `kMarker`
// outside a `//` comment, an XML comment or a `#line` directive's name: text of a file name that became code.
std::vector<std::string> exposedLines(std::string_view text) {
    std::vector<std::string> out;
    for (size_t begin = 0; begin < text.size();) {
        const size_t end = std::min(text.find_first_of("\n\r", begin), text.size());
        const std::string_view line = text.substr(begin, end - begin);
        if (const size_t at = line.find(kMarker); at != std::string_view::npos) {
            const std::string_view before = line.substr(0, at);
            const bool held = before.find("//") != std::string_view::npos || before.find("<!--") != std::string_view::npos ||
                              line.substr(line.find_first_not_of(" \t") == std::string_view::npos ? 0 : line.find_first_not_of(" \t"))
                                  .starts_with("#line ");
            if (!held) out.emplace_back(line);
        }
        begin = end + 1;
    }
    return out;
}

std::string readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

class HostileNames : public testing::Test {
protected:
    void SetUp() override {
        // A folder of each test's own: CTest runs the tests of this fixture side by side.
        dir_ = fs::temp_directory_path() /
               ("hexc_hostile_names_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        // LF and CR (each would end a `//` comment), a quote, a backslash, `#` and `--` (which XML refuses in a
        // comment); the template's folder ends in `*`, so its path holds `*/`.
        const std::string hostile = std::string("\n#error ") + kMarker + "_lf\r#error " + kMarker + "_cr \"q\\b#--";
        const fs::path templates = dir_ / ("t" + hostile + "*");
        fs::create_directories(templates);
        fs::copy_file("templates/builtin/unlit.glsl", templates / "unlit.glsl");
        material_ = dir_ / ("m" + hostile + ".json");
        const nlohmann::json m = {
            {"name", "m"},
            {"template", templates.filename().string() + "/unlit.glsl"},
            {"slots", {{{"name", "albedo"}, {"kind", "color"}, {"texture", fs::absolute("materials/textures/rock_albedo.png").string()}}}}};
        std::ofstream(material_) << m.dump();
    }

    // `hexc MATERIAL -o DIR OPTIONS`, the material's path quoted for the shell (it holds no `'`).
    Outcome run(const fs::path& out, const std::string& options) const {
        return runBounded("'" + material_.string() + "' -o " + out.string() + " " + options);
    }

    fs::path dir_, material_;
};

// Every text file under `out`: JSON parses (its strings hold the names as they are, escaped by JSON); no line of
// any other file holds the name's text outside a comment.
void expectNothingExposed(const fs::path& out, const std::string& what) {
    size_t files = 0;
    for (const auto& e : fs::recursive_directory_iterator(out)) {
        const fs::path ext = e.path().extension();
        if (!e.is_regular_file() || ext == ".spv" || ext == ".png" || ext == ".pfm") continue;
        ++files;
        const std::string text = readAll(e.path());
        if (ext == ".json") {
            EXPECT_TRUE(nlohmann::json::accept(text)) << what << ": " << e.path().filename();
            continue;
        }
        for (const std::string& line : exposedLines(text))
            ADD_FAILURE() << what << ": " << e.path().filename() << ": code from a file name: " << line;
    }
    EXPECT_GT(files, 0u) << what;
}

// The shaders still compile as a consumer's compiler sees them: GLSL and HLSL (glslang, its HLSL front end for HLSL).
void expectShadersCompile(const fs::path& out, const std::string& what) {
    const nlohmann::json manifest = nlohmann::json::parse(readAll(out / "m.manifest.json"));
    for (const auto& e : fs::directory_iterator(out)) {
        const std::string name = e.path().filename().string(), text = readAll(e.path());
        const hexc::ShaderStage stage = name.find(".vert.") != std::string::npos ? hexc::ShaderStage::Vertex : hexc::ShaderStage::Fragment;
        hexc::SpirvResult r;
        if (name == "m.frag.glsl" || name == "m.vert.glsl")
            r = hexc::compileToSpirv(text, stage, name, hexc::SourceLanguage::OpenGlGlsl);
        else if (name == "m.frag.hlsl")
            r = hexc::compileToSpirv(text, stage, name, hexc::SourceLanguage::Hlsl, manifest["targets"]["hlsl"]["entry_point"]);
        else if (name == "m.generated.frag")
            r = hexc::compileToSpirv(text, stage, name);
        else
            continue;
        EXPECT_FALSE(r.words.empty()) << what << ": " << name << "\n" << hexc::formatAll(r.diagnostics);
    }
}

TEST_F(HostileNames, TheCheckSeesANameThatBecameCode) {
    // The negative control: the banner as hexc wrote it before file names were escaped.
    EXPECT_EQ(exposedLines("#version 450\n// Generated by hexc from m\n#error injected_lf\r#error injected_cr.json\n").size(), 2u);
    EXPECT_TRUE(
        exposedLines("// Generated by hexc from m\\n#error injected_lf\\r#error injected_cr.json\n#line 3 \"t\\n injected\"\n").empty());
}

TEST_F(HostileNames, StayInTheirCommentsInEveryOutput) {
    const struct {
        const char* options;
        bool compiled;  // whether the outputs are shaders a consumer compiles on their own
    } runs[] = {
        {"", true},
        {"--debug", true},  // `#line` directives name the template
        {"--vertex --emit-generated", true},
        {"--functions", false},
        {"--debug --functions", false},
        {"--engine godot3,godot4,filament,threejs,babylon,unity,unreal", false},
    };
    for (const auto& r : runs) {
        const fs::path out = dir_ / ("out" + std::to_string(&r - runs));
        const Outcome o = run(out, r.options);
        ASSERT_EQ(o.exit, 0) << r.options << ": " << o.err;
        expectNothingExposed(out, r.options);
        if (r.compiled) expectShadersCompile(out, r.options);
    }
    // WGSL, where its translator (built in, or Node.js and naga) is there, as for the other wgsl tests.
    std::string whyNoNaga;
    if (const std::string naga = hexc::test::nagaPrefix(&whyNoNaga, false); !naga.empty()) {
        std::string err;
        const fs::path out = dir_ / "wgsl";
        ASSERT_EQ(
            hexc::test::runHexc("'" + material_.string() + "' -o " + out.string() + " --targets wgsl", &err, bounds() + " env " + naga), 0)
            << err;
        expectNothingExposed(out, "wgsl");
    } else if (std::getenv("HEXC_REQUIRE_BROWSER")) {
        ADD_FAILURE() << "the wgsl target cannot run: " << whyNoNaga;
    }
    // MaterialX: the export's comment names the file; the document stays XML as a strict parser reads it (Python's
    // expat: no `--` in a comment, which pugixml lets pass), its comment on one line, and reads back as a material.
    const fs::path mtlx = dir_ / "m.mtlx";
    Outcome o = runBounded("export-mtlx '" + material_.string() + "' -o " + mtlx.string());
    ASSERT_EQ(o.exit, 0) << o.err;
    const std::string xml = readAll(mtlx);
    const size_t comment = xml.find("<!--");
    ASSERT_NE(comment, std::string::npos);
    EXPECT_EQ(xml.find_first_of("\n\r", comment), xml.find("-->", comment) + 3) << xml.substr(comment, 300);
    EXPECT_EQ(std::system(("python3 -c 'import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])' " + mtlx.string()).c_str()), 0);
    EXPECT_EQ(runBounded(mtlx.string() + " -o " + (dir_ / "mtlx").string() + " --list-outputs").exit, 0);
}

TEST_F(HostileNames, ADepfileRefusesWhatItCannotExpress) {
    // Make's and Ninja's depfiles have no escape for a line break: the build is refused before anything is written.
    const Outcome o = run(dir_ / "out", "--depfile " + (dir_ / "m.d").string());
    EXPECT_EQ(o.exit, 1) << o.err;
    EXPECT_NE(o.err.find("holds a line break, which no depfile can express"), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "out"));
    EXPECT_FALSE(fs::exists(dir_ / "m.d"));
}

}  // namespace
