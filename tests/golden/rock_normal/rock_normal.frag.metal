#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct HexcParams
{
    float2 normal_tiling;
    float normal_rotation;
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
    float3 _1171 = fast::normalize(in.v_normal);
    float3 _1184 = fast::normalize(in.v_tangent.xyz - (_1171 * dot(_1171, in.v_tangent.xyz)));
    float2 _1298 = in.v_uv * hexcParams.normal_tiling;
    float2 _1317 = dfdx(_1298);
    float2 _1319 = dfdy(_1298);
    float _1391 = _1298.x;
    float _1393 = floor(_1391 * 0.0357142873108386993408203125);
    float _1395 = _1298.y;
    float _1396 = floor(_1395);
    float _1401 = fma(-28.0, _1393, _1391);
    float _1405 = _1395 - _1396;
    float2 _1406 = float2(_1401, _1405);
    float2 _1417 = float2(fma(3.4642856121063232421875, _1401, _1405 * (-2.0)), 4.0 * _1405);
    float2 _1607 = floor(_1417);
    int2 _1608 = int2(_1607);
    float2 _1612 = _1417 - _1607;
    float _1613 = _1612.x;
    float _1614 = _1612.y;
    float _1625 = -((1.0 - _1613) - _1614);
    float _1626 = step(0.0, _1625);
    float _1629 = fma(2.0, _1626, -1.0);
    int _1649 = int(_1626);
    int2 _1654 = _1608 + int2(_1649);
    int _1658 = 1 - _1649;
    int2 _1660 = _1608 + int2(_1649, _1658);
    int2 _1666 = _1608 + int2(_1658, _1649);
    uint _1431 = uint(int(_1396));
    uint2 _1438 = uint2((97u * uint(int(_1393))) - (2u * _1431), 4u * _1431);
    uint3 _1708 = (uint3(uint2(int2(uint2(_1654) + _1438)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1710 = _1708.y;
    uint _1712 = _1708.z;
    uint _1716 = _1708.x + (_1710 * _1712);
    uint _1725 = _1710 + (_1712 * _1716);
    uint3 _3209 = uint3(_1716, _1725, _1712 + (_1716 * _1725));
    uint3 _1740 = _3209 ^ (_3209 >> uint3(16u));
    uint _1742 = _1740.y;
    uint _1744 = _1740.z;
    uint _1748 = _1740.x + (_1742 * _1744);
    uint _1757 = _1742 + (_1744 * _1748);
    uint3 _1679 = uint3(_1748, _1757, _1744 + (_1748 * _1757)) >> uint3(8u);
    float _1691 = (fma(float(_1679.z), 1.1920928955078125e-07, -1.0) * 3.1415927410125732421875) * hexcParams.normal_rotation;
    float _1695 = cos(_1691);
    float _1697 = sin(_1691);
    uint3 _1810 = (uint3(uint2(int2(uint2(_1660) + _1438)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1812 = _1810.y;
    uint _1814 = _1810.z;
    uint _1818 = _1810.x + (_1812 * _1814);
    uint _1827 = _1812 + (_1814 * _1818);
    uint3 _3211 = uint3(_1818, _1827, _1814 + (_1818 * _1827));
    uint3 _1842 = _3211 ^ (_3211 >> uint3(16u));
    uint _1844 = _1842.y;
    uint _1846 = _1842.z;
    uint _1850 = _1842.x + (_1844 * _1846);
    uint _1859 = _1844 + (_1846 * _1850);
    uint3 _1781 = uint3(_1850, _1859, _1846 + (_1850 * _1859)) >> uint3(8u);
    float _1793 = (fma(float(_1781.z), 1.1920928955078125e-07, -1.0) * 3.1415927410125732421875) * hexcParams.normal_rotation;
    float _1797 = cos(_1793);
    float _1799 = sin(_1793);
    uint3 _1912 = (uint3(uint2(int2(uint2(_1666) + _1438)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1914 = _1912.y;
    uint _1916 = _1912.z;
    uint _1920 = _1912.x + (_1914 * _1916);
    uint _1929 = _1914 + (_1916 * _1920);
    uint3 _3213 = uint3(_1920, _1929, _1916 + (_1920 * _1929));
    uint3 _1944 = _3213 ^ (_3213 >> uint3(16u));
    uint _1946 = _1944.y;
    uint _1948 = _1944.z;
    uint _1952 = _1944.x + (_1946 * _1948);
    uint _1961 = _1946 + (_1948 * _1952);
    uint3 _1883 = uint3(_1952, _1961, _1948 + (_1952 * _1961)) >> uint3(8u);
    float _1895 = (fma(float(_1883.z), 1.1920928955078125e-07, -1.0) * 3.1415927410125732421875) * hexcParams.normal_rotation;
    float _1899 = cos(_1895);
    float _1901 = sin(_1895);
    float _1980 = float(_1654.y);
    float2 _1485 = _1406 - float2(fma(0.5, _1980, float(_1654.x)) * 0.2886598110198974609375, 0.25 * _1980);
    float _1996 = float(_1660.y);
    float2 _1489 = _1406 - float2(fma(0.5, _1996, float(_1660.x)) * 0.2886598110198974609375, 0.25 * _1996);
    float _2012 = float(_1666.y);
    float2 _1493 = _1406 - float2(fma(0.5, _2012, float(_1666.x)) * 0.2886598110198974609375, 0.25 * _2012);
    float _2024 = _1485.x;
    float _2029 = _1485.y;
    float _2050 = _1489.x;
    float _2055 = _1489.y;
    float _2076 = _1493.x;
    float _2081 = _1493.y;
    float _2102 = _1317.x;
    float _2107 = _1317.y;
    float _2114 = -_2102;
    float _2128 = _1319.x;
    float _2133 = _1319.y;
    float _2140 = -_2128;
    float3 _2382 = (hexcTex_normal.sample(hexcSampler, (float2(fma(_2024, _1695, _2029 * _1697), fma(-_2024, _1697, _2029 * _1695)) + (float2(_1679.xy) * 5.9604644775390625e-08)), gradient2d(float2(fma(_2102, _1695, _2107 * _1697), fma(_2114, _1697, _2107 * _1695)), float2(fma(_2128, _1695, _2133 * _1697), fma(_2140, _1697, _2133 * _1695)))).xyz * 2.0) - float3(1.0);
    float3 _2392 = abs(_2382);
    float2 _2419 = (-float2(_2382.xy)) / float2(fast::max(fast::max(_2392.z, 0.0078125 * fast::max(_2392.x, _2392.y)), 9.9999996826552253889678874634872e-21));
    float _2425 = _2419.x;
    float _2430 = _2419.y;
    float2 _2444 = float2(fma(_1695, _2425, -(_1697 * _2430)), fma(_1697, _2425, _1695 * _2430));
    float3 _2460 = (hexcTex_normal.sample(hexcSampler, (float2(fma(_2050, _1797, _2055 * _1799), fma(-_2050, _1799, _2055 * _1797)) + (float2(_1781.xy) * 5.9604644775390625e-08)), gradient2d(float2(fma(_2102, _1797, _2107 * _1799), fma(_2114, _1799, _2107 * _1797)), float2(fma(_2128, _1797, _2133 * _1799), fma(_2140, _1799, _2133 * _1797)))).xyz * 2.0) - float3(1.0);
    float3 _2470 = abs(_2460);
    float2 _2497 = (-float2(_2460.xy)) / float2(fast::max(fast::max(_2470.z, 0.0078125 * fast::max(_2470.x, _2470.y)), 9.9999996826552253889678874634872e-21));
    float _2503 = _2497.x;
    float _2508 = _2497.y;
    float2 _2522 = float2(fma(_1797, _2503, -(_1799 * _2508)), fma(_1799, _2503, _1797 * _2508));
    float3 _2538 = (hexcTex_normal.sample(hexcSampler, (float2(fma(_2076, _1899, _2081 * _1901), fma(-_2076, _1901, _2081 * _1899)) + (float2(_1883.xy) * 5.9604644775390625e-08)), gradient2d(float2(fma(_2102, _1899, _2107 * _1901), fma(_2114, _1901, _2107 * _1899)), float2(fma(_2128, _1899, _2133 * _1901), fma(_2140, _1901, _2133 * _1899)))).xyz * 2.0) - float3(1.0);
    float3 _2548 = abs(_2538);
    float2 _2575 = (-float2(_2538.xy)) / float2(fast::max(fast::max(_2548.z, 0.0078125 * fast::max(_2548.x, _2548.y)), 9.9999996826552253889678874634872e-21));
    float _2581 = _2575.x;
    float _2586 = _2575.y;
    float2 _2600 = float2(fma(_1899, _2581, -(_1901 * _2586)), fma(_1901, _2581, _1899 * _2586));
    float3 _2332 = float3(dot(_2444, _2444), dot(_2522, _2522), dot(_2600, _2600));
    float3 _2613 = pow(float3(_1625 * _1629, fma(-_1614, _1629, _1626), fma(-_1613, _1629, _1626)), float3(hexcParams.normal_exponent));
    float3 _2622 = mix(float3(1.0), fast::max(sqrt(_2332 / (float3(1.0) + _2332)), float3(0.0)), float3(hexcParams.normal_falloffcontrast)) * _2613;
    float _2634 = (_2622.x + _2622.y) + _2622.z;
    float3 _2923;
    if (_2634 > 0.0)
    {
        _2923 = _2622 / float3(_2634);
    }
    else
    {
        _2923 = _2613 / float3((_2613.x + _2613.y) + _2613.z);
    }
    float3 _2846 = fast::normalize(float3(-(((_2444 * _2923.x) + (_2522 * _2923.y)) + (_2600 * _2923.z)), 1.0));
    float3 _1216 = fast::normalize(((_1184 * _2846.x) + ((cross(_1171, _1184) * in.v_tangent.w) * _2846.y)) + (_1171 * _2846.z));
    float _1223 = fast::max(dot(_1216, float3(0.408248007297515869140625, 0.408248007297515869140625, 0.816497027873992919921875)), 0.0);
    out.o_color = float4((float3(0.5) * (0.1500000059604644775390625 + _1223)) + float3(0.039999999105930328369140625 * ((pow(fast::max(dot(_1216, float3(0.21418631076812744140625, 0.21418631076812744140625, 0.95302069187164306640625)), 0.0), 30.0) * 1.511971950531005859375) * _1223)), 1.0);
    return out;
}

