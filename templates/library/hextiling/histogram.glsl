// The histogram-preserving blend (Heitz and Neyret 2018, Deliot and Heitz 2019; hexc/histogram.h). `tex` holds each
// decorrelated channel gaussianised (mean 0.5, standard deviation 1/6); the tiles' values are blended with the
// variance-preserving weights W / |W|, so the blend keeps the Gaussian's spread wherever the tiles overlap. `lut` row
// 1 + lod holds each channel's inverse transform at a level of detail of the Gaussian texture, texel i for Gaussian
// value 0.5 + (2 i / (width - 1) - 1) 6.5 / 6 (+-6.5 standard deviations: every texel's rank is within reach, so the
// tails are kept); row 0 the way back to linear RGB (the axes in texels 0-2, the mean in texel 3) and the texture's
// range (texels 4 and 5), which the sum over the axes may leave. lod comes from the slot's st gradients as the
// sampler computes it (Euclidean lengths), and the rows are interpolated in it. `scalar` (a literal): one channel, in
// r, within its range already, and no way back to take.
vec4 hexcHistogram(texture2D tex, texture2D lut, sampler samp, HexcTiles t, HexcBlend b, vec2 dx, vec2 dy, bool scalar, out vec3 weights) {
    vec4 g[3];
    hexcFetchTaps(tex, samp, t, bvec3(true, true, b.taps > 2), b, g);
    vec3 W = hexcBlendWeights(t.w, vec3(1.0), b);
    weights = hexcShowWeights(W, t.channel);
    // The checker's third tap weighs 0: its unfetched 0 adds nothing.
    vec3 G = (W.x * (g[0].rgb - 0.5) + W.y * (g[1].rgb - 0.5) + W.z * (g[2].rgb - 0.5)) * inversesqrt(dot(W, W)) + 0.5;
    vec2 size = vec2(textureSize(sampler2D(tex, samp), 0));
    vec2 ex = dx * size, ey = dy * size;
    float lod = 0.5 * log2(max(max(dot(ex, ex), dot(ey, ey)), 1e-30));
    vec2 n = vec2(textureSize(sampler2D(lut, samp), 0));
    float v = (1.5 + clamp(lod, 0.0, n.y - 2.0)) / n.y;
    vec3 u = (clamp((G - 0.5) * (6.0 / 13.0) + 0.5, 0.0, 1.0) * (n.x - 1.0) + 0.5) / n.x;
    float q1 = textureLod(sampler2D(lut, samp), vec2(u.x, v), 0.0).r;
    if (scalar) return vec4(q1);
    float q2 = textureLod(sampler2D(lut, samp), vec2(u.y, v), 0.0).g;
    float q3 = textureLod(sampler2D(lut, samp), vec2(u.z, v), 0.0).b;
    vec3 rgb = texelFetch(sampler2D(lut, samp), ivec2(3, 0), 0).rgb + q1 * texelFetch(sampler2D(lut, samp), ivec2(0, 0), 0).rgb +
               q2 * texelFetch(sampler2D(lut, samp), ivec2(1, 0), 0).rgb + q3 * texelFetch(sampler2D(lut, samp), ivec2(2, 0), 0).rgb;
    return vec4(clamp(rgb, texelFetch(sampler2D(lut, samp), ivec2(4, 0), 0).rgb, texelFetch(sampler2D(lut, samp), ivec2(5, 0), 0).rgb), 1.0);
}
