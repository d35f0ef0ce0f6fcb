#pragma once
// Where hexc's own resources (parameter block, shared sampler, one texture per slot) go on each target, so the
// shaders fit an engine's resource layout. The template's own resources follow hexc's on each target, per register
// class, unless the layout gives them bases of their own (HLSL and MSL, where a register or index is not declared in
// the GLSL). Set from the command line or a layout file (docs/cli.md, "Resource layout").
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hexc/diagnostics.h"

namespace hexc {

struct ResourceLayout {
    // A template base left unset: the template's resources of that class follow hexc's.
    static constexpr uint32_t kAfterHexc = UINT32_MAX;
    // Vulkan (SPIR-V): hexc's descriptor set; the block at `binding`, the sampler at binding + 1, slot i's texture at
    // binding + 2 + i. The template may use the rest of the set. `combined` (1): each texture a combined image sampler
    // (sampler2D) at its binding, binding + 1 left unused; the other targets keep theirs.
    struct Vulkan {
        uint32_t set = 0, binding = 0, combined = 0;
    } vulkan;
    // HLSL: hexc's register space (shader model 5.1 or later when not 0) and first register of each class. The
    // template's: its first register of each class (templateB...), and with `templateSpaces` (1) a resource in Vulkan
    // set N goes to register space N (push constants to hexc's space), each space counting from the template bases.
    struct Hlsl {
        uint32_t space = 0, b = 0, t = 0, s = 0, u = 0;
        uint32_t templateB = kAfterHexc, templateT = kAfterHexc, templateS = kAfterHexc, templateU = kAfterHexc, templateSpaces = 0;
    } hlsl;
    // MSL: hexc's first buffer, texture and sampler index. `argument_buffers` (1): each descriptor set is an argument
    // buffer at [[buffer(set)]], each resource at [[id(its Vulkan binding)]] in it, as MoltenVK lays them out; the
    // three bases are then unused.
    struct Msl {
        uint32_t buffer = 0, texture = 0, sampler = 0, argumentBuffers = 0;
        uint32_t templateBuffer = kAfterHexc, templateTexture = kAfterHexc, templateSampler = kAfterHexc;  // as for HLSL
    } msl;
    // OpenGL GLSL: hexc's uniform block binding and first texture unit.
    struct Glsl {
        uint32_t binding = 0;
    } glsl;
    std::filesystem::path sourceFile;  // the layout file it came from, if any (for located errors)
};

// One field of a layout, as the layout file and the command line name it: `"<target>": {"<key>": N}` and the flag
// `--<key>` (vulkan) or `--<target>-<key>`, 0 to `max`.
struct LayoutField {
    const char* target;
    const char* key;
    uint32_t max;
    const char* help;  // for --help
    uint32_t& (*field)(ResourceLayout&);
};
// Every field, grouped by target in file order.
const std::vector<LayoutField>& layoutFields();

// One line naming every field, for stamps and messages: "vulkan 0/0 hlsl space0 b0 t0 s0 u0 msl 0/0/0 glsl 0".
std::string toString(const ResourceLayout& layout);

struct LayoutParseResult {
    std::optional<ResourceLayout> layout;
    Diagnostics diagnostics;
};

// A layout file: {"vulkan": {"set", "binding"}, "hlsl": {"space", "b", "t", "s", "u"}, "msl": {"buffer",
// "texture", "sampler"}, "glsl": {"binding"}}, every key optional. Errors are located in `file`.
LayoutParseResult parseLayout(std::string_view text, const std::filesystem::path& file);
LayoutParseResult parseLayoutFile(const std::filesystem::path& file);

}  // namespace hexc
