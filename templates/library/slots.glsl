// hexc per-slot snippets. codegen picks, per slot, a sampling section
// (`//@ <kind>.<hex|hex1|plain|histogram|packed|materialx>`), which
// defines `hexcAt_${name}` (the slot at st with its gradients and split-coordinates cell), and a coordinates section
// (`uv`, `uv.split`, `triplanar`), which defines the public `hexc_${name}` from it; plus the resource sections.
// Tokens `${...}` are replaced in one pass; one codegen does not know is an error. ${name}: the slot's name;
// ${set}, ${binding}: hexc's descriptors (plan.h, HexcBindings); ${tiling}, ${planesharpness}, ${origincell}, ${originoffset}: the parameters (uniform members or
// constants) the coordinates read; ${tiles}: the slot's `lattice.*` section; ${settings}: the `settings.*` sections,
// which build the HexcLattice `lattice` and HexcBlend `blend` (templates/library/hextiling.glsl) the library's functions
// take, in general code, with every setting of the slot; otherwise empty: every setting, a parameter's as its read, is
// folded into the functions, which take no struct, and the calls drop it (codegen/assembly.h); ${fields}:
// the `set` lines filling one; ${heighttex}: the
// texture variable of the slot holding its heights (its own when it blends by none); ${channel}: a scalar slot's channel
// (0 = r ... 3 = a); ${flipy}, ${explicit}, ${srgb} (MaterialX mode's shader decodes sRGB): literal switches; ${type}: the slot's result type; ${kind},
// ${projection}; ${tex}: the slot's texture variable (hexcTex_<slot>, or a layered role's
// array hexcArr_<role>, which the slot's library functions read at its layer); ${uv}: the uv in hexc's convention (origin top-left, v down), from the engine's (CompileOptions::uvOrigin); ${calls}: the `engine.call.*` lines (after `engine.color` when the functions take the vertex colour, which ${color_param} declares and ${color_arg} passes: templates/library/layers.glsl); ${texture}: a packed slot's texture; ${members}; ${struct}, ${field}, ${value}; ${id}, ${idy}, ${x}, ${y}.
// Each slot gets `hexc_${name}(...)` and an overload with `out vec3 weights` (the weights output).

//@ params
layout(set = ${set}, binding = ${binding}, std140) uniform HexcParams {
${members}
} hexcParams;

//@ constant
layout(constant_id = ${id}) const ${type} ${name} = ${value};

//@ constant.vec2
layout(constant_id = ${id}) const float ${name}_x = ${x};
layout(constant_id = ${idy}) const float ${name}_y = ${y};
const vec2 ${name} = vec2(${name}_x, ${name}_y);

//@ sampler
layout(set = ${set}, binding = ${binding}) uniform sampler hexcSampler;

//@ first
#define HEXC_FIRST_SLOT hexc_${name}
#define HEXC_FIRST_KIND_${kind} 1
#define HEXC_PROJECTION_${projection} 1

//@ texture
layout(set = ${set}, binding = ${binding}) uniform texture2D hexcTex_${name};
#define HEXC_HAS_${name} 1

//@ texture.array
// A layered role's textures across layers, one per layer (docs/material-format.md#texture-arrays).
layout(set = ${set}, binding = ${binding}) uniform texture2DArray ${variable};
#define HEXC_HAS_${name} 1

//@ has
// A packed slot whose texture is another slot's (docs/material-format.md#pack).
#define HEXC_HAS_${name} 1

//@ lut
layout(set = ${set}, binding = ${binding}) uniform texture2D hexcLut_${name};

//@ set
    ${struct}.${field} = ${value};

//@ settings.lattice
    HexcLattice lattice = hexcLattice();
${fields}

//@ settings.blend
    HexcBlend blend = hexcBlend();
${fields}

//@ lattice.paper
hexcTilesPaper(st, dx, dy, lattice)

//@ lattice.stable
hexcTilesStable(st, dx, dy, cell, lattice)

//@ lattice.periodic
hexcTilesPeriodic(st, dx, dy, ${period}, ${repeats}, lattice)

//@ lattice.checker.periodic
hexcTilesCheckerPeriodic(st, dx, dy, ${cells}, lattice)

//@ lattice.checker
hexcTilesChecker(st, dx, dy, cell, lattice)

//@ lattice.noise
hexcTilesNoise(st, dx, dy, lattice)

//@ color.hex
vec4 hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
${settings}
    return hexcColor(${tex}, hexcSampler, ${tiles}, blend, hexcLuma, ${heighttex}, weights);
}

//@ color.hex1
vec4 hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
${settings}
    return hexcColor1(${tex}, hexcSampler, ${tiles}, blend, gl_FragCoord.xy, weights);
}

//@ color.plain
// ${srgb}: MaterialX mode's sRGB texture, bound as stored and decoded after filtering (as MaterialX's <image>).
vec4 hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
    return hexcMxDecoded(${plain}(${tex}, hexcSampler, st, dx, dy, weights), ${srgb});
}

//@ color.histogram
// The histogram-preserving blend: hexcTex_ holds the Gaussian texture hexc derived, hexcLut_ the inverse transform.
vec4 hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
${settings}
    return hexcHistogram(${tex}, hexcLut_${name}, hexcSampler, ${tiles}, blend, dx, dy, false, weights);
}

//@ color.packed
// The packed texture ${texture} holds this slot's RGB; its alpha another slot's channel, so the slot's alpha is 1, as
// its opaque texture's was. The fetches are those of the pack's other slots (same lattice, same texture): hexc merges
// them into one set of taps (spirv/share.h).
vec4 hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
${settings}
    return vec4(hexcColor(${texture}, hexcSampler, ${tiles}, blend, hexcLuma, ${texture}, weights).rgb, 1.0);
}

//@ scalar.packed
// The packed texture ${texture} holds this slot's value in channel ${channel}.
float hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
${settings}
    return hexcColor(${texture}, hexcSampler, ${tiles}, blend, hexcChannel(${channel}), ${texture}, weights)[${channel}];
}

//@ scalar.histogram
// The Gaussian texture holds the slot's channel in r.
float hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
${settings}
    return hexcHistogram(${tex}, hexcLut_${name}, hexcSampler, ${tiles}, blend, dx, dy, true, weights).r;
}

//@ scalar.hex
// Scalar maps weigh tiles by their own channel.
float hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
${settings}
    return hexcColor(${tex}, hexcSampler, ${tiles}, blend, hexcChannel(${channel}), ${heighttex}, weights)[${channel}];
}

//@ scalar.hex1
float hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
${settings}
    return hexcColor1(${tex}, hexcSampler, ${tiles}, blend, gl_FragCoord.xy, weights)[${channel}];
}

//@ scalar.plain
float hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
    return hexcMxDecoded(${plain}(${tex}, hexcSampler, st, dx, dy, weights), ${srgb})[${channel}];
}

//@ normal.hex
vec2 hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
${settings}
    return hexcDeriv(${tex}, hexcSampler, ${tiles}, blend, ${flipy}, ${heighttex}, weights);
}

//@ normal.hex1
vec2 hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
${settings}
    return hexcDeriv1(${tex}, hexcSampler, ${tiles}, blend, ${flipy}, gl_FragCoord.xy, weights);
}

//@ normal.plain
vec2 hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
    return hexcNormalToDeriv(2.0 * ${plain}(${tex}, hexcSampler, st, dx, dy, weights).xyz - 1.0, ${flipy});
}

//@ uv
${type} hexc_${name}(vec2 uv, out vec3 weights) {
    vec2 st = ${uv} * ${tiling};
    return hexcAt_${name}(st, dFdx(st), dFdy(st), ivec2(0), weights);
}
${type} hexc_${name}(vec2 uv) { vec3 weights; return hexc_${name}(uv, weights); }

//@ uv.split
// uv relative to the per-frame origin, whose cell and offset the engine fills (docs/precision.md).
${type} hexc_${name}(vec2 uv, out vec3 weights) {
    vec2 st = ${uv} * ${tiling};
    return hexcAt_${name}(${originoffset} + st, dFdx(st), dFdy(st), ${origincell}, weights);
}
${type} hexc_${name}(vec2 uv) { vec3 weights; return hexc_${name}(uv, weights); }

//@ triplanar
${type} hexc_${name}(vec3 position, vec3 normal, out vec3 weights) {
    HexcPlanes p = hexcPlanes(position, normal, ${planesharpness}, ${tiling});
    ${type} value = ${type}(0.0);
    vec3 w;
    weights = vec3(0.0);
    // Planes of weight 0 are skipped: most pixels of a mesh face one or two planes.
    if (p.b.x > 0.0) { value += p.b.x * hexcLift(0, hexcAt_${name}(p.st[0], p.dx[0], p.dy[0], ivec2(0), w)); weights += p.b.x * w; }
    if (p.b.y > 0.0) { value += p.b.y * hexcLift(1, hexcAt_${name}(p.st[1], p.dx[1], p.dy[1], ivec2(0), w)); weights += p.b.y * w; }
    if (p.b.z > 0.0) { value += p.b.z * hexcLift(2, hexcAt_${name}(p.st[2], p.dx[2], p.dy[2], ivec2(0), w)); weights += p.b.z * w; }
    return hexcFinish(value, p.n);
}
${type} hexc_${name}(vec3 position, vec3 normal) { vec3 weights; return hexc_${name}(position, normal, weights); }

//@ lattice.materialx
hexcTilesMaterialX(st, dx, dy, lattice)

//@ color.materialx
// MaterialX mode (templates/library/materialx.glsl): ${luma} its lumacoeffs, ${srgb} whether the texture is sRGB.
vec4 hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
${settings}
    return hexcMxColor(${tex}, hexcSampler, ${tiles}, blend, ${luma}, ${srgb}, weights);
}

//@ scalar.materialx
// MaterialX's extract of a hextiledimage: the colour blended by its luma, then the channel.
float hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
${settings}
    return hexcMxColor(${tex}, hexcSampler, ${tiles}, blend, ${luma}, ${srgb}, weights)[${channel}];
}

//@ normal.materialx
vec2 hexcAt_${name}(vec2 st, vec2 dx, vec2 dy, ivec2 cell, out vec3 weights) {
${settings}
    return hexcMxDeriv(${tex}, hexcSampler, ${tiles}, blend, ${flipy}, weights);
}

//@ uv.topleft
uv

//@ uv.bottomleft
vec2(uv.x, 1.0 - uv.y)

//@ engine.normal
// A normal slot's tangent-space normal, as a green-up (OpenGL convention) normal map texel holds it: x along +u, y up
// the image, z out of the surface; what an engine's normal input takes.
vec3 hexc_${name}_normal(vec2 uv${color_param}) {
    return hexcDerivToNormal(hexc_${name}(uv${color_arg}));
}

//@ engine.calls
// The `functions` template's main calls every engine function once, so that each is kept (as a function: hexc marks
// them not to be inlined) and its resources declared; the text from main on is cut from the outputs.
vec4 hexcEngineCalls(vec2 uv) {
    vec4 sum = vec4(0.0);
${calls}
    return sum;
}

//@ engine.color
    vec4 color = vec4(uv, uv);  // the vertex colour the calls pass, when they take one: any value, as main is cut

//@ engine.call.color
    sum += hexc_${name}(uv${color_arg});

//@ engine.call.scalar
    sum.x += hexc_${name}(uv${color_arg});

//@ engine.call.normal
    sum.xy += hexc_${name}(uv${color_arg});
    sum.xyz += hexc_${name}_normal(uv${color_arg});
