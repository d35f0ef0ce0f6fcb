// libFuzzer target: hexc's own binary parsing, the KTX2 and DDS readers. The first byte picks the container, whose
// magic is put in front of the rest (the header and data), so the fuzzer spends its time past the magic. OpenEXR
// and stb's formats are their libraries' parsers, fuzzed upstream.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "hexc/image.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    static const std::filesystem::path file = std::filesystem::temp_directory_path() / ("hexc_fuzz_texture_" + std::to_string(::getpid()));
    std::string bytes = (data[0] & 1) ? std::string(
                                            "\xAB"
                                            "KTX 20\xBB\r\n\x1A\n",
                                            12)
                                      : std::string("DDS ");
    bytes.append(reinterpret_cast<const char*>(data + 1), size - 1);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
    std::string why;
    if (hexc::textureInfo(file, &why)) {
        try {
            hexc::loadTexture(file, false);  // level 0 fits in the file (checked), so this allocates at most its size
        } catch (const hexc::TextureError&) {
        }
    }
    return 0;
}
