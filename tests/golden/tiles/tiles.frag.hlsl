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
    float2 _901 = v_uv * hexcParams_albedo_tiling;
    float2 _967 = ddx(_901);
    float2 _969 = ddy(_901);
    float _971 = _901.x;
    float _973 = floor(_971 * 0.0357142873108386993408203125f);
    float _975 = _901.y;
    float _976 = floor(_975);
    float _981 = mad(-28.0f, _973, _971);
    float _985 = _975 - _976;
    float2 _986 = float2(_981, _985);
    float2 _997 = float2(mad(3.4642856121063232421875f, _981, _985 * (-2.0f)), 4.0f * _985);
    float2 _1116 = floor(_997);
    int2 _1117 = int2(_1116);
    float2 _1121 = _997 - _1116;
    float _1122 = _1121.x;
    float _1123 = _1121.y;
    float _1134 = -((1.0f - _1122) - _1123);
    float _1135 = step(0.0f, _1134);
    float _1138 = mad(2.0f, _1135, -1.0f);
    int _1158 = int(_1135);
    int2 _1163 = _1117 + _1158.xx;
    int _1167 = 1 - _1158;
    int2 _1169 = _1117 + int2(_1158, _1167);
    int2 _1175 = _1117 + int2(_1167, _1158);
    int _1008 = int(_976);
    int2 _1014 = int2((97 * int(_973)) - (2 * _1008), 4 * _1008);
    uint3 _1211 = (uint3(uint2(_1163 + _1014), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1213 = _1211.y;
    uint _1215 = _1211.z;
    uint _1219 = _1211.x + (_1213 * _1215);
    uint _1228 = _1213 + (_1215 * _1219);
    uint3 _2308 = uint3(_1219, _1228, _1215 + (_1219 * _1228));
    uint3 _1243 = _2308 ^ (_2308 >> uint3(16u, 16u, 16u));
    uint _1245 = _1243.y;
    uint _1247 = _1243.z;
    uint _1251 = _1243.x + (_1245 * _1247);
    uint _1260 = _1245 + (_1247 * _1251);
    uint3 _1187 = uint3(_1251, _1260, _1247 + (_1251 * _1260)) >> uint3(8u, 8u, 8u);
    float _1199 = (mad(float(_1187.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _1201 = cos(_1199);
    float _1203 = sin(_1199);
    uint3 _1307 = (uint3(uint2(_1169 + _1014), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1309 = _1307.y;
    uint _1311 = _1307.z;
    uint _1315 = _1307.x + (_1309 * _1311);
    uint _1324 = _1309 + (_1311 * _1315);
    uint3 _2310 = uint3(_1315, _1324, _1311 + (_1315 * _1324));
    uint3 _1339 = _2310 ^ (_2310 >> uint3(16u, 16u, 16u));
    uint _1341 = _1339.y;
    uint _1343 = _1339.z;
    uint _1347 = _1339.x + (_1341 * _1343);
    uint _1356 = _1341 + (_1343 * _1347);
    uint3 _1283 = uint3(_1347, _1356, _1343 + (_1347 * _1356)) >> uint3(8u, 8u, 8u);
    float _1295 = (mad(float(_1283.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _1297 = cos(_1295);
    float _1299 = sin(_1295);
    uint3 _1403 = (uint3(uint2(_1175 + _1014), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1405 = _1403.y;
    uint _1407 = _1403.z;
    uint _1411 = _1403.x + (_1405 * _1407);
    uint _1420 = _1405 + (_1407 * _1411);
    uint3 _2312 = uint3(_1411, _1420, _1407 + (_1411 * _1420));
    uint3 _1435 = _2312 ^ (_2312 >> uint3(16u, 16u, 16u));
    uint _1437 = _1435.y;
    uint _1439 = _1435.z;
    uint _1443 = _1435.x + (_1437 * _1439);
    uint _1452 = _1437 + (_1439 * _1443);
    uint3 _1379 = uint3(_1443, _1452, _1439 + (_1443 * _1452)) >> uint3(8u, 8u, 8u);
    float _1391 = (mad(float(_1379.z), 1.1920928955078125e-07f, -1.0f) * 3.1415927410125732421875f) * hexcParams_albedo_rotation;
    float _1393 = cos(_1391);
    float _1395 = sin(_1391);
    float _1471 = float(_1163.y);
    float2 _1051 = _986 - float2(mad(0.5f, _1471, float(_1163.x)) * 0.2886598110198974609375f, 0.25f * _1471);
    float _1483 = _1051.x;
    float _1488 = _1051.y;
    float _1513 = float(_1169.y);
    float2 _1061 = _986 - float2(mad(0.5f, _1513, float(_1169.x)) * 0.2886598110198974609375f, 0.25f * _1513);
    float _1525 = _1061.x;
    float _1530 = _1061.y;
    float _1555 = float(_1175.y);
    float2 _1071 = _986 - float2(mad(0.5f, _1555, float(_1175.x)) * 0.2886598110198974609375f, 0.25f * _1555);
    float _1567 = _1071.x;
    float _1572 = _1071.y;
    float _1593 = _967.x;
    float _1598 = _967.y;
    float _1605 = -_1593;
    float _1619 = _969.x;
    float _1624 = _969.y;
    float _1631 = -_1619;
    float4 _1770 = hexcTex_albedo.SampleGrad(hexcSampler, float2(mad(_1483, _1201, _1488 * _1203), mad(-_1483, _1203, _1488 * _1201)) + (float2(_1187.xy) * 5.9604644775390625e-08f), float2(mad(_1593, _1201, _1598 * _1203), mad(_1605, _1203, _1598 * _1201)), float2(mad(_1619, _1201, _1624 * _1203), mad(_1631, _1203, _1624 * _1201)));
    float4 _1780 = hexcTex_albedo.SampleGrad(hexcSampler, float2(mad(_1525, _1297, _1530 * _1299), mad(-_1525, _1299, _1530 * _1297)) + (float2(_1283.xy) * 5.9604644775390625e-08f), float2(mad(_1593, _1297, _1598 * _1299), mad(_1605, _1299, _1598 * _1297)), float2(mad(_1619, _1297, _1624 * _1299), mad(_1631, _1299, _1624 * _1297)));
    float4 _1790 = hexcTex_albedo.SampleGrad(hexcSampler, float2(mad(_1567, _1393, _1572 * _1395), mad(-_1567, _1395, _1572 * _1393)) + (float2(_1379.xy) * 5.9604644775390625e-08f), float2(mad(_1593, _1393, _1598 * _1395), mad(_1605, _1395, _1598 * _1393)), float2(mad(_1619, _1393, _1624 * _1395), mad(_1631, _1395, _1624 * _1393)));
    float3 _1842 = lerp(1.0f.xxx, float3(dot(_1770, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_1780, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_1790, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f))), hexcParams_albedo_falloffcontrast.xxx) * pow(float3(_1134 * _1138, mad(-_1123, _1138, _1135), mad(-_1122, _1138, _1135)), hexcParams_albedo_exponent.xxx);
    float3 _1853 = _1842 / ((_1842.x + _1842.y) + _1842.z).xxx;
    float3 _2307;
    if (hexcParams_albedo_falloff != 0.5f)
    {
        float3 _1875 = step(0.5f.xxx, _1853) * 2.0f;
        float3 _1879 = (1.0f.xxx - _1875) * 2.0f;
        float3 _1894 = mad(_1879 * 0.25f, pow(max(0.0f.xxx, mad(_1853, _1879, _1875)), (log(1.0f - hexcParams_albedo_falloff) * (-1.44269502162933349609375f)).xxx), _1875 * 0.5f);
        _2307 = _1894 / ((_1894.x + _1894.y) + _1894.z).xxx;
    }
    else
    {
        _2307 = _1853;
    }
    o_color = ((_1770 * _2307.x) + (_1780 * _2307.y)) + (_1790 * _2307.z);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    v_uv = stage_input.v_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.o_color = o_color;
    return stage_output;
}
