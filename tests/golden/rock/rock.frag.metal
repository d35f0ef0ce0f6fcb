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

struct rock_frag_out
{
    float4 o_color [[color(0)]];
};

struct rock_frag_in
{
    float2 v_uv [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float4 v_tangent [[user(locn2)]];
};

fragment rock_frag_out rock_frag(rock_frag_in in [[stage_in]], constant HexcParams& hexcParams [[buffer(0)]], texture2d<float> hexcTex_albedo [[texture(0)]], texture2d<float> hexcTex_normal [[texture(1)]], texture2d<float> hexcTex_roughness [[texture(2)]], sampler hexcSampler [[sampler(0)]])
{
    rock_frag_out out = {};
    float2 _1910 = in.v_uv * hexcParams.albedo_tiling;
    float2 _1912 = dfdx(_1910);
    float2 _1914 = dfdy(_1910);
    float _2016 = _1910.x;
    float _2018 = floor(_2016 * 0.0357142873108386993408203125);
    float _2020 = _1910.y;
    float _2021 = floor(_2020);
    float _2026 = fma(-28.0, _2018, _2016);
    float _2030 = _2020 - _2021;
    float2 _2031 = float2(_2026, _2030);
    float2 _2042 = float2(fma(3.4642856121063232421875, _2026, _2030 * (-2.0)), 4.0 * _2030);
    float2 _2161 = floor(_2042);
    int2 _2162 = int2(_2161);
    float2 _2166 = _2042 - _2161;
    float _2167 = _2166.x;
    float _2168 = _2166.y;
    float _2179 = -((1.0 - _2167) - _2168);
    float _2180 = step(0.0, _2179);
    float _2183 = fma(2.0, _2180, -1.0);
    float3 _2201 = float3(_2179 * _2183, fma(-_2168, _2183, _2180), fma(-_2167, _2183, _2180));
    int _2203 = int(_2180);
    int2 _2208 = _2162 + int2(_2203);
    int _2212 = 1 - _2203;
    int2 _2214 = _2162 + int2(_2203, _2212);
    int2 _2220 = _2162 + int2(_2212, _2203);
    uint2 _2056 = uint2(int2(int(_2018), int(_2021)));
    uint _2062 = _2056.y;
    uint2 _2068 = uint2((97u * _2056.x) - (2u * _2062), 4u * _2062);
    float _2292 = float(_2208.y);
    float2 _2096 = _2031 - float2(fma(0.5, _2292, float(_2208.x)) * 0.2886598110198974609375, 0.25 * _2292);
    uint3 _2475 = (uint3(uint2(int2(uint2(_2208) + _2068)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2477 = _2475.y;
    uint _2479 = _2475.z;
    uint _2483 = _2475.x + (_2477 * _2479);
    uint _2492 = _2477 + (_2479 * _2483);
    uint3 _10631 = uint3(_2483, _2492, _2479 + (_2483 * _2492));
    uint3 _2507 = _10631 ^ (_10631 >> uint3(16u));
    uint _2509 = _2507.y;
    uint _2511 = _2507.z;
    uint _2515 = _2507.x + (_2509 * _2511);
    uint _2524 = _2509 + (_2511 * _2515);
    float3 _2380 = float3(uint3(_2515, _2524, _2511 + (_2515 * _2524)) >> uint3(8u)) * 5.9604644775390625e-08;
    float _2390 = (fma(_2380.z, 2.0, -1.0) * 3.1415927410125732421875) * hexcParams.albedo_rotation;
    float _2462 = cos(_2390);
    float _2464 = sin(_2390);
    float _2606 = _2096.x;
    float _2611 = _2096.y;
    float2 _2336 = (float2(fma(_2606, _2462, _2611 * _2464), fma(-_2606, _2464, _2611 * _2462)) * 1.0) + _2380.xy;
    float _2632 = _1912.x;
    float _2637 = _1912.y;
    float _2644 = -_2632;
    float _2658 = _1914.x;
    float _2663 = _1914.y;
    float _2670 = -_2658;
    float _2688 = float(_2214.y);
    float2 _2116 = _2031 - float2(fma(0.5, _2688, float(_2214.x)) * 0.2886598110198974609375, 0.25 * _2688);
    uint3 _2871 = (uint3(uint2(int2(uint2(_2214) + _2068)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2873 = _2871.y;
    uint _2875 = _2871.z;
    uint _2879 = _2871.x + (_2873 * _2875);
    uint _2888 = _2873 + (_2875 * _2879);
    uint3 _10637 = uint3(_2879, _2888, _2875 + (_2879 * _2888));
    uint3 _2903 = _10637 ^ (_10637 >> uint3(16u));
    uint _2905 = _2903.y;
    uint _2907 = _2903.z;
    uint _2911 = _2903.x + (_2905 * _2907);
    uint _2920 = _2905 + (_2907 * _2911);
    float3 _2776 = float3(uint3(_2911, _2920, _2907 + (_2911 * _2920)) >> uint3(8u)) * 5.9604644775390625e-08;
    float _2786 = (fma(_2776.z, 2.0, -1.0) * 3.1415927410125732421875) * hexcParams.albedo_rotation;
    float _2858 = cos(_2786);
    float _2860 = sin(_2786);
    float _3002 = _2116.x;
    float _3007 = _2116.y;
    float2 _2732 = (float2(fma(_3002, _2858, _3007 * _2860), fma(-_3002, _2860, _3007 * _2858)) * 1.0) + _2776.xy;
    float _3084 = float(_2220.y);
    float2 _2136 = _2031 - float2(fma(0.5, _3084, float(_2220.x)) * 0.2886598110198974609375, 0.25 * _3084);
    uint3 _3267 = (uint3(uint2(int2(uint2(_2220) + _2068)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _3269 = _3267.y;
    uint _3271 = _3267.z;
    uint _3275 = _3267.x + (_3269 * _3271);
    uint _3284 = _3269 + (_3271 * _3275);
    uint3 _10642 = uint3(_3275, _3284, _3271 + (_3275 * _3284));
    uint3 _3299 = _10642 ^ (_10642 >> uint3(16u));
    uint _3301 = _3299.y;
    uint _3303 = _3299.z;
    uint _3307 = _3299.x + (_3301 * _3303);
    uint _3316 = _3301 + (_3303 * _3307);
    float3 _3172 = float3(uint3(_3307, _3316, _3303 + (_3307 * _3316)) >> uint3(8u)) * 5.9604644775390625e-08;
    float _3182 = (fma(_3172.z, 2.0, -1.0) * 3.1415927410125732421875) * hexcParams.albedo_rotation;
    float _3254 = cos(_3182);
    float _3256 = sin(_3182);
    float _3398 = _2136.x;
    float _3403 = _2136.y;
    float2 _3128 = (float2(fma(_3398, _3254, _3403 * _3256), fma(-_3398, _3256, _3403 * _3254)) * 1.0) + _3172.xy;
    float4 _3501 = hexcTex_albedo.sample(hexcSampler, _2336, gradient2d(float2(fma(_2632, _2462, _2637 * _2464), fma(_2644, _2464, _2637 * _2462)) * 1.0, float2(fma(_2658, _2462, _2663 * _2464), fma(_2670, _2464, _2663 * _2462)) * 1.0));
    float4 _3511 = hexcTex_albedo.sample(hexcSampler, _2732, gradient2d(float2(fma(_2632, _2858, _2637 * _2860), fma(_2644, _2860, _2637 * _2858)) * 1.0, float2(fma(_2658, _2858, _2663 * _2860), fma(_2670, _2860, _2663 * _2858)) * 1.0));
    float4 _3525 = hexcTex_albedo.sample(hexcSampler, _3128, gradient2d(float2(fma(_2632, _3254, _2637 * _3256), fma(_2644, _3256, _2637 * _3254)) * 1.0, float2(fma(_2658, _3254, _2663 * _3256), fma(_2670, _3256, _2663 * _3254)) * 1.0));
    float3 _3686 = _2201 * _2201;
    float3 _3704 = (_2201 * _3686) * (_3686 * _3686);
    float3 _3615 = mix(float3(1.0), fast::max(float3(dot(_3501, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_3511, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_3525, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0))), float3(0.0)), float3(hexcParams.albedo_falloffcontrast)) * _3704;
    float _3627 = (_3615.x + _3615.y) + _3615.z;
    float3 _10248;
    if (_3627 > 0.0)
    {
        _10248 = _3615 / float3(_3627);
    }
    else
    {
        _10248 = _3704 / float3((_3704.x + _3704.y) + _3704.z);
    }
    float3 _3755 = step(float3(0.5), _10248) * 2.0;
    float3 _3759 = (float3(1.0) - _3755) * 2.0;
    float3 _3765 = fast::max(float3(0.0), fma(_10248, _3759, _3755));
    float3 _3784 = fma(_3759 * 0.25, _3765 * _3765, _3755 * 0.5);
    float3 _3795 = _3784 / float3((_3784.x + _3784.y) + _3784.z);
    float2 _3983 = dfdx(_1910);
    float2 _3985 = dfdy(_1910);
    float _4706 = _3983.x;
    float _4711 = _3983.y;
    float _4718 = -_4706;
    float _4732 = _3985.x;
    float _4737 = _3985.y;
    float _4744 = -_4732;
    float4 _5595 = hexcTex_roughness.sample(hexcSampler, _2336, gradient2d(float2(fma(_4706, _2462, _4711 * _2464), fma(_4718, _2464, _4711 * _2462)) * 1.0, float2(fma(_4732, _2462, _4737 * _2464), fma(_4744, _2464, _4737 * _2462)) * 1.0));
    float4 _5605 = hexcTex_roughness.sample(hexcSampler, _2732, gradient2d(float2(fma(_4706, _2858, _4711 * _2860), fma(_4718, _2860, _4711 * _2858)) * 1.0, float2(fma(_4732, _2858, _4737 * _2860), fma(_4744, _2860, _4737 * _2858)) * 1.0));
    float4 _5619 = hexcTex_roughness.sample(hexcSampler, _3128, gradient2d(float2(fma(_4706, _3254, _4711 * _3256), fma(_4718, _3256, _4711 * _3254)) * 1.0, float2(fma(_4732, _3254, _4737 * _3256), fma(_4744, _3256, _4737 * _3254)) * 1.0));
    float3 _5709 = mix(float3(1.0), fast::max(float3(_5595.x, _5605.x, _5619.x), float3(0.0)), float3(hexcParams.roughness_falloffcontrast)) * _3704;
    float _5721 = (_5709.x + _5709.y) + _5709.z;
    float3 _10379;
    if (_5721 > 0.0)
    {
        _10379 = _5709 / float3(_5721);
    }
    else
    {
        _10379 = _3704 / float3((_3704.x + _3704.y) + _3704.z);
    }
    float3 _5849 = step(float3(0.5), _10379) * 2.0;
    float3 _5853 = (float3(1.0) - _5849) * 2.0;
    float3 _5859 = fast::max(float3(0.0), fma(_10379, _5853, _5849));
    float3 _5878 = fma(_5853 * 0.25, _5859 * _5859, _5849 * 0.5);
    float3 _5889 = _5878 / float3((_5878.x + _5878.y) + _5878.z);
    float _1789 = fast::clamp((((_5595 * _5889.x) + (_5605 * _5889.y)) + (_5619 * _5889.z)).x, 0.0199999995529651641845703125, 1.0);
    float3 _1794 = fast::normalize(in.v_normal);
    float3 _1807 = fast::normalize(in.v_tangent.xyz - (_1794 * dot(_1794, in.v_tangent.xyz)));
    float2 _6077 = dfdx(_1910);
    float2 _6079 = dfdy(_1910);
    float _6797 = _6077.x;
    float _6802 = _6077.y;
    float _6809 = -_6797;
    float _6823 = _6079.x;
    float _6828 = _6079.y;
    float _6835 = -_6823;
    float3 _7791 = (hexcTex_normal.sample(hexcSampler, _2336, gradient2d(float2(fma(_6797, _2462, _6802 * _2464), fma(_6809, _2464, _6802 * _2462)) * 1.0, float2(fma(_6823, _2462, _6828 * _2464), fma(_6835, _2464, _6828 * _2462)) * 1.0)).xyz * 2.0) - float3(1.0);
    float3 _7801 = abs(_7791);
    float2 _7828 = (-float2(_7791.xy)) / float2(fast::max(fast::max(_7801.z, 0.0078125 * fast::max(_7801.x, _7801.y)), 9.9999996826552253889678874634872e-21));
    float _7839 = _7828.x;
    float _7844 = _7828.y;
    float2 _7688 = float2(fma(_7839, _2462, _7844 * _2464), fma(-_7839, _2464, _7844 * _2462)) * 1.0;
    float3 _7877 = (hexcTex_normal.sample(hexcSampler, _2732, gradient2d(float2(fma(_6797, _2858, _6802 * _2860), fma(_6809, _2860, _6802 * _2858)) * 1.0, float2(fma(_6823, _2858, _6828 * _2860), fma(_6835, _2860, _6828 * _2858)) * 1.0)).xyz * 2.0) - float3(1.0);
    float3 _7887 = abs(_7877);
    float2 _7914 = (-float2(_7877.xy)) / float2(fast::max(fast::max(_7887.z, 0.0078125 * fast::max(_7887.x, _7887.y)), 9.9999996826552253889678874634872e-21));
    float _7925 = _7914.x;
    float _7930 = _7914.y;
    float2 _7702 = float2(fma(_7925, _2858, _7930 * _2860), fma(-_7925, _2860, _7930 * _2858)) * 1.0;
    float3 _7963 = (hexcTex_normal.sample(hexcSampler, _3128, gradient2d(float2(fma(_6797, _3254, _6802 * _3256), fma(_6809, _3256, _6802 * _3254)) * 1.0, float2(fma(_6823, _3254, _6828 * _3256), fma(_6835, _3256, _6828 * _3254)) * 1.0)).xyz * 2.0) - float3(1.0);
    float3 _7973 = abs(_7963);
    float2 _8000 = (-float2(_7963.xy)) / float2(fast::max(fast::max(_7973.z, 0.0078125 * fast::max(_7973.x, _7973.y)), 9.9999996826552253889678874634872e-21));
    float _8011 = _8000.x;
    float _8016 = _8000.y;
    float2 _7720 = float2(fma(_8011, _3254, _8016 * _3256), fma(-_8011, _3256, _8016 * _3254)) * 1.0;
    float3 _7733 = float3(dot(_7688, _7688), dot(_7702, _7702), dot(_7720, _7720));
    float3 _8073 = mix(float3(1.0), fast::max(sqrt(_7733 / (float3(1.0) + _7733)), float3(0.0)), float3(hexcParams.normal_falloffcontrast)) * _3704;
    float _8085 = (_8073.x + _8073.y) + _8073.z;
    float3 _10555;
    if (_8085 > 0.0)
    {
        _10555 = _8073 / float3(_8085);
    }
    else
    {
        _10555 = _3704 / float3((_3704.x + _3704.y) + _3704.z);
    }
    float3 _8427 = fast::normalize(float3(-(((_7688 * _10555.x) + (_7702 * _10555.y)) + (_7720 * _10555.z)), 1.0));
    float3 _1837 = fast::normalize(((_1807 * _8427.x) - ((cross(_1794, _1807) * in.v_tangent.w) * _8427.y)) + (_1794 * _8427.z));
    float _1844 = fast::max(dot(_1837, float3(0.408248007297515869140625, 0.408248007297515869140625, 0.816497027873992919921875)), 0.0);
    float _1857 = 2.0 / (((_1789 * _1789) * _1789) * _1789);
    out.o_color = float4(((((_3501 * _3795.x) + (_3511 * _3795.y)) + (_3525 * _3795.z)).xyz * (0.1500000059604644775390625 + _1844)) + float3(0.039999999105930328369140625 * (((pow(fast::max(dot(_1837, float3(0.21418631076812744140625, 0.21418631076812744140625, 0.95302069187164306640625)), 0.0), _1857 - 2.0) * (_1857 + 6.0)) * 0.0397887341678142547607421875) * _1844)), 1.0);
    return out;
}

