// The optimisation recipe hexc runs (optimizeSpirv) against spirv-opt's -O, which it replaces to compile faster: on
// every example, every scene variant and a set of generated materials, its SPIR-V must be valid (compile() validates a
// module before the passes only) and no bigger than -O's, in words and in the count of every opcode (OpExtInst counted
// per instruction, so a pow cannot hide behind a sqrt).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <spirv-tools/optimizer.hpp>

#include <fstream>
#include <map>

#include "codegen/codegen.h"
#include "hexc/compiler.h"
#include "hexc/scene.h"
#include "hexc/spirv.h"
#include "plan/plan.h"
#include "support.h"

using namespace hexc;
using hexc::test::loadMaterial;

namespace {

// Opcode (or "ExtInst <n>") -> how many, of a module's instructions.
std::map<std::string, size_t> opcodeCounts(const std::vector<uint32_t>& words) {
    std::map<std::string, size_t> counts;
    for (size_t at = 5; at < words.size(); at += words[at] >> 16) {
        const uint32_t opcode = words[at] & 0xffff;
        constexpr uint32_t kOpExtInst = 12;  // result type, result, set, instruction, operands
        ++counts[opcode == kOpExtInst ? "ExtInst " + std::to_string(words[at + 4]) : std::to_string(opcode)];
    }
    return counts;
}

std::vector<uint32_t> withPerformancePasses(const std::vector<uint32_t>& words) {
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_0);
    optimizer.RegisterPerformancePasses();
    std::vector<uint32_t> out;
    EXPECT_TRUE(optimizer.Run(words.data(), words.size(), &out));
    return out;
}

// hexc's recipe and -O on the material's unoptimised fragment shader (frozen first when baked, as compile() does).
void expectNoBiggerThanO(const Material& material, const CompileOptions& options) {
    SCOPED_TRACE(material.name + (options.bake ? " (baked)" : ""));
    const ShaderPlan plan = planShader(material, options);
    ASSERT_FALSE(hasErrors(plan.diagnostics)) << formatAll(plan.diagnostics);
    SpirvResult front = compileToSpirv(generateGlsl(plan), ShaderStage::Fragment, plan.templateName, SourceLanguage::Glsl, plan.entryPoint);
    ASSERT_FALSE(front.words.empty()) << formatAll(front.diagnostics);
    const std::vector<uint32_t> input = options.bake ? optimizeSpirv(front.words, true, false, false).words : front.words;
    const std::vector<uint32_t> recipe = optimizeSpirv(input).words, reference = withPerformancePasses(input);
    ASSERT_FALSE(recipe.empty());
    EXPECT_EQ(validationErrors(recipe), "");
    EXPECT_LE(recipe.size(), reference.size());
    const std::map<std::string, size_t> ours = opcodeCounts(recipe), theirs = opcodeCounts(reference);
    for (const auto& [opcode, count] : ours) {
        const size_t other = theirs.count(opcode) ? theirs.at(opcode) : 0;
        EXPECT_LE(count, other) << "opcode " << opcode;
    }
}

const char* kExamples[] = {"engine_rock", "rock", "rock_blend", "rock_normal", "rock_triplanar", "tiles", "tiles_stepped"};

TEST(Recipe, NoBiggerThanOOnEveryExample) {
    for (const char* name : kExamples)
        for (bool bake : {false, true}) {
            CompileOptions options;
            options.bake = bake;
            expectNoBiggerThanO(loadMaterial(std::string("materials/") + name + ".json"), options);
        }
}

TEST(Recipe, NoBiggerThanOOnEverySceneVariant) {
    SceneParseResult scene = parseSceneFile("materials/scenes/forest.json");
    ASSERT_TRUE(scene.scene) << formatAll(scene.diagnostics);
    for (const Variant& v : sceneVariants(*scene.scene)) expectNoBiggerThanO(v.material, {});
}

// The compiler bench's generated materials, one of each code they can have: the three batch examples under every
// combination of rotation and falloff it uses (the tiling it also varies is a uniform, which changes no code).
TEST(Recipe, NoBiggerThanOOnGeneratedMaterials) {
    for (const char* name : {"rock", "tiles", "rock_normal"})
        for (double rotation : {0.0, 0.5, 1.0})
            for (double falloff : {0.5, 0.75}) {
                const std::string file = std::string("materials/") + name + ".json";
                std::ifstream in(file);
                nlohmann::json m = nlohmann::json::parse(in);
                m["hextiling"]["rotation"] = rotation;
                m["hextiling"]["falloff"] = falloff;
                ParseResult parsed = parseMaterial(m.dump(), file);
                ASSERT_TRUE(parsed.material) << formatAll(parsed.diagnostics);
                expectNoBiggerThanO(*parsed.material, {});
            }
}

}  // namespace
