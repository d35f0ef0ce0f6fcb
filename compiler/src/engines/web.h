#pragma once
// The web engines' packages (three.js, Babylon.js; docs/engines.md): the engine's ES module
// (compiler/integrations/<engine>/package.<engine>.js) filled with the material's functions in GLSL ES 3.00, the
// textures they read and the engine input each slot fills; beside it, the slots' textures it loads.
#include <nlohmann/json.hpp>

#include <optional>
#include <string>

#include "hexc/engines.h"

namespace hexc {

// The package's files, named without the "<engine>/" folder: the module, and a copy of each slot texture the
// functions read (a packed texture is among the functions output's files already). `manifest` and `glsl` are the
// functions output's. A slot the engine has no input for is reported in `diagnostics`.
// The names webPackage gives its files, `copied` the slots whose own textures the functions read (not packed).
std::vector<std::string> webPackageNames(const Material& material, Engine engine, const std::vector<const Slot*>& copied);

// A slot's texture as a web package holds it: <material>.<slot>.<the file's extension>, beside the module.
std::string textureCopyName(const Material& material, const Slot& slot);

// The functions output a web package holds: its GLSL ES 3.00, and its WGSL when asked for (Babylon.js on WebGPU).
struct WebFunctions {
    std::string glsl;
    std::optional<std::string> wgsl;
};
std::vector<OutputFile> webPackage(const Material& material, Engine engine, const nlohmann::json& manifest, const WebFunctions& functions,
                                   bool uvBottomLeft, Diagnostics& diagnostics);

}  // namespace hexc
