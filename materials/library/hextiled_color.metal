// A fragment function written by hand (MSL 2.0) that hex-tiles one colour texture with hexc's library
// (docs/library.md). `hexc library --target msl -o include/`, then xcrun metal -I include -c hextiled_color.metal.
#include "hexc_hextiling.metal"

struct Settings {
    float2 tiling;
    float rotation;
    float falloff;
    float falloffContrast;
    float exponent;
};

struct Varyings {
    float4 position [[position]];
    float2 uv [[user(locn0)]];
};

fragment float4 hextiled_color(Varyings in [[stage_in]], constant Settings& settings [[buffer(0)]],
                               texture2d<float> albedo [[texture(0)]], sampler trilinearRepeat [[sampler(0)]]) {
    float2 st = in.uv * settings.tiling;
    HexcLattice lattice = hexcLattice();
    lattice.rotation = settings.rotation;
    lattice.rotate = settings.rotation != 0.0;
    HexcBlend blend = hexcBlend();
    blend.falloff = settings.falloff;
    blend.falloffContrast = settings.falloffContrast;
    blend.exponent = settings.exponent;
    blend.metric = settings.falloffContrast != 0.0;
    blend.gain = settings.falloff != 0.5;
    HexcTiles tiles = hexcTilesStable(st, dfdx(st), dfdy(st), int2(0), lattice);
    float3 weights;
    return hexcColor(albedo, trilinearRepeat, tiles, blend, float4(0.299, 0.587, 0.114, 0.0), albedo, weights);
}
