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
