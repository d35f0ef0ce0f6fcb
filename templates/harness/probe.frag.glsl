#version 450
// What the rasteriser hands a fragment shader: the interpolated uv and its screen-space derivatives, as
// float32. The precision tests evaluate the CPU reference at exactly these inputs.
// mode 0 writes (u, v, du/dx, dv/dx); mode 1 writes (du/dy, dv/dy, 0, 1).
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_probe;

layout(set = 0, binding = 0, std140) uniform Probe {
    int mode;
} probe;

void main() {
    o_probe = probe.mode == 0 ? vec4(v_uv, dFdx(v_uv)) : vec4(dFdy(v_uv), 0.0, 1.0);
}
