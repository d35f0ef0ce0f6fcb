#include "hexc/image_files.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "hexc/files.h"
#include "textures/containers.h"

namespace hexc {
namespace {

void appendBigEndian(std::string& out, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(char((v >> shift) & 0xff));
}

// A PNG chunk: length, type, data and the CRC of type and data.
void appendChunk(std::string& out, const char* type, const std::string& data) {
    appendBigEndian(out, uint32_t(data.size()));
    const std::string typed = type + data;
    out += typed;
    appendBigEndian(out, uint32_t(crc32(0, reinterpret_cast<const Bytef*>(typed.data()), uInt(typed.size()))));
}

uint16_t quantised16(float v) { return std::isnan(v) ? 0 : uint16_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 65535.0f)); }

// 16-bit RGBA PNG bytes (stb writes 8 bits only): every row unfiltered, deflated by zlib at its default level, so the
// same image gives the same bytes.
std::string png16Bytes(const Image& image) {
    std::string raw;
    raw.reserve(size_t(image.height) * (1 + size_t(image.width) * 8));
    for (int y = 0; y < image.height; ++y) {
        raw.push_back('\0');  // filter type None
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const uint16_t v = quantised16(image.at(x, y)[c]);
                raw.push_back(char(v >> 8));
                raw.push_back(char(v & 0xff));
            }
    }
    uLongf size = compressBound(uLong(raw.size()));
    std::string deflated(size, '\0');
    if (compress2(reinterpret_cast<Bytef*>(deflated.data()), &size, reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size()),
                  Z_DEFAULT_COMPRESSION) != Z_OK)
        throw std::runtime_error("zlib could not compress the image");
    deflated.resize(size);
    std::string header;
    appendBigEndian(header, uint32_t(image.width));
    appendBigEndian(header, uint32_t(image.height));
    header += std::string("\x10\x06\x00\x00\x00", 5);  // 16 bits, RGBA, deflate, adaptive filtering, no interlace
    std::string out = "\x89PNG\r\n\x1a\n";
    appendChunk(out, "IHDR", header);
    appendChunk(out, "IDAT", deflated);
    appendChunk(out, "IEND", "");
    return out;
}

bool writeBytes(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    return bool(out);
}

}  // namespace

std::string exrBytes(const Image& image) {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer fb;
    const char* names[] = {"R", "G", "B", "A"};
    for (size_t c = 0; c < 4; ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
        fb.insert(names[c],
                  Imf::Slice(Imf::FLOAT, (char*)(image.rgba.data() + c), 4 * sizeof(float), size_t(image.width) * 4 * sizeof(float)));
    }
    Imf::StdOSStream stream;
    {
        Imf::OutputFile out(stream, header);  // written out when it goes
        out.setFrameBuffer(fb);
        out.writePixels(image.height);
    }
    return stream.str();
}

namespace {

double srgbDecoded(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double srgbEncoded(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055; }

// As writeImage rounds an 8-bit PNG (in float), so a KTX2 level 0 holds the bytes the PNG of the same image does.
uint8_t quantised8(float v) { return std::isnan(v) ? 0 : uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

// A KTX2 level's texels, RGBA: bytes for the 8-bit formats, floats for SFLOAT.
struct Level {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba8;
    std::vector<float> rgba32f;
};

// The level below `above`: each texel the 2x2 box average of the four above it (an odd last row or column left out,
// a side of one averaged with itself). sRGB colour is averaged in linear light and encoded again, alpha and UNORM as
// stored; 8-bit results rounded. Averaging the stored level, not the float one, makes each level exactly the rounded
// average of the one a reader sees above it.
Level halved(const Level& above, bool srgb) {
    Level l;
    l.width = std::max(1, above.width / 2), l.height = std::max(1, above.height / 2);
    const bool isFloat = !above.rgba32f.empty();
    (isFloat ? l.rgba32f.resize(size_t(l.width) * l.height * 4) : l.rgba8.resize(size_t(l.width) * l.height * 4));
    for (int y = 0; y < l.height; ++y)
        for (int x = 0; x < l.width; ++x)
            for (int c = 0; c < 4; ++c) {
                double sum = 0;
                for (int k = 0; k < 4; ++k) {
                    const size_t at = (size_t(std::min(2 * y + k / 2, above.height - 1)) * above.width +
                                       size_t(std::min(2 * x + k % 2, above.width - 1))) *
                                          4 +
                                      size_t(c);
                    sum += isFloat         ? double(above.rgba32f[at])
                           : srgb && c < 3 ? srgbDecoded(above.rgba8[at] / 255.0)
                                           : above.rgba8[at] / 255.0;
                }
                const size_t to = (size_t(y) * l.width + x) * 4 + size_t(c);
                if (isFloat)
                    l.rgba32f[to] = float(sum / 4);
                else
                    l.rgba8[to] = quantised8(float(srgb && c < 3 ? srgbEncoded(sum / 4) : sum / 4));
            }
    return l;
}

// Level 0 as stored: the image's values, rounded to 8 bits (clamped to [0, 1], NaN as 0) or as floats.
Level levelZero(const Image& image, bool isFloat) {
    Level l;
    l.width = image.width, l.height = image.height;
    if (isFloat) l.rgba32f = image.rgba;
    for (size_t i = 0; !isFloat && i < image.rgba.size(); ++i) l.rgba8.push_back(quantised8(image.rgba[i]));
    return l;
}

void put(std::string& out, size_t at, uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) out[at + size_t(i)] = char((v >> (8 * i)) & 0xff);
}

// KTX2 bytes (KTX 2.0): the header, the level index, the descriptor (containers::ktx2Dfd), no key/value data, no
// supercompression; the levels stored smallest first, each at a multiple of its texel's size and of 4.
std::string ktx2Bytes(const Image& image, uint32_t vkFormat) {
    const bool isFloat = vkFormat == 109;
    std::vector<Level> levels{levelZero(image, isFloat)};
    while (levels.back().width > 1 || levels.back().height > 1) levels.push_back(halved(levels.back(), vkFormat == 43));
    const std::string dfd = containers::ktx2Dfd(vkFormat);
    const size_t index = 80, align = isFloat ? 16 : 4;
    std::string out(index + 24 * levels.size(), '\0');
    out.replace(0, 12, "\xABKTX 20\xBB\r\n\x1A\n");
    const uint64_t header[] = {vkFormat,   isFloat ? 4u : 1u, uint32_t(image.width), uint32_t(image.height), 0, 0, 1, levels.size(), 0,
                               out.size(), dfd.size()};  // ..., faceCount, levelCount, scheme, dfd offset and length
    for (size_t i = 0; i < std::size(header); ++i) put(out, 12 + 4 * i, header[i], 4);
    out += dfd;
    for (size_t i = levels.size(); i-- > 0;) {
        out.resize((out.size() + align - 1) / align * align, '\0');
        const Level& l = levels[i];
        const std::string_view data = isFloat ? std::string_view(reinterpret_cast<const char*>(l.rgba32f.data()), l.rgba32f.size() * 4)
                                              : std::string_view(reinterpret_cast<const char*>(l.rgba8.data()), l.rgba8.size());
        put(out, index + 24 * i, out.size(), 8);
        put(out, index + 24 * i + 8, data.size(), 8);
        put(out, index + 24 * i + 16, data.size(), 8);
        out += data;
    }
    return out;
}

uint32_t vkFormatOf(ImageFormat format) { return format == ImageFormat::Ktx2Float ? 109 : format == ImageFormat::Ktx2Srgb8 ? 43 : 37; }

}  // namespace

ImageFormat imageFormat(std::string_view bytes) {
    if (bytes.starts_with("\x89PNG\r\n\x1a\n") && bytes.size() > 24) return bytes[24] == 16 ? ImageFormat::Png16 : ImageFormat::Png8;
    if (bytes.starts_with("\x76\x2f\x31\x01")) return ImageFormat::Exr;
    if (bytes.starts_with("PF") || bytes.starts_with("Pf")) return ImageFormat::Pfm;
    if (containers::kindOf(bytes) == containers::Kind::Ktx2 && bytes.size() >= 16) {
        const uint32_t vk = uint8_t(bytes[12]) | uint32_t(uint8_t(bytes[13])) << 8 | uint32_t(uint8_t(bytes[14])) << 16 |
                            uint32_t(uint8_t(bytes[15])) << 24;
        if (vk == 37 || vk == 44) return ImageFormat::Ktx2Unorm8;  // BGRA as RGBA: the same family, the order hexc writes
        if (vk == 43 || vk == 50) return ImageFormat::Ktx2Srgb8;
        if (vk == 109) return ImageFormat::Ktx2Float;
    }
    return ImageFormat::Other;
}

bool isKtx2(ImageFormat format) {
    return format == ImageFormat::Ktx2Unorm8 || format == ImageFormat::Ktx2Srgb8 || format == ImageFormat::Ktx2Float;
}

const char* imageExtension(ImageFormat format) {
    return format == ImageFormat::Exr ? ".exr" : format == ImageFormat::Pfm ? ".pfm" : isKtx2(format) ? ".ktx2" : ".png";
}

void writeImageAs(const Image& image, ImageFormat format, const std::filesystem::path& file) {
    if (isKtx2(format))
        return writeFileAtomically(file,
                                   [&](const std::filesystem::path& tmp) { return writeBytes(tmp, ktx2Bytes(image, vkFormatOf(format))); });
    if (format == ImageFormat::Png16)
        return writeFileAtomically(file, [&](const std::filesystem::path& tmp) { return writeBytes(tmp, png16Bytes(image)); });
    if (format == ImageFormat::Exr) {
        return writeFileAtomically(file, [&](const std::filesystem::path& tmp) {
            try {
                return writeBytes(tmp, exrBytes(image));
            } catch (const std::exception&) {  // OpenEXR's Iex exceptions: a write that failed
                return false;
            }
        });
    }
    writeImage(image, file);  // PNG 8-bit or PFM, by the extension imageExtension gave
}

}  // namespace hexc
