#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct HexcParams
{
    float2 albedo_tiling;
    float albedo_falloff;
    float albedo_falloffcontrast;
    float albedo_exponent;
};

constant uint _2566 = {};

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
    float2 _1064 = in.v_uv * hexcParams.albedo_tiling;
    float2 _1083 = dfdx(_1064);
    float2 _1085 = dfdy(_1064);
    float _1157 = _1064.x;
    float _1159 = floor(_1157 * 0.0357142873108386993408203125);
    float _1161 = _1064.y;
    float _1162 = floor(_1161);
    float _1167 = fma(-28.0, _1159, _1157);
    float _1171 = _1161 - _1162;
    float2 _1172 = float2(_1167, _1171);
    float2 _1183 = float2(fma(3.4642856121063232421875, _1167, _1171 * (-2.0)), 4.0 * _1171);
    float2 _1373 = floor(_1183);
    int2 _1374 = int2(_1373);
    float2 _1378 = _1183 - _1373;
    float _1379 = _1378.x;
    float _1380 = _1378.y;
    float _1391 = -((1.0 - _1379) - _1380);
    float _1392 = step(0.0, _1391);
    float _1395 = fma(2.0, _1392, -1.0);
    int _1415 = int(_1392);
    int2 _1420 = _1374 + int2(_1415);
    int _1424 = 1 - _1415;
    int2 _1426 = _1374 + int2(_1415, _1424);
    int2 _1432 = _1374 + int2(_1424, _1415);
    uint _1197 = uint(int(_1162));
    uint2 _1204 = uint2((97u * uint(int(_1159))) - (2u * _1197), 4u * _1197);
    uint3 _1474 = (uint3(uint2(int2(uint2(_1420) + _1204)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1476 = _1474.y;
    uint _1478 = _1474.z;
    uint _1482 = _1474.x + (_1476 * _1478);
    uint _1491 = _1476 + (_1478 * _1482);
    uint3 _2560 = uint3(_1482, _1491, _1478 + (_1482 * _1491));
    uint3 _1506 = _2560 ^ (_2560 >> uint3(16u));
    uint _1508 = _1506.y;
    uint _1510 = _1506.z;
    uint _1514 = _1506.x + (_1508 * _1510);
    uint3 _1576 = (uint3(uint2(int2(uint2(_1426) + _1204)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1578 = _1576.y;
    uint _1580 = _1576.z;
    uint _1584 = _1576.x + (_1578 * _1580);
    uint _1593 = _1578 + (_1580 * _1584);
    uint3 _2562 = uint3(_1584, _1593, _1580 + (_1584 * _1593));
    uint3 _1608 = _2562 ^ (_2562 >> uint3(16u));
    uint _1610 = _1608.y;
    uint _1612 = _1608.z;
    uint _1616 = _1608.x + (_1610 * _1612);
    uint3 _1678 = (uint3(uint2(int2(uint2(_1432) + _1204)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1680 = _1678.y;
    uint _1682 = _1678.z;
    uint _1686 = _1678.x + (_1680 * _1682);
    uint _1695 = _1680 + (_1682 * _1686);
    uint3 _2564 = uint3(_1686, _1695, _1682 + (_1686 * _1695));
    uint3 _1710 = _2564 ^ (_2564 >> uint3(16u));
    uint _1712 = _1710.y;
    uint _1714 = _1710.z;
    uint _1718 = _1710.x + (_1712 * _1714);
    float _1746 = float(_1420.y);
    float _1762 = float(_1426.y);
    float _1778 = float(_1432.y);
    float4 _2047 = hexcTex_albedo.sample(hexcSampler, ((_1172 - float2(fma(0.5, _1746, float(_1420.x)) * 0.2886598110198974609375, 0.25 * _1746)) + (float2((uint3(_1514, _1508 + (_1510 * _1514), _2566) >> uint3(8u)).xy) * 5.9604644775390625e-08)), gradient2d(_1083, _1085));
    float4 _2057 = hexcTex_albedo.sample(hexcSampler, ((_1172 - float2(fma(0.5, _1762, float(_1426.x)) * 0.2886598110198974609375, 0.25 * _1762)) + (float2((uint3(_1616, _1610 + (_1612 * _1616), _2566) >> uint3(8u)).xy) * 5.9604644775390625e-08)), gradient2d(_1083, _1085));
    float4 _2067 = hexcTex_albedo.sample(hexcSampler, ((_1172 - float2(fma(0.5, _1778, float(_1432.x)) * 0.2886598110198974609375, 0.25 * _1778)) + (float2((uint3(_1718, _1712 + (_1714 * _1718), _2566) >> uint3(8u)).xy) * 5.9604644775390625e-08)), gradient2d(_1083, _1085));
    float3 _2119 = pow(float3(_1391 * _1395, fma(-_1380, _1395, _1392), fma(-_1379, _1395, _1392)), float3(hexcParams.albedo_exponent));
    float3 _2128 = mix(float3(1.0), fast::max(float3(dot(_2047, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_2057, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_2067, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0))), float3(0.0)), float3(hexcParams.albedo_falloffcontrast)) * _2119;
    float _2140 = (_2128.x + _2128.y) + _2128.z;
    float3 _2413;
    if (_2140 > 0.0)
    {
        _2413 = _2128 / float3(_2140);
    }
    else
    {
        _2413 = _2119 / float3((_2119.x + _2119.y) + _2119.z);
    }
    float3 _2559;
    if (true && (hexcParams.albedo_falloff != 0.5))
    {
        float3 _2185 = step(float3(0.5), _2413) * 2.0;
        float3 _2189 = (float3(1.0) - _2185) * 2.0;
        float3 _2204 = fma(_2189 * 0.25, pow(fast::max(float3(0.0), fma(_2413, _2189, _2185)), float3(log(1.0 - hexcParams.albedo_falloff) * (-1.44269502162933349609375))), _2185 * 0.5);
        _2559 = _2204 / float3((_2204.x + _2204.y) + _2204.z);
    }
    else
    {
        _2559 = _2413;
    }
    out.o_color = ((_2047 * _2559.x) + (_2057 * _2559.y)) + (_2067 * _2559.z);
    return out;
}

