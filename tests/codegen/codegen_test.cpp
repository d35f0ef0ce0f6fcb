// The code generator's own rules: token expansion of the library's sections.
#include <gtest/gtest.h>

#include "codegen/codegen.h"

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

}  // namespace
