#pragma once
// Images in and out of hexc: textures as the GPU receives them, float renders as they come back.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace hexc {

// A texture as uploaded: 8-bit RGBA (missing channels filled as stb does: grey -> rgb, alpha = 255),
// or 32-bit float RGBA. Row 0 is the top row of the file, which is v = 0 (texel centre v = 0.5/height).
struct Texture {
    int width = 0, height = 0;
    bool srgb = false;           // 8-bit only: decode sRGB to linear when sampling
    std::vector<uint8_t> rgba8;  // width*height*4, when 8-bit
    std::vector<float> rgba32f;  // width*height*4, when float
    bool isFloat() const { return !rgba32f.empty(); }
};

// A float RGBA image; row 0 is the top row.
struct Image {
    int width = 0, height = 0;
    std::vector<float> rgba;  // width*height*4
    float* at(int x, int y) { return &rgba[(size_t(y) * width + x) * 4]; }
    const float* at(int x, int y) const { return &rgba[(size_t(y) * width + x) * 4]; }
};

// A render of width x height pixels over uvRect = (u0, v0, u1, v1): pixel (i, j), row 0 at the top, is
// centred on uv = (u0 + (i + 0.5) / width * (u1 - u0), v0 + (j + 0.5) / height * (v1 - v0)), with
// du/dx = (u1 - u0) / width, dv/dy = (v1 - v0) / height and no cross terms.
struct View {
    int width = 0, height = 0;
    std::array<double, 4> uvRect{0, 0, 1, 1};
};

struct TextureInfo {
    int width = 0, height = 0, channels = 0;
    std::string channelNames;  // the channels the file has: "r", "ra" (grey + alpha), "rg" (e.g. BC5), "rgb", "rgba"
    int mipLevels = 1;         // stored in the file (KTX2, DDS); hexc's uploads make their own chain
    std::optional<bool> srgb;  // whether the file's format says sRGB, where it says (KTX2, DDS); float files hold linear values
    std::string format = {};   // the container's pixel format, for messages ("BC7 sRGB"); empty for stb's formats
    bool eightBit = false;     // stb's 8-bit formats: loadTexture gives rgba8, alpha 255 where the file has none
    int layers = 0;            // a KTX2 array's layers (docs/material-format.md#ktx2-arrays); 0 for a 2D texture
};

// A texture file as a compile reads it: once, whole, with what its header says. The parser reads each slot's texture
// into one (Slot::file); packing, the derived textures, the engine packages and the command line's up-to-date check
// take its bytes and texels from there, so every stage sees the same file, however it changes on disk meanwhile.
struct TextureFile {
    std::filesystem::path path;
    std::string bytes;  // the whole file: the compile's memory holds every slot's texture file once, encoded
    TextureInfo info;
};

// The largest texture file read (twice an 8192x8192 RGBA float texture, the largest any stage decodes; stb_image reads
// no more than 2 GiB either).
constexpr uint64_t kMaxTextureBytes = 2ull << 30;

// Reads `file` whole and its header, without decoding it (the formats loadTexture reads); nullopt with the reason in
// *error when it is not a readable image.
std::optional<TextureFile> readTextureFile(const std::filesystem::path& file, std::string* error);

// Size and channel count of an image file (readTextureFile's info).
std::optional<TextureInfo> textureInfo(const std::filesystem::path& file, std::string* error);

// A texture that cannot be decoded: a problem of the input (hexc render exits 1), not of an output.
struct TextureError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Loads any format stb_image reads (PNG, JPEG, TGA, BMP, HDR...) and PFM. HDR and PFM load as float.
// Throws TextureError with the file name and stb's reason on failure. `layer`: that layer of a KTX2 array (a slot's
// Slot::textureLayer); a file without it is an error.
Texture loadTexture(const std::filesystem::path& file, bool srgb, int layer = 0);

// The texels of a file read before, as loadTexture decodes the file.
Texture decodeTexture(const TextureFile& file, bool srgb, int layer = 0);

// An 8-bit RGBA texture as PNG bytes, the same bytes for the same texels; and PNG (or any stb format's) bytes decoded as
// loadTexture decodes a file. The latter throws TextureError when they do not decode.
std::string pngBytes(const Texture& texture);
Texture decodeTexture(std::string_view bytes, bool srgb);

// Whether writeImage writes this file's extension (.pfm or .png, any case).
bool isImageExtension(const std::filesystem::path& file);

// An image as a PFM file's bytes (RGB, little-endian floats, bottom row first): exact, and the same bytes every time.
std::string pfmBytes(const Image& image);

// Writes by extension: .pfm (float, exact), .png (8-bit, values clamped to [0,1], no sRGB encoding).
// Written to a temporary file and renamed. Throws std::runtime_error on failure.
void writeImage(const Image& image, const std::filesystem::path& file);

}  // namespace hexc
