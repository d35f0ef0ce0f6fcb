// Scene -> the (material, pass) variants to compile.
#include <algorithm>

#include "hexc/scene.h"

namespace hexc {

std::vector<Variant> sceneVariants(const Scene& scene) {
    std::vector<Variant> variants;
    for (const ScenePass& pass : scene.passes)
        for (const Material& material : scene.materials) {
            if (pass.materials && std::find(pass.materials->begin(), pass.materials->end(), material.name) == pass.materials->end())
                continue;
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
    return variants;
}

}  // namespace hexc
