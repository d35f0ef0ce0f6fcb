// The terrain example's textures (materials/terrain/): four layers (grass, sand, pebbles, snow), each an albedo, a
// normal map and a roughness + height map (grey = roughness, alpha = height), and a painted splat map whose RGBA holds
// the four layers' weights. Deterministic as generate.cpp says; every map tiles.
#include "noise.h"

namespace {

using namespace gen;

// One layer's height field and colour at a texel; the roughness follows from both.
struct LayerSample {
    double height;  // [0, 1]
    Rgb color;      // sRGB-encoded
    double roughness;
};

// Grass: blades as fast noise across x and slow along y, over soft clumps.
LayerSample grassAt(int x, int y) {
    const double clump = clamp01(0.5 + fbm(x, y, 8, 3, 301u));
    const double blade = clamp01(0.5 + 1.4 * gradientNoise(x / 2.0, y / 16.0, kSize / 2, kSize / 16, 303u));
    const double h = clamp01(0.35 * clump + 0.65 * blade);
    const Rgb dark{0.13, 0.25, 0.07}, light{0.42, 0.60, 0.17}, dry{0.62, 0.60, 0.30};
    return {h, mix(mix(dark, light, h), dry, 0.35 * clamp01(1.0 - 2.0 * clump)), 0.85 - 0.2 * blade};
}

// Sand: ripples running diagonally (sheared coordinates keep them periodic), fine grain.
LayerSample sandAt(int x, int y) {
    const double f = static_cast<double>(x + y), g = static_cast<double>(y);
    const double ripple = clamp01(0.5 + 1.2 * gradientNoise(f / 8.0, g / 64.0, kSize / 8, kSize / 64, 311u));
    const double grain = fbm(x, y, 128, 1, 313u);
    const double h = clamp01(0.75 * ripple + 0.25 * (0.5 + grain));
    const Rgb low{0.66, 0.52, 0.33}, high{0.89, 0.79, 0.58};
    return {h, scale(mix(low, high, ripple), 1.0 + 0.1 * grain), 0.9 - 0.1 * ripple};
}

// Pebbles: a cell grid (16 per side) with one rounded stone per cell, each its own grey-brown; mud between.
LayerSample pebblesAt(int x, int y) {
    constexpr int kCell = 16;
    const int cx = x / kCell, cy = y / kCell;
    const double px = (x % kCell + 0.5) / kCell - 0.5, py = (y % kCell + 0.5) / kCell - 0.5;
    const double ox = 0.15 * (hash01(cx, cy, 321u) - 0.5), oy = 0.15 * (hash01(cx, cy, 323u) - 0.5);
    const double radius = 0.32 + 0.12 * hash01(cx, cy, 325u);
    const double dx = px - ox, dy = py - oy, d2 = (dx * dx + dy * dy) / (radius * radius);
    const double dome = d2 < 1.0 ? std::sqrt(1.0 - d2) : 0.0;
    const double tone = hash01(cx, cy, 327u);
    const Rgb mud{0.24, 0.19, 0.14}, stone = mix(Rgb{0.45, 0.43, 0.41}, Rgb{0.63, 0.55, 0.45}, tone);
    const double speck = 1.0 + 0.08 * fbm(x, y, 64, 1, 329u);
    return {0.15 + 0.85 * dome, scale(mix(mud, stone, smoothstep(0.0, 0.15, dome)), speck), dome > 0.0 ? 0.45 - 0.2 * dome : 0.95};
}

// Snow: broad drifts, nearly white, with blue in the hollows and few sparkles.
LayerSample snowAt(int x, int y) {
    const double drift = clamp01(0.5 + 1.2 * fbm(x, y, 4, 4, 331u));
    const double sparkle = hash01(x, y, 333u) > 0.985 ? 1.0 : 0.0;
    const Rgb hollow{0.70, 0.78, 0.90}, crest{0.95, 0.96, 0.98};
    return {drift, mix(mix(hollow, crest, drift), Rgb{1, 1, 1}, sparkle), 0.55 - 0.35 * sparkle};
}

bool writeLayer(const std::filesystem::path& dir, const std::string& name, LayerSample (*at)(int, int)) {
    std::vector<uint8_t> albedo(kSize * kSize * 3), rh(kSize * kSize * 2);
    std::vector<double> height(kSize * kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const int i = y * kSize + x;
            const LayerSample s = at(x, y);
            height[i] = s.height;
            albedo[i * 3 + 0] = toByte(s.color.r);
            albedo[i * 3 + 1] = toByte(s.color.g);
            albedo[i * 3 + 2] = toByte(s.color.b);
            rh[i * 2 + 0] = toByte(s.roughness);
            rh[i * 2 + 1] = toByte(s.height);
        }
    const std::string stem = "terrain_" + name;
    return writePng(dir / (stem + "_albedo.png"), 3, albedo) && writePng(dir / (stem + "_normal.png"), 3, normalMap(height, 4.0)) &&
           writePng(dir / (stem + "_rh.png"), 2, rh);
}

// The splat map: sand low, grass and pebbles in the middle (grass where it is moist), snow high, from two broad noise
// fields. Borders are hard on the left (one layer per texel) and soften towards the right, where each layer's weight
// falls off over `soft` of its score below the best.
bool writeSplat(const std::filesystem::path& dir) {
    std::vector<uint8_t> splat(kSize * kSize * 4);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double e = clamp01(0.5 + 1.6 * fbm(x, y, 2, 3, 341u)), m = clamp01(0.5 + 1.6 * fbm(x, y, 2, 2, 343u));
            const double score[4] = {m * (1.0 - std::fabs(e - 0.5) * 2.0), 1.0 - 3.0 * e, (1.0 - m) * (1.0 - std::fabs(e - 0.5) * 2.0),
                                     3.0 * e - 2.0};
            const double soft = 0.2 * smoothstep(96.0, 160.0, x);
            const double best = std::max(std::max(score[0], score[1]), std::max(score[2], score[3]));
            double w[4], sum = 0.0;
            for (int i = 0; i < 4; ++i) {
                w[i] = soft > 0.0 ? std::max(score[i] - best + soft, 0.0) : (score[i] == best ? 1.0 : 0.0);
                sum += w[i];
            }
            for (int i = 0; i < 4; ++i) splat[(y * kSize + x) * 4 + i] = toByte(w[i] / sum);
        }
    return writePng(dir / "terrain_splat.png", 4, splat);
}

}  // namespace

bool writeTerrain(const std::filesystem::path& dir) {
    return writeLayer(dir, "grass", grassAt) && writeLayer(dir, "sand", sandAt) && writeLayer(dir, "pebbles", pebblesAt) &&
           writeLayer(dir, "snow", snowAt) && writeSplat(dir);
}
