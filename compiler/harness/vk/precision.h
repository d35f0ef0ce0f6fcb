#pragma once
// The precision stress measurement shared by the stress tests and the benchmark report: hex-tiling on the
// GPU far from the origin against the fp64 reference evaluated at the GPU's own float32 inputs.
#include <filesystem>
#include <string>
#include <vector>

#include "hexc/material.h"
#include "vk/render.h"
#include "vk/runner.h"

namespace hexc::vk {

// Absolute differences over the first `channels` channels of every pixel; NaN on one side counts as infinite.
struct ImageErrors {
    double max = 0, mean = 0, overOne255 = 0;  // overOne255: the share of values off by more than 1/255
};
ImageErrors compareImages(const Image& a, const Image& b, int channels);

// Where the view lies and how far its pixels are apart.
enum class Placement {
    Direct,   // at uv ~ (X, X), a texel per pixel where float32 resolves it, else half an ulp of X per pixel
    Split,    // near 0, with X the origin passed as split coordinates (hexc/origin.h)
    Aligned,  // at uv ~ (X, X), a texel per pixel or one ulp of X per pixel, each pixel sampling with the
              // gradients of one texel (templates/harness/aligned.frag.glsl), so mip level 0 at any X
};

struct PrecisionRow {
    std::string mode;  // "stable", "paper", "stable, split" or "stable, aligned"
    std::string path;  // "color" or "normal"
    double magnitude;  // X: |uv| of the view (split: of the origin)
    ImageErrors errors;
};

// The PNGs the probe tiles: a colour texture and a tangent-space normal map (the callers use materials/textures/
// rock_albedo.png and rock_normal.png).
struct ProbeTextures {
    std::filesystem::path color, normal;
};

// Renders the colour texture (colour path) and normal map (normal path, compared as the encoded normal
// n * 0.5 + 0.5) at tiling 4 in a 64 x 64 view placed by `placement` for each X in `magnitudes`, and compares
// every pixel with the reference evaluated at the uv and derivatives the rasteriser gave that pixel (read back with
// templates/harness/probe.frag.glsl; aligned views: the one-texel gradients they sample with). The textures are
// converted to float, so 8-bit filtering does not hide or add error. `workDir` receives the float textures and the
// aligned views' template. `target`: the emitted source executed. Throws on a render failure.
std::vector<PrecisionRow> measurePrecision(Runner& runner, const ProbeTextures& inputs, const std::filesystem::path& workDir, HashMode mode,
                                           Placement placement, const std::vector<double>& magnitudes,
                                           ExecutedTarget target = ExecutedTarget::Spirv);

// A Markdown table of rows: mode, path, |uv|, max, mean, share over 1/255.
std::string precisionTable(const std::vector<PrecisionRow>& rows);

}  // namespace hexc::vk
