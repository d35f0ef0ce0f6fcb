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
    float3 _1433 = normalize(v_normal);
    float3 _1446 = normalize(v_tangent.xyz - (_1433 * dot(_1433, v_tangent.xyz)));
    float2 _1564 = v_uv * hexcParams_normal_tiling;
    float2 _1583 = ddx(_1564);
    float2 _1585 = ddy(_1564);
    float _1668 = _1564.x;
    float _1670 = floor(_1668 * 0.0357142873108386993408203125f);
    float _1672 = _1564.y;
    float _1673 = floor(_1672);
    float _1678 = mad(-28.0f, _1670, _1668);
    float _1682 = _1672 - _1673;
    float2 _1683 = float2(_1678, _1682);
    float2 _1694 = float2(mad(3.4642856121063232421875f, _1678, _1682 * (-2.0f)), 4.0f * _1682);
    float2 _1923 = floor(_1694);
    int2 _1924 = int2(_1923);
    float2 _1928 = _1694 - _1923;
    float _1929 = _1928.x;
    float _1930 = _1928.y;
    float _1941 = -((1.0f - _1929) - _1930);
    float _1942 = step(0.0f, _1941);
    float _1945 = mad(2.0f, _1942, -1.0f);
    float3 _1963 = float3(_1941 * _1945, mad(-_1930, _1945, _1942), mad(-_1929, _1945, _1942));
    int _1965 = int(_1942);
    int2 _1970 = _1924 + _1965.xx;
    int _1974 = 1 - _1965;
    int2 _1976 = _1924 + int2(_1965, _1974);
    int2 _1982 = _1924 + int2(_1974, _1965);
    uint _1708 = uint(int(_1673));
    uint2 _1715 = uint2((97u * uint(int(_1670))) - (2u * _1708), 4u * _1708);
    uint3 _2093 = (uint3(uint2(int2(uint2(_1970) + _1715)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2095 = _2093.y;
    uint _2097 = _2093.z;
    uint _2101 = _2093.x + (_2095 * _2097);
    uint _2110 = _2095 + (_2097 * _2101);
    uint3 _4364 = uint3(_2101, _2110, _2097 + (_2101 * _2110));
    uint3 _2125 = _4364 ^ (_4364 >> uint3(16u, 16u, 16u));
    uint _2127 = _2125.y;
    uint _2129 = _2125.z;
    uint _2133 = _2125.x + (_2127 * _2129);
    uint _2142 = _2127 + (_2129 * _2133);
    float3 _2002 = float3(uint3(_2133, _2142, _2129 + (_2133 * _2142)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2011 = (mad(_2002.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _2080 = cos(_2011);
    float _2082 = sin(_2011);
    uint3 _2331 = (uint3(uint2(int2(uint2(_1976) + _1715)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2333 = _2331.y;
    uint _2335 = _2331.z;
    uint _2339 = _2331.x + (_2333 * _2335);
    uint _2348 = _2333 + (_2335 * _2339);
    uint3 _4367 = uint3(_2339, _2348, _2335 + (_2339 * _2348));
    uint3 _2363 = _4367 ^ (_4367 >> uint3(16u, 16u, 16u));
    uint _2365 = _2363.y;
    uint _2367 = _2363.z;
    uint _2371 = _2363.x + (_2365 * _2367);
    uint _2380 = _2365 + (_2367 * _2371);
    float3 _2240 = float3(uint3(_2371, _2380, _2367 + (_2371 * _2380)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2249 = (mad(_2240.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _2318 = cos(_2249);
    float _2320 = sin(_2249);
    uint3 _2569 = (uint3(uint2(int2(uint2(_1982) + _1715)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2571 = _2569.y;
    uint _2573 = _2569.z;
    uint _2577 = _2569.x + (_2571 * _2573);
    uint _2586 = _2571 + (_2573 * _2577);
    uint3 _4370 = uint3(_2577, _2586, _2573 + (_2577 * _2586));
    uint3 _2601 = _4370 ^ (_4370 >> uint3(16u, 16u, 16u));
    uint _2603 = _2601.y;
    uint _2605 = _2601.z;
    uint _2609 = _2601.x + (_2603 * _2605);
    uint _2618 = _2603 + (_2605 * _2609);
    float3 _2478 = float3(uint3(_2609, _2618, _2605 + (_2609 * _2618)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2487 = (mad(_2478.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _2556 = cos(_2487);
    float _2558 = sin(_2487);
    float _2704 = float(_1970.y);
    float2 _1774 = _1683 - float2(mad(0.5f, _2704, float(_1970.x)) * 0.2886598110198974609375f, 0.25f * _2704);
    float _2720 = float(_1976.y);
    float2 _1778 = _1683 - float2(mad(0.5f, _2720, float(_1976.x)) * 0.2886598110198974609375f, 0.25f * _2720);
    float _2736 = float(_1982.y);
    float2 _1782 = _1683 - float2(mad(0.5f, _2736, float(_1982.x)) * 0.2886598110198974609375f, 0.25f * _2736);
    float _2748 = _1774.x;
    float _2753 = _1774.y;
    float _2774 = _1778.x;
    float _2779 = _1778.y;
    float _2800 = _1782.x;
    float _2805 = _1782.y;
    float _2826 = _1583.x;
    float _2831 = _1583.y;
    float _2838 = -_2826;
    float _2852 = _1585.x;
    float _2857 = _1585.y;
    float _2864 = -_2852;
    float3 _3119 = (hexcTex_normal.SampleGrad(hexcSampler, (float2(mad(_2748, _2080, _2753 * _2082), mad(-_2748, _2082, _2753 * _2080)) * 1.0f) + _2002.xy, float2(mad(_2826, _2080, _2831 * _2082), mad(_2838, _2082, _2831 * _2080)) * 1.0f, float2(mad(_2852, _2080, _2857 * _2082), mad(_2864, _2082, _2857 * _2080)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _3129 = abs(_3119);
    float2 _3156 = (-float2(_3119.xy)) / max(max(_3129.z, 0.0078125f * max(_3129.x, _3129.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _3162 = _3156.x;
    float _3167 = _3156.y;
    float2 _3029 = float2(mad(_2080, _3162, -(_2082 * _3167)), mad(_2082, _3162, _2080 * _3167)) * 1.0f;
    float3 _3197 = (hexcTex_normal.SampleGrad(hexcSampler, (float2(mad(_2774, _2318, _2779 * _2320), mad(-_2774, _2320, _2779 * _2318)) * 1.0f) + _2240.xy, float2(mad(_2826, _2318, _2831 * _2320), mad(_2838, _2320, _2831 * _2318)) * 1.0f, float2(mad(_2852, _2318, _2857 * _2320), mad(_2864, _2320, _2857 * _2318)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _3207 = abs(_3197);
    float2 _3234 = (-float2(_3197.xy)) / max(max(_3207.z, 0.0078125f * max(_3207.x, _3207.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _3240 = _3234.x;
    float _3245 = _3234.y;
    float2 _3043 = float2(mad(_2318, _3240, -(_2320 * _3245)), mad(_2320, _3240, _2318 * _3245)) * 1.0f;
    float3 _3275 = (hexcTex_normal.SampleGrad(hexcSampler, (float2(mad(_2800, _2556, _2805 * _2558), mad(-_2800, _2558, _2805 * _2556)) * 1.0f) + _2478.xy, float2(mad(_2826, _2556, _2831 * _2558), mad(_2838, _2558, _2831 * _2556)) * 1.0f, float2(mad(_2852, _2556, _2857 * _2558), mad(_2864, _2558, _2857 * _2556)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _3285 = abs(_3275);
    float2 _3312 = (-float2(_3275.xy)) / max(max(_3285.z, 0.0078125f * max(_3285.x, _3285.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _3318 = _3312.x;
    float _3323 = _3312.y;
    float2 _3057 = float2(mad(_2556, _3318, -(_2558 * _3323)), mad(_2558, _3318, _2556 * _3323)) * 1.0f;
    float3 _3067 = float3(dot(_3029, _3029), dot(_3043, _3043), dot(_3057, _3057));
    float3 _3435 = _1963 * _1963;
    float3 _3453 = (_1963 * _3435) * (_3435 * _3435);
    float3 _3372 = lerp(1.0f.xxx, max(sqrt(_3067 / (1.0f.xxx + _3067)), 0.0f.xxx), hexcParams_normal_falloffcontrast.xxx) * _3453;
    float _3384 = (_3372.x + _3372.y) + _3372.z;
    float3 _4297;
    if (_3384 > 0.0f)
    {
        _4297 = _3372 / _3384.xxx;
    }
    else
    {
        _4297 = _3453 / ((_3453.x + _3453.y) + _3453.z).xxx;
    }
    float3 _3737 = normalize(float3(-(((_3029 * _4297.x) + (_3043 * _4297.y)) + (_3057 * _4297.z)), 1.0f));
    float3 _1478 = normalize(((_1446 * _3737.x) + ((cross(_1433, _1446) * v_tangent.w) * _3737.y)) + (_1433 * _3737.z));
    float _1485 = max(dot(_1478, float3(0.408248007297515869140625f, 0.408248007297515869140625f, 0.816497027873992919921875f)), 0.0f);
    o_color = float4((0.5f.xxx * (0.1500000059604644775390625f + _1485)) + (0.039999999105930328369140625f * ((pow(max(dot(_1478, float3(0.21418631076812744140625f, 0.21418631076812744140625f, 0.95302069187164306640625f)), 0.0f), 30.0f) * 1.511971950531005859375f) * _1485)).xxx, 1.0f);
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
