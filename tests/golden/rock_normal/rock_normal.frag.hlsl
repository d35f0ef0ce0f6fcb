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
    float3 _1285 = normalize(v_normal);
    float3 _1298 = normalize(v_tangent.xyz - (_1285 * dot(_1285, v_tangent.xyz)));
    float2 _1414 = v_uv * hexcParams_normal_tiling;
    float2 _1431 = ddx(_1414);
    float2 _1433 = ddy(_1414);
    float _1505 = _1414.x;
    float _1507 = floor(_1505 * 0.0357142873108386993408203125f);
    float _1509 = _1414.y;
    float _1510 = floor(_1509);
    float _1515 = mad(-28.0f, _1507, _1505);
    float _1519 = _1509 - _1510;
    float2 _1520 = float2(_1515, _1519);
    float2 _1531 = float2(mad(3.4642856121063232421875f, _1515, _1519 * (-2.0f)), 4.0f * _1519);
    float2 _1721 = floor(_1531);
    int2 _1722 = int2(_1721);
    float2 _1726 = _1531 - _1721;
    float _1727 = _1726.x;
    float _1728 = _1726.y;
    float _1739 = -((1.0f - _1727) - _1728);
    float _1740 = step(0.0f, _1739);
    float _1743 = mad(2.0f, _1740, -1.0f);
    float3 _1761 = float3(_1739 * _1743, mad(-_1728, _1743, _1740), mad(-_1727, _1743, _1740));
    int _1763 = int(_1740);
    int2 _1768 = _1722 + _1763.xx;
    int _1772 = 1 - _1763;
    int2 _1774 = _1722 + int2(_1763, _1772);
    int2 _1780 = _1722 + int2(_1772, _1763);
    uint _1545 = uint(int(_1510));
    uint2 _1552 = uint2((97u * uint(int(_1507))) - (2u * _1545), 4u * _1545);
    uint3 _1822 = (uint3(uint2(int2(uint2(_1768) + _1552)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1824 = _1822.y;
    uint _1826 = _1822.z;
    uint _1830 = _1822.x + (_1824 * _1826);
    uint _1839 = _1824 + (_1826 * _1830);
    uint3 _3516 = uint3(_1830, _1839, _1826 + (_1830 * _1839));
    uint3 _1854 = _3516 ^ (_3516 >> uint3(16u, 16u, 16u));
    uint _1856 = _1854.y;
    uint _1858 = _1854.z;
    uint _1862 = _1854.x + (_1856 * _1858);
    uint _1871 = _1856 + (_1858 * _1862);
    uint3 _1793 = uint3(_1862, _1871, _1858 + (_1862 * _1871)) >> uint3(8u, 8u, 8u);
    float _1805 = (mad(float(_1793.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _1809 = cos(_1805);
    float _1811 = sin(_1805);
    uint3 _1924 = (uint3(uint2(int2(uint2(_1774) + _1552)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1926 = _1924.y;
    uint _1928 = _1924.z;
    uint _1932 = _1924.x + (_1926 * _1928);
    uint _1941 = _1926 + (_1928 * _1932);
    uint3 _3518 = uint3(_1932, _1941, _1928 + (_1932 * _1941));
    uint3 _1956 = _3518 ^ (_3518 >> uint3(16u, 16u, 16u));
    uint _1958 = _1956.y;
    uint _1960 = _1956.z;
    uint _1964 = _1956.x + (_1958 * _1960);
    uint _1973 = _1958 + (_1960 * _1964);
    uint3 _1895 = uint3(_1964, _1973, _1960 + (_1964 * _1973)) >> uint3(8u, 8u, 8u);
    float _1907 = (mad(float(_1895.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _1911 = cos(_1907);
    float _1913 = sin(_1907);
    uint3 _2026 = (uint3(uint2(int2(uint2(_1780) + _1552)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2028 = _2026.y;
    uint _2030 = _2026.z;
    uint _2034 = _2026.x + (_2028 * _2030);
    uint _2043 = _2028 + (_2030 * _2034);
    uint3 _3520 = uint3(_2034, _2043, _2030 + (_2034 * _2043));
    uint3 _2058 = _3520 ^ (_3520 >> uint3(16u, 16u, 16u));
    uint _2060 = _2058.y;
    uint _2062 = _2058.z;
    uint _2066 = _2058.x + (_2060 * _2062);
    uint _2075 = _2060 + (_2062 * _2066);
    uint3 _1997 = uint3(_2066, _2075, _2062 + (_2066 * _2075)) >> uint3(8u, 8u, 8u);
    float _2009 = (mad(float(_1997.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _2013 = cos(_2009);
    float _2015 = sin(_2009);
    float _2094 = float(_1768.y);
    float2 _1599 = _1520 - float2(mad(0.5f, _2094, float(_1768.x)) * 0.2886598110198974609375f, 0.25f * _2094);
    float _2110 = float(_1774.y);
    float2 _1603 = _1520 - float2(mad(0.5f, _2110, float(_1774.x)) * 0.2886598110198974609375f, 0.25f * _2110);
    float _2126 = float(_1780.y);
    float2 _1607 = _1520 - float2(mad(0.5f, _2126, float(_1780.x)) * 0.2886598110198974609375f, 0.25f * _2126);
    float _2138 = _1599.x;
    float _2143 = _1599.y;
    float _2164 = _1603.x;
    float _2169 = _1603.y;
    float _2190 = _1607.x;
    float _2195 = _1607.y;
    float _2216 = _1431.x;
    float _2221 = _1431.y;
    float _2228 = -_2216;
    float _2242 = _1433.x;
    float _2247 = _1433.y;
    float _2254 = -_2242;
    float3 _2500 = (hexcTex_normal.SampleGrad(hexcSampler, float2(mad(_2138, _1809, _2143 * _1811), mad(-_2138, _1811, _2143 * _1809)) + (float2(_1793.xy) * 5.9604644775390625e-08f), float2(mad(_2216, _1809, _2221 * _1811), mad(_2228, _1811, _2221 * _1809)), float2(mad(_2242, _1809, _2247 * _1811), mad(_2254, _1811, _2247 * _1809))).xyz * 2.0f) - 1.0f.xxx;
    float3 _2510 = abs(_2500);
    float2 _2537 = (-float2(_2500.xy)) / max(max(_2510.z, 0.0078125f * max(_2510.x, _2510.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _2543 = _2537.x;
    float _2548 = _2537.y;
    float2 _2562 = float2(mad(_1809, _2543, -(_1811 * _2548)), mad(_1811, _2543, _1809 * _2548));
    float3 _2578 = (hexcTex_normal.SampleGrad(hexcSampler, float2(mad(_2164, _1911, _2169 * _1913), mad(-_2164, _1913, _2169 * _1911)) + (float2(_1895.xy) * 5.9604644775390625e-08f), float2(mad(_2216, _1911, _2221 * _1913), mad(_2228, _1913, _2221 * _1911)), float2(mad(_2242, _1911, _2247 * _1913), mad(_2254, _1913, _2247 * _1911))).xyz * 2.0f) - 1.0f.xxx;
    float3 _2588 = abs(_2578);
    float2 _2615 = (-float2(_2578.xy)) / max(max(_2588.z, 0.0078125f * max(_2588.x, _2588.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _2621 = _2615.x;
    float _2626 = _2615.y;
    float2 _2640 = float2(mad(_1911, _2621, -(_1913 * _2626)), mad(_1913, _2621, _1911 * _2626));
    float3 _2656 = (hexcTex_normal.SampleGrad(hexcSampler, float2(mad(_2190, _2013, _2195 * _2015), mad(-_2190, _2015, _2195 * _2013)) + (float2(_1997.xy) * 5.9604644775390625e-08f), float2(mad(_2216, _2013, _2221 * _2015), mad(_2228, _2015, _2221 * _2013)), float2(mad(_2242, _2013, _2247 * _2015), mad(_2254, _2015, _2247 * _2013))).xyz * 2.0f) - 1.0f.xxx;
    float3 _2666 = abs(_2656);
    float2 _2693 = (-float2(_2656.xy)) / max(max(_2666.z, 0.0078125f * max(_2666.x, _2666.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _2699 = _2693.x;
    float _2704 = _2693.y;
    float2 _2718 = float2(mad(_2013, _2699, -(_2015 * _2704)), mad(_2015, _2699, _2013 * _2704));
    float3 _2448 = float3(dot(_2562, _2562), dot(_2640, _2640), dot(_2718, _2718));
    float3 _2816 = _1761 * _1761;
    float3 _2834 = (_1761 * _2816) * (_2816 * _2816);
    float3 _2753 = lerp(1.0f.xxx, max(sqrt(_2448 / (1.0f.xxx + _2448)), 0.0f.xxx), hexcParams_normal_falloffcontrast.xxx) * _2834;
    float _2765 = (_2753.x + _2753.y) + _2753.z;
    float3 _3205;
    if (_2765 > 0.0f)
    {
        _3205 = _2753 / _2765.xxx;
    }
    else
    {
        _3205 = _2834 / ((_2834.x + _2834.y) + _2834.z).xxx;
    }
    float3 _3118 = normalize(float3(-(((_2562 * _3205.x) + (_2640 * _3205.y)) + (_2718 * _3205.z)), 1.0f));
    float3 _1330 = normalize(((_1298 * _3118.x) + ((cross(_1285, _1298) * v_tangent.w) * _3118.y)) + (_1285 * _3118.z));
    float _1337 = max(dot(_1330, float3(0.408248007297515869140625f, 0.408248007297515869140625f, 0.816497027873992919921875f)), 0.0f);
    o_color = float4((0.5f.xxx * (0.1500000059604644775390625f + _1337)) + (0.039999999105930328369140625f * ((pow(max(dot(_1330, float3(0.21418631076812744140625f, 0.21418631076812744140625f, 0.95302069187164306640625f)), 0.0f), 30.0f) * 1.511971950531005859375f) * _1337)).xxx, 1.0f);
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
