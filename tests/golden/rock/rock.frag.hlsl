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
    float2 _1917 = v_uv * hexcParams_albedo_tiling;
    float2 _1919 = ddx(_1917);
    float2 _1921 = ddy(_1917);
    float _2021 = _1917.x;
    float _2023 = floor(_2021 * 0.0357142873108386993408203125f);
    float _2025 = _1917.y;
    float _2026 = floor(_2025);
    float _2031 = mad(-28.0f, _2023, _2021);
    float _2035 = _2025 - _2026;
    float2 _2036 = float2(_2031, _2035);
    float2 _2047 = float2(mad(3.4642856121063232421875f, _2031, _2035 * (-2.0f)), 4.0f * _2035);
    float2 _2175 = floor(_2047);
    int2 _2176 = int2(_2175);
    float2 _2180 = _2047 - _2175;
    float _2181 = _2180.x;
    float _2182 = _2180.y;
    float _2193 = -((1.0f - _2181) - _2182);
    float _2194 = step(0.0f, _2193);
    float _2197 = mad(2.0f, _2194, -1.0f);
    float3 _2215 = float3(_2193 * _2197, mad(-_2182, _2197, _2194), mad(-_2181, _2197, _2194));
    int _2217 = int(_2194);
    int2 _2222 = _2176 + _2217.xx;
    int _2226 = 1 - _2217;
    int2 _2228 = _2176 + int2(_2217, _2226);
    int2 _2234 = _2176 + int2(_2226, _2217);
    uint2 _2061 = uint2(int2(int(_2023), int(_2026)));
    uint _2067 = _2061.y;
    uint2 _2073 = uint2((97u * _2061.x) - (2u * _2067), 4u * _2067);
    float _2306 = float(_2222.y);
    float2 _2101 = _2036 - float2(mad(0.5f, _2306, float(_2222.x)) * 0.2886598110198974609375f, 0.25f * _2306);
    uint3 _2488 = (uint3(uint2(int2(uint2(_2222) + _2073)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2490 = _2488.y;
    uint _2492 = _2488.z;
    uint _2496 = _2488.x + (_2490 * _2492);
    uint _2505 = _2490 + (_2492 * _2496);
    uint3 _10238 = uint3(_2496, _2505, _2492 + (_2496 * _2505));
    uint3 _2520 = _10238 ^ (_10238 >> uint3(16u, 16u, 16u));
    uint _2522 = _2520.y;
    uint _2524 = _2520.z;
    uint _2528 = _2520.x + (_2522 * _2524);
    uint _2537 = _2522 + (_2524 * _2528);
    float3 _2397 = float3(uint3(_2528, _2537, _2524 + (_2528 * _2537)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2406 = (mad(_2397.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _2475 = cos(_2406);
    float _2477 = sin(_2406);
    float _2619 = _2101.x;
    float _2624 = _2101.y;
    float2 _2355 = (float2(mad(_2619, _2475, _2624 * _2477), mad(-_2619, _2477, _2624 * _2475)) * 1.0f) + _2397.xy;
    float _2645 = _1919.x;
    float _2650 = _1919.y;
    float _2657 = -_2645;
    float _2671 = _1921.x;
    float _2676 = _1921.y;
    float _2683 = -_2671;
    float _2701 = float(_2228.y);
    float2 _2124 = _2036 - float2(mad(0.5f, _2701, float(_2228.x)) * 0.2886598110198974609375f, 0.25f * _2701);
    uint3 _2883 = (uint3(uint2(int2(uint2(_2228) + _2073)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2885 = _2883.y;
    uint _2887 = _2883.z;
    uint _2891 = _2883.x + (_2885 * _2887);
    uint _2900 = _2885 + (_2887 * _2891);
    uint3 _10241 = uint3(_2891, _2900, _2887 + (_2891 * _2900));
    uint3 _2915 = _10241 ^ (_10241 >> uint3(16u, 16u, 16u));
    uint _2917 = _2915.y;
    uint _2919 = _2915.z;
    uint _2923 = _2915.x + (_2917 * _2919);
    uint _2932 = _2917 + (_2919 * _2923);
    float3 _2792 = float3(uint3(_2923, _2932, _2919 + (_2923 * _2932)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2801 = (mad(_2792.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _2870 = cos(_2801);
    float _2872 = sin(_2801);
    float _3014 = _2124.x;
    float _3019 = _2124.y;
    float2 _2750 = (float2(mad(_3014, _2870, _3019 * _2872), mad(-_3014, _2872, _3019 * _2870)) * 1.0f) + _2792.xy;
    float _3096 = float(_2234.y);
    float2 _2147 = _2036 - float2(mad(0.5f, _3096, float(_2234.x)) * 0.2886598110198974609375f, 0.25f * _3096);
    uint3 _3278 = (uint3(uint2(int2(uint2(_2234) + _2073)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _3280 = _3278.y;
    uint _3282 = _3278.z;
    uint _3286 = _3278.x + (_3280 * _3282);
    uint _3295 = _3280 + (_3282 * _3286);
    uint3 _10244 = uint3(_3286, _3295, _3282 + (_3286 * _3295));
    uint3 _3310 = _10244 ^ (_10244 >> uint3(16u, 16u, 16u));
    uint _3312 = _3310.y;
    uint _3314 = _3310.z;
    uint _3318 = _3310.x + (_3312 * _3314);
    uint _3327 = _3312 + (_3314 * _3318);
    float3 _3187 = float3(uint3(_3318, _3327, _3314 + (_3318 * _3327)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _3196 = (mad(_3187.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _3265 = cos(_3196);
    float _3267 = sin(_3196);
    float _3409 = _2147.x;
    float _3414 = _2147.y;
    float2 _3145 = (float2(mad(_3409, _3265, _3414 * _3267), mad(-_3409, _3267, _3414 * _3265)) * 1.0f) + _3187.xy;
    float4 _3518 = hexcTex_albedo.SampleGrad(hexcSampler, _2355, float2(mad(_2645, _2475, _2650 * _2477), mad(_2657, _2477, _2650 * _2475)) * 1.0f, float2(mad(_2671, _2475, _2676 * _2477), mad(_2683, _2477, _2676 * _2475)) * 1.0f);
    float4 _3528 = hexcTex_albedo.SampleGrad(hexcSampler, _2750, float2(mad(_2645, _2870, _2650 * _2872), mad(_2657, _2872, _2650 * _2870)) * 1.0f, float2(mad(_2671, _2870, _2676 * _2872), mad(_2683, _2872, _2676 * _2870)) * 1.0f);
    float4 _3541 = hexcTex_albedo.SampleGrad(hexcSampler, _3145, float2(mad(_2645, _3265, _2650 * _3267), mad(_2657, _3267, _2650 * _3265)) * 1.0f, float2(mad(_2671, _3265, _2676 * _3267), mad(_2683, _3267, _2676 * _3265)) * 1.0f);
    float3 _3691 = _2215 * _2215;
    float3 _3709 = (_2215 * _3691) * (_3691 * _3691);
    float3 _3628 = lerp(1.0f.xxx, max(float3(dot(_3518, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_3528, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_3541, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f))), 0.0f.xxx), hexcParams_albedo_falloffcontrast.xxx) * _3709;
    float _3640 = (_3628.x + _3628.y) + _3628.z;
    float3 _9866;
    if (_3640 > 0.0f)
    {
        _9866 = _3628 / _3640.xxx;
    }
    else
    {
        _9866 = _3709 / ((_3709.x + _3709.y) + _3709.z).xxx;
    }
    float3 _3760 = step(0.5f.xxx, _9866) * 2.0f;
    float3 _3764 = (1.0f.xxx - _3760) * 2.0f;
    float3 _3770 = max(0.0f.xxx, mad(_9866, _3764, _3760));
    float3 _3789 = mad(_3764 * 0.25f, _3770 * _3770, _3760 * 0.5f);
    float3 _3800 = _3789 / ((_3789.x + _3789.y) + _3789.z).xxx;
    float2 _3988 = ddx(_1917);
    float2 _3990 = ddy(_1917);
    float _4715 = _3988.x;
    float _4720 = _3988.y;
    float _4727 = -_4715;
    float _4741 = _3990.x;
    float _4746 = _3990.y;
    float _4753 = -_4741;
    float4 _5588 = hexcTex_roughness.SampleGrad(hexcSampler, _2355, float2(mad(_4715, _2475, _4720 * _2477), mad(_4727, _2477, _4720 * _2475)) * 1.0f, float2(mad(_4741, _2475, _4746 * _2477), mad(_4753, _2477, _4746 * _2475)) * 1.0f);
    float4 _5598 = hexcTex_roughness.SampleGrad(hexcSampler, _2750, float2(mad(_4715, _2870, _4720 * _2872), mad(_4727, _2872, _4720 * _2870)) * 1.0f, float2(mad(_4741, _2870, _4746 * _2872), mad(_4753, _2872, _4746 * _2870)) * 1.0f);
    float4 _5611 = hexcTex_roughness.SampleGrad(hexcSampler, _3145, float2(mad(_4715, _3265, _4720 * _3267), mad(_4727, _3267, _4720 * _3265)) * 1.0f, float2(mad(_4741, _3265, _4746 * _3267), mad(_4753, _3267, _4746 * _3265)) * 1.0f);
    float3 _5698 = lerp(1.0f.xxx, max(float3(_5588.x, _5598.x, _5611.x), 0.0f.xxx), hexcParams_roughness_falloffcontrast.xxx) * _3709;
    float _5710 = (_5698.x + _5698.y) + _5698.z;
    float3 _9993;
    if (_5710 > 0.0f)
    {
        _9993 = _5698 / _5710.xxx;
    }
    else
    {
        _9993 = _3709 / ((_3709.x + _3709.y) + _3709.z).xxx;
    }
    float3 _5830 = step(0.5f.xxx, _9993) * 2.0f;
    float3 _5834 = (1.0f.xxx - _5830) * 2.0f;
    float3 _5840 = max(0.0f.xxx, mad(_9993, _5834, _5830));
    float3 _5859 = mad(_5834 * 0.25f, _5840 * _5840, _5830 * 0.5f);
    float3 _5870 = _5859 / ((_5859.x + _5859.y) + _5859.z).xxx;
    float _1796 = clamp((((_5588 * _5870.x) + (_5598 * _5870.y)) + (_5611 * _5870.z)).x, 0.0199999995529651641845703125f, 1.0f);
    float3 _1801 = normalize(v_normal);
    float3 _1814 = normalize(v_tangent.xyz - (_1801 * dot(_1801, v_tangent.xyz)));
    float2 _6058 = ddx(_1917);
    float2 _6060 = ddy(_1917);
    float _6784 = _6058.x;
    float _6789 = _6058.y;
    float _6796 = -_6784;
    float _6810 = _6060.x;
    float _6815 = _6060.y;
    float _6822 = -_6810;
    float3 _7783 = (hexcTex_normal.SampleGrad(hexcSampler, _2355, float2(mad(_6784, _2475, _6789 * _2477), mad(_6796, _2477, _6789 * _2475)) * 1.0f, float2(mad(_6810, _2475, _6815 * _2477), mad(_6822, _2477, _6815 * _2475)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _7793 = abs(_7783);
    float2 _7820 = (-float2(_7783.xy)) / max(max(_7793.z, 0.0078125f * max(_7793.x, _7793.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _7826 = _7820.x;
    float _7831 = _7820.y;
    float2 _7679 = float2(mad(_2475, _7826, -(_2477 * _7831)), mad(_2477, _7826, _2475 * _7831)) * 1.0f;
    float3 _7861 = (hexcTex_normal.SampleGrad(hexcSampler, _2750, float2(mad(_6784, _2870, _6789 * _2872), mad(_6796, _2872, _6789 * _2870)) * 1.0f, float2(mad(_6810, _2870, _6815 * _2872), mad(_6822, _2872, _6815 * _2870)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _7871 = abs(_7861);
    float2 _7898 = (-float2(_7861.xy)) / max(max(_7871.z, 0.0078125f * max(_7871.x, _7871.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _7904 = _7898.x;
    float _7909 = _7898.y;
    float2 _7693 = float2(mad(_2870, _7904, -(_2872 * _7909)), mad(_2872, _7904, _2870 * _7909)) * 1.0f;
    float3 _7939 = (hexcTex_normal.SampleGrad(hexcSampler, _3145, float2(mad(_6784, _3265, _6789 * _3267), mad(_6796, _3267, _6789 * _3265)) * 1.0f, float2(mad(_6810, _3265, _6815 * _3267), mad(_6822, _3267, _6815 * _3265)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _7949 = abs(_7939);
    float2 _7976 = (-float2(_7939.xy)) / max(max(_7949.z, 0.0078125f * max(_7949.x, _7949.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _7982 = _7976.x;
    float _7987 = _7976.y;
    float2 _7710 = float2(mad(_3265, _7982, -(_3267 * _7987)), mad(_3267, _7982, _3265 * _7987)) * 1.0f;
    float3 _7723 = float3(dot(_7679, _7679), dot(_7693, _7693), dot(_7710, _7710));
    float3 _8036 = lerp(1.0f.xxx, max(sqrt(_7723 / (1.0f.xxx + _7723)), 0.0f.xxx), hexcParams_normal_falloffcontrast.xxx) * _3709;
    float _8048 = (_8036.x + _8036.y) + _8036.z;
    float3 _10164;
    if (_8048 > 0.0f)
    {
        _10164 = _8036 / _8048.xxx;
    }
    else
    {
        _10164 = _3709 / ((_3709.x + _3709.y) + _3709.z).xxx;
    }
    float3 _8382 = normalize(float3(-(((_7679 * _10164.x) + (_7693 * _10164.y)) + (_7710 * _10164.z)), 1.0f));
    float3 _1844 = normalize(((_1814 * _8382.x) + ((cross(_1801, _1814) * v_tangent.w) * _8382.y)) + (_1801 * _8382.z));
    float _1851 = max(dot(_1844, float3(0.408248007297515869140625f, 0.408248007297515869140625f, 0.816497027873992919921875f)), 0.0f);
    float _1864 = 2.0f / (((_1796 * _1796) * _1796) * _1796);
    o_color = float4(((((_3518 * _3800.x) + (_3528 * _3800.y)) + (_3541 * _3800.z)).xyz * (0.1500000059604644775390625f + _1851)) + (0.039999999105930328369140625f * (((pow(max(dot(_1844, float3(0.21418631076812744140625f, 0.21418631076812744140625f, 0.95302069187164306640625f)), 0.0f), _1864 - 2.0f) * (_1864 + 6.0f)) * 0.0397887341678142547607421875f) * _1851)).xxx, 1.0f);
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
