// hexc's MaterialX mode ("mode": "materialx", docs/materialx.md#materialx-mode): MaterialX 1.39's <hextiledimage> and
// <hextilednormalmap>, written from their node definitions (libraries/stdlib/stdlib_defs.mtlx) and the maths of
// their implementation (Mikkelsen 2022 as MaterialX instantiates it), for hexc's slots. Appended after
// hextiling.glsl, whose lattice (Listing 1), tile centre (Listing 5), HexcTap, HexcTiles, HexcLattice and HexcBlend it uses.
// Where MaterialX differs from hexc's stable mode: its own hash of the tile id, the sample point rotated by
// R(+angle) about the tile centre, a tile's offset and angle from the same random number, the colour weights
// luma * w^7 (luma from `lumacoeffs`, mixed towards 1 by falloffcontrast), Schlick's gain, sRGB texels blended
// before decoding, and normal slopes not divided by the tile's scale.

// MaterialX's tile hash (a sine-free hash of Dave Hoskins): two numbers in [0, 1) from the id offset by 0.12345.
vec2 hexcMxHash(ivec2 id) {
    vec2 p = vec2(id) + vec2(0.12345);
    vec3 p3 = fract(vec3(p.x, p.y, p.x) * vec3(0.1031, 0.1030, 0.0973));
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.xx + p3.yz) * p3.zy);
}

// R(+angle) with cs = (cos, sin): MaterialX's mx_matrix_mul(v, mat2(c, -s, s, c)), written out so that no matrix
// layout convention can flip it between targets.
vec2 hexcMxRotate(vec2 v, vec2 cs) {
    return vec2(cs.x * v.x - cs.y * v.y, cs.y * v.x + cs.x * v.y);
}

// One tile: random numbers r = hash(id); angle mix(range, r.x) * rotation, scale mix(scalerange, r.y), offset
// r * offset (MaterialX's rotationrange, scalerange and offsetrange as hexc's reader maps them, docs/materialx.md);
// the sample point (st - c) R / scale + c + offset and the gradients R / scale.
HexcTap hexcMxTap(ivec2 id, vec2 st, vec2 dSTdx, vec2 dSTdy, HexcLattice l) {
    vec2 r = hexcMxHash(id);
    float angle = l.rotate ? radians(mix(l.rotationRange.x, l.rotationRange.y, r.x)) * l.rotation : 0.0;
    HexcTap tap;
    tap.rot = vec2(cos(angle), sin(angle));
    tap.invScale = 1.0 / mix(l.scaleRange.x, l.scaleRange.y, r.y);
    vec2 c = hexcTileCentre(id);
    tap.st = hexcMxRotate(st - c, tap.rot) * tap.invScale + c + r * l.offset;
    tap.dx = hexcMxRotate(dSTdx, tap.rot) * tap.invScale;
    tap.dy = hexcMxRotate(dSTdy, tap.rot) * tap.invScale;
    return tap;
}

HexcTiles hexcTilesMaterialX(vec2 st, vec2 dSTdx, vec2 dSTdy, HexcLattice l) {
    HexcTiles t;
    t.scaled = true;
    hexcTriangleGrid(st, t.w, t.id);
    t.channel = hexcHexChannels(t.id[0], t.id[2]);
    for (int i = 0; i < 3; ++i) t.tap[i] = hexcMxTap(t.id[i], st, dSTdx, dSTdy, l);
    return t;
}

// Schlick's gain (Graphics Gems IV), r clamped to [0.001, 0.999] as MaterialX does.
float hexcMxGain(float x, float r) {
    float rr = clamp(r, 0.001, 0.999);
    float a = (1.0 / rr - 2.0) * (1.0 - 2.0 * x);
    return x < 0.5 ? x / (a + 1.0) : (a - x) / (a - 1.0);
}

// luma * w^7, normalised; then the gain of each weight, normalised again, unless falloff is 0.5. Where every luma is 0
// (falloffcontrast 1 over three black taps) MaterialX divides 0 by 0; hexc weighs by the lattice alone (luma 1) there,
// which is the limit of a blend whose taps all have the same luma. The gain keeps a sum of 1 above 0 (one weight is >= 1/3).
vec3 hexcMxWeights(vec3 luma, vec3 w, float falloff) {
    vec3 w7 = hexcPowInt(w, 7), W = luma * w7;
    float sum = W.x + W.y + W.z;
    W = sum > 0.0 ? W / sum : w7 / (w7.x + w7.y + w7.z);
    if (falloff != 0.5) {
        W = vec3(hexcMxGain(W.x, falloff), hexcMxGain(W.y, falloff), hexcMxGain(W.z, falloff));
        W /= W.x + W.y + W.z;
    }
    return W;
}

// The sRGB decoding (IEC 61966-2-1, MaterialX's srgb_texture).
vec3 hexcMxDecode(vec3 c) {
    return mix(c / 12.92, pow(max(c + 0.055, vec3(0.0)) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

// A colour as MaterialX's srgb_texture gives it: decoded when `srgb` (a literal), else as it is.
vec4 hexcMxDecoded(vec4 c, bool srgb) {
    return srgb ? vec4(hexcMxDecode(c.rgb), c.a) : c;
}

// hextiledimage: the three taps weighed by their luma (mixed towards 1 by falloffcontrast), alpha by the lattice alone.
// `srgb` (a literal): an sRGB texture, bound with a linear (UNORM) format as MaterialX samples it: its stored
// (encoded) texels are filtered and blended, and the blend decoded (the manifest's `"decode": "shader"`).
vec4 hexcMxColor(texture2D tex, sampler samp, HexcTiles t, HexcBlend b, vec3 luma, bool srgb, out vec3 weights) {
    vec4 c1 = textureGrad(sampler2D(tex, samp), t.tap[0].st, t.tap[0].dx, t.tap[0].dy);
    vec4 c2 = textureGrad(sampler2D(tex, samp), t.tap[1].st, t.tap[1].dx, t.tap[1].dy);
    vec4 c3 = textureGrad(sampler2D(tex, samp), t.tap[2].st, t.tap[2].dx, t.tap[2].dy);
    vec3 cw = mix(vec3(1.0), vec3(dot(c1.rgb, luma), dot(c2.rgb, luma), dot(c3.rgb, luma)), b.falloffContrast);
    vec3 W = hexcMxWeights(cw, t.w, b.falloff);
    vec3 A = hexcMxWeights(vec3(1.0), t.w, b.falloff);
    weights = hexcShowWeights(W, t.channel);
    vec3 rgb = W.x * c1.rgb + W.y * c2.rgb + W.z * c3.rgb;
    return vec4(srgb ? hexcMxDecode(rgb) : rgb, A.x * c1.a + A.y * c2.a + A.z * c3.a);
}

// A tile's tangent-space normal as MaterialX turns it (T and B rotated about N by -angle: its xy by R(+angle)), as the
// surface gradient g = -n.xy / |n.z| of the unit normal. flipY: MaterialX's flip_g (1 - green before decoding). A texel
// of zero length (0.5, 0.5, 0.5), which MaterialX normalises to NaN, counts as the flat normal: gradient 0.
vec2 hexcMxGradient(texture2D tex, sampler samp, HexcTap tap, bool flipY) {
    vec3 m = textureGrad(sampler2D(tex, samp), tap.st, tap.dx, tap.dy).xyz;
    if (flipY) m.y = 1.0 - m.y;
    m = 2.0 * m - 1.0;
    float len = length(m);
    vec3 n = len > 0.0 ? vec3(hexcMxRotate(m.xy, tap.rot), m.z) / len : vec3(0.0, 0.0, 1.0);
    return -n.xy / max(1e-8, abs(n.z));
}

// hextilednormalmap: the tiles' gradients blended by the lattice weights (luma 1), clamped to [0, 1]. MaterialX's
// result normalize(N - sum W_i g_i) is hexc's normal from the derivative sum W_i g_i (hexcDerivToNormal).
vec2 hexcMxDeriv(texture2D tex, sampler samp, HexcTiles t, HexcBlend b, bool flipY, out vec3 weights) {
    vec3 W = clamp(hexcMxWeights(vec3(1.0), t.w, b.falloff), 0.0, 1.0);
    weights = hexcShowWeights(W, t.channel);
    return W.x * hexcMxGradient(tex, samp, t.tap[0], flipY) + W.y * hexcMxGradient(tex, samp, t.tap[1], flipY) +
           W.z * hexcMxGradient(tex, samp, t.tap[2], flipY);
}
