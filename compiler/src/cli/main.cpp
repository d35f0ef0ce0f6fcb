// hexc: a thin command line over libhexc. Parses every material, compiles all of them, and writes
// outputs only when everything succeeded.
#include <iostream>
#include <set>

#include "cli/options.h"
#include "cli/outputs.h"
#include "cli/render.h"
#include "hexc/compiler.h"

using namespace hexc;

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (!args.empty() && args[0] == "render") return cli::renderCommand({args.begin() + 1, args.end()});
    if (!args.empty() && args[0] == "preview") return cli::previewCommand({args.begin() + 1, args.end()});
    if (args.size() == 1 && (args[0] == "-h" || args[0] == "--help")) return std::cout << cli::kHelp, cli::kOk;
    if (args.size() == 1 && args[0] == "--version") return std::cout << "hexc " << version() << "\n", cli::kOk;
    cli::Arguments a;
    try {
        a = cli::parseArguments(args);
    } catch (const cli::UsageError& e) {
        std::cerr << "hexc: " << e.message << "\n";
        return cli::kUsage;
    }

    std::vector<OutputFile> outputs;
    std::set<std::string> names;
    bool failed = false;
    for (const auto& path : a.materials) {
        ParseResult parsed = parseMaterialFile(path);
        CompileResult compiled = parsed.material ? compile(*parsed.material, a.options) : CompileResult{};
        for (const Diagnostics* diags : {&parsed.diagnostics, &compiled.diagnostics})
            for (const Diagnostic& d : *diags)
                if (!a.quiet || d.severity == Diagnostic::Severity::Error) std::cerr << d.format() << "\n";
        if (!parsed.material || !compiled.ok()) {
            failed = true;
            continue;
        }
        if (!names.insert(parsed.material->name).second) {
            std::cerr << path.string() << ": error: another material on the command line is also named `" << parsed.material->name
                      << "`; their outputs would overwrite each other\n";
            failed = true;
        }
        outputs.insert(outputs.end(), compiled.files.begin(), compiled.files.end());
    }
    if (failed) {
        std::cerr << "hexc: nothing written\n";
        return cli::kInvalidInput;
    }
    try {
        std::filesystem::create_directories(a.outDir);
        for (const OutputFile& f : outputs) cli::writeAtomically(a.outDir, f.name, f.contents);
    } catch (const std::exception& e) {
        std::cerr << "hexc: " << e.what() << "\n";
        return cli::kWriteFailed;
    }
    if (!a.quiet) std::cerr << "hexc: wrote " << outputs.size() << " files to " << a.outDir.string() << "\n";
    return cli::kOk;
}
