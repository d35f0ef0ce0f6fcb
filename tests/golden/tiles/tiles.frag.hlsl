static uint _4085;

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
    float2 _1354 = v_uv * hexcParams_albedo_tiling;
    float2 _1356 = ddx(_1354);
    float2 _1358 = ddy(_1354);
    float _1457 = _1354.x;
    float _1459 = floor(_1457 * 0.0357142873108386993408203125f);
    float _1461 = _1354.y;
    float _1462 = floor(_1461);
    float _1467 = mad(-28.0f, _1459, _1457);
    float _1471 = _1461 - _1462;
    float2 _1472 = float2(_1467, _1471);
    float2 _1483 = float2(mad(3.4642856121063232421875f, _1467, _1471 * (-2.0f)), 4.0f * _1471);
    float2 _1602 = floor(_1483);
    int2 _1603 = int2(_1602);
    float2 _1607 = _1483 - _1602;
    float _1608 = _1607.x;
    float _1609 = _1607.y;
    float _1620 = -((1.0f - _1608) - _1609);
    float _1621 = step(0.0f, _1620);
    float _1624 = mad(2.0f, _1621, -1.0f);
    float3 _1642 = float3(_1620 * _1624, mad(-_1609, _1624, _1621), mad(-_1608, _1624, _1621));
    int _1644 = int(_1621);
    int2 _1649 = _1603 + _1644.xx;
    int _1653 = 1 - _1644;
    int2 _1655 = _1603 + int2(_1644, _1653);
    int2 _1661 = _1603 + int2(_1653, _1644);
    uint2 _1497 = uint2(int2(int(_1459), int(_1462)));
    uint _1503 = _1497.y;
    uint2 _1509 = uint2((97u * _1497.x) - (2u * _1503), 4u * _1503);
    float _1733 = float(_1649.y);
    uint3 _1916 = (uint3(uint2(int2(uint2(_1649) + _1509)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1918 = _1916.y;
    uint _1920 = _1916.z;
    uint _1924 = _1916.x + (_1918 * _1920);
    uint _1933 = _1918 + (_1920 * _1924);
    uint3 _4074 = uint3(_1924, _1933, _1920 + (_1924 * _1933));
    uint3 _1948 = _4074 ^ (_4074 >> uint3(16u, 16u, 16u));
    uint _1950 = _1948.y;
    uint _1952 = _1948.z;
    uint _1956 = _1948.x + (_1950 * _1952);
    float2 _1789 = _1356 * 1.0f;
    float2 _1801 = _1358 * 1.0f;
    float _2129 = float(_1655.y);
    uint3 _2312 = (uint3(uint2(int2(uint2(_1655) + _1509)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2314 = _2312.y;
    uint _2316 = _2312.z;
    uint _2320 = _2312.x + (_2314 * _2316);
    uint _2329 = _2314 + (_2316 * _2320);
    uint3 _4076 = uint3(_2320, _2329, _2316 + (_2320 * _2329));
    uint3 _2344 = _4076 ^ (_4076 >> uint3(16u, 16u, 16u));
    uint _2346 = _2344.y;
    uint _2348 = _2344.z;
    uint _2352 = _2344.x + (_2346 * _2348);
    float _2525 = float(_1661.y);
    uint3 _2708 = (uint3(uint2(int2(uint2(_1661) + _1509)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2710 = _2708.y;
    uint _2712 = _2708.z;
    uint _2716 = _2708.x + (_2710 * _2712);
    uint _2725 = _2710 + (_2712 * _2716);
    uint3 _4078 = uint3(_2716, _2725, _2712 + (_2716 * _2725));
    uint3 _2740 = _4078 ^ (_4078 >> uint3(16u, 16u, 16u));
    uint _2742 = _2740.y;
    uint _2744 = _2740.z;
    uint _2748 = _2740.x + (_2742 * _2744);
    float4 _2942 = hexcTex_albedo.SampleGrad(hexcSampler, ((_1472 - float2(mad(0.5f, _1733, float(_1649.x)) * 0.2886598110198974609375f, 0.25f * _1733)) * 1.0f) + (float3(uint3(_1956, _1950 + (_1952 * _1956), _4085) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f).xy, _1789, _1801);
    float4 _2952 = hexcTex_albedo.SampleGrad(hexcSampler, ((_1472 - float2(mad(0.5f, _2129, float(_1655.x)) * 0.2886598110198974609375f, 0.25f * _2129)) * 1.0f) + (float3(uint3(_2352, _2346 + (_2348 * _2352), _4085) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f).xy, _1789, _1801);
    float4 _2966 = hexcTex_albedo.SampleGrad(hexcSampler, ((_1472 - float2(mad(0.5f, _2525, float(_1661.x)) * 0.2886598110198974609375f, 0.25f * _2525)) * 1.0f) + (float3(uint3(_2748, _2742 + (_2744 * _2748), _4085) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f).xy, _1789, _1801);
    float3 _3127 = _1642 * _1642;
    float3 _3145 = (_1642 * _3127) * (_3127 * _3127);
    float3 _3056 = lerp(1.0f.xxx, max(float3(dot(_2942, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_2952, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_2966, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f))), 0.0f.xxx), hexcParams_albedo_falloffcontrast.xxx) * _3145;
    float _3068 = (_3056.x + _3056.y) + _3056.z;
    float3 _4042;
    if (_3068 > 0.0f)
    {
        _4042 = _3056 / _3068.xxx;
    }
    else
    {
        _4042 = _3145 / ((_3145.x + _3145.y) + _3145.z).xxx;
    }
    float3 _3196 = step(0.5f.xxx, _4042) * 2.0f;
    float3 _3200 = (1.0f.xxx - _3196) * 2.0f;
    float3 _3206 = max(0.0f.xxx, mad(_4042, _3200, _3196));
    float3 _3225 = mad(_3200 * 0.25f, _3206 * _3206, _3196 * 0.5f);
    float3 _3236 = _3225 / ((_3225.x + _3225.y) + _3225.z).xxx;
    o_color = ((_2942 * _3236.x) + (_2952 * _3236.y)) + (_2966 * _3236.z);
}

SPIRV_Cross_Output tiles_frag(SPIRV_Cross_Input stage_input)
{
    v_uv = stage_input.v_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.o_color = o_color;
    return stage_output;
}
