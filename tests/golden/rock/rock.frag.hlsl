cbuffer HexcParams : register(b0)
{
    float2 hexcParams_albedo_tiling : packoffset(c0);
    float hexcParams_albedo_rotation : packoffset(c0.z);
    float hexcParams_albedo_falloff : packoffset(c0.w);
    float hexcParams_albedo_falloffcontrast : packoffset(c1);
    float hexcParams_albedo_exponent : packoffset(c1.y);
    float2 hexcParams_normal_tiling : packoffset(c1.z);
    float hexcParams_normal_rotation : packoffset(c2);
    float hexcParams_normal_falloff : packoffset(c2.y);
    float hexcParams_normal_falloffcontrast : packoffset(c2.z);
    float hexcParams_normal_exponent : packoffset(c2.w);
    float2 hexcParams_roughness_tiling : packoffset(c3);
    float hexcParams_roughness_rotation : packoffset(c3.z);
    float hexcParams_roughness_falloff : packoffset(c3.w);
    float hexcParams_roughness_falloffcontrast : packoffset(c4);
    float hexcParams_roughness_exponent : packoffset(c4.y);
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
    float2 _1379 = v_uv * hexcParams_albedo_tiling;
    float2 _1399 = ddx(_1379);
    float2 _1401 = ddy(_1379);
    float _1457 = _1379.x;
    float _1459 = floor(_1457 * 0.0357142873108386993408203125f);
    float _1461 = _1379.y;
    float _1462 = floor(_1461);
    float _1467 = mad(-28.0f, _1459, _1457);
    float _1471 = _1461 - _1462;
    float2 _1472 = float2(_1467, _1471);
    float2 _1483 = float2(mad(3.4642856121063232421875f, _1467, _1471 * (-2.0f)), 4.0f * _1471);
    float2 _1613 = floor(_1483);
    int2 _1614 = int2(_1613);
    float2 _1618 = _1483 - _1613;
    float _1619 = _1618.x;
    float _1620 = _1618.y;
    float _1631 = -((1.0f - _1619) - _1620);
    float _1632 = step(0.0f, _1631);
    float _1635 = mad(2.0f, _1632, -1.0f);
    int _1655 = int(_1632);
    int2 _1660 = _1614 + _1655.xx;
    int _1664 = 1 - _1655;
    int2 _1666 = _1614 + int2(_1655, _1664);
    int2 _1672 = _1614 + int2(_1664, _1655);
    uint _1497 = uint(int(_1462));
    uint2 _1504 = uint2((97u * uint(int(_1459))) - (2u * _1497), 4u * _1497);
    uint3 _1708 = (uint3(uint2(int2(uint2(_1660) + _1504)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1710 = _1708.y;
    uint _1712 = _1708.z;
    uint _1716 = _1708.x + (_1710 * _1712);
    uint _1725 = _1710 + (_1712 * _1716);
    uint3 _6081 = uint3(_1716, _1725, _1712 + (_1716 * _1725));
    uint3 _1740 = _6081 ^ (_6081 >> uint3(16u, 16u, 16u));
    uint _1742 = _1740.y;
    uint _1744 = _1740.z;
    uint _1748 = _1740.x + (_1742 * _1744);
    uint _1757 = _1742 + (_1744 * _1748);
    uint3 _1684 = uint3(_1748, _1757, _1744 + (_1748 * _1757)) >> uint3(8u, 8u, 8u);
    float _1696 = (mad(float(_1684.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _1698 = cos(_1696);
    float _1700 = sin(_1696);
    uint3 _1804 = (uint3(uint2(int2(uint2(_1666) + _1504)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1806 = _1804.y;
    uint _1808 = _1804.z;
    uint _1812 = _1804.x + (_1806 * _1808);
    uint _1821 = _1806 + (_1808 * _1812);
    uint3 _6083 = uint3(_1812, _1821, _1808 + (_1812 * _1821));
    uint3 _1836 = _6083 ^ (_6083 >> uint3(16u, 16u, 16u));
    uint _1838 = _1836.y;
    uint _1840 = _1836.z;
    uint _1844 = _1836.x + (_1838 * _1840);
    uint _1853 = _1838 + (_1840 * _1844);
    uint3 _1780 = uint3(_1844, _1853, _1840 + (_1844 * _1853)) >> uint3(8u, 8u, 8u);
    float _1792 = (mad(float(_1780.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _1794 = cos(_1792);
    float _1796 = sin(_1792);
    uint3 _1900 = (uint3(uint2(int2(uint2(_1672) + _1504)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1902 = _1900.y;
    uint _1904 = _1900.z;
    uint _1908 = _1900.x + (_1902 * _1904);
    uint _1917 = _1902 + (_1904 * _1908);
    uint3 _6085 = uint3(_1908, _1917, _1904 + (_1908 * _1917));
    uint3 _1932 = _6085 ^ (_6085 >> uint3(16u, 16u, 16u));
    uint _1934 = _1932.y;
    uint _1936 = _1932.z;
    uint _1940 = _1932.x + (_1934 * _1936);
    uint _1949 = _1934 + (_1936 * _1940);
    uint3 _1876 = uint3(_1940, _1949, _1936 + (_1940 * _1949)) >> uint3(8u, 8u, 8u);
    float _1888 = (mad(float(_1876.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _1890 = cos(_1888);
    float _1892 = sin(_1888);
    float _1968 = float(_1660.y);
    float2 _1548 = _1472 - float2(mad(0.5f, _1968, float(_1660.x)) * 0.2886598110198974609375f, 0.25f * _1968);
    float _1980 = _1548.x;
    float _1985 = _1548.y;
    float _2010 = float(_1666.y);
    float2 _1558 = _1472 - float2(mad(0.5f, _2010, float(_1666.x)) * 0.2886598110198974609375f, 0.25f * _2010);
    float _2022 = _1558.x;
    float _2027 = _1558.y;
    float _2052 = float(_1672.y);
    float2 _1568 = _1472 - float2(mad(0.5f, _2052, float(_1672.x)) * 0.2886598110198974609375f, 0.25f * _2052);
    float _2064 = _1568.x;
    float _2069 = _1568.y;
    float _2090 = _1399.x;
    float _2095 = _1399.y;
    float _2102 = -_2090;
    float _2116 = _1401.x;
    float _2121 = _1401.y;
    float _2128 = -_2116;
    float4 _2267 = hexcTex_albedo.SampleGrad(hexcSampler, float2(mad(_1980, _1698, _1985 * _1700), mad(-_1980, _1700, _1985 * _1698)) + (float2(_1684.xy) * 5.9604644775390625e-08f), float2(mad(_2090, _1698, _2095 * _1700), mad(_2102, _1700, _2095 * _1698)), float2(mad(_2116, _1698, _2121 * _1700), mad(_2128, _1700, _2121 * _1698)));
    float4 _2277 = hexcTex_albedo.SampleGrad(hexcSampler, float2(mad(_2022, _1794, _2027 * _1796), mad(-_2022, _1796, _2027 * _1794)) + (float2(_1780.xy) * 5.9604644775390625e-08f), float2(mad(_2090, _1794, _2095 * _1796), mad(_2102, _1796, _2095 * _1794)), float2(mad(_2116, _1794, _2121 * _1796), mad(_2128, _1796, _2121 * _1794)));
    float4 _2287 = hexcTex_albedo.SampleGrad(hexcSampler, float2(mad(_2064, _1890, _2069 * _1892), mad(-_2064, _1892, _2069 * _1890)) + (float2(_1876.xy) * 5.9604644775390625e-08f), float2(mad(_2090, _1890, _2095 * _1892), mad(_2102, _1892, _2095 * _1890)), float2(mad(_2116, _1890, _2121 * _1892), mad(_2128, _1892, _2121 * _1890)));
    float3 _2336 = pow(float3(_1631 * _1635, mad(-_1620, _1635, _1632), mad(-_1619, _1635, _1632)), hexcParams_albedo_exponent.xxx);
    float3 _2343 = lerp(1.0f.xxx, max(float3(dot(_2267, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_2277, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_2287, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f))), 0.0f.xxx), hexcParams_albedo_falloffcontrast.xxx) * _2336;
    float _2351 = (_2343.x + _2343.y) + _2343.z;
    float3 _5382;
    if (_2351 > 0.0f)
    {
        _5382 = _2343 / _2351.xxx;
    }
    else
    {
        _5382 = _2336 / ((_2336.x + _2336.y) + _2336.z).xxx;
    }
    float3 _6078;
    if (hexcParams_albedo_falloff != 0.5f)
    {
        float3 _2394 = step(0.5f.xxx, _5382) * 2.0f;
        float3 _2398 = (1.0f.xxx - _2394) * 2.0f;
        float3 _2413 = mad(_2398 * 0.25f, pow(max(0.0f.xxx, mad(_5382, _2398, _2394)), (log(1.0f - hexcParams_albedo_falloff) * (-1.44269502162933349609375f)).xxx), _2394 * 0.5f);
        _6078 = _2413 / ((_2413.x + _2413.y) + _2413.z).xxx;
    }
    else
    {
        _6078 = _5382;
    }
    float2 _2575 = v_uv * hexcParams_roughness_tiling;
    float2 _2596 = ddx(_2575);
    float2 _2598 = ddy(_2575);
    float _2654 = _2575.x;
    float _2656 = floor(_2654 * 0.0357142873108386993408203125f);
    float _2658 = _2575.y;
    float _2659 = floor(_2658);
    float _2664 = mad(-28.0f, _2656, _2654);
    float _2668 = _2658 - _2659;
    float2 _2669 = float2(_2664, _2668);
    float2 _2680 = float2(mad(3.4642856121063232421875f, _2664, _2668 * (-2.0f)), 4.0f * _2668);
    float2 _2810 = floor(_2680);
    int2 _2811 = int2(_2810);
    float2 _2815 = _2680 - _2810;
    float _2816 = _2815.x;
    float _2817 = _2815.y;
    float _2828 = -((1.0f - _2816) - _2817);
    float _2829 = step(0.0f, _2828);
    float _2832 = mad(2.0f, _2829, -1.0f);
    int _2852 = int(_2829);
    int2 _2857 = _2811 + _2852.xx;
    int _2861 = 1 - _2852;
    int2 _2863 = _2811 + int2(_2852, _2861);
    int2 _2869 = _2811 + int2(_2861, _2852);
    uint _2694 = uint(int(_2659));
    uint2 _2701 = uint2((97u * uint(int(_2656))) - (2u * _2694), 4u * _2694);
    uint3 _2905 = (uint3(uint2(int2(uint2(_2857) + _2701)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2907 = _2905.y;
    uint _2909 = _2905.z;
    uint _2913 = _2905.x + (_2907 * _2909);
    uint _2922 = _2907 + (_2909 * _2913);
    uint3 _6087 = uint3(_2913, _2922, _2909 + (_2913 * _2922));
    uint3 _2937 = _6087 ^ (_6087 >> uint3(16u, 16u, 16u));
    uint _2939 = _2937.y;
    uint _2941 = _2937.z;
    uint _2945 = _2937.x + (_2939 * _2941);
    uint _2954 = _2939 + (_2941 * _2945);
    uint3 _2881 = uint3(_2945, _2954, _2941 + (_2945 * _2954)) >> uint3(8u, 8u, 8u);
    float _2893 = (mad(float(_2881.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_roughness_rotation;
    float _2895 = cos(_2893);
    float _2897 = sin(_2893);
    uint3 _3001 = (uint3(uint2(int2(uint2(_2863) + _2701)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _3003 = _3001.y;
    uint _3005 = _3001.z;
    uint _3009 = _3001.x + (_3003 * _3005);
    uint _3018 = _3003 + (_3005 * _3009);
    uint3 _6089 = uint3(_3009, _3018, _3005 + (_3009 * _3018));
    uint3 _3033 = _6089 ^ (_6089 >> uint3(16u, 16u, 16u));
    uint _3035 = _3033.y;
    uint _3037 = _3033.z;
    uint _3041 = _3033.x + (_3035 * _3037);
    uint _3050 = _3035 + (_3037 * _3041);
    uint3 _2977 = uint3(_3041, _3050, _3037 + (_3041 * _3050)) >> uint3(8u, 8u, 8u);
    float _2989 = (mad(float(_2977.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_roughness_rotation;
    float _2991 = cos(_2989);
    float _2993 = sin(_2989);
    uint3 _3097 = (uint3(uint2(int2(uint2(_2869) + _2701)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _3099 = _3097.y;
    uint _3101 = _3097.z;
    uint _3105 = _3097.x + (_3099 * _3101);
    uint _3114 = _3099 + (_3101 * _3105);
    uint3 _6091 = uint3(_3105, _3114, _3101 + (_3105 * _3114));
    uint3 _3129 = _6091 ^ (_6091 >> uint3(16u, 16u, 16u));
    uint _3131 = _3129.y;
    uint _3133 = _3129.z;
    uint _3137 = _3129.x + (_3131 * _3133);
    uint _3146 = _3131 + (_3133 * _3137);
    uint3 _3073 = uint3(_3137, _3146, _3133 + (_3137 * _3146)) >> uint3(8u, 8u, 8u);
    float _3085 = (mad(float(_3073.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_roughness_rotation;
    float _3087 = cos(_3085);
    float _3089 = sin(_3085);
    float _3165 = float(_2857.y);
    float2 _2745 = _2669 - float2(mad(0.5f, _3165, float(_2857.x)) * 0.2886598110198974609375f, 0.25f * _3165);
    float _3177 = _2745.x;
    float _3182 = _2745.y;
    float _3207 = float(_2863.y);
    float2 _2755 = _2669 - float2(mad(0.5f, _3207, float(_2863.x)) * 0.2886598110198974609375f, 0.25f * _3207);
    float _3219 = _2755.x;
    float _3224 = _2755.y;
    float _3249 = float(_2869.y);
    float2 _2765 = _2669 - float2(mad(0.5f, _3249, float(_2869.x)) * 0.2886598110198974609375f, 0.25f * _3249);
    float _3261 = _2765.x;
    float _3266 = _2765.y;
    float _3287 = _2596.x;
    float _3292 = _2596.y;
    float _3299 = -_3287;
    float _3313 = _2598.x;
    float _3318 = _2598.y;
    float _3325 = -_3313;
    float4 _3464 = hexcTex_roughness.SampleGrad(hexcSampler, float2(mad(_3177, _2895, _3182 * _2897), mad(-_3177, _2897, _3182 * _2895)) + (float2(_2881.xy) * 5.9604644775390625e-08f), float2(mad(_3287, _2895, _3292 * _2897), mad(_3299, _2897, _3292 * _2895)), float2(mad(_3313, _2895, _3318 * _2897), mad(_3325, _2897, _3318 * _2895)));
    float4 _3474 = hexcTex_roughness.SampleGrad(hexcSampler, float2(mad(_3219, _2991, _3224 * _2993), mad(-_3219, _2993, _3224 * _2991)) + (float2(_2977.xy) * 5.9604644775390625e-08f), float2(mad(_3287, _2991, _3292 * _2993), mad(_3299, _2993, _3292 * _2991)), float2(mad(_3313, _2991, _3318 * _2993), mad(_3325, _2993, _3318 * _2991)));
    float4 _3484 = hexcTex_roughness.SampleGrad(hexcSampler, float2(mad(_3261, _3087, _3266 * _3089), mad(-_3261, _3089, _3266 * _3087)) + (float2(_3073.xy) * 5.9604644775390625e-08f), float2(mad(_3287, _3087, _3292 * _3089), mad(_3299, _3089, _3292 * _3087)), float2(mad(_3313, _3087, _3318 * _3089), mad(_3325, _3089, _3318 * _3087)));
    float3 _3533 = pow(float3(_2828 * _2832, mad(-_2817, _2832, _2829), mad(-_2816, _2832, _2829)), hexcParams_roughness_exponent.xxx);
    float3 _3540 = lerp(1.0f.xxx, max(float3(_3464.x, _3474.x, _3484.x), 0.0f.xxx), hexcParams_roughness_falloffcontrast.xxx) * _3533;
    float _3548 = (_3540.x + _3540.y) + _3540.z;
    float3 _5383;
    if (_3548 > 0.0f)
    {
        _5383 = _3540 / _3548.xxx;
    }
    else
    {
        _5383 = _3533 / ((_3533.x + _3533.y) + _3533.z).xxx;
    }
    float3 _6079;
    if (hexcParams_roughness_falloff != 0.5f)
    {
        float3 _3591 = step(0.5f.xxx, _5383) * 2.0f;
        float3 _3595 = (1.0f.xxx - _3591) * 2.0f;
        float3 _3610 = mad(_3595 * 0.25f, pow(max(0.0f.xxx, mad(_5383, _3595, _3591)), (log(1.0f - hexcParams_roughness_falloff) * (-1.44269502162933349609375f)).xxx), _3591 * 0.5f);
        _6079 = _3610 / ((_3610.x + _3610.y) + _3610.z).xxx;
    }
    else
    {
        _6079 = _5383;
    }
    float _1256 = clamp((((_3464 * _6079.x) + (_3474 * _6079.y)) + (_3484 * _6079.z)).x, 0.0199999995529651641845703125f, 1.0f);
    float3 _1261 = normalize(v_normal);
    float3 _1274 = normalize(v_tangent.xyz - (_1261 * dot(_1261, v_tangent.xyz)));
    float2 _3772 = v_uv * hexcParams_normal_tiling;
    float2 _3792 = ddx(_3772);
    float2 _3794 = ddy(_3772);
    float _3850 = _3772.x;
    float _3852 = floor(_3850 * 0.0357142873108386993408203125f);
    float _3854 = _3772.y;
    float _3855 = floor(_3854);
    float _3860 = mad(-28.0f, _3852, _3850);
    float _3864 = _3854 - _3855;
    float2 _3865 = float2(_3860, _3864);
    float2 _3876 = float2(mad(3.4642856121063232421875f, _3860, _3864 * (-2.0f)), 4.0f * _3864);
    float2 _4006 = floor(_3876);
    int2 _4007 = int2(_4006);
    float2 _4011 = _3876 - _4006;
    float _4012 = _4011.x;
    float _4013 = _4011.y;
    float _4024 = -((1.0f - _4012) - _4013);
    float _4025 = step(0.0f, _4024);
    float _4028 = mad(2.0f, _4025, -1.0f);
    int _4048 = int(_4025);
    int2 _4053 = _4007 + _4048.xx;
    int _4057 = 1 - _4048;
    int2 _4059 = _4007 + int2(_4048, _4057);
    int2 _4065 = _4007 + int2(_4057, _4048);
    uint _3890 = uint(int(_3855));
    uint2 _3897 = uint2((97u * uint(int(_3852))) - (2u * _3890), 4u * _3890);
    uint3 _4101 = (uint3(uint2(int2(uint2(_4053) + _3897)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _4103 = _4101.y;
    uint _4105 = _4101.z;
    uint _4109 = _4101.x + (_4103 * _4105);
    uint _4118 = _4103 + (_4105 * _4109);
    uint3 _6093 = uint3(_4109, _4118, _4105 + (_4109 * _4118));
    uint3 _4133 = _6093 ^ (_6093 >> uint3(16u, 16u, 16u));
    uint _4135 = _4133.y;
    uint _4137 = _4133.z;
    uint _4141 = _4133.x + (_4135 * _4137);
    uint _4150 = _4135 + (_4137 * _4141);
    uint3 _4077 = uint3(_4141, _4150, _4137 + (_4141 * _4150)) >> uint3(8u, 8u, 8u);
    float _4089 = (mad(float(_4077.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _4091 = cos(_4089);
    float _4093 = sin(_4089);
    uint3 _4197 = (uint3(uint2(int2(uint2(_4059) + _3897)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _4199 = _4197.y;
    uint _4201 = _4197.z;
    uint _4205 = _4197.x + (_4199 * _4201);
    uint _4214 = _4199 + (_4201 * _4205);
    uint3 _6095 = uint3(_4205, _4214, _4201 + (_4205 * _4214));
    uint3 _4229 = _6095 ^ (_6095 >> uint3(16u, 16u, 16u));
    uint _4231 = _4229.y;
    uint _4233 = _4229.z;
    uint _4237 = _4229.x + (_4231 * _4233);
    uint _4246 = _4231 + (_4233 * _4237);
    uint3 _4173 = uint3(_4237, _4246, _4233 + (_4237 * _4246)) >> uint3(8u, 8u, 8u);
    float _4185 = (mad(float(_4173.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _4187 = cos(_4185);
    float _4189 = sin(_4185);
    uint3 _4293 = (uint3(uint2(int2(uint2(_4065) + _3897)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _4295 = _4293.y;
    uint _4297 = _4293.z;
    uint _4301 = _4293.x + (_4295 * _4297);
    uint _4310 = _4295 + (_4297 * _4301);
    uint3 _6097 = uint3(_4301, _4310, _4297 + (_4301 * _4310));
    uint3 _4325 = _6097 ^ (_6097 >> uint3(16u, 16u, 16u));
    uint _4327 = _4325.y;
    uint _4329 = _4325.z;
    uint _4333 = _4325.x + (_4327 * _4329);
    uint _4342 = _4327 + (_4329 * _4333);
    uint3 _4269 = uint3(_4333, _4342, _4329 + (_4333 * _4342)) >> uint3(8u, 8u, 8u);
    float _4281 = (mad(float(_4269.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _4283 = cos(_4281);
    float _4285 = sin(_4281);
    float _4361 = float(_4053.y);
    float2 _3941 = _3865 - float2(mad(0.5f, _4361, float(_4053.x)) * 0.2886598110198974609375f, 0.25f * _4361);
    float _4373 = _3941.x;
    float _4378 = _3941.y;
    float _4403 = float(_4059.y);
    float2 _3951 = _3865 - float2(mad(0.5f, _4403, float(_4059.x)) * 0.2886598110198974609375f, 0.25f * _4403);
    float _4415 = _3951.x;
    float _4420 = _3951.y;
    float _4445 = float(_4065.y);
    float2 _3961 = _3865 - float2(mad(0.5f, _4445, float(_4065.x)) * 0.2886598110198974609375f, 0.25f * _4445);
    float _4457 = _3961.x;
    float _4462 = _3961.y;
    float _4483 = _3792.x;
    float _4488 = _3792.y;
    float _4495 = -_4483;
    float _4509 = _3794.x;
    float _4514 = _3794.y;
    float _4521 = -_4509;
    float3 _4759 = (hexcTex_normal.SampleGrad(hexcSampler, float2(mad(_4373, _4091, _4378 * _4093), mad(-_4373, _4093, _4378 * _4091)) + (float2(_4077.xy) * 5.9604644775390625e-08f), float2(mad(_4483, _4091, _4488 * _4093), mad(_4495, _4093, _4488 * _4091)), float2(mad(_4509, _4091, _4514 * _4093), mad(_4521, _4093, _4514 * _4091))).xyz * 2.0f) - 1.0f.xxx;
    float3 _4769 = abs(_4759);
    float2 _4796 = (-float2(_4759.xy)) / max(max(_4769.z, 0.0078125f * max(_4769.x, _4769.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _4802 = _4796.x;
    float _4807 = _4796.y;
    float2 _4821 = float2(mad(_4091, _4802, -(_4093 * _4807)), mad(_4093, _4802, _4091 * _4807));
    float3 _4837 = (hexcTex_normal.SampleGrad(hexcSampler, float2(mad(_4415, _4187, _4420 * _4189), mad(-_4415, _4189, _4420 * _4187)) + (float2(_4173.xy) * 5.9604644775390625e-08f), float2(mad(_4483, _4187, _4488 * _4189), mad(_4495, _4189, _4488 * _4187)), float2(mad(_4509, _4187, _4514 * _4189), mad(_4521, _4189, _4514 * _4187))).xyz * 2.0f) - 1.0f.xxx;
    float3 _4847 = abs(_4837);
    float2 _4874 = (-float2(_4837.xy)) / max(max(_4847.z, 0.0078125f * max(_4847.x, _4847.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _4880 = _4874.x;
    float _4885 = _4874.y;
    float2 _4899 = float2(mad(_4187, _4880, -(_4189 * _4885)), mad(_4189, _4880, _4187 * _4885));
    float3 _4915 = (hexcTex_normal.SampleGrad(hexcSampler, float2(mad(_4457, _4283, _4462 * _4285), mad(-_4457, _4285, _4462 * _4283)) + (float2(_4269.xy) * 5.9604644775390625e-08f), float2(mad(_4483, _4283, _4488 * _4285), mad(_4495, _4285, _4488 * _4283)), float2(mad(_4509, _4283, _4514 * _4285), mad(_4521, _4285, _4514 * _4283))).xyz * 2.0f) - 1.0f.xxx;
    float3 _4925 = abs(_4915);
    float2 _4952 = (-float2(_4915.xy)) / max(max(_4925.z, 0.0078125f * max(_4925.x, _4925.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _4958 = _4952.x;
    float _4963 = _4952.y;
    float2 _4977 = float2(mad(_4283, _4958, -(_4285 * _4963)), mad(_4285, _4958, _4283 * _4963));
    float3 _4711 = float3(dot(_4821, _4821), dot(_4899, _4899), dot(_4977, _4977));
    float3 _4989 = pow(float3(_4024 * _4028, mad(-_4013, _4028, _4025), mad(-_4012, _4028, _4025)), hexcParams_normal_exponent.xxx);
    float3 _4996 = lerp(1.0f.xxx, max(sqrt(_4711 / (1.0f.xxx + _4711)), 0.0f.xxx), hexcParams_normal_falloffcontrast.xxx) * _4989;
    float _5004 = (_4996.x + _4996.y) + _4996.z;
    float3 _5387;
    if (_5004 > 0.0f)
    {
        _5387 = _4996 / _5004.xxx;
    }
    else
    {
        _5387 = _4989 / ((_4989.x + _4989.y) + _4989.z).xxx;
    }
    float3 _6080;
    if (hexcParams_normal_falloff != 0.5f)
    {
        float3 _5047 = step(0.5f.xxx, _5387) * 2.0f;
        float3 _5051 = (1.0f.xxx - _5047) * 2.0f;
        float3 _5066 = mad(_5051 * 0.25f, pow(max(0.0f.xxx, mad(_5387, _5051, _5047)), (log(1.0f - hexcParams_normal_falloff) * (-1.44269502162933349609375f)).xxx), _5047 * 0.5f);
        _6080 = _5066 / ((_5066.x + _5066.y) + _5066.z).xxx;
    }
    else
    {
        _6080 = _5387;
    }
    float3 _5214 = normalize(float3(-(((_4821 * _6080.x) + (_4899 * _6080.y)) + (_4977 * _6080.z)), 1.0f));
    float3 _1304 = normalize(((_1274 * _5214.x) + ((cross(_1261, _1274) * v_tangent.w) * _5214.y)) + (_1261 * _5214.z));
    float _1311 = max(dot(_1304, float3(0.408248007297515869140625f, 0.408248007297515869140625f, 0.816497027873992919921875f)), 0.0f);
    float _1324 = 2.0f / (((_1256 * _1256) * _1256) * _1256);
    o_color = float4(((((_2267 * _6078.x) + (_2277 * _6078.y)) + (_2287 * _6078.z)).xyz * (0.1500000059604644775390625f + _1311)) + (0.039999999105930328369140625f * (((pow(max(dot(_1304, float3(0.21418631076812744140625f, 0.21418631076812744140625f, 0.95302069187164306640625f)), 0.0f), _1324 - 2.0f) * (_1324 + 6.0f)) * 0.0397887341678142547607421875f) * _1311)).xxx, 1.0f);
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
