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
    float3 _1461 = normalize(v_normal);
    float3 _1474 = normalize(v_tangent.xyz - (_1461 * dot(_1461, v_tangent.xyz)));
    float2 _1583 = v_uv * hexcParams_normal_tiling;
    float2 _1585 = ddx(_1583);
    float2 _1587 = ddy(_1583);
    float _1689 = _1583.x;
    float _1691 = floor(_1689 * 0.0357142873108386993408203125f);
    float _1693 = _1583.y;
    float _1694 = floor(_1693);
    float _1699 = mad(-28.0f, _1691, _1689);
    float _1703 = _1693 - _1694;
    float2 _1704 = float2(_1699, _1703);
    float2 _1715 = float2(mad(3.4642856121063232421875f, _1699, _1703 * (-2.0f)), 4.0f * _1703);
    float2 _1834 = floor(_1715);
    int2 _1835 = int2(_1834);
    float2 _1839 = _1715 - _1834;
    float _1840 = _1839.x;
    float _1841 = _1839.y;
    float _1852 = -((1.0f - _1840) - _1841);
    float _1853 = step(0.0f, _1852);
    float _1856 = mad(2.0f, _1853, -1.0f);
    float3 _1874 = float3(_1852 * _1856, mad(-_1841, _1856, _1853), mad(-_1840, _1856, _1853));
    int _1876 = int(_1853);
    int2 _1881 = _1835 + _1876.xx;
    int _1885 = 1 - _1876;
    int2 _1887 = _1835 + int2(_1876, _1885);
    int2 _1893 = _1835 + int2(_1885, _1876);
    uint2 _1729 = uint2(int2(int(_1691), int(_1694)));
    uint _1735 = _1729.y;
    uint2 _1741 = uint2((97u * _1729.x) - (2u * _1735), 4u * _1735);
    float _1965 = float(_1881.y);
    float2 _1769 = _1704 - float2(mad(0.5f, _1965, float(_1881.x)) * 0.2886598110198974609375f, 0.25f * _1965);
    uint3 _2148 = (uint3(uint2(int2(uint2(_1881) + _1741)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2150 = _2148.y;
    uint _2152 = _2148.z;
    uint _2156 = _2148.x + (_2150 * _2152);
    uint _2165 = _2150 + (_2152 * _2156);
    uint3 _4717 = uint3(_2156, _2165, _2152 + (_2156 * _2165));
    uint3 _2180 = _4717 ^ (_4717 >> uint3(16u, 16u, 16u));
    uint _2182 = _2180.y;
    uint _2184 = _2180.z;
    uint _2188 = _2180.x + (_2182 * _2184);
    uint _2197 = _2182 + (_2184 * _2188);
    float3 _2053 = float3(uint3(_2188, _2197, _2184 + (_2188 * _2197)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2063 = (mad(_2053.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _2135 = cos(_2063);
    float _2137 = sin(_2063);
    float _2279 = _1769.x;
    float _2284 = _1769.y;
    float _2305 = _1585.x;
    float _2310 = _1585.y;
    float _2317 = -_2305;
    float _2331 = _1587.x;
    float _2336 = _1587.y;
    float _2343 = -_2331;
    float _2361 = float(_1887.y);
    float2 _1789 = _1704 - float2(mad(0.5f, _2361, float(_1887.x)) * 0.2886598110198974609375f, 0.25f * _2361);
    uint3 _2544 = (uint3(uint2(int2(uint2(_1887) + _1741)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2546 = _2544.y;
    uint _2548 = _2544.z;
    uint _2552 = _2544.x + (_2546 * _2548);
    uint _2561 = _2546 + (_2548 * _2552);
    uint3 _4723 = uint3(_2552, _2561, _2548 + (_2552 * _2561));
    uint3 _2576 = _4723 ^ (_4723 >> uint3(16u, 16u, 16u));
    uint _2578 = _2576.y;
    uint _2580 = _2576.z;
    uint _2584 = _2576.x + (_2578 * _2580);
    uint _2593 = _2578 + (_2580 * _2584);
    float3 _2449 = float3(uint3(_2584, _2593, _2580 + (_2584 * _2593)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2459 = (mad(_2449.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _2531 = cos(_2459);
    float _2533 = sin(_2459);
    float _2675 = _1789.x;
    float _2680 = _1789.y;
    float _2757 = float(_1893.y);
    float2 _1809 = _1704 - float2(mad(0.5f, _2757, float(_1893.x)) * 0.2886598110198974609375f, 0.25f * _2757);
    uint3 _2940 = (uint3(uint2(int2(uint2(_1893) + _1741)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _2942 = _2940.y;
    uint _2944 = _2940.z;
    uint _2948 = _2940.x + (_2942 * _2944);
    uint _2957 = _2942 + (_2944 * _2948);
    uint3 _4728 = uint3(_2948, _2957, _2944 + (_2948 * _2957));
    uint3 _2972 = _4728 ^ (_4728 >> uint3(16u, 16u, 16u));
    uint _2974 = _2972.y;
    uint _2976 = _2972.z;
    uint _2980 = _2972.x + (_2974 * _2976);
    uint _2989 = _2974 + (_2976 * _2980);
    float3 _2845 = float3(uint3(_2980, _2989, _2976 + (_2980 * _2989)) >> uint3(8u, 8u, 8u)) * 5.9604644775390625e-08f;
    float _2855 = (mad(_2845.z, 2.0f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _2927 = cos(_2855);
    float _2929 = sin(_2855);
    float _3071 = _1809.x;
    float _3076 = _1809.y;
    float3 _3299 = (hexcTex_normal.SampleGrad(hexcSampler, (float2(mad(_2279, _2135, _2284 * _2137), mad(-_2279, _2137, _2284 * _2135)) * 1.0f) + _2053.xy, float2(mad(_2305, _2135, _2310 * _2137), mad(_2317, _2137, _2310 * _2135)) * 1.0f, float2(mad(_2331, _2135, _2336 * _2137), mad(_2343, _2137, _2336 * _2135)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _3309 = abs(_3299);
    float2 _3336 = (-float2(_3299.xy)) / max(max(_3309.z, 0.0078125f * max(_3309.x, _3309.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _3347 = _3336.x;
    float _3352 = _3336.y;
    float2 _3196 = float2(mad(_3347, _2135, _3352 * _2137), mad(-_3347, _2137, _3352 * _2135)) * 1.0f;
    float3 _3385 = (hexcTex_normal.SampleGrad(hexcSampler, (float2(mad(_2675, _2531, _2680 * _2533), mad(-_2675, _2533, _2680 * _2531)) * 1.0f) + _2449.xy, float2(mad(_2305, _2531, _2310 * _2533), mad(_2317, _2533, _2310 * _2531)) * 1.0f, float2(mad(_2331, _2531, _2336 * _2533), mad(_2343, _2533, _2336 * _2531)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _3395 = abs(_3385);
    float2 _3422 = (-float2(_3385.xy)) / max(max(_3395.z, 0.0078125f * max(_3395.x, _3395.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _3433 = _3422.x;
    float _3438 = _3422.y;
    float2 _3210 = float2(mad(_3433, _2531, _3438 * _2533), mad(-_3433, _2533, _3438 * _2531)) * 1.0f;
    float3 _3471 = (hexcTex_normal.SampleGrad(hexcSampler, (float2(mad(_3071, _2927, _3076 * _2929), mad(-_3071, _2929, _3076 * _2927)) * 1.0f) + _2845.xy, float2(mad(_2305, _2927, _2310 * _2929), mad(_2317, _2929, _2310 * _2927)) * 1.0f, float2(mad(_2331, _2927, _2336 * _2929), mad(_2343, _2929, _2336 * _2927)) * 1.0f).xyz * 2.0f) - 1.0f.xxx;
    float3 _3481 = abs(_3471);
    float2 _3508 = (-float2(_3471.xy)) / max(max(_3481.z, 0.0078125f * max(_3481.x, _3481.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _3519 = _3508.x;
    float _3524 = _3508.y;
    float2 _3228 = float2(mad(_3519, _2927, _3524 * _2929), mad(-_3519, _2929, _3524 * _2927)) * 1.0f;
    float3 _3241 = float3(dot(_3196, _3196), dot(_3210, _3210), dot(_3228, _3228));
    float3 _3652 = _1874 * _1874;
    float3 _3670 = (_1874 * _3652) * (_3652 * _3652);
    float3 _3581 = lerp(1.0f.xxx, max(sqrt(_3241 / (1.0f.xxx + _3241)), 0.0f.xxx), hexcParams_normal_falloffcontrast.xxx) * _3670;
    float _3593 = (_3581.x + _3581.y) + _3581.z;
    float3 _4637;
    if (_3593 > 0.0f)
    {
        _4637 = _3581 / _3593.xxx;
    }
    else
    {
        _4637 = _3670 / ((_3670.x + _3670.y) + _3670.z).xxx;
    }
    float3 _3935 = normalize(float3(-(((_3196 * _4637.x) + (_3210 * _4637.y)) + (_3228 * _4637.z)), 1.0f));
    float3 _1506 = normalize(((_1474 * _3935.x) - ((cross(_1461, _1474) * v_tangent.w) * _3935.y)) + (_1461 * _3935.z));
    float _1513 = max(dot(_1506, float3(0.408248007297515869140625f, 0.408248007297515869140625f, 0.816497027873992919921875f)), 0.0f);
    o_color = float4((0.5f.xxx * (0.1500000059604644775390625f + _1513)) + (0.039999999105930328369140625f * ((pow(max(dot(_1506, float3(0.21418631076812744140625f, 0.21418631076812744140625f, 0.95302069187164306640625f)), 0.0f), 30.0f) * 1.511971950531005859375f) * _1513)).xxx, 1.0f);
}

SPIRV_Cross_Output rock_normal_frag(SPIRV_Cross_Input stage_input)
{
    v_normal = stage_input.v_normal;
    v_tangent = stage_input.v_tangent;
    v_uv = stage_input.v_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.o_color = o_color;
    return stage_output;
}
