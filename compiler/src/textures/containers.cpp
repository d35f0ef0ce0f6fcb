#include "textures/containers.h"

#include "textures/memory_stream.h"

#include <IexBaseExc.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfVersion.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <iterator>
#include <memory>
#include <mutex>
#include <string_view>
#include <vector>

namespace hexc::containers {
namespace {

// A pixel format as far as hexc needs it: its channels, colour space, storage and whether level 0 is decoded.
struct Format {
    uint32_t code;  // DXGI_FORMAT or VkFormat
    const char* name;
    const char* channels;  // as TextureInfo::channelNames
    bool srgb;
    int block, blockBytes;  // texels per block side (4 for BCn, else 1) and bytes per block
    enum Decode { No, Rgba8, Bgra8, Rgba32f } decode;
};

constexpr Format kDxgi[] = {
    {2, "R32G32B32A32 float", "rgba", false, 1, 16, Format::Rgba32f},
    {6, "R32G32B32 float", "rgb", false, 1, 12, Format::No},
    {10, "R16G16B16A16 float", "rgba", false, 1, 8, Format::No},
    {16, "R32G32 float", "rg", false, 1, 8, Format::No},
    {28, "R8G8B8A8", "rgba", false, 1, 4, Format::Rgba8},
    {29, "R8G8B8A8 sRGB", "rgba", true, 1, 4, Format::Rgba8},
    {41, "R32 float", "r", false, 1, 4, Format::No},
    {49, "R8G8", "rg", false, 1, 2, Format::No},
    {61, "R8", "r", false, 1, 1, Format::No},
    {71, "BC1", "rgba", false, 4, 8, Format::No},
    {72, "BC1 sRGB", "rgba", true, 4, 8, Format::No},
    {74, "BC2", "rgba", false, 4, 16, Format::No},
    {75, "BC2 sRGB", "rgba", true, 4, 16, Format::No},
    {77, "BC3", "rgba", false, 4, 16, Format::No},
    {78, "BC3 sRGB", "rgba", true, 4, 16, Format::No},
    {80, "BC4", "r", false, 4, 8, Format::No},
    {81, "BC4 signed", "r", false, 4, 8, Format::No},
    {83, "BC5", "rg", false, 4, 16, Format::No},
    {84, "BC5 signed", "rg", false, 4, 16, Format::No},
    {87, "B8G8R8A8", "rgba", false, 1, 4, Format::Bgra8},
    {88, "B8G8R8X8", "rgb", false, 1, 4, Format::No},
    {91, "B8G8R8A8 sRGB", "rgba", true, 1, 4, Format::Bgra8},
    {93, "B8G8R8X8 sRGB", "rgb", true, 1, 4, Format::No},
    {95, "BC6H", "rgb", false, 4, 16, Format::No},
    {96, "BC6H signed", "rgb", false, 4, 16, Format::No},
    {98, "BC7", "rgba", false, 4, 16, Format::No},
    {99, "BC7 sRGB", "rgba", true, 4, 16, Format::No},
};

constexpr Format kVk[] = {
    {9, "R8", "r", false, 1, 1, Format::No},
    {15, "R8 sRGB", "r", true, 1, 1, Format::No},
    {16, "R8G8", "rg", false, 1, 2, Format::No},
    {23, "R8G8B8", "rgb", false, 1, 3, Format::No},
    {29, "R8G8B8 sRGB", "rgb", true, 1, 3, Format::No},
    {37, "R8G8B8A8", "rgba", false, 1, 4, Format::Rgba8},
    {43, "R8G8B8A8 sRGB", "rgba", true, 1, 4, Format::Rgba8},
    {44, "B8G8R8A8", "rgba", false, 1, 4, Format::Bgra8},
    {50, "B8G8R8A8 sRGB", "rgba", true, 1, 4, Format::Bgra8},
    {97, "R16G16B16A16 float", "rgba", false, 1, 8, Format::No},
    {100, "R32 float", "r", false, 1, 4, Format::No},
    {103, "R32G32 float", "rg", false, 1, 8, Format::No},
    {106, "R32G32B32 float", "rgb", false, 1, 12, Format::No},
    {109, "R32G32B32A32 float", "rgba", false, 1, 16, Format::Rgba32f},
    {131, "BC1 RGB", "rgb", false, 4, 8, Format::No},
    {132, "BC1 RGB sRGB", "rgb", true, 4, 8, Format::No},
    {133, "BC1", "rgba", false, 4, 8, Format::No},
    {134, "BC1 sRGB", "rgba", true, 4, 8, Format::No},
    {135, "BC2", "rgba", false, 4, 16, Format::No},
    {136, "BC2 sRGB", "rgba", true, 4, 16, Format::No},
    {137, "BC3", "rgba", false, 4, 16, Format::No},
    {138, "BC3 sRGB", "rgba", true, 4, 16, Format::No},
    {139, "BC4", "r", false, 4, 8, Format::No},
    {140, "BC4 signed", "r", false, 4, 8, Format::No},
    {141, "BC5", "rg", false, 4, 16, Format::No},
    {142, "BC5 signed", "rg", false, 4, 16, Format::No},
    {143, "BC6H", "rgb", false, 4, 16, Format::No},
    {144, "BC6H signed", "rgb", false, 4, 16, Format::No},
    {145, "BC7", "rgba", false, 4, 16, Format::No},
    {146, "BC7 sRGB", "rgba", true, 4, 16, Format::No},
};

// Legacy DDS files name block formats by FourCC instead of a DXGI code.
constexpr std::pair<const char*, uint32_t> kFourCc[] = {{"DXT1", 71}, {"DXT2", 74},       {"DXT3", 74},     {"DXT4", 77}, {"DXT5", 77},
                                                        {"ATI1", 80}, {"BC4U", 80},       {"BC4S", 81},     {"ATI2", 83}, {"BC5U", 83},
                                                        {"BC5S", 84}, {"\x71\0\0\0", 10}, {"\x74\0\0\0", 2}};

template <size_t N>
const Format* find(const Format (&table)[N], uint32_t code) {
    for (const Format& f : table)
        if (f.code == code) return &f;
    return nullptr;
}

// A container's header as far as hexc reads it.
struct Header {
    int width = 0, height = 0, mips = 1;
    int layers = 0;  // a KTX2 array's layerCount; 0 for a 2D texture
    const Format* format = nullptr;
    // Whether the format says sRGB or not: a legacy DDS (no DX10 header) has no sRGB flag, so its 8-bit and block
    // formats may hold either (engines decide by the slot); only its float formats are known to be linear.
    bool colorSpaceStated = true;
    uint64_t dataOffset = 0;  // of level 0
    std::string problem;      // why the file cannot be used, when it cannot
};

uint32_t u32(const std::vector<unsigned char>& b, size_t at) {
    return at + 4 <= b.size() ? uint32_t(b[at]) | uint32_t(b[at + 1]) << 8 | uint32_t(b[at + 2]) << 16 | uint32_t(b[at + 3]) << 24 : 0;
}

std::vector<unsigned char> prefix(std::string_view bytes, size_t size) {
    const std::string_view head = bytes.substr(0, size);
    return {head.begin(), head.end()};
}

constexpr unsigned char kKtx2Magic[12] = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};

Header ktx2Header(const std::vector<unsigned char>& b) {
    Header h;
    if (b.size() < 104) return {.problem = "KTX2 header is truncated"};
    const uint32_t vkFormat = u32(b, 12);
    h.width = int(u32(b, 20));
    h.height = int(std::max(1u, u32(b, 24)));
    h.mips = int(std::max(1u, u32(b, 40)));
    h.dataOffset = u32(b, 80) | uint64_t(u32(b, 84)) << 32;
    h.format = find(kVk, vkFormat);
    // An array holds layerCount layers (a 1-layer array is still one); more than 2048 is past any device's limit
    // (maxImageArrayLayers, at least 256 in Vulkan).
    const uint32_t layers = u32(b, 32);
    if (vkFormat == 0)
        h.problem = "KTX2 with VK_FORMAT_UNDEFINED (Basis Universal) is not supported; transcode it to a BCn format";
    else if (!h.format)
        h.problem = "KTX2 vkFormat " + std::to_string(vkFormat) + " is not one hexc reads (8-bit, float or BC1-BC7)";
    else if (u32(b, 28) > 1 || u32(b, 36) > 1)
        h.problem = "a KTX2 cube or 3D texture is not a 2D texture or 2D array";
    else if (layers > 2048)
        h.problem = "a KTX2 array of " + std::to_string(layers) + " layers (hexc reads up to 2048)";
    else if (u32(b, 44) != 0)
        h.problem = "supercompressed KTX2 (scheme " + std::to_string(u32(b, 44)) + ")";
    h.layers = int(layers);
    return h;
}

const Format* ddsLegacyFormat(const std::vector<unsigned char>& b, std::string* problem) {
    const uint32_t flags = u32(b, 80), bits = u32(b, 88);
    if (flags & 0x4) {  // DDPF_FOURCC
        for (const auto& [cc, dxgi] : kFourCc)
            if (std::memcmp(cc, &b[84], 4) == 0) return find(kDxgi, dxgi);
        *problem = "DDS FourCC `" + std::string(reinterpret_cast<const char*>(&b[84]), 4) + "` is not one hexc reads";
        return nullptr;
    }
    const bool rgba = u32(b, 92) == 0xff && u32(b, 100) == 0xff0000, bgra = u32(b, 92) == 0xff0000 && u32(b, 100) == 0xff;
    if ((flags & 0x40) && bits == 32 && (flags & 0x1) && (rgba || bgra)) return find(kDxgi, rgba ? 28 : 87);
    *problem = "this uncompressed DDS layout (" + std::to_string(bits) + " bits per texel) is not one hexc reads; use 32-bit RGBA";
    return nullptr;
}

Header ddsHeader(const std::vector<unsigned char>& b) {
    Header h;
    if (b.size() < 128 || u32(b, 4) != 124) return {.problem = "DDS header is truncated or malformed"};
    h.height = int(u32(b, 12));
    h.width = int(u32(b, 16));
    h.mips = int(std::max(1u, u32(b, 28)));
    const bool dx10 = std::memcmp(&b[84], "DX10", 4) == 0;
    h.dataOffset = dx10 ? 148 : 128;
    if (dx10 && b.size() < 148) return {.problem = "DDS DX10 header is truncated"};
    if (dx10) {
        h.format = find(kDxgi, u32(b, 128));
        if (!h.format)
            h.problem = "DDS DXGI format " + std::to_string(u32(b, 128)) + " is not one hexc reads (8-bit, float or BC1-BC7)";
        else if (u32(b, 132) != 3 || u32(b, 140) > 1 || (u32(b, 136) & 0x4))
            h.problem = "a DDS array, cube or 3D texture is not a 2D texture";
    } else {
        h.format = ddsLegacyFormat(b, &h.problem);
        h.colorSpaceStated = h.format && std::string_view(h.format->name).ends_with("float");
    }
    return h;
}

// One layer of level 0: KTX2 stores an array's level 0 layer after layer (layer-major), each this size.
uint64_t layerBytes(const Header& h) {
    const Format& f = *h.format;
    return uint64_t((h.width + f.block - 1) / f.block) * uint64_t((h.height + f.block - 1) / f.block) * f.blockBytes;
}

// Level `level` of every layer: its texels, at least one a side, in whole blocks.
uint64_t levelBytes(const Header& h, int level) {
    Header at = h;
    at.width = std::max(1, h.width >> level), at.height = std::max(1, h.height >> level);
    return layerBytes(at) * uint64_t(std::max(1, h.layers));
}

uint32_t word(std::string_view bytes, uint64_t at) {
    uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}

// Why a KTX2 file's level index or descriptor cannot be trusted, or empty: each level whole within the file, no more
// levels than halving the larger side gives, and for the formats hexc writes the descriptor of the vkFormat (a
// descriptor saying other channels, bits or transfer would be read as something it is not).
std::string ktx2Problem(const Header& h, std::string_view bytes) {
    if (h.mips > int(std::bit_width(uint32_t(std::max(h.width, h.height)))))
        return "KTX2 levelCount " + std::to_string(h.mips) + " exceeds the size's";
    if (80 + uint64_t(h.mips) * 24 > bytes.size()) return "the file is truncated (the level index does not fit)";
    for (int i = 0; i < h.mips; ++i) {
        const uint64_t offset = word(bytes, 80 + 24 * i) | uint64_t(word(bytes, 84 + 24 * i)) << 32;
        const uint64_t length = word(bytes, 88 + 24 * i) | uint64_t(word(bytes, 92 + 24 * i)) << 32;
        if (length < levelBytes(h, i) || offset > bytes.size() || length > bytes.size() - offset)
            return "the file is truncated (level " + std::to_string(i) + " does not fit)";
    }
    const std::string dfd = ktx2Dfd(h.format->code);
    const uint32_t at = word(bytes, 48), length = word(bytes, 52);
    if (dfd.empty() || length == 0) return {};
    std::string found = length == dfd.size() && at <= bytes.size() - length ? std::string(bytes.substr(at, length)) : std::string();
    if (found.size() == dfd.size()) found[13] = dfd[13];  // colour primaries: any
    if (found != dfd) return std::string("the KTX2 Data Format Descriptor does not describe its vkFormat (") + h.format->name + ")";
    return {};
}

Header header(Kind kind, std::string_view bytes) {
    std::vector<unsigned char> b = prefix(bytes, 148);
    Header h = kind == Kind::Ktx2 ? ktx2Header(b) : ddsHeader(b);
    if (!h.problem.empty()) return h;
    if (h.width <= 0 || h.height <= 0 || h.width > 65536 || h.height > 65536) return {.problem = "the header gives no valid size"};
    // Level 0 must be in the file, every layer of it: a truncated texture would fail in the engine, not here.
    const uint64_t level0 = layerBytes(h) * uint64_t(std::max(1, h.layers));
    if (h.dataOffset > bytes.size() || level0 > bytes.size() - h.dataOffset) h.problem = "the file is truncated (level 0 does not fit)";
    if (kind == Kind::Ktx2 && h.problem.empty()) h.problem = ktx2Problem(h, bytes);
    return h;
}

// OpenEXR through the OpenEXR library (Debian's, fuzzed upstream), which reports a malformed file with an exception
// where tinyexr asserts and aborts the process. Its sanity check refuses a data window or tile past these sizes
// before allocating for it; the limits are process-wide, set once.
void limitExrSizes() {
    static std::once_flag once;
    std::call_once(once, [] {
        Imf::Header::setMaxImageSize(65536, 65536);
        Imf::Header::setMaxTileSize(65536, 65536);
    });
}

// The channels hexc decodes, as tinyexr's LoadEXR did: one channel is grey in all four, else R, G and B (A if there).
struct ExrChannels {
    std::vector<std::string> names;  // the file's channel per RGBA component, one entry for a grey file
    int count = 0;                   // the file's channels, up to 4, as TextureInfo::channels
};

ExrChannels exrChannels(const Imf::Header& h) {
    ExrChannels c;
    std::vector<std::string> all;
    for (auto it = h.channels().begin(); it != h.channels().end(); ++it) all.emplace_back(it.name());
    c.count = int(std::min<size_t>(all.size(), 4));
    if (all.size() == 1) {
        c.names = all;
        return c;
    }
    for (const char* name : {"R", "G", "B", "A"})
        if (h.channels().findChannel(name)) c.names.emplace_back(name);
    if (c.names.size() < 3 || c.names[0] != "R" || c.names[1] != "G" || c.names[2] != "B") c.names.clear();
    return c;
}

// Why an opened EXR cannot be used, or empty: a single part, a data window of 1..65536 a side (the window's corners
// are any 32-bit integers, hence 64 bits), channels hexc can decode.
std::string exrProblem(const Imf::InputFile& in, int64_t width, int64_t height) {
    if (Imf::isMultiPart(in.version()) || Imf::isNonImage(in.version())) return "a multi-part or deep file (hexc reads single-part images)";
    if (width < 1 || height < 1 || width > 65536 || height > 65536)
        return "the data window gives " + std::to_string(width) + "x" + std::to_string(height) + " (sizes are 1..65536)";
    if (exrChannels(in.header()).names.empty()) return "no R, G and B channels and not a single channel";
    return {};
}

// Scanlines per chunk by compression (NONE, RLE, ZIPS, ZIP, PIZ, PXR24, B44, B44A, DWAA, DWAB), the OpenEXR file layout.
constexpr int kExrLinesPerChunk[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};

// What exrLayoutProblem reads of the header: the data window, the tiles and the compression, with the values the
// OpenEXR library takes where the header has none (a 64 x 64 window, 32 x 32 tiles, ZIP), and whether the version
// field says the file is tiled.
struct ExrLayout {
    int32_t window[4] = {0, 0, 63, 63};  // x0, y0, x1, y1
    uint32_t tile[2] = {32, 32};
    uint8_t compression = 3;
    bool tiled = false;
    uint64_t table = 0;  // where level 0's chunk table starts: after the header's last byte
};

// Reads the header's attributes (`name\0type\0`, a 32-bit size and the value; an empty name ends them), each stated
// size checked against the bytes that follow it. Why they do not fit, or empty.
std::string readExrHeader(std::istream& in, uint64_t size, ExrLayout& l) {
    auto text = [&](std::string* out) {
        for (char c; out->size() <= 255 && in.get(c);) {
            if (c == '\0') return true;
            *out += c;
        }
        return false;
    };
    uint32_t version = 0;
    in.seekg(4).read(reinterpret_cast<char*>(&version), 4);  // after the magic number
    l.tiled = version & 0x200;
    for (std::string name; text(&name) && !name.empty(); name.clear()) {
        std::string type;
        uint32_t bytes = 0;
        if (!text(&type) || !in.read(reinterpret_cast<char*>(&bytes), 4)) break;
        const uint64_t at = uint64_t(in.tellg());
        if (bytes > size - at)
            return "the header's attribute `" + name + "` claims " + std::to_string(bytes) + " bytes past the file's end";
        if (name == "dataWindow" && bytes == 16) in.read(reinterpret_cast<char*>(l.window), 16);
        if (name == "tiles" && bytes == 9) in.read(reinterpret_cast<char*>(l.tile), 8);
        if (name == "compression" && bytes == 1) in.read(reinterpret_cast<char*>(&l.compression), 1);
        in.seekg(std::streamoff(at + bytes));
    }
    if (!in) return "the header is truncated or malformed";
    l.table = uint64_t(in.tellg());
    return {};
}

// Why the file's layout cannot be handed to the OpenEXR library, or empty. The library allocates what a file states
// before reading it (an attribute's size, a chunk's size), so a 400-byte file could make it ask for 2 GB, which takes a
// sanitized build tens of seconds: each stated size is checked against the bytes that follow it first. Level 0's
// chunk table holds a 64-bit offset a chunk; a scanline chunk starts with its y and size, a tile with its x, y, level
// x, level y and size. A window outside 1..65536 and an unknown compression are the library's to refuse.
std::string exrLayoutProblem(std::string_view bytes) {
    MemoryStream in(bytes);
    const uint64_t size = bytes.size();
    ExrLayout l;
    if (std::string problem = readExrHeader(in, size, l); !problem.empty()) return problem;
    const int64_t width = int64_t(l.window[2]) - l.window[0] + 1, height = int64_t(l.window[3]) - l.window[1] + 1;
    if (width < 1 || height < 1 || width > 65536 || height > 65536 || l.compression >= std::size(kExrLinesPerChunk) ||
        (l.tiled && (l.tile[0] < 1 || l.tile[1] < 1)))
        return {};
    const int64_t lines = kExrLinesPerChunk[l.compression];
    const int64_t chunks =
        l.tiled ? (width + l.tile[0] - 1) / l.tile[0] * ((height + l.tile[1] - 1) / l.tile[1]) : (height + lines - 1) / lines;
    if (uint64_t(chunks) > (size - l.table) / 8) return "level 0's chunk table runs past the file's end";
    const uint64_t head = l.tiled ? 20 : 8;  // a chunk's header, its size last
    for (int64_t c = 0; c < chunks; ++c) {
        uint64_t offset = 0;
        int32_t bytes = -1;
        in.seekg(std::streamoff(l.table + uint64_t(c) * 8));
        in.read(reinterpret_cast<char*>(&offset), 8);
        if (in && offset >= l.table && offset <= size - head)
            in.seekg(std::streamoff(offset + head - 4)).read(reinterpret_cast<char*>(&bytes), 4);
        if (!in || bytes < 0 || uint64_t(bytes) > size - offset - head)
            return "a chunk of level 0 starts or ends past the file's end (the file is truncated or malformed)";
    }
    return {};
}

// An EXR file's bytes as the OpenEXR library reads a file: a short read throws, as its own file stream does.
class ExrBytes : public Imf::IStream {
public:
    ExrBytes(std::string_view bytes, const std::filesystem::path& file) : Imf::IStream(file.c_str()), bytes_(bytes) {}
    bool read(char c[], int n) override {
        if (n < 0 || at_ > bytes_.size() || uint64_t(n) > bytes_.size() - at_) throw Iex::InputExc("Unexpected end of file.");
        std::memcpy(c, bytes_.data() + at_, size_t(n));
        at_ += uint64_t(n);
        return at_ < bytes_.size();
    }
    uint64_t tellg() override { return at_; }
    void seekg(uint64_t pos) override { at_ = pos; }

private:
    std::string_view bytes_;
    uint64_t at_ = 0;
};

// Checks the file's layout, opens it in the OpenEXR library once and hands it to use(file, width, height); false with
// the reason in *error when it cannot be used.
template <class Use>
bool readExr(std::string_view bytes, const std::filesystem::path& file, std::string* error, Use use) {
    limitExrSizes();
    std::string problem = exrLayoutProblem(bytes);
    try {
        if (problem.empty()) {
            ExrBytes stream(bytes, file);
            Imf::InputFile in(stream);
            const Imath::Box2i w = in.header().dataWindow();
            const int64_t width = int64_t(w.max.x) - w.min.x + 1, height = int64_t(w.max.y) - w.min.y + 1;
            problem = exrProblem(in, width, height);
            if (problem.empty()) {
                use(in, int(width), int(height));
                return true;
            }
        }
    } catch (const std::exception& e) {
        problem = e.what();
    }
    *error = "OpenEXR: " + problem;
    return false;
}

std::optional<TextureInfo> exrInfo(std::string_view bytes, const std::filesystem::path& file, std::string* error) {
    TextureInfo info;
    const auto describe = [&](Imf::InputFile& in, int width, int height) {
        info.width = width, info.height = height, info.channels = exrChannels(in.header()).count;
        info.channelNames = std::string("rgba").substr(0, size_t(info.channels));
        info.format = "OpenEXR";
    };
    return readExr(bytes, file, error, describe) ? std::optional<TextureInfo>(info) : std::nullopt;
}

Texture loadExr(std::string_view bytes, const std::filesystem::path& file) {
    Texture t;
    const auto decode = [&](Imf::InputFile& in, int width, int height) {
        const Imath::Box2i window = in.header().dataWindow();
        t.width = width, t.height = height;
        t.rgba32f.assign(size_t(t.width) * t.height * 4, 1.0f);  // alpha 1 where the file has none
        const std::vector<std::string> names = exrChannels(in.header()).names;
        Imf::FrameBuffer fb;
        for (size_t c = 0; c < names.size(); ++c)
            fb.insert(names[c], Imf::Slice::Make(Imf::FLOAT, t.rgba32f.data() + c, window, 4 * sizeof(float)));
        in.setFrameBuffer(fb);
        in.readPixels(window.min.y, window.max.y);
        if (names.size() == 1)
            for (size_t i = 0; i < t.rgba32f.size(); i += 4) std::fill_n(&t.rgba32f[i + 1], 3, t.rgba32f[i]);
    };
    if (std::string why; !readExr(bytes, file, &why, decode)) throw TextureError(file.string() + ": " + why);
    return t;
}

Texture decode(const Header& h, std::string_view bytes, const std::filesystem::path& file, bool srgb, int layer) {
    const Format& f = *h.format;
    MemoryStream in(bytes);
    in.seekg(std::streamoff(h.dataOffset + layerBytes(h) * uint64_t(layer)));
    Texture t;
    t.width = h.width;
    t.height = h.height;
    const size_t texels = size_t(h.width) * h.height;
    if (f.decode == Format::Rgba32f) {
        t.rgba32f.resize(texels * 4);
        in.read(reinterpret_cast<char*>(t.rgba32f.data()), std::streamsize(texels * 16));
    } else {
        t.rgba8.resize(texels * 4);
        in.read(reinterpret_cast<char*>(t.rgba8.data()), std::streamsize(texels * 4));
        if (f.decode == Format::Bgra8)
            for (size_t i = 0; i < t.rgba8.size(); i += 4) std::swap(t.rgba8[i], t.rgba8[i + 2]);
        t.srgb = srgb;
    }
    if (!in) throw TextureError(file.string() + ": the file is truncated");
    return t;
}

}  // namespace

std::string ktx2Dfd(uint32_t vkFormat) {
    if (vkFormat != 37 && vkFormat != 43 && vkFormat != 109) return {};
    const bool srgb = vkFormat == 43, isFloat = vkFormat == 109;
    const uint32_t bits = isFloat ? 32 : 8;
    // Words of the basic block: vendor 0 and type 0; version 2 (Data Format 1.3) and the block's size; colour model
    // RGBSDA, primaries BT.709, transfer sRGB or linear, straight alpha; a 1x1 texel block; bytes in plane 0.
    std::vector<uint32_t> w = {0, 2u | uint32_t(24 + 16 * 4) << 16, 1u | 1u << 8 | (srgb ? 2u : 1u) << 16, 0, bits / 2, 0};
    const uint32_t channels[] = {0, 1, 2, 15};  // R, G, B, A
    for (uint32_t c = 0; c < 4; ++c) {
        // Qualifiers: float and signed for SFLOAT; alpha linear where the transfer is sRGB.
        const uint32_t qualifiers = (isFloat ? 0xC0u : 0u) | (srgb && c == 3 ? 0x10u : 0u);
        w.insert(w.end(), {c * bits | (bits - 1) << 16 | (channels[c] | qualifiers) << 24, 0,  // offset, length, channel; position 0
                           isFloat ? 0xBF800000u : 0u, isFloat ? 0x3F800000u : 255u});         // lower, upper: -1..1 or 0..255
    }
    std::string out(4 + w.size() * 4, '\0');
    const uint32_t total = uint32_t(out.size());
    std::memcpy(out.data(), &total, 4);
    std::memcpy(out.data() + 4, w.data(), w.size() * 4);
    return out;
}

Kind kindOf(std::string_view bytes) {
    std::vector<unsigned char> b = prefix(bytes, 12);
    if (b.size() == 12 && std::memcmp(b.data(), kKtx2Magic, 12) == 0) return Kind::Ktx2;
    if (b.size() >= 4 && std::memcmp(b.data(), "DDS ", 4) == 0) return Kind::Dds;
    if (b.size() >= 4 && std::memcmp(b.data(), "\x76\x2f\x31\x01", 4) == 0) return Kind::Exr;
    return Kind::None;
}

std::optional<TextureInfo> info(Kind kind, std::string_view bytes, const std::filesystem::path& file, std::string* error) {
    if (kind == Kind::Exr) return exrInfo(bytes, file, error);
    Header h = header(kind, bytes);
    if (!h.problem.empty()) {
        *error = h.problem;
        return std::nullopt;
    }
    const std::string names = h.format->channels;
    const char* container = kind == Kind::Ktx2 ? "KTX2 " : "DDS ";
    const std::optional<bool> srgb = h.colorSpaceStated ? std::optional<bool>(h.format->srgb) : std::nullopt;
    TextureInfo info{h.width, h.height, int(names.size()), names, h.mips, srgb, container + std::string(h.format->name)};
    info.layers = h.layers;
    return info;
}

Texture load(Kind kind, std::string_view bytes, const std::filesystem::path& file, bool srgb, int layer) {
    if (kind == Kind::Exr && layer != 0) throw TextureError(file.string() + ": an EXR file has no layer " + std::to_string(layer));
    if (kind == Kind::Exr) return loadExr(bytes, file);
    Header h = header(kind, bytes);
    if (h.problem.empty() && (layer < 0 || layer >= std::max(1, h.layers)))
        h.problem = "no layer " + std::to_string(layer) + " (the file has " + std::to_string(std::max(1, h.layers)) + ")";
    if (!h.problem.empty()) throw TextureError(file.string() + ": " + h.problem);
    if (h.format->decode == Format::No)
        throw TextureError(file.string() + ": hexc render and preview do not decode " + h.format->name +
                           " (only uncompressed 8-bit and 32-bit float RGBA, and EXR); hexc compiles with it");
    return decode(h, bytes, file, srgb, layer);
}

}  // namespace hexc::containers
