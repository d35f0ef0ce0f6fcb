#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct HexcParams
{
    float2 albedo_tiling;
    float albedo_falloffcontrast;
};

constant uint _2853 = {};

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
    float2 _1178 = in.v_uv * hexcParams.albedo_tiling;
    float2 _1193 = dfdx(_1178);
    float2 _1195 = dfdy(_1178);
    float _1267 = _1178.x;
    float _1269 = floor(_1267 * 0.0357142873108386993408203125);
    float _1271 = _1178.y;
    float _1272 = floor(_1271);
    float _1277 = fma(-28.0, _1269, _1267);
    float _1281 = _1271 - _1272;
    float2 _1282 = float2(_1277, _1281);
    float2 _1293 = float2(fma(3.4642856121063232421875, _1277, _1281 * (-2.0)), 4.0 * _1281);
    float2 _1483 = floor(_1293);
    int2 _1484 = int2(_1483);
    float2 _1488 = _1293 - _1483;
    float _1489 = _1488.x;
    float _1490 = _1488.y;
    float _1501 = -((1.0 - _1489) - _1490);
    float _1502 = step(0.0, _1501);
    float _1505 = fma(2.0, _1502, -1.0);
    float3 _1523 = float3(_1501 * _1505, fma(-_1490, _1505, _1502), fma(-_1489, _1505, _1502));
    int _1525 = int(_1502);
    int2 _1530 = _1484 + int2(_1525);
    int _1534 = 1 - _1525;
    int2 _1536 = _1484 + int2(_1525, _1534);
    int2 _1542 = _1484 + int2(_1534, _1525);
    uint _1307 = uint(int(_1272));
    uint2 _1314 = uint2((97u * uint(int(_1269))) - (2u * _1307), 4u * _1307);
    uint3 _1584 = (uint3(uint2(int2(uint2(_1530) + _1314)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1586 = _1584.y;
    uint _1588 = _1584.z;
    uint _1592 = _1584.x + (_1586 * _1588);
    uint _1601 = _1586 + (_1588 * _1592);
    uint3 _2847 = uint3(_1592, _1601, _1588 + (_1592 * _1601));
    uint3 _1616 = _2847 ^ (_2847 >> uint3(16u));
    uint _1618 = _1616.y;
    uint _1620 = _1616.z;
    uint _1624 = _1616.x + (_1618 * _1620);
    uint3 _1686 = (uint3(uint2(int2(uint2(_1536) + _1314)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1688 = _1686.y;
    uint _1690 = _1686.z;
    uint _1694 = _1686.x + (_1688 * _1690);
    uint _1703 = _1688 + (_1690 * _1694);
    uint3 _2849 = uint3(_1694, _1703, _1690 + (_1694 * _1703));
    uint3 _1718 = _2849 ^ (_2849 >> uint3(16u));
    uint _1720 = _1718.y;
    uint _1722 = _1718.z;
    uint _1726 = _1718.x + (_1720 * _1722);
    uint3 _1788 = (uint3(uint2(int2(uint2(_1542) + _1314)), 0u) * uint3(1664525u)) + uint3(1013904223u);
    uint _1790 = _1788.y;
    uint _1792 = _1788.z;
    uint _1796 = _1788.x + (_1790 * _1792);
    uint _1805 = _1790 + (_1792 * _1796);
    uint3 _2851 = uint3(_1796, _1805, _1792 + (_1796 * _1805));
    uint3 _1820 = _2851 ^ (_2851 >> uint3(16u));
    uint _1822 = _1820.y;
    uint _1824 = _1820.z;
    uint _1828 = _1820.x + (_1822 * _1824);
    float _1856 = float(_1530.y);
    float _1872 = float(_1536.y);
    float _1888 = float(_1542.y);
    float4 _2159 = hexcTex_albedo.sample(hexcSampler, ((_1282 - float2(fma(0.5, _1856, float(_1530.x)) * 0.2886598110198974609375, 0.25 * _1856)) + (float2((uint3(_1624, _1618 + (_1620 * _1624), _2853) >> uint3(8u)).xy) * 5.9604644775390625e-08)), gradient2d(_1193, _1195));
    float4 _2169 = hexcTex_albedo.sample(hexcSampler, ((_1282 - float2(fma(0.5, _1872, float(_1536.x)) * 0.2886598110198974609375, 0.25 * _1872)) + (float2((uint3(_1726, _1720 + (_1722 * _1726), _2853) >> uint3(8u)).xy) * 5.9604644775390625e-08)), gradient2d(_1193, _1195));
    float4 _2179 = hexcTex_albedo.sample(hexcSampler, ((_1282 - float2(fma(0.5, _1888, float(_1542.x)) * 0.2886598110198974609375, 0.25 * _1888)) + (float2((uint3(_1828, _1822 + (_1824 * _1828), _2853) >> uint3(8u)).xy) * 5.9604644775390625e-08)), gradient2d(_1193, _1195));
    float3 _2318 = _1523 * _1523;
    float3 _2336 = (_1523 * _2318) * (_2318 * _2318);
    float3 _2255 = mix(float3(1.0), fast::max(float3(dot(_2159, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_2169, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_2179, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0))), float3(0.0)), float3(hexcParams.albedo_falloffcontrast)) * _2336;
    float _2267 = (_2255.x + _2255.y) + _2255.z;
    float3 _2691;
    if (_2267 > 0.0)
    {
        _2691 = _2255 / float3(_2267);
    }
    else
    {
        _2691 = _2336 / float3((_2336.x + _2336.y) + _2336.z);
    }
    float3 _2387 = step(float3(0.5), _2691) * 2.0;
    float3 _2391 = (float3(1.0) - _2387) * 2.0;
    float3 _2397 = fast::max(float3(0.0), fma(_2691, _2391, _2387));
    float3 _2416 = fma(_2391 * 0.25, _2397 * _2397, _2387 * 0.5);
    float3 _2427 = _2416 / float3((_2416.x + _2416.y) + _2416.z);
    out.o_color = ((_2159 * _2427.x) + (_2169 * _2427.y)) + (_2179 * _2427.z);
    return out;
}

