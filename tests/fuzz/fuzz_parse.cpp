// libFuzzer target: the material and scene parsers on arbitrary text. Run from the source root, so the seed
// materials' texture paths resolve (tests/fuzz/run.sh).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "hexc/material.h"
#include "hexc/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    if (hexc::isSceneDocument(text))
        hexc::parseScene(text, "materials/scenes/fuzz.json");
    else
        hexc::parseMaterial(text, "materials/fuzz.json");
    return 0;
}
