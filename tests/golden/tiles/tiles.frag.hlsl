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
    float2 _820 = v_uv * hexcParams_albedo_tiling;
    float2 _963 = ddx(_820);
    float2 _965 = ddy(_820);
    float2 _1078 = _820 * 3.4641015529632568359375f;
    float _1082 = _1078.y;
    float2 _1088 = float2(mad(-0.57735025882720947265625f, _1082, _1078.x), 1.1547005176544189453125f * _1082);
    int2 _1091 = int2(floor(_1088));
    float2 _1093 = frac(_1088);
    float _1094 = _1093.x;
    float _1095 = _1093.y;
    float _1106 = -((1.0f - _1094) - _1095);
    float _1107 = step(0.0f, _1106);
    float _1110 = mad(2.0f, _1107, -1.0f);
    int _1130 = int(_1107);
    int2 _1135 = _1091 + _1130.xx;
    int _1139 = 1 - _1130;
    int2 _1141 = _1091 + int2(_1130, _1139);
    int2 _1147 = _1091 + int2(_1139, _1130);
    int _1152 = _1135.x;
    int _1154 = _1135.y;
    float _1167 = mod(float(abs(_1152 * _1154) + abs(_1152 + _1154)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _1842;
    if (_1167 > 3.1415927410125732421875f)
    {
        _1842 = _1167 - 6.283185482025146484375f;
    }
    else
    {
        _1842 = _1167;
    }
    float _1176 = _1842 * hexcParams_albedo_rotation;
    float _1178 = cos(_1176);
    float _1180 = sin(_1176);
    int _1186 = _1141.x;
    int _1188 = _1141.y;
    float _1201 = mod(float(abs(_1186 * _1188) + abs(_1186 + _1188)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _1843;
    if (_1201 > 3.1415927410125732421875f)
    {
        _1843 = _1201 - 6.283185482025146484375f;
    }
    else
    {
        _1843 = _1201;
    }
    float _1210 = _1843 * hexcParams_albedo_rotation;
    float _1212 = cos(_1210);
    float _1214 = sin(_1210);
    int _1220 = _1147.x;
    int _1222 = _1147.y;
    float _1235 = mod(float(abs(_1220 * _1222) + abs(_1220 + _1222)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _1844;
    if (_1235 > 3.1415927410125732421875f)
    {
        _1844 = _1235 - 6.283185482025146484375f;
    }
    else
    {
        _1844 = _1235;
    }
    float _1244 = _1844 * hexcParams_albedo_rotation;
    float _1246 = cos(_1244);
    float _1248 = sin(_1244);
    float _1257 = float(_1154);
    float2 _1264 = float2(mad(0.5f, _1257, float(_1152)), _1257 * 0.866025447845458984375f);
    float _1274 = float(_1188);
    float2 _1281 = float2(mad(0.5f, _1274, float(_1186)), _1274 * 0.866025447845458984375f);
    float _1291 = float(_1222);
    float2 _1298 = float2(mad(0.5f, _1291, float(_1220)), _1291 * 0.866025447845458984375f);
    float2 _1002 = mad(v_uv, hexcParams_albedo_tiling, _1264 * (-0.288675129413604736328125f).xx);
    float _1304 = _1002.x;
    float _1309 = _1002.y;
    float2 _1332 = float2(_1135);
    float2 _1015 = mad(v_uv, hexcParams_albedo_tiling, _1281 * (-0.288675129413604736328125f).xx);
    float _1345 = _1015.x;
    float _1350 = _1015.y;
    float2 _1373 = float2(_1141);
    float2 _1028 = mad(v_uv, hexcParams_albedo_tiling, _1298 * (-0.288675129413604736328125f).xx);
    float _1386 = _1028.x;
    float _1391 = _1028.y;
    float2 _1414 = float2(_1147);
    float _1427 = _963.x;
    float _1432 = _963.y;
    float _1439 = -_1427;
    float _1453 = _965.x;
    float _1458 = _965.y;
    float _1465 = -_1453;
    float4 _861 = hexcTex_albedo.SampleGrad(hexcSampler, mad(_1264, 0.288675129413604736328125f.xx, float2(mad(_1304, _1178, _1309 * _1180), mad(-_1304, _1180, _1309 * _1178))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _1332), dot(float2(269.5f, 183.3000030517578125f), _1332))) * 43758.546875f), float2(mad(_1427, _1178, _1432 * _1180), mad(_1439, _1180, _1432 * _1178)), float2(mad(_1453, _1178, _1458 * _1180), mad(_1465, _1180, _1458 * _1178)));
    float4 _871 = hexcTex_albedo.SampleGrad(hexcSampler, mad(_1281, 0.288675129413604736328125f.xx, float2(mad(_1345, _1212, _1350 * _1214), mad(-_1345, _1214, _1350 * _1212))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _1373), dot(float2(269.5f, 183.3000030517578125f), _1373))) * 43758.546875f), float2(mad(_1427, _1212, _1432 * _1214), mad(_1439, _1214, _1432 * _1212)), float2(mad(_1453, _1212, _1458 * _1214), mad(_1465, _1214, _1458 * _1212)));
    float4 _881 = hexcTex_albedo.SampleGrad(hexcSampler, mad(_1298, 0.288675129413604736328125f.xx, float2(mad(_1386, _1246, _1391 * _1248), mad(-_1386, _1248, _1391 * _1246))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _1414), dot(float2(269.5f, 183.3000030517578125f), _1414))) * 43758.546875f), float2(mad(_1427, _1246, _1432 * _1248), mad(_1439, _1248, _1432 * _1246)), float2(mad(_1453, _1246, _1458 * _1248), mad(_1465, _1248, _1458 * _1246)));
    float3 _1594 = lerp(1.0f.xxx, float3(dot(_861, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_871, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_881, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f))), hexcParams_albedo_falloffcontrast.xxx) * pow(float3(_1106 * _1110, mad(-_1095, _1110, _1107), mad(-_1094, _1110, _1107)), hexcParams_albedo_exponent.xxx);
    float3 _1605 = _1594 / ((_1594.x + _1594.y) + _1594.z).xxx;
    float3 _1975;
    if (hexcParams_albedo_falloff != 0.5f)
    {
        float3 _1627 = step(0.5f.xxx, _1605) * 2.0f;
        float3 _1631 = (1.0f.xxx - _1627) * 2.0f;
        float3 _1646 = mad(_1631 * 0.25f, pow(max(0.0f.xxx, mad(_1605, _1631, _1627)), (log(1.0f - hexcParams_albedo_falloff) * (-1.44269502162933349609375f)).xxx), _1627 * 0.5f);
        _1975 = _1646 / ((_1646.x + _1646.y) + _1646.z).xxx;
    }
    else
    {
        _1975 = _1605;
    }
    o_color = ((_861 * _1975.x) + (_871 * _1975.y)) + (_881 * _1975.z);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    v_uv = stage_input.v_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.o_color = o_color;
    return stage_output;
}
