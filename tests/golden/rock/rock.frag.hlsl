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
    float2 _1910 = v_uv * hexcParams_albedo_tiling;
    float2 _1912 = ddx(_1910);
    float2 _1914 = ddy(_1910);
    float _2016 = _1910.x;
    float _2018 = floor(_2016 * 0.0357142873108386993408203125f);
    float _2020 = _1910.y;
    float _2021 = floor(_2020);
    float _2026 = mad(-28.0f, _2018, _2016);
    float _2030 = _2020 - _2021;
    float2 _2031 = float2(_2026, _2030);
    float2 _2042 = float2(mad(3.4642856121063232421875f, _2026, _2030 * (-2.0f)), 4.0f * _2030);
    float2 _2161 = floor(_2042);
    int2 _2162 = int2(_2161);
    float2 _2166 = _2042 - _2161;
    float _2167 = _2166.x;
    float _2168 = _2166.y;
    float _2179 = -((1.0f - _2167) - _2168);
    float _2180 = step(0.0f, _2179);
    float _2183 = mad(2.0f, _2180, -1.0f);
    float3 _2201 = float3(_2179 * _2183, mad(-_2168, _2183, _2180), mad(-_2167, _2183, _2180));
    int _2203 = int(_2180);
    int2 _2208 = _2162 + _2203.xx;
    int _2212 = 1 - _2203;
    int2 _2214 = _2162 + int2(_2203, _2212);
    int2 _2220 = _2162 + int2(_2212, _2203);
    uint2 _2056 = uint2(int2(int(_2018), int(_2021)));
    uint _2062 = _2056.y;
    uint2 _2068 = uint2((97u * _2056.x) - (2u * _2062), 4u * _2062);
    float _2292 = float(_2208.y);
    float2 _2096 = _2031 - float2(mad(0.5f, _2292, float(_2208.x)) * 0.2886598110198974609375f, 0.25f * _2292);
    uint3 _2475 = (uint3(uint2(int2(uint2(_2208) + _2068)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2477 = _2475.y;
    uint _2479 = _2475.z;
    uint _2483 = _2475.x + (_2477 * _2479);
    uint _2492 = _2477 + (_2479 * _2483);
    uint3 _10631 = uint3(_2483, _2492, _2479 + (_2483 * _2492));
    uint3 _2507 = _10631 ^ (_10631 >> uint3(16u, 16u, 16u));
    uint _2509 = _2507.y;
    uint _2511 = _2507.z;
    uint _2515 = _2507.x + (_2509 * _2511);
    uint _2524 = _2509 + (_2511 * _2515);
    float3 _2380 = float3(uint3(_2515, _2524, _2511 + (_2515 * _2524)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2390 = (mad(_2380.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _2462 = cos(_2390);
    float _2464 = sin(_2390);
    float _2606 = _2096.x;
    float _2611 = _2096.y;
    float2 _2336 = (float2(mad(_2606, _2462, _2611 * _2464), mad(-_2606, _2464, _2611 * _2462)) * 1.0f) + _2380.xy;
    float _2632 = _1912.x;
    float _2637 = _1912.y;
    float _2644 = -_2632;
    float _2658 = _1914.x;
    float _2663 = _1914.y;
    float _2670 = -_2658;
    float _2688 = float(_2214.y);
    float2 _2116 = _2031 - float2(mad(0.5f, _2688, float(_2214.x)) * 0.2886598110198974609375f, 0.25f * _2688);
    uint3 _2871 = (uint3(uint2(int2(uint2(_2214) + _2068)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2873 = _2871.y;
    uint _2875 = _2871.z;
    uint _2879 = _2871.x + (_2873 * _2875);
    uint _2888 = _2873 + (_2875 * _2879);
    uint3 _10637 = uint3(_2879, _2888, _2875 + (_2879 * _2888));
    uint3 _2903 = _10637 ^ (_10637 >> uint3(16u, 16u, 16u));
    uint _2905 = _2903.y;
    uint _2907 = _2903.z;
    uint _2911 = _2903.x + (_2905 * _2907);
    uint _2920 = _2905 + (_2907 * _2911);
    float3 _2776 = float3(uint3(_2911, _2920, _2907 + (_2911 * _2920)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2786 = (mad(_2776.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _2858 = cos(_2786);
    float _2860 = sin(_2786);
    float _3002 = _2116.x;
    float _3007 = _2116.y;
    float2 _2732 = (float2(mad(_3002, _2858, _3007 * _2860), mad(-_3002, _2860, _3007 * _2858)) * 1.0f) + _2776.xy;
    float _3084 = float(_2220.y);
    float2 _2136 = _2031 - float2(mad(0.5f, _3084, float(_2220.x)) * 0.2886598110198974609375f, 0.25f * _3084);
    uint3 _3267 = (uint3(uint2(int2(uint2(_2220) + _2068)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _3269 = _3267.y;
    uint _3271 = _3267.z;
    uint _3275 = _3267.x + (_3269 * _3271);
    uint _3284 = _3269 + (_3271 * _3275);
    uint3 _10642 = uint3(_3275, _3284, _3271 + (_3275 * _3284));
    uint3 _3299 = _10642 ^ (_10642 >> uint3(16u, 16u, 16u));
    uint _3301 = _3299.y;
    uint _3303 = _3299.z;
    uint _3307 = _3299.x + (_3301 * _3303);
    uint _3316 = _3301 + (_3303 * _3307);
    float3 _3172 = float3(uint3(_3307, _3316, _3303 + (_3307 * _3316)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _3182 = (mad(_3172.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _3254 = cos(_3182);
    float _3256 = sin(_3182);
    float _3398 = _2136.x;
    float _3403 = _2136.y;
    float2 _3128 = (float2(mad(_3398, _3254, _3403 * _3256), mad(-_3398, _3256, _3403 * _3254)) * 1.0f) + _3172.xy;
    float4 _3501 = hexcTex_albedo.SampleGrad(hexcSampler, _2336, float2(mad(_2632, _2462, _2637 * _2464), mad(_2644, _2464, _2637 * _2462)) * 1.0f, float2(mad(_2658, _2462, _2663 * _2464), mad(_2670, _2464, _2663 * _2462)) * 1.0f);
    float4 _3511 = hexcTex_albedo.SampleGrad(hexcSampler, _2732, float2(mad(_2632, _2858, _2637 * _2860), mad(_2644, _2860, _2637 * _2858)) * 1.0f, float2(mad(_2658, _2858, _2663 * _2860), mad(_2670, _2860, _2663 * _2858)) * 1.0f);
    float4 _3525 = hexcTex_albedo.SampleGrad(hexcSampler, _3128, float2(mad(_2632, _3254, _2637 * _3256), mad(_2644, _3256, _2637 * _3254)) * 1.0f, float2(mad(_2658, _3254, _2663 * _3256), mad(_2670, _3256, _2663 * _3254)) * 1.0f);
    float3 _3686 = _2201 * _2201;
    float3 _3704 = (_2201 * _3686) * (_3686 * _3686);
    float3 _3615 = lerp(1.0f.xxx, max(float3(dot(_3501, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_3511, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_3525, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f))), 0.0f.xxx), hexcParams_albedo_falloffcontrast.xxx) * _3704;
    float _3627 = (_3615.x + _3615.y) + _3615.z;
    float3 _10248;
    if (_3627 > 0.0f)
    {
        _10248 = _3615 / _3627.xxx;
    }
    else
    {
        _10248 = _3704 / ((_3704.x + _3704.y) + _3704.z).xxx;
    }
    float3 _3755 = step(0.5f.xxx, _10248) * 2.0f;
    float3 _3759 = (1.0f.xxx - _3755) * 2.0f;
    float3 _3765 = max(0.0f.xxx, mad(_10248, _3759, _3755));
    float3 _3784 = mad(_3759 * 0.25f, _3765 * _3765, _3755 * 0.5f);
    float3 _3795 = _3784 / ((_3784.x + _3784.y) + _3784.z).xxx;
    float2 _3983 = ddx(_1910);
    float2 _3985 = ddy(_1910);
    float _4706 = _3983.x;
    float _4711 = _3983.y;
    float _4718 = -_4706;
    float _4732 = _3985.x;
    float _4737 = _3985.y;
    float _4744 = -_4732;
    float4 _5595 = hexcTex_roughness.SampleGrad(hexcSampler, _2336, float2(mad(_4706, _2462, _4711 * _2464), mad(_4718, _2464, _4711 * _2462)) * 1.0f, float2(mad(_4732, _2462, _4737 * _2464), mad(_4744, _2464, _4737 * _2462)) * 1.0f);
    float4 _5605 = hexcTex_roughness.SampleGrad(hexcSampler, _2732, float2(mad(_4706, _2858, _4711 * _2860), mad(_4718, _2860, _4711 * _2858)) * 1.0f, float2(mad(_4732, _2858, _4737 * _2860), mad(_4744, _2860, _4737 * _2858)) * 1.0f);
    float4 _5619 = hexcTex_roughness.SampleGrad(hexcSampler, _3128, float2(mad(_4706, _3254, _4711 * _3256), mad(_4718, _3256, _4711 * _3254)) * 1.0f, float2(mad(_4732, _3254, _4737 * _3256), mad(_4744, _3256, _4737 * _3254)) * 1.0f);
    float3 _5709 = lerp(1.0f.xxx, max(float3(_5595.x, _5605.x, _5619.x), 0.0f.xxx), hexcParams_roughness_falloffcontrast.xxx) * _3704;
    float _5721 = (_5709.x + _5709.y) + _5709.z;
    float3 _10379;
    if (_5721 > 0.0f)
    {
        _10379 = _5709 / _5721.xxx;
    }
    else
    {
        _10379 = _3704 / ((_3704.x + _3704.y) + _3704.z).xxx;
    }
    float3 _5849 = step(0.5f.xxx, _10379) * 2.0f;
    float3 _5853 = (1.0f.xxx - _5849) * 2.0f;
    float3 _5859 = max(0.0f.xxx, mad(_10379, _5853, _5849));
    float3 _5878 = mad(_5853 * 0.25f, _5859 * _5859, _5849 * 0.5f);
    float3 _5889 = _5878 / ((_5878.x + _5878.y) + _5878.z).xxx;
    float _1789 = clamp((((_5595 * _5889.x) + (_5605 * _5889.y)) + (_5619 * _5889.z)).x, 0.0199999995529651641845703125f, 1.0f);
    float3 _1794 = normalize(v_normal);
    float3 _1807 = normalize(v_tangent.xyz - (_1794 * dot(_1794, v_tangent.xyz)));
    float2 _6077 = ddx(_1910);
    float2 _6079 = ddy(_1910);
    float _6797 = _6077.x;
    float _6802 = _6077.y;
    float _6809 = -_6797;
    float _6823 = _6079.x;
    float _6828 = _6079.y;
    float _6835 = -_6823;
    float3 _7791 = (hexcTex_normal.SampleGrad(hexcSampler, _2336, float2(mad(_6797, _2462, _6802 * _2464), mad(_6809, _2464, _6802 * _2462)) * 1.0f, float2(mad(_6823, _2462, _6828 * _2464), mad(_6835, _2464, _6828 * _2462)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _7801 = abs(_7791);
    float2 _7828 = (-float2(_7791.xy)) / max(max(_7801.z, 0.0078125f * max(_7801.x, _7801.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _7839 = _7828.x;
    float _7844 = _7828.y;
    float2 _7688 = float2(mad(_7839, _2462, _7844 * _2464), mad(-_7839, _2464, _7844 * _2462)) * 1.0f;
    float3 _7877 = (hexcTex_normal.SampleGrad(hexcSampler, _2732, float2(mad(_6797, _2858, _6802 * _2860), mad(_6809, _2860, _6802 * _2858)) * 1.0f, float2(mad(_6823, _2858, _6828 * _2860), mad(_6835, _2860, _6828 * _2858)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _7887 = abs(_7877);
    float2 _7914 = (-float2(_7877.xy)) / max(max(_7887.z, 0.0078125f * max(_7887.x, _7887.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _7925 = _7914.x;
    float _7930 = _7914.y;
    float2 _7702 = float2(mad(_7925, _2858, _7930 * _2860), mad(-_7925, _2860, _7930 * _2858)) * 1.0f;
    float3 _7963 = (hexcTex_normal.SampleGrad(hexcSampler, _3128, float2(mad(_6797, _3254, _6802 * _3256), mad(_6809, _3256, _6802 * _3254)) * 1.0f, float2(mad(_6823, _3254, _6828 * _3256), mad(_6835, _3256, _6828 * _3254)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _7973 = abs(_7963);
    float2 _8000 = (-float2(_7963.xy)) / max(max(_7973.z, 0.0078125f * max(_7973.x, _7973.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _8011 = _8000.x;
    float _8016 = _8000.y;
    float2 _7720 = float2(mad(_8011, _3254, _8016 * _3256), mad(-_8011, _3256, _8016 * _3254)) * 1.0f;
    float3 _7733 = float3(dot(_7688, _7688), dot(_7702, _7702), dot(_7720, _7720));
    float3 _8073 = lerp(1.0f.xxx, max(sqrt(_7733 / (1.0f.xxx + _7733)), 0.0f.xxx), hexcParams_normal_falloffcontrast.xxx) * _3704;
    float _8085 = (_8073.x + _8073.y) + _8073.z;
    float3 _10555;
    if (_8085 > 0.0f)
    {
        _10555 = _8073 / _8085.xxx;
    }
    else
    {
        _10555 = _3704 / ((_3704.x + _3704.y) + _3704.z).xxx;
    }
    float3 _8427 = normalize(float3(-(((_7688 * _10555.x) + (_7702 * _10555.y)) + (_7720 * _10555.z)), 1.0f));
    float3 _1837 = normalize(((_1807 * _8427.x) - ((cross(_1794, _1807) * v_tangent.w) * _8427.y)) + (_1794 * _8427.z));
    float _1844 = max(dot(_1837, float3(0.408248007297515869140625f, 0.408248007297515869140625f, 0.816497027873992919921875f)), 0.0f);
    float _1857 = 2.0f / (((_1789 * _1789) * _1789) * _1789);
    o_color = float4(((((_3501 * _3795.x) + (_3511 * _3795.y)) + (_3525 * _3795.z)).xyz * (0.1500000059604644775390625f + _1844)) + (0.039999999105930328369140625f * (((pow(max(dot(_1837, float3(0.21418631076812744140625f, 0.21418631076812744140625f, 0.95302069187164306640625f)), 0.0f), _1857 - 2.0f) * (_1857 + 6.0f)) * 0.0397887341678142547607421875f) * _1844)).xxx, 1.0f);
}

SPIRV_Cross_Output rock_frag(SPIRV_Cross_Input stage_input)
{
    v_uv = stage_input.v_uv;
    v_normal = stage_input.v_normal;
    v_tangent = stage_input.v_tangent;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.o_color = o_color;
    return stage_output;
}
