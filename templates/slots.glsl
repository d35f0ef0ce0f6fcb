// hexc per-slot snippets. codegen picks one section per slot (`//@ <kind>.<hex|hex1|plain>`) and the resource
// sections, and replaces the $placeholders: $name (slot name), $binding, $tiling, $rotation, $falloff,
// $falloffcontrast, $exponent, $origincell, $originoffset (uniform members, constants or literals),
// $lattice (a `lattice.*` section), $tf (a HexcTransform), $transform, $rotate, $metric, $gain, $exponentint, $gainint (literal feature
// switches and whole-number exponents, 0 = none), $luma, $channel,
// $flipy, $kind, $members, $constants.
// Each slot gets `hexc_$name(vec2 uv)` and an overload with `out vec3 weights` (Listing 7 hex weights).

//@ params
layout(set = 0, binding = 0, std140) uniform HexcParams {
$members
} hexcParams;

//@ constant
layout(constant_id = $id) const $type $name = $value;

//@ constant.vec2
layout(constant_id = $id) const float $name_x = $x;
layout(constant_id = $idy) const float $name_y = $y;
const vec2 $name = vec2($name_x, $name_y);

//@ sampler
layout(set = 0, binding = $binding) uniform sampler hexcSampler;

//@ first
#define HEXC_FIRST_SLOT hexc_$name
#define HEXC_FIRST_KIND_$kind 1

//@ texture
layout(set = 0, binding = $binding) uniform texture2D hexcTex_$name;
#define HEXC_HAS_$name 1

//@ transform
HexcTransform($rotationrange, $rotationsteps, $scalerange, $offset, ivec2($offsetstepsx, $offsetstepsy))

//@ lattice.paper
hexcTilesPaper(uv * $tiling, $rotation, $rotate)

//@ lattice.stable
hexcTilesStable(uv * $tiling, $rotation, $rotate, $transform, $tf)

//@ lattice.split
hexcTilesStableSplit(uv * $tiling, $origincell, $originoffset, $rotation, $rotate, $transform, $tf)

//@ color.hex
vec4 hexc_$name(vec2 uv, out vec3 weights) {
    return hexcColor(hexcTex_$name, hexcSampler, $lattice, $falloff, $falloffcontrast, $exponent, $luma, $metric, $gain, $exponentint, $gainint, weights);
}
vec4 hexc_$name(vec2 uv) { vec3 weights; return hexc_$name(uv, weights); }

//@ color.hex1
vec4 hexc_$name(vec2 uv, out vec3 weights) {
    return hexcColor1(hexcTex_$name, hexcSampler, $lattice, $falloff, $exponent, $gain, $exponentint, $gainint, weights);
}
vec4 hexc_$name(vec2 uv) { vec3 weights; return hexc_$name(uv, weights); }

//@ color.plain
vec4 hexc_$name(vec2 uv, out vec3 weights) {
    return hexcPlainColor(hexcTex_$name, hexcSampler, uv * $tiling, weights);
}
vec4 hexc_$name(vec2 uv) { vec3 weights; return hexc_$name(uv, weights); }

//@ scalar.hex
float hexc_$name(vec2 uv, out vec3 weights) {
    return hexcColor(hexcTex_$name, hexcSampler, $lattice, $falloff, $falloffcontrast, $exponent, $luma, $metric, $gain, $exponentint, $gainint, weights).$channel;
}
float hexc_$name(vec2 uv) { vec3 weights; return hexc_$name(uv, weights); }

//@ scalar.hex1
float hexc_$name(vec2 uv, out vec3 weights) {
    return hexcColor1(hexcTex_$name, hexcSampler, $lattice, $falloff, $exponent, $gain, $exponentint, $gainint, weights).$channel;
}
float hexc_$name(vec2 uv) { vec3 weights; return hexc_$name(uv, weights); }

//@ scalar.plain
float hexc_$name(vec2 uv, out vec3 weights) {
    return hexcPlainColor(hexcTex_$name, hexcSampler, uv * $tiling, weights).$channel;
}
float hexc_$name(vec2 uv) { vec3 weights; return hexc_$name(uv, weights); }

//@ normal.hex
vec2 hexc_$name(vec2 uv, out vec3 weights) {
    return hexcDeriv(hexcTex_$name, hexcSampler, $lattice, $falloff, $falloffcontrast, $exponent, $flipy, $metric, $gain, $exponentint, $gainint, weights);
}
vec2 hexc_$name(vec2 uv) { vec3 weights; return hexc_$name(uv, weights); }

//@ normal.hex1
vec2 hexc_$name(vec2 uv, out vec3 weights) {
    return hexcDeriv1(hexcTex_$name, hexcSampler, $lattice, $falloff, $exponent, $flipy, $gain, $exponentint, $gainint, weights);
}
vec2 hexc_$name(vec2 uv) { vec3 weights; return hexc_$name(uv, weights); }

//@ normal.plain
vec2 hexc_$name(vec2 uv, out vec3 weights) {
    return hexcPlainDeriv(hexcTex_$name, hexcSampler, uv * $tiling, $flipy, weights);
}
vec2 hexc_$name(vec2 uv) { vec3 weights; return hexc_$name(uv, weights); }
