// Stub of Core RP's Texture.hlsl: the texture struct a Shader Graph Custom Function node's Texture 2D port passes.
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

#endif
