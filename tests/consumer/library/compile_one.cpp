// Compiles one material with libhexc and prints the files it would write: proves hexc::compiler links.
#include <cstdio>

#include "hexc/compiler.h"
#include "hexc/material.h"

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    hexc::ParseResult parsed = hexc::parseMaterialFile(argv[1]);
    if (!parsed.material) return std::fputs(hexc::formatAll(parsed.diagnostics).c_str(), stderr), 1;
    hexc::CompileResult result = hexc::compile(*parsed.material);
    for (const auto& file : result.files) std::printf("%s\n", file.name.c_str());
    return result.ok() ? 0 : 1;
}
