cbuffer HexcParams : register(b0)
{
    float2 hexcParams_albedo_tiling : packoffset(c0);
    float hexcParams_albedo_rotation : packoffset(c0.z);
    float hexcParams_albedo_falloffcontrast : packoffset(c0.w);
    float hexcParams_normal_falloffcontrast : packoffset(c1);
    float hexcParams_roughness_falloffcontrast : packoffset(c1.y);
};

Texture2D<float4> hexcTex_albedo : register(t0);
SamplerState hexcSampler : register(s0);
Texture2D<float4> hexcTex_normal : register(t1);
Texture2D<float4> hexcTex_roughness : register(t2);

static float2 v_uv;
static float3 v_normal;
static float4 v_tangent;
static float4 o_color;

struct SPIRV_Cross_Input
{
    float2 v_uv : TEXCOORD0;
    float3 v_normal : TEXCOORD1;
    float4 v_tangent : TEXCOORD2;
};

struct SPIRV_Cross_Output
{
    float4 o_color : SV_Target0;
};

void frag_main()
{
    float2 _1928 = v_uv * hexcParams_albedo_tiling;
    float2 _1930 = ddx(_1928);
    float2 _1932 = ddy(_1928);
    float _2034 = _1928.x;
    float _2036 = floor(_2034 * 0.0357142873108386993408203125f);
    float _2038 = _1928.y;
    float _2039 = floor(_2038);
    float _2044 = mad(-28.0f, _2036, _2034);
    float _2048 = _2038 - _2039;
    float2 _2049 = float2(_2044, _2048);
    float2 _2060 = float2(mad(3.4642856121063232421875f, _2044, _2048 * (-2.0f)), 4.0f * _2048);
    float2 _2179 = floor(_2060);
    int2 _2180 = int2(_2179);
    float2 _2184 = _2060 - _2179;
    float _2185 = _2184.x;
    float _2186 = _2184.y;
    float _2197 = -((1.0f - _2185) - _2186);
    float _2198 = step(0.0f, _2197);
    float _2201 = mad(2.0f, _2198, -1.0f);
    float3 _2219 = float3(_2197 * _2201, mad(-_2186, _2201, _2198), mad(-_2185, _2201, _2198));
    int _2221 = int(_2198);
    int2 _2226 = _2180 + _2221.xx;
    int _2230 = 1 - _2221;
    int2 _2232 = _2180 + int2(_2221, _2230);
    int2 _2238 = _2180 + int2(_2230, _2221);
    uint2 _2074 = uint2(int2(int(_2036), int(_2039)));
    uint _2080 = _2074.y;
    uint2 _2086 = uint2((97u * _2074.x) - (2u * _2080), 4u * _2080);
    float _2310 = float(_2226.y);
    float2 _2114 = _2049 - float2(mad(0.5f, _2310, float(_2226.x)) * 0.2886598110198974609375f, 0.25f * _2310);
    uint3 _2493 = (uint3(uint2(int2(uint2(_2226) + _2086)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2495 = _2493.y;
    uint _2497 = _2493.z;
    uint _2501 = _2493.x + (_2495 * _2497);
    uint _2510 = _2495 + (_2497 * _2501);
    uint3 _10625 = uint3(_2501, _2510, _2497 + (_2501 * _2510));
    uint3 _2525 = _10625 ^ (_10625 >> uint3(16u, 16u, 16u));
    uint _2527 = _2525.y;
    uint _2529 = _2525.z;
    uint _2533 = _2525.x + (_2527 * _2529);
    uint _2542 = _2527 + (_2529 * _2533);
    float3 _2398 = float3(uint3(_2533, _2542, _2529 + (_2533 * _2542)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2408 = (mad(_2398.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _2480 = cos(_2408);
    float _2482 = sin(_2408);
    float _2624 = _2114.x;
    float _2629 = _2114.y;
    float2 _2354 = (float2(mad(_2624, _2480, _2629 * _2482), mad(-_2624, _2482, _2629 * _2480)) * 1.0f) + _2398.xy;
    float _2650 = _1930.x;
    float _2655 = _1930.y;
    float _2662 = -_2650;
    float _2676 = _1932.x;
    float _2681 = _1932.y;
    float _2688 = -_2676;
    float _2706 = float(_2232.y);
    float2 _2134 = _2049 - float2(mad(0.5f, _2706, float(_2232.x)) * 0.2886598110198974609375f, 0.25f * _2706);
    uint3 _2889 = (uint3(uint2(int2(uint2(_2232) + _2086)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2891 = _2889.y;
    uint _2893 = _2889.z;
    uint _2897 = _2889.x + (_2891 * _2893);
    uint _2906 = _2891 + (_2893 * _2897);
    uint3 _10631 = uint3(_2897, _2906, _2893 + (_2897 * _2906));
    uint3 _2921 = _10631 ^ (_10631 >> uint3(16u, 16u, 16u));
    uint _2923 = _2921.y;
    uint _2925 = _2921.z;
    uint _2929 = _2921.x + (_2923 * _2925);
    uint _2938 = _2923 + (_2925 * _2929);
    float3 _2794 = float3(uint3(_2929, _2938, _2925 + (_2929 * _2938)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2804 = (mad(_2794.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _2876 = cos(_2804);
    float _2878 = sin(_2804);
    float _3020 = _2134.x;
    float _3025 = _2134.y;
    float2 _2750 = (float2(mad(_3020, _2876, _3025 * _2878), mad(-_3020, _2878, _3025 * _2876)) * 1.0f) + _2794.xy;
    float _3102 = float(_2238.y);
    float2 _2154 = _2049 - float2(mad(0.5f, _3102, float(_2238.x)) * 0.2886598110198974609375f, 0.25f * _3102);
    uint3 _3285 = (uint3(uint2(int2(uint2(_2238) + _2086)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _3287 = _3285.y;
    uint _3289 = _3285.z;
    uint _3293 = _3285.x + (_3287 * _3289);
    uint _3302 = _3287 + (_3289 * _3293);
    uint3 _10636 = uint3(_3293, _3302, _3289 + (_3293 * _3302));
    uint3 _3317 = _10636 ^ (_10636 >> uint3(16u, 16u, 16u));
    uint _3319 = _3317.y;
    uint _3321 = _3317.z;
    uint _3325 = _3317.x + (_3319 * _3321);
    uint _3334 = _3319 + (_3321 * _3325);
    float3 _3190 = float3(uint3(_3325, _3334, _3321 + (_3325 * _3334)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _3200 = (mad(_3190.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _3272 = cos(_3200);
    float _3274 = sin(_3200);
    float _3416 = _2154.x;
    float _3421 = _2154.y;
    float2 _3146 = (float2(mad(_3416, _3272, _3421 * _3274), mad(-_3416, _3274, _3421 * _3272)) * 1.0f) + _3190.xy;
    float4 _3519 = hexcTex_albedo.SampleGrad(hexcSampler, _2354, float2(mad(_2650, _2480, _2655 * _2482), mad(_2662, _2482, _2655 * _2480)) * 1.0f, float2(mad(_2676, _2480, _2681 * _2482), mad(_2688, _2482, _2681 * _2480)) * 1.0f);
    float4 _3529 = hexcTex_albedo.SampleGrad(hexcSampler, _2750, float2(mad(_2650, _2876, _2655 * _2878), mad(_2662, _2878, _2655 * _2876)) * 1.0f, float2(mad(_2676, _2876, _2681 * _2878), mad(_2688, _2878, _2681 * _2876)) * 1.0f);
    float4 _3543 = hexcTex_albedo.SampleGrad(hexcSampler, _3146, float2(mad(_2650, _3272, _2655 * _3274), mad(_2662, _3274, _2655 * _3272)) * 1.0f, float2(mad(_2676, _3272, _2681 * _3274), mad(_2688, _3274, _2681 * _3272)) * 1.0f);
    float3 _3704 = _2219 * _2219;
    float3 _3722 = (_2219 * _3704) * (_3704 * _3704);
    float3 _3633 = lerp(1.0f.xxx, max(float3(dot(_3519, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_3529, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_3543, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f))), 0.0f.xxx), hexcParams_albedo_falloffcontrast.xxx) * _3722;
    float _3645 = (_3633.x + _3633.y) + _3633.z;
    float3 _10242;
    if (_3645 > 0.0f)
    {
        _10242 = _3633 / _3645.xxx;
    }
    else
    {
        _10242 = _3722 / ((_3722.x + _3722.y) + _3722.z).xxx;
    }
    float3 _3773 = step(0.5f.xxx, _10242) * 2.0f;
    float3 _3777 = (1.0f.xxx - _3773) * 2.0f;
    float3 _3783 = max(0.0f.xxx, mad(_10242, _3777, _3773));
    float3 _3802 = mad(_3777 * 0.25f, _3783 * _3783, _3773 * 0.5f);
    float3 _3813 = _3802 / ((_3802.x + _3802.y) + _3802.z).xxx;
    float2 _4001 = ddx(_1928);
    float2 _4003 = ddy(_1928);
    float _4724 = _4001.x;
    float _4729 = _4001.y;
    float _4736 = -_4724;
    float _4750 = _4003.x;
    float _4755 = _4003.y;
    float _4762 = -_4750;
    float4 _5613 = hexcTex_roughness.SampleGrad(hexcSampler, _2354, float2(mad(_4724, _2480, _4729 * _2482), mad(_4736, _2482, _4729 * _2480)) * 1.0f, float2(mad(_4750, _2480, _4755 * _2482), mad(_4762, _2482, _4755 * _2480)) * 1.0f);
    float4 _5623 = hexcTex_roughness.SampleGrad(hexcSampler, _2750, float2(mad(_4724, _2876, _4729 * _2878), mad(_4736, _2878, _4729 * _2876)) * 1.0f, float2(mad(_4750, _2876, _4755 * _2878), mad(_4762, _2878, _4755 * _2876)) * 1.0f);
    float4 _5637 = hexcTex_roughness.SampleGrad(hexcSampler, _3146, float2(mad(_4724, _3272, _4729 * _3274), mad(_4736, _3274, _4729 * _3272)) * 1.0f, float2(mad(_4750, _3272, _4755 * _3274), mad(_4762, _3274, _4755 * _3272)) * 1.0f);
    float3 _5727 = lerp(1.0f.xxx, max(float3(_5613.x, _5623.x, _5637.x), 0.0f.xxx), hexcParams_roughness_falloffcontrast.xxx) * _3722;
    float _5739 = (_5727.x + _5727.y) + _5727.z;
    float3 _10373;
    if (_5739 > 0.0f)
    {
        _10373 = _5727 / _5739.xxx;
    }
    else
    {
        _10373 = _3722 / ((_3722.x + _3722.y) + _3722.z).xxx;
    }
    float3 _5867 = step(0.5f.xxx, _10373) * 2.0f;
    float3 _5871 = (1.0f.xxx - _5867) * 2.0f;
    float3 _5877 = max(0.0f.xxx, mad(_10373, _5871, _5867));
    float3 _5896 = mad(_5871 * 0.25f, _5877 * _5877, _5867 * 0.5f);
    float3 _5907 = _5896 / ((_5896.x + _5896.y) + _5896.z).xxx;
    float _1807 = clamp((((_5613 * _5907.x) + (_5623 * _5907.y)) + (_5637 * _5907.z)).x, 0.0199999995529651641845703125f, 1.0f);
    float3 _1812 = normalize(v_normal);
    float3 _1825 = normalize(v_tangent.xyz - (_1812 * dot(_1812, v_tangent.xyz)));
    float2 _6095 = ddx(_1928);
    float2 _6097 = ddy(_1928);
    float _6815 = _6095.x;
    float _6820 = _6095.y;
    float _6827 = -_6815;
    float _6841 = _6097.x;
    float _6846 = _6097.y;
    float _6853 = -_6841;
    float3 _7809 = (hexcTex_normal.SampleGrad(hexcSampler, _2354, float2(mad(_6815, _2480, _6820 * _2482), mad(_6827, _2482, _6820 * _2480)) * 1.0f, float2(mad(_6841, _2480, _6846 * _2482), mad(_6853, _2482, _6846 * _2480)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _7819 = abs(_7809);
    float2 _7846 = (-float2(_7809.xy)) / max(max(_7819.z, 0.0078125f * max(_7819.x, _7819.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _7852 = _7846.x;
    float _7857 = _7846.y;
    float2 _7706 = float2(mad(_2480, _7852, -(_2482 * _7857)), mad(_2482, _7852, _2480 * _7857)) * 1.0f;
    float3 _7887 = (hexcTex_normal.SampleGrad(hexcSampler, _2750, float2(mad(_6815, _2876, _6820 * _2878), mad(_6827, _2878, _6820 * _2876)) * 1.0f, float2(mad(_6841, _2876, _6846 * _2878), mad(_6853, _2878, _6846 * _2876)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _7897 = abs(_7887);
    float2 _7924 = (-float2(_7887.xy)) / max(max(_7897.z, 0.0078125f * max(_7897.x, _7897.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _7930 = _7924.x;
    float _7935 = _7924.y;
    float2 _7720 = float2(mad(_2876, _7930, -(_2878 * _7935)), mad(_2878, _7930, _2876 * _7935)) * 1.0f;
    float3 _7965 = (hexcTex_normal.SampleGrad(hexcSampler, _3146, float2(mad(_6815, _3272, _6820 * _3274), mad(_6827, _3274, _6820 * _3272)) * 1.0f, float2(mad(_6841, _3272, _6846 * _3274), mad(_6853, _3274, _6846 * _3272)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _7975 = abs(_7965);
    float2 _8002 = (-float2(_7965.xy)) / max(max(_7975.z, 0.0078125f * max(_7975.x, _7975.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _8008 = _8002.x;
    float _8013 = _8002.y;
    float2 _7738 = float2(mad(_3272, _8008, -(_3274 * _8013)), mad(_3274, _8008, _3272 * _8013)) * 1.0f;
    float3 _7751 = float3(dot(_7706, _7706), dot(_7720, _7720), dot(_7738, _7738));
    float3 _8067 = lerp(1.0f.xxx, max(sqrt(_7751 / (1.0f.xxx + _7751)), 0.0f.xxx), hexcParams_normal_falloffcontrast.xxx) * _3722;
    float _8079 = (_8067.x + _8067.y) + _8067.z;
    float3 _10549;
    if (_8079 > 0.0f)
    {
        _10549 = _8067 / _8079.xxx;
    }
    else
    {
        _10549 = _3722 / ((_3722.x + _3722.y) + _3722.z).xxx;
    }
    float3 _8421 = normalize(float3(-(((_7706 * _10549.x) + (_7720 * _10549.y)) + (_7738 * _10549.z)), 1.0f));
    float3 _1855 = normalize(((_1825 * _8421.x) + ((cross(_1812, _1825) * v_tangent.w) * _8421.y)) + (_1812 * _8421.z));
    float _1862 = max(dot(_1855, float3(0.408248007297515869140625f, 0.408248007297515869140625f, 0.816497027873992919921875f)), 0.0f);
    float _1875 = 2.0f / (((_1807 * _1807) * _1807) * _1807);
    o_color = float4(((((_3519 * _3813.x) + (_3529 * _3813.y)) + (_3543 * _3813.z)).xyz * (0.1500000059604644775390625f + _1862)) + (0.039999999105930328369140625f * (((pow(max(dot(_1855, float3(0.21418631076812744140625f, 0.21418631076812744140625f, 0.95302069187164306640625f)), 0.0f), _1875 - 2.0f) * (_1875 + 6.0f)) * 0.0397887341678142547607421875f) * _1862)).xxx, 1.0f);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    v_uv = stage_input.v_uv;
    v_normal = stage_input.v_normal;
    v_tangent = stage_input.v_tangent;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.o_color = o_color;
    return stage_output;
}
