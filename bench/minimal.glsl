#version 450
// Bench template: the three slots with almost no shading (their sum), so that the texture work dominates the frame:
// the minimal shading the paper listing is also timed with (bench/paper-listing.glsl, PAPER_LISTING_MINIMAL).
// Reads `albedo`, `normal` and `roughness`.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

#include <hexc>

void main() {
    vec2 deriv = hexc_normal(v_uv);
    o_color = vec4(hexc_albedo(v_uv).rgb + vec3(hexc_roughness(v_uv)) + vec3(deriv, 0.0), 1.0);
}
