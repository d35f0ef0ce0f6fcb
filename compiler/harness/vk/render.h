#pragma once
// Renders a material on the Vulkan runner: what `hexc render`, `hexc preview`, the execution tests and
// the benchmark share. A render shows one output of a material over a UV rectangle (see runner.h and
// templates/fullscreen.vert.glsl for the pixel-to-UV mapping).
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hexc/budgets.h"
#include "hexc/compiler.h"
#include "hexc/image.h"
#include "vk/runner.h"

namespace hexc::vk {

// hexc render and preview upload every slot's texture to lavapipe, which holds it and its mips in host memory at 4
// (8-bit) or 16 (float) bytes a texel, twice (host copy, device image); edit's page uploads it to WebGL.
inline constexpr TexelBudget kRenderBudget{8192, "hexc render and preview", "lavapipe holds each texture with its mips in host memory"};

enum class RenderOutput {
    Albedo,      // a colour (or scalar) slot's blended value
    Normal,      // a normal slot's tangent-space normal, encoded n * 0.5 + 0.5 like a normal map
    Derivative,  // a normal slot's blended height derivative (dH/du, dH/dy, 0, 1), y = -v up the texture
    Weights,     // a slot's hex-tile weights (Listing 7), (w1, w2, w3, 1)
    Shaded,      // the material's own template
};

// Which emitted source is executed: the SPIR-V, or the HLSL / GLSL re-compiled to SPIR-V by glslang.
enum class ExecutedTarget { Spirv, Hlsl, Glsl };

// The slot an output shows: `slotName` if given, else the slot named "albedo" (Albedo) or "normal"
// (Normal, Derivative), else the first slot of a fitting kind; Weights: the first slot.
// Throws std::invalid_argument naming what is missing.
const Slot& slotForOutput(const Material& material, RenderOutput output, const std::string& slotName);

// The material a render compiles: for a slot output, only that slot under the `value` or `weights`
// template; for a layered material's role named by `slotName` (Albedo, Normal, Derivative), the layers' blend of it
// (layerRoleFirst); for Shaded, the material itself.
Material renderedMaterial(const Material& material, RenderOutput output, const std::string& slotName);

// The index of a layered material's role named `name`, if it has one.
std::optional<size_t> layerRole(const Material& material, const std::string& name);

// The layered material with role `role` first, under the `value` template, which shows it (HEXC_FIRST_SLOT).
Material layerRoleFirst(Material material, size_t role);

// The material as shown with `templateName` (a template file or built-in name) if given, under `options`: a template
// that declares resources of its own, which only an engine can fill, is replaced by the built-in `lit`, and *note
// says so (else it is cleared). Compiles it once for SPIR-V to find out; throws CompileError when it does not compile.
Material shownMaterial(Material material, const std::string& templateName, const CompileOptions& options, std::string* note);

// The same for a material already compiled with its own template (`compiled` did not fail), compiling nothing: the
// template's own resources are those its manifest lists.
Material shownMaterial(Material material, const CompileResult& compiled, std::string* note);

// The material with every slot plain-tiled (`enabled` false): what hex-tiling is compared with.
Material plainTiled(Material material);

// Parameter values by member name, replacing the material's (e.g. a split-coordinates origin).
using ParameterValues = std::map<std::string, std::vector<double>>;

// What a template of the engine's binds beside hexc's: its resources by name (set and binding are taken from the
// manifest, as an engine would) and its fragment push constant bytes from offset 16 (runner.h).
struct TemplateInputs {
    std::map<std::string, TemplateResource> resources;
    std::vector<uint8_t> pushConstants;
};

// Compiles (throws CompileError on failure; `compileOptions` apart from its targets apply), uploads and
// draws. `frameMs`, if given, receives one GPU time per timed frame (`timedFrames` after one untimed
// warm-up frame).
Image render(Runner& runner, const Material& material, RenderOutput output, const std::string& slotName, const View& view,
             ExecutedTarget target = ExecutedTarget::Spirv, int timedFrames = 0, std::vector<double>* frameMs = nullptr,
             const ParameterValues& parameters = {}, const CompileOptions& compileOptions = {}, const TemplateInputs& own = {});

// Draws a fragment shader of the embedded templates (no material) with the given uniform block.
Image renderShader(Runner& runner, const std::string& templateFile, const std::vector<uint8_t>& uniforms, const View& view);

// Draws `request`'s fragment shader (one written by hand, its resources filled in by the caller) over `view`, with the
// harness's vertex stage; with request.timedFrames, each timed frame's GPU time goes to `frameMs`.
Image renderFragment(Runner& runner, RenderRequest request, const View& view, std::vector<double>* frameMs = nullptr);

// Derivative images (dH/du, dH/dy, ., .) to tangent-space normals encoded n * 0.5 + 0.5, in place (Eq. 2).
void derivativeToNormalMap(Image& image);

// The parameter block as the manifest lays it out, filled with the material's values or `parameters` (by a
// member's name or any of its aliases).
std::vector<uint8_t> packParameters(const nlohmann::json& manifest, const ParameterValues& parameters = {});

}  // namespace hexc::vk
