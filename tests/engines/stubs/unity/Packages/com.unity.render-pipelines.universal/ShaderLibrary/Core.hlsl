// Stub of URP's Core.hlsl: the Core RP texture macros as Direct3D 11 defines them, and the vertex helpers the package uses.
#ifndef HEXC_STUB_URP_CORE
#define HEXC_STUB_URP_CORE

#define real float
#define real3 float3
#define real3x3 float3x3

#define TEXTURE2D(textureName) Texture2D textureName
#define SAMPLER(samplerName) SamplerState samplerName
#define TEXTURE2D_PARAM(textureName, samplerName) TEXTURE2D(textureName), SAMPLER(samplerName)
#define TEXTURE2D_ARGS(textureName, samplerName) textureName, samplerName
#define SAMPLE_TEXTURE2D_GRAD(textureName, samplerName, coord2, dpdx, dpdy) textureName.SampleGrad(samplerName, coord2, dpdx, dpdy)
#define SAMPLE_TEXTURE2D_LOD(textureName, samplerName, coord2, lod) textureName.SampleLevel(samplerName, coord2, lod)
#define SAMPLE_TEXTURE2D(textureName, samplerName, coord2) textureName.Sample(samplerName, coord2)
#define TEXTURE2D_ARRAY(textureName) Texture2DArray textureName
#define TEXTURE2D_ARRAY_PARAM(textureName, samplerName) TEXTURE2D_ARRAY(textureName), SAMPLER(samplerName)
#define TEXTURE2D_ARRAY_ARGS(textureName, samplerName) textureName, samplerName
#define SAMPLE_TEXTURE2D_ARRAY_GRAD(textureName, samplerName, coord2, index, dpdx, dpdy) textureName.SampleGrad(samplerName, float3(coord2, index), dpdx, dpdy)
#define SAMPLE_TEXTURE2D_ARRAY_LOD(textureName, samplerName, coord2, index, lod) textureName.SampleLevel(samplerName, float3(coord2, index), lod)
#define SAMPLE_TEXTURE2D_ARRAY(textureName, samplerName, coord2, index) textureName.Sample(samplerName, float3(coord2, index))

struct VertexPositionInputs
{
    float3 positionWS;
    float3 positionVS;
    float4 positionCS;
    float4 positionNDC;
};

struct VertexNormalInputs
{
    real3 tangentWS;
    real3 bitangentWS;
    float3 normalWS;
};

VertexPositionInputs GetVertexPositionInputs(float3 positionOS)
{
    VertexPositionInputs o = (VertexPositionInputs)0;
    o.positionWS = positionOS;
    o.positionCS = float4(positionOS, 1.0);
    return o;
}

VertexNormalInputs GetVertexNormalInputs(float3 normalOS, float4 tangentOS)
{
    VertexNormalInputs o;
    o.normalWS = normalOS;
    o.tangentWS = tangentOS.xyz;
    o.bitangentWS = cross(normalOS, tangentOS.xyz) * tangentOS.w;
    return o;
}

real GetOddNegativeScale() { return 1.0; }

float3 GetWorldSpaceNormalizeViewDir(float3 positionWS) { return normalize(-positionWS); }

real3 TransformTangentToWorld(real3 dirTS, real3x3 tangentToWorld) { return mul(dirTS, tangentToWorld); }

#endif
