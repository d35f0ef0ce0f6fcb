#include "hexc/budgets.h"

#include <string>

namespace hexc {

std::string TexelBudget::text() const { return "at most " + std::to_string(side) + "x" + std::to_string(side) + " texels, as " + why; }

std::string texturePointer(const Material& material, const Slot& slot) {
    std::string path;
    for (size_t i = 0; i < material.slots.size(); ++i)
        if (material.slots[i].name == slot.name) path = "/slots/" + std::to_string(i) + "/texture";
    for (size_t k = 0; material.layers && k < material.layers->splats.size(); ++k)
        if (&material.slots[material.layers->splats[k]] == &slot) path = "/layer_blend/splat/" + std::to_string(k);
    return path;
}

std::optional<Diagnostic> overTexelBudget(const Material& material, const Slot& slot, const TexelBudget& budget) {
    const int64_t texels = int64_t(slot.width) * slot.height;
    if (texels <= budget.texels()) return std::nullopt;
    const std::string path = texturePointer(material, slot);
    return Diagnostic::make(Code::TextureTooLarge, {material.sourceFile.string(), slot.line, slot.col}, path,
                            slot.texturePath.string() + " is " + std::to_string(slot.width) + "x" + std::to_string(slot.height) + " (" +
                                std::to_string(texels) + " texels), more than " + budget.what + " takes: " + budget.text());
}

}  // namespace hexc
