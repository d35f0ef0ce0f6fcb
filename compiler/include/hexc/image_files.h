#pragma once
// Image files beyond writeImage's (hexc/image.h): the formats `hexc bake` writes a slot's bake in, the format its
// texture came in.
#include <filesystem>
#include <string_view>

#include "hexc/image.h"

namespace hexc {

// The file format a texture's bytes are: what a bake of it is written as.
enum class ImageFormat { Png8, Png16, Exr, Pfm, Other };
ImageFormat imageFormat(std::string_view bytes);

// The file extension a format is written with (Other: ".png", written as Png8).
const char* imageExtension(ImageFormat format);

// Writes `image` in `format` (Other as Png8), atomically (hexc/files.h): PNG 8- or 16-bit RGBA, values clamped to
// [0, 1] and rounded (NaN as 0); OpenEXR float RGBA, ZIP-compressed; PFM as writeImage. Throws std::runtime_error.
void writeImageAs(const Image& image, ImageFormat format, const std::filesystem::path& file);

}  // namespace hexc
