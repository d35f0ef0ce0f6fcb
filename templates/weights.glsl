#version 450
// hexc template `weights`: the hex-tile weights of the first slot (Listing 7), one colour per tile.
// Stage inputs: location 0 = texture coordinate.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

#include <hexc>

void main() {
    vec3 weights;
    HEXC_FIRST_SLOT(v_uv, weights);
    o_color = vec4(weights, 1.0);
}
