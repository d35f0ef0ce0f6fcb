// Stub of URP's Lighting.hlsl: SurfaceData, InputData and UniversalFragmentPBR as URP declares them.
#ifndef HEXC_STUB_URP_LIGHTING
#define HEXC_STUB_URP_LIGHTING

struct SurfaceData
{
    half3 albedo;
    half3 specular;
    half metallic;
    half smoothness;
    half3 normalTS;
    half3 emission;
    half occlusion;
    half alpha;
    half clearCoatMask;
    half clearCoatSmoothness;
};

struct InputData
{
    float3 positionWS;
    float4 positionCS;
    half3 normalWS;
    half3 viewDirectionWS;
    float4 shadowCoord;
    half fogCoord;
    half3 vertexLighting;
    half3 bakedGI;
    float2 normalizedScreenSpaceUV;
    half4 shadowMask;
    half3x3 tangentToWorld;
};

half4 UniversalFragmentPBR(InputData inputData, SurfaceData surfaceData)
{
    half light = saturate(dot(inputData.normalWS, half3(0.0, 0.0, 1.0)));
    return half4(surfaceData.albedo * light * surfaceData.occlusion * (1.0 - surfaceData.metallic) * surfaceData.smoothness + surfaceData.emission,
                 surfaceData.alpha);
}

#endif
