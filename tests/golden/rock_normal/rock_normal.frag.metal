#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

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
    float3 _1065 = fast::normalize(in.v_normal);
    float3 _1078 = fast::normalize(in.v_tangent.xyz - (_1065 * dot(_1065, in.v_tangent.xyz)));
    float2 _1189 = in.v_uv * hexcParams.normal_tiling;
    float2 _1209 = dfdx(_1189);
    float2 _1211 = dfdy(_1189);
    float _1267 = _1189.x;
    float _1269 = floor(_1267 * 0.0357142873108386993408203125);
    float _1271 = _1189.y;
    float _1272 = floor(_1271);
    float _1277 = fma(-28.0, _1269, _1267);
    float _1281 = _1271 - _1272;
    float2 _1282 = float2(_1277, _1281);
    float2 _1293 = float2(fma(3.4642856121063232421875, _1277, _1281 * (-2.0)), 4.0 * _1281);
    float2 _1423 = floor(_1293);
    int2 _1424 = int2(_1423);
    float2 _1428 = _1293 - _1423;
    float _1429 = _1428.x;
    float _1430 = _1428.y;
    float _1441 = -((1.0 - _1429) - _1430);
    float _1442 = step(0.0, _1441);
    float _1445 = fma(2.0, _1442, -1.0);
    int _1465 = int(_1442);
    int2 _1470 = _1424 + int2(_1465);
    int _1474 = 1 - _1465;
    int2 _1476 = _1424 + int2(_1465, _1474);
    int2 _1482 = _1424 + int2(_1474, _1465);
    uint _1307 = uint(int(_1272));
    uint2 _1314 = uint2((97u * uint(int(_1269))) - (2u * _1307), 4u * _1307);
    uint3 _1518 = (uint3(uint2(int2(uint2(_1470) + _1314)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1520 = _1518.y;
    uint _1522 = _1518.z;
    uint _1526 = _1518.x + (_1520 * _1522);
    uint _1535 = _1520 + (_1522 * _1526);
    uint3 _2973 = uint3(_1526, _1535, _1522 + (_1526 * _1535));
    uint3 _1550 = _2973 ^ (_2973 >> uint3(16u));
    uint _1552 = _1550.y;
    uint _1554 = _1550.z;
    uint _1558 = _1550.x + (_1552 * _1554);
    uint _1567 = _1552 + (_1554 * _1558);
    uint3 _1494 = uint3(_1558, _1567, _1554 + (_1558 * _1567)) >> uint3(8u);
    float _1506 = (fma(float(_1494.z), 1.1920928955078125e-07, -1.0) * 3.1415927410125732421875) * hexcParams.normal_rotation;
    float _1508 = cos(_1506);
    float _1510 = sin(_1506);
    uint3 _1614 = (uint3(uint2(int2(uint2(_1476) + _1314)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1616 = _1614.y;
    uint _1618 = _1614.z;
    uint _1622 = _1614.x + (_1616 * _1618);
    uint _1631 = _1616 + (_1618 * _1622);
    uint3 _2975 = uint3(_1622, _1631, _1618 + (_1622 * _1631));
    uint3 _1646 = _2975 ^ (_2975 >> uint3(16u));
    uint _1648 = _1646.y;
    uint _1650 = _1646.z;
    uint _1654 = _1646.x + (_1648 * _1650);
    uint _1663 = _1648 + (_1650 * _1654);
    uint3 _1590 = uint3(_1654, _1663, _1650 + (_1654 * _1663)) >> uint3(8u);
    float _1602 = (fma(float(_1590.z), 1.1920928955078125e-07, -1.0) * 3.1415927410125732421875) * hexcParams.normal_rotation;
    float _1604 = cos(_1602);
    float _1606 = sin(_1602);
    uint3 _1710 = (uint3(uint2(int2(uint2(_1482) + _1314)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1712 = _1710.y;
    uint _1714 = _1710.z;
    uint _1718 = _1710.x + (_1712 * _1714);
    uint _1727 = _1712 + (_1714 * _1718);
    uint3 _2977 = uint3(_1718, _1727, _1714 + (_1718 * _1727));
    uint3 _1742 = _2977 ^ (_2977 >> uint3(16u));
    uint _1744 = _1742.y;
    uint _1746 = _1742.z;
    uint _1750 = _1742.x + (_1744 * _1746);
    uint _1759 = _1744 + (_1746 * _1750);
    uint3 _1686 = uint3(_1750, _1759, _1746 + (_1750 * _1759)) >> uint3(8u);
    float _1698 = (fma(float(_1686.z), 1.1920928955078125e-07, -1.0) * 3.1415927410125732421875) * hexcParams.normal_rotation;
    float _1700 = cos(_1698);
    float _1702 = sin(_1698);
    float _1778 = float(_1470.y);
    float2 _1358 = _1282 - float2(fma(0.5, _1778, float(_1470.x)) * 0.2886598110198974609375, 0.25 * _1778);
    float _1790 = _1358.x;
    float _1795 = _1358.y;
    float _1820 = float(_1476.y);
    float2 _1368 = _1282 - float2(fma(0.5, _1820, float(_1476.x)) * 0.2886598110198974609375, 0.25 * _1820);
    float _1832 = _1368.x;
    float _1837 = _1368.y;
    float _1862 = float(_1482.y);
    float2 _1378 = _1282 - float2(fma(0.5, _1862, float(_1482.x)) * 0.2886598110198974609375, 0.25 * _1862);
    float _1874 = _1378.x;
    float _1879 = _1378.y;
    float _1900 = _1209.x;
    float _1905 = _1209.y;
    float _1912 = -_1900;
    float _1926 = _1211.x;
    float _1931 = _1211.y;
    float _1938 = -_1926;
    float3 _2176 = (hexcTex_normal.sample(hexcSampler, (float2(fma(_1790, _1508, _1795 * _1510), fma(-_1790, _1510, _1795 * _1508)) + (float2(_1494.xy) * 5.9604644775390625e-08)), gradient2d(float2(fma(_1900, _1508, _1905 * _1510), fma(_1912, _1510, _1905 * _1508)), float2(fma(_1926, _1508, _1931 * _1510), fma(_1938, _1510, _1931 * _1508)))).xyz * 2.0) - float3(1.0);
    float3 _2186 = abs(_2176);
    float2 _2213 = (-float2(_2176.xy)) / float2(fast::max(fast::max(_2186.z, 0.0078125 * fast::max(_2186.x, _2186.y)), 9.9999996826552253889678874634872e-21));
    float _2219 = _2213.x;
    float _2224 = _2213.y;
    float2 _2238 = float2(fma(_1508, _2219, -(_1510 * _2224)), fma(_1510, _2219, _1508 * _2224));
    float3 _2254 = (hexcTex_normal.sample(hexcSampler, (float2(fma(_1832, _1604, _1837 * _1606), fma(-_1832, _1606, _1837 * _1604)) + (float2(_1590.xy) * 5.9604644775390625e-08)), gradient2d(float2(fma(_1900, _1604, _1905 * _1606), fma(_1912, _1606, _1905 * _1604)), float2(fma(_1926, _1604, _1931 * _1606), fma(_1938, _1606, _1931 * _1604)))).xyz * 2.0) - float3(1.0);
    float3 _2264 = abs(_2254);
    float2 _2291 = (-float2(_2254.xy)) / float2(fast::max(fast::max(_2264.z, 0.0078125 * fast::max(_2264.x, _2264.y)), 9.9999996826552253889678874634872e-21));
    float _2297 = _2291.x;
    float _2302 = _2291.y;
    float2 _2316 = float2(fma(_1604, _2297, -(_1606 * _2302)), fma(_1606, _2297, _1604 * _2302));
    float3 _2332 = (hexcTex_normal.sample(hexcSampler, (float2(fma(_1874, _1700, _1879 * _1702), fma(-_1874, _1702, _1879 * _1700)) + (float2(_1686.xy) * 5.9604644775390625e-08)), gradient2d(float2(fma(_1900, _1700, _1905 * _1702), fma(_1912, _1702, _1905 * _1700)), float2(fma(_1926, _1700, _1931 * _1702), fma(_1938, _1702, _1931 * _1700)))).xyz * 2.0) - float3(1.0);
    float3 _2342 = abs(_2332);
    float2 _2369 = (-float2(_2332.xy)) / float2(fast::max(fast::max(_2342.z, 0.0078125 * fast::max(_2342.x, _2342.y)), 9.9999996826552253889678874634872e-21));
    float _2375 = _2369.x;
    float _2380 = _2369.y;
    float2 _2394 = float2(fma(_1700, _2375, -(_1702 * _2380)), fma(_1702, _2375, _1700 * _2380));
    float3 _2128 = float3(dot(_2238, _2238), dot(_2316, _2316), dot(_2394, _2394));
    float3 _2406 = pow(float3(_1441 * _1445, fma(-_1430, _1445, _1442), fma(-_1429, _1445, _1442)), float3(hexcParams.normal_exponent));
    float3 _2413 = mix(float3(1.0), fast::max(sqrt(_2128 / (float3(1.0) + _2128)), float3(0.0)), float3(hexcParams.normal_falloffcontrast)) * _2406;
    float _2421 = (_2413.x + _2413.y) + _2413.z;
    float3 _2695;
    if (_2421 > 0.0)
    {
        _2695 = _2413 / float3(_2421);
    }
    else
    {
        _2695 = _2406 / float3((_2406.x + _2406.y) + _2406.z);
    }
    float3 _2972;
    if (hexcParams.normal_falloff != 0.5)
    {
        float3 _2464 = step(float3(0.5), _2695) * 2.0;
        float3 _2468 = (float3(1.0) - _2464) * 2.0;
        float3 _2483 = fma(_2468 * 0.25, pow(fast::max(float3(0.0), fma(_2695, _2468, _2464)), float3(log(1.0 - hexcParams.normal_falloff) * (-1.44269502162933349609375))), _2464 * 0.5);
        _2972 = _2483 / float3((_2483.x + _2483.y) + _2483.z);
    }
    else
    {
        _2972 = _2695;
    }
    float3 _2631 = fast::normalize(float3(-(((_2238 * _2972.x) + (_2316 * _2972.y)) + (_2394 * _2972.z)), 1.0));
    float3 _1110 = fast::normalize(((_1078 * _2631.x) + ((cross(_1065, _1078) * in.v_tangent.w) * _2631.y)) + (_1065 * _2631.z));
    float _1117 = fast::max(dot(_1110, float3(0.408248007297515869140625, 0.408248007297515869140625, 0.816497027873992919921875)), 0.0);
    out.o_color = float4((float3(0.5) * (0.1500000059604644775390625 + _1117)) + float3(0.039999999105930328369140625 * ((pow(fast::max(dot(_1110, float3(0.21418631076812744140625, 0.21418631076812744140625, 0.95302069187164306640625)), 0.0), 30.0) * 1.511971950531005859375) * _1117)), 1.0);
    return out;
}

