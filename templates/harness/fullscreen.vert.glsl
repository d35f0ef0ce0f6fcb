#version 450
// Full-screen triangle for rendering a material over a UV rectangle (used by the lavapipe runner, preview, bench).
// No vertex buffers: vertex 0, 1, 2 sit at NDC (-1,-1), (3,-1), (-1,3), a triangle that covers the viewport.
//
// UV mapping: view.uvRect = (u0, v0, u1, v1). NDC x = -1 -> u0, x = +1 -> u1; NDC y = -1 (the top row in Vulkan)
// -> v0, y = +1 -> v1. UV is interpolated linearly in screen space, so in a W x H render the centre of pixel
// (i, j), row j = 0 at the top, receives
//     uv = (u0 + (i + 0.5) / W * (u1 - u0),  v0 + (j + 0.5) / H * (v1 - v0)).
// The surface is flat and faces the viewer: normal (0,0,1), tangent (1,0,0) with handedness +1.
// The vertex colour (a layered material's vertex weights) varies over the view, affine in screen space as the
// triangle interpolates it: at pixel (i, j), with x = (i + 0.5) / W and y = (j + 0.5) / H,
//     colour = (1 - x, x, y, 1 - y)
// (reference/layers.h, vertexColorAt, evaluates the same).

layout(push_constant) uniform View {
    vec4 uvRect;  // u0, v0, u1, v1
} view;

layout(location = 0) out vec2 v_uv;
layout(location = 1) out vec3 v_normal;
layout(location = 2) out vec4 v_tangent;
layout(location = 3) out vec3 v_position;  // (u, v, 0): the plane z = 0, for triplanar materials
layout(location = 4) out vec4 v_color;     // the location hexc gives the vertex colour in a template using 0-3

void main() {
    // t = (0,0), (2,0), (0,2): 0 at NDC -1, 1 at NDC +1 on each axis.
    vec2 t = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    gl_Position = vec4(t * 2.0 - 1.0, 0.0, 1.0);
    v_uv = view.uvRect.xy + t * (view.uvRect.zw - view.uvRect.xy);
    v_normal = vec3(0.0, 0.0, 1.0);
    v_tangent = vec4(1.0, 0.0, 0.0, 1.0);
    v_position = vec3(v_uv, 0.0);
    v_color = vec4(1.0 - t.x, t.x, t.y, 1.0 - t.y);
}
