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
