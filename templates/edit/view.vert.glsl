#version 300 es
// The vertex stage of `hexc edit`'s page (WebGL 2): feeds a fragment shader hexc emitted for GLSL ES 3.00 the inputs
// hexc's templates read, by location (templates/builtin/lit.glsl): 0 texture coordinate, 1 surface normal,
// 2 tangent (w: bitangent sign, cross(N, T) * w along +v), 3 position; 15 the texture coordinate the page's views
// read (templates/edit/views.glsl). ES 3.00 links stages by name, not location,
// so the page defines HEXC_INPUT_<location> as the fragment shader's name of each input it has, after #version.
//
// The built-in templates light with a fixed direction, normalize(1, 1, 2), in the frame they are given: the page moves
// the light by turning that frame (u_light, a rotation taking the chosen light direction to the templates' own).
// Triplanar materials project the position and normal themselves: they get them unturned, in world space.
precision highp float;

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_tangent;
layout(location = 3) in vec2 a_uv;

uniform mat4 u_viewProjection;
uniform mat3 u_light;
uniform float u_uvScale;  // texture coordinate units per unit of the mesh's own

#ifdef HEXC_INPUT_0
out vec2 HEXC_INPUT_0;
#endif
#ifdef HEXC_INPUT_1
out vec3 HEXC_INPUT_1;
#endif
#ifdef HEXC_INPUT_2
out vec4 HEXC_INPUT_2;
#endif
#ifdef HEXC_INPUT_3
out vec3 HEXC_INPUT_3;
#endif
#ifdef HEXC_INPUT_15
out vec2 HEXC_INPUT_15;
#endif

void main() {
    gl_Position = u_viewProjection * vec4(a_position, 1.0);
#ifdef HEXC_INPUT_0
    HEXC_INPUT_0 = a_uv * u_uvScale;
#endif
#ifdef HEXC_INPUT_15
    HEXC_INPUT_15 = a_uv * u_uvScale;
#endif
#if defined(HEXC_INPUT_3)
    HEXC_INPUT_3 = a_position * u_uvScale;
#endif
#if defined(HEXC_INPUT_1) && defined(HEXC_INPUT_3)
    HEXC_INPUT_1 = a_normal;
#elif defined(HEXC_INPUT_1)
    HEXC_INPUT_1 = u_light * a_normal;
#endif
#ifdef HEXC_INPUT_2
    HEXC_INPUT_2 = vec4(u_light * a_tangent.xyz, a_tangent.w);
#endif
}
