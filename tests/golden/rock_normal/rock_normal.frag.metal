#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct HexcParams
{
    float2 normal_tiling;
    float normal_rotation;
    float normal_falloffcontrast;
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
    float3 _1495 = fast::normalize(in.v_normal);
    float3 _1508 = fast::normalize(in.v_tangent.xyz - (_1495 * dot(_1495, in.v_tangent.xyz)));
    float2 _1617 = in.v_uv * hexcParams.normal_tiling;
    float2 _1619 = dfdx(_1617);
    float2 _1621 = dfdy(_1617);
    float _1721 = _1617.x;
    float _1723 = floor(_1721 * 0.0357142873108386993408203125);
    float _1725 = _1617.y;
    float _1726 = floor(_1725);
    float _1731 = fma(-28.0, _1723, _1721);
    float _1735 = _1725 - _1726;
    float2 _1736 = float2(_1731, _1735);
    float2 _1747 = float2(fma(3.4642856121063232421875, _1731, _1735 * (-2.0)), 4.0 * _1735);
    float2 _1875 = floor(_1747);
    int2 _1876 = int2(_1875);
    float2 _1880 = _1747 - _1875;
    float _1881 = _1880.x;
    float _1882 = _1880.y;
    float _1893 = -((1.0 - _1881) - _1882);
    float _1894 = step(0.0, _1893);
    float _1897 = fma(2.0, _1894, -1.0);
    float3 _1915 = float3(_1893 * _1897, fma(-_1882, _1897, _1894), fma(-_1881, _1897, _1894));
    int _1917 = int(_1894);
    int2 _1922 = _1876 + int2(_1917);
    int _1926 = 1 - _1917;
    int2 _1928 = _1876 + int2(_1917, _1926);
    int2 _1934 = _1876 + int2(_1926, _1917);
    uint2 _1761 = uint2(int2(int(_1723), int(_1726)));
    uint _1767 = _1761.y;
    uint2 _1773 = uint2((97u * _1761.x) - (2u * _1767), 4u * _1767);
    float _2006 = float(_1922.y);
    float2 _1801 = _1736 - float2(fma(0.5, _2006, float(_1922.x)) * 0.2886598110198974609375, 0.25 * _2006);
    uint3 _2188 = (uint3(uint2(int2(uint2(_1922) + _1773)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2190 = _2188.y;
    uint _2192 = _2188.z;
    uint _2196 = _2188.x + (_2190 * _2192);
    uint _2205 = _2190 + (_2192 * _2196);
    uint3 _4608 = uint3(_2196, _2205, _2192 + (_2196 * _2205));
    uint3 _2220 = _4608 ^ (_4608 >> uint3(16u));
    uint _2222 = _2220.y;
    uint _2224 = _2220.z;
    uint _2228 = _2220.x + (_2222 * _2224);
    uint _2237 = _2222 + (_2224 * _2228);
    float3 _2097 = float3(uint3(_2228, _2237, _2224 + (_2228 * _2237)) >> uint3(8u)) * 5.9604644775390625e-08;
    float _2106 = (fma(_2097.z, 2.0, -1.0) * 3.1415927410125732421875) * hexcParams.normal_rotation;
    float _2175 = cos(_2106);
    float _2177 = sin(_2106);
    float _2319 = _1801.x;
    float _2324 = _1801.y;
    float _2345 = _1619.x;
    float _2350 = _1619.y;
    float _2357 = -_2345;
    float _2371 = _1621.x;
    float _2376 = _1621.y;
    float _2383 = -_2371;
    float _2401 = float(_1928.y);
    float2 _1824 = _1736 - float2(fma(0.5, _2401, float(_1928.x)) * 0.2886598110198974609375, 0.25 * _2401);
    uint3 _2583 = (uint3(uint2(int2(uint2(_1928) + _1773)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2585 = _2583.y;
    uint _2587 = _2583.z;
    uint _2591 = _2583.x + (_2585 * _2587);
    uint _2600 = _2585 + (_2587 * _2591);
    uint3 _4611 = uint3(_2591, _2600, _2587 + (_2591 * _2600));
    uint3 _2615 = _4611 ^ (_4611 >> uint3(16u));
    uint _2617 = _2615.y;
    uint _2619 = _2615.z;
    uint _2623 = _2615.x + (_2617 * _2619);
    uint _2632 = _2617 + (_2619 * _2623);
    float3 _2492 = float3(uint3(_2623, _2632, _2619 + (_2623 * _2632)) >> uint3(8u)) * 5.9604644775390625e-08;
    float _2501 = (fma(_2492.z, 2.0, -1.0) * 3.1415927410125732421875) * hexcParams.normal_rotation;
    float _2570 = cos(_2501);
    float _2572 = sin(_2501);
    float _2714 = _1824.x;
    float _2719 = _1824.y;
    float _2796 = float(_1934.y);
    float2 _1847 = _1736 - float2(fma(0.5, _2796, float(_1934.x)) * 0.2886598110198974609375, 0.25 * _2796);
    uint3 _2978 = (uint3(uint2(int2(uint2(_1934) + _1773)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2980 = _2978.y;
    uint _2982 = _2978.z;
    uint _2986 = _2978.x + (_2980 * _2982);
    uint _2995 = _2980 + (_2982 * _2986);
    uint3 _4614 = uint3(_2986, _2995, _2982 + (_2986 * _2995));
    uint3 _3010 = _4614 ^ (_4614 >> uint3(16u));
    uint _3012 = _3010.y;
    uint _3014 = _3010.z;
    uint _3018 = _3010.x + (_3012 * _3014);
    uint _3027 = _3012 + (_3014 * _3018);
    float3 _2887 = float3(uint3(_3018, _3027, _3014 + (_3018 * _3027)) >> uint3(8u)) * 5.9604644775390625e-08;
    float _2896 = (fma(_2887.z, 2.0, -1.0) * 3.1415927410125732421875) * hexcParams.normal_rotation;
    float _2965 = cos(_2896);
    float _2967 = sin(_2896);
    float _3109 = _1847.x;
    float _3114 = _1847.y;
    float3 _3344 = (hexcTex_normal.sample(hexcSampler, ((float2(fma(_2319, _2175, _2324 * _2177), fma(-_2319, _2177, _2324 * _2175)) * 1.0) + _2097.xy), gradient2d(float2(fma(_2345, _2175, _2350 * _2177), fma(_2357, _2177, _2350 * _2175)) * 1.0, float2(fma(_2371, _2175, _2376 * _2177), fma(_2383, _2177, _2376 * _2175)) * 1.0)).xyz * 2.0) - float3(1.0);
    float3 _3354 = abs(_3344);
    float2 _3381 = (-float2(_3344.xy)) / float2(fast::max(fast::max(_3354.z, 0.0078125 * fast::max(_3354.x, _3354.y)), 9.9999996826552253889678874634872e-21));
    float _3387 = _3381.x;
    float _3392 = _3381.y;
    float2 _3240 = float2(fma(_2175, _3387, -(_2177 * _3392)), fma(_2177, _3387, _2175 * _3392)) * 1.0;
    float3 _3422 = (hexcTex_normal.sample(hexcSampler, ((float2(fma(_2714, _2570, _2719 * _2572), fma(-_2714, _2572, _2719 * _2570)) * 1.0) + _2492.xy), gradient2d(float2(fma(_2345, _2570, _2350 * _2572), fma(_2357, _2572, _2350 * _2570)) * 1.0, float2(fma(_2371, _2570, _2376 * _2572), fma(_2383, _2572, _2376 * _2570)) * 1.0)).xyz * 2.0) - float3(1.0);
    float3 _3432 = abs(_3422);
    float2 _3459 = (-float2(_3422.xy)) / float2(fast::max(fast::max(_3432.z, 0.0078125 * fast::max(_3432.x, _3432.y)), 9.9999996826552253889678874634872e-21));
    float _3465 = _3459.x;
    float _3470 = _3459.y;
    float2 _3254 = float2(fma(_2570, _3465, -(_2572 * _3470)), fma(_2572, _3465, _2570 * _3470)) * 1.0;
    float3 _3500 = (hexcTex_normal.sample(hexcSampler, ((float2(fma(_3109, _2965, _3114 * _2967), fma(-_3109, _2967, _3114 * _2965)) * 1.0) + _2887.xy), gradient2d(float2(fma(_2345, _2965, _2350 * _2967), fma(_2357, _2967, _2350 * _2965)) * 1.0, float2(fma(_2371, _2965, _2376 * _2967), fma(_2383, _2967, _2376 * _2965)) * 1.0)).xyz * 2.0) - float3(1.0);
    float3 _3510 = abs(_3500);
    float2 _3537 = (-float2(_3500.xy)) / float2(fast::max(fast::max(_3510.z, 0.0078125 * fast::max(_3510.x, _3510.y)), 9.9999996826552253889678874634872e-21));
    float _3543 = _3537.x;
    float _3548 = _3537.y;
    float2 _3271 = float2(fma(_2965, _3543, -(_2967 * _3548)), fma(_2967, _3543, _2965 * _3548)) * 1.0;
    float3 _3284 = float3(dot(_3240, _3240), dot(_3254, _3254), dot(_3271, _3271));
    float3 _3660 = _1915 * _1915;
    float3 _3678 = (_1915 * _3660) * (_3660 * _3660);
    float3 _3597 = mix(float3(1.0), fast::max(sqrt(_3284 / (float3(1.0) + _3284)), float3(0.0)), float3(hexcParams.normal_falloffcontrast)) * _3678;
    float _3609 = (_3597.x + _3597.y) + _3597.z;
    float3 _4530;
    if (_3609 > 0.0)
    {
        _4530 = _3597 / float3(_3609);
    }
    else
    {
        _4530 = _3678 / float3((_3678.x + _3678.y) + _3678.z);
    }
    float3 _3943 = fast::normalize(float3(-(((_3240 * _4530.x) + (_3254 * _4530.y)) + (_3271 * _4530.z)), 1.0));
    float3 _1540 = fast::normalize(((_1508 * _3943.x) + ((cross(_1495, _1508) * in.v_tangent.w) * _3943.y)) + (_1495 * _3943.z));
    float _1547 = fast::max(dot(_1540, float3(0.408248007297515869140625, 0.408248007297515869140625, 0.816497027873992919921875)), 0.0);
    out.o_color = float4((float3(0.5) * (0.1500000059604644775390625 + _1547)) + float3(0.039999999105930328369140625 * ((pow(fast::max(dot(_1540, float3(0.21418631076812744140625, 0.21418631076812744140625, 0.95302069187164306640625)), 0.0), 30.0) * 1.511971950531005859375) * _1547)), 1.0);
    return out;
}

