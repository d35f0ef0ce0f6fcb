#version 450
// hexc template `unlit`: writes the hex-tiled colour of slot `albedo` (alpha included).
// Stage inputs: location 0 = texture coordinate.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

#include <hexc>

void main() {
#ifdef HEXC_HAS_albedo
    o_color = hexc_albedo(v_uv);
#else
#error template `unlit` needs a colour slot named `albedo`
#endif
}
