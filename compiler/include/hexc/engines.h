#pragma once
// Engine packages (docs/engines.md): a material's functions (CompileOptions::functions) wrapped in an engine's own
// material model, so that the engine's lighting, shadows and environment light the hex-tiled slots. A layer above
// compile(), which knows no engine.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hexc/compiler.h"

namespace hexc {

// One row each in the engine table (engines/engines.cpp), in this order.
enum class Engine { Godot3, Godot4, Filament, Threejs, Babylon, Unity, Unreal, ThreejsWebgpu };
inline constexpr Engine kLastEngine = Engine::ThreejsWebgpu;

// The --engine name of the engine's row ("godot3", "threejs-webgpu" ...)
std::string_view toString(Engine engine);
std::optional<Engine> engineNamed(std::string_view name);  // nullopt for a name hexc has no package for
std::vector<std::string_view> engineNames();
// three.js (WebGL 2 and WebGPU) and Babylon.js: their packages (ES modules) copy the slots' textures beside them.
bool isWebEngine(Engine engine);

// The package of `material` for `engine`: the files under "<engine>/" (its shader or material source, the manifest of
// the functions it holds, the textures hexc derives), compiled with `options` as the functions output in the engine's
// GLSL dialect (GLSL ES 3.00 in the web engines' ES module, engines/web.cpp), WGSL (three.js WebGPU's module, the same
// writer) or HLSL (Unity's Shader Graph Custom Function file and URP shader, Unreal's Custom node include:
// engines/hlsl.cpp), every setting baked. A slot no engine input
// takes is a warning, its function kept but not called. The manifest names only files in the package, or a file outside
// it from the package's folder: with options.manifestPathsFrom (the folder the caller writes into), a texture the
// package does not hold from manifestPathsFrom/<engine>; without it, as the material names it.
CompileResult compileForEngine(const Material& material, Engine engine, CompileOptions options);

// The names of the files compileForEngine writes, "<engine>/..." (found by planning alone: hexc --list-outputs).
OutputNames engineOutputNames(const Material& material, Engine engine, const CompileOptions& options);

// Each named engine's package (hexc --engine), every file under its engine's folder, sorted; a name hexc has no
// package for is an error. No file when any package fails.
CompileResult compilePackages(const Material& material, const std::vector<std::string>& engines, const CompileOptions& options);
// The names of the files compilePackages writes, sorted; the plan's diagnostics once.
OutputNames packageOutputNames(const Material& material, const std::vector<std::string>& engines, const CompileOptions& options);

}  // namespace hexc
