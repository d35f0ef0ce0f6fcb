#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct HexcParams
{
    float2 albedo_tiling;
    float albedo_rotation;
    float albedo_falloffcontrast;
    float normal_falloffcontrast;
    float roughness_falloffcontrast;
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

fragment main0_out main0(main0_in in [[stage_in]], constant HexcParams& hexcParams [[buffer(0)]], texture2d<float> hexcTex_albedo [[texture(0)]], texture2d<float> hexcTex_normal [[texture(1)]], texture2d<float> hexcTex_roughness [[texture(2)]], sampler hexcSampler [[sampler(0)]])
{
    main0_out out = {};
    float2 _1618 = in.v_uv * hexcParams.albedo_tiling;
    float2 _1635 = dfdx(_1618);
    float2 _1637 = dfdy(_1618);
    float _1709 = _1618.x;
    float _1711 = floor(_1709 * 0.0357142873108386993408203125);
    float _1713 = _1618.y;
    float _1714 = floor(_1713);
    float _1719 = fma(-28.0, _1711, _1709);
    float _1723 = _1713 - _1714;
    float2 _1724 = float2(_1719, _1723);
    float2 _1735 = float2(fma(3.4642856121063232421875, _1719, _1723 * (-2.0)), 4.0 * _1723);
    float2 _1925 = floor(_1735);
    int2 _1926 = int2(_1925);
    float2 _1930 = _1735 - _1925;
    float _1931 = _1930.x;
    float _1932 = _1930.y;
    float _1943 = -((1.0 - _1931) - _1932);
    float _1944 = step(0.0, _1943);
    float _1947 = fma(2.0, _1944, -1.0);
    float3 _1965 = float3(_1943 * _1947, fma(-_1932, _1947, _1944), fma(-_1931, _1947, _1944));
    int _1967 = int(_1944);
    int2 _1972 = _1926 + int2(_1967);
    int _1976 = 1 - _1967;
    int2 _1978 = _1926 + int2(_1967, _1976);
    int2 _1984 = _1926 + int2(_1976, _1967);
    uint _1749 = uint(int(_1714));
    uint2 _1756 = uint2((97u * uint(int(_1711))) - (2u * _1749), 4u * _1749);
    uint3 _2026 = (uint3(uint2(int2(uint2(_1972) + _1756)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2028 = _2026.y;
    uint _2030 = _2026.z;
    uint _2034 = _2026.x + (_2028 * _2030);
    uint _2043 = _2028 + (_2030 * _2034);
    uint3 _7238 = uint3(_2034, _2043, _2030 + (_2034 * _2043));
    uint3 _2058 = _7238 ^ (_7238 >> uint3(16u));
    uint _2060 = _2058.y;
    uint _2062 = _2058.z;
    uint _2066 = _2058.x + (_2060 * _2062);
    uint _2075 = _2060 + (_2062 * _2066);
    uint3 _1997 = uint3(_2066, _2075, _2062 + (_2066 * _2075)) >> uint3(8u);
    float _2009 = (fma(float(_1997.z), 1.1920928955078125e-07, -1.0) * 3.1415927410125732421875) * hexcParams.albedo_rotation;
    float _2013 = cos(_2009);
    float _2015 = sin(_2009);
    uint3 _2128 = (uint3(uint2(int2(uint2(_1978) + _1756)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2130 = _2128.y;
    uint _2132 = _2128.z;
    uint _2136 = _2128.x + (_2130 * _2132);
    uint _2145 = _2130 + (_2132 * _2136);
    uint3 _7240 = uint3(_2136, _2145, _2132 + (_2136 * _2145));
    uint3 _2160 = _7240 ^ (_7240 >> uint3(16u));
    uint _2162 = _2160.y;
    uint _2164 = _2160.z;
    uint _2168 = _2160.x + (_2162 * _2164);
    uint _2177 = _2162 + (_2164 * _2168);
    uint3 _2099 = uint3(_2168, _2177, _2164 + (_2168 * _2177)) >> uint3(8u);
    float _2111 = (fma(float(_2099.z), 1.1920928955078125e-07, -1.0) * 3.1415927410125732421875) * hexcParams.albedo_rotation;
    float _2115 = cos(_2111);
    float _2117 = sin(_2111);
    uint3 _2230 = (uint3(uint2(int2(uint2(_1984) + _1756)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2232 = _2230.y;
    uint _2234 = _2230.z;
    uint _2238 = _2230.x + (_2232 * _2234);
    uint _2247 = _2232 + (_2234 * _2238);
    uint3 _7242 = uint3(_2238, _2247, _2234 + (_2238 * _2247));
    uint3 _2262 = _7242 ^ (_7242 >> uint3(16u));
    uint _2264 = _2262.y;
    uint _2266 = _2262.z;
    uint _2270 = _2262.x + (_2264 * _2266);
    uint _2279 = _2264 + (_2266 * _2270);
    uint3 _2201 = uint3(_2270, _2279, _2266 + (_2270 * _2279)) >> uint3(8u);
    float _2213 = (fma(float(_2201.z), 1.1920928955078125e-07, -1.0) * 3.1415927410125732421875) * hexcParams.albedo_rotation;
    float _2217 = cos(_2213);
    float _2219 = sin(_2213);
    float _2298 = float(_1972.y);
    float2 _1803 = _1724 - float2(fma(0.5, _2298, float(_1972.x)) * 0.2886598110198974609375, 0.25 * _2298);
    float _2314 = float(_1978.y);
    float2 _1807 = _1724 - float2(fma(0.5, _2314, float(_1978.x)) * 0.2886598110198974609375, 0.25 * _2314);
    float _2330 = float(_1984.y);
    float2 _1811 = _1724 - float2(fma(0.5, _2330, float(_1984.x)) * 0.2886598110198974609375, 0.25 * _2330);
    float _2342 = _1803.x;
    float _2347 = _1803.y;
    float2 _1823 = float2(fma(_2342, _2013, _2347 * _2015), fma(-_2342, _2015, _2347 * _2013)) + (float2(_1997.xy) * 5.9604644775390625e-08);
    float _2368 = _1807.x;
    float _2373 = _1807.y;
    float2 _1836 = float2(fma(_2368, _2115, _2373 * _2117), fma(-_2368, _2117, _2373 * _2115)) + (float2(_2099.xy) * 5.9604644775390625e-08);
    float _2394 = _1811.x;
    float _2399 = _1811.y;
    float2 _1849 = float2(fma(_2394, _2217, _2399 * _2219), fma(-_2394, _2219, _2399 * _2217)) + (float2(_2201.xy) * 5.9604644775390625e-08);
    float _2420 = _1635.x;
    float _2425 = _1635.y;
    float _2432 = -_2420;
    float _2446 = _1637.x;
    float _2451 = _1637.y;
    float _2458 = -_2446;
    float4 _2601 = hexcTex_albedo.sample(hexcSampler, _1823, gradient2d(float2(fma(_2420, _2013, _2425 * _2015), fma(_2432, _2015, _2425 * _2013)), float2(fma(_2446, _2013, _2451 * _2015), fma(_2458, _2015, _2451 * _2013))));
    float4 _2611 = hexcTex_albedo.sample(hexcSampler, _1836, gradient2d(float2(fma(_2420, _2115, _2425 * _2117), fma(_2432, _2117, _2425 * _2115)), float2(fma(_2446, _2115, _2451 * _2117), fma(_2458, _2117, _2451 * _2115))));
    float4 _2621 = hexcTex_albedo.sample(hexcSampler, _1849, gradient2d(float2(fma(_2420, _2217, _2425 * _2219), fma(_2432, _2219, _2425 * _2217)), float2(fma(_2446, _2217, _2451 * _2219), fma(_2458, _2219, _2451 * _2217))));
    float3 _2760 = _1965 * _1965;
    float3 _2778 = (_1965 * _2760) * (_2760 * _2760);
    float3 _2697 = mix(float3(1.0), fast::max(float3(dot(_2601, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_2611, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_2621, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0))), float3(0.0)), float3(hexcParams.albedo_falloffcontrast)) * _2778;
    float _2709 = (_2697.x + _2697.y) + _2697.z;
    float3 _6440;
    if (_2709 > 0.0)
    {
        _6440 = _2697 / float3(_2709);
    }
    else
    {
        _6440 = _2778 / float3((_2778.x + _2778.y) + _2778.z);
    }
    float3 _2829 = step(float3(0.5), _6440) * 2.0;
    float3 _2833 = (float3(1.0) - _2829) * 2.0;
    float3 _2839 = fast::max(float3(0.0), fma(_6440, _2833, _2829));
    float3 _2858 = fma(_2833 * 0.25, _2839 * _2839, _2829 * 0.5);
    float3 _2869 = _2858 / float3((_2858.x + _2858.y) + _2858.z);
    float2 _3099 = dfdx(_1618);
    float2 _3101 = dfdy(_1618);
    float _3884 = _3099.x;
    float _3889 = _3099.y;
    float _3896 = -_3884;
    float _3910 = _3101.x;
    float _3915 = _3101.y;
    float _3922 = -_3910;
    float4 _4065 = hexcTex_roughness.sample(hexcSampler, _1823, gradient2d(float2(fma(_3884, _2013, _3889 * _2015), fma(_3896, _2015, _3889 * _2013)), float2(fma(_3910, _2013, _3915 * _2015), fma(_3922, _2015, _3915 * _2013))));
    float4 _4075 = hexcTex_roughness.sample(hexcSampler, _1836, gradient2d(float2(fma(_3884, _2115, _3889 * _2117), fma(_3896, _2117, _3889 * _2115)), float2(fma(_3910, _2115, _3915 * _2117), fma(_3922, _2117, _3915 * _2115))));
    float4 _4085 = hexcTex_roughness.sample(hexcSampler, _1849, gradient2d(float2(fma(_3884, _2217, _3889 * _2219), fma(_3896, _2219, _3889 * _2217)), float2(fma(_3910, _2217, _3915 * _2219), fma(_3922, _2219, _3915 * _2217))));
    float3 _4161 = mix(float3(1.0), fast::max(float3(_4065.x, _4075.x, _4085.x), float3(0.0)), float3(hexcParams.roughness_falloffcontrast)) * _2778;
    float _4173 = (_4161.x + _4161.y) + _4161.z;
    float3 _6475;
    if (_4173 > 0.0)
    {
        _6475 = _4161 / float3(_4173);
    }
    else
    {
        _6475 = _2778 / float3((_2778.x + _2778.y) + _2778.z);
    }
    float3 _4293 = step(float3(0.5), _6475) * 2.0;
    float3 _4297 = (float3(1.0) - _4293) * 2.0;
    float3 _4303 = fast::max(float3(0.0), fma(_6475, _4297, _4293));
    float3 _4322 = fma(_4297 * 0.25, _4303 * _4303, _4293 * 0.5);
    float3 _4333 = _4322 / float3((_4322.x + _4322.y) + _4322.z);
    float _1490 = fast::clamp((((_4065 * _4333.x) + (_4075 * _4333.y)) + (_4085 * _4333.z)).x, 0.0199999995529651641845703125, 1.0);
    float3 _1495 = fast::normalize(in.v_normal);
    float3 _1508 = fast::normalize(in.v_tangent.xyz - (_1495 * dot(_1495, in.v_tangent.xyz)));
    float2 _4562 = dfdx(_1618);
    float2 _4564 = dfdy(_1618);
    float _5347 = _4562.x;
    float _5352 = _4562.y;
    float _5359 = -_5347;
    float _5373 = _4564.x;
    float _5378 = _4564.y;
    float _5385 = -_5373;
    float3 _5631 = (hexcTex_normal.sample(hexcSampler, _1823, gradient2d(float2(fma(_5347, _2013, _5352 * _2015), fma(_5359, _2015, _5352 * _2013)), float2(fma(_5373, _2013, _5378 * _2015), fma(_5385, _2015, _5378 * _2013)))).xyz * 2.0) - float3(1.0);
    float3 _5641 = abs(_5631);
    float2 _5668 = (-float2(_5631.xy)) / float2(fast::max(fast::max(_5641.z, 0.0078125 * fast::max(_5641.x, _5641.y)), 9.9999996826552253889678874634872e-21));
    float _5674 = _5668.x;
    float _5679 = _5668.y;
    float2 _5693 = float2(fma(_2013, _5674, -(_2015 * _5679)), fma(_2015, _5674, _2013 * _5679));
    float3 _5709 = (hexcTex_normal.sample(hexcSampler, _1836, gradient2d(float2(fma(_5347, _2115, _5352 * _2117), fma(_5359, _2117, _5352 * _2115)), float2(fma(_5373, _2115, _5378 * _2117), fma(_5385, _2117, _5378 * _2115)))).xyz * 2.0) - float3(1.0);
    float3 _5719 = abs(_5709);
    float2 _5746 = (-float2(_5709.xy)) / float2(fast::max(fast::max(_5719.z, 0.0078125 * fast::max(_5719.x, _5719.y)), 9.9999996826552253889678874634872e-21));
    float _5752 = _5746.x;
    float _5757 = _5746.y;
    float2 _5771 = float2(fma(_2115, _5752, -(_2117 * _5757)), fma(_2117, _5752, _2115 * _5757));
    float3 _5787 = (hexcTex_normal.sample(hexcSampler, _1849, gradient2d(float2(fma(_5347, _2217, _5352 * _2219), fma(_5359, _2219, _5352 * _2217)), float2(fma(_5373, _2217, _5378 * _2219), fma(_5385, _2219, _5378 * _2217)))).xyz * 2.0) - float3(1.0);
    float3 _5797 = abs(_5787);
    float2 _5824 = (-float2(_5787.xy)) / float2(fast::max(fast::max(_5797.z, 0.0078125 * fast::max(_5797.x, _5797.y)), 9.9999996826552253889678874634872e-21));
    float _5830 = _5824.x;
    float _5835 = _5824.y;
    float2 _5849 = float2(fma(_2217, _5830, -(_2219 * _5835)), fma(_2219, _5830, _2217 * _5835));
    float3 _5579 = float3(dot(_5693, _5693), dot(_5771, _5771), dot(_5849, _5849));
    float3 _5884 = mix(float3(1.0), fast::max(sqrt(_5579 / (float3(1.0) + _5579)), float3(0.0)), float3(hexcParams.normal_falloffcontrast)) * _2778;
    float _5896 = (_5884.x + _5884.y) + _5884.z;
    float3 _6513;
    if (_5896 > 0.0)
    {
        _6513 = _5884 / float3(_5896);
    }
    else
    {
        _6513 = _2778 / float3((_2778.x + _2778.y) + _2778.z);
    }
    float3 _6249 = fast::normalize(float3(-(((_5693 * _6513.x) + (_5771 * _6513.y)) + (_5849 * _6513.z)), 1.0));
    float3 _1538 = fast::normalize(((_1508 * _6249.x) + ((cross(_1495, _1508) * in.v_tangent.w) * _6249.y)) + (_1495 * _6249.z));
    float _1545 = fast::max(dot(_1538, float3(0.408248007297515869140625, 0.408248007297515869140625, 0.816497027873992919921875)), 0.0);
    float _1558 = 2.0 / (((_1490 * _1490) * _1490) * _1490);
    out.o_color = float4(((((_2601 * _2869.x) + (_2611 * _2869.y)) + (_2621 * _2869.z)).xyz * (0.1500000059604644775390625 + _1545)) + float3(0.039999999105930328369140625 * (((pow(fast::max(dot(_1538, float3(0.21418631076812744140625, 0.21418631076812744140625, 0.95302069187164306640625)), 0.0), _1558 - 2.0) * (_1558 + 6.0)) * 0.0397887341678142547607421875) * _1545)), 1.0);
    return out;
}

