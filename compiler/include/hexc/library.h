#pragma once
// `hexc library`: hexc's hex-tiling functions (templates/library/hextiling/) as an include file for shaders an
// engine writes by hand, on each target (docs/library.md).
#include <optional>
#include <string_view>

#include "hexc/compiler.h"

namespace hexc {

// The library for each of `targets`: "hexc_hextiling.{spvasm,hlsl,glsl,metal,wgsl}", from one compile. Made from the same GLSL
// as every material, through glslang and SPIRV-Cross (WGSL: naga, whose missing translator is a CompileError saying what to
// install), unoptimised so that every function keeps its name and signature.
// HLSL and MSL take a texture and a sampler; OpenGL GLSL one sampler2D for both; SPIR-V is written as assembly.
// Throws CompileError on a hexc bug.
std::vector<OutputFile> hexcLibrary(const std::vector<Target>& targets);

// `hexc library --target`'s names: each target's (SPIR-V's is `spirv-asm`), in target order; and the one a name or
// a target's alias (`metal`) names.
std::vector<std::string> libraryTargetNames();
std::optional<Target> libraryTargetNamed(std::string_view name);

}  // namespace hexc
