static uint _2566;

cbuffer HexcParams : register(b0)
{
    float2 hexcParams_albedo_tiling : packoffset(c0);
    float hexcParams_albedo_falloff : packoffset(c0.z);
    float hexcParams_albedo_falloffcontrast : packoffset(c0.w);
    float hexcParams_albedo_exponent : packoffset(c1);
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
    float2 _1064 = v_uv * hexcParams_albedo_tiling;
    float2 _1083 = ddx(_1064);
    float2 _1085 = ddy(_1064);
    float _1157 = _1064.x;
    float _1159 = floor(_1157 * 0.0357142873108386993408203125f);
    float _1161 = _1064.y;
    float _1162 = floor(_1161);
    float _1167 = mad(-28.0f, _1159, _1157);
    float _1171 = _1161 - _1162;
    float2 _1172 = float2(_1167, _1171);
    float2 _1183 = float2(mad(3.4642856121063232421875f, _1167, _1171 * (-2.0f)), 4.0f * _1171);
    float2 _1373 = floor(_1183);
    int2 _1374 = int2(_1373);
    float2 _1378 = _1183 - _1373;
    float _1379 = _1378.x;
    float _1380 = _1378.y;
    float _1391 = -((1.0f - _1379) - _1380);
    float _1392 = step(0.0f, _1391);
    float _1395 = mad(2.0f, _1392, -1.0f);
    int _1415 = int(_1392);
    int2 _1420 = _1374 + _1415.xx;
    int _1424 = 1 - _1415;
    int2 _1426 = _1374 + int2(_1415, _1424);
    int2 _1432 = _1374 + int2(_1424, _1415);
    uint _1197 = uint(int(_1162));
    uint2 _1204 = uint2((97u * uint(int(_1159))) - (2u * _1197), 4u * _1197);
    uint3 _1474 = (uint3(uint2(int2(uint2(_1420) + _1204)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1476 = _1474.y;
    uint _1478 = _1474.z;
    uint _1482 = _1474.x + (_1476 * _1478);
    uint _1491 = _1476 + (_1478 * _1482);
    uint3 _2560 = uint3(_1482, _1491, _1478 + (_1482 * _1491));
    uint3 _1506 = _2560 ^ (_2560 >> uint3(16u, 16u, 16u));
    uint _1508 = _1506.y;
    uint _1510 = _1506.z;
    uint _1514 = _1506.x + (_1508 * _1510);
    uint3 _1576 = (uint3(uint2(int2(uint2(_1426) + _1204)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1578 = _1576.y;
    uint _1580 = _1576.z;
    uint _1584 = _1576.x + (_1578 * _1580);
    uint _1593 = _1578 + (_1580 * _1584);
    uint3 _2562 = uint3(_1584, _1593, _1580 + (_1584 * _1593));
    uint3 _1608 = _2562 ^ (_2562 >> uint3(16u, 16u, 16u));
    uint _1610 = _1608.y;
    uint _1612 = _1608.z;
    uint _1616 = _1608.x + (_1610 * _1612);
    uint3 _1678 = (uint3(uint2(int2(uint2(_1432) + _1204)), 0u) * uint3(1664525u, 1664525u, 1664525u)) + uint3(1013904223u, 1013904223u, 1013904223u);
    uint _1680 = _1678.y;
    uint _1682 = _1678.z;
    uint _1686 = _1678.x + (_1680 * _1682);
    uint _1695 = _1680 + (_1682 * _1686);
    uint3 _2564 = uint3(_1686, _1695, _1682 + (_1686 * _1695));
    uint3 _1710 = _2564 ^ (_2564 >> uint3(16u, 16u, 16u));
    uint _1712 = _1710.y;
    uint _1714 = _1710.z;
    uint _1718 = _1710.x + (_1712 * _1714);
    float _1746 = float(_1420.y);
    float _1762 = float(_1426.y);
    float _1778 = float(_1432.y);
    float4 _2047 = hexcTex_albedo.SampleGrad(hexcSampler, (_1172 - float2(mad(0.5f, _1746, float(_1420.x)) * 0.2886598110198974609375f, 0.25f * _1746)) + (float2((uint3(_1514, _1508 + (_1510 * _1514), _2566) >> uint3(8u, 8u, 8u)).xy) * 5.9604644775390625e-08f), _1083, _1085);
    float4 _2057 = hexcTex_albedo.SampleGrad(hexcSampler, (_1172 - float2(mad(0.5f, _1762, float(_1426.x)) * 0.2886598110198974609375f, 0.25f * _1762)) + (float2((uint3(_1616, _1610 + (_1612 * _1616), _2566) >> uint3(8u, 8u, 8u)).xy) * 5.9604644775390625e-08f), _1083, _1085);
    float4 _2067 = hexcTex_albedo.SampleGrad(hexcSampler, (_1172 - float2(mad(0.5f, _1778, float(_1432.x)) * 0.2886598110198974609375f, 0.25f * _1778)) + (float2((uint3(_1718, _1712 + (_1714 * _1718), _2566) >> uint3(8u, 8u, 8u)).xy) * 5.9604644775390625e-08f), _1083, _1085);
    float3 _2119 = pow(float3(_1391 * _1395, mad(-_1380, _1395, _1392), mad(-_1379, _1395, _1392)), hexcParams_albedo_exponent.xxx);
    float3 _2128 = lerp(1.0f.xxx, max(float3(dot(_2047, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_2057, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_2067, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f))), 0.0f.xxx), hexcParams_albedo_falloffcontrast.xxx) * _2119;
    float _2140 = (_2128.x + _2128.y) + _2128.z;
    float3 _2413;
    if (_2140 > 0.0f)
    {
        _2413 = _2128 / _2140.xxx;
    }
    else
    {
        _2413 = _2119 / ((_2119.x + _2119.y) + _2119.z).xxx;
    }
    float3 _2559;
    if (true && (hexcParams_albedo_falloff != 0.5f))
    {
        float3 _2185 = step(0.5f.xxx, _2413) * 2.0f;
        float3 _2189 = (1.0f.xxx - _2185) * 2.0f;
        float3 _2204 = mad(_2189 * 0.25f, pow(max(0.0f.xxx, mad(_2413, _2189, _2185)), (log(1.0f - hexcParams_albedo_falloff) * (-1.44269502162933349609375f)).xxx), _2185 * 0.5f);
        _2559 = _2204 / ((_2204.x + _2204.y) + _2204.z).xxx;
    }
    else
    {
        _2559 = _2413;
    }
    o_color = ((_2047 * _2559.x) + (_2057 * _2559.y)) + (_2067 * _2559.z);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    v_uv = stage_input.v_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.o_color = o_color;
    return stage_output;
}
