// The periodic lattice of `hexc bake` (docs/cli.md#hexc-bake), a compile option: the skew A0 = (97/28, -2; 0, 4) of
// stable mode becomes A = P / K, P the integer matrix nearest K A0 (`period`, its columns) and K the `repeats` of the
// texture across the bake, so that a shift of st by (K, 0) or (0, K) moves the lattice onto itself (by P's columns).
// Ids are wrapped modulo P's integer lattice before they are hashed; the centre c = A^-1 id and the sample point use
// the unwrapped id, which the texture's period 1 in st makes the same. Integer arithmetic, exact for the ids of
// st in [0, K]^2.
int hexcFloorDiv(int a, int d) {
    return a >= 0 ? a / d : -((d - 1 - a) / d);  // d > 0; GLSL's / and % on negatives are not floored
}

HexcTap hexcPeriodicTap(ivec2 id, vec2 st, vec2 dSTdx, vec2 dSTdy, ivec4 period, int repeats, HexcLattice l, out ivec2 wrapped) {
    int det = period.x * period.w - period.z * period.y;
    ivec2 f = ivec2(period.w * id.x - period.z * id.y, period.x * id.y - period.y * id.x);  // adj(P) id
    ivec2 q = ivec2(hexcFloorDiv(f.x, det), hexcFloorDiv(f.y, det));
    wrapped = id - ivec2(period.x * q.x + period.z * q.y, period.y * q.x + period.w * q.y);
    // c = K adj(P) id / det, and c modulo 1 from the integer remainders of K f (exact).
    ivec2 kf = repeats * f;
    ivec2 rem = kf - det * ivec2(hexcFloorDiv(kf.x, det), hexcFloorDiv(kf.y, det));
    return hexcPlaceTile(wrapped, st - vec2(kf) / float(det), vec2(rem) / float(det), dSTdx, dSTdy, l, false);
}

HexcTiles hexcTilesPeriodic(vec2 st, vec2 dSTdx, vec2 dSTdy, ivec4 period, int repeats, HexcLattice l) {
    HexcTiles t;
    t.dx = dSTdx;
    t.dy = dSTdy;
    t.scaled = l.transform;
    ivec2 id[3];
    hexcTriangle(mat2(vec4(period)) * st / float(repeats), t.w, id);
    t.tap[0] = hexcPeriodicTap(id[0], st, dSTdx, dSTdy, period, repeats, l, t.id[0]);
    t.tap[1] = hexcPeriodicTap(id[1], st, dSTdx, dSTdy, period, repeats, l, t.id[1]);
    t.tap[2] = hexcPeriodicTap(id[2], st, dSTdx, dSTdy, period, repeats, l, t.id[2]);
    t.channel = hexcHexChannels(t.id[0], t.id[2]);
    return t;
}

// The checker mask on the periodic lattice: the cells' ids wrapped modulo `cells` = K maskScale a row (st >= 0), and
// each tap placed again with its wrapped id (the optimiser drops the first placing). A cell's centre within its unit
// of st, and so its sample point, is the same K units away.
HexcTiles hexcTilesCheckerPeriodic(vec2 st, vec2 dSTdx, vec2 dSTdy, int cells, HexcLattice l) {
    HexcTiles t = hexcTilesChecker(st, dSTdx, dSTdy, ivec2(0), l);
    uvec2 n = uint(cells) * uvec2(1u);
    t.id[0] = ivec2(2u * ((uvec2(t.id[0]) >> 1u) % n));
    t.id[1] = ivec2(2u * ((uvec2(t.id[1]) >> 1u) % n) + 1u);
    t.id[2] = t.id[1];
    float s = 1.0 / float(l.maskScale);
    vec2 q = fract(st) * float(l.maskScale);
    vec2 a = floor(q), b = floor(q + 0.5);
    t.tap[0] = hexcPlaceTile(t.id[0], (q - a - 0.5) * s, (a + 0.5) * s, dSTdx, dSTdy, l, false);
    t.tap[1] = hexcPlaceTile(t.id[1], (q + 0.5 - b - 0.5) * s, b * s, dSTdx, dSTdy, l, false);
    t.tap[2] = t.tap[1];
    return t;
}
