cbuffer HexcParams : register(b0)
{
    float2 hexcParams_albedo_tiling : packoffset(c0);
    float hexcParams_albedo_rotation : packoffset(c0.z);
    float hexcParams_albedo_falloff : packoffset(c0.w);
    float hexcParams_albedo_falloffcontrast : packoffset(c1);
    float hexcParams_albedo_exponent : packoffset(c1.y);
    float hexcParams_normal_falloffcontrast : packoffset(c1.z);
    float hexcParams_normal_exponent : packoffset(c1.w);
    float hexcParams_roughness_falloff : packoffset(c2);
    float hexcParams_roughness_falloffcontrast : packoffset(c2.y);
    float hexcParams_roughness_exponent : packoffset(c2.z);
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
    float2 _1500 = v_uv * hexcParams_albedo_tiling;
    float2 _1521 = ddx(_1500);
    float2 _1523 = ddy(_1500);
    float _1595 = _1500.x;
    float _1597 = floor(_1595 * 0.0357142873108386993408203125f);
    float _1599 = _1500.y;
    float _1600 = floor(_1599);
    float _1605 = mad(-28.0f, _1597, _1595);
    float _1609 = _1599 - _1600;
    float2 _1610 = float2(_1605, _1609);
    float2 _1621 = float2(mad(3.4642856121063232421875f, _1605, _1609 * (-2.0f)), 4.0f * _1609);
    float2 _1811 = floor(_1621);
    int2 _1812 = int2(_1811);
    float2 _1816 = _1621 - _1811;
    float _1817 = _1816.x;
    float _1818 = _1816.y;
    float _1829 = -((1.0f - _1817) - _1818);
    float _1830 = step(0.0f, _1829);
    float _1833 = mad(2.0f, _1830, -1.0f);
    float3 _1851 = float3(_1829 * _1833, mad(-_1818, _1833, _1830), mad(-_1817, _1833, _1830));
    int _1853 = int(_1830);
    int2 _1858 = _1812 + _1853.xx;
    int _1862 = 1 - _1853;
    int2 _1864 = _1812 + int2(_1853, _1862);
    int2 _1870 = _1812 + int2(_1862, _1853);
    uint _1635 = uint(int(_1600));
    uint2 _1642 = uint2((97u * uint(int(_1597))) - (2u * _1635), 4u * _1635);
    uint3 _1912 = (uint3(uint2(int2(uint2(_1858) + _1642)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1914 = _1912.y;
    uint _1916 = _1912.z;
    uint _1920 = _1912.x + (_1914 * _1916);
    uint _1929 = _1914 + (_1916 * _1920);
    uint3 _6578 = uint3(_1920, _1929, _1916 + (_1920 * _1929));
    uint3 _1944 = _6578 ^ (_6578 >> uint3(16u, 16u, 16u));
    uint _1946 = _1944.y;
    uint _1948 = _1944.z;
    uint _1952 = _1944.x + (_1946 * _1948);
    uint _1961 = _1946 + (_1948 * _1952);
    uint3 _1883 = uint3(_1952, _1961, _1948 + (_1952 * _1961)) >> uint3(8u, 8u, 8u);
    float _1895 = (mad(float(_1883.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _1899 = cos(_1895);
    float _1901 = sin(_1895);
    uint3 _2014 = (uint3(uint2(int2(uint2(_1864) + _1642)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2016 = _2014.y;
    uint _2018 = _2014.z;
    uint _2022 = _2014.x + (_2016 * _2018);
    uint _2031 = _2016 + (_2018 * _2022);
    uint3 _6580 = uint3(_2022, _2031, _2018 + (_2022 * _2031));
    uint3 _2046 = _6580 ^ (_6580 >> uint3(16u, 16u, 16u));
    uint _2048 = _2046.y;
    uint _2050 = _2046.z;
    uint _2054 = _2046.x + (_2048 * _2050);
    uint _2063 = _2048 + (_2050 * _2054);
    uint3 _1985 = uint3(_2054, _2063, _2050 + (_2054 * _2063)) >> uint3(8u, 8u, 8u);
    float _1997 = (mad(float(_1985.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _2001 = cos(_1997);
    float _2003 = sin(_1997);
    uint3 _2116 = (uint3(uint2(int2(uint2(_1870) + _1642)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2118 = _2116.y;
    uint _2120 = _2116.z;
    uint _2124 = _2116.x + (_2118 * _2120);
    uint _2133 = _2118 + (_2120 * _2124);
    uint3 _6582 = uint3(_2124, _2133, _2120 + (_2124 * _2133));
    uint3 _2148 = _6582 ^ (_6582 >> uint3(16u, 16u, 16u));
    uint _2150 = _2148.y;
    uint _2152 = _2148.z;
    uint _2156 = _2148.x + (_2150 * _2152);
    uint _2165 = _2150 + (_2152 * _2156);
    uint3 _2087 = uint3(_2156, _2165, _2152 + (_2156 * _2165)) >> uint3(8u, 8u, 8u);
    float _2099 = (mad(float(_2087.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _2103 = cos(_2099);
    float _2105 = sin(_2099);
    float _2184 = float(_1858.y);
    float2 _1689 = _1610 - float2(mad(0.5f, _2184, float(_1858.x)) * 0.2886598110198974609375f, 0.25f * _2184);
    float _2200 = float(_1864.y);
    float2 _1693 = _1610 - float2(mad(0.5f, _2200, float(_1864.x)) * 0.2886598110198974609375f, 0.25f * _2200);
    float _2216 = float(_1870.y);
    float2 _1697 = _1610 - float2(mad(0.5f, _2216, float(_1870.x)) * 0.2886598110198974609375f, 0.25f * _2216);
    float _2228 = _1689.x;
    float _2233 = _1689.y;
    float2 _1709 = float2(mad(_2228, _1899, _2233 * _1901), mad(-_2228, _1901, _2233 * _1899)) + (float2(_1883.xy) * 5.9604644775390625e-08f);
    float _2254 = _1693.x;
    float _2259 = _1693.y;
    float2 _1722 = float2(mad(_2254, _2001, _2259 * _2003), mad(-_2254, _2003, _2259 * _2001)) + (float2(_1985.xy) * 5.9604644775390625e-08f);
    float _2280 = _1697.x;
    float _2285 = _1697.y;
    float2 _1735 = float2(mad(_2280, _2103, _2285 * _2105), mad(-_2280, _2105, _2285 * _2103)) + (float2(_2087.xy) * 5.9604644775390625e-08f);
    float _2306 = _1521.x;
    float _2311 = _1521.y;
    float _2318 = -_2306;
    float _2332 = _1523.x;
    float _2337 = _1523.y;
    float _2344 = -_2332;
    float4 _2485 = hexcTex_albedo.SampleGrad(hexcSampler, _1709, float2(mad(_2306, _1899, _2311 * _1901), mad(_2318, _1901, _2311 * _1899)), float2(mad(_2332, _1899, _2337 * _1901), mad(_2344, _1901, _2337 * _1899)));
    float4 _2495 = hexcTex_albedo.SampleGrad(hexcSampler, _1722, float2(mad(_2306, _2001, _2311 * _2003), mad(_2318, _2003, _2311 * _2001)), float2(mad(_2332, _2001, _2337 * _2003), mad(_2344, _2003, _2337 * _2001)));
    float4 _2505 = hexcTex_albedo.SampleGrad(hexcSampler, _1735, float2(mad(_2306, _2103, _2311 * _2105), mad(_2318, _2105, _2311 * _2103)), float2(mad(_2332, _2103, _2337 * _2105), mad(_2344, _2105, _2337 * _2103)));
    float3 _2557 = pow(_1851, hexcParams_albedo_exponent.xxx);
    float3 _2566 = lerp(1.0f.xxx, max(float3(dot(_2485, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_2495, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_2505, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f))), 0.0f.xxx), hexcParams_albedo_falloffcontrast.xxx) * _2557;
    float _2578 = (_2566.x + _2566.y) + _2566.z;
    float3 _5844;
    if (_2578 > 0.0f)
    {
        _5844 = _2566 / _2578.xxx;
    }
    else
    {
        _5844 = _2557 / ((_2557.x + _2557.y) + _2557.z).xxx;
    }
    float3 _6576;
    if (true && (hexcParams_albedo_falloff != 0.5f))
    {
        float3 _2623 = step(0.5f.xxx, _5844) * 2.0f;
        float3 _2627 = (1.0f.xxx - _2623) * 2.0f;
        float3 _2642 = mad(_2627 * 0.25f, pow(max(0.0f.xxx, mad(_5844, _2627, _2623)), (log(1.0f - hexcParams_albedo_falloff) * (-1.44269502162933349609375f)).xxx), _2623 * 0.5f);
        _6576 = _2642 / ((_2642.x + _2642.y) + _2642.z).xxx;
    }
    else
    {
        _6576 = _5844;
    }
    float2 _2829 = ddx(_1500);
    float2 _2831 = ddy(_1500);
    float _3614 = _2829.x;
    float _3619 = _2829.y;
    float _3626 = -_3614;
    float _3640 = _2831.x;
    float _3645 = _2831.y;
    float _3652 = -_3640;
    float4 _3793 = hexcTex_roughness.SampleGrad(hexcSampler, _1709, float2(mad(_3614, _1899, _3619 * _1901), mad(_3626, _1901, _3619 * _1899)), float2(mad(_3640, _1899, _3645 * _1901), mad(_3652, _1901, _3645 * _1899)));
    float4 _3803 = hexcTex_roughness.SampleGrad(hexcSampler, _1722, float2(mad(_3614, _2001, _3619 * _2003), mad(_3626, _2003, _3619 * _2001)), float2(mad(_3640, _2001, _3645 * _2003), mad(_3652, _2003, _3645 * _2001)));
    float4 _3813 = hexcTex_roughness.SampleGrad(hexcSampler, _1735, float2(mad(_3614, _2103, _3619 * _2105), mad(_3626, _2105, _3619 * _2103)), float2(mad(_3640, _2103, _3645 * _2105), mad(_3652, _2105, _3645 * _2103)));
    float3 _3865 = pow(_1851, hexcParams_roughness_exponent.xxx);
    float3 _3874 = lerp(1.0f.xxx, max(float3(_3793.x, _3803.x, _3813.x), 0.0f.xxx), hexcParams_roughness_falloffcontrast.xxx) * _3865;
    float _3886 = (_3874.x + _3874.y) + _3874.z;
    float3 _5858;
    if (_3886 > 0.0f)
    {
        _5858 = _3874 / _3886.xxx;
    }
    else
    {
        _5858 = _3865 / ((_3865.x + _3865.y) + _3865.z).xxx;
    }
    float3 _6577;
    if (true && (hexcParams_roughness_falloff != 0.5f))
    {
        float3 _3931 = step(0.5f.xxx, _5858) * 2.0f;
        float3 _3935 = (1.0f.xxx - _3931) * 2.0f;
        float3 _3950 = mad(_3935 * 0.25f, pow(max(0.0f.xxx, mad(_5858, _3935, _3931)), (log(1.0f - hexcParams_roughness_falloff) * (-1.44269502162933349609375f)).xxx), _3931 * 0.5f);
        _6577 = _3950 / ((_3950.x + _3950.y) + _3950.z).xxx;
    }
    else
    {
        _6577 = _5858;
    }
    float _1374 = clamp((((_3793 * _6577.x) + (_3803 * _6577.y)) + (_3813 * _6577.z)).x, 0.0199999995529651641845703125f, 1.0f);
    float3 _1379 = normalize(v_normal);
    float3 _1392 = normalize(v_tangent.xyz - (_1379 * dot(_1379, v_tangent.xyz)));
    float2 _4134 = ddx(_1500);
    float2 _4136 = ddy(_1500);
    float _4919 = _4134.x;
    float _4924 = _4134.y;
    float _4931 = -_4919;
    float _4945 = _4136.x;
    float _4950 = _4136.y;
    float _4957 = -_4945;
    float3 _5199 = (hexcTex_normal.SampleGrad(hexcSampler, _1709, float2(mad(_4919, _1899, _4924 * _1901), mad(_4931, _1901, _4924 * _1899)), float2(mad(_4945, _1899, _4950 * _1901), mad(_4957, _1901, _4950 * _1899))).xyz * 2.0f) - 1.0f.xxx;
    float3 _5209 = abs(_5199);
    float2 _5236 = (-float2(_5199.xy)) / max(max(_5209.z, 0.0078125f * max(_5209.x, _5209.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _5242 = _5236.x;
    float _5247 = _5236.y;
    float2 _5261 = float2(mad(_1899, _5242, -(_1901 * _5247)), mad(_1901, _5242, _1899 * _5247));
    float3 _5277 = (hexcTex_normal.SampleGrad(hexcSampler, _1722, float2(mad(_4919, _2001, _4924 * _2003), mad(_4931, _2003, _4924 * _2001)), float2(mad(_4945, _2001, _4950 * _2003), mad(_4957, _2003, _4950 * _2001))).xyz * 2.0f) - 1.0f.xxx;
    float3 _5287 = abs(_5277);
    float2 _5314 = (-float2(_5277.xy)) / max(max(_5287.z, 0.0078125f * max(_5287.x, _5287.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _5320 = _5314.x;
    float _5325 = _5314.y;
    float2 _5339 = float2(mad(_2001, _5320, -(_2003 * _5325)), mad(_2003, _5320, _2001 * _5325));
    float3 _5355 = (hexcTex_normal.SampleGrad(hexcSampler, _1735, float2(mad(_4919, _2103, _4924 * _2105), mad(_4931, _2105, _4924 * _2103)), float2(mad(_4945, _2103, _4950 * _2105), mad(_4957, _2105, _4950 * _2103))).xyz * 2.0f) - 1.0f.xxx;
    float3 _5365 = abs(_5355);
    float2 _5392 = (-float2(_5355.xy)) / max(max(_5365.z, 0.0078125f * max(_5365.x, _5365.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _5398 = _5392.x;
    float _5403 = _5392.y;
    float2 _5417 = float2(mad(_2103, _5398, -(_2105 * _5403)), mad(_2105, _5398, _2103 * _5403));
    float3 _5149 = float3(dot(_5261, _5261), dot(_5339, _5339), dot(_5417, _5417));
    float3 _5430 = pow(_1851, hexcParams_normal_exponent.xxx);
    float3 _5439 = lerp(1.0f.xxx, max(sqrt(_5149 / (1.0f.xxx + _5149)), 0.0f.xxx), hexcParams_normal_falloffcontrast.xxx) * _5430;
    float _5451 = (_5439.x + _5439.y) + _5439.z;
    float3 _5875;
    if (_5451 > 0.0f)
    {
        _5875 = _5439 / _5451.xxx;
    }
    else
    {
        _5875 = _5430 / ((_5430.x + _5430.y) + _5430.z).xxx;
    }
    float3 _5663 = normalize(float3(-(((_5261 * _5875.x) + (_5339 * _5875.y)) + (_5417 * _5875.z)), 1.0f));
    float3 _1422 = normalize(((_1392 * _5663.x) + ((cross(_1379, _1392) * v_tangent.w) * _5663.y)) + (_1379 * _5663.z));
    float _1429 = max(dot(_1422, float3(0.408248007297515869140625f, 0.408248007297515869140625f, 0.816497027873992919921875f)), 0.0f);
    float _1442 = 2.0f / (((_1374 * _1374) * _1374) * _1374);
    o_color = float4(((((_2485 * _6576.x) + (_2495 * _6576.y)) + (_2505 * _6576.z)).xyz * (0.1500000059604644775390625f + _1429)) + (0.039999999105930328369140625f * (((pow(max(dot(_1422, float3(0.21418631076812744140625f, 0.21418631076812744140625f, 0.95302069187164306640625f)), 0.0f), _1442 - 2.0f) * (_1442 + 6.0f)) * 0.0397887341678142547607421875f) * _1429)).xxx, 1.0f);
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
