// The Vulkan objects a render makes (resources.h): memory, buffers, images and views, shader modules, layout
// barriers, texture uploads, the render pass, the pipeline and the render target.
#include "vk/resources.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <string>

namespace hexc::vk {
namespace {

uint32_t memoryType(const VulkanContext& ctx, uint32_t typeBits, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) {
    for (VkMemoryPropertyFlags wanted : {required | preferred, required})
        for (uint32_t i = 0; i < ctx.memory.memoryTypeCount; ++i)
            if ((typeBits & (1u << i)) && (ctx.memory.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
    throw VulkanError("no Vulkan memory type with the required properties");
}

VkDeviceMemory allocate(VulkanContext& ctx, const VkMemoryRequirements& req, VkMemoryPropertyFlags required,
                        VkMemoryPropertyFlags preferred, Cleanup& cleanup) {
    VkMemoryAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    info.allocationSize = req.size;
    info.memoryTypeIndex = memoryType(ctx, req.memoryTypeBits, required, preferred);
    VkDeviceMemory memory;
    VK_CHECK(vkAllocateMemory, ctx.device, &info, nullptr, &memory);
    cleanup.defer([dev = ctx.device, memory] { vkFreeMemory(dev, memory, nullptr); });
    return memory;
}

}  // namespace

HostBuffer createHostBuffer(VulkanContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage, Cleanup& cleanup) {
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    HostBuffer b;
    VK_CHECK(vkCreateBuffer, ctx.device, &info, nullptr, &b.buffer);
    cleanup.defer([dev = ctx.device, buf = b.buffer] { vkDestroyBuffer(dev, buf, nullptr); });
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(ctx.device, b.buffer, &req);
    // Cached memory makes the read-back fast where the device offers it.
    const VkMemoryPropertyFlags required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    VkDeviceMemory memory = allocate(ctx, req, required, VK_MEMORY_PROPERTY_HOST_CACHED_BIT, cleanup);
    VK_CHECK(vkBindBufferMemory, ctx.device, b.buffer, memory, 0);
    VK_CHECK(vkMapMemory, ctx.device, memory, 0, VK_WHOLE_SIZE, 0, &b.mapped);  // vkFreeMemory unmaps
    return b;
}

namespace {

VkImage createImage(VulkanContext& ctx, VkFormat format, uint32_t width, uint32_t height, uint32_t mipLevels, VkImageUsageFlags usage,
                    Cleanup& cleanup, uint32_t layers = 1) {
    VkImageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = mipLevels;
    info.arrayLayers = layers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImage image;
    VK_CHECK(vkCreateImage, ctx.device, &info, nullptr, &image);
    cleanup.defer([dev = ctx.device, image] { vkDestroyImage(dev, image, nullptr); });
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(ctx.device, image, &req);
    VkDeviceMemory memory = allocate(ctx, req, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, cleanup);
    VK_CHECK(vkBindImageMemory, ctx.device, image, memory, 0);
    return image;
}

VkImageView createView(VulkanContext& ctx, VkImage image, VkFormat format, VkImageAspectFlags aspect, uint32_t mipLevels, Cleanup& cleanup,
                       VkImageViewType type = VK_IMAGE_VIEW_TYPE_2D, uint32_t layers = 1) {
    VkImageViewCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    info.image = image;
    info.viewType = type;
    info.format = format;
    info.subresourceRange = {aspect, 0, mipLevels, 0, layers};
    VkImageView view;
    VK_CHECK(vkCreateImageView, ctx.device, &info, nullptr, &view);
    cleanup.defer([dev = ctx.device, view] { vkDestroyImageView(dev, view, nullptr); });
    return view;
}

VkShaderModule createShaderModule(VulkanContext& ctx, const std::vector<uint32_t>& spirv, Cleanup& cleanup) {
    VkShaderModuleCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    info.codeSize = spirv.size() * sizeof(uint32_t);
    info.pCode = spirv.data();
    VkShaderModule module;
    VK_CHECK(vkCreateShaderModule, ctx.device, &info, nullptr, &module);
    cleanup.defer([dev = ctx.device, module] { vkDestroyShaderModule(dev, module, nullptr); });
    return module;
}

// A layout transition (and memory dependency) for mip levels [baseLevel, baseLevel + levelCount) of a colour image.
void imageBarrier(VkCommandBuffer cb, VkImage image, uint32_t baseLevel, uint32_t levelCount, VkImageLayout from, VkImageLayout to,
                  VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    VkImageMemoryBarrier b{};
    b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, baseLevel, levelCount, 0, VK_REMAINING_ARRAY_LAYERS};
    vkCmdPipelineBarrier(cb, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

// The layers (one size and format) as one image, each with a full mip chain, seen through a view of `type`.
VkImageView upload(VulkanContext& ctx, VkCommandBuffer cb, const std::vector<const Texture*>& layers, VkImageViewType type,
                   Cleanup& cleanup) {
    const Texture& t = *layers.front();
    const uint32_t count = uint32_t(layers.size());
    const VkFormat format = t.isFloat() ? VK_FORMAT_R32G32B32A32_SFLOAT : t.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
    const uint32_t levels = std::bit_width(unsigned(std::max(t.width, t.height)));  // floor(log2(max)) + 1

    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(ctx.physical, format, &props);
    const VkFormatFeatureFlags features = props.optimalTilingFeatures;
    const VkFormatFeatureFlags blit = VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT;
    if (!(features & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT) || (levels > 1 && (features & blit) != blit))
        throw VulkanError("the Vulkan device cannot sample or blit texture format " + std::to_string(int(format)));
    // A linear blit needs the format's linear-filter feature (optional for RGBA32F on some GPUs); without it the
    // mips are point-sampled instead. Such a device could not filter the format linearly when sampling either.
    const VkFilter mipFilter = (features & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;

    const size_t bytes = t.isFloat() ? t.rgba32f.size() * sizeof(float) : t.rgba8.size();
    HostBuffer staging = createHostBuffer(ctx, bytes * count, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, cleanup);
    for (uint32_t layer = 0; layer < count; ++layer) {
        const Texture& l = *layers[layer];
        const void* pixels = l.isFloat() ? static_cast<const void*>(l.rgba32f.data()) : l.rgba8.data();
        std::memcpy(static_cast<char*>(staging.mapped) + bytes * layer, pixels, bytes);
    }

    VkImage image =
        createImage(ctx, format, uint32_t(t.width), uint32_t(t.height), levels,
                    VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, cleanup, count);
    imageBarrier(cb, image, 0, levels, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    std::vector<VkBufferImageCopy> copies(count);
    for (uint32_t layer = 0; layer < count; ++layer) {
        copies[layer].bufferOffset = bytes * layer;
        copies[layer].imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, layer, 1};
        copies[layer].imageExtent = {uint32_t(t.width), uint32_t(t.height), 1};
    }
    vkCmdCopyBufferToImage(cb, staging.buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, count, copies.data());

    int32_t w = t.width, h = t.height;
    for (uint32_t level = 1; level < levels; ++level) {
        imageBarrier(cb, image, level - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_READ_BIT);
        const int32_t nw = std::max(1, w / 2), nh = std::max(1, h / 2);
        VkImageBlit region{};
        region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, count};
        region.srcOffsets[1] = {w, h, 1};
        region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, count};
        region.dstOffsets[1] = {nw, nh, 1};
        vkCmdBlitImage(cb, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, mipFilter);
        w = nw;
        h = nh;
    }
    // Levels 0..levels-2 were blit sources, the last level only a destination.
    if (levels > 1)
        imageBarrier(cb, image, 0, levels - 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    imageBarrier(cb, image, levels - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                 VK_ACCESS_SHADER_READ_BIT);
    return createView(ctx, image, format, VK_IMAGE_ASPECT_COLOR_BIT, levels, cleanup, type, count);
}

}  // namespace

VkImageView uploadTexture(VulkanContext& ctx, VkCommandBuffer cb, const Texture& t, Cleanup& cleanup) {
    return upload(ctx, cb, {&t}, VK_IMAGE_VIEW_TYPE_2D, cleanup);
}

VkImageView uploadTextureArray(VulkanContext& ctx, VkCommandBuffer cb, const std::vector<const Texture*>& layers, Cleanup& cleanup) {
    return upload(ctx, cb, layers, VK_IMAGE_VIEW_TYPE_2D_ARRAY, cleanup);
}

VkRenderPass createRenderPass(VulkanContext& ctx, Cleanup& cleanup) {
    VkAttachmentDescription attachments[2]{};
    attachments[0].format = kColorFormat;
    attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    attachments[1] = attachments[0];
    attachments[1].format = kDepthFormat;
    attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;

    VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &colorRef;
    subpass.pDepthStencilAttachment = &depthRef;

    // Makes the colour writes visible to the copy that follows the pass. Frames are separate submissions with a
    // fence wait in between, so nothing before the pass needs a dependency.
    VkSubpassDependency toCopy{};
    toCopy.srcSubpass = 0;
    toCopy.dstSubpass = VK_SUBPASS_EXTERNAL;
    toCopy.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    toCopy.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    toCopy.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    toCopy.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;

    VkRenderPassCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
    info.attachmentCount = 2;
    info.pAttachments = attachments;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 1;
    info.pDependencies = &toCopy;
    VkRenderPass pass;
    VK_CHECK(vkCreateRenderPass, ctx.device, &info, nullptr, &pass);
    cleanup.defer([dev = ctx.device, pass] { vkDestroyRenderPass(dev, pass, nullptr); });
    return pass;
}

namespace {

// The vertex and fragment stages, each from a shader module of its own, at the request's entry points.
std::array<VkPipelineShaderStageCreateInfo, 2> shaderStages(VulkanContext& ctx, const RenderRequest& req, Cleanup& cleanup) {
    std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
    stages[0].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = createShaderModule(ctx, req.vertexSpirv, cleanup);
    stages[0].pName = req.vertexEntry.c_str();
    stages[1] = stages[0];
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].pName = req.fragmentEntry.c_str();
    stages[1].module = createShaderModule(ctx, req.fragmentSpirv, cleanup);
    return stages;
}

// Filled triangles, neither face culled.
VkPipelineRasterizationStateCreateInfo rasterizationState() {
    VkPipelineRasterizationStateCreateInfo raster{};
    raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_NONE;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1;
    return raster;
}

}  // namespace

VkPipeline createPipeline(VulkanContext& ctx, const RenderRequest& req, VkPipelineLayout layout, VkRenderPass pass, Cleanup& cleanup) {
    const std::array<VkPipelineShaderStageCreateInfo, 2> stages = shaderStages(ctx, req, cleanup);

    VkPipelineVertexInputStateCreateInfo vertexInput{};
    vertexInput.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
    VkPipelineInputAssemblyStateCreateInfo assembly{};
    assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;

    VkViewport viewport{0, 0, float(req.width), float(req.height), 0, 1};
    VkRect2D scissor{{0, 0}, {uint32_t(req.width), uint32_t(req.height)}};
    VkPipelineViewportStateCreateInfo viewportState{};
    viewportState.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
    viewportState.viewportCount = 1;
    viewportState.pViewports = &viewport;
    viewportState.scissorCount = 1;
    viewportState.pScissors = &scissor;

    const VkPipelineRasterizationStateCreateInfo raster = rasterizationState();

    VkPipelineMultisampleStateCreateInfo multisample{};
    multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;

    // Depth is never a real test (ALWAYS); it is bound and written because llvmpipe otherwise drops a repeated
    // opaque full-screen draw, which would make the timed frames measure nothing.
    VkPipelineDepthStencilStateCreateInfo depth{};
    depth.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
    depth.depthTestEnable = VK_TRUE;
    depth.depthWriteEnable = VK_TRUE;
    depth.depthCompareOp = VK_COMPARE_OP_ALWAYS;

    VkPipelineColorBlendAttachmentState blendAttachment{};
    blendAttachment.colorWriteMask =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    VkPipelineColorBlendStateCreateInfo blend{};
    blend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
    blend.attachmentCount = 1;
    blend.pAttachments = &blendAttachment;

    VkGraphicsPipelineCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
    info.stageCount = 2;
    info.pStages = stages.data();
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewportState;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.layout = layout;
    info.renderPass = pass;
    VkPipeline pipeline;
    VK_CHECK(vkCreateGraphicsPipelines, ctx.device, ctx.pipelineCache, 1, &info, nullptr, &pipeline);
    cleanup.defer([dev = ctx.device, pipeline] { vkDestroyPipeline(dev, pipeline, nullptr); });
    return pipeline;
}

std::pair<VkImage, VkFramebuffer> createTarget(VulkanContext& ctx, VkRenderPass pass, uint32_t width, uint32_t height, Cleanup& cleanup) {
    const VkDevice dev = ctx.device;
    const VkImage color =
        createImage(ctx, kColorFormat, width, height, 1, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, cleanup);
    const VkImage depth = createImage(ctx, kDepthFormat, width, height, 1, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, cleanup);
    const VkImageView views[2] = {createView(ctx, color, kColorFormat, VK_IMAGE_ASPECT_COLOR_BIT, 1, cleanup),
                                  createView(ctx, depth, kDepthFormat, VK_IMAGE_ASPECT_DEPTH_BIT, 1, cleanup)};
    VkFramebufferCreateInfo fbInfo{};
    fbInfo.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    fbInfo.renderPass = pass;
    fbInfo.attachmentCount = 2;
    fbInfo.pAttachments = views;
    fbInfo.width = width;
    fbInfo.height = height;
    fbInfo.layers = 1;
    VkFramebuffer framebuffer;
    VK_CHECK(vkCreateFramebuffer, dev, &fbInfo, nullptr, &framebuffer);
    cleanup.defer([dev, framebuffer] { vkDestroyFramebuffer(dev, framebuffer, nullptr); });
    return {color, framebuffer};
}

HostBuffer createUniforms(VulkanContext& ctx, const std::vector<uint8_t>& data, Cleanup& cleanup) {
    const VkDeviceSize bytes = std::max<VkDeviceSize>(16, (data.size() + 15) / 16 * 16);
    const HostBuffer uniforms = createHostBuffer(ctx, bytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, cleanup);
    std::memset(uniforms.mapped, 0, bytes);
    if (!data.empty()) std::memcpy(uniforms.mapped, data.data(), data.size());
    return uniforms;
}

}  // namespace hexc::vk
