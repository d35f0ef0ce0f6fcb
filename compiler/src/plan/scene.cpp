// Scene -> the (material, pass) variants to compile.
#include <algorithm>
#include <unordered_set>

#include "hexc/scene.h"

namespace hexc {

std::vector<Variant> sceneVariants(const Scene& scene) {
    std::vector<Variant> variants;
    for (const ScenePass& pass : scene.passes) {
        // A set, not a search of the pass's list per material: a scene of thousands stays linear.
        const std::unordered_set<std::string_view> listed =
            pass.materials ? std::unordered_set<std::string_view>(pass.materials->begin(), pass.materials->end())
                           : std::unordered_set<std::string_view>{};
        for (const Material& material : scene.materials) {
            if (pass.materials && !listed.contains(material.name)) continue;
            Variant v{material.name + "." + pass.name, material.name, pass.name, material};
            v.material.name = v.name;
            if (pass.templ) v.material.templ = *pass.templ;
            // A pass that names its slots gets a shader without the others: no fetches, no parameters.
            if (pass.slots)
                std::erase_if(v.material.slots, [&](const Slot& s) {
                    return std::find(pass.slots->begin(), pass.slots->end(), s.name) == pass.slots->end();
                });
            variants.push_back(std::move(v));
        }
    }
    return variants;
}

}  // namespace hexc
