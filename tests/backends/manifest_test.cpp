// The manifest describes what the plan decided: what the shader does with each slot (kind, taps, flip, sRGB decoding,
// luma weights, height map) comes from the slot's plan, not from the material behind it.
#include <gtest/gtest.h>

#include <filesystem>

#include "backends/backends.h"
#include "plan/plan.h"
#include "support.h"

using namespace hexc;
using hexc::test::loadMaterial;

namespace {

// The settings the plan copies, changed in the material after planning: a manifest that read them from
// `SlotPlan::slot` would change with them.
Material withDecisionsChanged(Material m) {
    for (Slot& s : m.slots) {
        s.hex.taps = s.hex.taps == 1 ? 2 : 1;
        s.flipY = !s.flipY;
        s.hex.lumacoeffs = {0.5, 0.25, 0.25};
    }
    return m;
}

TEST(Manifest, ReadsThePlanNotTheMaterial) {
    size_t compared = 0;
    for (const auto& entry : std::filesystem::directory_iterator("materials")) {
        if (entry.path().extension() != ".json" || entry.path().filename() == "material.schema.json") continue;
        const Material m = loadMaterial(entry.path());
        ShaderPlan plan = planShader(m, CompileOptions{});
        ASSERT_FALSE(hasErrors(plan.diagnostics)) << entry.path() << "\n" << formatAll(plan.diagnostics);
        const nlohmann::json expected = buildManifest(m, plan, nlohmann::json::object());
        const Material changed = withDecisionsChanged(m);
        for (SlotPlan& sp : plan.slots) sp.slot = &changed.slots[size_t(sp.slot - m.slots.data())];
        EXPECT_EQ(buildManifest(changed, plan, nlohmann::json::object()).dump(1), expected.dump(1)) << entry.path();
        ++compared;
    }
    EXPECT_GE(compared, 6u);  // the JSON examples of materials/
}

// And the other way: a plan whose decisions change shows them, slot by slot.
TEST(Manifest, ShowsThePlansDecisions) {
    const Material m = loadMaterial("materials/rock.json");
    ShaderPlan plan = planShader(m, CompileOptions{});
    ASSERT_EQ(plan.slots.size(), 3u);  // albedo (colour), normal, roughness (scalar, channel r)
    SlotPlan &albedo = plan.slots[0], &normal = plan.slots[1], &roughness = plan.slots[2];
    albedo.taps = 2;
    albedo.srgb = true;
    normal.adaptive = true;
    normal.flipY = true;
    roughness.taps = 1;
    const nlohmann::json slots = buildManifest(m, plan, nlohmann::json::object())["slots"];
    EXPECT_EQ(slots[0]["hextiling"]["taps"], 2);
    EXPECT_EQ(slots[0]["decode"], "shader");
    EXPECT_EQ(slots[1]["hextiling"]["taps"], "adaptive");
    EXPECT_EQ(slots[1]["flip_y"], true);
    EXPECT_EQ(slots[1]["normal_green"], "down (DirectX)");
    EXPECT_EQ(slots[2]["hextiling"]["taps"], 1);
}

}  // namespace
