#pragma once
// The files hexc derives from a material's textures and writes beside its shaders: each histogram slot's tables
// (hexc/histogram.h) and each pack's texture (docs/material-format.md#pack).
#include <vector>

#include "hexc/compiler.h"
#include "plan/plan.h"

namespace hexc {

// Through `cache` when set, keyed by the textures' bytes: a material whose other settings changed takes them from
// there. A texture that cannot be read stops the compile (CompileError).
std::vector<OutputFile> derivedTextureFiles(const Material& material, const ShaderPlan& plan, ShaderCache* cache);

}  // namespace hexc
