#pragma once
// `hexc render` and `hexc preview`: run a material on the Vulkan runner (lavapipe) and write images.
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "hexc/budgets.h"
#include "hexc/image.h"
#include "hexc/material.h"
#include "options.h"
#include "vk/runner.h"

namespace hexc::cli {

int renderCommand(const std::vector<std::string>& args);
int previewCommand(const std::vector<std::string>& args);

// The commands with their messages and diagnostics reported to `m`, and the image put into `into` instead of a file
// when it is given (-o then not needed); the exit code. `args` are the command's (the material among them).
int render(const std::vector<std::string>& args, const Messages& m, Image* into);
int preview(const std::vector<std::string>& args, const Messages& m, Image* into);

// What the commands that run a material on Vulkan (render, preview, bake) share.

// Parses the material, reporting diagnostics; nullopt on error.
std::optional<Material> loadMaterial(const std::string& path, const Messages& m);

// The Vulkan runner, or null after saying why there is none.
std::unique_ptr<vk::Runner> makeRunner(const Messages& m);

// Refuses (CompileError), before any texture is decoded, one over the budget of `stage` among the material's slots (or
// `only` and its height slot).
void checkTexelBudget(const Material& material, const TexelBudget& budget, const Slot* only = nullptr);

// The sRGB transfer function (IEC 61966-2-1) on RGB, as an sRGB swapchain encodes what a shader writes; alpha
// stays linear. Negative values (no colour) become 0.
void encodeSrgb(Image& image);

// Runs a command body, mapping failures to the documented exit codes. `material` names the input an out-of-memory
// condition is reported against (the body fills it in once it knows it).
template <typename Body>
int guarded(const std::string& material, const Messages& m, Body body) {
    try {
        return body();
    } catch (const UsageError& e) {
        *m.text << "hexc: " << e.message << "\n";
        return kUsage;
    } catch (const CompileError& e) {
        m.report(byPosition(e.diagnostics));
        return kInvalidInput;
    } catch (const std::invalid_argument& e) {
        *m.text << "hexc: " << e.what() << "\n";
        return kInvalidInput;
    } catch (const TextureError& e) {  // a texture that passed validation (its header) but does not decode
        *m.text << "hexc: " << e.what() << "\n";
        return kInvalidInput;
    } catch (const std::bad_alloc&) {  // an input larger than this machine holds, within the budgets: not an output's fault
        m.report({Diagnostic::make(Code::OutOfMemory, {material}, "",
                                   "out of memory: its textures or the image need more than this machine has")});
        return kInvalidInput;
    } catch (const vk::VulkanError& e) {
        *m.text << "hexc: Vulkan: " << e.what() << "\n";
        return kNoVulkan;
    } catch (const std::exception& e) {
        *m.text << "hexc: " << e.what() << "\n";
        return kWriteFailed;
    }
}

// Draws text (lines apart at `\n`) with stb_easy_font's quads, scaled, in white on whatever is there.
void drawLabel(Image& image, int x0, int y0, const std::string& text, int scale);

}  // namespace hexc::cli
