#pragma once
// Texture files that pipelines hand over besides stb's formats: GPU containers (KTX2, DDS, with block-compressed
// formats and mips) and OpenEXR. Compiling needs only their headers; render and preview decode level 0 where
// that is simple (uncompressed 8-bit or 32-bit float RGBA, and any EXR through the OpenEXR library).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "hexc/image.h"

namespace hexc::containers {

enum class Kind { None, Ktx2, Dds, Exr };

// Each reads the file's bytes (TextureFile::bytes); `file` names it in messages.

// By the file's first bytes, not its extension.
Kind kindOf(std::string_view bytes);

// Size, channels, mip count and the format's colour space; nullopt with the reason in *error for a malformed,
// truncated or unknown file.
std::optional<TextureInfo> info(Kind kind, std::string_view bytes, const std::filesystem::path& file, std::string* error);

// Level 0 as loadTexture returns it, of layer `layer` of a KTX2 array (0 otherwise); throws TextureError naming the
// format when it is not decoded here, or naming the layer when the file has no such layer.
Texture load(Kind kind, std::string_view bytes, const std::filesystem::path& file, bool srgb, int layer);

// The KTX2 Data Format Descriptor (dfdTotalSize and one basic block, KTX 2.0 section 3.10) of an uncompressed RGBA
// vkFormat hexc writes: R8G8B8A8 UNORM (37) or sRGB (43, alpha linear) and R32G32B32A32 SFLOAT (109); empty for
// others. The reader refuses a file whose descriptor differs for these formats (colour primaries aside).
std::string ktx2Dfd(uint32_t vkFormat);

}  // namespace hexc::containers
