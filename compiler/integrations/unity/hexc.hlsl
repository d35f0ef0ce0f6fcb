// hexc material `${material}` for Unity (docs/engines.md#unity): a Shader Graph Custom Function file, also included by
// ${material}.shader (URP). Conventions: uv ${uvorigin}; Unity stores a texture's bottom row first, so every read
// below samples at (s, -t) (exact with repeat wrapping). Textures: import each as a Default texture with mipmaps,
// repeat and trilinear filtering, sRGB on for an sRGB slot only (a normal map too as Default, sRGB off: hexc decodes it).
//
// Custom Function node (Type File, Source this file, Precision Single): Name, then the ports in order (Color: a Vertex
// Color node, the layers' weights, linear).
${nodes}
#ifndef HEXC_${guard}_INCLUDED
#define HEXC_${guard}_INCLUDED

// A texture read at hexc's (s, t), top row at t = 0, from Unity's bottom-row-first storage.
#define HEXC_SAMPLE_GRAD(tex, smp, st, dx, dy) \
    SAMPLE_TEXTURE2D_GRAD(tex, smp, (st) * float2(1.0, -1.0), (dx) * float2(1.0, -1.0), (dy) * float2(1.0, -1.0))
// An explicit level (a histogram table, one level per slot) and a plain-tiled slot's implicit one.
#define HEXC_SAMPLE_LEVEL(tex, smp, st, lod) SAMPLE_TEXTURE2D_LOD(tex, smp, (st) * float2(1.0, -1.0), lod)
#define HEXC_SAMPLE(tex, smp, st) SAMPLE_TEXTURE2D(tex, smp, (st) * float2(1.0, -1.0))
// The same on a layered role's 2D array texture: (s, t, layer), the layer a whole number.
#define HEXC_SAMPLE_ARRAY_GRAD(tex, smp, stl, dx, dy) \
    SAMPLE_TEXTURE2D_ARRAY_GRAD(tex, smp, (stl).xy * float2(1.0, -1.0), (stl).z, (dx) * float2(1.0, -1.0), (dy) * float2(1.0, -1.0))
#define HEXC_SAMPLE_ARRAY_LEVEL(tex, smp, stl, lod) SAMPLE_TEXTURE2D_ARRAY_LOD(tex, smp, (stl).xy * float2(1.0, -1.0), (stl).z, lod)
#define HEXC_SAMPLE_ARRAY(tex, smp, stl) SAMPLE_TEXTURE2D_ARRAY(tex, smp, (stl).xy * float2(1.0, -1.0), (stl).z)

// hexc's functions for this material (hexc --functions, HLSL), each taking the textures it reads.
${functions}

// The Custom Function node's entry points (Shader Graph appends _float to the node's Name).
${wrappers}

#endif
