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

float mod(float x, float y)
{
    return x - y * floor(x / y);
}

float2 mod(float2 x, float2 y)
{
    return x - y * floor(x / y);
}

float3 mod(float3 x, float3 y)
{
    return x - y * floor(x / y);
}

float4 mod(float4 x, float4 y)
{
    return x - y * floor(x / y);
}

void frag_main()
{
    float3 _931 = normalize(v_normal);
    float3 _944 = normalize(v_tangent.xyz - (_931 * dot(_931, v_tangent.xyz)));
    float2 _1054 = v_uv * hexcParams_normal_tiling;
    float2 _1223 = ddx(_1054);
    float2 _1225 = ddy(_1054);
    float2 _1338 = _1054 * 3.4641015529632568359375f;
    float _1342 = _1338.y;
    float2 _1348 = float2(mad(-0.57735025882720947265625f, _1342, _1338.x), 1.1547005176544189453125f * _1342);
    int2 _1351 = int2(floor(_1348));
    float2 _1353 = frac(_1348);
    float _1354 = _1353.x;
    float _1355 = _1353.y;
    float _1366 = -((1.0f - _1354) - _1355);
    float _1367 = step(0.0f, _1366);
    float _1370 = mad(2.0f, _1367, -1.0f);
    int _1390 = int(_1367);
    int2 _1395 = _1351 + _1390.xx;
    int _1399 = 1 - _1390;
    int2 _1401 = _1351 + int2(_1390, _1399);
    int2 _1407 = _1351 + int2(_1399, _1390);
    int _1412 = _1395.x;
    int _1414 = _1395.y;
    float _1427 = mod(float(abs(_1412 * _1414) + abs(_1412 + _1414)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _2346;
    if (_1427 > 3.1415927410125732421875f)
    {
        _2346 = _1427 - 6.283185482025146484375f;
    }
    else
    {
        _2346 = _1427;
    }
    float _1436 = _2346 * hexcParams_normal_rotation;
    float _1438 = cos(_1436);
    float _1440 = sin(_1436);
    int _1446 = _1401.x;
    int _1448 = _1401.y;
    float _1461 = mod(float(abs(_1446 * _1448) + abs(_1446 + _1448)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _2347;
    if (_1461 > 3.1415927410125732421875f)
    {
        _2347 = _1461 - 6.283185482025146484375f;
    }
    else
    {
        _2347 = _1461;
    }
    float _1470 = _2347 * hexcParams_normal_rotation;
    float _1472 = cos(_1470);
    float _1474 = sin(_1470);
    int _1480 = _1407.x;
    int _1482 = _1407.y;
    float _1495 = mod(float(abs(_1480 * _1482) + abs(_1480 + _1482)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _2348;
    if (_1495 > 3.1415927410125732421875f)
    {
        _2348 = _1495 - 6.283185482025146484375f;
    }
    else
    {
        _2348 = _1495;
    }
    float _1504 = _2348 * hexcParams_normal_rotation;
    float _1506 = cos(_1504);
    float _1508 = sin(_1504);
    float _1517 = float(_1414);
    float2 _1524 = float2(mad(0.5f, _1517, float(_1412)), _1517 * 0.866025447845458984375f);
    float _1534 = float(_1448);
    float2 _1541 = float2(mad(0.5f, _1534, float(_1446)), _1534 * 0.866025447845458984375f);
    float _1551 = float(_1482);
    float2 _1558 = float2(mad(0.5f, _1551, float(_1480)), _1551 * 0.866025447845458984375f);
    float2 _1262 = mad(v_uv, hexcParams_normal_tiling, _1524 * (-0.288675129413604736328125f).xx);
    float _1564 = _1262.x;
    float _1569 = _1262.y;
    float2 _1592 = float2(_1395);
    float2 _1275 = mad(v_uv, hexcParams_normal_tiling, _1541 * (-0.288675129413604736328125f).xx);
    float _1605 = _1275.x;
    float _1610 = _1275.y;
    float2 _1633 = float2(_1401);
    float2 _1288 = mad(v_uv, hexcParams_normal_tiling, _1558 * (-0.288675129413604736328125f).xx);
    float _1646 = _1288.x;
    float _1651 = _1288.y;
    float2 _1674 = float2(_1407);
    float _1687 = _1223.x;
    float _1692 = _1223.y;
    float _1699 = -_1687;
    float _1713 = _1225.x;
    float _1718 = _1225.y;
    float _1725 = -_1713;
    float3 _1855 = (hexcTex_normal.SampleGrad(hexcSampler, mad(_1524, 0.288675129413604736328125f.xx, float2(mad(_1564, _1438, _1569 * _1440), mad(-_1564, _1440, _1569 * _1438))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _1592), dot(float2(269.5f, 183.3000030517578125f), _1592))) * 43758.546875f), float2(mad(_1687, _1438, _1692 * _1440), mad(_1699, _1440, _1692 * _1438)), float2(mad(_1713, _1438, _1718 * _1440), mad(_1725, _1440, _1718 * _1438))).xyz * 2.0f) - 1.0f.xxx;
    float3 _1865 = abs(_1855);
    float2 _1891 = (-float2(_1855.xy)) / max(_1865.z, 0.0078125f * max(_1865.x, _1865.y)).xx;
    float _1897 = _1891.x;
    float _1902 = _1891.y;
    float2 _1916 = float2(mad(_1438, _1897, -(_1440 * _1902)), mad(_1440, _1897, _1438 * _1902));
    float3 _1932 = (hexcTex_normal.SampleGrad(hexcSampler, mad(_1541, 0.288675129413604736328125f.xx, float2(mad(_1605, _1472, _1610 * _1474), mad(-_1605, _1474, _1610 * _1472))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _1633), dot(float2(269.5f, 183.3000030517578125f), _1633))) * 43758.546875f), float2(mad(_1687, _1472, _1692 * _1474), mad(_1699, _1474, _1692 * _1472)), float2(mad(_1713, _1472, _1718 * _1474), mad(_1725, _1474, _1718 * _1472))).xyz * 2.0f) - 1.0f.xxx;
    float3 _1942 = abs(_1932);
    float2 _1968 = (-float2(_1932.xy)) / max(_1942.z, 0.0078125f * max(_1942.x, _1942.y)).xx;
    float _1974 = _1968.x;
    float _1979 = _1968.y;
    float2 _1993 = float2(mad(_1472, _1974, -(_1474 * _1979)), mad(_1474, _1974, _1472 * _1979));
    float3 _2009 = (hexcTex_normal.SampleGrad(hexcSampler, mad(_1558, 0.288675129413604736328125f.xx, float2(mad(_1646, _1506, _1651 * _1508), mad(-_1646, _1508, _1651 * _1506))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _1674), dot(float2(269.5f, 183.3000030517578125f), _1674))) * 43758.546875f), float2(mad(_1687, _1506, _1692 * _1508), mad(_1699, _1508, _1692 * _1506)), float2(mad(_1713, _1506, _1718 * _1508), mad(_1725, _1508, _1718 * _1506))).xyz * 2.0f) - 1.0f.xxx;
    float3 _2019 = abs(_2009);
    float2 _2045 = (-float2(_2009.xy)) / max(_2019.z, 0.0078125f * max(_2019.x, _2019.y)).xx;
    float _2051 = _2045.x;
    float _2056 = _2045.y;
    float2 _2070 = float2(mad(_1506, _2051, -(_1508 * _2056)), mad(_1508, _2051, _1506 * _2056));
    float3 _1146 = float3(dot(_1916, _1916), dot(_1993, _1993), dot(_2070, _2070));
    float3 _2085 = lerp(1.0f.xxx, sqrt(_1146 / (1.0f.xxx + _1146)), hexcParams_normal_falloffcontrast.xxx) * pow(float3(_1366 * _1370, mad(-_1355, _1370, _1367), mad(-_1354, _1370, _1367)), hexcParams_normal_exponent.xxx);
    float3 _2096 = _2085 / ((_2085.x + _2085.y) + _2085.z).xxx;
    float3 _2540;
    if (hexcParams_normal_falloff != 0.5f)
    {
        float3 _2118 = step(0.5f.xxx, _2096) * 2.0f;
        float3 _2122 = (1.0f.xxx - _2118) * 2.0f;
        float3 _2137 = mad(_2122 * 0.25f, pow(max(0.0f.xxx, mad(_2096, _2122, _2118)), (log(1.0f - hexcParams_normal_falloff) * (-1.44269502162933349609375f)).xxx), _2118 * 0.5f);
        _2540 = _2137 / ((_2137.x + _2137.y) + _2137.z).xxx;
    }
    else
    {
        _2540 = _2096;
    }
    float3 _2285 = normalize(float3(-(((_1916 * _2540.x) + (_1993 * _2540.y)) + (_2070 * _2540.z)), 1.0f));
    float3 _976 = normalize(((_944 * _2285.x) + ((cross(_931, _944) * v_tangent.w) * _2285.y)) + (_931 * _2285.z));
    float _983 = max(dot(_976, float3(0.408248007297515869140625f, 0.408248007297515869140625f, 0.816497027873992919921875f)), 0.0f);
    o_color = float4((0.5f.xxx * (0.1500000059604644775390625f + _983)) + (0.039999999105930328369140625f * ((pow(max(dot(_976, float3(0.21418631076812744140625f, 0.21418631076812744140625f, 0.95302069187164306640625f)), 0.0f), 30.0f) * 1.511971950531005859375f) * _983)).xxx, 1.0f);
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
