#version 450
// hexc template `unlit`: writes the hex-tiled colour of slot `albedo` (alpha included).
// Stage inputs: location 0 = texture coordinate; with the triplanar projection instead location 1 = surface
// normal and 3 = position, in world space.
// hexc slot albedo color required
#include <hexc>

#ifdef HEXC_PROJECTION_triplanar
layout(location = 1) in vec3 v_normal;
layout(location = 3) in vec3 v_position;
#else
layout(location = 0) in vec2 v_uv;
#endif
layout(location = 0) out vec4 o_color;

void main() {
#if defined(HEXC_HAS_albedo) && defined(HEXC_PROJECTION_triplanar)
    o_color = hexc_albedo(v_position, v_normal);
#elif defined(HEXC_HAS_albedo)
    o_color = hexc_albedo(v_uv);
#else
#error template `unlit` needs a colour slot named `albedo`
#endif
}
