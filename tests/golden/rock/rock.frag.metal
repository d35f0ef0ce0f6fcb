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
    float2 _1928 = in.v_uv * hexcParams.albedo_tiling;
    float2 _1930 = dfdx(_1928);
    float2 _1932 = dfdy(_1928);
    float _2034 = _1928.x;
    float _2036 = floor(_2034 * 0.0357142873108386993408203125);
    float _2038 = _1928.y;
    float _2039 = floor(_2038);
    float _2044 = fma(-28.0, _2036, _2034);
    float _2048 = _2038 - _2039;
    float2 _2049 = float2(_2044, _2048);
    float2 _2060 = float2(fma(3.4642856121063232421875, _2044, _2048 * (-2.0)), 4.0 * _2048);
    float2 _2179 = floor(_2060);
    int2 _2180 = int2(_2179);
    float2 _2184 = _2060 - _2179;
    float _2185 = _2184.x;
    float _2186 = _2184.y;
    float _2197 = -((1.0 - _2185) - _2186);
    float _2198 = step(0.0, _2197);
    float _2201 = fma(2.0, _2198, -1.0);
    float3 _2219 = float3(_2197 * _2201, fma(-_2186, _2201, _2198), fma(-_2185, _2201, _2198));
    int _2221 = int(_2198);
    int2 _2226 = _2180 + int2(_2221);
    int _2230 = 1 - _2221;
    int2 _2232 = _2180 + int2(_2221, _2230);
    int2 _2238 = _2180 + int2(_2230, _2221);
    uint2 _2074 = uint2(int2(int(_2036), int(_2039)));
    uint _2080 = _2074.y;
    uint2 _2086 = uint2((97u * _2074.x) - (2u * _2080), 4u * _2080);
    float _2310 = float(_2226.y);
    float2 _2114 = _2049 - float2(fma(0.5, _2310, float(_2226.x)) * 0.2886598110198974609375, 0.25 * _2310);
    uint3 _2493 = (uint3(uint2(int2(uint2(_2226) + _2086)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2495 = _2493.y;
    uint _2497 = _2493.z;
    uint _2501 = _2493.x + (_2495 * _2497);
    uint _2510 = _2495 + (_2497 * _2501);
    uint3 _10625 = uint3(_2501, _2510, _2497 + (_2501 * _2510));
    uint3 _2525 = _10625 ^ (_10625 >> uint3(16u));
    uint _2527 = _2525.y;
    uint _2529 = _2525.z;
    uint _2533 = _2525.x + (_2527 * _2529);
    uint _2542 = _2527 + (_2529 * _2533);
    float3 _2398 = float3(uint3(_2533, _2542, _2529 + (_2533 * _2542)) >> uint3(8u)) * 5.9604644775390625e-08;
    float _2408 = (fma(_2398.z, 2.0, -1.0) * 3.1415927410125732421875) * hexcParams.albedo_rotation;
    float _2480 = cos(_2408);
    float _2482 = sin(_2408);
    float _2624 = _2114.x;
    float _2629 = _2114.y;
    float2 _2354 = (float2(fma(_2624, _2480, _2629 * _2482), fma(-_2624, _2482, _2629 * _2480)) * 1.0) + _2398.xy;
    float _2650 = _1930.x;
    float _2655 = _1930.y;
    float _2662 = -_2650;
    float _2676 = _1932.x;
    float _2681 = _1932.y;
    float _2688 = -_2676;
    float _2706 = float(_2232.y);
    float2 _2134 = _2049 - float2(fma(0.5, _2706, float(_2232.x)) * 0.2886598110198974609375, 0.25 * _2706);
    uint3 _2889 = (uint3(uint2(int2(uint2(_2232) + _2086)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _2891 = _2889.y;
    uint _2893 = _2889.z;
    uint _2897 = _2889.x + (_2891 * _2893);
    uint _2906 = _2891 + (_2893 * _2897);
    uint3 _10631 = uint3(_2897, _2906, _2893 + (_2897 * _2906));
    uint3 _2921 = _10631 ^ (_10631 >> uint3(16u));
    uint _2923 = _2921.y;
    uint _2925 = _2921.z;
    uint _2929 = _2921.x + (_2923 * _2925);
    uint _2938 = _2923 + (_2925 * _2929);
    float3 _2794 = float3(uint3(_2929, _2938, _2925 + (_2929 * _2938)) >> uint3(8u)) * 5.9604644775390625e-08;
    float _2804 = (fma(_2794.z, 2.0, -1.0) * 3.1415927410125732421875) * hexcParams.albedo_rotation;
    float _2876 = cos(_2804);
    float _2878 = sin(_2804);
    float _3020 = _2134.x;
    float _3025 = _2134.y;
    float2 _2750 = (float2(fma(_3020, _2876, _3025 * _2878), fma(-_3020, _2878, _3025 * _2876)) * 1.0) + _2794.xy;
    float _3102 = float(_2238.y);
    float2 _2154 = _2049 - float2(fma(0.5, _3102, float(_2238.x)) * 0.2886598110198974609375, 0.25 * _3102);
    uint3 _3285 = (uint3(uint2(int2(uint2(_2238) + _2086)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _3287 = _3285.y;
    uint _3289 = _3285.z;
    uint _3293 = _3285.x + (_3287 * _3289);
    uint _3302 = _3287 + (_3289 * _3293);
    uint3 _10636 = uint3(_3293, _3302, _3289 + (_3293 * _3302));
    uint3 _3317 = _10636 ^ (_10636 >> uint3(16u));
    uint _3319 = _3317.y;
    uint _3321 = _3317.z;
    uint _3325 = _3317.x + (_3319 * _3321);
    uint _3334 = _3319 + (_3321 * _3325);
    float3 _3190 = float3(uint3(_3325, _3334, _3321 + (_3325 * _3334)) >> uint3(8u)) * 5.9604644775390625e-08;
    float _3200 = (fma(_3190.z, 2.0, -1.0) * 3.1415927410125732421875) * hexcParams.albedo_rotation;
    float _3272 = cos(_3200);
    float _3274 = sin(_3200);
    float _3416 = _2154.x;
    float _3421 = _2154.y;
    float2 _3146 = (float2(fma(_3416, _3272, _3421 * _3274), fma(-_3416, _3274, _3421 * _3272)) * 1.0) + _3190.xy;
    float4 _3519 = hexcTex_albedo.sample(hexcSampler, _2354, gradient2d(float2(fma(_2650, _2480, _2655 * _2482), fma(_2662, _2482, _2655 * _2480)) * 1.0, float2(fma(_2676, _2480, _2681 * _2482), fma(_2688, _2482, _2681 * _2480)) * 1.0));
    float4 _3529 = hexcTex_albedo.sample(hexcSampler, _2750, gradient2d(float2(fma(_2650, _2876, _2655 * _2878), fma(_2662, _2878, _2655 * _2876)) * 1.0, float2(fma(_2676, _2876, _2681 * _2878), fma(_2688, _2878, _2681 * _2876)) * 1.0));
    float4 _3543 = hexcTex_albedo.sample(hexcSampler, _3146, gradient2d(float2(fma(_2650, _3272, _2655 * _3274), fma(_2662, _3274, _2655 * _3272)) * 1.0, float2(fma(_2676, _3272, _2681 * _3274), fma(_2688, _3274, _2681 * _3272)) * 1.0));
    float3 _3704 = _2219 * _2219;
    float3 _3722 = (_2219 * _3704) * (_3704 * _3704);
    float3 _3633 = mix(float3(1.0), fast::max(float3(dot(_3519, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_3529, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_3543, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0))), float3(0.0)), float3(hexcParams.albedo_falloffcontrast)) * _3722;
    float _3645 = (_3633.x + _3633.y) + _3633.z;
    float3 _10242;
    if (_3645 > 0.0)
    {
        _10242 = _3633 / float3(_3645);
    }
    else
    {
        _10242 = _3722 / float3((_3722.x + _3722.y) + _3722.z);
    }
    float3 _3773 = step(float3(0.5), _10242) * 2.0;
    float3 _3777 = (float3(1.0) - _3773) * 2.0;
    float3 _3783 = fast::max(float3(0.0), fma(_10242, _3777, _3773));
    float3 _3802 = fma(_3777 * 0.25, _3783 * _3783, _3773 * 0.5);
    float3 _3813 = _3802 / float3((_3802.x + _3802.y) + _3802.z);
    float2 _4001 = dfdx(_1928);
    float2 _4003 = dfdy(_1928);
    float _4724 = _4001.x;
    float _4729 = _4001.y;
    float _4736 = -_4724;
    float _4750 = _4003.x;
    float _4755 = _4003.y;
    float _4762 = -_4750;
    float4 _5613 = hexcTex_roughness.sample(hexcSampler, _2354, gradient2d(float2(fma(_4724, _2480, _4729 * _2482), fma(_4736, _2482, _4729 * _2480)) * 1.0, float2(fma(_4750, _2480, _4755 * _2482), fma(_4762, _2482, _4755 * _2480)) * 1.0));
    float4 _5623 = hexcTex_roughness.sample(hexcSampler, _2750, gradient2d(float2(fma(_4724, _2876, _4729 * _2878), fma(_4736, _2878, _4729 * _2876)) * 1.0, float2(fma(_4750, _2876, _4755 * _2878), fma(_4762, _2878, _4755 * _2876)) * 1.0));
    float4 _5637 = hexcTex_roughness.sample(hexcSampler, _3146, gradient2d(float2(fma(_4724, _3272, _4729 * _3274), fma(_4736, _3274, _4729 * _3272)) * 1.0, float2(fma(_4750, _3272, _4755 * _3274), fma(_4762, _3274, _4755 * _3272)) * 1.0));
    float3 _5727 = mix(float3(1.0), fast::max(float3(_5613.x, _5623.x, _5637.x), float3(0.0)), float3(hexcParams.roughness_falloffcontrast)) * _3722;
    float _5739 = (_5727.x + _5727.y) + _5727.z;
    float3 _10373;
    if (_5739 > 0.0)
    {
        _10373 = _5727 / float3(_5739);
    }
    else
    {
        _10373 = _3722 / float3((_3722.x + _3722.y) + _3722.z);
    }
    float3 _5867 = step(float3(0.5), _10373) * 2.0;
    float3 _5871 = (float3(1.0) - _5867) * 2.0;
    float3 _5877 = fast::max(float3(0.0), fma(_10373, _5871, _5867));
    float3 _5896 = fma(_5871 * 0.25, _5877 * _5877, _5867 * 0.5);
    float3 _5907 = _5896 / float3((_5896.x + _5896.y) + _5896.z);
    float _1807 = fast::clamp((((_5613 * _5907.x) + (_5623 * _5907.y)) + (_5637 * _5907.z)).x, 0.0199999995529651641845703125, 1.0);
    float3 _1812 = fast::normalize(in.v_normal);
    float3 _1825 = fast::normalize(in.v_tangent.xyz - (_1812 * dot(_1812, in.v_tangent.xyz)));
    float2 _6095 = dfdx(_1928);
    float2 _6097 = dfdy(_1928);
    float _6815 = _6095.x;
    float _6820 = _6095.y;
    float _6827 = -_6815;
    float _6841 = _6097.x;
    float _6846 = _6097.y;
    float _6853 = -_6841;
    float3 _7809 = (hexcTex_normal.sample(hexcSampler, _2354, gradient2d(float2(fma(_6815, _2480, _6820 * _2482), fma(_6827, _2482, _6820 * _2480)) * 1.0, float2(fma(_6841, _2480, _6846 * _2482), fma(_6853, _2482, _6846 * _2480)) * 1.0)).xyz * 2.0) - float3(1.0);
    float3 _7819 = abs(_7809);
    float2 _7846 = (-float2(_7809.xy)) / float2(fast::max(fast::max(_7819.z, 0.0078125 * fast::max(_7819.x, _7819.y)), 9.9999996826552253889678874634872e-21));
    float _7852 = _7846.x;
    float _7857 = _7846.y;
    float2 _7706 = float2(fma(_2480, _7852, -(_2482 * _7857)), fma(_2482, _7852, _2480 * _7857)) * 1.0;
    float3 _7887 = (hexcTex_normal.sample(hexcSampler, _2750, gradient2d(float2(fma(_6815, _2876, _6820 * _2878), fma(_6827, _2878, _6820 * _2876)) * 1.0, float2(fma(_6841, _2876, _6846 * _2878), fma(_6853, _2878, _6846 * _2876)) * 1.0)).xyz * 2.0) - float3(1.0);
    float3 _7897 = abs(_7887);
    float2 _7924 = (-float2(_7887.xy)) / float2(fast::max(fast::max(_7897.z, 0.0078125 * fast::max(_7897.x, _7897.y)), 9.9999996826552253889678874634872e-21));
    float _7930 = _7924.x;
    float _7935 = _7924.y;
    float2 _7720 = float2(fma(_2876, _7930, -(_2878 * _7935)), fma(_2878, _7930, _2876 * _7935)) * 1.0;
    float3 _7965 = (hexcTex_normal.sample(hexcSampler, _3146, gradient2d(float2(fma(_6815, _3272, _6820 * _3274), fma(_6827, _3274, _6820 * _3272)) * 1.0, float2(fma(_6841, _3272, _6846 * _3274), fma(_6853, _3274, _6846 * _3272)) * 1.0)).xyz * 2.0) - float3(1.0);
    float3 _7975 = abs(_7965);
    float2 _8002 = (-float2(_7965.xy)) / float2(fast::max(fast::max(_7975.z, 0.0078125 * fast::max(_7975.x, _7975.y)), 9.9999996826552253889678874634872e-21));
    float _8008 = _8002.x;
    float _8013 = _8002.y;
    float2 _7738 = float2(fma(_3272, _8008, -(_3274 * _8013)), fma(_3274, _8008, _3272 * _8013)) * 1.0;
    float3 _7751 = float3(dot(_7706, _7706), dot(_7720, _7720), dot(_7738, _7738));
    float3 _8067 = mix(float3(1.0), fast::max(sqrt(_7751 / (float3(1.0) + _7751)), float3(0.0)), float3(hexcParams.normal_falloffcontrast)) * _3722;
    float _8079 = (_8067.x + _8067.y) + _8067.z;
    float3 _10549;
    if (_8079 > 0.0)
    {
        _10549 = _8067 / float3(_8079);
    }
    else
    {
        _10549 = _3722 / float3((_3722.x + _3722.y) + _3722.z);
    }
    float3 _8421 = fast::normalize(float3(-(((_7706 * _10549.x) + (_7720 * _10549.y)) + (_7738 * _10549.z)), 1.0));
    float3 _1855 = fast::normalize(((_1825 * _8421.x) + ((cross(_1812, _1825) * in.v_tangent.w) * _8421.y)) + (_1812 * _8421.z));
    float _1862 = fast::max(dot(_1855, float3(0.408248007297515869140625, 0.408248007297515869140625, 0.816497027873992919921875)), 0.0);
    float _1875 = 2.0 / (((_1807 * _1807) * _1807) * _1807);
    out.o_color = float4(((((_3519 * _3813.x) + (_3529 * _3813.y)) + (_3543 * _3813.z)).xyz * (0.1500000059604644775390625 + _1862)) + float3(0.039999999105930328369140625 * (((pow(fast::max(dot(_1855, float3(0.21418631076812744140625, 0.21418631076812744140625, 0.95302069187164306640625)), 0.0), _1875 - 2.0) * (_1875 + 6.0)) * 0.0397887341678142547607421875) * _1862)), 1.0);
    return out;
}

