#pragma once
// Command-line arguments of `hexc` (compile mode) -> CompileOptions and a list of materials.
#include <filesystem>
#include <string>
#include <vector>

#include "hexc/compiler.h"

namespace hexc::cli {

// Exit codes, documented in --help and docs/cli.md.
enum Exit { kOk = 0, kInvalidInput = 1, kUsage = 2, kWriteFailed = 3, kNoVulkan = 4 };

struct Arguments {
    std::vector<std::filesystem::path> materials;
    std::filesystem::path outDir;
    CompileOptions options;
    std::filesystem::path depfile;        // --depfile
    std::vector<std::string> variants;    // --variant: only these scene variants
    bool quiet = false;
};

// Throws UsageError with a message naming the bad argument.
struct UsageError {
    std::string message;
};
Arguments parseArguments(const std::vector<std::string>& args);

extern const char* const kHelp;

}  // namespace hexc::cli
