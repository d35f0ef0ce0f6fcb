#pragma once
// `hexc render` and `hexc preview`: run a material on the Vulkan runner (lavapipe) and write images.
#include <string>
#include <vector>

#include "hexc/image.h"
#include "options.h"

namespace hexc::cli {

int renderCommand(const std::vector<std::string>& args);
int previewCommand(const std::vector<std::string>& args);

// The commands with their messages and diagnostics reported to `m`, and the image put into `into` instead of a file
// when it is given (-o then not needed); the exit code. `args` are the command's (the material among them).
int render(const std::vector<std::string>& args, const Messages& m, Image* into);
int preview(const std::vector<std::string>& args, const Messages& m, Image* into);

// Draws text (lines apart at `\n`) with stb_easy_font's quads, scaled, in white on whatever is there.
void drawLabel(Image& image, int x0, int y0, const std::string& text, int scale);

}  // namespace hexc::cli
