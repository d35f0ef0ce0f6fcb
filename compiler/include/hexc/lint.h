#pragma once
// Texture checks (docs/lint.md): what hex-tiling needs of a texture's content and no shader can fix. A normal map's
// green convention, inferred from its data; its average tilt; whether a texture tiles. `hexc lint` prints them, and
// a compile reports each failed check as a warning (HX130-HX133) at the slot.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "hexc/budgets.h"
#include "hexc/diagnostics.h"
#include "hexc/image.h"
#include "hexc/material.h"

namespace hexc {

// The checks a slot's `lint_skip` may name: HX130, HX131 and HX132.
inline const std::vector<std::string> kLintChecks = {"green", "tilt", "seam"};

// The thresholds, derived in docs/lint.md from generated maps (tests/textures/lint_test.cpp) and the repository's.
struct LintLimits {
    // The declared green convention's normalised curl (in [0, sqrt(2)]) over the flipped one's, past which the
    // declaration is wrong: read right, the generated and repository maps curl at most 0.14 times the flipped reading,
    // read wrong at least 8.6 times; 2 leaves a margin of 4 on the side of a missed warning and 14 on a false one.
    static constexpr double kCurlRatio = 2.0;
    // ... and its curl is at least this: read right they curl at most 0.098, read wrong at least 0.59 (0.25 is about
    // their geometric mean). Below it both readings are nearly curl-free (a height field that varies along one axis,
    // a flat map) and the data cannot tell the conventions apart.
    static constexpr double kCurlFloor = 0.25;
    // The average normal's lean, in degrees: 8-bit rounding alone (128 for 0) leans a flat map 0.32 degrees, and no
    // generated or repository map leans more than 0.14.
    static constexpr double kTiltDegrees = 2.0;
    // The wrap-around edge's difference over its neighbour boundaries': seamless textures read at most 1.66, crops of
    // longer-period noise at least 4.72 (geometric mean 2.8, rounded down to find seams sooner).
    static constexpr double kSeamRatio = 2.5;
    // The smallest side the checks measure (the seam's median needs interior boundaries on both sides of the edge).
    static constexpr int kMinSide = 4;
};

// What it holds per texel: the decoded texture (up to 16 bytes) and the normal map's slopes (8).
inline constexpr TexelBudget kLintBudget{4096, "the texture checks", "they hold up to 24 bytes a texel"};

// A texture's figures. A check that does not apply (not a normal map) or could not run leaves its figures unset.
struct TextureFigures {
    int width = 0, height = 0;
    std::string skipped;    // why nothing was measured (too small, over the budget, not decodable); empty when measured
    int64_t nonFinite = 0;  // texels whose read channels are NaN or infinite; the other checks are then not run
    std::array<int, 2> firstNonFinite{0, 0};
    std::optional<double> curlDeclared, curlOther;  // normal maps: normalised curl, green as declared and flipped
    std::optional<double> tiltDegrees;              // normal maps: the lean of the average slope
    std::array<double, 2> meanSlope{0, 0};          // (dh/dx, dh/dy) per unit of the map's normals, y down the rows
    std::optional<std::array<double, 2>> seam;      // across the left/right and top/bottom edges, interior = 1
};

// Measures a decoded texture as a slot of `kind` reads it: `channel` for a scalar, `flipY` for a normal map (green
// down); `channels` the file's channel count (a two-channel normal map's z is reconstructed).
TextureFigures measureTexture(const Texture& texture, SlotKind kind, int channel, bool flipY, int channels);

// The figures of a slot's texture (decoded from Slot::file), or why it was not measured.
TextureFigures measureSlot(const Slot& slot);

// A slot's failed checks as warnings (HX130 green, HX131 tilt, HX132 seam, HX133 non-finite texels) at `at` and
// `path`, less those its `lint_skip` names.
Diagnostics lintWarnings(const Slot& slot, const TextureFigures& figures, const SourceLoc& at, const std::string& path);

// A figure as the checks print it, with `digits` decimals.
std::string figure(double v, int digits);

// Every slot's warnings (what a compile reports).
Diagnostics lintMaterial(const Material& material);

}  // namespace hexc
