cbuffer HexcParams : register(b0)
{
    float2 hexcParams_normal_tiling : packoffset(c0);
    float hexcParams_normal_rotation : packoffset(c0.z);
    float hexcParams_normal_falloffcontrast : packoffset(c0.w);
};

Texture2D<float4> hexcTex_normal : register(t0);
SamplerState hexcSampler : register(s0);

static float3 v_normal;
static float4 v_tangent;
static float2 v_uv;
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
    float3 _1479 = normalize(v_normal);
    float3 _1492 = normalize(v_tangent.xyz - (_1479 * dot(_1479, v_tangent.xyz)));
    float2 _1601 = v_uv * hexcParams_normal_tiling;
    float2 _1603 = ddx(_1601);
    float2 _1605 = ddy(_1601);
    float _1707 = _1601.x;
    float _1709 = floor(_1707 * 0.0357142873108386993408203125f);
    float _1711 = _1601.y;
    float _1712 = floor(_1711);
    float _1717 = mad(-28.0f, _1709, _1707);
    float _1721 = _1711 - _1712;
    float2 _1722 = float2(_1717, _1721);
    float2 _1733 = float2(mad(3.4642856121063232421875f, _1717, _1721 * (-2.0f)), 4.0f * _1721);
    float2 _1852 = floor(_1733);
    int2 _1853 = int2(_1852);
    float2 _1857 = _1733 - _1852;
    float _1858 = _1857.x;
    float _1859 = _1857.y;
    float _1870 = -((1.0f - _1858) - _1859);
    float _1871 = step(0.0f, _1870);
    float _1874 = mad(2.0f, _1871, -1.0f);
    float3 _1892 = float3(_1870 * _1874, mad(-_1859, _1874, _1871), mad(-_1858, _1874, _1871));
    int _1894 = int(_1871);
    int2 _1899 = _1853 + _1894.xx;
    int _1903 = 1 - _1894;
    int2 _1905 = _1853 + int2(_1894, _1903);
    int2 _1911 = _1853 + int2(_1903, _1894);
    uint2 _1747 = uint2(int2(int(_1709), int(_1712)));
    uint _1753 = _1747.y;
    uint2 _1759 = uint2((97u * _1747.x) - (2u * _1753), 4u * _1753);
    float _1983 = float(_1899.y);
    float2 _1787 = _1722 - float2(mad(0.5f, _1983, float(_1899.x)) * 0.2886598110198974609375f, 0.25f * _1983);
    uint3 _2166 = (uint3(uint2(int2(uint2(_1899) + _1759)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2168 = _2166.y;
    uint _2170 = _2166.z;
    uint _2174 = _2166.x + (_2168 * _2170);
    uint _2183 = _2168 + (_2170 * _2174);
    uint3 _4711 = uint3(_2174, _2183, _2170 + (_2174 * _2183));
    uint3 _2198 = _4711 ^ (_4711 >> uint3(16u, 16u, 16u));
    uint _2200 = _2198.y;
    uint _2202 = _2198.z;
    uint _2206 = _2198.x + (_2200 * _2202);
    uint _2215 = _2200 + (_2202 * _2206);
    float3 _2071 = float3(uint3(_2206, _2215, _2202 + (_2206 * _2215)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2081 = (mad(_2071.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _2153 = cos(_2081);
    float _2155 = sin(_2081);
    float _2297 = _1787.x;
    float _2302 = _1787.y;
    float _2323 = _1603.x;
    float _2328 = _1603.y;
    float _2335 = -_2323;
    float _2349 = _1605.x;
    float _2354 = _1605.y;
    float _2361 = -_2349;
    float _2379 = float(_1905.y);
    float2 _1807 = _1722 - float2(mad(0.5f, _2379, float(_1905.x)) * 0.2886598110198974609375f, 0.25f * _2379);
    uint3 _2562 = (uint3(uint2(int2(uint2(_1905) + _1759)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2564 = _2562.y;
    uint _2566 = _2562.z;
    uint _2570 = _2562.x + (_2564 * _2566);
    uint _2579 = _2564 + (_2566 * _2570);
    uint3 _4717 = uint3(_2570, _2579, _2566 + (_2570 * _2579));
    uint3 _2594 = _4717 ^ (_4717 >> uint3(16u, 16u, 16u));
    uint _2596 = _2594.y;
    uint _2598 = _2594.z;
    uint _2602 = _2594.x + (_2596 * _2598);
    uint _2611 = _2596 + (_2598 * _2602);
    float3 _2467 = float3(uint3(_2602, _2611, _2598 + (_2602 * _2611)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2477 = (mad(_2467.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _2549 = cos(_2477);
    float _2551 = sin(_2477);
    float _2693 = _1807.x;
    float _2698 = _1807.y;
    float _2775 = float(_1911.y);
    float2 _1827 = _1722 - float2(mad(0.5f, _2775, float(_1911.x)) * 0.2886598110198974609375f, 0.25f * _2775);
    uint3 _2958 = (uint3(uint2(int2(uint2(_1911) + _1759)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2960 = _2958.y;
    uint _2962 = _2958.z;
    uint _2966 = _2958.x + (_2960 * _2962);
    uint _2975 = _2960 + (_2962 * _2966);
    uint3 _4722 = uint3(_2966, _2975, _2962 + (_2966 * _2975));
    uint3 _2990 = _4722 ^ (_4722 >> uint3(16u, 16u, 16u));
    uint _2992 = _2990.y;
    uint _2994 = _2990.z;
    uint _2998 = _2990.x + (_2992 * _2994);
    uint _3007 = _2992 + (_2994 * _2998);
    float3 _2863 = float3(uint3(_2998, _3007, _2994 + (_2998 * _3007)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2873 = (mad(_2863.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _2945 = cos(_2873);
    float _2947 = sin(_2873);
    float _3089 = _1827.x;
    float _3094 = _1827.y;
    float3 _3317 = (hexcTex_normal.SampleGrad(hexcSampler, (float2(mad(_2297, _2153, _2302 * _2155), mad(-_2297, _2155, _2302 * _2153)) * 1.0f) + _2071.xy, float2(mad(_2323, _2153, _2328 * _2155), mad(_2335, _2155, _2328 * _2153)) * 1.0f, float2(mad(_2349, _2153, _2354 * _2155), mad(_2361, _2155, _2354 * _2153)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _3327 = abs(_3317);
    float2 _3354 = (-float2(_3317.xy)) / max(max(_3327.z, 0.0078125f * max(_3327.x, _3327.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _3360 = _3354.x;
    float _3365 = _3354.y;
    float2 _3214 = float2(mad(_2153, _3360, -(_2155 * _3365)), mad(_2155, _3360, _2153 * _3365)) * 1.0f;
    float3 _3395 = (hexcTex_normal.SampleGrad(hexcSampler, (float2(mad(_2693, _2549, _2698 * _2551), mad(-_2693, _2551, _2698 * _2549)) * 1.0f) + _2467.xy, float2(mad(_2323, _2549, _2328 * _2551), mad(_2335, _2551, _2328 * _2549)) * 1.0f, float2(mad(_2349, _2549, _2354 * _2551), mad(_2361, _2551, _2354 * _2549)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _3405 = abs(_3395);
    float2 _3432 = (-float2(_3395.xy)) / max(max(_3405.z, 0.0078125f * max(_3405.x, _3405.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _3438 = _3432.x;
    float _3443 = _3432.y;
    float2 _3228 = float2(mad(_2549, _3438, -(_2551 * _3443)), mad(_2551, _3438, _2549 * _3443)) * 1.0f;
    float3 _3473 = (hexcTex_normal.SampleGrad(hexcSampler, (float2(mad(_3089, _2945, _3094 * _2947), mad(-_3089, _2947, _3094 * _2945)) * 1.0f) + _2863.xy, float2(mad(_2323, _2945, _2328 * _2947), mad(_2335, _2947, _2328 * _2945)) * 1.0f, float2(mad(_2349, _2945, _2354 * _2947), mad(_2361, _2947, _2354 * _2945)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _3483 = abs(_3473);
    float2 _3510 = (-float2(_3473.xy)) / max(max(_3483.z, 0.0078125f * max(_3483.x, _3483.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _3516 = _3510.x;
    float _3521 = _3510.y;
    float2 _3246 = float2(mad(_2945, _3516, -(_2947 * _3521)), mad(_2947, _3516, _2945 * _3521)) * 1.0f;
    float3 _3259 = float3(dot(_3214, _3214), dot(_3228, _3228), dot(_3246, _3246));
    float3 _3646 = _1892 * _1892;
    float3 _3664 = (_1892 * _3646) * (_3646 * _3646);
    float3 _3575 = lerp(1.0f.xxx, max(sqrt(_3259 / (1.0f.xxx + _3259)), 0.0f.xxx), hexcParams_normal_falloffcontrast.xxx) * _3664;
    float _3587 = (_3575.x + _3575.y) + _3575.z;
    float3 _4631;
    if (_3587 > 0.0f)
    {
        _4631 = _3575 / _3587.xxx;
    }
    else
    {
        _4631 = _3664 / ((_3664.x + _3664.y) + _3664.z).xxx;
    }
    float3 _3929 = normalize(float3(-(((_3214 * _4631.x) + (_3228 * _4631.y)) + (_3246 * _4631.z)), 1.0f));
    float3 _1524 = normalize(((_1492 * _3929.x) + ((cross(_1479, _1492) * v_tangent.w) * _3929.y)) + (_1479 * _3929.z));
    float _1531 = max(dot(_1524, float3(0.408248007297515869140625f, 0.408248007297515869140625f, 0.816497027873992919921875f)), 0.0f);
    o_color = float4((0.5f.xxx * (0.1500000059604644775390625f + _1531)) + (0.039999999105930328369140625f * ((pow(max(dot(_1524, float3(0.21418631076812744140625f, 0.21418631076812744140625f, 0.95302069187164306640625f)), 0.0f), 30.0f) * 1.511971950531005859375f) * _1531)).xxx, 1.0f);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    v_normal = stage_input.v_normal;
    v_tangent = stage_input.v_tangent;
    v_uv = stage_input.v_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.o_color = o_color;
    return stage_output;
}
