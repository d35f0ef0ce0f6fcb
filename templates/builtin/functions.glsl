#version 450
// hexc template `functions` (hexc --functions, docs/engines.md): no shader of its own, but every slot's function
// for an engine to call from its own material: hexc_<slot>(uv), and hexc_<slot>_normal(uv) for a normal slot. Its
// main only calls each of them (hexcEngineCalls), so that they are compiled and kept; hexc cuts main and the stage
// input and output below from what it writes.
// Stage inputs: location 0 = texture coordinate.
#include <hexc>

layout(location = 0) in vec2 hexcEngineUv;
layout(location = 0) out vec4 hexcEngineOut;

void main() {
    hexcEngineOut = hexcEngineCalls(hexcEngineUv);
}
