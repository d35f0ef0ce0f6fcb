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
    float2 _1772 = in.v_uv * hexcParams.albedo_tiling;
    float2 _1791 = dfdx(_1772);
    float2 _1793 = dfdy(_1772);
    float _1876 = _1772.x;
    float _1878 = floor(_1876 * 0.0357142873108386993408203125);
    float _1880 = _1772.y;
    float _1881 = floor(_1880);
    float _1886 = fma(-28.0, _1878, _1876);
    float _1890 = _1880 - _1881;
    float2 _1891 = float2(_1886, _1890);
    float2 _1902 = float2(fma(3.4642856121063232421875, _1886, _1890 * (-2.0)), 4.0 * _1890);
    float2 _2131 = floor(_1902);
    int2 _2132 = int2(_2131);
    float2 _2136 = _1902 - _2131;
    float _2137 = _2136.x;
    float _2138 = _2136.y;
    float _2149 = -((1.0 - _2137) - _2138);
    float _2150 = step(0.0, _2149);
    float _2153 = fma(2.0, _2150, -1.0);
    float3 _2171 = float3(_2149 * _2153, fma(-_2138, _2153, _2150), fma(-_2137, _2153, _2150));
    int _2173 = int(_2150);
    int2 _2178 = _2132 + int2(_2173);
    int _2182 = 1 - _2173;
    int2 _2184 = _2132 + int2(_2173, _2182);
    int2 _2190 = _2132 + int2(_2182, _2173);
    uint _1916 = uint(int(_1881));
    uint2 _1923 = uint2((97u * uint(int(_1878))) - (2u * _1916), 4u * _1916);
    uint3 _2301 = (uint3(uint2(int2(uint2(_2178) + _1923)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2303 = _2301.y;
    uint _2305 = _2301.z;
    uint _2309 = _2301.x + (_2303 * _2305);
    uint _2318 = _2303 + (_2305 * _2309);
    uint3 _9544 = uint3(_2309, _2318, _2305 + (_2309 * _2318));
    uint3 _2333 = _9544 ^ (_9544 >> uint3(16u));
    uint _2335 = _2333.y;
    uint _2337 = _2333.z;
    uint _2341 = _2333.x + (_2335 * _2337);
    uint _2350 = _2335 + (_2337 * _2341);
    float3 _2210 = float3(uint3(_2341, _2350, _2337 + (_2341 * _2350)) >> uint3(8u)) * 5.9604644775390625e-08;
    float _2219 = (fma(_2210.z, 2.0, -1.0) * 3.1415927410125732421875) * hexcParams.albedo_rotation;
    float _2288 = cos(_2219);
    float _2290 = sin(_2219);
    uint3 _2539 = (uint3(uint2(int2(uint2(_2184) + _1923)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2541 = _2539.y;
    uint _2543 = _2539.z;
    uint _2547 = _2539.x + (_2541 * _2543);
    uint _2556 = _2541 + (_2543 * _2547);
    uint3 _9547 = uint3(_2547, _2556, _2543 + (_2547 * _2556));
    uint3 _2571 = _9547 ^ (_9547 >> uint3(16u));
    uint _2573 = _2571.y;
    uint _2575 = _2571.z;
    uint _2579 = _2571.x + (_2573 * _2575);
    uint _2588 = _2573 + (_2575 * _2579);
    float3 _2448 = float3(uint3(_2579, _2588, _2575 + (_2579 * _2588)) >> uint3(8u)) * 5.9604644775390625e-08;
    float _2457 = (fma(_2448.z, 2.0, -1.0) * 3.1415927410125732421875) * hexcParams.albedo_rotation;
    float _2526 = cos(_2457);
    float _2528 = sin(_2457);
    uint3 _2777 = (uint3(uint2(int2(uint2(_2190) + _1923)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2779 = _2777.y;
    uint _2781 = _2777.z;
    uint _2785 = _2777.x + (_2779 * _2781);
    uint _2794 = _2779 + (_2781 * _2785);
    uint3 _9550 = uint3(_2785, _2794, _2781 + (_2785 * _2794));
    uint3 _2809 = _9550 ^ (_9550 >> uint3(16u));
    uint _2811 = _2809.y;
    uint _2813 = _2809.z;
    uint _2817 = _2809.x + (_2811 * _2813);
    uint _2826 = _2811 + (_2813 * _2817);
    float3 _2686 = float3(uint3(_2817, _2826, _2813 + (_2817 * _2826)) >> uint3(8u)) * 5.9604644775390625e-08;
    float _2695 = (fma(_2686.z, 2.0, -1.0) * 3.1415927410125732421875) * hexcParams.albedo_rotation;
    float _2764 = cos(_2695);
    float _2766 = sin(_2695);
    float _2912 = float(_2178.y);
    float2 _1982 = _1891 - float2(fma(0.5, _2912, float(_2178.x)) * 0.2886598110198974609375, 0.25 * _2912);
    float _2928 = float(_2184.y);
    float2 _1986 = _1891 - float2(fma(0.5, _2928, float(_2184.x)) * 0.2886598110198974609375, 0.25 * _2928);
    float _2944 = float(_2190.y);
    float2 _1990 = _1891 - float2(fma(0.5, _2944, float(_2190.x)) * 0.2886598110198974609375, 0.25 * _2944);
    float _2956 = _1982.x;
    float _2961 = _1982.y;
    float2 _2005 = (float2(fma(_2956, _2288, _2961 * _2290), fma(-_2956, _2290, _2961 * _2288)) * 1.0) + _2210.xy;
    float _2982 = _1986.x;
    float _2987 = _1986.y;
    float2 _2021 = (float2(fma(_2982, _2526, _2987 * _2528), fma(-_2982, _2528, _2987 * _2526)) * 1.0) + _2448.xy;
    float _3008 = _1990.x;
    float _3013 = _1990.y;
    float2 _2037 = (float2(fma(_3008, _2764, _3013 * _2766), fma(-_3008, _2766, _3013 * _2764)) * 1.0) + _2686.xy;
    float _3034 = _1791.x;
    float _3039 = _1791.y;
    float _3046 = -_3034;
    float _3060 = _1793.x;
    float _3065 = _1793.y;
    float _3072 = -_3060;
    float4 _3215 = hexcTex_albedo.sample(hexcSampler, _2005, gradient2d(float2(fma(_3034, _2288, _3039 * _2290), fma(_3046, _2290, _3039 * _2288)) * 1.0, float2(fma(_3060, _2288, _3065 * _2290), fma(_3072, _2290, _3065 * _2288)) * 1.0));
    float4 _3225 = hexcTex_albedo.sample(hexcSampler, _2021, gradient2d(float2(fma(_3034, _2526, _3039 * _2528), fma(_3046, _2528, _3039 * _2526)) * 1.0, float2(fma(_3060, _2526, _3065 * _2528), fma(_3072, _2528, _3065 * _2526)) * 1.0));
    float4 _3235 = hexcTex_albedo.sample(hexcSampler, _2037, gradient2d(float2(fma(_3034, _2764, _3039 * _2766), fma(_3046, _2766, _3039 * _2764)) * 1.0, float2(fma(_3060, _2764, _3065 * _2766), fma(_3072, _2766, _3065 * _2764)) * 1.0));
    float3 _3374 = _2171 * _2171;
    float3 _3392 = (_2171 * _3374) * (_3374 * _3374);
    float3 _3311 = mix(float3(1.0), fast::max(float3(dot(_3215, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_3225, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_3235, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0))), float3(0.0)), float3(hexcParams.albedo_falloffcontrast)) * _3392;
    float _3323 = (_3311.x + _3311.y) + _3311.z;
    float3 _9221;
    if (_3323 > 0.0)
    {
        _9221 = _3311 / float3(_3323);
    }
    else
    {
        _9221 = _3392 / float3((_3392.x + _3392.y) + _3392.z);
    }
    float3 _3443 = step(float3(0.5), _9221) * 2.0;
    float3 _3447 = (float3(1.0) - _3443) * 2.0;
    float3 _3453 = fast::max(float3(0.0), fma(_9221, _3447, _3443));
    float3 _3472 = fma(_3447 * 0.25, _3453 * _3453, _3443 * 0.5);
    float3 _3483 = _3472 / float3((_3472.x + _3472.y) + _3472.z);
    float2 _3717 = dfdx(_1772);
    float2 _3719 = dfdy(_1772);
    float _4960 = _3717.x;
    float _4965 = _3717.y;
    float _4972 = -_4960;
    float _4986 = _3719.x;
    float _4991 = _3719.y;
    float _4998 = -_4986;
    float4 _5141 = hexcTex_roughness.sample(hexcSampler, _2005, gradient2d(float2(fma(_4960, _2288, _4965 * _2290), fma(_4972, _2290, _4965 * _2288)) * 1.0, float2(fma(_4986, _2288, _4991 * _2290), fma(_4998, _2290, _4991 * _2288)) * 1.0));
    float4 _5151 = hexcTex_roughness.sample(hexcSampler, _2021, gradient2d(float2(fma(_4960, _2526, _4965 * _2528), fma(_4972, _2528, _4965 * _2526)) * 1.0, float2(fma(_4986, _2526, _4991 * _2528), fma(_4998, _2528, _4991 * _2526)) * 1.0));
    float4 _5161 = hexcTex_roughness.sample(hexcSampler, _2037, gradient2d(float2(fma(_4960, _2764, _4965 * _2766), fma(_4972, _2766, _4965 * _2764)) * 1.0, float2(fma(_4986, _2764, _4991 * _2766), fma(_4998, _2766, _4991 * _2764)) * 1.0));
    float3 _5237 = mix(float3(1.0), fast::max(float3(_5141.x, _5151.x, _5161.x), float3(0.0)), float3(hexcParams.roughness_falloffcontrast)) * _3392;
    float _5249 = (_5237.x + _5237.y) + _5237.z;
    float3 _9332;
    if (_5249 > 0.0)
    {
        _9332 = _5237 / float3(_5249);
    }
    else
    {
        _9332 = _3392 / float3((_3392.x + _3392.y) + _3392.z);
    }
    float3 _5369 = step(float3(0.5), _9332) * 2.0;
    float3 _5373 = (float3(1.0) - _5369) * 2.0;
    float3 _5379 = fast::max(float3(0.0), fma(_9332, _5373, _5369));
    float3 _5398 = fma(_5373 * 0.25, _5379 * _5379, _5369 * 0.5);
    float3 _5409 = _5398 / float3((_5398.x + _5398.y) + _5398.z);
    float _1642 = fast::clamp((((_5141 * _5409.x) + (_5151 * _5409.y)) + (_5161 * _5409.z)).x, 0.0199999995529651641845703125, 1.0);
    float3 _1647 = fast::normalize(in.v_normal);
    float3 _1660 = fast::normalize(in.v_tangent.xyz - (_1647 * dot(_1647, in.v_tangent.xyz)));
    float2 _5642 = dfdx(_1772);
    float2 _5644 = dfdy(_1772);
    float _6885 = _5642.x;
    float _6890 = _5642.y;
    float _6897 = -_6885;
    float _6911 = _5644.x;
    float _6916 = _5644.y;
    float _6923 = -_6911;
    float3 _7178 = (hexcTex_normal.sample(hexcSampler, _2005, gradient2d(float2(fma(_6885, _2288, _6890 * _2290), fma(_6897, _2290, _6890 * _2288)) * 1.0, float2(fma(_6911, _2288, _6916 * _2290), fma(_6923, _2290, _6916 * _2288)) * 1.0)).xyz * 2.0) - float3(1.0);
    float3 _7188 = abs(_7178);
    float2 _7215 = (-float2(_7178.xy)) / float2(fast::max(fast::max(_7188.z, 0.0078125 * fast::max(_7188.x, _7188.y)), 9.9999996826552253889678874634872e-21));
    float _7221 = _7215.x;
    float _7226 = _7215.y;
    float2 _7088 = float2(fma(_2288, _7221, -(_2290 * _7226)), fma(_2290, _7221, _2288 * _7226)) * 1.0;
    float3 _7256 = (hexcTex_normal.sample(hexcSampler, _2021, gradient2d(float2(fma(_6885, _2526, _6890 * _2528), fma(_6897, _2528, _6890 * _2526)) * 1.0, float2(fma(_6911, _2526, _6916 * _2528), fma(_6923, _2528, _6916 * _2526)) * 1.0)).xyz * 2.0) - float3(1.0);
    float3 _7266 = abs(_7256);
    float2 _7293 = (-float2(_7256.xy)) / float2(fast::max(fast::max(_7266.z, 0.0078125 * fast::max(_7266.x, _7266.y)), 9.9999996826552253889678874634872e-21));
    float _7299 = _7293.x;
    float _7304 = _7293.y;
    float2 _7102 = float2(fma(_2526, _7299, -(_2528 * _7304)), fma(_2528, _7299, _2526 * _7304)) * 1.0;
    float3 _7334 = (hexcTex_normal.sample(hexcSampler, _2037, gradient2d(float2(fma(_6885, _2764, _6890 * _2766), fma(_6897, _2766, _6890 * _2764)) * 1.0, float2(fma(_6911, _2764, _6916 * _2766), fma(_6923, _2766, _6916 * _2764)) * 1.0)).xyz * 2.0) - float3(1.0);
    float3 _7344 = abs(_7334);
    float2 _7371 = (-float2(_7334.xy)) / float2(fast::max(fast::max(_7344.z, 0.0078125 * fast::max(_7344.x, _7344.y)), 9.9999996826552253889678874634872e-21));
    float _7377 = _7371.x;
    float _7382 = _7371.y;
    float2 _7116 = float2(fma(_2764, _7377, -(_2766 * _7382)), fma(_2766, _7377, _2764 * _7382)) * 1.0;
    float3 _7126 = float3(dot(_7088, _7088), dot(_7102, _7102), dot(_7116, _7116));
    float3 _7431 = mix(float3(1.0), fast::max(sqrt(_7126 / (float3(1.0) + _7126)), float3(0.0)), float3(hexcParams.normal_falloffcontrast)) * _3392;
    float _7443 = (_7431.x + _7431.y) + _7431.z;
    float3 _9481;
    if (_7443 > 0.0)
    {
        _9481 = _7431 / float3(_7443);
    }
    else
    {
        _9481 = _3392 / float3((_3392.x + _3392.y) + _3392.z);
    }
    float3 _7796 = fast::normalize(float3(-(((_7088 * _9481.x) + (_7102 * _9481.y)) + (_7116 * _9481.z)), 1.0));
    float3 _1690 = fast::normalize(((_1660 * _7796.x) + ((cross(_1647, _1660) * in.v_tangent.w) * _7796.y)) + (_1647 * _7796.z));
    float _1697 = fast::max(dot(_1690, float3(0.408248007297515869140625, 0.408248007297515869140625, 0.816497027873992919921875)), 0.0);
    float _1710 = 2.0 / (((_1642 * _1642) * _1642) * _1642);
    out.o_color = float4(((((_3215 * _3483.x) + (_3225 * _3483.y)) + (_3235 * _3483.z)).xyz * (0.1500000059604644775390625 + _1697)) + float3(0.039999999105930328369140625 * (((pow(fast::max(dot(_1690, float3(0.21418631076812744140625, 0.21418631076812744140625, 0.95302069187164306640625)), 0.0), _1710 - 2.0) * (_1710 + 6.0)) * 0.0397887341678142547607421875) * _1697)), 1.0);
    return out;
}

