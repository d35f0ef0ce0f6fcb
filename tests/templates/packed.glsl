#version 450
// Test template for packed slots (tests/execution/cases_test.cpp, PackedPath): reads every slot of a packing test, so they
// pack, and shows them in one image: slot `color`'s RGB with slot `s3` in alpha, else scalar slots s0..s3 in R, G, B, A.
// Stage inputs: location 0 = texture coordinate.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

#include <hexc>

void main() {
#ifdef HEXC_HAS_color
    o_color = vec4(hexc_color(v_uv).rgb, hexc_s3(v_uv));
#else
    o_color = vec4(hexc_s0(v_uv), hexc_s1(v_uv), hexc_s2(v_uv), hexc_s3(v_uv));
#endif
}
