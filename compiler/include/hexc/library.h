#pragma once
// `hexc library`: hexc's hex-tiling functions (templates/library/hextiling.glsl) as an include file for shaders an
// engine writes by hand, on each target (docs/library.md).
#include "hexc/compiler.h"

namespace hexc {

enum class LibraryTarget { Hlsl, Glsl, Msl, SpirvAsm };

// The library for each of `targets`: "hexc_hextiling.{hlsl,glsl,metal,spvasm}", from one compile. Made from the same GLSL as every material,
// through glslang and SPIRV-Cross, unoptimised so that every function keeps its name and signature. HLSL and MSL
// take a texture and a sampler; OpenGL GLSL one sampler2D for both. Throws CompileError on a hexc bug.
std::vector<OutputFile> hexcLibrary(const std::vector<LibraryTarget>& targets);

}  // namespace hexc
