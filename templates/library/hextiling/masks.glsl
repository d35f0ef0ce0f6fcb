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
    t.tap[0] = hexcPlaceTile(t.id[0], (fa - 0.5) * s, (a + 0.5) * s, dSTdx, dSTdy, l, false);
    t.tap[1] = hexcPlaceTile(t.id[1], (fb - 0.5) * s, b * s, dSTdx, dSTdy, l, false);
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
// origin (so with hexcCosSin's exact cos and sin), weighed by three bands of one value noise or by three noises
// (`triple`).
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
    t.tap[0] = hexcPlaceTile(t.id[0], st, vec2(0.0), dSTdx, dSTdy, l, true);
    t.tap[1] = hexcPlaceTile(t.id[1], st, vec2(0.0), dSTdx, dSTdy, l, true);
    t.tap[2] = hexcPlaceTile(t.id[2], st, vec2(0.0), dSTdx, dSTdy, l, true);
    return t;
}
