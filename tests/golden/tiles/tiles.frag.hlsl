static uint _3983;

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
    float2 _1371 = v_uv * hexcParams_albedo_tiling;
    float2 _1373 = ddx(_1371);
    float2 _1375 = ddy(_1371);
    float _1473 = _1371.x;
    float _1475 = floor(_1473 * 0.0357142873108386993408203125f);
    float _1477 = _1371.y;
    float _1478 = floor(_1477);
    float _1483 = mad(-28.0f, _1475, _1473);
    float _1487 = _1477 - _1478;
    float2 _1488 = float2(_1483, _1487);
    float2 _1499 = float2(mad(3.4642856121063232421875f, _1483, _1487 * (-2.0f)), 4.0f * _1487);
    float2 _1627 = floor(_1499);
    int2 _1628 = int2(_1627);
    float2 _1632 = _1499 - _1627;
    float _1633 = _1632.x;
    float _1634 = _1632.y;
    float _1645 = -((1.0f - _1633) - _1634);
    float _1646 = step(0.0f, _1645);
    float _1649 = mad(2.0f, _1646, -1.0f);
    float3 _1667 = float3(_1645 * _1649, mad(-_1634, _1649, _1646), mad(-_1633, _1649, _1646));
    int _1669 = int(_1646);
    int2 _1674 = _1628 + _1669.xx;
    int _1678 = 1 - _1669;
    int2 _1680 = _1628 + int2(_1669, _1678);
    int2 _1686 = _1628 + int2(_1678, _1669);
    uint2 _1513 = uint2(int2(int(_1475), int(_1478)));
    uint _1519 = _1513.y;
    uint2 _1525 = uint2((97u * _1513.x) - (2u * _1519), 4u * _1519);
    float _1758 = float(_1674.y);
    uint3 _1940 = (uint3(uint2(int2(uint2(_1674) + _1525)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1942 = _1940.y;
    uint _1944 = _1940.z;
    uint _1948 = _1940.x + (_1942 * _1944);
    uint _1957 = _1942 + (_1944 * _1948);
    uint3 _3973 = uint3(_1948, _1957, _1944 + (_1948 * _1957));
    uint3 _1972 = _3973 ^ (_3973 >> uint3(16u, 16u, 16u));
    uint _1974 = _1972.y;
    uint _1976 = _1972.z;
    uint _1980 = _1972.x + (_1974 * _1976);
    float2 _1818 = _1373 * 1.0f;
    float2 _1829 = _1375 * 1.0f;
    float _2153 = float(_1680.y);
    uint3 _2335 = (uint3(uint2(int2(uint2(_1680) + _1525)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2337 = _2335.y;
    uint _2339 = _2335.z;
    uint _2343 = _2335.x + (_2337 * _2339);
    uint _2352 = _2337 + (_2339 * _2343);
    uint3 _3975 = uint3(_2343, _2352, _2339 + (_2343 * _2352));
    uint3 _2367 = _3975 ^ (_3975 >> uint3(16u, 16u, 16u));
    uint _2369 = _2367.y;
    uint _2371 = _2367.z;
    uint _2375 = _2367.x + (_2369 * _2371);
    float _2548 = float(_1686.y);
    uint3 _2730 = (uint3(uint2(int2(uint2(_1686) + _1525)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2732 = _2730.y;
    uint _2734 = _2730.z;
    uint _2738 = _2730.x + (_2732 * _2734);
    uint _2747 = _2732 + (_2734 * _2738);
    uint3 _3977 = uint3(_2738, _2747, _2734 + (_2738 * _2747));
    uint3 _2762 = _3977 ^ (_3977 >> uint3(16u, 16u, 16u));
    uint _2764 = _2762.y;
    uint _2766 = _2762.z;
    uint _2770 = _2762.x + (_2764 * _2766);
    float4 _2970 = hexcTex_albedo.SampleGrad(hexcSampler, ((_1488 - float2(mad(0.5f, _1758, float(_1674.x)) * 0.2886598110198974609375f, 0.25f * _1758)) * 1.0f) + (float3(uint3(_1980, _1974 + (_1976 * _1980), _3983) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f).xy, _1818, _1829);
    float4 _2980 = hexcTex_albedo.SampleGrad(hexcSampler, ((_1488 - float2(mad(0.5f, _2153, float(_1680.x)) * 0.2886598110198974609375f, 0.25f * _2153)) * 1.0f) + (float3(uint3(_2375, _2369 + (_2371 * _2375), _3983) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f).xy, _1818, _1829);
    float4 _2993 = hexcTex_albedo.SampleGrad(hexcSampler, ((_1488 - float2(mad(0.5f, _2548, float(_1686.x)) * 0.2886598110198974609375f, 0.25f * _2548)) * 1.0f) + (float3(uint3(_2770, _2764 + (_2766 * _2770), _3983) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f).xy, _1818, _1829);
    float3 _3143 = _1667 * _1667;
    float3 _3161 = (_1667 * _3143) * (_3143 * _3143);
    float3 _3080 = lerp(1.0f.xxx, max(float3(dot(_2970, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_2980, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_2993, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f))), 0.0f.xxx), hexcParams_albedo_falloffcontrast.xxx) * _3161;
    float _3092 = (_3080.x + _3080.y) + _3080.z;
    float3 _3943;
    if (_3092 > 0.0f)
    {
        _3943 = _3080 / _3092.xxx;
    }
    else
    {
        _3943 = _3161 / ((_3161.x + _3161.y) + _3161.z).xxx;
    }
    float3 _3212 = step(0.5f.xxx, _3943) * 2.0f;
    float3 _3216 = (1.0f.xxx - _3212) * 2.0f;
    float3 _3222 = max(0.0f.xxx, mad(_3943, _3216, _3212));
    float3 _3241 = mad(_3216 * 0.25f, _3222 * _3222, _3212 * 0.5f);
    float3 _3252 = _3241 / ((_3241.x + _3241.y) + _3241.z).xxx;
    o_color = ((_2970 * _3252.x) + (_2980 * _3252.y)) + (_2993 * _3252.z);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    v_uv = stage_input.v_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.o_color = o_color;
    return stage_output;
}
