#version 300 es
// hexc edit's display pass: one triangle over the viewport (no vertex buffers), texture coordinates 0..1 on it.
out vec2 v_screen;

void main() {
    vec2 t = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(t * 2.0 - 1.0, 0.0, 1.0);
    v_screen = t;
}
