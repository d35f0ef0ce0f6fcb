#pragma once
// Runs a vertex + fragment shader pair over a UV rectangle on Vulkan (Mesa lavapipe in tests and CI) into an
// RGBA32F image and reads it back; optionally times the draw. Used by the execution tests, preview and bench.
//
// Resource interface the shaders see (hexc's, in descriptor set RenderRequest::set, at its bindings):
//   paramsBinding          uniform buffer, fragment stage: RenderRequest::uniformData (std140)
//   samplerBinding         one sampler for every texture: linear min/mag/mip, REPEAT on u/v/w, lod 0..all, no
//                          anisotropy
//   firstTextureBinding+i  sampled image (texture2D): RenderRequest::textures[i], with a full mip chain (a
//                          texture2DArray of RenderRequest::textureArrays[i] when that is given); or, with
//                          RenderRequest::combinedSamplers, a sampler2D combining it with that sampler
//                          (how GLSL emitted for OpenGL binds textures once brought back to Vulkan)
//   other sets      RenderRequest::templateResources, the fragment shader's own; sets no one uses are empty
//   push constant   bytes 0..15, vertex stage: RenderRequest::uvRect (see templates/fullscreen.vert.glsl); from byte
//                   16, fragment stage: RenderRequest::fragmentPushConstants
// The fragment shader writes location 0; the render target is VK_FORMAT_R32G32B32A32_SFLOAT, no blending.
//
// Mip chain: level 0 is the texture; level n+1 is vkCmdBlitImage of level n with VK_FILTER_LINEAR (an exact 2x2
// average when level n has even sizes; 8-bit levels are rounded to 8 bits each step, sRGB ones averaged in linear).
#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "hexc/image.h"

namespace hexc::vk {

// A failure of the Vulkan device or driver, not of what was asked of it (`hexc render` and `preview` exit 4).
struct VulkanError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct VulkanContext;  // instance, device and long-lived objects; defined in vk/context.h

// A resource of the fragment shader's own, beside hexc's (a template's per-frame block, shadow map...).
struct TemplateResource {
    enum class Kind { UniformBuffer, CombinedImageSampler, SampledImage, Sampler };
    Kind kind = Kind::UniformBuffer;
    uint32_t set = 0, binding = 0;
    std::vector<uint8_t> data;         // UniformBuffer: its bytes (std140)
    const Texture* texture = nullptr;  // images: not owned, with a full mip chain like hexc's; samplers are hexc's one sampler
};

struct RenderRequest {
    std::vector<uint32_t> vertexSpirv, fragmentSpirv;
    std::string vertexEntry = "main", fragmentEntry = "main";
    std::vector<uint8_t> uniformData;      // may be empty: a zeroed 16-byte buffer is bound instead
    std::vector<const Texture*> textures;  // not owned; must outlive render()
    // Per texture i < size: when not empty, a 2D array texture (texture2DArray) of these layers, all of one size and
    // format, each with its own full mip chain; textures[i] is its layer 0. Not owned.
    std::vector<std::vector<const Texture*>> textureArrays;
    int width = 0, height = 0;
    std::array<float, 4> uvRect{0, 0, 1, 1};                                           // u0, v0, u1, v1
    int timedFrames = 0;                                                               // > 0: draw this many extra frames, timing each one
    bool combinedSamplers = false;                                                     // textures as COMBINED_IMAGE_SAMPLER (see above)
    uint32_t set = 0, paramsBinding = 0, samplerBinding = 1, firstTextureBinding = 2;  // hexc's, where the shader has them
    std::vector<TemplateResource> templateResources;  // at their own sets and bindings (no two resources share one)
    std::vector<uint8_t> fragmentPushConstants;       // the fragment stage's push constants, from byte 16 (see above)
};

struct RenderResult {
    Image image;                  // row 0 is the top row
    std::vector<double> frameMs;  // one GPU duration per timed frame, in milliseconds
};

// Owns one Vulkan instance and device, reused across renders because creating a device is slow.
// Not thread-safe: use one Runner per thread.
class Runner {
public:
    // Returns nullptr and sets *whyNot (if given) when no usable Vulkan device exists. Prefers a CPU device
    // (lavapipe), whose results are the same on every machine. With HEXC_VK_VALIDATION=1 in the environment,
    // enables VK_LAYER_KHRONOS_validation when it is installed.
    static std::unique_ptr<Runner> create(std::string* whyNot);

    // Draws 3 vertices once, reads the image back, then draws timedFrames more times, each its own submission
    // bracketed by timestamps. Throws std::runtime_error naming the failed call and its VkResult.
    RenderResult render(const RenderRequest& request);

    std::string deviceName() const;

    ~Runner();
    Runner(const Runner&) = delete;
    Runner& operator=(const Runner&) = delete;

private:
    explicit Runner(std::unique_ptr<VulkanContext> context);
    std::unique_ptr<VulkanContext> ctx_;
};

}  // namespace hexc::vk
