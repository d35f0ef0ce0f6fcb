// hexc material `${material}` for Unity (docs/engines.md#unity): a Shader Graph Custom Function file, also included by
// ${material}.shader (URP). Conventions: uv ${uvorigin}; Unity stores a texture's bottom row first, so every read
// below samples at (s, -t) (exact with repeat wrapping) and fetches row h - 1 - y for row y. The functions take HLSL's
// Texture2D and SamplerState, as Unity's TEXTURE2D and SAMPLER declare them on every graphics API but OpenGL ES 2.0.
// Textures: import each as a Default texture with mipmaps, repeat and trilinear filtering, sRGB on for an sRGB slot
// only (a normal map too as Default, sRGB off: hexc decodes it); a histogram table (.lut.exr) without mipmaps, sRGB
// off, Format RGBA Float.
//
// Custom Function node (Type File, Source this file, Precision Single): Name, then the ports in order (Color: a Vertex
// Color node, the layers' weights, linear).
${nodes}
#ifndef HEXC_${guard}_INCLUDED
#define HEXC_${guard}_INCLUDED

// hexc's functions for this material (hexc --functions, HLSL), each taking the textures it reads.
${functions}

// The Custom Function node's entry points (Shader Graph appends _float to the node's Name).
${wrappers}

#endif
