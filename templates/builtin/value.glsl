#version 450
// hexc template `value`: the first slot's raw blended result, for inspection and testing:
// color -> RGBA, scalar -> (s, s, s, 1), normal -> the height derivative (dH/du, dH/dy, 0, 1), y = -v up the texture.
// A triplanar material is shown on the unit sphere (hexcPreviewSphere) and a normal slot as its surface
// gradient (x, y, z, 1).
// Stage inputs: location 0 = texture coordinate.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

#include <hexc>

void main() {
#if defined(HEXC_PROJECTION_triplanar)
    vec3 position, normal;
    hexcPreviewSphere(v_uv, position, normal);
#define HEXC_INPUTS position, normal
#define HEXC_DERIV_PAD 1.0
#else
#define HEXC_INPUTS v_uv
#define HEXC_DERIV_PAD 0.0, 1.0
#endif
#if defined(HEXC_FIRST_KIND_normal)
    o_color = vec4(HEXC_FIRST_SLOT(HEXC_INPUTS), HEXC_DERIV_PAD);
#elif defined(HEXC_FIRST_KIND_scalar)
    o_color = vec4(vec3(HEXC_FIRST_SLOT(HEXC_INPUTS)), 1.0);
#else
    o_color = HEXC_FIRST_SLOT(HEXC_INPUTS);
#endif
}
