#pragma once
// What the shader benchmark measures besides time: error against a reference image and contrast against the
// source texture (what a fragment shader executes per pixel is hexc::countOps, hexc/spirv.h).
#include <map>
#include <string>
#include <vector>

#include "hexc/image.h"
#include "hexc/spirv.h"

namespace hexc::bench {

// Absolute error over the RGB channels (alpha is 1 in both); PSNR with peak 1, infinite for identical images.
struct ErrorStats {
    double max = 0, mean = 0, psnrDb = 0;
};
ErrorStats compareRgb(const Image& image, const Image& reference);

// Rec. 601 luminance, the weights hex-tiling's colour falloff metric uses (Eq. 4).
double luminance(double r, double g, double b);
std::vector<double> luminances(const Image& image);

// How much contrast blending kept: the variance ratio (rendered / source) and the earth mover's distance
// between the 64-bin histograms of luminance over [0, 1] (in luminance units: 0 = same distribution).
struct Contrast {
    double varianceRatio = 0, histogramEmd = 0;
};
Contrast contrast(const std::vector<double>& rendered, const std::vector<double>& source);

}  // namespace hexc::bench
