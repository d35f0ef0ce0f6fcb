#version 450
#extension GL_GOOGLE_cpp_style_line_directive : require
// `hexc library`: a fragment shader that calls each public function of hextiling.glsl once, so that glslang and
// SPIRV-Cross keep them (docs/library.md lists them). hexc emits it unoptimised, then cuts this entry point and
// its resources (named hexcLib*) away: what remains is the library, on each target.
#include <hexc/hextiling.glsl>

layout(set = 0, binding = 0) uniform texture2D hexcLibTexture;
layout(set = 0, binding = 1) uniform sampler hexcLibSampler;

void main() {
    vec2 st = vec2(0.0), dx = vec2(0.0), dy = vec2(0.0);
    HexcLattice l = hexcLattice();
    HexcBlend b = hexcBlend();
    vec3 w;
    HexcTiles t = hexcTilesStable(st, dx, dy, ivec2(0), l);
    t = hexcTilesPaper(st, dx, dy, l);
    t = hexcTilesChecker(st, dx, dy, ivec2(0), l);
    t = hexcTilesNoise(st, dx, dy, l);
    vec4 c = hexcColor(hexcLibTexture, hexcLibSampler, t, b, hexcLuma + hexcChannel(0), hexcLibTexture, w);
    c += hexcColor1(hexcLibTexture, hexcLibSampler, t, b, st, w) + vec4(hexcShowWeights(w, t.channel), 0.0);
    vec2 d = hexcDeriv(hexcLibTexture, hexcLibSampler, t, b, false, hexcLibTexture, w);
    d += hexcDeriv1(hexcLibTexture, hexcLibSampler, t, b, false, st, w);
    vec4 unused = c + vec4(hexcDerivToNormal(d), 0.0);  // no output: no stage interface to cut
}
