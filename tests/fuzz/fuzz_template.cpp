// libFuzzer target: template text. Each input becomes the template of the example rock material (written to a
// file, as --template passes it), so the template checks, codegen and glslang see arbitrary GLSL.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "hexc/compiler.h"
#include "hexc/material.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const hexc::Material rock = *hexc::parseMaterialFile("materials/rock.json").material;
    static const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("hexc_fuzz_template_" + std::to_string(::getpid()) + ".glsl");
    std::ofstream(file, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    hexc::CompileOptions options;
    options.templateFile = file;
    options.targets = {hexc::Target::Spirv, hexc::Target::Glsl};
    hexc::compile(rock, options);
    return 0;
}
