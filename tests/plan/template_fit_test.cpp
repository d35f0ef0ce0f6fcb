// Templates declare the slots they read (`// hexc slot <name> <kind> [required]`); a material that does not fit gets
// a diagnostic at its own slot instead of a glslang error inside the template.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "hexc/compiler.h"

using namespace hexc;

namespace {

// A material given as JSON text, as if read from materials/fit.json, compiled.
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
