#pragma once
// The precomputation of the histogram-preserving blend (docs/material-format.md#blend): Heitz and Neyret 2018,
// "High-Performance By-Example Noise using a Histogram-Preserving Blending Operator", and its real-time form by
// Deliot and Heitz 2019, "Procedural Stochastic Textures by Tiling and Blending". From a slot's texture hexc derives
//   - a decorrelated colour space: the principal axes of the texels' linear RGB (identity for a scalar slot);
//   - T, per decorrelated channel: the channel's empirical CDF composed with the inverse CDF of a Gaussian of mean
//     0.5 and standard deviation 1/6, applied to every texel: the Gaussian texture the shader samples instead;
//   - the inverse of T as a look-up table, one row per mip level of the Gaussian texture: a level is a box average, of
//     smaller variance s_l^2 than level 0's s_0^2, and the value it stands for is the average of the texels under
//     it, E[T^-1(Y)] with Y ~ N(g, s_0^2 - s_l^2) (the level-0 value given the level-l value, for a Gaussian field).
// The shader blends Gaussian values with variance-preserving weights, G = sum w_i (g_i - 0.5) / sqrt(sum w_i^2) + 0.5,
// then reads each channel's inverse in the row of its level of detail and returns to RGB.
#include <array>
#include <string>

#include "hexc/image.h"
#include "hexc/material.h"

namespace hexc {

// Entries per look-up table row, in equal steps over the Gaussian values 0.5 +- kHistogramLutSigmas standard deviations:
// 6.5 covers the extreme ranks of any texture below 2^32 texels (Phi^-1(0.5 / 2^32) = -6.34), so no texel's value is
// out of the table's reach (the tails are kept).
constexpr int kHistogramLutWidth = 512;
constexpr double kHistogramLutSigmas = 6.5;

struct HistogramTransform {
    // The texture's size, float RGBA: T of decorrelated channel k in channel k (a scalar slot: in r, g and b); alpha 1.
    Texture gaussian;
    // kHistogramLutWidth x (1 + levels of the Gaussian texture's full mip chain), float RGBA, linear values.
    // Row 0, texels 0-2: the decorrelated axes in linear RGB, texel 3: the mean, so RGB = mean + sum_k q_k axis_k;
    // texels 4 and 5: the texels' smallest and largest linear values per channel (a colour slot's result is kept
    // within them: the sum over the axes can leave that box).
    // Row 1 + l, texel i: q_k = T_k^-1 at Gaussian value histogramLutGaussian(i), in channel k, for mip level l.
    Texture lut;
};

// The transform of `source` (as loadTexture gives it, sRGB decoded to linear first) for `slot`: a colour slot's RGB,
// a scalar slot's channel. Deterministic: the same texels give the same bytes; equal texels are ranked by a hash of
// their position. It holds about 25 bytes per texel beside `source` (the result's Gaussian texture included).
HistogramTransform histogramTransform(const Texture& source, const Slot& slot);

// The Gaussian value of a table row's entry i: 0.5 + (2 i / (kHistogramLutWidth - 1) - 1) kHistogramLutSigmas / 6.
double histogramLutGaussian(int entry);

// The output files hexc writes for a histogram slot: "<material>.<slot>.gaussian.pfm" and "<material>.<slot>.lut.pfm",
// ".exr" for `exr` (CompileOptions::exrTables).
std::string histogramFileName(const std::string& material, const std::string& slot, const char* which, bool exr = false);

}  // namespace hexc
