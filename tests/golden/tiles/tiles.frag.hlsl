cbuffer HexcParams : register(b0)
{
    float2 hexcParams_albedo_tiling : packoffset(c0);
    float hexcParams_albedo_rotation : packoffset(c0.z);
    float hexcParams_albedo_falloff : packoffset(c0.w);
    float hexcParams_albedo_falloffcontrast : packoffset(c1);
    float hexcParams_albedo_exponent : packoffset(c1.y);
};

Texture2D<float4> hexcTex_albedo : register(t0);
SamplerState hexcSampler : register(s0);

static float4 o_color;
static float2 v_uv;

struct SPIRV_Cross_Input
{
    float2 v_uv : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float4 o_color : SV_Target0;
};

void frag_main()
{
    float2 _953 = v_uv * hexcParams_albedo_tiling;
    float2 _973 = ddx(_953);
    float2 _975 = ddy(_953);
    float _1031 = _953.x;
    float _1033 = floor(_1031 * 0.0357142873108386993408203125f);
    float _1035 = _953.y;
    float _1036 = floor(_1035);
    float _1041 = mad(-28.0f, _1033, _1031);
    float _1045 = _1035 - _1036;
    float2 _1046 = float2(_1041, _1045);
    float2 _1057 = float2(mad(3.4642856121063232421875f, _1041, _1045 * (-2.0f)), 4.0f * _1045);
    float2 _1187 = floor(_1057);
    int2 _1188 = int2(_1187);
    float2 _1192 = _1057 - _1187;
    float _1193 = _1192.x;
    float _1194 = _1192.y;
    float _1205 = -((1.0f - _1193) - _1194);
    float _1206 = step(0.0f, _1205);
    float _1209 = mad(2.0f, _1206, -1.0f);
    int _1229 = int(_1206);
    int2 _1234 = _1188 + _1229.xx;
    int _1238 = 1 - _1229;
    int2 _1240 = _1188 + int2(_1229, _1238);
    int2 _1246 = _1188 + int2(_1238, _1229);
    uint _1071 = uint(int(_1036));
    uint2 _1078 = uint2((97u * uint(int(_1033))) - (2u * _1071), 4u * _1071);
    uint3 _1282 = (uint3(uint2(int2(uint2(_1234) + _1078)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1284 = _1282.y;
    uint _1286 = _1282.z;
    uint _1290 = _1282.x + (_1284 * _1286);
    uint _1299 = _1284 + (_1286 * _1290);
    uint3 _2405 = uint3(_1290, _1299, _1286 + (_1290 * _1299));
    uint3 _1314 = _2405 ^ (_2405 >> uint3(16u, 16u, 16u));
    uint _1316 = _1314.y;
    uint _1318 = _1314.z;
    uint _1322 = _1314.x + (_1316 * _1318);
    uint _1331 = _1316 + (_1318 * _1322);
    uint3 _1258 = uint3(_1322, _1331, _1318 + (_1322 * _1331)) >> uint3(8u, 8u, 8u);
    float _1270 = (mad(float(_1258.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _1272 = cos(_1270);
    float _1274 = sin(_1270);
    uint3 _1378 = (uint3(uint2(int2(uint2(_1240) + _1078)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1380 = _1378.y;
    uint _1382 = _1378.z;
    uint _1386 = _1378.x + (_1380 * _1382);
    uint _1395 = _1380 + (_1382 * _1386);
    uint3 _2407 = uint3(_1386, _1395, _1382 + (_1386 * _1395));
    uint3 _1410 = _2407 ^ (_2407 >> uint3(16u, 16u, 16u));
    uint _1412 = _1410.y;
    uint _1414 = _1410.z;
    uint _1418 = _1410.x + (_1412 * _1414);
    uint _1427 = _1412 + (_1414 * _1418);
    uint3 _1354 = uint3(_1418, _1427, _1414 + (_1418 * _1427)) >> uint3(8u, 8u, 8u);
    float _1366 = (mad(float(_1354.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _1368 = cos(_1366);
    float _1370 = sin(_1366);
    uint3 _1474 = (uint3(uint2(int2(uint2(_1246) + _1078)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1476 = _1474.y;
    uint _1478 = _1474.z;
    uint _1482 = _1474.x + (_1476 * _1478);
    uint _1491 = _1476 + (_1478 * _1482);
    uint3 _2409 = uint3(_1482, _1491, _1478 + (_1482 * _1491));
    uint3 _1506 = _2409 ^ (_2409 >> uint3(16u, 16u, 16u));
    uint _1508 = _1506.y;
    uint _1510 = _1506.z;
    uint _1514 = _1506.x + (_1508 * _1510);
    uint _1523 = _1508 + (_1510 * _1514);
    uint3 _1450 = uint3(_1514, _1523, _1510 + (_1514 * _1523)) >> uint3(8u, 8u, 8u);
    float _1462 = (mad(float(_1450.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _1464 = cos(_1462);
    float _1466 = sin(_1462);
    float _1542 = float(_1234.y);
    float2 _1122 = _1046 - float2(mad(0.5f, _1542, float(_1234.x)) * 0.2886598110198974609375f, 0.25f * _1542);
    float _1554 = _1122.x;
    float _1559 = _1122.y;
    float _1584 = float(_1240.y);
    float2 _1132 = _1046 - float2(mad(0.5f, _1584, float(_1240.x)) * 0.2886598110198974609375f, 0.25f * _1584);
    float _1596 = _1132.x;
    float _1601 = _1132.y;
    float _1626 = float(_1246.y);
    float2 _1142 = _1046 - float2(mad(0.5f, _1626, float(_1246.x)) * 0.2886598110198974609375f, 0.25f * _1626);
    float _1638 = _1142.x;
    float _1643 = _1142.y;
    float _1664 = _973.x;
    float _1669 = _973.y;
    float _1676 = -_1664;
    float _1690 = _975.x;
    float _1695 = _975.y;
    float _1702 = -_1690;
    float4 _1841 = hexcTex_albedo.SampleGrad(hexcSampler, float2(mad(_1554, _1272, _1559 * _1274), mad(-_1554, _1274, _1559 * _1272)) + (float2(_1258.xy) * 5.9604644775390625e-08f), float2(mad(_1664, _1272, _1669 * _1274), mad(_1676, _1274, _1669 * _1272)), float2(mad(_1690, _1272, _1695 * _1274), mad(_1702, _1274, _1695 * _1272)));
    float4 _1851 = hexcTex_albedo.SampleGrad(hexcSampler, float2(mad(_1596, _1368, _1601 * _1370), mad(-_1596, _1370, _1601 * _1368)) + (float2(_1354.xy) * 5.9604644775390625e-08f), float2(mad(_1664, _1368, _1669 * _1370), mad(_1676, _1370, _1669 * _1368)), float2(mad(_1690, _1368, _1695 * _1370), mad(_1702, _1370, _1695 * _1368)));
    float4 _1861 = hexcTex_albedo.SampleGrad(hexcSampler, float2(mad(_1638, _1464, _1643 * _1466), mad(-_1638, _1466, _1643 * _1464)) + (float2(_1450.xy) * 5.9604644775390625e-08f), float2(mad(_1664, _1464, _1669 * _1466), mad(_1676, _1466, _1669 * _1464)), float2(mad(_1690, _1464, _1695 * _1466), mad(_1702, _1466, _1695 * _1464)));
    float3 _1910 = pow(float3(_1205 * _1209, mad(-_1194, _1209, _1206), mad(-_1193, _1209, _1206)), hexcParams_albedo_exponent.xxx);
    float3 _1917 = lerp(1.0f.xxx, max(float3(dot(_1841, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_1851, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_1861, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f))), 0.0f.xxx), hexcParams_albedo_falloffcontrast.xxx) * _1910;
    float _1925 = (_1917.x + _1917.y) + _1917.z;
    float3 _2183;
    if (_1925 > 0.0f)
    {
        _2183 = _1917 / _1925.xxx;
    }
    else
    {
        _2183 = _1910 / ((_1910.x + _1910.y) + _1910.z).xxx;
    }
    float3 _2404;
    if (hexcParams_albedo_falloff != 0.5f)
    {
        float3 _1968 = step(0.5f.xxx, _2183) * 2.0f;
        float3 _1972 = (1.0f.xxx - _1968) * 2.0f;
        float3 _1987 = mad(_1972 * 0.25f, pow(max(0.0f.xxx, mad(_2183, _1972, _1968)), (log(1.0f - hexcParams_albedo_falloff) * (-1.44269502162933349609375f)).xxx), _1968 * 0.5f);
        _2404 = _1987 / ((_1987.x + _1987.y) + _1987.z).xxx;
    }
    else
    {
        _2404 = _2183;
    }
    o_color = ((_1841 * _2404.x) + (_1851 * _2404.y)) + (_1861 * _2404.z);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    v_uv = stage_input.v_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.o_color = o_color;
    return stage_output;
}
