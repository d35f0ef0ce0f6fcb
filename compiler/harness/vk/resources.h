#pragma once
// The Vulkan objects a render makes (resources.cpp): host buffers, uploaded textures, the render pass, the pipeline
// and the render target. Each is destroyed by the Cleanup it is registered with.
#include <utility>
#include <vector>

#include "vk/context.h"

namespace hexc::vk {

// Every buffer here is written or read by the host (uniforms, staging, read-back), so all are host-visible,
// coherent (no flush/invalidate calls) and stay mapped until freed.
struct HostBuffer {
    VkBuffer buffer;
    void* mapped;
};

HostBuffer createHostBuffer(VulkanContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage, Cleanup& cleanup);

// Creates the texture's image with a full mip chain and records, into cb, the upload of level 0 from a staging
// buffer and the blits that build each further level from the one before. Returns a view of all levels, which
// is in SHADER_READ_ONLY_OPTIMAL once cb has run.
VkImageView uploadTexture(VulkanContext& ctx, VkCommandBuffer cb, const Texture& t, Cleanup& cleanup);
// A 2D array texture of `layers` (one size and format), each layer with its own mip chain, as uploadTexture makes it.
VkImageView uploadTextureArray(VulkanContext& ctx, VkCommandBuffer cb, const std::vector<const Texture*>& layers, Cleanup& cleanup);

// Colour (cleared, then kept for the read-back copy) and depth (cleared, discarded).
VkRenderPass createRenderPass(VulkanContext& ctx, Cleanup& cleanup);

VkPipeline createPipeline(VulkanContext& ctx, const RenderRequest& req, VkPipelineLayout layout, VkRenderPass pass, Cleanup& cleanup);

// The colour render target (also the copy source) and the framebuffer over it and a depth buffer.
std::pair<VkImage, VkFramebuffer> createTarget(VulkanContext& ctx, VkRenderPass pass, uint32_t width, uint32_t height, Cleanup& cleanup);

// The parameter block: an empty block still gets a (zeroed) 16-byte buffer, so binding 0 is always valid.
HostBuffer createUniforms(VulkanContext& ctx, const std::vector<uint8_t>& data, Cleanup& cleanup);

}  // namespace hexc::vk
