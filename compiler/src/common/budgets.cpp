#include "hexc/budgets.h"

#include <string>

namespace hexc {
namespace {

struct Budget {
    int side;          // the budget is side x side texels
    const char* what;  // the stage, as the message names it
    const char* why;   // what it holds per texel
};

// Each side keeps the stage within about 1.5 GB on its worst texture format (the histogram blend well within it).
Budget budget(TextureStage stage) {
    switch (stage) {
        case TextureStage::Histogram:  // ~25 bytes a texel beside the decoded texture; a whole run 855 MB at 4096 x 4096
            return {4096, "the histogram blend's precomputation", "it holds about 25 bytes a texel beside the decoded texture"};
        case TextureStage::Packing:  // 4 bytes a texel for each slot decoded, the packed texture and its PNG
            return {8192, "packing", "it decodes each slot's texture at 4 bytes a texel"};
        case TextureStage::Render:  // 4 (8-bit) or 16 (float) bytes a texel, twice: host copy, device image with mips
            return {8192, "hexc render and preview", "lavapipe holds each texture with its mips in host memory"};
        case TextureStage::Reference:  // fp64 RGBA with mips: 32 * 4/3 bytes a texel, 716 MB at 4096x4096
            return {4096, "--reference", "it holds the texture in fp64 with its mips"};
    }
    return {0, "", ""};
}

}  // namespace

int64_t texelBudget(TextureStage stage) { return int64_t(budget(stage).side) * budget(stage).side; }

std::string texelBudgetText(TextureStage stage) {
    const Budget b = budget(stage);
    return "at most " + std::to_string(b.side) + "x" + std::to_string(b.side) + " texels, as " + b.why;
}

std::optional<Diagnostic> overTexelBudget(const Material& material, const Slot& slot, TextureStage stage) {
    const int64_t texels = int64_t(slot.width) * slot.height;
    if (texels <= texelBudget(stage)) return std::nullopt;
    std::string path;
    for (size_t i = 0; i < material.slots.size(); ++i)
        if (material.slots[i].name == slot.name) path = "/slots/" + std::to_string(i) + "/texture";
    return Diagnostic::make(Code::TextureTooLarge, {material.sourceFile.string(), slot.line, slot.col}, path,
                            slot.texturePath.string() + " is " + std::to_string(slot.width) + "x" + std::to_string(slot.height) + " (" +
                                std::to_string(texels) + " texels), more than " + budget(stage).what + " takes: " + texelBudgetText(stage));
}

}  // namespace hexc
