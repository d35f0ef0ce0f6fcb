#include "hexc/image_files.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>

#include "hexc/files.h"

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

bool writeExr(const Image& image, const std::filesystem::path& file) {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer fb;
    const char* names[] = {"R", "G", "B", "A"};
    for (size_t c = 0; c < 4; ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
        fb.insert(names[c],
                  Imf::Slice(Imf::FLOAT, (char*)(image.rgba.data() + c), 4 * sizeof(float), size_t(image.width) * 4 * sizeof(float)));
    }
    Imf::OutputFile out(file.c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(image.height);
    return true;
}

}  // namespace

ImageFormat imageFormat(std::string_view bytes) {
    if (bytes.starts_with("\x89PNG\r\n\x1a\n") && bytes.size() > 24) return bytes[24] == 16 ? ImageFormat::Png16 : ImageFormat::Png8;
    if (bytes.starts_with("\x76\x2f\x31\x01")) return ImageFormat::Exr;
    if (bytes.starts_with("PF") || bytes.starts_with("Pf")) return ImageFormat::Pfm;
    return ImageFormat::Other;
}

const char* imageExtension(ImageFormat format) {
    return format == ImageFormat::Exr ? ".exr" : format == ImageFormat::Pfm ? ".pfm" : ".png";
}

void writeImageAs(const Image& image, ImageFormat format, const std::filesystem::path& file) {
    if (format == ImageFormat::Png16)
        return writeFileAtomically(file, [&](const std::filesystem::path& tmp) { return writeBytes(tmp, png16Bytes(image)); });
    if (format == ImageFormat::Exr) {
        return writeFileAtomically(file, [&](const std::filesystem::path& tmp) {
            try {
                return writeExr(image, tmp);
            } catch (const std::exception&) {  // OpenEXR's Iex exceptions: a write that failed
                return false;
            }
        });
    }
    writeImage(image, file);  // PNG 8-bit or PFM, by the extension imageExtension gave
}

}  // namespace hexc
