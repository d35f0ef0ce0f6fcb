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
    float3 _1011 = fast::normalize(in.v_normal);
    float3 _1024 = fast::normalize(in.v_tangent.xyz - (_1011 * dot(_1011, in.v_tangent.xyz)));
    float2 _1135 = in.v_uv * hexcParams.normal_tiling;
    float2 _1201 = dfdx(_1135);
    float2 _1203 = dfdy(_1135);
    float _1205 = _1135.x;
    float _1207 = floor(_1205 * 0.0357142873108386993408203125);
    float _1209 = _1135.y;
    float _1210 = floor(_1209);
    float _1215 = fma(-28.0, _1207, _1205);
    float _1219 = _1209 - _1210;
    float2 _1220 = float2(_1215, _1219);
    float2 _1231 = float2(fma(3.4642856121063232421875, _1215, _1219 * (-2.0)), 4.0 * _1219);
    float2 _1350 = floor(_1231);
    int2 _1351 = int2(_1350);
    float2 _1355 = _1231 - _1350;
    float _1356 = _1355.x;
    float _1357 = _1355.y;
    float _1368 = -((1.0 - _1356) - _1357);
    float _1369 = step(0.0, _1368);
    float _1372 = fma(2.0, _1369, -1.0);
    int _1392 = int(_1369);
    int2 _1397 = _1351 + int2(_1392);
    int _1401 = 1 - _1392;
    int2 _1403 = _1351 + int2(_1392, _1401);
    int2 _1409 = _1351 + int2(_1401, _1392);
    int _1242 = int(_1210);
    int2 _1248 = int2((97 * int(_1207)) - (2 * _1242), 4 * _1242);
    uint3 _1445 = (uint3(uint2(_1397 + _1248), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1447 = _1445.y;
    uint _1449 = _1445.z;
    uint _1453 = _1445.x + (_1447 * _1449);
    uint _1462 = _1447 + (_1449 * _1453);
    uint3 _2870 = uint3(_1453, _1462, _1449 + (_1453 * _1462));
    uint3 _1477 = _2870 ^ (_2870 >> uint3(16u));
    uint _1479 = _1477.y;
    uint _1481 = _1477.z;
    uint _1485 = _1477.x + (_1479 * _1481);
    uint _1494 = _1479 + (_1481 * _1485);
    uint3 _1421 = uint3(_1485, _1494, _1481 + (_1485 * _1494)) >> uint3(8u);
    float _1433 = (fma(float(_1421.z), 1.1920928955078125e-07, -1.0) * 3.1415927410125732421875) * hexcParams.normal_rotation;
    float _1435 = cos(_1433);
    float _1437 = sin(_1433);
    uint3 _1541 = (uint3(uint2(_1403 + _1248), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1543 = _1541.y;
    uint _1545 = _1541.z;
    uint _1549 = _1541.x + (_1543 * _1545);
    uint _1558 = _1543 + (_1545 * _1549);
    uint3 _2872 = uint3(_1549, _1558, _1545 + (_1549 * _1558));
    uint3 _1573 = _2872 ^ (_2872 >> uint3(16u));
    uint _1575 = _1573.y;
    uint _1577 = _1573.z;
    uint _1581 = _1573.x + (_1575 * _1577);
    uint _1590 = _1575 + (_1577 * _1581);
    uint3 _1517 = uint3(_1581, _1590, _1577 + (_1581 * _1590)) >> uint3(8u);
    float _1529 = (fma(float(_1517.z), 1.1920928955078125e-07, -1.0) * 3.1415927410125732421875) * hexcParams.normal_rotation;
    float _1531 = cos(_1529);
    float _1533 = sin(_1529);
    uint3 _1637 = (uint3(uint2(_1409 + _1248), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1639 = _1637.y;
    uint _1641 = _1637.z;
    uint _1645 = _1637.x + (_1639 * _1641);
    uint _1654 = _1639 + (_1641 * _1645);
    uint3 _2874 = uint3(_1645, _1654, _1641 + (_1645 * _1654));
    uint3 _1669 = _2874 ^ (_2874 >> uint3(16u));
    uint _1671 = _1669.y;
    uint _1673 = _1669.z;
    uint _1677 = _1669.x + (_1671 * _1673);
    uint _1686 = _1671 + (_1673 * _1677);
    uint3 _1613 = uint3(_1677, _1686, _1673 + (_1677 * _1686)) >> uint3(8u);
    float _1625 = (fma(float(_1613.z), 1.1920928955078125e-07, -1.0) * 3.1415927410125732421875) * hexcParams.normal_rotation;
    float _1627 = cos(_1625);
    float _1629 = sin(_1625);
    float _1705 = float(_1397.y);
    float2 _1285 = _1220 - float2(fma(0.5, _1705, float(_1397.x)) * 0.2886598110198974609375, 0.25 * _1705);
    float _1717 = _1285.x;
    float _1722 = _1285.y;
    float _1747 = float(_1403.y);
    float2 _1295 = _1220 - float2(fma(0.5, _1747, float(_1403.x)) * 0.2886598110198974609375, 0.25 * _1747);
    float _1759 = _1295.x;
    float _1764 = _1295.y;
    float _1789 = float(_1409.y);
    float2 _1305 = _1220 - float2(fma(0.5, _1789, float(_1409.x)) * 0.2886598110198974609375, 0.25 * _1789);
    float _1801 = _1305.x;
    float _1806 = _1305.y;
    float _1827 = _1201.x;
    float _1832 = _1201.y;
    float _1839 = -_1827;
    float _1853 = _1203.x;
    float _1858 = _1203.y;
    float _1865 = -_1853;
    float3 _2103 = (hexcTex_normal.sample(hexcSampler, (float2(fma(_1717, _1435, _1722 * _1437), fma(-_1717, _1437, _1722 * _1435)) + (float2(_1421.xy) * 5.9604644775390625e-08)), gradient2d(float2(fma(_1827, _1435, _1832 * _1437), fma(_1839, _1437, _1832 * _1435)), float2(fma(_1853, _1435, _1858 * _1437), fma(_1865, _1437, _1858 * _1435)))).xyz * 2.0) - float3(1.0);
    float3 _2113 = abs(_2103);
    float2 _2139 = (-float2(_2103.xy)) / float2(fast::max(_2113.z, 0.0078125 * fast::max(_2113.x, _2113.y)));
    float _2145 = _2139.x;
    float _2150 = _2139.y;
    float2 _2164 = float2(fma(_1435, _2145, -(_1437 * _2150)), fma(_1437, _2145, _1435 * _2150));
    float3 _2180 = (hexcTex_normal.sample(hexcSampler, (float2(fma(_1759, _1531, _1764 * _1533), fma(-_1759, _1533, _1764 * _1531)) + (float2(_1517.xy) * 5.9604644775390625e-08)), gradient2d(float2(fma(_1827, _1531, _1832 * _1533), fma(_1839, _1533, _1832 * _1531)), float2(fma(_1853, _1531, _1858 * _1533), fma(_1865, _1533, _1858 * _1531)))).xyz * 2.0) - float3(1.0);
    float3 _2190 = abs(_2180);
    float2 _2216 = (-float2(_2180.xy)) / float2(fast::max(_2190.z, 0.0078125 * fast::max(_2190.x, _2190.y)));
    float _2222 = _2216.x;
    float _2227 = _2216.y;
    float2 _2241 = float2(fma(_1531, _2222, -(_1533 * _2227)), fma(_1533, _2222, _1531 * _2227));
    float3 _2257 = (hexcTex_normal.sample(hexcSampler, (float2(fma(_1801, _1627, _1806 * _1629), fma(-_1801, _1629, _1806 * _1627)) + (float2(_1613.xy) * 5.9604644775390625e-08)), gradient2d(float2(fma(_1827, _1627, _1832 * _1629), fma(_1839, _1629, _1832 * _1627)), float2(fma(_1853, _1627, _1858 * _1629), fma(_1865, _1629, _1858 * _1627)))).xyz * 2.0) - float3(1.0);
    float3 _2267 = abs(_2257);
    float2 _2293 = (-float2(_2257.xy)) / float2(fast::max(_2267.z, 0.0078125 * fast::max(_2267.x, _2267.y)));
    float _2299 = _2293.x;
    float _2304 = _2293.y;
    float2 _2318 = float2(fma(_1627, _2299, -(_1629 * _2304)), fma(_1629, _2299, _1627 * _2304));
    float3 _2055 = float3(dot(_2164, _2164), dot(_2241, _2241), dot(_2318, _2318));
    float3 _2333 = mix(float3(1.0), sqrt(_2055 / (float3(1.0) + _2055)), float3(hexcParams.normal_falloffcontrast)) * pow(float3(_1368 * _1372, fma(-_1357, _1372, _1369), fma(-_1356, _1372, _1369)), float3(hexcParams.normal_exponent));
    float3 _2344 = _2333 / float3((_2333.x + _2333.y) + _2333.z);
    float3 _2869;
    if (hexcParams.normal_falloff != 0.5)
    {
        float3 _2366 = step(float3(0.5), _2344) * 2.0;
        float3 _2370 = (float3(1.0) - _2366) * 2.0;
        float3 _2385 = fma(_2370 * 0.25, pow(fast::max(float3(0.0), fma(_2344, _2370, _2366)), float3(log(1.0 - hexcParams.normal_falloff) * (-1.44269502162933349609375))), _2366 * 0.5);
        _2869 = _2385 / float3((_2385.x + _2385.y) + _2385.z);
    }
    else
    {
        _2869 = _2344;
    }
    float3 _2533 = fast::normalize(float3(-(((_2164 * _2869.x) + (_2241 * _2869.y)) + (_2318 * _2869.z)), 1.0));
    float3 _1056 = fast::normalize(((_1024 * _2533.x) + ((cross(_1011, _1024) * in.v_tangent.w) * _2533.y)) + (_1011 * _2533.z));
    float _1063 = fast::max(dot(_1056, float3(0.408248007297515869140625, 0.408248007297515869140625, 0.816497027873992919921875)), 0.0);
    out.o_color = float4((float3(0.5) * (0.1500000059604644775390625 + _1063)) + float3(0.039999999105930328369140625 * ((pow(fast::max(dot(_1056, float3(0.21418631076812744140625, 0.21418631076812744140625, 0.95302069187164306640625)), 0.0), 30.0) * 1.511971950531005859375) * _1063)), 1.0);
    return out;
}

