#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct HexcParams
{
    float2 albedo_tiling;
    float albedo_falloffcontrast;
};

constant uint _3983 = {};

struct main0_out
{
    float4 o_color [[color(0)]];
};

struct main0_in
{
    float2 v_uv [[user(locn0)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant HexcParams& hexcParams [[buffer(0)]], texture2d<float> hexcTex_albedo [[texture(0)]], sampler hexcSampler [[sampler(0)]])
{
    main0_out out = {};
    float2 _1371 = in.v_uv * hexcParams.albedo_tiling;
    float2 _1373 = dfdx(_1371);
    float2 _1375 = dfdy(_1371);
    float _1473 = _1371.x;
    float _1475 = floor(_1473 * 0.0357142873108386993408203125);
    float _1477 = _1371.y;
    float _1478 = floor(_1477);
    float _1483 = fma(-28.0, _1475, _1473);
    float _1487 = _1477 - _1478;
    float2 _1488 = float2(_1483, _1487);
    float2 _1499 = float2(fma(3.4642856121063232421875, _1483, _1487 * (-2.0)), 4.0 * _1487);
    float2 _1627 = floor(_1499);
    int2 _1628 = int2(_1627);
    float2 _1632 = _1499 - _1627;
    float _1633 = _1632.x;
    float _1634 = _1632.y;
    float _1645 = -((1.0 - _1633) - _1634);
    float _1646 = step(0.0, _1645);
    float _1649 = fma(2.0, _1646, -1.0);
    float3 _1667 = float3(_1645 * _1649, fma(-_1634, _1649, _1646), fma(-_1633, _1649, _1646));
    int _1669 = int(_1646);
    int2 _1674 = _1628 + int2(_1669);
    int _1678 = 1 - _1669;
    int2 _1680 = _1628 + int2(_1669, _1678);
    int2 _1686 = _1628 + int2(_1678, _1669);
    uint2 _1513 = uint2(int2(int(_1475), int(_1478)));
    uint _1519 = _1513.y;
    uint2 _1525 = uint2((97u * _1513.x) - (2u * _1519), 4u * _1519);
    float _1758 = float(_1674.y);
    uint3 _1940 = (uint3(uint2(int2(uint2(_1674) + _1525)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1942 = _1940.y;
    uint _1944 = _1940.z;
    uint _1948 = _1940.x + (_1942 * _1944);
    uint _1957 = _1942 + (_1944 * _1948);
    uint3 _3973 = uint3(_1948, _1957, _1944 + (_1948 * _1957));
    uint3 _1972 = _3973 ^ (_3973 >> uint3(16u));
    uint _1974 = _1972.y;
    uint _1976 = _1972.z;
    uint _1980 = _1972.x + (_1974 * _1976);
    float2 _1818 = _1373 * 1.0;
    float2 _1829 = _1375 * 1.0;
    float _2153 = float(_1680.y);
    uint3 _2335 = (uint3(uint2(int2(uint2(_1680) + _1525)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2337 = _2335.y;
    uint _2339 = _2335.z;
    uint _2343 = _2335.x + (_2337 * _2339);
    uint _2352 = _2337 + (_2339 * _2343);
    uint3 _3975 = uint3(_2343, _2352, _2339 + (_2343 * _2352));
    uint3 _2367 = _3975 ^ (_3975 >> uint3(16u));
    uint _2369 = _2367.y;
    uint _2371 = _2367.z;
    uint _2375 = _2367.x + (_2369 * _2371);
    float _2548 = float(_1686.y);
    uint3 _2730 = (uint3(uint2(int2(uint2(_1686) + _1525)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2732 = _2730.y;
    uint _2734 = _2730.z;
    uint _2738 = _2730.x + (_2732 * _2734);
    uint _2747 = _2732 + (_2734 * _2738);
    uint3 _3977 = uint3(_2738, _2747, _2734 + (_2738 * _2747));
    uint3 _2762 = _3977 ^ (_3977 >> uint3(16u));
    uint _2764 = _2762.y;
    uint _2766 = _2762.z;
    uint _2770 = _2762.x + (_2764 * _2766);
    float4 _2970 = hexcTex_albedo.sample(hexcSampler, (((_1488 - float2(fma(0.5, _1758, float(_1674.x)) * 0.2886598110198974609375, 0.25 * _1758)) * 1.0) + (float3(uint3(_1980, _1974 + (_1976 * _1980), _3983) >> uint3(8u)) * 5.9604644775390625e-08).xy), gradient2d(_1818, _1829));
    float4 _2980 = hexcTex_albedo.sample(hexcSampler, (((_1488 - float2(fma(0.5, _2153, float(_1680.x)) * 0.2886598110198974609375, 0.25 * _2153)) * 1.0) + (float3(uint3(_2375, _2369 + (_2371 * _2375), _3983) >> uint3(8u)) * 5.9604644775390625e-08).xy), gradient2d(_1818, _1829));
    float4 _2993 = hexcTex_albedo.sample(hexcSampler, (((_1488 - float2(fma(0.5, _2548, float(_1686.x)) * 0.2886598110198974609375, 0.25 * _2548)) * 1.0) + (float3(uint3(_2770, _2764 + (_2766 * _2770), _3983) >> uint3(8u)) * 5.9604644775390625e-08).xy), gradient2d(_1818, _1829));
    float3 _3143 = _1667 * _1667;
    float3 _3161 = (_1667 * _3143) * (_3143 * _3143);
    float3 _3080 = mix(float3(1.0), fast::max(float3(dot(_2970, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_2980, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_2993, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0))), float3(0.0)), float3(hexcParams.albedo_falloffcontrast)) * _3161;
    float _3092 = (_3080.x + _3080.y) + _3080.z;
    float3 _3943;
    if (_3092 > 0.0)
    {
        _3943 = _3080 / float3(_3092);
    }
    else
    {
        _3943 = _3161 / float3((_3161.x + _3161.y) + _3161.z);
    }
    float3 _3212 = step(float3(0.5), _3943) * 2.0;
    float3 _3216 = (float3(1.0) - _3212) * 2.0;
    float3 _3222 = fast::max(float3(0.0), fma(_3943, _3216, _3212));
    float3 _3241 = fma(_3216 * 0.25, _3222 * _3222, _3212 * 0.5);
    float3 _3252 = _3241 / float3((_3241.x + _3241.y) + _3241.z);
    out.o_color = ((_2970 * _3252.x) + (_2980 * _3252.y)) + (_2993 * _3252.z);
    return out;
}

