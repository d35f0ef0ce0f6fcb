// libFuzzer target: a layered material with its textures. The input is a material document, a NUL byte, then up to
// four texture files separated by "@@HEXC@@": the files f0 .. f3 beside the document, which the document names as
// its slots' `texture` (KTX2 arrays with `layer`) and its `layer_blend.splat` maps. So the layers' parser, the KTX2
// array checks, the splat maps' coverage (which decodes them) and the plan see fuzzed files. The document sits in a
// folder terrain/ beside a link textures/ to the example textures, so materials/terrain/terrain.json parses as it is.
// A material that parses is compiled to SPIR-V (the layers' code through glslang); an internal error is a finding.
// Run from the source root (tests/fuzz/run.sh).
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "hexc/compiler.h"
#include "hexc/material.h"

namespace {

constexpr std::string_view kSeparator = "@@HEXC@@";
constexpr int kFiles = 4;

// The folder of the document, made once per process.
std::filesystem::path documentFolder() {
    const std::filesystem::path root = std::filesystem::temp_directory_path() / ("hexc_fuzz_layers_" + std::to_string(::getpid()));
    std::filesystem::create_directories(root / "terrain");
    std::error_code ignored;
    std::filesystem::create_directory_symlink(std::filesystem::absolute("materials/textures"), root / "textures", ignored);
    return root / "terrain";
}

// hexc's own fault, which the library reports as a diagnostic (HX900) rather than crashing: a finding all the same.
void failOnInternal(const hexc::Diagnostics& diagnostics) {
    for (const hexc::Diagnostic& d : diagnostics)
        if (d.code == hexc::Code::Internal) {
            std::fprintf(stderr, "%s\n", d.message.c_str());
            std::abort();
        }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::filesystem::path folder = documentFolder();
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    const size_t cut = std::min(input.find('\0'), input.size());
    std::string_view files = input.substr(std::min(cut + 1, input.size()));
    // Every file written each time (empty when the input has fewer), so none is left from an earlier input.
    for (int i = 0; i < kFiles; ++i) {
        const size_t end = std::min(files.find(kSeparator), files.size());
        std::ofstream(folder / ("f" + std::to_string(i)), std::ios::binary | std::ios::trunc) << files.substr(0, end);
        files = files.substr(std::min(end + kSeparator.size(), files.size()));
    }
    const hexc::ParseResult parsed = hexc::parseMaterial(input.substr(0, cut), folder / "fuzz.json");
    failOnInternal(parsed.diagnostics);
    if (!parsed.material) return 0;
    hexc::CompileOptions options;
    options.targets = {hexc::Target::Spirv};
    options.concurrentTargets = false;  // one core per fuzzer process
    failOnInternal(hexc::compile(*parsed.material, options).diagnostics);
    return 0;
}
