#pragma once
// The CPU oracle of a layered material (docs/material-format.md#layers): a role's blend of the layers' slots by the
// splat maps' weights, linear or by height, with the layers below the skip bound dropped. Written from the format's
// definition; each layer's slot and each splat map is evaluated by evaluate() (reference.h) as any slot.
#include <memory>
#include <vector>

#include "reference/reference.h"

namespace hexc::reference {

// Every texture a layered material's blend samples: the layers' slots and the splat maps.
class LayerTextures {
public:
    explicit LayerTextures(const Material& material);
    const SlotTextures& of(size_t slot) const { return *textures_.at(slot); }
    const HeightSource* heights(size_t slot) const { return heights_.at(slot)->source(); }

private:
    std::vector<std::unique_ptr<SlotTextures>> textures_;  // per material slot; null for slots outside the layers
    std::vector<std::unique_ptr<Heights>> heights_;
};

struct LayerResult {
    Rgba value{};                    // the blend of the role (a normal role: (dH/ds, dH/dt, 0, 1) as evaluate gives)
    std::vector<double> splat;       // per layer: its weight as filtered, before keeping (splat, vertex colour or product)
    std::vector<double> weights;     // per layer: its final weight (0: not fetched)
    std::vector<SlotResult> layers;  // per layer: its slot of the role, evaluated for every layer (for error bounds)
    std::vector<double> heights;     // height mode: per layer its height (a dropped layer's too, for error bounds)
    double heightSum = 1;            // height mode: the sum of b_i before normalising (for error bounds)
    std::vector<double> shares;      // height mode: per layer b_i / heightSum, before the shares below skip_below drop
};

// The role `role` (an index into Material::layers->roles) of `material` at uv with uv gradients, and the interpolated
// vertex colour where the layers take weights from it.
LayerResult evaluateLayers(const Material& material, size_t role, const LayerTextures& textures, double u, double v, double dudx,
                           double dvdx, double dudy, double dvdy, const Rgba& vertexColor = {1, 1, 1, 1});

// The vertex colour the harness's full-screen draw (templates/harness/fullscreen.vert.glsl) gives pixel (i, j) of a
// view: affine in screen space, (1 - x, x, y, 1 - y) with x = (i + 0.5) / width, y = (j + 0.5) / height (row 0 at the top).
Rgba vertexColorAt(const View& view, int i, int j);

// Every pixel of a view, row by row, as evaluateLayers gives it at the pixel centre's uv and vertex colour.
std::vector<LayerResult> evaluateLayersView(const Material& material, size_t role, const LayerTextures& textures, const View& view);

}  // namespace hexc::reference
