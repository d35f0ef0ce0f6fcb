// hexc bake's periodic lattice (CompileOptions::periodicRepeats) on lavapipe against the fp64 reference of the same
// lattice.
#include <gtest/gtest.h>

#include "checks.h"

namespace hexc::exec {
namespace {

constexpr int kRepeats = 4;

// A bake's view of `slot` (bakeView in compiler/cli/bake.h): st over [0, K]^2. At 128 pixels for K = 4 and tiling 4 a
// pixel spans 4 / 128 st, 8 texels of the rock's 256^2 textures: exactly mip level 3, a power of two, so lavapipe's
// piecewise-linear log2 is exact and no level blend is involved (checks.h, kMinified).
View bakeWindow(const Slot& slot, int size) { return {size, size, {0, 0, kRepeats / slot.hex.tiling[0], kRepeats / slot.hex.tiling[1]}}; }

Check bakeCheck(const Material& one, const Draw& draw) {
    const Slot& slot = one.slots[0];
    const View view = bakeWindow(slot, 128);
    const int level = deepestLevel(slot, view);
    return kindRow(slot.kind).derivative ? checkNormal(one, view, level, draw, kRepeats) : checkColor(one, view, level, draw, kRepeats);
}

Draw periodic() {
    CompileOptions options;
    options.periodicRepeats = kRepeats;
    return on(vk::ExecutedTarget::Spirv, options);
}

// hexc's shader with the periodic lattice against the reference's periodic lattice, written apart from it
// (reference/lattice.cpp, periodicTaps), within the execution tests' derived bounds: colour, scalar and normal slots.
TEST(BakeCommand, PeriodicLatticeMatchesTheReference) {
    REQUIRE_VULKAN();
    for (const char* name : {"albedo", "roughness", "normal"}) {
        const Check c = bakeCheck(slotOf(name), periodic());
        report(name, c);
        EXPECT_LE(c.worstRatio, 1.0) << name;
    }
}

// Negative control: the plain (non-periodic) lattice drawn against the periodic reference fails the same check.
TEST(BakeCommand, PlainLatticeFailsThePeriodicReference) {
    REQUIRE_VULKAN();
    const Check c = bakeCheck(slotOf("albedo"), on(vk::ExecutedTarget::Spirv));
    report("albedo, plain lattice", c);
    EXPECT_GT(c.worstRatio, 1.0);
}

}  // namespace
}  // namespace hexc::exec
