// The plan owns every decision (snippets, features, typed parameter references), codegen expands snippet tokens
// in one pass and refuses unknown ones, and the manifest names every slot's parameters per slot, with aliases
// where slots share a lattice; the bound on what a template's macros expand to.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstring>
#include <set>

#include "codegen/codegen.h"
#include "hexc/compiler.h"
#include "plan/macros.h"
#include "plan/plan.h"
#include "vk/render.h"
#include "support.h"

using namespace hexc;
using hexc::test::loadMaterial;

namespace {

Material rock() { return loadMaterial("materials/rock.json"); }

// rock.json with the normal slot on its own tiling: it no longer shares the lattice of albedo and roughness.
Material rockWithOwnNormalTiling() {
    Material m = rock();
    m.slots[1].hex.tiling = {2, 2};
    return m;
}

const ParamMember& param(const ShaderPlan& plan, ParamRef ref) {
    EXPECT_TRUE(ref.has_value());
    return plan.params.at(ref.value());
}

nlohmann::json manifestOf(const Material& material, const CompileOptions& options = {}) {
    CompileResult r = compile(material, options);
    EXPECT_TRUE(r.ok()) << formatAll(r.diagnostics);
    for (const OutputFile& f : r.files)
        if (f.name.ends_with(".manifest.json")) return nlohmann::json::parse(f.contents);
    return {};
}

// Every name an engine can set a member by, mapped to the member's name.
std::map<std::string, std::string> settableNames(const nlohmann::json& manifest) {
    std::map<std::string, std::string> names;
    for (const auto& m : manifest["parameters"]["members"]) {
        EXPECT_TRUE(names.emplace(m["name"], m["name"]).second) << m["name"];
        for (const auto& alias : m.value("aliases", nlohmann::json::array())) EXPECT_TRUE(names.emplace(alias, m["name"]).second) << alias;
    }
    return names;
}

}  // namespace

TEST(Plan, HoldsEverySnippetAndFeatureOfRock) {
    Material m = rock();
    ShaderPlan plan = planShader(m, {});
    ASSERT_FALSE(hasErrors(plan.diagnostics)) << formatAll(plan.diagnostics);
    ASSERT_EQ(plan.slots.size(), 3u);
    ASSERT_EQ(plan.lattices.size(), 1u);  // same tiling, rotation and mode: one lattice
    const LatticePlan& l = plan.lattices[0];
    EXPECT_EQ(l.section, "lattice.stable");
    EXPECT_TRUE(l.rotate);
    EXPECT_FALSE(l.transform);
    EXPECT_FALSE(l.originCell);
    EXPECT_FALSE(l.planeSharpness);
    EXPECT_EQ(param(plan, l.rotation).value, std::vector<double>{1.0});

    const char* sections[] = {"color.hex", "normal.hex", "scalar.hex"};
    const char* types[] = {"vec4", "vec2", "float"};
    for (size_t i = 0; i < 3; ++i) {
        const SlotPlan& sp = plan.slots[i];
        EXPECT_EQ(sp.slot, &m.slots[i]);
        EXPECT_EQ(sp.section, sections[i]);
        EXPECT_EQ(sp.coordinates, "uv");
        EXPECT_EQ(sp.type, types[i]);
        EXPECT_EQ(sp.lattice, 0u);
        EXPECT_EQ(sp.taps, 3);
        EXPECT_TRUE(sp.metric);
        EXPECT_EQ(sp.exponentInt, 7);  // the paper's gamma, multiplied out
        EXPECT_FALSE(sp.exponent);     // so it is no parameter
        EXPECT_FALSE(sp.heightMap);
        EXPECT_EQ(param(plan, sp.falloffContrast).name, m.slots[i].name + "_falloffcontrast");
    }
    // falloff 0.75 (k = 2) on albedo and roughness: a gain by squaring, no parameter; 0.5 on normal: no gain.
    EXPECT_TRUE(plan.slots[0].gain);
    EXPECT_EQ(plan.slots[0].gainInt, 2);
    EXPECT_FALSE(plan.slots[0].falloff);
    EXPECT_FALSE(plan.slots[1].gain);
    EXPECT_FALSE(plan.slots[1].falloff);
}

// MaterialX mode's blend applies Schlick's gain to the falloff itself: falloff 0.75 stays a parameter there.
TEST(Plan, KeepsTheFalloffOfMaterialXMode) {
    Material m = rock();
    m.slots[0].hex.mode = HashMode::MaterialX;
    ShaderPlan plan = planShader(m, {});
    EXPECT_TRUE(plan.slots[0].gain);
    EXPECT_EQ(plan.slots[0].gainInt, 0);
    EXPECT_EQ(param(plan, plan.slots[0].falloff).value, std::vector<double>{0.75});
}

TEST(Plan, LeavesOutTheFeaturesAMaterialTurnsOff) {
    Material m = rock();
    for (Slot& s : m.slots) {
        s.hex.rotation = 0;
        s.hex.falloffcontrast = 0;
        s.hex.exponent = 6.5;
    }
    ShaderPlan plan = planShader(m, {});
    ASSERT_EQ(plan.lattices.size(), 1u);
    EXPECT_FALSE(plan.lattices[0].rotate);
    EXPECT_FALSE(plan.lattices[0].rotation);
    for (const SlotPlan& sp : plan.slots) {
        EXPECT_FALSE(sp.metric);
        EXPECT_FALSE(sp.falloffContrast);
        EXPECT_EQ(sp.exponentInt, 0);
        EXPECT_EQ(param(plan, sp.exponent).value, std::vector<double>{6.5});
    }
    // Without specialisation the same material emits every feature, read from parameters.
    CompileOptions all;
    all.specialise = false;
    ShaderPlan full = planShader(m, all);
    EXPECT_TRUE(full.lattices[0].rotate);
    EXPECT_EQ(param(full, full.lattices[0].rotation).name, "albedo_rotation");
    EXPECT_EQ(param(full, full.slots[1].falloff).name, "normal_falloff");
}

// A layer's slot reads its lattice's tiles from the weights' fill, which only a role's read runs; without shared
// lattices (hexc edit's page) each computes its own, so that its function also works read alone.
TEST(Plan, ALayersSlotComputesItsOwnTilesWithoutSharedLattices) {
    Material terrain = *parseMaterialFile("materials/terrain/terrain.json").material;
    CompileOptions perSlot;
    perSlot.shareLattice = false;
    const ShaderPlan shared = planShader(terrain, {}), separate = planShader(terrain, perSlot);
    ASSERT_TRUE(shared.layers && separate.layers);
    EXPECT_FALSE(shared.layers->lattices.empty());
    EXPECT_TRUE(separate.layers->lattices.empty());
    for (const SlotPlan& sp : separate.slots) EXPECT_FALSE(sp.layerLattice) << sp.name;
}

TEST(Plan, ReferencesBakedConstantsAfterTheBlockMembers) {
    Material m = rock();
    m.slots[0].hex.splitCoordinates = true;  // per-frame origin: block members even when baking
    m.slots[0].hex.rotationSteps = 4;        // and a lattice with per-tile transforms
    CompileOptions bake;
    bake.bake = true;
    ShaderPlan plan = planShader(m, bake);
    ASSERT_EQ(plan.lattices.size(), 2u);
    const LatticePlan& split = plan.lattices[0];
    EXPECT_TRUE(split.transform);
    EXPECT_EQ(split.rotationSteps, 4);
    EXPECT_EQ(param(plan, split.originCell).name, "albedo_origin_cell");
    EXPECT_FALSE(param(plan, split.originCell).constantId);
    EXPECT_EQ(param(plan, split.tiling).name, "albedo_tiling");
    EXPECT_TRUE(param(plan, split.tiling).constantId);
    EXPECT_EQ(param(plan, split.scaleRange).name, "albedo_scalerange");
    EXPECT_EQ(param(plan, plan.lattices[1].tiling).name, "normal_tiling");
    EXPECT_EQ(param(plan, plan.slots[2].falloffContrast).name, "roughness_falloffcontrast");
    // Block members first (the reflection check relies on it).
    bool constants = false;
    for (const ParamMember& p : plan.params) {
        EXPECT_FALSE(constants && !p.constantId) << p.name;
        constants = constants || p.constantId.has_value();
    }
}

TEST(Manifest, SharedLatticeSettingsHaveEverySlotsNameAsAlias) {
    nlohmann::json manifest = manifestOf(rock());
    std::map<std::string, std::string> names = settableNames(manifest);
    for (const char* slot : {"albedo", "normal", "roughness"}) {
        EXPECT_EQ(names[std::string(slot) + "_tiling"], "albedo_tiling");
        EXPECT_EQ(names[std::string(slot) + "_rotation"], "albedo_rotation");
        EXPECT_EQ(names[std::string(slot) + "_falloffcontrast"], std::string(slot) + "_falloffcontrast");
    }
    for (const auto& m : manifest["parameters"]["members"]) {
        // The name and the aliases are exactly the reading slots' names for the setting.
        std::string setting = m["name"].get<std::string>().substr(m["slots"][0].get<std::string>().size());
        std::set<std::string> expected, got = {m["name"]};
        for (const auto& s : m["slots"]) expected.insert(s.get<std::string>() + setting);
        for (const auto& a : m.value("aliases", nlohmann::json::array())) got.insert(a.get<std::string>());
        EXPECT_EQ(got, expected) << m.dump();
    }
}

TEST(Manifest, SlotsOnTheirOwnLatticeHaveTheirOwnMembers) {
    std::map<std::string, std::string> names = settableNames(manifestOf(rockWithOwnNormalTiling()));
    EXPECT_EQ(names["albedo_tiling"], "albedo_tiling");
    EXPECT_EQ(names["roughness_tiling"], "albedo_tiling");
    EXPECT_EQ(names["normal_tiling"], "normal_tiling");
    EXPECT_EQ(names["normal_rotation"], "normal_rotation");

    CompileOptions perSlot;
    perSlot.shareLattice = false;
    nlohmann::json separate = manifestOf(rock(), perSlot);
    for (const auto& m : separate["parameters"]["members"]) EXPECT_FALSE(m.contains("aliases")) << m.dump();
    names = settableNames(separate);
    for (const char* slot : {"albedo", "normal", "roughness"})
        EXPECT_EQ(names[std::string(slot) + "_tiling"], std::string(slot) + "_tiling");
}

TEST(Manifest, AnEngineSetsASharedSettingByAnySlotsName) {
    nlohmann::json manifest = manifestOf(rock());
    size_t offset = 0;
    for (const auto& m : manifest["parameters"]["members"])
        if (m["name"] == "albedo_rotation") offset = m["offset"];
    std::vector<uint8_t> block = vk::packParameters(manifest, {{"roughness_rotation", {0.25}}});
    float rotation = 0;
    std::memcpy(&rotation, block.data() + offset, 4);
    EXPECT_EQ(rotation, 0.25f);
}

TEST(Macros, CountsTheTokensOfTheExpansion) {
    EXPECT_EQ(boundMacroExpansion("#define A x y\nA A\n").tokens, 4);
    // The argument's size times its uses, through a nested call: F(G(1)) = ((1 + 1) * (1 + 1)) is 13 tokens.
    EXPECT_EQ(boundMacroExpansion("#define G(a) (a + a)\n#define F(b) (b * b)\nF(G(1))\n").tokens, 13);
    // A macro inside its own body stays a name (C rules), comments and continuations are not tokens.
    EXPECT_EQ(boundMacroExpansion("#define A A + \\\n 1 /* 2 3 */\nA // 4\n").tokens, 3);
    // A function-like name without `(` is a plain token; #undef ends a macro.
    EXPECT_EQ(boundMacroExpansion("#define F(a) a a a\nF;\n#undef F\nF(1)\n").tokens, 6);
}

TEST(Macros, FindsTheLineWhereTheBoundIsPassed) {
    std::string source = "#define M0 1\n";
    for (int i = 1; i <= 30; ++i)
        source += "#define M" + std::to_string(i) + " M" + std::to_string(i - 1) + " M" + std::to_string(i - 1) + "\n";
    source += "M21\nM22\n";  // 2^21 tokens, then 2^22 more: 6.3 M in all
    MacroExpansion e = boundMacroExpansion(source);
    EXPECT_EQ(e.tokens, double(1 << 21) + double(1 << 22));
    EXPECT_EQ(e.line, 33);
}

// Calls as the optimiser meets them: not the names declarations define, nor built-in types' constructors.
TEST(Macros, CountsCallsNotDeclarationsOrConstructors) {
    const char* source =
        "float f(float x) { return g(x) + vec3(1.0).x + h(x) * float(2); }\n"
        "vec4 k(ivec2 c, dmat2x3 m) { if (true) { return vec4(f(1.0)); } else t(0); }\n"
        "const vec2 table[2] = vec2[2](vec2(0.0), vec2(1.0));\n"
        "void main() {\n  k(ivec2(0), dmat2x3(0.0));\n}\n";
    EXPECT_EQ(boundMacroExpansion(source).calls, 5);  // g, h, f, t, k
}
