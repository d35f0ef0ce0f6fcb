// A pixel shader written by hand that hex-tiles one colour texture with hexc's library (docs/library.md).
//   hexc library --target hlsl -o include/      then compile with include/ on the include path:
//   dxc -T ps_6_0 -E main -I include hextiled_color.hlsl
#include "hexc_hextiling.hlsl"

cbuffer Settings : register(b0) {
    float2 tiling;          // repeats per uv unit (the material key `tiling`)
    float rotation;         // 0..1 (`rotation`)
    float falloff;          // r (`falloff`, 0.5 = no gain)
    float falloffContrast;  // beta (`falloffcontrast`, 0 = no luminance metric)
    float exponent;         // gamma (`exponent`)
};
Texture2D<float4> albedo : register(t0);
SamplerState trilinearRepeat : register(s0);  // trilinear, repeat: what the blend assumes

float4 main(float4 position : SV_Position, float2 uv : TEXCOORD0) : SV_Target {
    float2 st = uv * tiling;
    HexcLattice lattice = hexcLattice();  // stable mode's defaults; set what differs
    lattice.rotation = rotation;
    lattice.rotate = rotation != 0.0;
    HexcBlend blend = hexcBlend();
    blend.falloff = falloff;
    blend.falloffContrast = falloffContrast;
    blend.exponent = exponent;
    blend.metric = falloffContrast != 0.0;
    blend.gain = falloff != 0.5;
    // One lattice serves every texture read with the same st: pass `tiles` to each hexcColor / hexcDeriv.
    HexcTiles tiles = hexcTilesStable(st, ddx(st), ddy(st), int2(0, 0), lattice);
    float3 weights;  // the tiles' weights, for debugging views
    const float4 rec601 = float4(0.299, 0.587, 0.114, 0.0);  // the falloff metric: luminance (Eq. 4)
    return hexcColor(albedo, trilinearRepeat, tiles, blend, rec601, albedo, weights);
}
