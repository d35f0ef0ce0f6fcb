#version 450
// hexc template `lit`: albedo + tangent-space normal + roughness under one directional light.
// Slots read (all optional): `albedo` (color), `normal` (normal), `roughness` (scalar).
// Stage inputs: location 0 = texture coordinate, 1 = surface normal, 2 = tangent (w = bitangent sign: cross(N, T) * w
// runs along +v, as MikkTSpace gives it for texture coordinates with v down the image), all in the same (world or view) space as the light direction below. With the triplanar projection:
// 1 = surface normal and 3 = position, in world space.
// hexc slot albedo color
// hexc slot normal normal
// hexc slot roughness scalar
#include <hexc>

#ifdef HEXC_PROJECTION_triplanar
layout(location = 1) in vec3 v_normal;
layout(location = 3) in vec3 v_position;
#define HEXC_INPUTS v_position, v_normal
#else
layout(location = 0) in vec2 v_uv;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec4 v_tangent;
#define HEXC_INPUTS v_uv
#endif
layout(location = 0) out vec4 o_color;

const vec3 kLightDir = vec3(0.408248, 0.408248, 0.816497);  // towards the light, normalised (1, 1, 2)
const vec3 kViewDir = vec3(0.0, 0.0, 1.0);
const float kAmbient = 0.15;

void main() {
#ifdef HEXC_HAS_albedo
    vec3 albedo = hexc_albedo(HEXC_INPUTS).rgb;
#else
    vec3 albedo = vec3(0.5);
#endif
#ifdef HEXC_HAS_roughness
    float roughness = clamp(hexc_roughness(HEXC_INPUTS), 0.02, 1.0);
#else
    float roughness = 0.5;
#endif
    vec3 N = normalize(v_normal);
#if defined(HEXC_HAS_normal) && defined(HEXC_PROJECTION_triplanar)
    N = hexcPerturbNormal(N, hexc_normal(v_position, N));
#elif defined(HEXC_HAS_normal)
    // Tangent-space normal from the blended derivative, taken to the surface frame (Mikkelsen 2020).
    vec3 T = normalize(v_tangent.xyz - N * dot(N, v_tangent.xyz));
    vec3 B = cross(N, T) * v_tangent.w;
    vec3 n = hexcDerivToNormal(hexc_normal(v_uv));  // its y runs up the texture, along -B
    N = normalize(n.x * T - n.y * B + n.z * N);
#endif
    // Blinn-Phong with the specular power derived from roughness.
    float diffuse = max(dot(N, kLightDir), 0.0);
    vec3 H = normalize(kLightDir + kViewDir);
    float power = 2.0 / (roughness * roughness * roughness * roughness) - 2.0;
    float specular = pow(max(dot(N, H), 0.0), power) * (power + 8.0) / 25.1327412 * diffuse;
    o_color = vec4(albedo * (kAmbient + diffuse) + vec3(0.04 * specular), 1.0);
}
