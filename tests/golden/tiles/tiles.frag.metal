#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct HexcParams
{
    float2 albedo_tiling;
    float albedo_falloffcontrast;
};

constant uint _4085 = {};

struct tiles_frag_out
{
    float4 o_color [[color(0)]];
};

struct tiles_frag_in
{
    float2 v_uv [[user(locn0)]];
};

fragment tiles_frag_out tiles_frag(tiles_frag_in in [[stage_in]], constant HexcParams& hexcParams [[buffer(0)]], texture2d<float> hexcTex_albedo [[texture(0)]], sampler hexcSampler [[sampler(0)]])
{
    tiles_frag_out out = {};
    float2 _1354 = in.v_uv * hexcParams.albedo_tiling;
    float2 _1356 = dfdx(_1354);
    float2 _1358 = dfdy(_1354);
    float _1457 = _1354.x;
    float _1459 = floor(_1457 * 0.0357142873108386993408203125);
    float _1461 = _1354.y;
    float _1462 = floor(_1461);
    float _1467 = fma(-28.0, _1459, _1457);
    float _1471 = _1461 - _1462;
    float2 _1472 = float2(_1467, _1471);
    float2 _1483 = float2(fma(3.4642856121063232421875, _1467, _1471 * (-2.0)), 4.0 * _1471);
    float2 _1602 = floor(_1483);
    int2 _1603 = int2(_1602);
    float2 _1607 = _1483 - _1602;
    float _1608 = _1607.x;
    float _1609 = _1607.y;
    float _1620 = -((1.0 - _1608) - _1609);
    float _1621 = step(0.0, _1620);
    float _1624 = fma(2.0, _1621, -1.0);
    float3 _1642 = float3(_1620 * _1624, fma(-_1609, _1624, _1621), fma(-_1608, _1624, _1621));
    int _1644 = int(_1621);
    int2 _1649 = _1603 + int2(_1644);
    int _1653 = 1 - _1644;
    int2 _1655 = _1603 + int2(_1644, _1653);
    int2 _1661 = _1603 + int2(_1653, _1644);
    uint2 _1497 = uint2(int2(int(_1459), int(_1462)));
    uint _1503 = _1497.y;
    uint2 _1509 = uint2((97u * _1497.x) - (2u * _1503), 4u * _1503);
    float _1733 = float(_1649.y);
    uint3 _1916 = (uint3(uint2(int2(uint2(_1649) + _1509)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1918 = _1916.y;
    uint _1920 = _1916.z;
    uint _1924 = _1916.x + (_1918 * _1920);
    uint _1933 = _1918 + (_1920 * _1924);
    uint3 _4074 = uint3(_1924, _1933, _1920 + (_1924 * _1933));
    uint3 _1948 = _4074 ^ (_4074 >> uint3(16u));
    uint _1950 = _1948.y;
    uint _1952 = _1948.z;
    uint _1956 = _1948.x + (_1950 * _1952);
    float2 _1789 = _1356 * 1.0;
    float2 _1801 = _1358 * 1.0;
    float _2129 = float(_1655.y);
    uint3 _2312 = (uint3(uint2(int2(uint2(_1655) + _1509)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2314 = _2312.y;
    uint _2316 = _2312.z;
    uint _2320 = _2312.x + (_2314 * _2316);
    uint _2329 = _2314 + (_2316 * _2320);
    uint3 _4076 = uint3(_2320, _2329, _2316 + (_2320 * _2329));
    uint3 _2344 = _4076 ^ (_4076 >> uint3(16u));
    uint _2346 = _2344.y;
    uint _2348 = _2344.z;
    uint _2352 = _2344.x + (_2346 * _2348);
    float _2525 = float(_1661.y);
    uint3 _2708 = (uint3(uint2(int2(uint2(_1661) + _1509)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2710 = _2708.y;
    uint _2712 = _2708.z;
    uint _2716 = _2708.x + (_2710 * _2712);
    uint _2725 = _2710 + (_2712 * _2716);
    uint3 _4078 = uint3(_2716, _2725, _2712 + (_2716 * _2725));
    uint3 _2740 = _4078 ^ (_4078 >> uint3(16u));
    uint _2742 = _2740.y;
    uint _2744 = _2740.z;
    uint _2748 = _2740.x + (_2742 * _2744);
    float4 _2942 = hexcTex_albedo.sample(hexcSampler, (((_1472 - float2(fma(0.5, _1733, float(_1649.x)) * 0.2886598110198974609375, 0.25 * _1733)) * 1.0) + (float3(uint3(_1956, _1950 + (_1952 * _1956), _4085) >> uint3(8u)) * 5.9604644775390625e-08).xy), gradient2d(_1789, _1801));
    float4 _2952 = hexcTex_albedo.sample(hexcSampler, (((_1472 - float2(fma(0.5, _2129, float(_1655.x)) * 0.2886598110198974609375, 0.25 * _2129)) * 1.0) + (float3(uint3(_2352, _2346 + (_2348 * _2352), _4085) >> uint3(8u)) * 5.9604644775390625e-08).xy), gradient2d(_1789, _1801));
    float4 _2966 = hexcTex_albedo.sample(hexcSampler, (((_1472 - float2(fma(0.5, _2525, float(_1661.x)) * 0.2886598110198974609375, 0.25 * _2525)) * 1.0) + (float3(uint3(_2748, _2742 + (_2744 * _2748), _4085) >> uint3(8u)) * 5.9604644775390625e-08).xy), gradient2d(_1789, _1801));
    float3 _3127 = _1642 * _1642;
    float3 _3145 = (_1642 * _3127) * (_3127 * _3127);
    float3 _3056 = mix(float3(1.0), fast::max(float3(dot(_2942, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_2952, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_2966, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0))), float3(0.0)), float3(hexcParams.albedo_falloffcontrast)) * _3145;
    float _3068 = (_3056.x + _3056.y) + _3056.z;
    float3 _4042;
    if (_3068 > 0.0)
    {
        _4042 = _3056 / float3(_3068);
    }
    else
    {
        _4042 = _3145 / float3((_3145.x + _3145.y) + _3145.z);
    }
    float3 _3196 = step(float3(0.5), _4042) * 2.0;
    float3 _3200 = (float3(1.0) - _3196) * 2.0;
    float3 _3206 = fast::max(float3(0.0), fma(_4042, _3200, _3196));
    float3 _3225 = fma(_3200 * 0.25, _3206 * _3206, _3196 * 0.5);
    float3 _3236 = _3225 / float3((_3225.x + _3225.y) + _3225.z);
    out.o_color = ((_2942 * _3236.x) + (_2952 * _3236.y)) + (_2966 * _3236.z);
    return out;
}

