#version 450
// The precision harness's aligned views (docs/precision.md): slot `s` at the rasterised uv, tiling 4, sampled
// with the gradients of one texel per pixel of the 256-texel probe textures whatever float32 resolves at that
// uv. Far from the origin neighbouring pixels then land one ulp of uv apart, each reading mip level 0, so a
// wrong tile shows as a wrong texel instead of vanishing in the last mip levels. It calls what hexc_s calls,
// hexcAt_s(st, dst/dx, dst/dy, split cell, weights), with its own gradients; naming hexc_s in this comment
// keeps the slot in the shader (docs/templates.md: a slot the template never mentions is left out).
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

#include <hexc>

void main() {
    vec3 weights;
    const vec2 texel = vec2(1.0 / 256.0, 0.0);  // in st
#if defined(HEXC_FIRST_KIND_normal)
    o_color = vec4(hexcAt_s(v_uv * 4.0, texel.xy, texel.yx, ivec2(0), weights), 0.0, 1.0);
#else
    o_color = hexcAt_s(v_uv * 4.0, texel.xy, texel.yx, ivec2(0), weights);
#endif
}
