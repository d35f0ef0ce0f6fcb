// hexc-gen-textures: writes the small tileable test textures that the example materials use.
//
//   hexc-gen-textures OUTDIR
//
// Writes rock_albedo.png, rock_normal.png, rock_roughness.png, tiles_albedo.png and the terrain's layers and splat map
// (terrain.cpp), 256x256 each.
// The PNGs are checked in under materials/textures/; a test regenerates them and compares bytes.
//
// Determinism: there is no clock, no std::rand and no <random> distribution (their output is
// implementation-defined). Every value comes from an integer hash of integer lattice coordinates and
// is then combined with + - * / and sqrt only, which IEEE 754 rounds exactly, so the result does not
// depend on the libm in use. The build turns off FMA contraction (-ffp-contract=off) so that no
// compiler fuses a*b+c differently on another machine.
//
// Tileability: every noise lattice has a whole number of cells across the image and wraps its cell
// ids modulo that count, so the left/right and top/bottom edges meet seamlessly.
#include <stb_image_write.h>

#include <cstdio>

#include "noise.h"

namespace {

using namespace gen;

// ---- the rock material ---------------------------------------------------------------------

// One field drives albedo, height (hence normals) and roughness, so the three maps line up.
struct RockSample {
    double base;    // broad mottling, about [0, 1]
    double streak;  // 0..1, elongated veins running at atan(1/2) ~ 26.6 degrees below the +x axis
    double crack;   // 0..1, thin crack network
};

RockSample rockAt(int x, int y) {
    RockSample s;
    s.base = clamp01(0.5 + 1.1 * fbm(x, y, 4, 4, 11u));

    // Streaks: anisotropic noise, fast across the streak and slow along it. Sampling it at the
    // sheared coordinates f = x - 2y, g = y keeps it periodic in 256 (integer shear), and makes the
    // streaks run along the direction (2, 1) in texels, which is deliberately not axis-aligned so
    // that hex-tile rotation is easy to see.
    const double f = static_cast<double>(x - 2 * y), g = static_cast<double>(y);
    const double across = gradientNoise(f / 16.0, g / 64.0, kSize / 16, kSize / 64, 23u);
    const double along = 0.5 + gradientNoise(f / 32.0, g / 32.0, kSize / 32, kSize / 32, 29u);
    s.streak = smoothstep(0.15, 0.35, across) * clamp01(along * 1.6);

    // Cracks: where a low-frequency noise crosses zero.
    const double c = std::fabs(fbm(x, y, 4, 3, 37u));
    s.crack = 1.0 - smoothstep(0.0, 0.035, c);
    return s;
}

double rockHeight(const RockSample& s) { return 0.55 * s.base + 0.35 * s.streak - 0.45 * s.crack; }

bool writeRock(const std::filesystem::path& dir) {
    std::vector<RockSample> field(kSize * kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) field[y * kSize + x] = rockAt(x, y);

    // Albedo, authored directly as sRGB-encoded values (the material declares it "srgb").
    std::vector<uint8_t> albedo(kSize * kSize * 3);
    const Rgb dark{0.29, 0.26, 0.23}, light{0.60, 0.56, 0.50}, vein{0.80, 0.66, 0.44}, crack{0.10, 0.09, 0.08};
    for (int i = 0; i < kSize * kSize; ++i) {
        const RockSample& s = field[i];
        const double grain = 1.0 + 0.06 * fbm(i % kSize, i / kSize, 64, 1, 41u);  // fine grain
        Rgb c = mix(dark, light, s.base);
        c = mix(c, vein, 0.85 * s.streak);
        c = mix(c, crack, 0.9 * s.crack);
        c = scale(c, grain);
        albedo[i * 3 + 0] = toByte(c.r);
        albedo[i * 3 + 1] = toByte(c.g);
        albedo[i * 3 + 2] = toByte(c.b);
    }

    std::vector<double> height(kSize * kSize);
    for (int i = 0; i < kSize * kSize; ++i) height[i] = rockHeight(field[i]);
    const std::vector<uint8_t> normal = normalMap(height, 6.0);

    // Roughness: cracks and mottled areas rough, polished veins smoother. Linear grey, one channel.
    std::vector<uint8_t> roughness(kSize * kSize);
    for (int i = 0; i < kSize * kSize; ++i) {
        const RockSample& s = field[i];
        roughness[i] = toByte(0.78 - 0.22 * s.base - 0.35 * s.streak + 0.2 * s.crack);
    }

    // Height, for height blending: the field the normals come from, its range [-0.45, 0.9] mapped to [0, 1].
    std::vector<uint8_t> heightMap(kSize * kSize);
    for (int i = 0; i < kSize * kSize; ++i) heightMap[i] = toByte((height[i] + 0.45) / 1.35);

    return writePng(dir / "rock_albedo.png", 3, albedo) && writePng(dir / "rock_normal.png", 3, normal) &&
           writePng(dir / "rock_roughness.png", 1, roughness) && writePng(dir / "rock_height.png", 1, heightMap);
}

// ---- the tiles material --------------------------------------------------------------------

// Axis-aligned square tiles (8 x 8 tiles of 32 texels) in four distinct glaze colours with grout
// between them: separated colour clusters, the case where blending loses contrast (paper Sec. 2.2).
bool writeTiles(const std::filesystem::path& dir) {
    constexpr int kTile = 32;      // texels per tile; kSize / kTile tiles per side
    constexpr int kGroutHalf = 2;  // grout is 2 * kGroutHalf texels wide, centred on tile borders
    const Rgb palette[4] = {{0.74, 0.34, 0.20}, {0.14, 0.47, 0.52}, {0.88, 0.69, 0.22}, {0.89, 0.86, 0.77}};
    const Rgb grout{0.33, 0.31, 0.29};

    std::vector<uint8_t> pixels(kSize * kSize * 3);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const int tx = x / kTile, ty = y / kTile;
            const int lx = x % kTile, ly = y % kTile;
            // distance (in texels) from this texel to the nearest tile border
            const int edge = std::min(std::min(lx, kTile - 1 - lx), std::min(ly, kTile - 1 - ly));
            Rgb c;
            if (edge < kGroutHalf) {
                c = grout;
            } else {
                const Rgb glaze = palette[hash3(tx, ty, 59u) % 4u];
                const double tileShade = 0.92 + 0.16 * hash01(tx, ty, 61u);  // per-tile variation
                const double mottle = 1.0 + 0.08 * fbm(x, y, 16, 2, 67u);    // glaze unevenness
                const double bevel = edge == kGroutHalf ? 0.82 : (edge == kGroutHalf + 1 ? 0.92 : 1.0);
                c = scale(glaze, tileShade * mottle * bevel);
            }
            uint8_t* p = &pixels[(y * kSize + x) * 3];
            p[0] = toByte(c.r);
            p[1] = toByte(c.g);
            p[2] = toByte(c.b);
        }
    return writePng(dir / "tiles_albedo.png", 3, pixels);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: hexc-gen-textures OUTDIR\n");
        return 2;
    }
    const std::filesystem::path dir = argv[1];
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        std::fprintf(stderr, "hexc-gen-textures: cannot create %s: %s\n", dir.string().c_str(), ec.message().c_str());
        return 1;
    }
    // Pin the encoder settings instead of relying on libstb's defaults.
    stbi_write_png_compression_level = 9;
    stbi_write_force_png_filter = -1;  // per-row adaptive filter choice (deterministic)

    return writeRock(dir) && writeTiles(dir) && writeTerrain(dir) ? 0 : 1;
}
