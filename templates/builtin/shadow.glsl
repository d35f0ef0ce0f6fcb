#version 450
// hexc template `shadow`: alpha-tested depth: discards where the hex-tiled albedo's alpha is below 0.5.
// Slots read: `albedo` (color), optional; without it the pass writes depth only.
layout(location = 0) in vec2 v_uv;

// hexc slot albedo color
#include <hexc>

void main() {
#ifdef HEXC_HAS_albedo
    if (hexc_albedo(v_uv).a < 0.5) discard;
#endif
}
