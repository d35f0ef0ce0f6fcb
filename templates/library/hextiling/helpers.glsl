// Plain tiling, for slots with hex-tiling disabled: one fetch with hardware gradients, or (hexcPlainColorGrad) with the
// given ones where the call may sit in non-uniform control flow (the triplanar planes). Two functions, not a flag: WGSL
// refuses an implicit-gradient fetch anywhere in a function called from non-uniform flow, even on a branch a literal
// flag never takes, and --debug keeps the calls.
vec4 hexcPlainColor(texture2D tex, sampler samp, vec2 st, vec2 dx, vec2 dy, out vec3 weights) {
    weights = vec3(1.0, 0.0, 0.0);
    return texture(sampler2D(tex, samp), st);
}

vec4 hexcPlainColorGrad(texture2D tex, sampler samp, vec2 st, vec2 dx, vec2 dy, out vec3 weights) {
    weights = vec3(1.0, 0.0, 0.0);
    return textureGrad(sampler2D(tex, samp), st, dx, dy);
}

// The paper's conversion of a blended derivative back to a tangent-space normal (Section 3).
vec3 hexcDerivToNormal(vec2 deriv) {
    return normalize(vec3(-deriv, 1.0));
}

// Triplanar projection (docs/material-format.md#triplanar-projection): the unit normal, each plane's weight
// and each plane's st with its gradients. Planes x, y, z read (y, z), (z, x), (x, y) of the position.
struct HexcPlanes {
    vec3 n, b;
    vec2 st[3], dx[3], dy[3];
};

HexcPlanes hexcPlanes(vec3 position, vec3 normal, float sharpness, vec2 tiling) {
    HexcPlanes p;
    // Derivatives here, in uniform control flow: the planes are then sampled with explicit gradients.
    vec3 dPdx = dFdx(position), dPdy = dFdy(position);
    float len = length(normal);
    p.n = len > 0.0 ? normal / len : vec3(0.0);
    vec3 b = pow(abs(p.n), vec3(sharpness));
    float sum = b.x + b.y + b.z;
    p.b = sum > 0.0 ? b / sum : vec3(1.0 / 3.0);
    p.st[0] = position.yz * tiling; p.dx[0] = dPdx.yz * tiling; p.dy[0] = dPdy.yz * tiling;
    p.st[1] = position.zx * tiling; p.dx[1] = dPdx.zx * tiling; p.dy[1] = dPdy.zx * tiling;
    p.st[2] = position.xy * tiling; p.dx[2] = dPdx.xy * tiling; p.dy[2] = dPdy.xy * tiling;
    return p;
}

// A plane's value in the blend: colour and scalar as they are; a normal slot's derivative (dH/ds, dH/dy), y = -t
// (see Conventions), as the world-space gradient it implies on plane k, whose (s, t) are world (y, z), (z, x), (x, y).
vec4 hexcLift(int k, vec4 v) { return v; }
float hexcLift(int k, float v) { return v; }
vec3 hexcLift(int k, vec2 d) {
    return k == 0 ? vec3(0.0, d.x, -d.y) : (k == 1 ? vec3(-d.y, 0.0, d.x) : vec3(d.x, -d.y, 0.0));
}

// The blended planes' result: colour and scalar as they are; gradients projected onto the surface (the surface
// gradient of Mikkelsen 2020).
vec4 hexcFinish(vec4 v, vec3 n) { return v; }
float hexcFinish(float v, vec3 n) { return v; }
vec3 hexcFinish(vec3 g, vec3 n) { return g - dot(g, n) * n; }

// The bumped normal from a surface gradient (a triplanar normal slot's result).
vec3 hexcPerturbNormal(vec3 normal, vec3 surfaceGradient) {
    return normalize(normalize(normal) - surfaceGradient);
}

// The value and weights templates' preview surface for triplanar materials: the unit sphere, uv as longitude
// and latitude in radians. Its cos and sin from hexcCosSin: a target's own may err by 2^-11 (SwiftShader's do), which
// moves a texel 0.19 of a 256^2 texture at tiling 1.5, so that a preview would differ from target to target.
void hexcPreviewSphere(vec2 uv, out vec3 position, out vec3 normal) {
    vec2 lon = hexcCosSin(uv.x), lat = hexcCosSin(uv.y);
    position = vec3(lat.x * lon.y, lat.y, lat.x * lon.x);
    normal = position;
}
