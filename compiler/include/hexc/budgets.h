#pragma once
// Texel budgets: the most texels of one texture that a stage holding it in memory accepts (docs/cli.md#budgets).
// They are checked from the size in the texture's header, which the parser reads without decoding, so a small file
// that claims a huge size is refused before any memory is taken for it.
#include <cstdint>
#include <optional>
#include <string>

#include "hexc/diagnostics.h"
#include "hexc/material.h"

namespace hexc {

// A stage's budget: side x side texels. Each side keeps its stage within about 1.5 GB on its worst texture format.
struct TexelBudget {
    int side;
    const char* what;  // the stage, as the message names it
    const char* why;   // what it holds per texel
    int64_t texels() const { return int64_t(side) * side; }
    std::string text() const;  // "at most 4096x4096 texels, as it holds ..."
};

// The library's stages that decode a texture. A tool over the library keeps its own (the harness: hexc render's
// upload, vk/render.h, and the fp64 reference, reference/reference.h).
// ~25 bytes a texel beside the decoded texture; a whole run 855 MB at 4096 x 4096.
inline constexpr TexelBudget kHistogramBudget{4096, "the histogram blend's precomputation",
                                              "it holds about 25 bytes a texel beside the decoded texture"};
// 4 bytes a texel for each slot decoded, the packed texture and its PNG.
inline constexpr TexelBudget kPackingBudget{8192, "packing", "it decodes each slot's texture at 4 bytes a texel"};

// The layers' splat maps, decoded to count each layer's coverage for the manifest's expected fetches: 4 bytes a texel,
// and as much again while the decoder's buffer is copied out.
inline constexpr TexelBudget kSplatBudget{8192, "the splat maps' coverage (the manifest's expected fetches)",
                                          "it decodes the splat map at 4 bytes a texel"};

// The JSON pointer of a slot's texture (`/slots/2/texture`, a splat map's `/layer_blend/splat/0`), where diagnostics
// about its texture point.
std::string texturePointer(const Material& material, const Slot& slot);

// An error located at the slot (HX125, naming the texture, its size and the budget) when its texture has more
// texels than `budget` holds; nullopt when it fits.
std::optional<Diagnostic> overTexelBudget(const Material& material, const Slot& slot, const TexelBudget& budget);

}  // namespace hexc
