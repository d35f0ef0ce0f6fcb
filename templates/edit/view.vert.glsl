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
//
// A layered material weighed by vertex colours (`layer_blend.weights` "vertex" or "both") reads them at the location
// its manifest gives (`layers.vertex_color`); the page defines HEXC_VERTEX_COLOR as its name. No mesh here is painted,
// so the page paints them: colour (1 - t.x, t.x, t.y, 1 - t.y), so layer 0 gives way to layer 1 along t.x and layer 3
// to layer 2 along t.y. On the sphere, the cube (radius 1) and the plane, t = 0.5 + 0.5 (x, y) in the mesh's own units
// (across the plane's two units about the origin; the shader clamps beyond). In the texture-space view, t is the
// pixel's place in the window, (0, 0) at its top left and (1, 1) at its bottom right, as `hexc render` paints them
// (templates/harness/fullscreen.vert.glsl), so that view shows what `hexc render` draws of any uv window. Both are
// affine in the position, so they interpolate exactly even across the plane's four vertices.
precision highp float;

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_tangent;
layout(location = 3) in vec2 a_uv;

uniform mat4 u_viewProjection;
uniform mat3 u_light;
uniform float u_uvScale;  // texture coordinate units per unit of the mesh's own
uniform bool u_flat;      // the texture-space view: vertex colours follow the window

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
#ifdef HEXC_VERTEX_COLOR
out vec4 HEXC_VERTEX_COLOR;
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
#ifdef HEXC_VERTEX_COLOR
    // The texture-space view's projection is orthographic (w = 1): NDC y = +1 is the window's top row.
    vec2 t = u_flat ? vec2(0.5 + 0.5 * gl_Position.x, 0.5 - 0.5 * gl_Position.y) : 0.5 + 0.5 * a_position.xy;
    HEXC_VERTEX_COLOR = vec4(1.0 - t.x, t.x, t.y, 1.0 - t.y);
#endif
}
