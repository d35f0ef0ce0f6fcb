#version 450
// A fragment shader written by hand (OpenGL GLSL 4.5) that hex-tiles a tangent-space normal map with hexc's
// library (docs/library.md). `hexc library --target glsl -o include/`; OpenGL has no #include: paste the file
// here, or let glslang read it (GL_GOOGLE_include_directive) or the driver (ARB_shading_language_include).
#include "hexc_hextiling.glsl"

layout(binding = 0, std140) uniform Settings {
    vec2 tiling;
    float rotation;
    float falloff;
    float falloffContrast;
    float exponent;
} settings;
layout(binding = 0) uniform sampler2D normalMap;  // texture unit 0: trilinear, repeat

layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 derivative;  // (dH/du, dH/dy, 0, 1), y up the image

void main() {
    vec2 st = uv * settings.tiling;
    HexcLattice lattice = hexcLattice();
    lattice.rotation = settings.rotation;
    lattice.rotate = settings.rotation != 0.0;
    HexcBlend blend = hexcBlend();
    blend.falloff = settings.falloff;
    blend.falloffContrast = settings.falloffContrast;
    blend.exponent = settings.exponent;
    blend.metric = settings.falloffContrast != 0.0;
    blend.gain = settings.falloff != 0.5;
    HexcTiles tiles = hexcTilesStable(st, dFdx(st), dFdy(st), ivec2(0), lattice);
    vec3 weights;
    // OpenGL GLSL: each texture is one sampler2D, after the other parameters (here the map and its height source).
    vec2 d = hexcDeriv(tiles, blend, false, weights, normalMap, normalMap);
    derivative = vec4(d, 0.0, 1.0);  // the normal is hexcDerivToNormal(d), in tangent space
}
