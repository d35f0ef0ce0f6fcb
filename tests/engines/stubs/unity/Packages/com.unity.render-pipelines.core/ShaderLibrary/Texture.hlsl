// Stub of Core RP's Texture.hlsl: the texture structs a Shader Graph Custom Function node's Texture 2D and Texture 2D
// Array ports pass.
#ifndef HEXC_STUB_CORE_TEXTURE
#define HEXC_STUB_CORE_TEXTURE

struct UnityTexture2D
{
    TEXTURE2D(tex);
    SAMPLER(samplerstate);
    float4 texelSize;
    float4 scaleTranslate;
};

UnityTexture2D UnityBuildTexture2DStructInternal(TEXTURE2D_PARAM(tex, samplerstate), float4 texelSize, float4 scaleTranslate)
{
    UnityTexture2D result;
    result.tex = tex;
    result.samplerstate = samplerstate;
    result.texelSize = texelSize;
    result.scaleTranslate = scaleTranslate;
    return result;
}

#define UnityBuildTexture2DStructNoScale(n) UnityBuildTexture2DStructInternal(TEXTURE2D_ARGS(n, sampler##n), n##_TexelSize, float4(1, 1, 0, 0))

struct UnityTexture2DArray
{
    TEXTURE2D_ARRAY(tex);
    SAMPLER(samplerstate);
};

UnityTexture2DArray UnityBuildTexture2DArrayStructInternal(TEXTURE2D_ARRAY_PARAM(tex, samplerstate))
{
    UnityTexture2DArray result;
    result.tex = tex;
    result.samplerstate = samplerstate;
    return result;
}

#define UnityBuildTexture2DArrayStruct(n) UnityBuildTexture2DArrayStructInternal(TEXTURE2D_ARRAY_ARGS(n, sampler##n))

#endif
