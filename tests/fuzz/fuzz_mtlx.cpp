// libFuzzer target: the MaterialX reader (and, through it, the JSON rules) on arbitrary text. Run from the source
// root, so the seed documents' texture paths resolve (tests/fuzz/run.sh).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "hexc/materialx.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    hexc::parseMaterialX(std::string_view(reinterpret_cast<const char*>(data), size), "materials/mtlx/fuzz.mtlx");
    return 0;
}
