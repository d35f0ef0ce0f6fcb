// hexc: dispatches to the command line's commands (cli/: compile, render, preview, bake, library, lint, export-mtlx) and to
// `hexc edit` (edit/). It stands above both wings, which need nothing of each other.
#include <csignal>

#include "bake.h"
#include "build.h"
#include "edit.h"
#include "export.h"
#include "hexc/files.h"
#include "library.h"
#include "lint.h"
#include "options.h"
#include "render.h"

using namespace hexc;

namespace {

// Interrupted (Ctrl-C, a build system's kill): the temporaries being written are removed, then the signal ends the
// process as it would have.
extern "C" void interrupted(int signal) {
    removeOwnTemporaries();
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

}  // namespace

int main(int argc, char** argv) {
    for (int s : {SIGINT, SIGTERM, SIGHUP}) std::signal(s, interrupted);
    std::vector<std::string> args(argv + 1, argv + argc);
    if (!args.empty() && args[0] == "render") return cli::renderCommand({args.begin() + 1, args.end()});
    if (!args.empty() && args[0] == "bake") return cli::bakeCommand({args.begin() + 1, args.end()});
    if (!args.empty() && args[0] == "preview") return cli::previewCommand({args.begin() + 1, args.end()});
    if (!args.empty() && args[0] == "library") return cli::libraryCommand({args.begin() + 1, args.end()});
    if (!args.empty() && args[0] == "edit") return edit::editCommand({args.begin() + 1, args.end()});
    if (!args.empty() && args[0] == "lint") return cli::lintCommand({args.begin() + 1, args.end()});
    if (!args.empty() && args[0] == "export-mtlx") return cli::exportCommand({args.begin() + 1, args.end()});
    cli::Arguments a;
    if (std::optional<int> done = cli::parseArguments(args, a)) return *done;
    return cli::buildCommand(a);
}
