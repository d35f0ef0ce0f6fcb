// libFuzzer target: hexc's own binary parsing, the KTX2 and DDS readers, and EXR reading through the OpenEXR library
// (with hexc's size limits; it reports a malformed file by exception, where tinyexr asserted). The first byte picks the container, whose magic is
// put in front of the rest (the header and data), so the fuzzer spends its time past the magic. stb's formats are its
// parsers, fuzzed upstream; hexc's own checks of their headers are plain arithmetic (tests/hostile_test.cpp).
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "hexc/image.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    static const std::filesystem::path file = std::filesystem::temp_directory_path() / ("hexc_fuzz_texture_" + std::to_string(::getpid()));
    static const std::string kMagic[] = {std::string("\xAB"
                                                     "KTX 20\xBB\r\n\x1A\n",
                                                     12),
                                         "DDS ", std::string("\x76\x2f\x31\x01", 4)};
    std::string bytes = kMagic[data[0] % 3];
    bytes.append(reinterpret_cast<const char*>(data + 1), size - 1);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
    std::string why;
    // Decoded only within a million texels: a larger size that passes the header checks (a compressed EXR claims many
    // texels in few bytes) is the texel budgets' to refuse (hexc/budgets.h, tests/hostile_test.cpp), not the decoder's.
    if (std::optional<hexc::TextureInfo> info = hexc::textureInfo(file, &why); info && int64_t(info->width) * info->height <= (1 << 20)) {
        try {
            // The header is checked (KTX2, DDS: level 0, every layer of a KTX2 array, fits in the file): the last layer.
            hexc::loadTexture(file, false, std::max(0, info->layers - 1));
        } catch (const hexc::TextureError&) {
        }
    }
    return 0;
}
