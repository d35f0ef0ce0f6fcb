#version 300 es
// hexc edit's display pass: the view as an engine's sRGB swapchain shows it. The materials' shaders write linear
// values (hexc render's `--encoding linear`); WebGL's canvas stores what it is given, so the page encodes them with the
// sRGB transfer function (IEC 61966-2-1) on RGB, alpha kept, as `hexc preview` does.
precision highp float;

uniform sampler2D u_frame;
in vec2 v_screen;
out vec4 o_color;

void main() {
    vec4 c = texture(u_frame, v_screen);
    vec3 v = max(c.rgb, 0.0);
    o_color = vec4(mix(12.92 * v, 1.055 * pow(v, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, v)), c.a);
}
