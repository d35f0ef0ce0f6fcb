#pragma once
// Command-line arguments of `hexc` (compile mode) -> CompileOptions and a list of materials.
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "command.h"
#include "hexc/cache.h"
#include "hexc/compiler.h"
#include "hexc/layout.h"
#include "hexc/report.h"

namespace CLI {
class App;
class Validator;
}  // namespace CLI

namespace hexc::cli {

// The commands' shared pieces (compiler/command), named here as every command of the command line uses them.
using command::kInvalidInput;
using command::kNoVulkan;
using command::kOk;
using command::kUsage;
using command::kWriteFailed;
using command::parseSize;
using command::parseWith;
using command::writeAtomically;

// Where a command reports: stderr, or a caller's stream and list (the C API's render, preview and build, whose result
// holds the text and the located diagnostics).
struct Messages {
    std::ostream* text = &std::cerr;
    Diagnostics* located = nullptr;
    // Prints `diagnostics` as the command line does, and keeps them in `located`.
    void report(const Diagnostics& diagnostics) const;
};

// Called as each compile of a build finishes, with the compiles finished, those to make and the material's (or scene
// variant's) name, one call at a time; false stops the build before anything is written.
using BuildProgress = std::function<bool(size_t done, size_t total, const std::string& name)>;

struct Arguments {
    std::vector<std::filesystem::path> materials;
    std::filesystem::path outDir;
    CompileOptions options;
    std::vector<std::string> engines;   // --engine: a package per engine instead of shaders (hexc/engines.h)
    std::filesystem::path depfile;      // --depfile
    std::vector<std::string> variants;  // --variant: only these scene variants
    bool quiet = false;                 // -q: no summary; warnings stay
    bool verbose = false;               // -v: what was compiled, skipped, shared, and why
    bool warnings = true;               // --no-warnings turns them off
    bool force = false;                 // --force: compile even what the stamps say is up to date
    bool listOutputs = false;           // --list-outputs: print the files a build would write; compile nothing
    unsigned jobs = 0;                  // -j: materials compiled at once; 0: one per core
    std::filesystem::path cacheDir;     // --cache-dir; empty: no folder cache (--no-cache, or no home folder)
    // Set by the C API's hexc_build, not by the command line:
    Messages messages;             // where diagnostics and the summary go
    BuildProgress progress;        // instead of the progress line on a terminal
    ShaderCache* cache = nullptr;  // its context's cache, instead of one over cacheDir
};

// A command line that parses but does not make sense (render.cpp's checks across options); exit kUsage.
struct UsageError {
    std::string message;
};

// --layout FILE and one flag per layout field (hexc/layout.h), for every command that compiles.
struct LayoutOptions {
    struct Flag {
        std::string name;
        const LayoutField* field;
        std::optional<uint32_t> value = {};
    };
    std::filesystem::path file;
    std::vector<Flag> flags;
    void add(CLI::App& app);  // once; the options stay bound to this object
    // The layout file (if any) with the flags over it; false after reporting the file's errors.
    bool resolve(ResourceLayout& out, const Messages& m = {}) const;
};

// A target option's help, "spirv, hlsl, ..., msl (or metal)", and its check: the names of `names`, each with its target's
// alias, and whether `named` knows a name.
std::string targetList(const std::vector<std::string>& names, std::optional<Target> (*named)(std::string_view));
CLI::Validator targetCheck(const std::vector<std::string>& names, std::optional<Target> (*named)(std::string_view));

// `hexc`'s compile mode; nullopt with `out` filled when it should run, else the exit code (see command::parseWith),
// reported to out.messages.
std::optional<int> parseArguments(const std::vector<std::string>& args, Arguments& out);

}  // namespace hexc::cli
