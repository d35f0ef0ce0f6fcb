// naga built into hexc (backends/naga_wasm.cpp): WGSL without Node.js, the same WGSL and the same errors as naga in
// Node.js, and a module naga cannot read, or one that would take more than naga's memory bound, as hexc's error.
// tests/wgsl/wgsl_test.py compares the two routes on every file the Tint test validates.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "backends/backends.h"
#include "backends/naga.h"
#include "codegen/codegen.h"
#include "hexc/spirv.h"
#include "plan/plan.h"
#include "support.h"

using namespace hexc;
using hexc::test::loadMaterial;
using hexc::test::readFile;
using hexc::test::runHexc;

namespace {

#ifdef HEXC_NAGA_BUILT_IN
#define REQUIRE_BUILT_IN()
#else
#define REQUIRE_BUILT_IN()                                                                                \
    if (std::getenv("HEXC_REQUIRE_BROWSER")) FAIL() << "naga is not built in (HEXC_NAGA_IN_PROCESS off)"; \
    GTEST_SKIP() << "naga is not built in (HEXC_NAGA_IN_PROCESS off)"
#endif

// rock.json's optimised fragment module and its plan, as compile() hands them to the wgsl target.
struct Module {
    ShaderPlan plan;
    std::vector<uint32_t> words;
};
const Module& rock() {
    static const Material material = loadMaterial("materials/rock.json");
    static const Module m = [] {
        Module made{planShader(material, CompileOptions{}), {}};
        made.words = optimizeSpirv(compileToSpirv(generateGlsl(made.plan), ShaderStage::Fragment, made.plan.templateName,
                                                  SourceLanguage::Glsl, made.plan.entryPoint)
                                       .words)
                         .words;
        return made;
    }();
    return m;
}

// naga by the route HEXC_NAGA asks for: `node` for Node's, unset for the built-in one.
NagaResult nagaBy(bool node, const std::vector<uint32_t>& words) {
    node ? setenv("HEXC_NAGA", "node", 1) : unsetenv("HEXC_NAGA");
    NagaResult r = nagaWgsl(words);
    unsetenv("HEXC_NAGA");
    return r;
}

}  // namespace

// With no `node` anywhere on PATH, --targets wgsl writes the WGSL, and it is the WGSL naga in Node.js writes.
TEST(NagaBuiltIn, WritesWgslWithoutNode) {
    REQUIRE_BUILT_IN();
    const std::filesystem::path out = std::filesystem::temp_directory_path() / "hexc_naga_built_in";
    std::filesystem::remove_all(out);
    std::string err;
    ASSERT_EQ(runHexc("materials/rock.json --targets wgsl --no-cache -o " + (out / "built_in").string(), &err, "PATH=/nonexistent"), 0)
        << err;
    const std::string wgsl = readFile(out / "built_in" / "rock.frag.wgsl");
    EXPECT_NE(wgsl.find("// Settings: naga-wasm 30.1.0; optimised;"), std::string::npos) << wgsl.substr(0, 400);
    EXPECT_NE(wgsl.find("@fragment"), std::string::npos);
    REQUIRE_NAGA_BY(true);
    ASSERT_EQ(runHexc("materials/rock.json --targets wgsl --no-cache -o " + (out / "node").string(), &err, naga), 0) << err;
    EXPECT_EQ(readFile(out / "node" / "rock.frag.wgsl"), wgsl);
}

// The control: one word of the module changed (its first function's result type, to an id nothing defines), and naga
// refuses it, with the message naga in Node.js gives; emitWgsl makes that hexc's error at the material's template.
TEST(NagaBuiltIn, ACorruptModuleIsNagasErrorAsInNode) {
    REQUIRE_BUILT_IN();
    Module m = rock();
    const NagaResult good = nagaBy(false, m.words);
    ASSERT_TRUE(good.wgsl) << good.error;
    constexpr uint32_t kOpFunction = 54;
    size_t at = 5;
    while (at < m.words.size() && (m.words[at] & 0xffff) != kOpFunction) at += m.words[at] >> 16;
    ASSERT_LT(at, m.words.size());
    m.words[at + 1] = 0x7fffff;
    const NagaResult bad = nagaBy(false, m.words);
    EXPECT_FALSE(bad.wgsl);
    EXPECT_FALSE(bad.unavailable);
    EXPECT_FALSE(bad.error.empty());
    try {
        emitWgsl(m.words, m.plan, CompileOptions{});
        ADD_FAILURE() << "naga translated a corrupt module";
    } catch (const CompileError& e) {
        ASSERT_EQ(e.diagnostics.size(), 1u);
        EXPECT_EQ(formatAll(e.diagnostics),
                  "templates/builtin/lit.glsl: error[HX300]: naga cannot translate the shader to WGSL: " + bad.error + "\n");
    }
    REQUIRE_NAGA_BY(true);
    setenv("HEXC_NODE_PATH", std::filesystem::absolute("tests/node/node_modules").c_str(), 1);
    EXPECT_EQ(nagaBy(true, m.words).error, bad.error);
    EXPECT_EQ(nagaBy(true, rock().words).wgsl, good.wgsl);
}

// A module bigger than naga's memory bound (256 MiB) stops naga where its allocation fails: an error, not a crash or
// an allocation of what the module asks; and the next translation, in an instance of its own, works.
TEST(NagaBuiltIn, MemoryIsBounded) {
    REQUIRE_BUILT_IN();
    std::vector<uint32_t> huge = rock().words;
    huge.resize((257u << 20) / 4);
    const NagaResult r = nagaBy(false, huge);
    EXPECT_FALSE(r.wgsl);
    EXPECT_NE(r.error.find("naga stopped"), std::string::npos) << r.error;
    EXPECT_TRUE(nagaBy(false, rock().words).wgsl);
}
