#version 450
// Bench template: the `lit` template's triplanar path on a surface whose normal weighs all three planes, so
// every pixel pays for three planes (the worst case). Reads `albedo`, `normal` and `roughness`.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

#include <hexc>

const vec3 kLightDir = vec3(0.408248, 0.408248, 0.816497);

void main() {
    vec3 N = normalize(vec3(1.0, 1.5, 2.0));
    vec3 P = vec3(v_uv, v_uv.x + v_uv.y);
    vec3 albedo = hexc_albedo(P, N).rgb;
    float roughness = hexc_roughness(P, N);
    N = hexcPerturbNormal(N, hexc_normal(P, N));
    o_color = vec4(albedo * (0.15 + max(dot(N, kLightDir), 0.0)) + vec3(0.04 * (1.0 - roughness)), 1.0);
}
