#version 450
// hexc-bench-shaders op cost: 16 x vec4 = 64 dependent pow per pixel.
// The time above baseline.glsl's, divided by the operations added, is what one costs on the device.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

#include <hexc>

void main() {
    // Starting from a texture sample and uv keeps every value per-pixel, so nothing folds to a constant.
    vec4 x = hexc_albedo(v_uv) + v_uv.xyxy;
    for (int i = 0; i < 16; ++i) x = pow(x, vec4(0.97)) + 0.25;
    o_color = x;
}
