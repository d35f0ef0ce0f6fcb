// hexc hex-tiling library: Mikkelsen 2022, "Practical Real-Time Hex-Tiling" (JCGT 11(3)), Listings 1-10.
// Injected by hexc at the template's `#include <hexc>` line. Every name here starts with `hexc` followed
// by an upper-case letter, so it never collides with the generated per-slot functions `hexc_<slot>`.
//
// hexc injects it piece by piece (compiler/src/codegen/pieces.h): the constants, structs and functions a shader
// reaches, each function in the form a slot's settings make of it. The settings hexc fixes (the fields marked
// "literal" below, e.g. l.rotate, b.exponentInt) are folded into a copy of each function that reads them,
// `<function>_<slot>`, with only the branches they take (codegen/specialise.h), and the others become the reads of
// the slot's parameters, so that the copy takes neither settings struct; without specialisation
// (--no-specialise, `hexc library`) this text is the general library. So that the folding can see them, a function
// takes its settings as `HexcLattice l` and `HexcBlend b` and never writes them; a setting decides code in an
// `if (...) {` block (with `} else {`), an `if (...) statement;` or a whole `x = c ? a : b;` or `return c ? a : b;`;
// and a top-level item starts at column 0, a multi-line one ending with a `}` at column 0.
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

// Listing 1, from skewed lattice coordinates: barycentric weights and the three tile ids.
void hexcTriangle(vec2 skewed, out vec3 w, out ivec2 id[3]) {
    ivec2 baseId = ivec2(floor(skewed));
    vec3 temp = vec3(skewed - floor(skewed), 0.0);
    temp.z = 1.0 - temp.x - temp.y;
    float s = step(0.0, -temp.z);
    float s2 = 2.0 * s - 1.0;
    w = vec3(-temp.z * s2, s - temp.y * s2, s - temp.x * s2);
    int si = int(s);
    id[0] = baseId + ivec2(si, si);
    id[1] = baseId + ivec2(si, 1 - si);
    id[2] = baseId + ivec2(1 - si, si);
}

// Listing 1: st *= 2 sqrt(3), then skew into the simplex grid with rows (1, -1/sqrt(3)) and (0, 2/sqrt(3)).
void hexcTriangleGrid(vec2 st, out vec3 w, out ivec2 id[3]) {
    st *= 2.0 * sqrt(3.0);
    hexcTriangle(vec2(st.x - 0.57735027 * st.y, 1.15470054 * st.y), w, id);
}

// Listing 2: the paper's per-tile offset, fract(sin(M p) * 43758.5453) with M rows (127.1, 311.7), (269.5, 183.3).
vec2 hexcHashPaper(ivec2 id) {
    vec2 p = vec2(id);
    vec2 r = vec2(dot(vec2(127.1, 311.7), p), dot(vec2(269.5, 183.3), p));
    return fract(sin(r) * 43758.5453);
}

// Listing 5: tile centre in st space; the inverse skew has rows (1, 1/2) and (0, sqrt(3)/2).
vec2 hexcTileCentre(ivec2 id) {
    return vec2(float(id.x) + 0.5 * float(id.y), float(id.y) / 1.15470054) / (2.0 * sqrt(3.0));
}

// Listing 6: the paper's per-tile rotation angle in (-pi, pi], scaled by rotStrength; returns (cos, sin).
vec2 hexcRotationPaper(ivec2 id, float rotStrength) {
    float angle = float(abs(id.x * id.y) + abs(id.x + id.y)) + hexcPi;
    // The angle is positive, so HLSL fmod and GLSL mod agree here; the paper's `< 0` branch never runs.
    angle = mod(angle, 2.0 * hexcPi);
    if (angle > hexcPi) angle -= 2.0 * hexcPi;
    angle *= rotStrength;
    return vec2(cos(angle), sin(angle));
}

// Listing 7: the channel each hex tile keeps across triangles, so the weights output shows one colour per tile.
// `%` on negative integers is undefined in GLSL and target-dependent elsewhere, so the remainder is
// taken of a non-negative value.
ivec3 hexcHexChannels(ivec2 v1, ivec2 v3) {
    int d = v1.x - v1.y;
    int a = abs(d) % 3;
    int i1 = (d < 0 && a != 0) ? 3 - a : a;
    int vh = i1 < 2 ? i1 + 1 : 0;
    int vl = i1 > 0 ? i1 - 1 : 2;
    return ivec3(i1, v1.x < v3.x ? vl : vh, v1.x < v3.x ? vh : vl);
}

// The weights output: tile i's weight in channel t.channel[i].
vec3 hexcShowWeights(vec3 W, ivec3 channel) {
    return W.x * vec3(equal(ivec3(0, 1, 2), ivec3(channel.x))) + W.y * vec3(equal(ivec3(0, 1, 2), ivec3(channel.y))) +
           W.z * vec3(equal(ivec3(0, 1, 2), ivec3(channel.z)));
}

// The unit vector picking channel c (0 = r ... 3 = a): a scalar map's falloff metric, a height slot's height.
vec4 hexcChannel(int c) {
    // Selects of constants rather than a vector comparison: with a literal c, the optimiser folds them.
    return c == 0 ? vec4(1.0, 0.0, 0.0, 0.0) : c == 1 ? vec4(0.0, 1.0, 0.0, 0.0) : c == 2 ? vec4(0.0, 0.0, 1.0, 0.0) : vec4(0.0, 0.0, 0.0, 1.0);
}

// mul(v, R): into the tile's rotated frame (by -angle).
vec2 hexcRotateToTile(vec2 v, vec2 cs) {
    return vec2(v.x * cs.x + v.y * cs.y, -v.x * cs.y + v.y * cs.x);
}

// A derivative sampled in the tile's frame back to st space. The tile reads h(M uv + c) with M = R(-angle), so by the
// chain rule the (u, v) gradient is M^T grad h = R(+angle) grad h: Listing 3's mul(R, d), which holds for a
// derivative whose y runs along +v. Ours runs along -v (F = diag(1, -1)), so the rotation back is
// F R(+angle) F = R(-angle): the same rotation as into the tile.
vec2 hexcRotateFromTile(vec2 d, vec2 cs) {
    return hexcRotateToTile(d, cs);
}

// What a lattice computes its tiles from, filled by each generated slot function from hexcLattice() (the neutral
// values). Fields marked "literal" are set from constants chosen by hexc, so that the code of a feature left out is
// not emitted rather than computing a no-op at run time: rotation turned off, or no per-tile transforms.
struct HexcLattice {
    float rotation;              // rotStrength of Listings 3, 4, 6
    bool rotate;                 // literal: false, no rotation code
    // Per-tile transforms (stable mode, docs/material-format.md#per-tile-transforms): the angle drawn from
    // rotationRange (degrees), in rotationSteps steps when > 0; the texture scaled by a factor drawn from
    // scaleRange; the offset times `offset`, snapped to an offsetSteps grid when > 0.
    bool transform;              // literal: false, none of them (the defaults, without their code)
    vec2 rotationRange;
    int rotationSteps;           // literal
    vec2 scaleRange;
    float offset;
    ivec2 offsetSteps;           // literal
    int maskScale;               // literal: checker and noise masks, cells per unit of st
    bool triple;                 // literal: the noise mask draws three noises
    float aspect;                // literal: the texture's width / height; tiles turn in st with u scaled by it (not in paper mode)
};

HexcLattice hexcLattice() {
    return HexcLattice(0.0, false, false, vec2(-180.0, 180.0), 0, vec2(1.0), 1.0, ivec2(0), 1, false, 1.0);
}

// Listings 3-4, shared part, `paper` mode: tile `id`'s tap at st_i = (st - c_i) R_i + c_i + hash(v_i), gradients
// rotated with the tile.
HexcTap hexcPaperTap(ivec2 id, vec2 st, vec2 dSTdx, vec2 dSTdy, HexcLattice l) {
    HexcTap p;
    p.invScale = 1.0;
    p.rot = l.rotate ? hexcRotationPaper(id, l.rotation) : vec2(1.0, 0.0);
    vec2 c = hexcTileCentre(id);
    p.st = hexcRotateToTile(st - c, p.rot) + c + hexcHashPaper(id);
    p.dx = hexcRotateToTile(dSTdx, p.rot);
    p.dy = hexcRotateToTile(dSTdy, p.rot);
    return p;
}

// Derivatives of the continuous st are taken once, before the lattice.
HexcTiles hexcTilesPaper(vec2 st, vec2 dSTdx, vec2 dSTdy, HexcLattice l) {
    HexcTiles t;
    t.dx = dSTdx;
    t.dy = dSTdy;
    t.scaled = false;
    hexcTriangleGrid(st, t.w, t.id);
    t.channel = hexcHexChannels(t.id[0], t.id[2]);
    t.tap[0] = hexcPaperTap(t.id[0], st, dSTdx, dSTdy, l);
    t.tap[1] = hexcPaperTap(t.id[1], st, dSTdx, dSTdy, l);
    t.tap[2] = hexcPaperTap(t.id[2], st, dSTdx, dSTdy, l);
    return t;
}

// `stable` mode (docs/material-format.md#mode). Three changes to the paper, none visible, that make the
// result exact and identical on every target as far as |st.x| < 2^26 (where 28 kx stops being exact in float32;
// docs/precision.md#stable-modes-range) and |st.y| < 2^31:
// 1. The lattice scale 2 sqrt(3) becomes 97/28 (relative difference 4.4e-6). Then the lattice repeats
//    exactly every 28 st units in u (97 ids) and every 1 in v (ids (-2, 4)), so st is reduced to
//    [0, 28) x [0, 1) by exact subtractions before any product, and the ids come back as exact integers.
// 2. Offset and rotation come from pcg3d (Jarzynski and Olano 2020) of the integer tile id: 32-bit
//    integer arithmetic, the same bits everywhere, where the paper's fract(sin(x) * 43758.5453) is not.
// 3. The tile centre is added back modulo the texture's period, from integer remainders:
//    st_i = (st - c_i) R_i / s_i + (c_i mod 1) + offset_i, so the texture coordinate stays below 3 in magnitude
//    whatever st is, and offset 0 without rotation reads the plain texture. (R_i turns texel-isotropic space,
//    hexcToTile.)
const float hexcStableScale = 97.0 / 28.0;

uvec3 hexcPcg3d(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

// A tile's offset in [0, 1)^2, rotation (cos, sin) of an angle in [-pi, pi) * rotStrength and 1 / scale,
// from the top 24 bits of each hash word (exact in float32).
void hexcStableTile(ivec2 id, HexcLattice l, out vec2 offset, out vec2 rot, out float invScale) {
    vec3 u = vec3(hexcPcg3d(uvec3(uvec2(id), 0u)) >> 8u) * (1.0 / 16777216.0);
    offset = u.xy;
    float angle = (u.z * 2.0 - 1.0) * hexcPi * l.rotation;
    invScale = 1.0;
    if (l.transform) {
        vec2 steps = vec2(l.offsetSteps);
        offset = mix(offset, floor(offset * steps) / steps, greaterThan(steps, vec2(0.0))) * l.offset;
        float a = l.rotationSteps > 0 ? floor(u.z * float(l.rotationSteps)) / float(l.rotationSteps) : u.z;
        angle = radians(mix(l.rotationRange.x, l.rotationRange.y, a)) * l.rotation;
        float v = float(hexcPcg3d(uvec3(uvec2(id), 1u)).x >> 8u) * (1.0 / 16777216.0);
        invScale = 1.0 / mix(l.scaleRange.x, l.scaleRange.y, v);
    }
    rot = l.rotate ? vec2(cos(angle), sin(angle)) : vec2(1.0, 0.0);
}

// Tile centre of local (reduced) ids: the inverse of skewed = (s x - 2 y, 4 y).
vec2 hexcStableCentre(ivec2 local) {
    return vec2((float(local.x) + 0.5 * float(local.y)) / hexcStableScale, 0.25 * float(local.y));
}

// The same centre modulo the texture's period 1, which the tile's sample point adds back: c.x = (28 l.x + 14 l.y) / 97
// and c.y = l.y / 4, so their fractions are integer remainders, exact (l.x >= -2 and l.y >= 0: the numerator plus
// 2 * 97 is positive). The global centre differs by the whole st units (28 kx, ky) of the reduction and of the cell.
vec2 hexcStableCentreInPeriod(ivec2 local) {
    return vec2(float((28 * local.x + 14 * local.y + 194) % 97) / 97.0, float(local.y & 3) * 0.25);
}

// A vector into the tile's frame: rotated with it in texel-isotropic space (u scaled by the aspect before and back
// after), then scaled; the code of each only when its literal is set (an aspect of 1 is a constant comparison).
vec2 hexcToTile(vec2 v, HexcTap p, HexcLattice l) {
    if (l.rotate) {
        if (l.aspect == 1.0) {
            v = hexcRotateToTile(v, p.rot);
        } else {
            v = hexcRotateToTile(vec2(v.x * l.aspect, v.y), p.rot);
            v = vec2(v.x / l.aspect, v.y);
        }
    }
    return l.transform ? v * p.invScale : v;
}

// Places tile `id`: its transform from the hash of `id`, the sample point from `d` (st relative to the point c the
// tile rotates and scales about) and the gradients, rotated and scaled with the tile; `c` (modulo the texture's
// period) is added back, so that offset 0 without rotation or scale reads the texture where st does.
HexcTap hexcPlaceTile(ivec2 id, vec2 d, vec2 c, vec2 dSTdx, vec2 dSTdy, HexcLattice l) {
    HexcTap p;
    vec2 offset;
    hexcStableTile(id, l, offset, p.rot, p.invScale);
    p.st = hexcToTile(d, p, l) + c + offset;
    p.dx = hexcToTile(dSTdx, p, l);
    p.dy = hexcToTile(dSTdy, p, l);
    return p;
}

// Stable mode's tile of local (reduced) id `local`: its id, local + shift in 32-bit unsigned arithmetic (ids are only
// hashed, so they may wrap), and its tap.
HexcTap hexcStableTap(ivec2 local, uvec2 shift, vec2 r, vec2 dSTdx, vec2 dSTdy, HexcLattice l, out ivec2 id) {
    id = ivec2(uvec2(local) + shift);
    return hexcPlaceTile(id, r - hexcStableCentre(local), hexcStableCentreInPeriod(local), dSTdx, dSTdy, l);
}

// st = (28, 1) * cell + st_local: `cell` is a split-coordinates origin (0 otherwise), whose lattice shift is
// added to the ids. With split coordinates the engine computes the cell and the offset in st from a double origin
// each frame (docs/precision.md) and the mesh supplies a small st relative to it, whose gradients are precise.
HexcTiles hexcTilesStable(vec2 st, vec2 dSTdx, vec2 dSTdy, ivec2 cell, HexcLattice l) {
    HexcTiles t;
    t.dx = dSTdx;
    t.dy = dSTdy;
    t.scaled = l.transform;
    // st = (28 kx + r.x, ky + r.y); each subtraction is exact (Sterbenz) and r is small, while 28 kx is exact:
    // 7 kx < 2^24, so |st.x| < 2^26.
    float kx = floor(st.x / 28.0), ky = floor(st.y);
    vec2 r = vec2(st.x - 28.0 * kx, st.y - ky);
    ivec2 local[3];
    hexcTriangle(vec2(hexcStableScale * r.x - 2.0 * r.y, 4.0 * r.y), t.w, local);
    uvec2 c = uvec2(cell) + uvec2(ivec2(kx, ky));
    uvec2 shift = uvec2(97u * c.x - 2u * c.y, 4u * c.y);
    t.tap[0] = hexcStableTap(local[0], shift, r, dSTdx, dSTdy, l, t.id[0]);
    t.tap[1] = hexcStableTap(local[1], shift, r, dSTdx, dSTdy, l, t.id[1]);
    t.tap[2] = hexcStableTap(local[2], shift, r, dSTdx, dSTdy, l, t.id[2]);
    t.channel = hexcHexChannels(t.id[0], t.id[2]);
    return t;
}

// The checker mask (docs/material-format.md#mask): two square grids of `scale` cells per unit of st, the second
// shifted by half a cell, each cell a tile with its own transform. Two taps: tile 3 repeats tile 2 with weight 0.
float hexcTaper(vec2 f) {
    return min(min(f.x, 1.0 - f.x), min(f.y, 1.0 - f.y));
}

HexcTiles hexcTilesChecker(vec2 st, vec2 dSTdx, vec2 dSTdy, ivec2 cell, HexcLattice l) {
    HexcTiles t;
    t.dx = dSTdx;
    t.dy = dSTdy;
    t.scaled = l.transform;
    int scale = l.maskScale;
    vec2 k = floor(st);
    vec2 q = (st - k) * float(scale);
    uvec2 base = uint(scale) * (uvec2(ivec2(k)) + uvec2(28u * uint(cell.x), uint(cell.y)));
    vec2 a = floor(q), b = floor(q + 0.5);
    vec2 fa = q - a, fb = q + 0.5 - b;
    // 2^-24 keeps the weights above 0 where both tapers vanish (a border of one grid crossing the other's), and
    // dividing by the larger keeps w^exponent from underflowing there.
    vec2 m = vec2(hexcTaper(fa), hexcTaper(fb)) + 1.0 / 16777216.0;
    t.w = vec3(m / max(m.x, m.y), 0.0);
    t.id[0] = ivec2(2u * (base + uvec2(ivec2(a))));
    t.id[1] = ivec2(2u * (base + uvec2(ivec2(b))) + 1u);
    t.id[2] = t.id[1];
    t.channel = ivec3(0, 1, 1);
    float s = 1.0 / float(scale);
    // The cells' centres in the unit of st holding it: (a + 1/2) / scale and b / scale.
    t.tap[0] = hexcPlaceTile(t.id[0], (fa - 0.5) * s, (a + 0.5) * s, dSTdx, dSTdy, l);
    t.tap[1] = hexcPlaceTile(t.id[1], (fb - 0.5) * s, b * s, dSTdx, dSTdy, l);
    t.tap[2] = t.tap[1];
    return t;
}

// Value noise over integer cells `c` (32-bit wrapping), fraction f, corner values from pcg3d(corner, salt).
float hexcValueNoise(uvec2 c, vec2 f, uint salt) {
    vec2 s = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    vec4 h = vec4(hexcPcg3d(uvec3(c, salt)).x, hexcPcg3d(uvec3(c + uvec2(1u, 0u), salt)).x,
                  hexcPcg3d(uvec3(c + uvec2(0u, 1u), salt)).x, hexcPcg3d(uvec3(c + uvec2(1u, 1u), salt)).x);
    h = vec4(uvec4(h) >> 8u) * (1.0 / 16777216.0);
    return mix(mix(h.x, h.y, s.x), mix(h.z, h.w, s.x), s.y);
}

// The noise masks: three copies of the texture, each with one transform (ids (0,0), (1,0), (2,0)) about the st
// origin, weighed by three bands of one value noise or by three noises (`triple`).
HexcTiles hexcTilesNoise(vec2 st, vec2 dSTdx, vec2 dSTdy, HexcLattice l) {
    HexcTiles t;
    t.dx = dSTdx;
    t.dy = dSTdy;
    t.scaled = l.transform;
    int scale = l.maskScale;
    vec2 k = floor(st);
    vec2 q = (st - k) * float(scale);
    vec2 fl = floor(q);
    uvec2 c = uint(scale) * uvec2(ivec2(k)) + uvec2(ivec2(fl));
    vec2 f = q - fl;
    if (l.triple) {
        vec3 n = vec3(hexcValueNoise(c, f, 4u), hexcValueNoise(c, f, 5u), hexcValueNoise(c, f, 6u));
        t.w = n / max(max(n.x, n.y), max(n.z, 1.0 / 16777216.0));
    } else {
        float p = clamp(4.0 * hexcValueNoise(c, f, 3u) - 1.0, 0.0, 2.0);
        t.w = max(vec3(0.0), 1.0 - abs(p - vec3(0.0, 1.0, 2.0)));
    }
    t.id = ivec2[3](ivec2(0, 0), ivec2(1, 0), ivec2(2, 0));
    t.channel = ivec3(0, 1, 2);
    t.tap[0] = hexcPlaceTile(t.id[0], st, vec2(0.0), dSTdx, dSTdy, l);
    t.tap[1] = hexcPlaceTile(t.id[1], st, vec2(0.0), dSTdx, dSTdy, l);
    t.tap[2] = hexcPlaceTile(t.id[2], st, vec2(0.0), dSTdx, dSTdy, l);
    return t;
}

// x^n for a literal n in 1..16 by repeated squaring: hexc passes n when an exponent is a whole number, the
// optimiser folds the branches, and gamma = 7 costs four multiplications instead of a pow (exp2 and log2).
vec3 hexcPowInt(vec3 x, int n) {
    vec3 r = vec3(1.0);
    if ((n & 1) != 0) r *= x;
    x *= x;
    if ((n & 2) != 0) r *= x;
    x *= x;
    if ((n & 4) != 0) r *= x;
    x *= x;
    if ((n & 8) != 0) r *= x;
    x *= x;
    if ((n & 16) != 0) r *= x;
    return r;
}

// Listing 8 / Eq. 5: Perlin's gain g with k = log(1 - r) / log(1/2). kInt > 0: k is that whole number
// (r = 1 - 2^-k, e.g. the paper's 0.75 gives k = 2), a literal chosen by hexc.
float hexcGainK(float r, int kInt) {
    return kInt > 0 ? float(kInt) : log(1.0 - r) / log(0.5);
}

vec3 hexcGainCurve(vec3 x, float r, int kInt) {
    vec3 s = 2.0 * step(0.5, x);
    vec3 m = 2.0 * (1.0 - s);
    vec3 base = max(vec3(0.0), s + x * m);
    return 0.5 * s + 0.25 * m * (kInt > 0 ? hexcPowInt(base, kInt) : pow(base, vec3(hexcGainK(r, kInt))));
}

// The gain, then renormalised.
vec3 hexcGain3(vec3 x, float r, int kInt) {
    vec3 res = hexcGainCurve(x, r, kInt);
    return res / (res.x + res.y + res.z);
}

// How a slot weighs its tiles' samples, filled by each generated slot function from hexcBlend() (the neutral
// values). Fields marked "literal" are set from constants chosen by hexc: metric and gain are false when
// falloffcontrast is 0 or falloff is 0.5, so that the metric (and the samples' luminance) or the gain is not
// emitted instead of computing a no-op; a whole-number exponent or gain exponent (> 0) replaces a pow.
struct HexcBlend {
    float falloff;               // r of Eq. 5 / Listing 8
    float falloffContrast;       // beta of Eq. 3-4
    float exponent;              // gamma of Eq. 1
    bool metric;                 // literal: the falloff metric is computed
    bool gain;                   // literal: the gain is applied
    int exponentInt;             // literal: > 0, gamma is this whole number (multiplied out); 0: a pow per pixel
    int gainInt;                 // literal: > 0, the gain's k is this whole number; 0 with gain: a log and a pow
    int taps;                    // literal: 3, or 2 for the checker mask (no third fetch)
    bool sharedLod;              // literal: lod "shared", every fetch at the slot's level of detail (hexcTileLods)
    bool adaptive;               // literal: "taps": "adaptive", fetch a tap only when it can matter (hexcAdaptiveTaps)
    float adaptiveError;         // literal: the bound it keeps, epsilon below
    bool height;                 // literal: blend by the heights in channel heightLuma of the height texture
    vec4 heightLuma;
    float heightWidth;
};

HexcBlend hexcBlend() {
    return HexcBlend(0.5, 0.0, 7.0, false, false, 0, 0, 3, false, false, 1.0 / 255.0, false, vec4(0.0), 1.0);
}

// The falloff metric's factor of each tap (Eqs. 3-4) from its luminance, channel or slope Dw; 1 without the metric.
// A negative metric (HDR texels with negative values) counts as 0.
vec3 hexcMetric(vec3 Dw, HexcBlend b) {
    return b.metric ? mix(vec3(1.0), max(Dw, vec3(0.0)), b.falloffContrast) : vec3(1.0);
}

// The tiles' weights from the lattice's w, each tap's metric factor M (hexcMetric) and the gain. A guard keeps them
// finite and normalised outside the paper's domain, and changes nothing inside it: when every weighted term is 0
// (falloffcontrast 1 over three black samples) the metric is ignored.
vec3 hexcBlendWeights(vec3 w, vec3 M, HexcBlend b) {
    vec3 wg = b.exponentInt > 0 ? hexcPowInt(w, b.exponentInt) : pow(w, vec3(b.exponent));
    vec3 W = M * wg;
    float sum = W.x + W.y + W.z;
    W = sum > 0.0 ? W / sum : wg / (wg.x + wg.y + wg.z);
    if (b.gain && (b.gainInt > 0 || b.falloff != 0.5)) W = hexcGain3(W, b.falloff, b.gainInt);
    return W;
}

// Adaptive taps ("taps": "adaptive", docs/material-format.md#taps): which taps to fetch, decided from the lattice
// weights alone, before any sample, so that the result moves by at most e = b.adaptiveError against all three.
// With wg = w^gamma, the metric D_i in [1 - beta, 1] (luminance or channel in [0, 1]; a normal's slope sine always),
// W = D wg / sum(D wg), and the final weights G = g(W) / sum(g(W)) (g the gain, monotone):
//   W_i <= U_i = wg_i / (wg_i + (1 - beta) sum_{j != i} wg_j)     (D_i = 1, the others 1 - beta)
//   W_i >= L_i = (1 - beta) wg_i / ((1 - beta) wg_i + sum_{j != i} wg_j)
//   G_i <= Gup_i = g(U_i) / (g(U_i) + sum_{j != i} g(L_j))       (G_i rises with W_i, falls with the others)
// A skipped tap gets wg_i = 0: the rest of the blend renormalises itself. The result moves by sum_j |G_j - G'_j| / 2
// (the total variation TV) times the spread of the taps' values (<= 1 for values in [0, 1]). Two taps skipped:
// G' = (1, 0, 0), TV = G_a + G_b <= Gup_a + Gup_b. One skipped (i): TV <= G_i + the gain's change on the two kept,
// whose pre-gain weights grow by 1 / (1 - W_i): each g(cW) / g(W) lies in [1, c^k] (g's elasticity x g'(x) / g(x) is
// in [0, k] for k >= 1, which the parser requires), so the kept pair's log-odds move by at most k ln c, their share
// by at most a quarter of that (the logistic's slope): TV <= Gup_i + k/4 ln(1 / (1 - U_i)). Without the gain, g(x) = x
// and k = 0.
// The heaviest tap (largest w) is always fetched; the other two together when Gup_a + Gup_b < e, else the one
// with the smaller bound when that is < e.
bvec3 hexcAdaptiveTaps(vec3 w, HexcBlend b) {
    // The bounds need only the weights' ratios: w over its largest keeps the largest wg at 1, where w^gamma itself
    // (down to (1/3)^64 ~ 3e-31) would fall below the guards' 1e-30 and float32's normal range. A wg that underflows
    // still has U_i < 2^-126 / (1 - beta): nothing.
    vec3 wn = w / max(max(w.x, w.y), max(w.z, 1e-30));
    vec3 wg = b.exponentInt > 0 ? hexcPowInt(wn, b.exponentInt) : pow(wn, vec3(b.exponent));
    float lo = b.metric ? 1.0 - b.falloffContrast : 1.0;
    vec3 others = vec3(wg.x + wg.y + wg.z) - wg;
    vec3 U = wg / max(wg + lo * others, vec3(1e-30));
    vec3 L = lo * wg / max(lo * wg + others, vec3(1e-30));
    vec3 gU = U, gL = L;
    float k = 0.0;
    if (b.gain && (b.gainInt > 0 || b.falloff != 0.5)) {
        gU = hexcGainCurve(U, b.falloff, b.gainInt);
        gL = hexcGainCurve(L, b.falloff, b.gainInt);
        k = hexcGainK(b.falloff, b.gainInt);
    }
    vec3 Gup = gU / max(gU + vec3(gL.x + gL.y + gL.z) - gL, vec3(1e-30));
    // Where the gain is a pure power for tap i and the others (all three arguments below 0.5: g(x) = 0.5 (2x)^k), g
    // underflows float32 (0.01^19 = 1e-38) and the guard above would shrink Gup_i; the ratio does not: take it before
    // the power. U_i = 0 gives an infinite ratio, Gup_i = 0.
    if (k > 0.0) {
        vec3 r1 = L.yzx / max(U, vec3(1e-30)), r2 = L.zxy / max(U, vec3(1e-30));
        vec3 p1 = b.gainInt > 0 ? hexcPowInt(r1, b.gainInt) : pow(r1, vec3(k));
        vec3 p2 = b.gainInt > 0 ? hexcPowInt(r2, b.gainInt) : pow(r2, vec3(k));
        Gup = mix(Gup, 1.0 / (1.0 + p1 + p2), lessThan(max(U, max(L.yzx, L.zxy)), vec3(0.5)));
    }
    // U_i = 1 only for a tap whose weight cannot be bounded: never skipped, so its term may be infinite.
    vec3 B = Gup - 0.25 * k * log(max(vec3(1.0) - U, vec3(1e-30)));
    int d = w.x >= w.y && w.x >= w.z ? 0 : (w.y >= w.z ? 1 : 2);
    int a = d == 0 ? 1 : 0, c = d == 2 ? 1 : 2;
    bvec3 f = bvec3(true);
    if (Gup[a] + Gup[c] < b.adaptiveError) {
        f[a] = false;
        f[c] = false;
    } else if (min(B[a], B[c]) < b.adaptiveError) {
        f[B[a] <= B[c] ? a : c] = false;
    }
    return f;
}

// Height blending (docs/material-format.md#height-blending): weights W reshaped by the tiles' heights h, so the
// highest tile shows and others only within `width` of it. A tile's weight stays 0 where W is 0 (no seams), and
// the highest tile keeps width * W > 0, so the sum never vanishes.
vec3 hexcHeightBlend(vec3 W, vec3 h, float width) {
    vec3 a = max(h, vec3(0.0)) * W;
    vec3 Wh = W * max(a - max(max(a.x, a.y), a.z) + width, vec3(0.0));
    return Wh / (Wh.x + Wh.y + Wh.z);
}

// lod "shared" (docs/material-format.md#lod): the three tiles' levels of detail on `tex`, computed once: the sampler's
// rho = max(|dx|, |dy|) of the unrotated gradients in texels. A tile turns the texels (hexcToTile), which keeps their
// lengths, so that is each tile's own level (the paper's mode, turning st, is off by up to log2 of the
// aspect); a tile's own texture scale shifts its level by log2 of it.
vec3 hexcTileLods(texture2D tex, sampler samp, HexcTiles t, HexcBlend b) {
    vec3 lods = vec3(0.0);  // unread without b.sharedLod
    if (b.sharedLod) {
        vec2 size = vec2(textureSize(sampler2D(tex, samp), 0));
        vec2 ex = t.dx * size, ey = t.dy * size;
        float lod = 0.5 * log2(max(max(dot(ex, ex), dot(ey, ey)), 1e-30));
        lods = t.scaled ? lod + log2(vec3(t.tap[0].invScale, t.tap[1].invScale, t.tap[2].invScale)) : vec3(lod);
    }
    return lods;
}

// One tap's fetch: with its own gradients (the sampler picks the level, and filters anisotropically when the
// sampler does), or at the level hexcTileLods gave (`b.sharedLod`).
vec4 hexcFetch(texture2D tex, sampler samp, HexcTap p, float lod, HexcBlend b) {
    return b.sharedLod ? textureLod(sampler2D(tex, samp), p.st, lod) : textureGrad(sampler2D(tex, samp), p.st, p.dx, p.dy);
}

// The taps a slot fetches: all (b.taps = 2, the checker, leaves out the third, weightless one), or with adaptive taps
// those that can matter.
bvec3 hexcFetched(vec3 w, HexcBlend b) {
    return b.adaptive ? hexcAdaptiveTaps(w, b) : bvec3(true, true, b.taps > 2);
}

// The texels of the taps `f` picks (the others read 0), every path's fetches. Adaptive taps branch around each
// fetch, as a GPU needs to skip one: the gradients (textureGrad) or the level (textureLod, lod "shared") are
// explicit, so a fetch in non-uniform control flow is defined. Otherwise `f` is every tap (the checker's two): the
// branches read that from the settings, so that codegen folds them.
void hexcFetchTaps(texture2D tex, sampler samp, HexcTiles t, bvec3 f, HexcBlend b, out vec4 c[3]) {
    vec3 lod = hexcTileLods(tex, samp, t, b);
    c = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
    if (!b.adaptive || f.x) c[0] = hexcFetch(tex, samp, t.tap[0], lod.x, b);
    if (!b.adaptive || f.y) c[1] = hexcFetch(tex, samp, t.tap[1], lod.y, b);
    if ((b.adaptive && f.z) || (!b.adaptive && b.taps > 2)) c[2] = hexcFetch(tex, samp, t.tap[2], lod.z, b);
}

// The heights of the tiles' samples from the height slot's texture (b.heightLuma picks its channel).
vec3 hexcTileHeights(texture2D tex, sampler samp, HexcTiles t, HexcBlend b) {
    vec4 h[3];
    hexcFetchTaps(tex, samp, t, bvec3(true, true, b.taps > 2), b, h);
    return vec3(dot(h[0], b.heightLuma), dot(h[1], b.heightLuma), dot(h[2], b.heightLuma));
}

// Listing 4: colour path. `luma` selects the falloff metric: Rec. 601 luminance for colour (Eq. 4),
// a unit vector picking the channel for scalar maps. `heightTex`: the height slot's texture (b.height).
vec4 hexcColor(texture2D tex, sampler samp, HexcTiles t, HexcBlend b, vec4 luma, texture2D heightTex, out vec3 weights) {
    bvec3 f = hexcFetched(t.w, b);
    vec4 c[3];
    hexcFetchTaps(tex, samp, t, f, b, c);
    vec3 Dw = vec3(dot(c[0], luma), dot(c[1], luma), dot(c[2], luma));
    vec3 W = hexcBlendWeights(t.w * vec3(f), hexcMetric(Dw, b), b);  // a skipped tap weighs 0, the others renormalise
    if (b.height) W = hexcHeightBlend(W, hexcTileHeights(heightTex, samp, t, b), b.heightWidth);
    weights = hexcShowWeights(W, t.channel);
    return W.x * c[0] + W.y * c[1] + W.z * c[2];
}

// The histogram-preserving blend (Heitz and Neyret 2018, Deliot and Heitz 2019; hexc/histogram.h). `tex` holds each
// decorrelated channel gaussianised (mean 0.5, standard deviation 1/6); the tiles' values are blended with the
// variance-preserving weights W / |W|, so the blend keeps the Gaussian's spread wherever the tiles overlap. `lut` row
// 1 + lod holds each channel's inverse transform at a level of detail of the Gaussian texture, texel i for Gaussian
// value 0.5 + (2 i / (width - 1) - 1) 6.5 / 6 (+-6.5 standard deviations: every texel's rank is within reach, so the
// tails are kept); row 0 the way back to linear RGB (the axes in texels 0-2, the mean in texel 3) and the texture's
// range (texels 4 and 5), which the sum over the axes may leave. lod comes from the slot's st gradients as the
// sampler computes it (Euclidean lengths), and the rows are interpolated in it. `scalar` (a literal): one channel, in
// r, within its range already, and no way back to take.
vec4 hexcHistogram(texture2D tex, texture2D lut, sampler samp, HexcTiles t, HexcBlend b, vec2 dx, vec2 dy, bool scalar, out vec3 weights) {
    vec4 g[3];
    hexcFetchTaps(tex, samp, t, bvec3(true, true, b.taps > 2), b, g);
    vec3 W = hexcBlendWeights(t.w, vec3(1.0), b);
    weights = hexcShowWeights(W, t.channel);
    // The checker's third tap weighs 0: its unfetched 0 adds nothing.
    vec3 G = (W.x * (g[0].rgb - 0.5) + W.y * (g[1].rgb - 0.5) + W.z * (g[2].rgb - 0.5)) * inversesqrt(dot(W, W)) + 0.5;
    vec2 size = vec2(textureSize(sampler2D(tex, samp), 0));
    vec2 ex = dx * size, ey = dy * size;
    float lod = 0.5 * log2(max(max(dot(ex, ex), dot(ey, ey)), 1e-30));
    vec2 n = vec2(textureSize(sampler2D(lut, samp), 0));
    float v = (1.5 + clamp(lod, 0.0, n.y - 2.0)) / n.y;
    vec3 u = (clamp((G - 0.5) * (6.0 / 13.0) + 0.5, 0.0, 1.0) * (n.x - 1.0) + 0.5) / n.x;
    float q1 = textureLod(sampler2D(lut, samp), vec2(u.x, v), 0.0).r;
    if (scalar) return vec4(q1);
    float q2 = textureLod(sampler2D(lut, samp), vec2(u.y, v), 0.0).g;
    float q3 = textureLod(sampler2D(lut, samp), vec2(u.z, v), 0.0).b;
    vec3 rgb = texelFetch(sampler2D(lut, samp), ivec2(3, 0), 0).rgb + q1 * texelFetch(sampler2D(lut, samp), ivec2(0, 0), 0).rgb +
               q2 * texelFetch(sampler2D(lut, samp), ivec2(1, 0), 0).rgb + q3 * texelFetch(sampler2D(lut, samp), ivec2(2, 0), 0).rgb;
    return vec4(clamp(rgb, texelFetch(sampler2D(lut, samp), ivec2(4, 0), 0).rgb, texelFetch(sampler2D(lut, samp), ivec2(5, 0), 0).rgb), 1.0);
}

// Listing 9: tangent-space normal in [-1, 1] to the height derivative dH/duv, |z| kept >= max(|x|,|y|)/128.
// flipY: the map's green axis points down (DirectX convention). Guard: a zero vector gives 0, not 0/0.
vec2 hexcNormalToDeriv(vec3 vM, bool flipY) {
    vec3 vMa = abs(vM);
    float zMa = max(max(vMa.z, (1.0 / 128.0) * max(vMa.x, vMa.y)), 1e-20);
    return -vec2(vM.x, flipY ? -vM.y : vM.y) / zMa;
}

// Listings 3 and 10: a tap's normal-map texel as the derivative in st space, rotated back with its tile and, a tile scaled
// by s showing H(p / s), divided by s (`scaled`, a literal).
vec2 hexcTapDeriv(vec4 texel, HexcTap p, bool scaled, bool flipY) {
    vec2 d = hexcRotateFromTile(hexcNormalToDeriv(2.0 * texel.xyz - 1.0, flipY), p.rot);
    return scaled ? d * p.invScale : d;
}

// Listing 3: normal-map derivative path. Each sampled derivative is rotated back with its tile's
// rotation before blending; the falloff metric is the sine of the slope angle (Eq. 3).
vec2 hexcDeriv(texture2D tex, sampler samp, HexcTiles t, HexcBlend b, bool flipY, texture2D heightTex, out vec3 weights) {
    // One branch per tap around its fetch and its derivative (adaptive taps: see hexcFetchTaps), folded without them.
    bvec3 f = hexcFetched(t.w, b);
    vec3 lod = hexcTileLods(tex, samp, t, b);
    vec2 d1 = vec2(0.0), d2 = vec2(0.0), d3 = vec2(0.0);
    if (!b.adaptive || f.x) d1 = hexcTapDeriv(hexcFetch(tex, samp, t.tap[0], lod.x, b), t.tap[0], t.scaled, flipY);
    if (!b.adaptive || f.y) d2 = hexcTapDeriv(hexcFetch(tex, samp, t.tap[1], lod.y, b), t.tap[1], t.scaled, flipY);
    if ((b.adaptive && f.z) || (!b.adaptive && b.taps > 2)) d3 = hexcTapDeriv(hexcFetch(tex, samp, t.tap[2], lod.z, b), t.tap[2], t.scaled, flipY);
    vec3 D = vec3(dot(d1, d1), dot(d2, d2), dot(d3, d3));
    vec3 W = hexcBlendWeights(t.w * vec3(f), hexcMetric(sqrt(D / (1.0 + D)), b), b);
    if (b.height) W = hexcHeightBlend(W, hexcTileHeights(heightTex, samp, t, b), b.heightWidth);
    weights = hexcShowWeights(W, t.channel);
    return W.x * d1 + W.y * d2 + W.z * d3;
}

// 1-tap dithered hex tiling ("taps": 1): one fetch per pixel instead of three. Each pixel picks one of the
// three tiles with probability equal to its blend weight, by an integer hash of the pixel position (the
// same on every target), and samples only that tile, with the tile's own rotated gradients so the mip
// level stays right. The falloff metric would need all three samples, so the weights are Eq. 1 without it.
// `pixel`: the pixel's position (gl_FragCoord.xy; a parameter so the library needs no stage input).

// a ? x : y, member by member (a select of a whole struct would need a branch).
HexcTap hexcSelect(bool a, HexcTap x, HexcTap y) {
    return HexcTap(a ? x.st : y.st, a ? x.dx : y.dx, a ? x.dy : y.dy, a ? x.rot : y.rot, a ? x.invScale : y.invScale);
}

// The picked tap, and which it is (one-hot in `pick`).
HexcTap hexcDitherTile(HexcTiles t, HexcBlend b, vec2 pixel, out vec3 pick) {
    vec3 W = hexcBlendWeights(t.w, vec3(1.0), b);  // no metric: one sample
    float u = float(hexcPcg3d(uvec3(uvec2(pixel), 2u)).x >> 8u) * (1.0 / 16777216.0);
    int i = u < W.x ? 0 : (u < W.x + W.y ? 1 : 2);
    pick = vec3(equal(ivec3(0, 1, 2), ivec3(i)));
    return hexcSelect(i == 0, t.tap[0], hexcSelect(i == 1, t.tap[1], t.tap[2]));
}

vec4 hexcColor1(texture2D tex, sampler samp, HexcTiles t, HexcBlend b, vec2 pixel, out vec3 weights) {
    vec3 pick;
    HexcTap tap = hexcDitherTile(t, b, pixel, pick);
    weights = hexcShowWeights(pick, t.channel);
    return hexcFetch(tex, samp, tap, dot(pick, hexcTileLods(tex, samp, t, b)), b);
}

vec2 hexcDeriv1(texture2D tex, sampler samp, HexcTiles t, HexcBlend b, bool flipY, vec2 pixel, out vec3 weights) {
    vec3 pick;
    HexcTap tap = hexcDitherTile(t, b, pixel, pick);
    weights = hexcShowWeights(pick, t.channel);
    float lod = dot(pick, hexcTileLods(tex, samp, t, b));
    return hexcTapDeriv(hexcFetch(tex, samp, tap, lod, b), tap, t.scaled, flipY);
}

// Plain tiling, for slots with hex-tiling disabled: one fetch, hardware gradients, or the given ones where
// the call may sit in non-uniform control flow (`explicitGrad`, a literal: the triplanar planes).
vec4 hexcPlainColor(texture2D tex, sampler samp, vec2 st, vec2 dx, vec2 dy, bool explicitGrad, out vec3 weights) {
    weights = vec3(1.0, 0.0, 0.0);
    return explicitGrad ? textureGrad(sampler2D(tex, samp), st, dx, dy) : texture(sampler2D(tex, samp), st);
}

vec2 hexcPlainDeriv(texture2D tex, sampler samp, vec2 st, vec2 dx, vec2 dy, bool explicitGrad, bool flipY, out vec3 weights) {
    return hexcNormalToDeriv(2.0 * hexcPlainColor(tex, samp, st, dx, dy, explicitGrad, weights).xyz - 1.0, flipY);
}

// The paper's conversion of a blended derivative back to a tangent-space normal (Section 3).
vec3 hexcDerivToNormal(vec2 deriv) {
    return normalize(vec3(-deriv, 1.0));
}

// Triplanar projection (docs/material-format.md#triplanar-projection): the unit normal, each plane's weight
// and each plane's st with its gradients. Planes x, y, z read (y, z), (z, x), (x, y) of the position.
struct HexcPlanes {
    vec3 n, b;
    vec2 st[3], dx[3], dy[3];
};

HexcPlanes hexcPlanes(vec3 position, vec3 normal, float sharpness, vec2 tiling) {
    HexcPlanes p;
    // Derivatives here, in uniform control flow: the planes are then sampled with explicit gradients.
    vec3 dPdx = dFdx(position), dPdy = dFdy(position);
    float len = length(normal);
    p.n = len > 0.0 ? normal / len : vec3(0.0);
    vec3 b = pow(abs(p.n), vec3(sharpness));
    float sum = b.x + b.y + b.z;
    p.b = sum > 0.0 ? b / sum : vec3(1.0 / 3.0);
    p.st[0] = position.yz * tiling; p.dx[0] = dPdx.yz * tiling; p.dy[0] = dPdy.yz * tiling;
    p.st[1] = position.zx * tiling; p.dx[1] = dPdx.zx * tiling; p.dy[1] = dPdy.zx * tiling;
    p.st[2] = position.xy * tiling; p.dx[2] = dPdx.xy * tiling; p.dy[2] = dPdy.xy * tiling;
    return p;
}

// A plane's value in the blend: colour and scalar as they are; a normal slot's derivative (dH/ds, dH/dy), y = -t
// (see Conventions), as the world-space gradient it implies on plane k, whose (s, t) are world (y, z), (z, x), (x, y).
vec4 hexcLift(int k, vec4 v) { return v; }
float hexcLift(int k, float v) { return v; }
vec3 hexcLift(int k, vec2 d) {
    return k == 0 ? vec3(0.0, d.x, -d.y) : (k == 1 ? vec3(-d.y, 0.0, d.x) : vec3(d.x, -d.y, 0.0));
}

// The blended planes' result: colour and scalar as they are; gradients projected onto the surface (the surface
// gradient of Mikkelsen 2020).
vec4 hexcFinish(vec4 v, vec3 n) { return v; }
float hexcFinish(float v, vec3 n) { return v; }
vec3 hexcFinish(vec3 g, vec3 n) { return g - dot(g, n) * n; }

// The bumped normal from a surface gradient (a triplanar normal slot's result).
vec3 hexcPerturbNormal(vec3 normal, vec3 surfaceGradient) {
    return normalize(normalize(normal) - surfaceGradient);
}

// The value and weights templates' preview surface for triplanar materials: the unit sphere, uv as longitude
// and latitude in radians.
void hexcPreviewSphere(vec2 uv, out vec3 position, out vec3 normal) {
    position = vec3(cos(uv.y) * sin(uv.x), sin(uv.y), cos(uv.y) * cos(uv.x));
    normal = position;
}
