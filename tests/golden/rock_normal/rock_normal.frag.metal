#pragma clang diagnostic ignored "-Wmissing-prototypes"

#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

// Implementation of the GLSL mod() function, which is slightly different than Metal fmod()
template<typename Tx, typename Ty>
inline Tx mod(Tx x, Ty y)
{
    return x - y * floor(x / y);
}

struct HexcParams
{
    float2 normal_tiling;
    float normal_rotation;
    float normal_falloff;
    float normal_falloffcontrast;
    float normal_exponent;
};

struct main0_out
{
    float4 o_color [[color(0)]];
};

struct main0_in
{
    float2 v_uv [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant HexcParams& hexcParams [[buffer(0)]], texture2d<float> hexcTex_normal [[texture(0)]], sampler hexcSampler [[sampler(0)]])
{
    main0_out out = {};
    float3 _931 = fast::normalize(in.v_normal);
    float3 _944 = fast::normalize(in.v_tangent.xyz - (_931 * dot(_931, in.v_tangent.xyz)));
    float2 _1054 = in.v_uv * hexcParams.normal_tiling;
    float2 _1223 = dfdx(_1054);
    float2 _1225 = dfdy(_1054);
    float2 _1338 = _1054 * 3.4641015529632568359375;
    float _1342 = _1338.y;
    float2 _1348 = float2(fma(-0.57735025882720947265625, _1342, _1338.x), 1.1547005176544189453125 * _1342);
    int2 _1351 = int2(floor(_1348));
    float2 _1353 = fract(_1348);
    float _1354 = _1353.x;
    float _1355 = _1353.y;
    float _1366 = -((1.0 - _1354) - _1355);
    float _1367 = step(0.0, _1366);
    float _1370 = fma(2.0, _1367, -1.0);
    int _1390 = int(_1367);
    int2 _1395 = _1351 + int2(_1390);
    int _1399 = 1 - _1390;
    int2 _1401 = _1351 + int2(_1390, _1399);
    int2 _1407 = _1351 + int2(_1399, _1390);
    int _1412 = _1395.x;
    int _1414 = _1395.y;
    float _1427 = mod(float(abs(_1412 * _1414) + abs(_1412 + _1414)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _2346;
    if (_1427 > 3.1415927410125732421875)
    {
        _2346 = _1427 - 6.283185482025146484375;
    }
    else
    {
        _2346 = _1427;
    }
    float _1436 = _2346 * hexcParams.normal_rotation;
    float _1438 = cos(_1436);
    float _1440 = sin(_1436);
    int _1446 = _1401.x;
    int _1448 = _1401.y;
    float _1461 = mod(float(abs(_1446 * _1448) + abs(_1446 + _1448)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _2347;
    if (_1461 > 3.1415927410125732421875)
    {
        _2347 = _1461 - 6.283185482025146484375;
    }
    else
    {
        _2347 = _1461;
    }
    float _1470 = _2347 * hexcParams.normal_rotation;
    float _1472 = cos(_1470);
    float _1474 = sin(_1470);
    int _1480 = _1407.x;
    int _1482 = _1407.y;
    float _1495 = mod(float(abs(_1480 * _1482) + abs(_1480 + _1482)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _2348;
    if (_1495 > 3.1415927410125732421875)
    {
        _2348 = _1495 - 6.283185482025146484375;
    }
    else
    {
        _2348 = _1495;
    }
    float _1504 = _2348 * hexcParams.normal_rotation;
    float _1506 = cos(_1504);
    float _1508 = sin(_1504);
    float _1517 = float(_1414);
    float2 _1524 = float2(fma(0.5, _1517, float(_1412)), _1517 * 0.866025447845458984375);
    float _1534 = float(_1448);
    float2 _1541 = float2(fma(0.5, _1534, float(_1446)), _1534 * 0.866025447845458984375);
    float _1551 = float(_1482);
    float2 _1558 = float2(fma(0.5, _1551, float(_1480)), _1551 * 0.866025447845458984375);
    float2 _1262 = fma(in.v_uv, hexcParams.normal_tiling, _1524 * float2(-0.288675129413604736328125));
    float _1564 = _1262.x;
    float _1569 = _1262.y;
    float2 _1592 = float2(_1395);
    float2 _1275 = fma(in.v_uv, hexcParams.normal_tiling, _1541 * float2(-0.288675129413604736328125));
    float _1605 = _1275.x;
    float _1610 = _1275.y;
    float2 _1633 = float2(_1401);
    float2 _1288 = fma(in.v_uv, hexcParams.normal_tiling, _1558 * float2(-0.288675129413604736328125));
    float _1646 = _1288.x;
    float _1651 = _1288.y;
    float2 _1674 = float2(_1407);
    float _1687 = _1223.x;
    float _1692 = _1223.y;
    float _1699 = -_1687;
    float _1713 = _1225.x;
    float _1718 = _1225.y;
    float _1725 = -_1713;
    float3 _1855 = (hexcTex_normal.sample(hexcSampler, (fma(_1524, float2(0.288675129413604736328125), float2(fma(_1564, _1438, _1569 * _1440), fma(-_1564, _1440, _1569 * _1438))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _1592), dot(float2(269.5, 183.3000030517578125), _1592))) * 43758.546875)), gradient2d(float2(fma(_1687, _1438, _1692 * _1440), fma(_1699, _1440, _1692 * _1438)), float2(fma(_1713, _1438, _1718 * _1440), fma(_1725, _1440, _1718 * _1438)))).xyz * 2.0) - float3(1.0);
    float3 _1865 = abs(_1855);
    float2 _1891 = (-float2(_1855.xy)) / float2(fast::max(_1865.z, 0.0078125 * fast::max(_1865.x, _1865.y)));
    float _1897 = _1891.x;
    float _1902 = _1891.y;
    float2 _1916 = float2(fma(_1438, _1897, -(_1440 * _1902)), fma(_1440, _1897, _1438 * _1902));
    float3 _1932 = (hexcTex_normal.sample(hexcSampler, (fma(_1541, float2(0.288675129413604736328125), float2(fma(_1605, _1472, _1610 * _1474), fma(-_1605, _1474, _1610 * _1472))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _1633), dot(float2(269.5, 183.3000030517578125), _1633))) * 43758.546875)), gradient2d(float2(fma(_1687, _1472, _1692 * _1474), fma(_1699, _1474, _1692 * _1472)), float2(fma(_1713, _1472, _1718 * _1474), fma(_1725, _1474, _1718 * _1472)))).xyz * 2.0) - float3(1.0);
    float3 _1942 = abs(_1932);
    float2 _1968 = (-float2(_1932.xy)) / float2(fast::max(_1942.z, 0.0078125 * fast::max(_1942.x, _1942.y)));
    float _1974 = _1968.x;
    float _1979 = _1968.y;
    float2 _1993 = float2(fma(_1472, _1974, -(_1474 * _1979)), fma(_1474, _1974, _1472 * _1979));
    float3 _2009 = (hexcTex_normal.sample(hexcSampler, (fma(_1558, float2(0.288675129413604736328125), float2(fma(_1646, _1506, _1651 * _1508), fma(-_1646, _1508, _1651 * _1506))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _1674), dot(float2(269.5, 183.3000030517578125), _1674))) * 43758.546875)), gradient2d(float2(fma(_1687, _1506, _1692 * _1508), fma(_1699, _1508, _1692 * _1506)), float2(fma(_1713, _1506, _1718 * _1508), fma(_1725, _1508, _1718 * _1506)))).xyz * 2.0) - float3(1.0);
    float3 _2019 = abs(_2009);
    float2 _2045 = (-float2(_2009.xy)) / float2(fast::max(_2019.z, 0.0078125 * fast::max(_2019.x, _2019.y)));
    float _2051 = _2045.x;
    float _2056 = _2045.y;
    float2 _2070 = float2(fma(_1506, _2051, -(_1508 * _2056)), fma(_1508, _2051, _1506 * _2056));
    float3 _1146 = float3(dot(_1916, _1916), dot(_1993, _1993), dot(_2070, _2070));
    float3 _2085 = mix(float3(1.0), sqrt(_1146 / (float3(1.0) + _1146)), float3(hexcParams.normal_falloffcontrast)) * pow(float3(_1366 * _1370, fma(-_1355, _1370, _1367), fma(-_1354, _1370, _1367)), float3(hexcParams.normal_exponent));
    float3 _2096 = _2085 / float3((_2085.x + _2085.y) + _2085.z);
    float3 _2540;
    if (hexcParams.normal_falloff != 0.5)
    {
        float3 _2118 = step(float3(0.5), _2096) * 2.0;
        float3 _2122 = (float3(1.0) - _2118) * 2.0;
        float3 _2137 = fma(_2122 * 0.25, pow(fast::max(float3(0.0), fma(_2096, _2122, _2118)), float3(log(1.0 - hexcParams.normal_falloff) * (-1.44269502162933349609375))), _2118 * 0.5);
        _2540 = _2137 / float3((_2137.x + _2137.y) + _2137.z);
    }
    else
    {
        _2540 = _2096;
    }
    float3 _2285 = fast::normalize(float3(-(((_1916 * _2540.x) + (_1993 * _2540.y)) + (_2070 * _2540.z)), 1.0));
    float3 _976 = fast::normalize(((_944 * _2285.x) + ((cross(_931, _944) * in.v_tangent.w) * _2285.y)) + (_931 * _2285.z));
    float _983 = fast::max(dot(_976, float3(0.408248007297515869140625, 0.408248007297515869140625, 0.816497027873992919921875)), 0.0);
    out.o_color = float4((float3(0.5) * (0.1500000059604644775390625 + _983)) + float3(0.039999999105930328369140625 * ((pow(fast::max(dot(_976, float3(0.21418631076812744140625, 0.21418631076812744140625, 0.95302069187164306640625)), 0.0), 30.0) * 1.511971950531005859375) * _983)), 1.0);
    return out;
}

