#version 450
// An engine's own template: it brings its per-frame and per-object blocks, a shadow map, an environment map, a
// separate texture with its own sampler and push constants, all clear of hexc's bindings, and reads the
// `albedo` (color) and `roughness` (scalar) slots. hexc places every resource on each target without collisions
// and lists the template's under `template_resources` in the manifest (docs/templates.md).
#include <hexc>

layout(set = 1, binding = 0, std140) uniform Frame {
    vec3 lightDir;      // towards the light, normalised
    float exposure;
} frame;
layout(set = 2, binding = 0, std140) uniform Object {
    vec4 tint;
} object;
layout(set = 1, binding = 1) uniform sampler2D shadowMap;
layout(set = 1, binding = 2) uniform sampler2D environment;  // latitude-longitude
layout(set = 1, binding = 3) uniform texture2D detail;
layout(set = 1, binding = 4) uniform sampler detailSampler;
// One push constant block for all stages, as engines share it: bytes 0-15 are the vertex stage's.
layout(push_constant) uniform Push {
    layout(offset = 16) float ambient;
} push;

layout(location = 0) in vec2 v_uv;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 o_color;

void main() {
    vec3 albedo = hexc_albedo(v_uv).rgb * object.tint.rgb;
    float roughness = hexc_roughness(v_uv);
    vec3 N = normalize(v_normal);
    float shadow = texture(shadowMap, v_uv).r;
    float detail = texture(sampler2D(detail, detailSampler), v_uv * 8.0).r;
    vec2 latLong = vec2(atan(N.y, N.x) * 0.15915494 + 0.5, acos(clamp(N.z, -1.0, 1.0)) * 0.31830989);
    vec3 sky = textureLod(environment, latLong, roughness * 6.0).rgb;
    float diffuse = max(dot(N, frame.lightDir), 0.0) * shadow;
    o_color = vec4((albedo * (push.ambient + diffuse) + sky * 0.04) * detail * frame.exposure, 1.0);
}
