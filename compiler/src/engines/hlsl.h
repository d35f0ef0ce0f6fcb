#pragma once
// The HLSL engines' packages (Unity, Unreal; docs/engines.md): the functions output's HLSL with each function taking
// the textures it reads as parameters (Shader Graph's and Unreal's Custom nodes pass textures in; neither lets an
// include file declare global ones), inside the engine's templates (compiler/integrations/unity/, unreal/).
#include <nlohmann/json.hpp>

#include "hexc/engines.h"

namespace hexc {

bool isHlslEngine(Engine engine);

// The names hlslPackage gives its files.
std::vector<std::string> hlslPackageNames(const std::string& material, Engine engine);

// The package's files, named without the "<engine>/" folder. `manifest` and `hlsl` are the functions output's for
// HLSL, every setting baked. A slot the engine has no input for is reported in `diagnostics`.
std::vector<OutputFile> hlslPackage(const Material& material, Engine engine, const nlohmann::json& manifest, const std::string& hlsl,
                                    bool uvBottomLeft, Diagnostics& diagnostics);

}  // namespace hexc
