#version 450
// The paper's Listings 1-10 (Mikkelsen 2022, seed 000) as written, ported from HLSL, per slot as the paper shows
// them: the bench's baseline for "x paper listing". The material is the bench's full-quality one (rock's three maps
// at tiling 4, rotation 1, falloff 0.75 on every slot), its settings as constants (the listings' default-argument
// style; hexc's baked row is the like-for-like comparison), in hexc's default layout (sampler at binding 1,
// textures from 2 in slot order), shaded as the built-in `lit` template shades it (with PAPER_LISTING_MINIMAL
// defined, as bench/minimal.glsl does). tests/execution/library_test.cpp checks that it draws what hexc's paper mode draws.
//
// HLSL float2x2(a, b, c, d) fills rows and mul(M, v) is M v, mul(v, M) is v M: with rot = mat2(cs, si, -si, cs)
// (the rows (cs, -si), (si, cs) of Listing 6), GLSL's rot * v and v * rot are the same products.
layout(set = 0, binding = 1) uniform sampler samp;
layout(set = 0, binding = 2) uniform texture2D albedoTex;
layout(set = 0, binding = 3) uniform texture2D normalTex;
layout(set = 0, binding = 4) uniform texture2D roughnessTex;

layout(location = 0) in vec2 v_uv;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec4 v_tangent;
layout(location = 0) out vec4 o_color;

const float M_PI = 3.14159265358979;
const float g_fallOffContrast = 0.6;
const float g_exp = 7.0;
const float kTiling = 4.0;

// Listing 1.
void TriangleGrid(out float w1, out float w2, out float w3, out ivec2 vertex1, out ivec2 vertex2, out ivec2 vertex3, vec2 st) {
    st *= 2.0 * sqrt(3.0);
    vec2 skewedCoord = vec2(st.x - 0.57735027 * st.y, 1.15470054 * st.y);  // mul(gridToSkewedGrid, st)
    ivec2 baseId = ivec2(floor(skewedCoord));
    vec3 temp = vec3(fract(skewedCoord), 0.0);
    temp.z = 1.0 - temp.x - temp.y;
    float s = step(0.0, -temp.z);
    float s2 = 2.0 * s - 1.0;
    w1 = -temp.z * s2;
    w2 = s - temp.y * s2;
    w3 = s - temp.x * s2;
    int si = int(s);
    vertex1 = baseId + ivec2(si, si);
    vertex2 = baseId + ivec2(si, 1 - si);
    vertex3 = baseId + ivec2(1 - si, si);
}

// Listing 2.
vec2 hash(vec2 p) {
    vec2 r = vec2(127.1 * p.x + 311.7 * p.y, 269.5 * p.x + 183.3 * p.y);  // mul(float2x2(...), p)
    return fract(sin(r) * 43758.5453);
}

// Listing 5.
vec2 MakeCenST(ivec2 Vertex) {
    vec2 v = vec2(Vertex);
    return vec2(v.x + 0.5 * v.y, v.y / 1.15470054) / (2.0 * sqrt(3.0));  // mul(invSkewMat, Vertex)
}

// Listing 6. The angle is positive, so HLSL's fmod and GLSL's mod agree.
mat2 LoadRot2x2(ivec2 idx, float rotStrength) {
    float angle = float(abs(idx.x * idx.y) + abs(idx.x + idx.y)) + M_PI;
    angle = mod(angle, 2.0 * M_PI);
    if (angle < 0.0) angle += 2.0 * M_PI;
    if (angle > M_PI) angle -= 2.0 * M_PI;
    angle *= rotStrength;
    float cs = cos(angle), si = sin(angle);
    return mat2(cs, si, -si, cs);
}

// Listing 8.
vec3 Gain3(vec3 x, float r) {
    float k = log(1.0 - r) / log(0.5);
    vec3 s = 2.0 * step(0.5, x);
    vec3 m = 2.0 * (1.0 - s);
    vec3 res = 0.5 * s + 0.25 * m * pow(max(vec3(0.0), s + x * m), vec3(k));
    return res.xyz / (res.x + res.y + res.z);
}

// Listing 9.
vec2 TspaceNormalToDerivative(vec3 vM) {
    const float scale = 1.0 / 128.0;
    vec3 vMa = abs(vM);
    float z_ma = max(vMa.z, scale * max(vMa.x, vMa.y));
    const bool gFlipVertDeriv = false;
    float s = gFlipVertDeriv ? -1.0 : 1.0;
    return -vec2(vM.x, s * vM.y) / z_ma;
}

// Listing 10.
vec2 sampleDeriv(texture2D nmap, vec2 st, vec2 dSTdx, vec2 dSTdy) {
    vec3 vM = 2.0 * textureGrad(sampler2D(nmap, samp), st, dSTdx, dSTdy).xyz - 1.0;
    return TspaceNormalToDerivative(vM);
}

// Listing 3 (the weights' visualisation, Listing 7, left out: nothing reads it).
vec2 bumpHex2derivNMap(texture2D nmap, vec2 st, float rotStrength, float r) {
    vec2 dSTdx = dFdx(st), dSTdy = dFdy(st);
    float w1, w2, w3;
    ivec2 vertex1, vertex2, vertex3;
    TriangleGrid(w1, w2, w3, vertex1, vertex2, vertex3, st);
    mat2 rot1 = LoadRot2x2(vertex1, rotStrength), rot2 = LoadRot2x2(vertex2, rotStrength), rot3 = LoadRot2x2(vertex3, rotStrength);
    vec2 cen1 = MakeCenST(vertex1), cen2 = MakeCenST(vertex2), cen3 = MakeCenST(vertex3);
    vec2 st1 = (st - cen1) * rot1 + cen1 + hash(vec2(vertex1));
    vec2 st2 = (st - cen2) * rot2 + cen2 + hash(vec2(vertex2));
    vec2 st3 = (st - cen3) * rot3 + cen3 + hash(vec2(vertex3));
    vec2 d1 = sampleDeriv(nmap, st1, dSTdx * rot1, dSTdy * rot1);
    vec2 d2 = sampleDeriv(nmap, st2, dSTdx * rot2, dSTdy * rot2);
    vec2 d3 = sampleDeriv(nmap, st3, dSTdx * rot3, dSTdy * rot3);
    d1 = rot1 * d1;
    d2 = rot2 * d2;
    d3 = rot3 * d3;
    vec3 D = vec3(dot(d1, d1), dot(d2, d2), dot(d3, d3));
    vec3 Dw = sqrt(D / (1.0 + D));
    Dw = mix(vec3(1.0), Dw, g_fallOffContrast);
    vec3 W = Dw * pow(vec3(w1, w2, w3), vec3(g_exp));
    W /= (W.x + W.y + W.z);
    if (r != 0.5) W = Gain3(W, r);
    return W.x * d1 + W.y * d2 + W.z * d3;
}

// Listing 4.
vec4 hex2colTex(texture2D tex, vec2 st, float rotStrength, float r) {
    vec2 dSTdx = dFdx(st), dSTdy = dFdy(st);
    float w1, w2, w3;
    ivec2 vertex1, vertex2, vertex3;
    TriangleGrid(w1, w2, w3, vertex1, vertex2, vertex3, st);
    mat2 rot1 = LoadRot2x2(vertex1, rotStrength), rot2 = LoadRot2x2(vertex2, rotStrength), rot3 = LoadRot2x2(vertex3, rotStrength);
    vec2 cen1 = MakeCenST(vertex1), cen2 = MakeCenST(vertex2), cen3 = MakeCenST(vertex3);
    vec2 st1 = (st - cen1) * rot1 + cen1 + hash(vec2(vertex1));
    vec2 st2 = (st - cen2) * rot2 + cen2 + hash(vec2(vertex2));
    vec2 st3 = (st - cen3) * rot3 + cen3 + hash(vec2(vertex3));
    vec4 c1 = textureGrad(sampler2D(tex, samp), st1, dSTdx * rot1, dSTdy * rot1);
    vec4 c2 = textureGrad(sampler2D(tex, samp), st2, dSTdx * rot2, dSTdy * rot2);
    vec4 c3 = textureGrad(sampler2D(tex, samp), st3, dSTdx * rot3, dSTdy * rot3);
    vec3 Lw = vec3(0.299, 0.587, 0.114);
    vec3 Dw = vec3(dot(c1.xyz, Lw), dot(c2.xyz, Lw), dot(c3.xyz, Lw));
    Dw = mix(vec3(1.0), Dw, g_fallOffContrast);
    vec3 W = Dw * pow(vec3(w1, w2, w3), vec3(g_exp));
    W /= (W.x + W.y + W.z);
    if (r != 0.5) W = Gain3(W, r);
    return W.x * c1 + W.y * c2 + W.z * c3;
}

// templates/builtin/lit.glsl's shading, on the listings' results.
const vec3 kLightDir = vec3(0.408248, 0.408248, 0.816497);
const vec3 kViewDir = vec3(0.0, 0.0, 1.0);
const float kAmbient = 0.15;

void main() {
    vec2 st = v_uv * kTiling;
#ifdef PAPER_LISTING_MINIMAL
    // bench/minimal.glsl's shading: the three results summed.
    vec2 deriv = bumpHex2derivNMap(normalTex, st, 1.0, 0.75);
    o_color = vec4(hex2colTex(albedoTex, st, 1.0, 0.75).rgb + vec3(hex2colTex(roughnessTex, st, 1.0, 0.75).r) + vec3(deriv, 0.0), 1.0);
#else
    vec3 albedo = hex2colTex(albedoTex, st, 1.0, 0.75).rgb;
    float roughness = clamp(hex2colTex(roughnessTex, st, 1.0, 0.75).r, 0.02, 1.0);
    vec2 deriv = bumpHex2derivNMap(normalTex, st, 1.0, 0.75);
    vec3 N = normalize(v_normal);
    vec3 T = normalize(v_tangent.xyz - N * dot(N, v_tangent.xyz));
    vec3 B = cross(N, T) * v_tangent.w;
    vec3 n = normalize(vec3(-deriv, 1.0));  // the paper's conversion; y runs up the texture, along -B
    N = normalize(n.x * T - n.y * B + n.z * N);
    float diffuse = max(dot(N, kLightDir), 0.0);
    vec3 H = normalize(kLightDir + kViewDir);
    float power = 2.0 / (roughness * roughness * roughness * roughness) - 2.0;
    float specular = pow(max(dot(N, H), 0.0), power) * (power + 8.0) / 25.1327412 * diffuse;
    o_color = vec4(albedo * (kAmbient + diffuse) + vec3(0.04 * specular), 1.0);
#endif
}
