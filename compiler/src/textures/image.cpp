// Texture loading (stb_image, plus PFM so that float renders written by writeImage load back exactly) and
// image writing (.pfm, .png), always through a temporary file and a rename.
#include "hexc/image.h"

#include "textures/containers.h"
#include "textures/memory_stream.h"
#include "hexc/files.h"
#include "hexc/suggest.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>

namespace hexc {
namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& reason) {
    throw std::runtime_error(file.string() + ": " + reason);
}

[[noreturn]] void failRead(const std::filesystem::path& file, const std::string& reason) {
    throw TextureError(file.string() + ": " + reason);
}

[[noreturn]] void failStb(const std::filesystem::path& file) {
    const char* reason = stbi_failure_reason();
    failRead(file, reason ? reason : "cannot load image");
}

std::string lowerExtension(const std::filesystem::path& file) { return lowerCase(file.extension().string()); }

// Portable Float Map: "PF" (RGB) or "Pf" (grey), width, height, then a scale whose sign gives the byte order
// (negative: little-endian), each followed by whitespace; then rows of floats from the bottom row up.
struct PfmHeader {
    int width = 0, height = 0, channels = 0;
    bool littleEndian = true;
};

// The header, checked like every container's: a size of 1..65536 and the texels in the file's `size` bytes.
PfmHeader readPfmHeader(std::istream& in, uint64_t size, const std::filesystem::path& file) {
    std::string magic;
    PfmHeader h;
    double scale = 0;
    in >> magic >> h.width >> h.height >> scale;
    in.get();  // the single whitespace character that ends the header
    if (!in || (magic != "PF" && magic != "Pf") || h.width <= 0 || h.height <= 0 || h.width > 65536 || h.height > 65536 || scale == 0)
        failRead(file, "not a PFM file (bad header)");
    h.channels = magic == "PF" ? 3 : 1;
    h.littleEndian = scale < 0;
    const uint64_t dataBytes = uint64_t(h.width) * uint64_t(h.height) * h.channels * 4;
    if (dataBytes > size - uint64_t(in.tellg())) failRead(file, "PFM file is truncated");
    return h;
}

Texture loadPfm(std::string_view bytes, const std::filesystem::path& file) {
    MemoryStream in(bytes);
    const PfmHeader header = readPfmHeader(in, bytes.size(), file);
    const int width = header.width, height = header.height;
    const int channels = header.channels;
    std::vector<uint32_t> words(size_t(width) * height * channels);
    in.read(reinterpret_cast<char*>(words.data()), std::streamsize(words.size() * 4));
    if (in.gcount() != std::streamsize(words.size() * 4)) failRead(file, "PFM file is truncated");
    if (header.littleEndian != (std::endian::native == std::endian::little))
        for (uint32_t& w : words) w = (w >> 24) | ((w >> 8) & 0xff00u) | ((w << 8) & 0xff0000u) | (w << 24);  // std::byteswap is C++23

    Texture t;
    t.width = width;
    t.height = height;
    t.rgba32f.resize(size_t(width) * height * 4);
    for (int y = 0; y < height; ++y) {
        const uint32_t* row = &words[size_t(height - 1 - y) * width * channels];
        for (int x = 0; x < width; ++x) {
            float* dst = &t.rgba32f[(size_t(y) * width + x) * 4];
            for (int c = 0; c < 3; ++c) dst[c] = std::bit_cast<float>(row[x * channels + (channels == 3 ? c : 0)]);
            dst[3] = 1.0f;
        }
    }
    return t;
}

bool writePfm(const Image& image, const std::filesystem::path& file) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    if (!out) return false;
    const std::string bytes = pfmBytes(image);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    return bool(out);
}

bool writePng(const Image& image, const std::filesystem::path& file) {
    std::vector<unsigned char> bytes(image.rgba.size());
    for (size_t i = 0; i < bytes.size(); ++i) {
        const float v = image.rgba[i];
        // NaN fails both comparisons inside clamp and would survive it; write it as 0.
        bytes[i] = std::isnan(v) ? 0 : (unsigned char)std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f);
    }
    return stbi_write_png(file.string().c_str(), image.width, image.height, 4, bytes.data(), image.width * 4) != 0;
}

uint64_t bigEndian32(const unsigned char* p) { return uint64_t(p[0]) << 24 | p[1] << 16 | p[2] << 8 | p[3]; }

// Whether the bytes are a PNG whose chunks stop before IEND. stbi_info reads only the header, so a truncated PNG
// would pass validation and fail when an engine loads it; walking the chunk headers costs no decode.
bool truncatedPng(std::string_view bytes) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
    if (!bytes.starts_with("\x89PNG\r\n\x1a\n")) return false;
    for (uint64_t at = 8; at + 12 <= bytes.size();) {  // after the 8-byte signature: length, type, data, CRC
        if (bytes.substr(size_t(at) + 4, 4) == "IEND") return false;
        at += 12 + bigEndian32(b + at);
    }
    return true;
}

uint64_t littleEndian(const unsigned char* p, int bytes) {
    uint64_t v = 0;
    for (int i = bytes - 1; i >= 0; --i) v = v << 8 | p[i];
    return v;
}

// What the headers of stb's formats say that stbi_info does not check: a PNG's size outside 1..65536 (beyond stb's own
// limit, stbi_info says only "unknown image type"), and an uncompressed BMP or TGA whose texels are not all in the file.
// Empty when there is nothing wrong with it. 64-bit arithmetic throughout: every field is the file's to choose.
std::string stbHeaderProblem(std::string_view bytes, const std::filesystem::path& file) {
    unsigned char b[54] = {};
    const size_t got = bytes.copy(reinterpret_cast<char*>(b), sizeof b);
    const uint64_t size = bytes.size();
    const auto sized = [](int64_t w, int64_t h) { return std::to_string(w) + "x" + std::to_string(h) + " (sizes are 1..65536)"; };
    if (got >= 24 && std::memcmp(b, "\x89PNG\r\n\x1a\n", 8) == 0) {
        const int64_t w = int64_t(b[16]) << 24 | b[17] << 16 | b[18] << 8 | b[19],
                      h = int64_t(b[20]) << 24 | b[21] << 16 | b[22] << 8 | b[23];
        if (w < 1 || h < 1 || w > 65536 || h > 65536) return "the PNG header gives " + sized(w, h);
    }
    uint64_t needed = 0;  // bytes of an uncompressed file's header and texels
    if (got >= 54 && b[0] == 'B' && b[1] == 'M' && littleEndian(b + 14, 4) >= 40 &&
        (littleEndian(b + 30, 4) == 0 || littleEndian(b + 30, 4) == 3)) {
        const uint64_t w = uint64_t(std::llabs(int32_t(littleEndian(b + 18, 4)))),
                       h = uint64_t(std::llabs(int32_t(littleEndian(b + 22, 4))));
        needed = littleEndian(b + 10, 4) + (w * littleEndian(b + 28, 2) + 31) / 32 * 4 * h;  // rows padded to 4 bytes
    } else if (got >= 18 && lowerExtension(file) == ".tga" && b[2] >= 1 && b[2] <= 3) {      // colour-mapped, true-colour, grey
        const uint64_t colourMap = b[1] ? littleEndian(b + 5, 2) * ((b[7] + 7) / 8) : 0;
        needed = 18 + b[0] + colourMap + littleEndian(b + 12, 2) * littleEndian(b + 14, 2) * ((b[16] + 7) / 8);
    }
    if (needed > size) return "the file is truncated (its texels do not fit)";
    return {};
}

// What the bytes' header says; nullopt with the reason in *error when they are not a readable image.
std::optional<TextureInfo> infoOf(std::string_view bytes, const std::filesystem::path& file, std::string* error) {
    if (containers::Kind kind = containers::kindOf(bytes); kind != containers::Kind::None)
        return containers::info(kind, bytes, file, error);
    if (lowerExtension(file) == ".pfm") {
        try {
            MemoryStream in(bytes);
            PfmHeader h = readPfmHeader(in, bytes.size(), file);
            return TextureInfo{h.width, h.height, h.channels, h.channels == 3 ? "rgb" : "r", 1, std::nullopt};
        } catch (const TextureError& e) {
            *error = std::string(e.what()).substr(file.string().size() + 2);  // the reason, without the file name
            return std::nullopt;
        }
    }
    if (std::string problem = stbHeaderProblem(bytes, file); !problem.empty()) {
        *error = problem;
        return std::nullopt;
    }
    TextureInfo info;
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    if (bytes.size() > INT_MAX || !stbi_info_from_memory(data, int(bytes.size()), &info.width, &info.height, &info.channels)) {
        const char* reason = bytes.size() > INT_MAX ? "larger than stb_image reads (2 GiB)" : stbi_failure_reason();
        *error = reason ? reason : "cannot read image";
        return std::nullopt;
    }
    if (info.width < 1 || info.height < 1 || info.width > 65536 || info.height > 65536) {
        *error = "the header gives " + std::to_string(info.width) + "x" + std::to_string(info.height) + " (sizes are 1..65536)";
        return std::nullopt;
    }
    if (truncatedPng(bytes)) {
        *error = "the PNG is truncated (its chunks end before IEND)";
        return std::nullopt;
    }
    static const char* const kNames[] = {"", "r", "ra", "rgb", "rgba"};  // stb: grey, grey + alpha, RGB, RGBA
    info.channelNames = kNames[std::clamp(info.channels, 0, 4)];
    info.eightBit = !stbi_is_hdr_from_memory(data, int(bytes.size()));
    return info;
}

// Level 0 of the bytes, as loadTexture documents it.
Texture decode(std::string_view bytes, const std::filesystem::path& file, bool srgb, int layer) {
    if (containers::Kind kind = containers::kindOf(bytes); kind != containers::Kind::None)
        return containers::load(kind, bytes, file, srgb, layer);
    if (layer != 0) failRead(file, "no layer " + std::to_string(layer) + ": only a KTX2 array has layers");
    if (lowerExtension(file) == ".pfm") return loadPfm(bytes, file);
    if (bytes.size() > INT_MAX) failRead(file, "larger than stb_image reads (2 GiB)");
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int size = int(bytes.size());
    Texture t;
    int channelsInFile = 0;
    if (stbi_is_hdr_from_memory(data, size)) {
        std::unique_ptr<float, void (*)(void*)> texels(stbi_loadf_from_memory(data, size, &t.width, &t.height, &channelsInFile, 4),
                                                       stbi_image_free);
        if (!texels) failStb(file);
        t.rgba32f.assign(texels.get(), texels.get() + size_t(t.width) * t.height * 4);
    } else {
        std::unique_ptr<stbi_uc, void (*)(void*)> texels(stbi_load_from_memory(data, size, &t.width, &t.height, &channelsInFile, 4),
                                                         stbi_image_free);
        if (!texels) failStb(file);
        t.rgba8.assign(texels.get(), texels.get() + size_t(t.width) * t.height * 4);
        t.srgb = srgb;
    }
    return t;
}

}  // namespace

std::optional<TextureFile> readTextureFile(const std::filesystem::path& file, std::string* error) {
    // readFile opens only regular files: opening a FIFO would wait for a writer forever.
    std::optional<std::string> bytes = readFile(file, error, kMaxTextureBytes);
    if (!bytes) return std::nullopt;
    std::optional<TextureInfo> info = infoOf(*bytes, file, error);
    if (!info) return std::nullopt;
    return TextureFile{file, std::move(*bytes), std::move(*info)};
}

std::optional<TextureInfo> textureInfo(const std::filesystem::path& file, std::string* error) {
    std::optional<TextureFile> read = readTextureFile(file, error);
    return read ? std::optional<TextureInfo>(std::move(read->info)) : std::nullopt;
}

Texture decodeTexture(const TextureFile& file, bool srgb, int layer) { return decode(file.bytes, file.path, srgb, layer); }

Texture loadTexture(const std::filesystem::path& file, bool srgb, int layer) {
    std::string why;
    std::optional<std::string> bytes = readFile(file, &why, kMaxTextureBytes);
    if (!bytes) failRead(file, why);
    return decode(*bytes, file, srgb, layer);
}

std::string pfmBytes(const Image& image) {
    std::string out = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    out.reserve(out.size() + size_t(image.width) * size_t(image.height) * 12);
    for (int y = image.height - 1; y >= 0; --y)  // PFM stores the bottom row first
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const uint32_t bits = std::bit_cast<uint32_t>(image.at(x, y)[c]);
                for (int b = 0; b < 4; ++b) out += char(bits >> (8 * b));  // little-endian
            }
    return out;
}

std::string pngBytes(const Texture& texture) {
    std::string out;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
    };
    if (!stbi_write_png_to_func(append, &out, texture.width, texture.height, 4, texture.rgba8.data(), texture.width * 4))
        throw std::runtime_error("cannot encode a PNG");
    return out;
}

Texture decodeTexture(std::string_view bytes, bool srgb) {
    Texture t;
    int channelsInFile = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &t.width, &t.height, &channelsInFile, 4),
        stbi_image_free);
    if (!data) throw TextureError(std::string("cannot decode an image: ") + (stbi_failure_reason() ? stbi_failure_reason() : "unknown"));
    t.rgba8.assign(data.get(), data.get() + size_t(t.width) * t.height * 4);
    t.srgb = srgb;
    return t;
}

bool isImageExtension(const std::filesystem::path& file) {
    const std::string ext = lowerExtension(file);
    return ext == ".pfm" || ext == ".png";
}

void writeImage(const Image& image, const std::filesystem::path& file) {
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != size_t(image.width) * image.height * 4)
        fail(file, "image has no pixels or the wrong number of values");
    const std::string ext = lowerExtension(file);
    if (ext == ".pfm")
        writeFileAtomically(file, [&](const std::filesystem::path& tmp) { return writePfm(image, tmp); });
    else if (ext == ".png")
        writeFileAtomically(file, [&](const std::filesystem::path& tmp) { return writePng(image, tmp); });
    else
        fail(file, "unsupported image extension '" + file.extension().string() + "' (supported: .pfm, .png)");
}

}  // namespace hexc
