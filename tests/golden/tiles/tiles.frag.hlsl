static uint _3749;

cbuffer HexcParams : register(b0)
{
    float2 hexcParams_albedo_tiling : packoffset(c0);
    float hexcParams_albedo_falloffcontrast : packoffset(c0.z);
};

Texture2D<float4> hexcTex_albedo : register(t0);
SamplerState hexcSampler : register(s0);

static float4 o_color;
static float2 v_uv;

struct SPIRV_Cross_Input
{
    float2 v_uv : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float4 o_color : SV_Target0;
};

void frag_main()
{
    float2 _1319 = v_uv * hexcParams_albedo_tiling;
    float2 _1336 = ddx(_1319);
    float2 _1338 = ddy(_1319);
    float _1421 = _1319.x;
    float _1423 = floor(_1421 * 0.0357142873108386993408203125f);
    float _1425 = _1319.y;
    float _1426 = floor(_1425);
    float _1431 = mad(-28.0f, _1423, _1421);
    float _1435 = _1425 - _1426;
    float2 _1436 = float2(_1431, _1435);
    float2 _1447 = float2(mad(3.4642856121063232421875f, _1431, _1435 * (-2.0f)), 4.0f * _1435);
    float2 _1676 = floor(_1447);
    int2 _1677 = int2(_1676);
    float2 _1681 = _1447 - _1676;
    float _1682 = _1681.x;
    float _1683 = _1681.y;
    float _1694 = -((1.0f - _1682) - _1683);
    float _1695 = step(0.0f, _1694);
    float _1698 = mad(2.0f, _1695, -1.0f);
    float3 _1716 = float3(_1694 * _1698, mad(-_1683, _1698, _1695), mad(-_1682, _1698, _1695));
    int _1718 = int(_1695);
    int2 _1723 = _1677 + _1718.xx;
    int _1727 = 1 - _1718;
    int2 _1729 = _1677 + int2(_1718, _1727);
    int2 _1735 = _1677 + int2(_1727, _1718);
    uint _1461 = uint(int(_1426));
    uint2 _1468 = uint2((97u * uint(int(_1423))) - (2u * _1461), 4u * _1461);
    uint3 _1846 = (uint3(uint2(int2(uint2(_1723) + _1468)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1848 = _1846.y;
    uint _1850 = _1846.z;
    uint _1854 = _1846.x + (_1848 * _1850);
    uint _1863 = _1848 + (_1850 * _1854);
    uint3 _3738 = uint3(_1854, _1863, _1850 + (_1854 * _1863));
    uint3 _1878 = _3738 ^ (_3738 >> uint3(16u, 16u, 16u));
    uint _1880 = _1878.y;
    uint _1882 = _1878.z;
    uint _1886 = _1878.x + (_1880 * _1882);
    uint3 _2084 = (uint3(uint2(int2(uint2(_1729) + _1468)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2086 = _2084.y;
    uint _2088 = _2084.z;
    uint _2092 = _2084.x + (_2086 * _2088);
    uint _2101 = _2086 + (_2088 * _2092);
    uint3 _3740 = uint3(_2092, _2101, _2088 + (_2092 * _2101));
    uint3 _2116 = _3740 ^ (_3740 >> uint3(16u, 16u, 16u));
    uint _2118 = _2116.y;
    uint _2120 = _2116.z;
    uint _2124 = _2116.x + (_2118 * _2120);
    uint3 _2322 = (uint3(uint2(int2(uint2(_1735) + _1468)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2324 = _2322.y;
    uint _2326 = _2322.z;
    uint _2330 = _2322.x + (_2324 * _2326);
    uint _2339 = _2324 + (_2326 * _2330);
    uint3 _3742 = uint3(_2330, _2339, _2326 + (_2330 * _2339));
    uint3 _2354 = _3742 ^ (_3742 >> uint3(16u, 16u, 16u));
    uint _2356 = _2354.y;
    uint _2358 = _2354.z;
    uint _2362 = _2354.x + (_2356 * _2358);
    float _2457 = float(_1723.y);
    float _2473 = float(_1729.y);
    float _2489 = float(_1735.y);
    float2 _1596 = _1336 * 1.0f;
    float2 _1610 = _1338 * 1.0f;
    float4 _2760 = hexcTex_albedo.SampleGrad(hexcSampler, ((_1436 - float2(mad(0.5f, _2457, float(_1723.x)) * 0.2886598110198974609375f, 0.25f * _2457)) * 1.0f) + (float3(uint3(_1886, _1880 + (_1882 * _1886), _3749) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f).xy, _1596, _1610);
    float4 _2770 = hexcTex_albedo.SampleGrad(hexcSampler, ((_1436 - float2(mad(0.5f, _2473, float(_1729.x)) * 0.2886598110198974609375f, 0.25f * _2473)) * 1.0f) + (float3(uint3(_2124, _2118 + (_2120 * _2124), _3749) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f).xy, _1596, _1610);
    float4 _2780 = hexcTex_albedo.SampleGrad(hexcSampler, ((_1436 - float2(mad(0.5f, _2489, float(_1735.x)) * 0.2886598110198974609375f, 0.25f * _2489)) * 1.0f) + (float3(uint3(_2362, _2356 + (_2358 * _2362), _3749) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f).xy, _1596, _1610);
    float3 _2919 = _1716 * _1716;
    float3 _2937 = (_1716 * _2919) * (_2919 * _2919);
    float3 _2856 = lerp(1.0f.xxx, max(float3(dot(_2760, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_2770, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_2780, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f))), 0.0f.xxx), hexcParams_albedo_falloffcontrast.xxx) * _2937;
    float _2868 = (_2856.x + _2856.y) + _2856.z;
    float3 _3713;
    if (_2868 > 0.0f)
    {
        _3713 = _2856 / _2868.xxx;
    }
    else
    {
        _3713 = _2937 / ((_2937.x + _2937.y) + _2937.z).xxx;
    }
    float3 _2988 = step(0.5f.xxx, _3713) * 2.0f;
    float3 _2992 = (1.0f.xxx - _2988) * 2.0f;
    float3 _2998 = max(0.0f.xxx, mad(_3713, _2992, _2988));
    float3 _3017 = mad(_2992 * 0.25f, _2998 * _2998, _2988 * 0.5f);
    float3 _3028 = _3017 / ((_3017.x + _3017.y) + _3017.z).xxx;
    o_color = ((_2760 * _3028.x) + (_2770 * _3028.y)) + (_2780 * _3028.z);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    v_uv = stage_input.v_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.o_color = o_color;
    return stage_output;
}
