// --debug's `#line` directives: each names a file, and --line-directives decides how many there are.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "hexc/compiler.h"
#include "support.h"

using namespace hexc;
using hexc::test::loadMaterial;
using hexc::test::runHexc;

namespace {

const LineDirectives kModes[] = {LineDirectives::None, LineDirectives::Functions, LineDirectives::Statements};

CompileResult compileDebug(const Material& m, LineDirectives mode) {
    CompileOptions options;
    options.debug = true;
    options.lineDirectives = mode;
    return compile(m, options);
}

// What the `#line` directives of one source say: the files they name, how many there are, and the most in one
// function body (SPIRV-Cross writes a body between a `{` and a `}` line of their own at column 0, on every target).
struct Lines {
    std::multiset<std::string> files;
    size_t count = 0, mostInAFunction = 0, functions = 0;
};

Lines linesOf(const std::string& source) {
    static const std::regex directive(R"(#line (\d+) "([^"]*)\"\s*)");
    Lines out;
    std::istringstream in(source);
    size_t inBody = 0;
    bool body = false;
    for (std::string line; std::getline(in, line);) {
        if (line == "{") body = true, inBody = 0;
        if (line == "}") body = false, ++out.functions;
        if (!line.starts_with("#line")) continue;
        std::smatch m;
        EXPECT_TRUE(std::regex_match(line, m, directive)) << "a #line that names no file: " << line;
        out.files.insert(m[2]);
        ++out.count;
        if (body) out.mostInAFunction = std::max(out.mostInAFunction, ++inBody);
    }
    return out;
}

const std::string& textOf(const CompileResult& r, const std::string& suffix) {
    for (const OutputFile& f : r.files)
        if (f.name.ends_with(suffix)) return f.contents;
    throw std::runtime_error("no output " + suffix);
}

// rock under the built-in `lit` template, on each text target and in each mode.
TEST(LineDirectives, EachModeOnEveryTextTarget) {
    const Material rock = loadMaterial("materials/rock.json");
    std::map<LineDirectives, CompileResult> results;
    for (LineDirectives mode : kModes) {
        results[mode] = compileDebug(rock, mode);
        ASSERT_TRUE(results[mode].ok()) << formatAll(results[mode].diagnostics);
    }
    for (const char* target : {".frag.hlsl", ".frag.glsl", ".frag.metal"}) {
        const Lines none = linesOf(textOf(results[LineDirectives::None], target));
        const Lines functions = linesOf(textOf(results[LineDirectives::Functions], target));
        const Lines statements = linesOf(textOf(results[LineDirectives::Statements], target));
        EXPECT_EQ(none.count, 0u) << target;
        // Functions: one before each function and one at its first statement; every file the code comes from named.
        EXPECT_EQ(functions.mostInAFunction, 1u) << target;
        EXPECT_EQ(std::set<std::string>(functions.files.begin(), functions.files.end()),
                  (std::set<std::string>{"templates/builtin/lit.glsl", "hexc/hextiling.glsl", "hexc/generated"}))
            << target;
        // ... so at most two per function: one before it, one in its body.
        EXPECT_LE(functions.count, 2 * functions.functions) << target;
        // Statements: the same files, several lines in some function, more in all.
        EXPECT_EQ(std::set<std::string>(statements.files.begin(), statements.files.end()),
                  std::set<std::string>(functions.files.begin(), functions.files.end()))
            << target;
        EXPECT_GT(statements.mostInAFunction, 1u) << target;
        EXPECT_GT(statements.count, functions.count) << target;
        std::printf("  %s: %zu functions; #line none %zu, functions %zu (at most %zu in a body), statements %zu (at most %zu)\n", target,
                    functions.functions, none.count, functions.count, functions.mostInAFunction, statements.count,
                    statements.mostInAFunction);
    }
    // GLSL declares the extension that lets `#line` name files only where it has one.
    EXPECT_EQ(textOf(results[LineDirectives::None], ".glsl").find("GL_GOOGLE_cpp_style_line_directive"), std::string::npos);
    EXPECT_NE(textOf(results[LineDirectives::Functions], ".glsl").find("GL_GOOGLE_cpp_style_line_directive"), std::string::npos);
    // The SPIR-V keeps every statement's line whatever the text targets show.
    EXPECT_EQ(textOf(results[LineDirectives::None], ".spv"), textOf(results[LineDirectives::Statements], ".spv"));
}

// A template file is named by its path as the material wrote it; a `"`, which a `#line` name cannot hold, as `'`.
TEST(LineDirectives, ATemplateFileIsNamedAsTheMaterialWroteIt) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_line_names";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "shaders");
    const std::string body =
        "#version 450\nlayout(location = 0) in vec2 v_uv;\nlayout(location = 0) out vec4 o;\n#include <hexc>\n"
        "void main() {\n    o = hexc_albedo(v_uv);\n}\n";
    for (const std::string name : {"engine.glsl", "say \"hi\".glsl"}) {
        std::ofstream(dir / "shaders" / name) << body;
        std::string escaped = name;
        if (size_t q = escaped.find('"'); q != std::string::npos) escaped = "say \\\"hi\\\".glsl";
        std::ofstream(dir / "m.json") << R"({"name": "m", "template": "shaders/)" + escaped +
                                             R"(", "slots": [{"name": "albedo", "kind": "color", "texture": ")" +
                                             std::filesystem::absolute("materials/textures/rock_albedo.png").string() + R"("}]})";
        const CompileResult r = compileDebug(loadMaterial((dir / "m.json").string()), LineDirectives::Functions);
        ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
        std::string shown = "shaders/" + name;
        std::replace(shown.begin(), shown.end(), '"', '\'');
        for (const char* target : {".hlsl", ".glsl", ".metal"}) EXPECT_EQ(linesOf(textOf(r, target)).files.count(shown), 2u) << target;
    }
}

// The option on the command line: a mode only with --debug; the shader cache and the stamps tell the modes apart.
TEST(LineDirectives, CommandLine) {
    const std::filesystem::path out = std::filesystem::temp_directory_path() / "hexc_line_cli";
    std::filesystem::remove_all(out);
    std::string err;
    EXPECT_EQ(runHexc("materials/rock.json --line-directives none -o " + out.string(), &err), 2);
    EXPECT_EQ(err, "hexc: --line-directives requires --debug (see hexc --help)\n");
    EXPECT_EQ(runHexc("materials/rock.json --debug --line-directives all -o " + out.string(), &err), 2);
    EXPECT_EQ(err, "hexc: --line-directives: all not in {none,functions,statements} (see hexc --help)\n");
    EXPECT_FALSE(std::filesystem::exists(out));
    auto lines = [&](const std::string& mode) {
        EXPECT_EQ(runHexc("materials/rock.json -q --debug" + mode + " -o " + out.string(), &err), 0) << err;
        std::ifstream in(out / "rock.frag.hlsl");
        return linesOf(std::string(std::istreambuf_iterator<char>(in), {})).count;
    };
    const size_t byDefault = lines(""), statements = lines(" --line-directives statements");
    EXPECT_EQ(lines(" --line-directives functions"), byDefault);
    EXPECT_GT(statements, byDefault);  // not up to date, nor taken from the cache, under another mode
    EXPECT_EQ(lines(" --line-directives none"), 0u);
    CompileOptions a, b;
    b.lineDirectives = LineDirectives::Statements;
    EXPECT_EQ(codeOptionsKey(a), codeOptionsKey(b));  // without --debug the mode changes nothing
    a.debug = b.debug = true;
    EXPECT_NE(codeOptionsKey(a), codeOptionsKey(b));
}

}  // namespace
