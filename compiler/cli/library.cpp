#include "library.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <map>

#include "hexc/library.h"
#include "options.h"

namespace hexc::cli {

namespace {

const char* const kLibraryHelp = R"(hexc library - hexc's hex-tiling functions for shaders you write by hand

  hexc library --target hlsl|glsl|msl|wgsl|spirv-asm [--target ...] -o DIR

Writes DIR/hexc_hextiling.{hlsl,glsl,metal,wgsl,spvasm}: the colour path (hexcColor), the normal map derivative path
(hexcDeriv), their 1-tap variants (hexcColor1, hexcDeriv1), the lattices of each mode and mask (hexcTilesStable,
hexcTilesPaper, hexcTilesChecker, hexcTilesNoise), shared by every texture that uses the same coordinates, and
the settings as structs (hexcLattice(), hexcBlend()). Made from the GLSL hexc injects into materials, through
glslang and SPIRV-Cross (WGSL: naga, built in or in Node.js as for the wgsl target). docs/library.md
documents each function and shows a whole shader per target.
)";

}  // namespace

int libraryCommand(const std::vector<std::string>& args) {
    CLI::App app{kLibraryHelp, "hexc library"};
    std::vector<std::string> targets;
    std::filesystem::path outDir;
    app.add_option("-t,--target,--targets", targets,
                   targetList(libraryTargetNames(), libraryTargetNamed) + "; repeatable or comma-separated")
        ->required()
        ->delimiter(',')
        ->check(targetCheck(libraryTargetNames(), libraryTargetNamed));
    app.add_option("-o,--out", outDir, "output folder")->required()->type_name("DIR");
    if (std::optional<int> done = parseWith(app, args)) return *done;
    std::vector<Target> chosen;
    for (const std::string& t : targets) chosen.push_back(*libraryTargetNamed(t));
    std::vector<OutputFile> files;
    try {
        files = hexcLibrary(chosen);
    } catch (const CompileError& e) {  // wgsl's translator is missing, or the embedded library does not compile (a hexc bug)
        std::cerr << formatAll(e.diagnostics) << "hexc: no library written\n";
        return kInvalidInput;
    }
    try {
        if (std::error_code ec; !std::filesystem::create_directories(outDir, ec) && !std::filesystem::is_directory(outDir))
            throw std::runtime_error("cannot write to " + outDir.string() + ": " +
                                     (std::filesystem::exists(outDir) ? "it is a file, not a folder" : ec.message()));
        for (const OutputFile& f : files) writeAtomically(outDir, f.name, f.contents);
    } catch (const std::exception& e) {
        std::cerr << "hexc: " << e.what() << "\n";
        return kWriteFailed;
    }
    for (const OutputFile& f : files) std::cerr << "hexc: wrote " << (outDir / f.name).string() << "\n";
    return kOk;
}

}  // namespace hexc::cli
