#pragma once
// `hexc render` and `hexc preview`: run a material on the Vulkan runner (lavapipe) and write images.
#include <string>
#include <vector>

#include "hexc/compiler.h"
#include "hexc/material.h"

namespace hexc::cli {

// The material as shown with `templateName` (a template file or built-in name) if given, under `options`: a template
// that declares resources of its own, which only an engine can fill, is replaced by the built-in `lit`, and *note
// says so (else it is cleared). Throws CompileError when it does not compile.
Material shownMaterial(Material material, const std::string& templateName, const CompileOptions& options, std::string* note);

// The material with every slot plain-tiled (`enabled` false): what hex-tiling is compared with.
Material plainTiled(Material material);

int renderCommand(const std::vector<std::string>& args);
int previewCommand(const std::vector<std::string>& args);

}  // namespace hexc::cli
