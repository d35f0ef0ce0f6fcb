// hexc layered materials (docs/material-format.md#layers). Each role the template reads, hexc_<role>, blends the
// layers' slots (hexcAt_<layer>_<role>, templates/library/slots.glsl) by the layers' weights at the pixel. The
// gradients are taken once, before the layers' branches, and every layer's slot is sampled with them: a derivative
// inside a branch that not every pixel of a quad takes is undefined (and WGSL refuses it). codegen (codegen/layers.cpp)
// fills the tokens: ${skip}, ${width}: literals (parameters in general code); ${keep_below}: ${skip}, or 0 in height
// mode, where the height blend drops its shares below ${skip} instead; ${splats}, ${keep}, ${heights}, ${layers}: the
// per-splat and per-layer lines below; ${index}, ${splat}, ${channel}, ${slot}, ${tiling}; ${role}, ${type}, ${uv};
// ${location}: the vertex colour input's; ${fetched}: when layer ${index}'s slot is fetched (layer.kept, or layer.every when CompileOptions::skipLayers is off).
// The vertex colour (weights "vertex" or "both"): ${color}, what the weights read (the stage input hexcVertexColor in a
// shader, the parameter `color` in the functions output, whose functions take it after uv: ${color_param} declares it
// and ${color_arg} passes it on; both empty otherwise).
// Weights are arrays of 8, hexc's most layers; those past the material's stay 0.
// What the roles share is read once per pixel: the first role read at a coordinate fills the weights (the splat maps,
// and in height mode each kept layer's height) into private variables, and every later role read at that coordinate
// takes them from there (a template that reads roles at several coordinates, e.g. a parallax search, gets each
// coordinate's weights). Each role function holds the fill behind that test; only the first read at a uv runs it.
// The tiles of each distinct lattice (a tiling and lattice settings) are shared the same way, by every layer and role
// reading it: the fill computes them once per pixel (${lattices}: a `weights.lattice` line per lattice) where a layer
// reading the lattice is kept (${kept}), before the heights read them, and the slots read them (${tiles}: `lattice.call`).
// In `lattice`, the function computing them, ${tiles} is the lattice's `lattice.*` section of slots.glsl and
// ${settings} its HexcLattice in general code. The functions output shares none: each slot computes its own tiles.

//@ functions
// Drops the weights below `skip` (their layers are not fetched) and renormalises the others to sum 1; where every
// weight is dropped (an unpainted texel), layer 0 shows.
void hexcLayerKeep(inout float w[8], float skip) {
    float sum = 0.0;
    for (int i = 0; i < 8; ++i) {
        w[i] = w[i] >= skip ? w[i] : 0.0;
        sum += w[i];
    }
    if (sum <= 0.0) {
        w[0] = 1.0;
        sum = 1.0;
    }
    for (int i = 0; i < 8; ++i) w[i] /= sum;
}

// The height blend: a kept layer shows where its height plus its weight comes within `width` of the highest such sum,
// in proportion to how far within; the layer on top always shows, so the sum is positive. Then the shares below
// `skip` are dropped (their layers' roles are not fetched) and the others renormalised: skipping acts on the shares the
// heights leave, so it moves the blend by at most the dropped shares (docs/material-format.md#layers). The top's share
// is kept whatever `skip` is: the threshold is at most its b.
void hexcLayerHeights(inout float w[8], float h[8], float width, float skip) {
    float top = -2.0;  // below any height (in [0, 1]) plus weight (in [0, 1])
    for (int i = 0; i < 8; ++i)
        if (w[i] > 0.0) top = max(top, h[i] + w[i]);
    float sum = 0.0;
    for (int i = 0; i < 8; ++i) {
        w[i] = w[i] > 0.0 ? max(h[i] + w[i] - top + width, 0.0) : 0.0;
        sum += w[i];
    }
    hexcLayerKeep(w, min(skip * sum, width));  // b_i / sum >= skip; the top's b is width
}

//@ weights
// The layers' weights at st (hexc's uv), with its gradients dx, dy: layer i's splat channel, vertex colour channel or
// their product, kept and renormalised.
void hexcLayerFill(vec2 st, vec2 dx, vec2 dy${color_param}, out float w[8]) {
    vec3 t;
    for (int i = 0; i < 8; ++i) w[i] = 0.0;
${splats}
${keep}
    hexcLayerKeep(w, ${keep_below});
${lattices}
${heights}
}

//@ shared
// The pixel's weights, filled by its first role read (or a read at another coordinate) and shared by the others.
bool hexcLayersFilled = false;
vec2 hexcLayersSt;
float hexcLayersW[8];
void hexcLayerWeights(vec2 st, vec2 dx, vec2 dy, out float w[8]) {
    if (!hexcLayersFilled || st != hexcLayersSt) {
        hexcLayerFill(st, dx, dy, hexcLayersW);
        hexcLayersFilled = true;
        hexcLayersSt = st;
    }
    w = hexcLayersW;
}

//@ shared.functions
// The functions output has no main of its own, and a global's initialiser is a store in main (glslang), so shared
// state would start undefined in an engine's shader: each role fills its own weights there.
void hexcLayerWeights(vec2 st, vec2 dx, vec2 dy${color_param}, out float w[8]) {
    hexcLayerFill(st, dx, dy${color_arg}, w);
}

//@ lattice
// Lattice ${index}'s tiles at st.
HexcTiles hexcLayerTiles${index}(vec2 st, vec2 dx, vec2 dy, ivec2 cell) {
${settings}
    return ${tiles};
}

//@ lattice.shared
// Lattice ${index}'s tiles at the coordinate of the pixel's weights, filled with them (hexcLayerFill).
HexcTiles hexcLatticeTiles${index};

//@ lattice.call
hexcLatticeTiles${index}

//@ lattice.call.functions
hexcLayerTiles${index}(st, dx, dy, cell)

//@ weights.lattice
    if (${kept}) hexcLatticeTiles${index} = hexcLayerTiles${index}(st * ${tiling}, dx * ${tiling}, dy * ${tiling}, ivec2(0));

//@ weights.splat
    vec4 splat${index} = hexcAt_splat${index}(st * ${tiling}, dx * ${tiling}, dy * ${tiling}, ivec2(0), t);

//@ weights.layer
    w[${index}] = splat${splat}[${channel}];

//@ weights.layer.vertex
    w[${index}] = clamp(${color}[${index}], 0.0, 1.0);

//@ weights.layer.both
    w[${index}] = splat${splat}[${channel}] * clamp(${color}[${index}], 0.0, 1.0);

//@ color.parameter
, vec4 color
//@ color.argument
, color
//@ vertex.input
// The vertex colour, interpolated: channel i weighs layer i (`weights` "vertex" or "both"); clamped to [0, 1].
layout(location = ${location}) in vec4 hexcVertexColor;

//@ weights.heights
    // Each layer's height where its weight is above 0, for the height blend (which then drops the shares below skip).
    float h[8];
    for (int i = 0; i < 8; ++i) h[i] = 0.0;
${layers}
    hexcLayerHeights(w, h, ${width}, ${skip});

//@ weights.height
    if (${fetched}) h[${index}] = hexcAt_${slot}(st * ${tiling}, dx * ${tiling}, dy * ${tiling}, ivec2(0), t);

//@ role
// The layers' `${role}` slots blended by the layers' weights; a layer of weight 0 is not fetched.
${type} hexc_${role}(vec2 uv${color_param}, out vec3 weights) {
    vec2 st = ${uv};
    vec2 dx = dFdx(st), dy = dFdy(st);
    float w[8];
    hexcLayerWeights(st, dx, dy${color_arg}, w);
    ${type} value = ${type}(0.0);
    vec3 t;
    weights = vec3(0.0);
${layers}
    return value;
}
${type} hexc_${role}(vec2 uv${color_param}) { vec3 weights; return hexc_${role}(uv${color_arg}, weights); }
#define HEXC_HAS_${role} 1

//@ role.layer
    if (${fetched}) {
        value += w[${index}] * hexcAt_${slot}(st * ${tiling}, dx * ${tiling}, dy * ${tiling}, ivec2(0), t);
        weights += w[${index}] * t;
    }

//@ layer.kept
w[${index}] > 0.0
//@ layer.every
true
