#version 450
// hexc template `weights`: the hex-tile weights of the first slot (Listing 7), one colour per tile.
// Stage inputs: location 0 = texture coordinate.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

#include <hexc>

void main() {
    vec3 weights;
#if defined(HEXC_PROJECTION_triplanar)
    // A triplanar material on the unit sphere, as in the `value` template.
    vec3 position, normal;
    hexcPreviewSphere(v_uv, position, normal);
    HEXC_FIRST_SLOT(position, normal, weights);
#else
    HEXC_FIRST_SLOT(v_uv, weights);
#endif
    o_color = vec4(weights, 1.0);
}
