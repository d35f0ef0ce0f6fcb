#version 450
// hexc-bench-shaders op cost, the floor: one texture sample, a loop of 16 dependent vec4 multiply-adds and the
// full-screen draw. The other op-cost templates replace the multiply-add with the operation they measure.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

#include <hexc>

void main() {
    // Starting from a texture sample and uv keeps every value per-pixel, so nothing folds to a constant.
    vec4 x = hexc_albedo(v_uv) + v_uv.xyxy;
    for (int i = 0; i < 16; ++i) x = x * 0.97 + 0.25;
    o_color = x;
}
