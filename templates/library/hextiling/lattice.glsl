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

// (cos, sin) of an angle, the same on every target: within 1.2e-7 in [-pi, pi], 3.3e-6 at 3600 degrees (float32
// rounding). WGSL and Vulkan allow the target's cos and sin an absolute error of 2^-11 in [-pi, pi] (SwiftShader uses
// it), and an error e in a tile's rotation moves its sample point by e |d|, d being st relative to the point the tile
// turns about: at most a tile's size on the lattices, but |st| on the noise masks, which turn about the st origin.
// Reduced by quarter turns k to |r| <= pi/4, where the Taylor series to r^9 and r^8 are within 2e-9 and 3e-8.
vec2 hexcCosSin(float angle) {
    float k = round(angle * (2.0 / hexcPi));
    float r = angle - k * (0.5 * hexcPi), r2 = r * r;
    float s = r * (1.0 + r2 * (-1.0 / 6.0 + r2 * (1.0 / 120.0 + r2 * (-1.0 / 5040.0 + r2 * (1.0 / 362880.0)))));
    float c = 1.0 + r2 * (-0.5 + r2 * (1.0 / 24.0 + r2 * (-1.0 / 720.0 + r2 * (1.0 / 40320.0))));
    // Quarter turn q: (cos, sin) of r turned by q * 90 degrees (q & 3 is the remainder for negative k too).
    int q = int(k) & 3;
    vec2 cs = (q & 1) != 0 ? vec2(-s, c) : vec2(c, s);
    return (q & 2) != 0 ? -cs : cs;
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
// from the top 24 bits of each hash word (exact in float32); `aboutOrigin` (a literal): the tile turns about the st
// origin, so its (cos, sin) must be exact (hexcCosSin).
void hexcStableTile(ivec2 id, HexcLattice l, bool aboutOrigin, out vec2 offset, out vec2 rot, out float invScale) {
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
    rot = !l.rotate ? vec2(1.0, 0.0) : aboutOrigin ? hexcCosSin(angle) : vec2(cos(angle), sin(angle));
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
HexcTap hexcPlaceTile(ivec2 id, vec2 d, vec2 c, vec2 dSTdx, vec2 dSTdy, HexcLattice l, bool aboutOrigin) {
    HexcTap p;
    vec2 offset;
    hexcStableTile(id, l, aboutOrigin, offset, p.rot, p.invScale);
    p.st = hexcToTile(d, p, l) + c + offset;
    p.dx = hexcToTile(dSTdx, p, l);
    p.dy = hexcToTile(dSTdy, p, l);
    return p;
}

// Stable mode's tile of local (reduced) id `local`: its id, local + shift in 32-bit unsigned arithmetic (ids are only
// hashed, so they may wrap), and its tap.
HexcTap hexcStableTap(ivec2 local, uvec2 shift, vec2 r, vec2 dSTdx, vec2 dSTdy, HexcLattice l, out ivec2 id) {
    id = ivec2(uvec2(local) + shift);
    return hexcPlaceTile(id, r - hexcStableCentre(local), hexcStableCentreInPeriod(local), dSTdx, dSTdy, l, false);
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
