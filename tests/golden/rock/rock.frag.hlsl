cbuffer HexcParams : register(b0)
{
    float2 hexcParams_albedo_tiling : packoffset(c0);
    float hexcParams_albedo_rotation : packoffset(c0.z);
    float hexcParams_albedo_falloff : packoffset(c0.w);
    float hexcParams_albedo_falloffcontrast : packoffset(c1);
    float hexcParams_albedo_exponent : packoffset(c1.y);
    float2 hexcParams_normal_tiling : packoffset(c1.z);
    float hexcParams_normal_rotation : packoffset(c2);
    float hexcParams_normal_falloff : packoffset(c2.y);
    float hexcParams_normal_falloffcontrast : packoffset(c2.z);
    float hexcParams_normal_exponent : packoffset(c2.w);
    float2 hexcParams_roughness_tiling : packoffset(c3);
    float hexcParams_roughness_rotation : packoffset(c3.z);
    float hexcParams_roughness_falloff : packoffset(c3.w);
    float hexcParams_roughness_falloffcontrast : packoffset(c4);
    float hexcParams_roughness_exponent : packoffset(c4.y);
};

Texture2D<float4> hexcTex_albedo : register(t0);
SamplerState hexcSampler : register(s0);
Texture2D<float4> hexcTex_normal : register(t1);
Texture2D<float4> hexcTex_roughness : register(t2);

static float2 v_uv;
static float3 v_normal;
static float4 v_tangent;
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
    float2 _1247 = v_uv * hexcParams_albedo_tiling;
    float2 _1390 = ddx(_1247);
    float2 _1392 = ddy(_1247);
    float2 _1505 = _1247 * 3.4641015529632568359375f;
    float _1509 = _1505.y;
    float2 _1515 = float2(mad(-0.57735025882720947265625f, _1509, _1505.x), 1.1547005176544189453125f * _1509);
    int2 _1518 = int2(floor(_1515));
    float2 _1520 = frac(_1515);
    float _1521 = _1520.x;
    float _1522 = _1520.y;
    float _1533 = -((1.0f - _1521) - _1522);
    float _1534 = step(0.0f, _1533);
    float _1537 = mad(2.0f, _1534, -1.0f);
    int _1557 = int(_1534);
    int2 _1562 = _1518 + _1557.xx;
    int _1566 = 1 - _1557;
    int2 _1568 = _1518 + int2(_1557, _1566);
    int2 _1574 = _1518 + int2(_1566, _1557);
    int _1579 = _1562.x;
    int _1581 = _1562.y;
    float _1594 = mod(float(abs(_1579 * _1581) + abs(_1579 + _1581)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _4621;
    if (_1594 > 3.1415927410125732421875f)
    {
        _4621 = _1594 - 6.283185482025146484375f;
    }
    else
    {
        _4621 = _1594;
    }
    float _1603 = _4621 * hexcParams_albedo_rotation;
    float _1605 = cos(_1603);
    float _1607 = sin(_1603);
    int _1613 = _1568.x;
    int _1615 = _1568.y;
    float _1628 = mod(float(abs(_1613 * _1615) + abs(_1613 + _1615)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _4622;
    if (_1628 > 3.1415927410125732421875f)
    {
        _4622 = _1628 - 6.283185482025146484375f;
    }
    else
    {
        _4622 = _1628;
    }
    float _1637 = _4622 * hexcParams_albedo_rotation;
    float _1639 = cos(_1637);
    float _1641 = sin(_1637);
    int _1647 = _1574.x;
    int _1649 = _1574.y;
    float _1662 = mod(float(abs(_1647 * _1649) + abs(_1647 + _1649)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _4623;
    if (_1662 > 3.1415927410125732421875f)
    {
        _4623 = _1662 - 6.283185482025146484375f;
    }
    else
    {
        _4623 = _1662;
    }
    float _1671 = _4623 * hexcParams_albedo_rotation;
    float _1673 = cos(_1671);
    float _1675 = sin(_1671);
    float _1684 = float(_1581);
    float2 _1691 = float2(mad(0.5f, _1684, float(_1579)), _1684 * 0.866025447845458984375f);
    float _1701 = float(_1615);
    float2 _1708 = float2(mad(0.5f, _1701, float(_1613)), _1701 * 0.866025447845458984375f);
    float _1718 = float(_1649);
    float2 _1725 = float2(mad(0.5f, _1718, float(_1647)), _1718 * 0.866025447845458984375f);
    float2 _1429 = mad(v_uv, hexcParams_albedo_tiling, _1691 * (-0.288675129413604736328125f).xx);
    float _1731 = _1429.x;
    float _1736 = _1429.y;
    float2 _1759 = float2(_1562);
    float2 _1442 = mad(v_uv, hexcParams_albedo_tiling, _1708 * (-0.288675129413604736328125f).xx);
    float _1772 = _1442.x;
    float _1777 = _1442.y;
    float2 _1800 = float2(_1568);
    float2 _1455 = mad(v_uv, hexcParams_albedo_tiling, _1725 * (-0.288675129413604736328125f).xx);
    float _1813 = _1455.x;
    float _1818 = _1455.y;
    float2 _1841 = float2(_1574);
    float _1854 = _1390.x;
    float _1859 = _1390.y;
    float _1866 = -_1854;
    float _1880 = _1392.x;
    float _1885 = _1392.y;
    float _1892 = -_1880;
    float4 _1288 = hexcTex_albedo.SampleGrad(hexcSampler, mad(_1691, 0.288675129413604736328125f.xx, float2(mad(_1731, _1605, _1736 * _1607), mad(-_1731, _1607, _1736 * _1605))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _1759), dot(float2(269.5f, 183.3000030517578125f), _1759))) * 43758.546875f), float2(mad(_1854, _1605, _1859 * _1607), mad(_1866, _1607, _1859 * _1605)), float2(mad(_1880, _1605, _1885 * _1607), mad(_1892, _1607, _1885 * _1605)));
    float4 _1298 = hexcTex_albedo.SampleGrad(hexcSampler, mad(_1708, 0.288675129413604736328125f.xx, float2(mad(_1772, _1639, _1777 * _1641), mad(-_1772, _1641, _1777 * _1639))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _1800), dot(float2(269.5f, 183.3000030517578125f), _1800))) * 43758.546875f), float2(mad(_1854, _1639, _1859 * _1641), mad(_1866, _1641, _1859 * _1639)), float2(mad(_1880, _1639, _1885 * _1641), mad(_1892, _1641, _1885 * _1639)));
    float4 _1308 = hexcTex_albedo.SampleGrad(hexcSampler, mad(_1725, 0.288675129413604736328125f.xx, float2(mad(_1813, _1673, _1818 * _1675), mad(-_1813, _1675, _1818 * _1673))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _1841), dot(float2(269.5f, 183.3000030517578125f), _1841))) * 43758.546875f), float2(mad(_1854, _1673, _1859 * _1675), mad(_1866, _1675, _1859 * _1673)), float2(mad(_1880, _1673, _1885 * _1675), mad(_1892, _1675, _1885 * _1673)));
    float3 _2021 = lerp(1.0f.xxx, float3(dot(_1288, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_1298, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f)), dot(_1308, float4(0.2989999949932098388671875f, 0.58700001239776611328125f, 0.114000000059604644775390625f, 0.0f))), hexcParams_albedo_falloffcontrast.xxx) * pow(float3(_1533 * _1537, mad(-_1522, _1537, _1534), mad(-_1521, _1537, _1534)), hexcParams_albedo_exponent.xxx);
    float3 _2032 = _2021 / ((_2021.x + _2021.y) + _2021.z).xxx;
    float3 _5057;
    if (hexcParams_albedo_falloff != 0.5f)
    {
        float3 _2054 = step(0.5f.xxx, _2032) * 2.0f;
        float3 _2058 = (1.0f.xxx - _2054) * 2.0f;
        float3 _2073 = mad(_2058 * 0.25f, pow(max(0.0f.xxx, mad(_2032, _2058, _2054)), (log(1.0f - hexcParams_albedo_falloff) * (-1.44269502162933349609375f)).xxx), _2054 * 0.5f);
        _5057 = _2073 / ((_2073.x + _2073.y) + _2073.z).xxx;
    }
    else
    {
        _5057 = _2032;
    }
    float2 _2234 = v_uv * hexcParams_roughness_tiling;
    float2 _2378 = ddx(_2234);
    float2 _2380 = ddy(_2234);
    float2 _2493 = _2234 * 3.4641015529632568359375f;
    float _2497 = _2493.y;
    float2 _2503 = float2(mad(-0.57735025882720947265625f, _2497, _2493.x), 1.1547005176544189453125f * _2497);
    int2 _2506 = int2(floor(_2503));
    float2 _2508 = frac(_2503);
    float _2509 = _2508.x;
    float _2510 = _2508.y;
    float _2521 = -((1.0f - _2509) - _2510);
    float _2522 = step(0.0f, _2521);
    float _2525 = mad(2.0f, _2522, -1.0f);
    int _2545 = int(_2522);
    int2 _2550 = _2506 + _2545.xx;
    int _2554 = 1 - _2545;
    int2 _2556 = _2506 + int2(_2545, _2554);
    int2 _2562 = _2506 + int2(_2554, _2545);
    int _2567 = _2550.x;
    int _2569 = _2550.y;
    float _2582 = mod(float(abs(_2567 * _2569) + abs(_2567 + _2569)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _4624;
    if (_2582 > 3.1415927410125732421875f)
    {
        _4624 = _2582 - 6.283185482025146484375f;
    }
    else
    {
        _4624 = _2582;
    }
    float _2591 = _4624 * hexcParams_roughness_rotation;
    float _2593 = cos(_2591);
    float _2595 = sin(_2591);
    int _2601 = _2556.x;
    int _2603 = _2556.y;
    float _2616 = mod(float(abs(_2601 * _2603) + abs(_2601 + _2603)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _4625;
    if (_2616 > 3.1415927410125732421875f)
    {
        _4625 = _2616 - 6.283185482025146484375f;
    }
    else
    {
        _4625 = _2616;
    }
    float _2625 = _4625 * hexcParams_roughness_rotation;
    float _2627 = cos(_2625);
    float _2629 = sin(_2625);
    int _2635 = _2562.x;
    int _2637 = _2562.y;
    float _2650 = mod(float(abs(_2635 * _2637) + abs(_2635 + _2637)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _4626;
    if (_2650 > 3.1415927410125732421875f)
    {
        _4626 = _2650 - 6.283185482025146484375f;
    }
    else
    {
        _4626 = _2650;
    }
    float _2659 = _4626 * hexcParams_roughness_rotation;
    float _2661 = cos(_2659);
    float _2663 = sin(_2659);
    float _2672 = float(_2569);
    float2 _2679 = float2(mad(0.5f, _2672, float(_2567)), _2672 * 0.866025447845458984375f);
    float _2689 = float(_2603);
    float2 _2696 = float2(mad(0.5f, _2689, float(_2601)), _2689 * 0.866025447845458984375f);
    float _2706 = float(_2637);
    float2 _2713 = float2(mad(0.5f, _2706, float(_2635)), _2706 * 0.866025447845458984375f);
    float2 _2417 = mad(v_uv, hexcParams_roughness_tiling, _2679 * (-0.288675129413604736328125f).xx);
    float _2719 = _2417.x;
    float _2724 = _2417.y;
    float2 _2747 = float2(_2550);
    float2 _2430 = mad(v_uv, hexcParams_roughness_tiling, _2696 * (-0.288675129413604736328125f).xx);
    float _2760 = _2430.x;
    float _2765 = _2430.y;
    float2 _2788 = float2(_2556);
    float2 _2443 = mad(v_uv, hexcParams_roughness_tiling, _2713 * (-0.288675129413604736328125f).xx);
    float _2801 = _2443.x;
    float _2806 = _2443.y;
    float2 _2829 = float2(_2562);
    float _2842 = _2378.x;
    float _2847 = _2378.y;
    float _2854 = -_2842;
    float _2868 = _2380.x;
    float _2873 = _2380.y;
    float _2880 = -_2868;
    float4 _2276 = hexcTex_roughness.SampleGrad(hexcSampler, mad(_2679, 0.288675129413604736328125f.xx, float2(mad(_2719, _2593, _2724 * _2595), mad(-_2719, _2595, _2724 * _2593))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _2747), dot(float2(269.5f, 183.3000030517578125f), _2747))) * 43758.546875f), float2(mad(_2842, _2593, _2847 * _2595), mad(_2854, _2595, _2847 * _2593)), float2(mad(_2868, _2593, _2873 * _2595), mad(_2880, _2595, _2873 * _2593)));
    float4 _2286 = hexcTex_roughness.SampleGrad(hexcSampler, mad(_2696, 0.288675129413604736328125f.xx, float2(mad(_2760, _2627, _2765 * _2629), mad(-_2760, _2629, _2765 * _2627))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _2788), dot(float2(269.5f, 183.3000030517578125f), _2788))) * 43758.546875f), float2(mad(_2842, _2627, _2847 * _2629), mad(_2854, _2629, _2847 * _2627)), float2(mad(_2868, _2627, _2873 * _2629), mad(_2880, _2629, _2873 * _2627)));
    float4 _2296 = hexcTex_roughness.SampleGrad(hexcSampler, mad(_2713, 0.288675129413604736328125f.xx, float2(mad(_2801, _2661, _2806 * _2663), mad(-_2801, _2663, _2806 * _2661))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _2829), dot(float2(269.5f, 183.3000030517578125f), _2829))) * 43758.546875f), float2(mad(_2842, _2661, _2847 * _2663), mad(_2854, _2663, _2847 * _2661)), float2(mad(_2868, _2661, _2873 * _2663), mad(_2880, _2663, _2873 * _2661)));
    float3 _3009 = lerp(1.0f.xxx, float3(_2276.x, _2286.x, _2296.x), hexcParams_roughness_falloffcontrast.xxx) * pow(float3(_2521 * _2525, mad(-_2510, _2525, _2522), mad(-_2509, _2525, _2522)), hexcParams_roughness_exponent.xxx);
    float3 _3020 = _3009 / ((_3009.x + _3009.y) + _3009.z).xxx;
    float3 _5058;
    if (hexcParams_roughness_falloff != 0.5f)
    {
        float3 _3042 = step(0.5f.xxx, _3020) * 2.0f;
        float3 _3046 = (1.0f.xxx - _3042) * 2.0f;
        float3 _3061 = mad(_3046 * 0.25f, pow(max(0.0f.xxx, mad(_3020, _3046, _3042)), (log(1.0f - hexcParams_roughness_falloff) * (-1.44269502162933349609375f)).xxx), _3042 * 0.5f);
        _5058 = _3061 / ((_3061.x + _3061.y) + _3061.z).xxx;
    }
    else
    {
        _5058 = _3020;
    }
    float _1125 = clamp((((_2276 * _5058.x) + (_2286 * _5058.y)) + (_2296 * _5058.z)).x, 0.0199999995529651641845703125f, 1.0f);
    float3 _1130 = normalize(v_normal);
    float3 _1143 = normalize(v_tangent.xyz - (_1130 * dot(_1130, v_tangent.xyz)));
    float2 _3222 = v_uv * hexcParams_normal_tiling;
    float2 _3391 = ddx(_3222);
    float2 _3393 = ddy(_3222);
    float2 _3506 = _3222 * 3.4641015529632568359375f;
    float _3510 = _3506.y;
    float2 _3516 = float2(mad(-0.57735025882720947265625f, _3510, _3506.x), 1.1547005176544189453125f * _3510);
    int2 _3519 = int2(floor(_3516));
    float2 _3521 = frac(_3516);
    float _3522 = _3521.x;
    float _3523 = _3521.y;
    float _3534 = -((1.0f - _3522) - _3523);
    float _3535 = step(0.0f, _3534);
    float _3538 = mad(2.0f, _3535, -1.0f);
    int _3558 = int(_3535);
    int2 _3563 = _3519 + _3558.xx;
    int _3567 = 1 - _3558;
    int2 _3569 = _3519 + int2(_3558, _3567);
    int2 _3575 = _3519 + int2(_3567, _3558);
    int _3580 = _3563.x;
    int _3582 = _3563.y;
    float _3595 = mod(float(abs(_3580 * _3582) + abs(_3580 + _3582)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _4627;
    if (_3595 > 3.1415927410125732421875f)
    {
        _4627 = _3595 - 6.283185482025146484375f;
    }
    else
    {
        _4627 = _3595;
    }
    float _3604 = _4627 * hexcParams_normal_rotation;
    float _3606 = cos(_3604);
    float _3608 = sin(_3604);
    int _3614 = _3569.x;
    int _3616 = _3569.y;
    float _3629 = mod(float(abs(_3614 * _3616) + abs(_3614 + _3616)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _4628;
    if (_3629 > 3.1415927410125732421875f)
    {
        _4628 = _3629 - 6.283185482025146484375f;
    }
    else
    {
        _4628 = _3629;
    }
    float _3638 = _4628 * hexcParams_normal_rotation;
    float _3640 = cos(_3638);
    float _3642 = sin(_3638);
    int _3648 = _3575.x;
    int _3650 = _3575.y;
    float _3663 = mod(float(abs(_3648 * _3650) + abs(_3648 + _3650)) + 3.1415927410125732421875f, 6.283185482025146484375f);
    float _4629;
    if (_3663 > 3.1415927410125732421875f)
    {
        _4629 = _3663 - 6.283185482025146484375f;
    }
    else
    {
        _4629 = _3663;
    }
    float _3672 = _4629 * hexcParams_normal_rotation;
    float _3674 = cos(_3672);
    float _3676 = sin(_3672);
    float _3685 = float(_3582);
    float2 _3692 = float2(mad(0.5f, _3685, float(_3580)), _3685 * 0.866025447845458984375f);
    float _3702 = float(_3616);
    float2 _3709 = float2(mad(0.5f, _3702, float(_3614)), _3702 * 0.866025447845458984375f);
    float _3719 = float(_3650);
    float2 _3726 = float2(mad(0.5f, _3719, float(_3648)), _3719 * 0.866025447845458984375f);
    float2 _3430 = mad(v_uv, hexcParams_normal_tiling, _3692 * (-0.288675129413604736328125f).xx);
    float _3732 = _3430.x;
    float _3737 = _3430.y;
    float2 _3760 = float2(_3563);
    float2 _3443 = mad(v_uv, hexcParams_normal_tiling, _3709 * (-0.288675129413604736328125f).xx);
    float _3773 = _3443.x;
    float _3778 = _3443.y;
    float2 _3801 = float2(_3569);
    float2 _3456 = mad(v_uv, hexcParams_normal_tiling, _3726 * (-0.288675129413604736328125f).xx);
    float _3814 = _3456.x;
    float _3819 = _3456.y;
    float2 _3842 = float2(_3575);
    float _3855 = _3391.x;
    float _3860 = _3391.y;
    float _3867 = -_3855;
    float _3881 = _3393.x;
    float _3886 = _3393.y;
    float _3893 = -_3881;
    float3 _4023 = (hexcTex_normal.SampleGrad(hexcSampler, mad(_3692, 0.288675129413604736328125f.xx, float2(mad(_3732, _3606, _3737 * _3608), mad(-_3732, _3608, _3737 * _3606))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _3760), dot(float2(269.5f, 183.3000030517578125f), _3760))) * 43758.546875f), float2(mad(_3855, _3606, _3860 * _3608), mad(_3867, _3608, _3860 * _3606)), float2(mad(_3881, _3606, _3886 * _3608), mad(_3893, _3608, _3886 * _3606))).xyz * 2.0f) - 1.0f.xxx;
    float3 _4033 = abs(_4023);
    float2 _4059 = (-float2(_4023.xy)) / max(_4033.z, 0.0078125f * max(_4033.x, _4033.y)).xx;
    float _4065 = _4059.x;
    float _4070 = _4059.y;
    float2 _4084 = float2(mad(_3606, _4065, -(_3608 * _4070)), mad(_3608, _4065, _3606 * _4070));
    float3 _4100 = (hexcTex_normal.SampleGrad(hexcSampler, mad(_3709, 0.288675129413604736328125f.xx, float2(mad(_3773, _3640, _3778 * _3642), mad(-_3773, _3642, _3778 * _3640))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _3801), dot(float2(269.5f, 183.3000030517578125f), _3801))) * 43758.546875f), float2(mad(_3855, _3640, _3860 * _3642), mad(_3867, _3642, _3860 * _3640)), float2(mad(_3881, _3640, _3886 * _3642), mad(_3893, _3642, _3886 * _3640))).xyz * 2.0f) - 1.0f.xxx;
    float3 _4110 = abs(_4100);
    float2 _4136 = (-float2(_4100.xy)) / max(_4110.z, 0.0078125f * max(_4110.x, _4110.y)).xx;
    float _4142 = _4136.x;
    float _4147 = _4136.y;
    float2 _4161 = float2(mad(_3640, _4142, -(_3642 * _4147)), mad(_3642, _4142, _3640 * _4147));
    float3 _4177 = (hexcTex_normal.SampleGrad(hexcSampler, mad(_3726, 0.288675129413604736328125f.xx, float2(mad(_3814, _3674, _3819 * _3676), mad(-_3814, _3676, _3819 * _3674))) + frac(sin(float2(dot(float2(127.09999847412109375f, 311.70001220703125f), _3842), dot(float2(269.5f, 183.3000030517578125f), _3842))) * 43758.546875f), float2(mad(_3855, _3674, _3860 * _3676), mad(_3867, _3676, _3860 * _3674)), float2(mad(_3881, _3674, _3886 * _3676), mad(_3893, _3676, _3886 * _3674))).xyz * 2.0f) - 1.0f.xxx;
    float3 _4187 = abs(_4177);
    float2 _4213 = (-float2(_4177.xy)) / max(_4187.z, 0.0078125f * max(_4187.x, _4187.y)).xx;
    float _4219 = _4213.x;
    float _4224 = _4213.y;
    float2 _4238 = float2(mad(_3674, _4219, -(_3676 * _4224)), mad(_3676, _4219, _3674 * _4224));
    float3 _3314 = float3(dot(_4084, _4084), dot(_4161, _4161), dot(_4238, _4238));
    float3 _4253 = lerp(1.0f.xxx, sqrt(_3314 / (1.0f.xxx + _3314)), hexcParams_normal_falloffcontrast.xxx) * pow(float3(_3534 * _3538, mad(-_3523, _3538, _3535), mad(-_3522, _3538, _3535)), hexcParams_normal_exponent.xxx);
    float3 _4264 = _4253 / ((_4253.x + _4253.y) + _4253.z).xxx;
    float3 _5059;
    if (hexcParams_normal_falloff != 0.5f)
    {
        float3 _4286 = step(0.5f.xxx, _4264) * 2.0f;
        float3 _4290 = (1.0f.xxx - _4286) * 2.0f;
        float3 _4305 = mad(_4290 * 0.25f, pow(max(0.0f.xxx, mad(_4264, _4290, _4286)), (log(1.0f - hexcParams_normal_falloff) * (-1.44269502162933349609375f)).xxx), _4286 * 0.5f);
        _5059 = _4305 / ((_4305.x + _4305.y) + _4305.z).xxx;
    }
    else
    {
        _5059 = _4264;
    }
    float3 _4453 = normalize(float3(-(((_4084 * _5059.x) + (_4161 * _5059.y)) + (_4238 * _5059.z)), 1.0f));
    float3 _1173 = normalize(((_1143 * _4453.x) + ((cross(_1130, _1143) * v_tangent.w) * _4453.y)) + (_1130 * _4453.z));
    float _1180 = max(dot(_1173, float3(0.408248007297515869140625f, 0.408248007297515869140625f, 0.816497027873992919921875f)), 0.0f);
    float _1193 = 2.0f / (((_1125 * _1125) * _1125) * _1125);
    o_color = float4(((((_1288 * _5057.x) + (_1298 * _5057.y)) + (_1308 * _5057.z)).xyz * (0.1500000059604644775390625f + _1180)) + (0.039999999105930328369140625f * (((pow(max(dot(_1173, float3(0.21418631076812744140625f, 0.21418631076812744140625f, 0.95302069187164306640625f)), 0.0f), _1193 - 2.0f) * (_1193 + 6.0f)) * 0.0397887341678142547607421875f) * _1180)).xxx, 1.0f);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    v_uv = stage_input.v_uv;
    v_normal = stage_input.v_normal;
    v_tangent = stage_input.v_tangent;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.o_color = o_color;
    return stage_output;
}
