#pragma clang diagnostic ignored "-Wmissing-prototypes"

#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

// Implementation of the GLSL mod() function, which is slightly different than Metal fmod()
template<typename Tx, typename Ty>
inline Tx mod(Tx x, Ty y)
{
    return x - y * floor(x / y);
}

struct HexcParams
{
    float2 albedo_tiling;
    float albedo_rotation;
    float albedo_falloff;
    float albedo_falloffcontrast;
    float albedo_exponent;
};

struct main0_out
{
    float4 o_color [[color(0)]];
};

struct main0_in
{
    float2 v_uv [[user(locn0)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant HexcParams& hexcParams [[buffer(0)]], texture2d<float> hexcTex_albedo [[texture(0)]], sampler hexcSampler [[sampler(0)]])
{
    main0_out out = {};
    float2 _820 = in.v_uv * hexcParams.albedo_tiling;
    float2 _963 = dfdx(_820);
    float2 _965 = dfdy(_820);
    float2 _1078 = _820 * 3.4641015529632568359375;
    float _1082 = _1078.y;
    float2 _1088 = float2(fma(-0.57735025882720947265625, _1082, _1078.x), 1.1547005176544189453125 * _1082);
    int2 _1091 = int2(floor(_1088));
    float2 _1093 = fract(_1088);
    float _1094 = _1093.x;
    float _1095 = _1093.y;
    float _1106 = -((1.0 - _1094) - _1095);
    float _1107 = step(0.0, _1106);
    float _1110 = fma(2.0, _1107, -1.0);
    int _1130 = int(_1107);
    int2 _1135 = _1091 + int2(_1130);
    int _1139 = 1 - _1130;
    int2 _1141 = _1091 + int2(_1130, _1139);
    int2 _1147 = _1091 + int2(_1139, _1130);
    int _1152 = _1135.x;
    int _1154 = _1135.y;
    float _1167 = mod(float(abs(_1152 * _1154) + abs(_1152 + _1154)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _1842;
    if (_1167 > 3.1415927410125732421875)
    {
        _1842 = _1167 - 6.283185482025146484375;
    }
    else
    {
        _1842 = _1167;
    }
    float _1176 = _1842 * hexcParams.albedo_rotation;
    float _1178 = cos(_1176);
    float _1180 = sin(_1176);
    int _1186 = _1141.x;
    int _1188 = _1141.y;
    float _1201 = mod(float(abs(_1186 * _1188) + abs(_1186 + _1188)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _1843;
    if (_1201 > 3.1415927410125732421875)
    {
        _1843 = _1201 - 6.283185482025146484375;
    }
    else
    {
        _1843 = _1201;
    }
    float _1210 = _1843 * hexcParams.albedo_rotation;
    float _1212 = cos(_1210);
    float _1214 = sin(_1210);
    int _1220 = _1147.x;
    int _1222 = _1147.y;
    float _1235 = mod(float(abs(_1220 * _1222) + abs(_1220 + _1222)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _1844;
    if (_1235 > 3.1415927410125732421875)
    {
        _1844 = _1235 - 6.283185482025146484375;
    }
    else
    {
        _1844 = _1235;
    }
    float _1244 = _1844 * hexcParams.albedo_rotation;
    float _1246 = cos(_1244);
    float _1248 = sin(_1244);
    float _1257 = float(_1154);
    float2 _1264 = float2(fma(0.5, _1257, float(_1152)), _1257 * 0.866025447845458984375);
    float _1274 = float(_1188);
    float2 _1281 = float2(fma(0.5, _1274, float(_1186)), _1274 * 0.866025447845458984375);
    float _1291 = float(_1222);
    float2 _1298 = float2(fma(0.5, _1291, float(_1220)), _1291 * 0.866025447845458984375);
    float2 _1002 = fma(in.v_uv, hexcParams.albedo_tiling, _1264 * float2(-0.288675129413604736328125));
    float _1304 = _1002.x;
    float _1309 = _1002.y;
    float2 _1332 = float2(_1135);
    float2 _1015 = fma(in.v_uv, hexcParams.albedo_tiling, _1281 * float2(-0.288675129413604736328125));
    float _1345 = _1015.x;
    float _1350 = _1015.y;
    float2 _1373 = float2(_1141);
    float2 _1028 = fma(in.v_uv, hexcParams.albedo_tiling, _1298 * float2(-0.288675129413604736328125));
    float _1386 = _1028.x;
    float _1391 = _1028.y;
    float2 _1414 = float2(_1147);
    float _1427 = _963.x;
    float _1432 = _963.y;
    float _1439 = -_1427;
    float _1453 = _965.x;
    float _1458 = _965.y;
    float _1465 = -_1453;
    float4 _861 = hexcTex_albedo.sample(hexcSampler, (fma(_1264, float2(0.288675129413604736328125), float2(fma(_1304, _1178, _1309 * _1180), fma(-_1304, _1180, _1309 * _1178))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _1332), dot(float2(269.5, 183.3000030517578125), _1332))) * 43758.546875)), gradient2d(float2(fma(_1427, _1178, _1432 * _1180), fma(_1439, _1180, _1432 * _1178)), float2(fma(_1453, _1178, _1458 * _1180), fma(_1465, _1180, _1458 * _1178))));
    float4 _871 = hexcTex_albedo.sample(hexcSampler, (fma(_1281, float2(0.288675129413604736328125), float2(fma(_1345, _1212, _1350 * _1214), fma(-_1345, _1214, _1350 * _1212))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _1373), dot(float2(269.5, 183.3000030517578125), _1373))) * 43758.546875)), gradient2d(float2(fma(_1427, _1212, _1432 * _1214), fma(_1439, _1214, _1432 * _1212)), float2(fma(_1453, _1212, _1458 * _1214), fma(_1465, _1214, _1458 * _1212))));
    float4 _881 = hexcTex_albedo.sample(hexcSampler, (fma(_1298, float2(0.288675129413604736328125), float2(fma(_1386, _1246, _1391 * _1248), fma(-_1386, _1248, _1391 * _1246))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _1414), dot(float2(269.5, 183.3000030517578125), _1414))) * 43758.546875)), gradient2d(float2(fma(_1427, _1246, _1432 * _1248), fma(_1439, _1248, _1432 * _1246)), float2(fma(_1453, _1246, _1458 * _1248), fma(_1465, _1248, _1458 * _1246))));
    float3 _1594 = mix(float3(1.0), float3(dot(_861, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_871, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_881, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0))), float3(hexcParams.albedo_falloffcontrast)) * pow(float3(_1106 * _1110, fma(-_1095, _1110, _1107), fma(-_1094, _1110, _1107)), float3(hexcParams.albedo_exponent));
    float3 _1605 = _1594 / float3((_1594.x + _1594.y) + _1594.z);
    float3 _1975;
    if (hexcParams.albedo_falloff != 0.5)
    {
        float3 _1627 = step(float3(0.5), _1605) * 2.0;
        float3 _1631 = (float3(1.0) - _1627) * 2.0;
        float3 _1646 = fma(_1631 * 0.25, pow(fast::max(float3(0.0), fma(_1605, _1631, _1627)), float3(log(1.0 - hexcParams.albedo_falloff) * (-1.44269502162933349609375))), _1627 * 0.5);
        _1975 = _1646 / float3((_1646.x + _1646.y) + _1646.z);
    }
    else
    {
        _1975 = _1605;
    }
    out.o_color = ((_861 * _1975.x) + (_871 * _1975.y)) + (_881 * _1975.z);
    return out;
}

