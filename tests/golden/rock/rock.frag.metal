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
    float2 normal_tiling;
    float normal_rotation;
    float normal_falloff;
    float normal_falloffcontrast;
    float normal_exponent;
    float2 roughness_tiling;
    float roughness_rotation;
    float roughness_falloff;
    float roughness_falloffcontrast;
    float roughness_exponent;
};

struct main0_out
{
    float4 o_color [[color(0)]];
};

struct main0_in
{
    float2 v_uv [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant HexcParams& hexcParams [[buffer(0)]], texture2d<float> hexcTex_albedo [[texture(0)]], texture2d<float> hexcTex_normal [[texture(1)]], texture2d<float> hexcTex_roughness [[texture(2)]], sampler hexcSampler [[sampler(0)]])
{
    main0_out out = {};
    float2 _1247 = in.v_uv * hexcParams.albedo_tiling;
    float2 _1390 = dfdx(_1247);
    float2 _1392 = dfdy(_1247);
    float2 _1505 = _1247 * 3.4641015529632568359375;
    float _1509 = _1505.y;
    float2 _1515 = float2(fma(-0.57735025882720947265625, _1509, _1505.x), 1.1547005176544189453125 * _1509);
    int2 _1518 = int2(floor(_1515));
    float2 _1520 = fract(_1515);
    float _1521 = _1520.x;
    float _1522 = _1520.y;
    float _1533 = -((1.0 - _1521) - _1522);
    float _1534 = step(0.0, _1533);
    float _1537 = fma(2.0, _1534, -1.0);
    int _1557 = int(_1534);
    int2 _1562 = _1518 + int2(_1557);
    int _1566 = 1 - _1557;
    int2 _1568 = _1518 + int2(_1557, _1566);
    int2 _1574 = _1518 + int2(_1566, _1557);
    int _1579 = _1562.x;
    int _1581 = _1562.y;
    float _1594 = mod(float(abs(_1579 * _1581) + abs(_1579 + _1581)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _4621;
    if (_1594 > 3.1415927410125732421875)
    {
        _4621 = _1594 - 6.283185482025146484375;
    }
    else
    {
        _4621 = _1594;
    }
    float _1603 = _4621 * hexcParams.albedo_rotation;
    float _1605 = cos(_1603);
    float _1607 = sin(_1603);
    int _1613 = _1568.x;
    int _1615 = _1568.y;
    float _1628 = mod(float(abs(_1613 * _1615) + abs(_1613 + _1615)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _4622;
    if (_1628 > 3.1415927410125732421875)
    {
        _4622 = _1628 - 6.283185482025146484375;
    }
    else
    {
        _4622 = _1628;
    }
    float _1637 = _4622 * hexcParams.albedo_rotation;
    float _1639 = cos(_1637);
    float _1641 = sin(_1637);
    int _1647 = _1574.x;
    int _1649 = _1574.y;
    float _1662 = mod(float(abs(_1647 * _1649) + abs(_1647 + _1649)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _4623;
    if (_1662 > 3.1415927410125732421875)
    {
        _4623 = _1662 - 6.283185482025146484375;
    }
    else
    {
        _4623 = _1662;
    }
    float _1671 = _4623 * hexcParams.albedo_rotation;
    float _1673 = cos(_1671);
    float _1675 = sin(_1671);
    float _1684 = float(_1581);
    float2 _1691 = float2(fma(0.5, _1684, float(_1579)), _1684 * 0.866025447845458984375);
    float _1701 = float(_1615);
    float2 _1708 = float2(fma(0.5, _1701, float(_1613)), _1701 * 0.866025447845458984375);
    float _1718 = float(_1649);
    float2 _1725 = float2(fma(0.5, _1718, float(_1647)), _1718 * 0.866025447845458984375);
    float2 _1429 = fma(in.v_uv, hexcParams.albedo_tiling, _1691 * float2(-0.288675129413604736328125));
    float _1731 = _1429.x;
    float _1736 = _1429.y;
    float2 _1759 = float2(_1562);
    float2 _1442 = fma(in.v_uv, hexcParams.albedo_tiling, _1708 * float2(-0.288675129413604736328125));
    float _1772 = _1442.x;
    float _1777 = _1442.y;
    float2 _1800 = float2(_1568);
    float2 _1455 = fma(in.v_uv, hexcParams.albedo_tiling, _1725 * float2(-0.288675129413604736328125));
    float _1813 = _1455.x;
    float _1818 = _1455.y;
    float2 _1841 = float2(_1574);
    float _1854 = _1390.x;
    float _1859 = _1390.y;
    float _1866 = -_1854;
    float _1880 = _1392.x;
    float _1885 = _1392.y;
    float _1892 = -_1880;
    float4 _1288 = hexcTex_albedo.sample(hexcSampler, (fma(_1691, float2(0.288675129413604736328125), float2(fma(_1731, _1605, _1736 * _1607), fma(-_1731, _1607, _1736 * _1605))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _1759), dot(float2(269.5, 183.3000030517578125), _1759))) * 43758.546875)), gradient2d(float2(fma(_1854, _1605, _1859 * _1607), fma(_1866, _1607, _1859 * _1605)), float2(fma(_1880, _1605, _1885 * _1607), fma(_1892, _1607, _1885 * _1605))));
    float4 _1298 = hexcTex_albedo.sample(hexcSampler, (fma(_1708, float2(0.288675129413604736328125), float2(fma(_1772, _1639, _1777 * _1641), fma(-_1772, _1641, _1777 * _1639))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _1800), dot(float2(269.5, 183.3000030517578125), _1800))) * 43758.546875)), gradient2d(float2(fma(_1854, _1639, _1859 * _1641), fma(_1866, _1641, _1859 * _1639)), float2(fma(_1880, _1639, _1885 * _1641), fma(_1892, _1641, _1885 * _1639))));
    float4 _1308 = hexcTex_albedo.sample(hexcSampler, (fma(_1725, float2(0.288675129413604736328125), float2(fma(_1813, _1673, _1818 * _1675), fma(-_1813, _1675, _1818 * _1673))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _1841), dot(float2(269.5, 183.3000030517578125), _1841))) * 43758.546875)), gradient2d(float2(fma(_1854, _1673, _1859 * _1675), fma(_1866, _1675, _1859 * _1673)), float2(fma(_1880, _1673, _1885 * _1675), fma(_1892, _1675, _1885 * _1673))));
    float3 _2021 = mix(float3(1.0), float3(dot(_1288, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_1298, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0)), dot(_1308, float4(0.2989999949932098388671875, 0.58700001239776611328125, 0.114000000059604644775390625, 0.0))), float3(hexcParams.albedo_falloffcontrast)) * pow(float3(_1533 * _1537, fma(-_1522, _1537, _1534), fma(-_1521, _1537, _1534)), float3(hexcParams.albedo_exponent));
    float3 _2032 = _2021 / float3((_2021.x + _2021.y) + _2021.z);
    float3 _5057;
    if (hexcParams.albedo_falloff != 0.5)
    {
        float3 _2054 = step(float3(0.5), _2032) * 2.0;
        float3 _2058 = (float3(1.0) - _2054) * 2.0;
        float3 _2073 = fma(_2058 * 0.25, pow(fast::max(float3(0.0), fma(_2032, _2058, _2054)), float3(log(1.0 - hexcParams.albedo_falloff) * (-1.44269502162933349609375))), _2054 * 0.5);
        _5057 = _2073 / float3((_2073.x + _2073.y) + _2073.z);
    }
    else
    {
        _5057 = _2032;
    }
    float2 _2234 = in.v_uv * hexcParams.roughness_tiling;
    float2 _2378 = dfdx(_2234);
    float2 _2380 = dfdy(_2234);
    float2 _2493 = _2234 * 3.4641015529632568359375;
    float _2497 = _2493.y;
    float2 _2503 = float2(fma(-0.57735025882720947265625, _2497, _2493.x), 1.1547005176544189453125 * _2497);
    int2 _2506 = int2(floor(_2503));
    float2 _2508 = fract(_2503);
    float _2509 = _2508.x;
    float _2510 = _2508.y;
    float _2521 = -((1.0 - _2509) - _2510);
    float _2522 = step(0.0, _2521);
    float _2525 = fma(2.0, _2522, -1.0);
    int _2545 = int(_2522);
    int2 _2550 = _2506 + int2(_2545);
    int _2554 = 1 - _2545;
    int2 _2556 = _2506 + int2(_2545, _2554);
    int2 _2562 = _2506 + int2(_2554, _2545);
    int _2567 = _2550.x;
    int _2569 = _2550.y;
    float _2582 = mod(float(abs(_2567 * _2569) + abs(_2567 + _2569)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _4624;
    if (_2582 > 3.1415927410125732421875)
    {
        _4624 = _2582 - 6.283185482025146484375;
    }
    else
    {
        _4624 = _2582;
    }
    float _2591 = _4624 * hexcParams.roughness_rotation;
    float _2593 = cos(_2591);
    float _2595 = sin(_2591);
    int _2601 = _2556.x;
    int _2603 = _2556.y;
    float _2616 = mod(float(abs(_2601 * _2603) + abs(_2601 + _2603)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _4625;
    if (_2616 > 3.1415927410125732421875)
    {
        _4625 = _2616 - 6.283185482025146484375;
    }
    else
    {
        _4625 = _2616;
    }
    float _2625 = _4625 * hexcParams.roughness_rotation;
    float _2627 = cos(_2625);
    float _2629 = sin(_2625);
    int _2635 = _2562.x;
    int _2637 = _2562.y;
    float _2650 = mod(float(abs(_2635 * _2637) + abs(_2635 + _2637)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _4626;
    if (_2650 > 3.1415927410125732421875)
    {
        _4626 = _2650 - 6.283185482025146484375;
    }
    else
    {
        _4626 = _2650;
    }
    float _2659 = _4626 * hexcParams.roughness_rotation;
    float _2661 = cos(_2659);
    float _2663 = sin(_2659);
    float _2672 = float(_2569);
    float2 _2679 = float2(fma(0.5, _2672, float(_2567)), _2672 * 0.866025447845458984375);
    float _2689 = float(_2603);
    float2 _2696 = float2(fma(0.5, _2689, float(_2601)), _2689 * 0.866025447845458984375);
    float _2706 = float(_2637);
    float2 _2713 = float2(fma(0.5, _2706, float(_2635)), _2706 * 0.866025447845458984375);
    float2 _2417 = fma(in.v_uv, hexcParams.roughness_tiling, _2679 * float2(-0.288675129413604736328125));
    float _2719 = _2417.x;
    float _2724 = _2417.y;
    float2 _2747 = float2(_2550);
    float2 _2430 = fma(in.v_uv, hexcParams.roughness_tiling, _2696 * float2(-0.288675129413604736328125));
    float _2760 = _2430.x;
    float _2765 = _2430.y;
    float2 _2788 = float2(_2556);
    float2 _2443 = fma(in.v_uv, hexcParams.roughness_tiling, _2713 * float2(-0.288675129413604736328125));
    float _2801 = _2443.x;
    float _2806 = _2443.y;
    float2 _2829 = float2(_2562);
    float _2842 = _2378.x;
    float _2847 = _2378.y;
    float _2854 = -_2842;
    float _2868 = _2380.x;
    float _2873 = _2380.y;
    float _2880 = -_2868;
    float4 _2276 = hexcTex_roughness.sample(hexcSampler, (fma(_2679, float2(0.288675129413604736328125), float2(fma(_2719, _2593, _2724 * _2595), fma(-_2719, _2595, _2724 * _2593))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _2747), dot(float2(269.5, 183.3000030517578125), _2747))) * 43758.546875)), gradient2d(float2(fma(_2842, _2593, _2847 * _2595), fma(_2854, _2595, _2847 * _2593)), float2(fma(_2868, _2593, _2873 * _2595), fma(_2880, _2595, _2873 * _2593))));
    float4 _2286 = hexcTex_roughness.sample(hexcSampler, (fma(_2696, float2(0.288675129413604736328125), float2(fma(_2760, _2627, _2765 * _2629), fma(-_2760, _2629, _2765 * _2627))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _2788), dot(float2(269.5, 183.3000030517578125), _2788))) * 43758.546875)), gradient2d(float2(fma(_2842, _2627, _2847 * _2629), fma(_2854, _2629, _2847 * _2627)), float2(fma(_2868, _2627, _2873 * _2629), fma(_2880, _2629, _2873 * _2627))));
    float4 _2296 = hexcTex_roughness.sample(hexcSampler, (fma(_2713, float2(0.288675129413604736328125), float2(fma(_2801, _2661, _2806 * _2663), fma(-_2801, _2663, _2806 * _2661))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _2829), dot(float2(269.5, 183.3000030517578125), _2829))) * 43758.546875)), gradient2d(float2(fma(_2842, _2661, _2847 * _2663), fma(_2854, _2663, _2847 * _2661)), float2(fma(_2868, _2661, _2873 * _2663), fma(_2880, _2663, _2873 * _2661))));
    float3 _3009 = mix(float3(1.0), float3(_2276.x, _2286.x, _2296.x), float3(hexcParams.roughness_falloffcontrast)) * pow(float3(_2521 * _2525, fma(-_2510, _2525, _2522), fma(-_2509, _2525, _2522)), float3(hexcParams.roughness_exponent));
    float3 _3020 = _3009 / float3((_3009.x + _3009.y) + _3009.z);
    float3 _5058;
    if (hexcParams.roughness_falloff != 0.5)
    {
        float3 _3042 = step(float3(0.5), _3020) * 2.0;
        float3 _3046 = (float3(1.0) - _3042) * 2.0;
        float3 _3061 = fma(_3046 * 0.25, pow(fast::max(float3(0.0), fma(_3020, _3046, _3042)), float3(log(1.0 - hexcParams.roughness_falloff) * (-1.44269502162933349609375))), _3042 * 0.5);
        _5058 = _3061 / float3((_3061.x + _3061.y) + _3061.z);
    }
    else
    {
        _5058 = _3020;
    }
    float _1125 = fast::clamp((((_2276 * _5058.x) + (_2286 * _5058.y)) + (_2296 * _5058.z)).x, 0.0199999995529651641845703125, 1.0);
    float3 _1130 = fast::normalize(in.v_normal);
    float3 _1143 = fast::normalize(in.v_tangent.xyz - (_1130 * dot(_1130, in.v_tangent.xyz)));
    float2 _3222 = in.v_uv * hexcParams.normal_tiling;
    float2 _3391 = dfdx(_3222);
    float2 _3393 = dfdy(_3222);
    float2 _3506 = _3222 * 3.4641015529632568359375;
    float _3510 = _3506.y;
    float2 _3516 = float2(fma(-0.57735025882720947265625, _3510, _3506.x), 1.1547005176544189453125 * _3510);
    int2 _3519 = int2(floor(_3516));
    float2 _3521 = fract(_3516);
    float _3522 = _3521.x;
    float _3523 = _3521.y;
    float _3534 = -((1.0 - _3522) - _3523);
    float _3535 = step(0.0, _3534);
    float _3538 = fma(2.0, _3535, -1.0);
    int _3558 = int(_3535);
    int2 _3563 = _3519 + int2(_3558);
    int _3567 = 1 - _3558;
    int2 _3569 = _3519 + int2(_3558, _3567);
    int2 _3575 = _3519 + int2(_3567, _3558);
    int _3580 = _3563.x;
    int _3582 = _3563.y;
    float _3595 = mod(float(abs(_3580 * _3582) + abs(_3580 + _3582)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _4627;
    if (_3595 > 3.1415927410125732421875)
    {
        _4627 = _3595 - 6.283185482025146484375;
    }
    else
    {
        _4627 = _3595;
    }
    float _3604 = _4627 * hexcParams.normal_rotation;
    float _3606 = cos(_3604);
    float _3608 = sin(_3604);
    int _3614 = _3569.x;
    int _3616 = _3569.y;
    float _3629 = mod(float(abs(_3614 * _3616) + abs(_3614 + _3616)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _4628;
    if (_3629 > 3.1415927410125732421875)
    {
        _4628 = _3629 - 6.283185482025146484375;
    }
    else
    {
        _4628 = _3629;
    }
    float _3638 = _4628 * hexcParams.normal_rotation;
    float _3640 = cos(_3638);
    float _3642 = sin(_3638);
    int _3648 = _3575.x;
    int _3650 = _3575.y;
    float _3663 = mod(float(abs(_3648 * _3650) + abs(_3648 + _3650)) + 3.1415927410125732421875, 6.283185482025146484375);
    float _4629;
    if (_3663 > 3.1415927410125732421875)
    {
        _4629 = _3663 - 6.283185482025146484375;
    }
    else
    {
        _4629 = _3663;
    }
    float _3672 = _4629 * hexcParams.normal_rotation;
    float _3674 = cos(_3672);
    float _3676 = sin(_3672);
    float _3685 = float(_3582);
    float2 _3692 = float2(fma(0.5, _3685, float(_3580)), _3685 * 0.866025447845458984375);
    float _3702 = float(_3616);
    float2 _3709 = float2(fma(0.5, _3702, float(_3614)), _3702 * 0.866025447845458984375);
    float _3719 = float(_3650);
    float2 _3726 = float2(fma(0.5, _3719, float(_3648)), _3719 * 0.866025447845458984375);
    float2 _3430 = fma(in.v_uv, hexcParams.normal_tiling, _3692 * float2(-0.288675129413604736328125));
    float _3732 = _3430.x;
    float _3737 = _3430.y;
    float2 _3760 = float2(_3563);
    float2 _3443 = fma(in.v_uv, hexcParams.normal_tiling, _3709 * float2(-0.288675129413604736328125));
    float _3773 = _3443.x;
    float _3778 = _3443.y;
    float2 _3801 = float2(_3569);
    float2 _3456 = fma(in.v_uv, hexcParams.normal_tiling, _3726 * float2(-0.288675129413604736328125));
    float _3814 = _3456.x;
    float _3819 = _3456.y;
    float2 _3842 = float2(_3575);
    float _3855 = _3391.x;
    float _3860 = _3391.y;
    float _3867 = -_3855;
    float _3881 = _3393.x;
    float _3886 = _3393.y;
    float _3893 = -_3881;
    float3 _4023 = (hexcTex_normal.sample(hexcSampler, (fma(_3692, float2(0.288675129413604736328125), float2(fma(_3732, _3606, _3737 * _3608), fma(-_3732, _3608, _3737 * _3606))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _3760), dot(float2(269.5, 183.3000030517578125), _3760))) * 43758.546875)), gradient2d(float2(fma(_3855, _3606, _3860 * _3608), fma(_3867, _3608, _3860 * _3606)), float2(fma(_3881, _3606, _3886 * _3608), fma(_3893, _3608, _3886 * _3606)))).xyz * 2.0) - float3(1.0);
    float3 _4033 = abs(_4023);
    float2 _4059 = (-float2(_4023.xy)) / float2(fast::max(_4033.z, 0.0078125 * fast::max(_4033.x, _4033.y)));
    float _4065 = _4059.x;
    float _4070 = _4059.y;
    float2 _4084 = float2(fma(_3606, _4065, -(_3608 * _4070)), fma(_3608, _4065, _3606 * _4070));
    float3 _4100 = (hexcTex_normal.sample(hexcSampler, (fma(_3709, float2(0.288675129413604736328125), float2(fma(_3773, _3640, _3778 * _3642), fma(-_3773, _3642, _3778 * _3640))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _3801), dot(float2(269.5, 183.3000030517578125), _3801))) * 43758.546875)), gradient2d(float2(fma(_3855, _3640, _3860 * _3642), fma(_3867, _3642, _3860 * _3640)), float2(fma(_3881, _3640, _3886 * _3642), fma(_3893, _3642, _3886 * _3640)))).xyz * 2.0) - float3(1.0);
    float3 _4110 = abs(_4100);
    float2 _4136 = (-float2(_4100.xy)) / float2(fast::max(_4110.z, 0.0078125 * fast::max(_4110.x, _4110.y)));
    float _4142 = _4136.x;
    float _4147 = _4136.y;
    float2 _4161 = float2(fma(_3640, _4142, -(_3642 * _4147)), fma(_3642, _4142, _3640 * _4147));
    float3 _4177 = (hexcTex_normal.sample(hexcSampler, (fma(_3726, float2(0.288675129413604736328125), float2(fma(_3814, _3674, _3819 * _3676), fma(-_3814, _3676, _3819 * _3674))) + fract(sin(float2(dot(float2(127.09999847412109375, 311.70001220703125), _3842), dot(float2(269.5, 183.3000030517578125), _3842))) * 43758.546875)), gradient2d(float2(fma(_3855, _3674, _3860 * _3676), fma(_3867, _3676, _3860 * _3674)), float2(fma(_3881, _3674, _3886 * _3676), fma(_3893, _3676, _3886 * _3674)))).xyz * 2.0) - float3(1.0);
    float3 _4187 = abs(_4177);
    float2 _4213 = (-float2(_4177.xy)) / float2(fast::max(_4187.z, 0.0078125 * fast::max(_4187.x, _4187.y)));
    float _4219 = _4213.x;
    float _4224 = _4213.y;
    float2 _4238 = float2(fma(_3674, _4219, -(_3676 * _4224)), fma(_3676, _4219, _3674 * _4224));
    float3 _3314 = float3(dot(_4084, _4084), dot(_4161, _4161), dot(_4238, _4238));
    float3 _4253 = mix(float3(1.0), sqrt(_3314 / (float3(1.0) + _3314)), float3(hexcParams.normal_falloffcontrast)) * pow(float3(_3534 * _3538, fma(-_3523, _3538, _3535), fma(-_3522, _3538, _3535)), float3(hexcParams.normal_exponent));
    float3 _4264 = _4253 / float3((_4253.x + _4253.y) + _4253.z);
    float3 _5059;
    if (hexcParams.normal_falloff != 0.5)
    {
        float3 _4286 = step(float3(0.5), _4264) * 2.0;
        float3 _4290 = (float3(1.0) - _4286) * 2.0;
        float3 _4305 = fma(_4290 * 0.25, pow(fast::max(float3(0.0), fma(_4264, _4290, _4286)), float3(log(1.0 - hexcParams.normal_falloff) * (-1.44269502162933349609375))), _4286 * 0.5);
        _5059 = _4305 / float3((_4305.x + _4305.y) + _4305.z);
    }
    else
    {
        _5059 = _4264;
    }
    float3 _4453 = fast::normalize(float3(-(((_4084 * _5059.x) + (_4161 * _5059.y)) + (_4238 * _5059.z)), 1.0));
    float3 _1173 = fast::normalize(((_1143 * _4453.x) + ((cross(_1130, _1143) * in.v_tangent.w) * _4453.y)) + (_1130 * _4453.z));
    float _1180 = fast::max(dot(_1173, float3(0.408248007297515869140625, 0.408248007297515869140625, 0.816497027873992919921875)), 0.0);
    float _1193 = 2.0 / (((_1125 * _1125) * _1125) * _1125);
    out.o_color = float4(((((_1288 * _5057.x) + (_1298 * _5057.y)) + (_1308 * _5057.z)).xyz * (0.1500000059604644775390625 + _1180)) + float3(0.039999999105930328369140625 * (((pow(fast::max(dot(_1173, float3(0.21418631076812744140625, 0.21418631076812744140625, 0.95302069187164306640625)), 0.0), _1193 - 2.0) * (_1193 + 6.0)) * 0.0397887341678142547607421875) * _1180)), 1.0);
    return out;
}

