#version 450
// Test template for packed layers (tests/plan/layers_test.cpp, APackedTextureIsCountedOncePerRead): reads the albedo and
// height roles of tests/execution/layers/four_packed.json, whose layers pack the height into the albedo's alpha.
// Stage inputs: location 0 = texture coordinate.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

#include <hexc>

void main() { o_color = vec4(hexc_albedo(v_uv).rgb, hexc_height(v_uv)); }
