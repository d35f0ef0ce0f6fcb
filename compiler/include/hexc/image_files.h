#pragma once
// Image files beyond writeImage's (hexc/image.h): the formats `hexc bake` writes a slot's bake in, the format its
// texture came in.
#include <filesystem>
#include <string_view>

#include "hexc/image.h"

namespace hexc {

// The file format a texture's bytes are: what a bake of it is written as.
// KTX2: R8G8B8A8 UNORM or sRGB (B8G8R8A8 as these) and R32G32B32A32 SFLOAT; other KTX2 formats are Other.
enum class ImageFormat { Png8, Png16, Exr, Pfm, Ktx2Unorm8, Ktx2Srgb8, Ktx2Float, Other };
ImageFormat imageFormat(std::string_view bytes);

bool isKtx2(ImageFormat format);

// The file extension a format is written with (Other: ".png", written as Png8).
const char* imageExtension(ImageFormat format);

// Writes `image` in `format` (Other as Png8), atomically (hexc/files.h): PNG 8- or 16-bit RGBA, values clamped to
// [0, 1] and rounded (NaN as 0); OpenEXR float RGBA, ZIP-compressed; PFM as writeImage; KTX2 with its full mip chain,
// each level the 2x2 box average of the stored level above (sRGB colour in linear light, then encoded again; an odd
// last row or column left out), no supercompression. Throws std::runtime_error.
void writeImageAs(const Image& image, ImageFormat format, const std::filesystem::path& file);

// An image as an OpenEXR file's bytes as writeImageAs writes one: float RGBA, ZIP-compressed, the same bytes every time.
// Throws OpenEXR's exceptions (std::exception) on failure.
std::string exrBytes(const Image& image);

}  // namespace hexc
