#version 450
// hexc-bench-shaders op cost: 16 dependent textureGrad per pixel with the view's own gradients.
// The time above baseline.glsl's, divided by the operations added, is what one costs on the device.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

#include <hexc>

void main() {
    vec2 st = v_uv * 4.0;  // the bench material's tiling, so the sampled mip level matches its slots'
    vec2 dx = dFdx(st), dy = dFdy(st);
    // Starting from a texture sample and uv keeps every value per-pixel, so nothing folds to a constant.
    vec4 x = hexc_albedo(v_uv) + v_uv.xyxy;
    // Each sample point moves by less than a texel with the previous result: dependent, yet as coherent
    // between neighbouring pixels as the samples inside one hex tile.
    for (int i = 0; i < 16; ++i) x = textureGrad(sampler2D(hexcTex_albedo, hexcSampler), st + x.xy * 0.001, dx, dy) + 0.25;
    o_color = x;
}
