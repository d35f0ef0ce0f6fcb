#pragma once
// Texel budgets: the most texels of one texture that each stage holding it in memory accepts (docs/cli.md#budgets).
// They are checked from the size in the texture's header, which the parser reads without decoding, so a small file
// that claims a huge size is refused before any memory is taken for it.
#include <cstdint>
#include <optional>
#include <string>

#include "hexc/diagnostics.h"
#include "hexc/material.h"

namespace hexc {

enum class TextureStage {
    Histogram,  // the histogram blend's precomputation (compile, render, preview, edit's page)
    Packing,    // "pack": true decodes each slot's texture and the packed one (compile)
    Render,     // hexc render and preview upload every slot's texture to lavapipe, which holds it with its mips; edit's page, to WebGL
    Reference,  // hexc render --reference holds the texture in fp64 with its mips
};

// The stage's budget in texels, and as a message says it: "at most 4096x4096 texels, as it holds ...".
int64_t texelBudget(TextureStage stage);
std::string texelBudgetText(TextureStage stage);

// An error located at the slot (HX125, naming the texture, its size and the budget) when its texture has more
// texels than `stage` holds; nullopt when it fits.
std::optional<Diagnostic> overTexelBudget(const Material& material, const Slot& slot, TextureStage stage);

}  // namespace hexc
