// libFuzzer target: the whole pipeline. The first byte chooses the options (targets, specialisation, lattice
// sharing, baking, HLSL shader model, GLSL version); the rest is a material, compiled when it parses.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "hexc/compiler.h"
#include "hexc/material.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1) return 0;
    const uint8_t bits = data[0];
    hexc::ParseResult parsed =
        hexc::parseMaterial(std::string_view(reinterpret_cast<const char*>(data + 1), size - 1), "materials/fuzz.json");
    if (!parsed.material) return 0;
    hexc::CompileOptions options;
    options.specialise = bits & 1;
    options.shareLattice = bits & 2;
    options.bake = bits & 4;
    options.hlslShaderModel = bits & 8 ? 60 : 50;
    options.glslVersion = bits & 16 ? 330 : 450;
    if (bits & 32) options.targets = {hexc::Target::Spirv};
    hexc::compile(*parsed.material, options);
    return 0;
}
