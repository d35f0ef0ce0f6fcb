// hexc: a thin command line over libhexc: compile (cli/build), render and preview (cli/render).
#include <iostream>

#include "build.h"
#include "options.h"
#include "render.h"
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

    return cli::buildCommand(a);
}
