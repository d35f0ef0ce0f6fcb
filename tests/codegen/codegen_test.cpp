// The code generator's own rules: token expansion of the library's sections, and reading the plan alone.
#include <gtest/gtest.h>

#include <filesystem>

#include "codegen/codegen.h"
#include "common/templates.h"

using namespace hexc;

namespace {

TEST(Codegen, ExpandsTokensInOnePass) {
    EXPECT_EQ(
        expandTokens("${falloff} ${falloffcontrast}$x ${a}_y", {{"falloff", "f"}, {"falloffcontrast", "c"}, {"a", "${falloff}"}}, "t"),
        "f c$x ${falloff}_y");
}

TEST(Codegen, UnknownTokenIsAnInternalError) {
    for (const char* text : {"a ${nope} b", "a ${unterminated"}) {
        try {
            expandTokens(text, {{"name", "albedo"}}, "color.hex");
            ADD_FAILURE() << text << " was expanded";
        } catch (const CompileError& e) {
            ASSERT_EQ(e.diagnostics.size(), 1u);
            EXPECT_NE(e.diagnostics[0].message.find("internal error: section `color.hex`"), std::string::npos) << e.diagnostics[0].message;
        }
    }
}

// A kind reads the snippets of the kind its row says it is read like (`like`): that kind has every section the row
// allows, so a kind like `scalar` adds none of its own (docs/internals.md, "Add a slot kind").
TEST(Codegen, EveryKindsSnippetsAreThoseOfTheKindItIsReadLike) {
    const std::map<std::string, std::string> sections = snippetSections("slots.glsl");
    for (const SlotKindRow& row : kindRows()) {
        const std::string like(toString(row.like));
        std::vector<std::string> wanted = {like + ".hex", like + ".hex1", like + ".plain", like + ".materialx", "engine.call." + like};
        if (row.mayUseHistogram) wanted.push_back(like + ".histogram");
        if (row.mayPack) wanted.push_back(like + ".packed");
        for (const std::string& section : wanted) EXPECT_TRUE(sections.count(section)) << row.name << ": no section " << section;
    }
}

// Codegen takes every setting it emits from the plan (docs/internals.md's stage table): a plan whose slots no longer
// point at the material's generates the same code, for every example, packed or not, specialised or not. A codegen
// that still read `SlotPlan::slot` would crash or differ here.
TEST(Codegen, ReadsThePlanNotTheMaterial) {
    size_t compared = 0;
    for (const auto& entry : std::filesystem::directory_iterator("materials")) {
        if (entry.path().extension() != ".json" || entry.path().filename() == "material.schema.json") continue;
        ParseResult parsed = parseMaterialFile(entry.path());
        ASSERT_TRUE(parsed.material) << entry.path() << "\n" << formatAll(parsed.diagnostics);
        for (const bool pack : {false, true})
            for (const bool specialise : {true, false}) {
                Material m = *parsed.material;
                m.pack = pack;
                CompileOptions options;
                options.specialise = specialise;
                const ShaderPlan plan = planShader(m, options);
                ASSERT_FALSE(hasErrors(plan.diagnostics)) << entry.path() << "\n" << formatAll(plan.diagnostics);
                ShaderPlan alone = plan;
                for (SlotPlan& sp : alone.slots) sp.slot = nullptr;
                EXPECT_EQ(generateGlsl(alone), generateGlsl(plan)) << entry.path() << " pack " << pack << " specialise " << specialise;
                ++compared;
            }
    }
    EXPECT_GE(compared, 4u * 6);  // the six or more JSON examples of materials/
}

}  // namespace
