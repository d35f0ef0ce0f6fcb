cbuffer HexcParams : register(b0)
{
    float2 hexcParams_normal_tiling : packoffset(c0);
    float hexcParams_normal_rotation : packoffset(c0.z);
    float hexcParams_normal_falloff : packoffset(c0.w);
    float hexcParams_normal_falloffcontrast : packoffset(c1);
    float hexcParams_normal_exponent : packoffset(c1.y);
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
    float3 _1065 = normalize(v_normal);
    float3 _1078 = normalize(v_tangent.xyz - (_1065 * dot(_1065, v_tangent.xyz)));
    float2 _1189 = v_uv * hexcParams_normal_tiling;
    float2 _1209 = ddx(_1189);
    float2 _1211 = ddy(_1189);
    float _1267 = _1189.x;
    float _1269 = floor(_1267 * 0.0357142873108386993408203125f);
    float _1271 = _1189.y;
    float _1272 = floor(_1271);
    float _1277 = mad(-28.0f, _1269, _1267);
    float _1281 = _1271 - _1272;
    float2 _1282 = float2(_1277, _1281);
    float2 _1293 = float2(mad(3.4642856121063232421875f, _1277, _1281 * (-2.0f)), 4.0f * _1281);
    float2 _1423 = floor(_1293);
    int2 _1424 = int2(_1423);
    float2 _1428 = _1293 - _1423;
    float _1429 = _1428.x;
    float _1430 = _1428.y;
    float _1441 = -((1.0f - _1429) - _1430);
    float _1442 = step(0.0f, _1441);
    float _1445 = mad(2.0f, _1442, -1.0f);
    int _1465 = int(_1442);
    int2 _1470 = _1424 + _1465.xx;
    int _1474 = 1 - _1465;
    int2 _1476 = _1424 + int2(_1465, _1474);
    int2 _1482 = _1424 + int2(_1474, _1465);
    uint _1307 = uint(int(_1272));
    uint2 _1314 = uint2((97u * uint(int(_1269))) - (2u * _1307), 4u * _1307);
    uint3 _1518 = (uint3(uint2(int2(uint2(_1470) + _1314)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1520 = _1518.y;
    uint _1522 = _1518.z;
    uint _1526 = _1518.x + (_1520 * _1522);
    uint _1535 = _1520 + (_1522 * _1526);
    uint3 _2973 = uint3(_1526, _1535, _1522 + (_1526 * _1535));
    uint3 _1550 = _2973 ^ (_2973 >> uint3(16u, 16u, 16u));
    uint _1552 = _1550.y;
    uint _1554 = _1550.z;
    uint _1558 = _1550.x + (_1552 * _1554);
    uint _1567 = _1552 + (_1554 * _1558);
    uint3 _1494 = uint3(_1558, _1567, _1554 + (_1558 * _1567)) >> uint3(8u, 8u, 8u);
    float _1506 = (mad(float(_1494.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _1508 = cos(_1506);
    float _1510 = sin(_1506);
    uint3 _1614 = (uint3(uint2(int2(uint2(_1476) + _1314)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1616 = _1614.y;
    uint _1618 = _1614.z;
    uint _1622 = _1614.x + (_1616 * _1618);
    uint _1631 = _1616 + (_1618 * _1622);
    uint3 _2975 = uint3(_1622, _1631, _1618 + (_1622 * _1631));
    uint3 _1646 = _2975 ^ (_2975 >> uint3(16u, 16u, 16u));
    uint _1648 = _1646.y;
    uint _1650 = _1646.z;
    uint _1654 = _1646.x + (_1648 * _1650);
    uint _1663 = _1648 + (_1650 * _1654);
    uint3 _1590 = uint3(_1654, _1663, _1650 + (_1654 * _1663)) >> uint3(8u, 8u, 8u);
    float _1602 = (mad(float(_1590.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _1604 = cos(_1602);
    float _1606 = sin(_1602);
    uint3 _1710 = (uint3(uint2(int2(uint2(_1482) + _1314)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1712 = _1710.y;
    uint _1714 = _1710.z;
    uint _1718 = _1710.x + (_1712 * _1714);
    uint _1727 = _1712 + (_1714 * _1718);
    uint3 _2977 = uint3(_1718, _1727, _1714 + (_1718 * _1727));
    uint3 _1742 = _2977 ^ (_2977 >> uint3(16u, 16u, 16u));
    uint _1744 = _1742.y;
    uint _1746 = _1742.z;
    uint _1750 = _1742.x + (_1744 * _1746);
    uint _1759 = _1744 + (_1746 * _1750);
    uint3 _1686 = uint3(_1750, _1759, _1746 + (_1750 * _1759)) >> uint3(8u, 8u, 8u);
    float _1698 = (mad(float(_1686.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_normal_rotation;
    float _1700 = cos(_1698);
    float _1702 = sin(_1698);
    float _1778 = float(_1470.y);
    float2 _1358 = _1282 - float2(mad(0.5f, _1778, float(_1470.x)) * 0.2886598110198974609375f, 0.25f * _1778);
    float _1790 = _1358.x;
    float _1795 = _1358.y;
    float _1820 = float(_1476.y);
    float2 _1368 = _1282 - float2(mad(0.5f, _1820, float(_1476.x)) * 0.2886598110198974609375f, 0.25f * _1820);
    float _1832 = _1368.x;
    float _1837 = _1368.y;
    float _1862 = float(_1482.y);
    float2 _1378 = _1282 - float2(mad(0.5f, _1862, float(_1482.x)) * 0.2886598110198974609375f, 0.25f * _1862);
    float _1874 = _1378.x;
    float _1879 = _1378.y;
    float _1900 = _1209.x;
    float _1905 = _1209.y;
    float _1912 = -_1900;
    float _1926 = _1211.x;
    float _1931 = _1211.y;
    float _1938 = -_1926;
    float3 _2176 = (hexcTex_normal.SampleGrad(hexcSampler, float2(mad(_1790, _1508, _1795 * _1510), mad(-_1790, _1510, _1795 * _1508)) + (float2(_1494.xy) * 5.9604644775390625e-08f), float2(mad(_1900, _1508, _1905 * _1510), mad(_1912, _1510, _1905 * _1508)), float2(mad(_1926, _1508, _1931 * _1510), mad(_1938, _1510, _1931 * _1508))).xyz * 2.0f) - 1.0f.xxx;
    float3 _2186 = abs(_2176);
    float2 _2213 = (-float2(_2176.xy)) / max(max(_2186.z, 0.0078125f * max(_2186.x, _2186.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _2219 = _2213.x;
    float _2224 = _2213.y;
    float2 _2238 = float2(mad(_1508, _2219, -(_1510 * _2224)), mad(_1510, _2219, _1508 * _2224));
    float3 _2254 = (hexcTex_normal.SampleGrad(hexcSampler, float2(mad(_1832, _1604, _1837 * _1606), mad(-_1832, _1606, _1837 * _1604)) + (float2(_1590.xy) * 5.9604644775390625e-08f), float2(mad(_1900, _1604, _1905 * _1606), mad(_1912, _1606, _1905 * _1604)), float2(mad(_1926, _1604, _1931 * _1606), mad(_1938, _1606, _1931 * _1604))).xyz * 2.0f) - 1.0f.xxx;
    float3 _2264 = abs(_2254);
    float2 _2291 = (-float2(_2254.xy)) / max(max(_2264.z, 0.0078125f * max(_2264.x, _2264.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _2297 = _2291.x;
    float _2302 = _2291.y;
    float2 _2316 = float2(mad(_1604, _2297, -(_1606 * _2302)), mad(_1606, _2297, _1604 * _2302));
    float3 _2332 = (hexcTex_normal.SampleGrad(hexcSampler, float2(mad(_1874, _1700, _1879 * _1702), mad(-_1874, _1702, _1879 * _1700)) + (float2(_1686.xy) * 5.9604644775390625e-08f), float2(mad(_1900, _1700, _1905 * _1702), mad(_1912, _1702, _1905 * _1700)), float2(mad(_1926, _1700, _1931 * _1702), mad(_1938, _1702, _1931 * _1700))).xyz * 2.0f) - 1.0f.xxx;
    float3 _2342 = abs(_2332);
    float2 _2369 = (-float2(_2332.xy)) / max(max(_2342.z, 0.0078125f * max(_2342.x, _2342.y)), 9.9999996826552253889678874634872e-21f).xx;
    float _2375 = _2369.x;
    float _2380 = _2369.y;
    float2 _2394 = float2(mad(_1700, _2375, -(_1702 * _2380)), mad(_1702, _2375, _1700 * _2380));
    float3 _2128 = float3(dot(_2238, _2238), dot(_2316, _2316), dot(_2394, _2394));
    float3 _2406 = pow(float3(_1441 * _1445, mad(-_1430, _1445, _1442), mad(-_1429, _1445, _1442)), hexcParams_normal_exponent.xxx);
    float3 _2413 = lerp(1.0f.xxx, max(sqrt(_2128 / (1.0f.xxx + _2128)), 0.0f.xxx), hexcParams_normal_falloffcontrast.xxx) * _2406;
    float _2421 = (_2413.x + _2413.y) + _2413.z;
    float3 _2695;
    if (_2421 > 0.0f)
    {
        _2695 = _2413 / _2421.xxx;
    }
    else
    {
        _2695 = _2406 / ((_2406.x + _2406.y) + _2406.z).xxx;
    }
    float3 _2972;
    if (hexcParams_normal_falloff != 0.5f)
    {
        float3 _2464 = step(0.5f.xxx, _2695) * 2.0f;
        float3 _2468 = (1.0f.xxx - _2464) * 2.0f;
        float3 _2483 = mad(_2468 * 0.25f, pow(max(0.0f.xxx, mad(_2695, _2468, _2464)), (log(1.0f - hexcParams_normal_falloff) * (-1.44269502162933349609375f)).xxx), _2464 * 0.5f);
        _2972 = _2483 / ((_2483.x + _2483.y) + _2483.z).xxx;
    }
    else
    {
        _2972 = _2695;
    }
    float3 _2631 = normalize(float3(-(((_2238 * _2972.x) + (_2316 * _2972.y)) + (_2394 * _2972.z)), 1.0f));
    float3 _1110 = normalize(((_1078 * _2631.x) + ((cross(_1065, _1078) * v_tangent.w) * _2631.y)) + (_1065 * _2631.z));
    float _1117 = max(dot(_1110, float3(0.408248007297515869140625f, 0.408248007297515869140625f, 0.816497027873992919921875f)), 0.0f);
    o_color = float4((0.5f.xxx * (0.1500000059604644775390625f + _1117)) + (0.039999999105930328369140625f * ((pow(max(dot(_1110, float3(0.21418631076812744140625f, 0.21418631076812744140625f, 0.95302069187164306640625f)), 0.0f), 30.0f) * 1.511971950531005859375f) * _1117)).xxx, 1.0f);
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
