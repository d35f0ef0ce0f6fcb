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
