#include "edit.h"

#include <CLI/CLI.hpp>
#include <malloc.h>

#include <iostream>
#include <tuple>

#include "capture.h"
#include "hexc/materialx.h"
#include "hexc/report.h"
#include "command.h"
#include "server.h"
#include "session.h"

namespace hexc::edit {

namespace {

const char* const kEditHelp = R"(hexc edit - tune a material live in a browser page, and save it

  hexc edit materials/rock.json            prints the address to open: http://127.0.0.1:PORT/?token=...

Serves a page (WebGL 2) that renders the material with hexc's own GLSL ES 3.00 output: a panel with every
hex-tiling setting of the material and of each slot (range, default, unit, reset), sliders that take effect
without recompiling, and settings that change the shader's structure (mask, taps, blend, kind ...) recompiled
here. A ground plane from one tile to hundreds, a sphere, a cube, or texture space; a split between plain
tiling, hex-tiling and the weights; a movable light; the cost of the shader as it ships. Save writes the
material back, keeping its text where unchanged; an edit of the file in another editor, or of a texture,
reloads the page. The material's template is used unless it declares resources of its own (an engine's),
then the built-in `lit`, as the page says.

Safe by default: it listens on 127.0.0.1 only, every request needs the token of the printed address (a cookie
after the first load) and this server's own host name, and it serves its page, the material and the
material's textures only, from the material's folder (--root widens it; a texture outside it is an error,
and hexc edit exits with 1). docs/edit.md has the details.
)";

}  // namespace

int editCommand(const std::vector<std::string>& args) {
    CLI::App app(kEditHelp, "hexc edit");
    std::filesystem::path material, root;
    int port = 0;
    CaptureOptions capture;
    std::string size = "1280x720";
    app.add_option("material", material, "the material to edit (JSON)")->type_name("MATERIAL.json");
    app.add_option("--port", port, "the port to listen on (default: any free one; the address says which)")
        ->check(CLI::Range(0, 65535))
        ->type_name("N");
    app.add_option("--root", root, "the folder whose files may be served (default: the material's folder)")->type_name("DIR");
    app.add_option("--capture", capture.out, "render one frame in headless Chromium, write it and exit")->type_name("OUT.png");
    app.add_option("--size", size, "with --capture: the frame's size (default 1280x720)")->type_name("WxH");
    app.add_option("--browser", capture.browser, "with --capture: the Chromium to start (default chromium)")->type_name("PATH");
    if (std::optional<int> done = command::parseWith(app, args)) return *done;
    if (material.empty()) {
        std::cerr << "hexc: no material given (see hexc edit --help)\n";
        return command::kUsage;
    }
    if (isMaterialXFile(material)) {
        std::cerr << "hexc: hexc edit edits JSON materials; `hexc " << material.string() << " -o DIR` compiles a MaterialX document\n";
        return command::kUsage;
    }
    const std::optional<std::pair<int, int>> wh = command::parseSize(size, 16, kMaxCaptureSide);
    if (!wh) {
        std::cerr << "hexc: --size expects WxH, each from 16 to " << kMaxCaptureSide << ", got " << size << "\n";
        return command::kUsage;
    }
    std::tie(capture.width, capture.height) = *wh;
    if (!capture.out.empty() && capture.out.extension() != ".png") {
        std::cerr << "hexc: --capture " << capture.out.string() << ": hexc edit captures .png\n";
        return command::kUsage;
    }
    // Reported now too; a material with errors is still served (the page shows them and reloads once the file is
    // fixed), one that cannot be read is not, nor one whose textures lie outside the folder served: the page could
    // show none of them, and --root is the fix.
    const ParseResult parsed = parseMaterialFile(material);
    std::cerr << formatAll(byPosition(parsed.diagnostics));
    if (!parsed.material && !std::filesystem::is_regular_file(material)) return command::kInvalidInput;
    if (root.empty()) root = material.has_parent_path() ? material.parent_path() : ".";
    Session session(material, root);
    if (parsed.material) {
        const Diagnostics outside = session.confined(*parsed.material);
        std::cerr << formatAll(byPosition(outside));
        if (!outside.empty()) return command::kInvalidInput;
    }
    // A texture's texels and tables (tens of MB each, freed after each answer) go back to the system when freed: by
    // default glibc raises its threshold for mapping a block of its own to the largest block freed so far, and the
    // server's 32 threads keep such blocks in arenas of their own, so a session that reloads a large texture grew by
    // hundreds of MB. A fixed threshold keeps every block of 1 MiB or more out of the arenas.
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
    Capture capturing(capture);
    try {
        Server server(session, port, capture.out.empty() ? Server::CaptureHandler{} : capturing.handler());
        if (!capture.out.empty()) return capturing.run(server);
        std::cout << "hexc: editing " << material.string() << "; open " << server.url() << " (Ctrl-C stops)" << std::endl;
        server.run();
    } catch (const std::exception& e) {
        std::cerr << "hexc: " << e.what() << "\n";
        return command::kWriteFailed;
    }
    return command::kOk;
}

}  // namespace hexc::edit
