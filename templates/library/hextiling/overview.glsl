// hexc hex-tiling library: Mikkelsen 2022, "Practical Real-Time Hex-Tiling" (JCGT 11(3)), Listings 1-10.
// Injected by hexc at the template's `#include <hexc>` line. Every name here starts with `hexc` followed
// by an upper-case letter, so it never collides with the generated per-slot functions `hexc_<slot>`.
// One file per concern in templates/library/hextiling/, assembled in this order into hexc/hextiling.glsl
// (compiler/src/CMakeLists.txt): overview (this file: shared constants and structs), lattice, masks, blends, taps,
// histogram, derivatives, dither, helpers, periodic (hexc bake's lattice); each uses only what comes before it.
//
// Folding rules. hexc injects the library piece by piece (compiler/src/codegen/pieces.h): the constants, structs and
// functions a shader reaches. A function that takes `HexcLattice l` or `HexcBlend b` is emitted per slot as
// `<function>_<slot>`, which takes neither: the slot's settings fix every field of both (codegen/codegen.cpp,
// latticeSettings and blendSettings), folded in at the source (codegen/specialise.h):
// - the fields marked "literal" (HexcLattice: rotate, transform, rotationSteps, offsetSteps, maskScale, triple,
//   aspect; HexcBlend: metric, gain, exponentInt, gainInt, taps, sharedLod, adaptive, adaptiveError, height) become
//   constants, and every branch they decide keeps only the path taken;
// - the others become the reads of the slot's parameters (rotation, rotationRange, scaleRange, offset; falloff,
//   falloffContrast, exponent, heightWidth), hexcChannel(k) for heightLuma, or the neutral constructor's value.
// So that the folding sees them: a function takes its settings as `HexcLattice l` and `HexcBlend b` and never writes
// them; a setting decides code only in an `if (...) {` block (with `} else {`), an `if (...) statement;` or a whole
// `x = c ? a : b;` or `return c ? a : b;`, whose condition compares settings and literals (==, !=, <, <=, >, >=, !,
// &&, ||; no arithmetic, no call); and a top-level item starts at column 0, a multi-line one ending with a `}` at
// column 0. tests/codegen/specialise_test.cpp (EveryExampleAndVariantFoldsWhatItsSettingsFix) holds every example and
// feature variant to it: no slot's copy keeps a settings read or a condition that reads no variable. Without
// specialisation (--no-specialise, `hexc library`) this text is the general library.
//
// Conventions: texture space is (u, v) with v down the image. A normal slot's derivative is (dH/du, dH/dy) with
// y = -v, up the image: a green-up (OpenGL) map gives it as sampled, a green-down (DirectX) map once flip_y negates
// its green. The paper's HLSL `mul(v, R)` with R = float2x2(cs, -si, si, cs) (rows) is written out as
// hexcRotateToTile (rotation by -angle), so no matrix layout convention can flip it between targets.

const float hexcPi = 3.14159265358979;
// Listing 4, Eq. 4: Rec. 601 luminance weights.
const vec4 hexcLuma = vec4(0.299, 0.587, 0.114, 0.0);

// One tap: a tile's sample point, its screen-space gradients (rotated and scaled with the tile), the tile's rotation
// and 1 / its texture scale (1 without per-tile transforms).
struct HexcTap {
    vec2 st, dx, dy;
    vec2 rot;                    // (cos, sin) of the tile's rotation angle
    float invScale;
};

// The per-pixel lattice data every slot with the same coordinate shares: Listing 1's weights and tile ids, and
// each tile's tap.
struct HexcTiles {
    vec3 w;                      // barycentric weights of the three hex tiles, sum 1
    bool scaled;                 // literal: false when every invScale is 1 (no per-tile transforms)
    vec2 dx, dy;                 // the st gradients, before any tile's transform
    ivec2 id[3];                 // integer lattice ids of the three tile centres
    HexcTap tap[3];
    ivec3 channel;               // the weights output's channel of each tile (Listing 7 for the hex mask)
};
