// Vulkan runner: see runner.h for the resource interface. Vulkan 1.0 only (render pass, no extensions), so it runs
// on any driver; lavapipe is the one it is tested on.
#include "vk/runner.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string_view>

#include "vk/loader.h"

namespace hexc::vk {
namespace {

std::string resultName(VkResult r) {
    switch (r) {
#define HEXC_VK_RESULT(name) \
    case name:               \
        return #name;
        HEXC_VK_RESULT(VK_SUCCESS)
        HEXC_VK_RESULT(VK_NOT_READY)
        HEXC_VK_RESULT(VK_TIMEOUT)
        HEXC_VK_RESULT(VK_INCOMPLETE)
        HEXC_VK_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
        HEXC_VK_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        HEXC_VK_RESULT(VK_ERROR_INITIALIZATION_FAILED)
        HEXC_VK_RESULT(VK_ERROR_DEVICE_LOST)
        HEXC_VK_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
        HEXC_VK_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
        HEXC_VK_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
        HEXC_VK_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
        HEXC_VK_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
        HEXC_VK_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
        HEXC_VK_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
        HEXC_VK_RESULT(VK_ERROR_FRAGMENTED_POOL)
        HEXC_VK_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
        HEXC_VK_RESULT(VK_ERROR_INVALID_SHADER_NV)
        HEXC_VK_RESULT(VK_ERROR_UNKNOWN)
#undef HEXC_VK_RESULT
        default:
            return "VkResult(" + std::to_string(int(r)) + ")";
    }
}

// The one place a VkResult is checked: anything but VK_SUCCESS throws, naming the call.
void check(VkResult result, const char* call) {
    if (result != VK_SUCCESS) throw VulkanError(std::string(call) + " failed: " + resultName(result));
}
#define VK_CHECK(fn, ...) check(fn(__VA_ARGS__), #fn)

// Destroy calls registered as objects are created, run newest first: every path out, exceptions included,
// frees exactly what was made.
class Cleanup {
public:
    Cleanup() = default;
    Cleanup(const Cleanup&) = delete;
    Cleanup& operator=(const Cleanup&) = delete;
    ~Cleanup() {
        for (auto it = fns_.rbegin(); it != fns_.rend(); ++it) (*it)();
    }
    void defer(std::function<void()> fn) { fns_.push_back(std::move(fn)); }

private:
    std::vector<std::function<void()>> fns_;
};

constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
// The vertex shader's uv rectangle takes push constant bytes 0..15; a fragment shader's own start after it.
constexpr uint32_t kFragmentPushOffset = sizeof(RenderRequest::uvRect);

}  // namespace

struct VulkanContext {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memory{};
    uint32_t queueFamily = 0;
    uint32_t timestampValidBits = 0;  // 0: the queue cannot write timestamps
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    VkPipelineCache pipelineCache = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    Cleanup cleanup;  // destroys the objects above; declared last so that it runs first

    ~VulkanContext() {
        if (device) vkDeviceWaitIdle(device);
    }
};

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

// Every buffer here is written or read by the host (uniforms, staging, read-back), so all are host-visible,
// coherent (no flush/invalidate calls) and stay mapped until freed.
struct HostBuffer {
    VkBuffer buffer;
    void* mapped;
};

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

VkImage createImage(VulkanContext& ctx, VkFormat format, uint32_t width, uint32_t height, uint32_t mipLevels, VkImageUsageFlags usage,
                    Cleanup& cleanup) {
    VkImageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = mipLevels;
    info.arrayLayers = 1;
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

VkImageView createView(VulkanContext& ctx, VkImage image, VkFormat format, VkImageAspectFlags aspect, uint32_t mipLevels,
                       Cleanup& cleanup) {
    VkImageViewCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    info.image = image;
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = format;
    info.subresourceRange = {aspect, 0, mipLevels, 0, 1};
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
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, baseLevel, levelCount, 0, 1};
    vkCmdPipelineBarrier(cb, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

// Creates the texture's image with a full mip chain and records, into cb, the upload of level 0 from a staging
// buffer and the blits that build each further level from the one before. Returns a view of all levels, which
// is in SHADER_READ_ONLY_OPTIMAL once cb has run.
VkImageView uploadTexture(VulkanContext& ctx, VkCommandBuffer cb, const Texture& t, Cleanup& cleanup) {
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

    const void* pixels = t.isFloat() ? static_cast<const void*>(t.rgba32f.data()) : t.rgba8.data();
    const size_t bytes = t.isFloat() ? t.rgba32f.size() * sizeof(float) : t.rgba8.size();
    HostBuffer staging = createHostBuffer(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, cleanup);
    std::memcpy(staging.mapped, pixels, bytes);

    VkImage image = createImage(ctx, format, uint32_t(t.width), uint32_t(t.height), levels,
                                VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, cleanup);
    imageBarrier(cb, image, 0, levels, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {uint32_t(t.width), uint32_t(t.height), 1};
    vkCmdCopyBufferToImage(cb, staging.buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);

    int32_t w = t.width, h = t.height;
    for (uint32_t level = 1; level < levels; ++level) {
        imageBarrier(cb, image, level - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_READ_BIT);
        const int32_t nw = std::max(1, w / 2), nh = std::max(1, h / 2);
        VkImageBlit region{};
        region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, 1};
        region.srcOffsets[1] = {w, h, 1};
        region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
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
    return createView(ctx, image, format, VK_IMAGE_ASPECT_COLOR_BIT, levels, cleanup);
}

// Colour (cleared, then kept for the read-back copy) and depth (cleared, discarded).
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

VkPipeline createPipeline(VulkanContext& ctx, const RenderRequest& req, VkPipelineLayout layout, VkRenderPass pass, Cleanup& cleanup) {
    VkPipelineShaderStageCreateInfo stages[2]{};
    stages[0].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = createShaderModule(ctx, req.vertexSpirv, cleanup);
    stages[0].pName = req.vertexEntry.c_str();
    stages[1] = stages[0];
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].pName = req.fragmentEntry.c_str();
    stages[1].module = createShaderModule(ctx, req.fragmentSpirv, cleanup);

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

    VkPipelineRasterizationStateCreateInfo raster{};
    raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_NONE;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1;

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
    info.pStages = stages;
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

VkCommandBuffer allocateCommandBuffer(VulkanContext& ctx, Cleanup& cleanup) {
    VkCommandBufferAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    info.commandPool = ctx.commandPool;
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    VkCommandBuffer cb;
    VK_CHECK(vkAllocateCommandBuffers, ctx.device, &info, &cb);
    cleanup.defer([dev = ctx.device, pool = ctx.commandPool, cb] { vkFreeCommandBuffers(dev, pool, 1, &cb); });
    return cb;
}

void submitAndWait(VulkanContext& ctx, VkCommandBuffer cb) {
    VK_CHECK(vkResetFences, ctx.device, 1, &ctx.fence);
    VkSubmitInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    info.commandBufferCount = 1;
    info.pCommandBuffers = &cb;
    VK_CHECK(vkQueueSubmit, ctx.queue, 1, &info, ctx.fence);
    VK_CHECK(vkWaitForFences, ctx.device, 1, &ctx.fence, VK_TRUE, UINT64_MAX);
}

void validate(const VulkanContext& ctx, const RenderRequest& req) {
    const VkPhysicalDeviceLimits& limits = ctx.properties.limits;
    auto fail = [](const std::string& what) { throw std::runtime_error("vk::Runner::render: " + what); };
    if (req.width <= 0 || req.height <= 0 || uint32_t(req.width) > limits.maxImageDimension2D ||
        uint32_t(req.height) > limits.maxImageDimension2D)
        fail("image size " + std::to_string(req.width) + "x" + std::to_string(req.height) + " is out of range");
    if (req.vertexSpirv.empty() || req.fragmentSpirv.empty()) fail("a shader has no SPIR-V");
    if (req.uniformData.size() > limits.maxUniformBufferRange) fail("uniform data is larger than the device allows");
    if (req.textures.size() > limits.maxPerStageDescriptorSampledImages) fail("too many textures for the device");
    if (req.set >= limits.maxBoundDescriptorSets)
        fail("descriptor set " + std::to_string(req.set) + " is beyond the device's " + std::to_string(limits.maxBoundDescriptorSets));
    if (req.fragmentPushConstants.size() % 4 || kFragmentPushOffset + req.fragmentPushConstants.size() > limits.maxPushConstantsSize)
        fail("fragment push constants must be a multiple of 4 bytes within the device's push constant size");
    std::vector<const Texture*> textures = req.textures;
    for (const TemplateResource& r : req.templateResources) {
        const bool image = r.kind == TemplateResource::Kind::CombinedImageSampler || r.kind == TemplateResource::Kind::SampledImage;
        if (image) textures.push_back(r.texture);
        if (r.kind == TemplateResource::Kind::UniformBuffer && r.data.size() > limits.maxUniformBufferRange)
            fail("a template's uniform data is larger than the device allows");
    }
    for (const Texture* t : textures) {
        const size_t values = t ? size_t(t->width) * t->height * 4 : 0;
        if (!t || t->width <= 0 || t->height <= 0 || uint32_t(std::max(t->width, t->height)) > limits.maxImageDimension2D ||
            (t->isFloat() ? t->rgba32f.size() : t->rgba8.size()) != values)
            fail("a texture is missing, empty, too large or has the wrong number of values");
    }
    if (req.timedFrames < 0) fail("timedFrames is negative");
    if (req.timedFrames > 0 && ctx.timestampValidBits == 0) fail("the Vulkan queue cannot write timestamps");
}

// Picks the physical device and queue family, creates the device and the objects every render shares.
// The instance layers asked for: validation is opt-in (HEXC_VK_VALIDATION=1) and optional, as it is not installed
// on most machines that run the tests.
std::vector<const char*> instanceLayers() {
    std::vector<const char*> layers;
    const char* wantValidation = std::getenv("HEXC_VK_VALIDATION");
    if (wantValidation && std::string_view(wantValidation) == "1") {
        uint32_t count = 0;
        VK_CHECK(vkEnumerateInstanceLayerProperties, &count, nullptr);
        std::vector<VkLayerProperties> available(count);
        VK_CHECK(vkEnumerateInstanceLayerProperties, &count, available.data());
        const char* validation = "VK_LAYER_KHRONOS_validation";
        if (std::any_of(available.begin(), available.end(),
                        [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, validation) == 0; }))
            layers.push_back(validation);
        else
            std::fprintf(stderr, "hexc: HEXC_VK_VALIDATION=1 but %s is not installed; running without it\n", validation);
    }
    return layers;
}

void createInstance(VulkanContext& ctx) {
    const std::vector<const char*> layers = instanceLayers();
    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "hexc";
    app.apiVersion = VK_API_VERSION_1_0;
    VkInstanceCreateInfo instanceInfo{};
    instanceInfo.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    instanceInfo.pApplicationInfo = &app;
    instanceInfo.enabledLayerCount = uint32_t(layers.size());
    instanceInfo.ppEnabledLayerNames = layers.data();
    VK_CHECK(vkCreateInstance, &instanceInfo, nullptr, &ctx.instance);
    ctx.cleanup.defer([instance = ctx.instance] { vkDestroyInstance(instance, nullptr); });
}

// Usable: a graphics queue and the two attachment formats. Among usable devices, a CPU one (lavapipe) wins.
void pickDevice(VulkanContext& ctx) {
    uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices, ctx.instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    VK_CHECK(vkEnumeratePhysicalDevices, ctx.instance, &count, devices.data());
    bool found = false;
    for (VkPhysicalDevice pd : devices) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(pd, &props);
        if (found && !(props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU && ctx.properties.deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU))
            continue;
        VkFormatProperties color, depth;
        vkGetPhysicalDeviceFormatProperties(pd, kColorFormat, &color);
        vkGetPhysicalDeviceFormatProperties(pd, kDepthFormat, &depth);
        if (!(color.optimalTilingFeatures & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT) ||
            !(depth.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT))
            continue;
        uint32_t familyCount = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(pd, &familyCount, nullptr);
        std::vector<VkQueueFamilyProperties> families(familyCount);
        vkGetPhysicalDeviceQueueFamilyProperties(pd, &familyCount, families.data());
        for (uint32_t i = 0; i < familyCount; ++i) {
            if (!(families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT)) continue;
            ctx.physical = pd;
            ctx.properties = props;
            ctx.queueFamily = i;
            ctx.timestampValidBits = families[i].timestampValidBits;
            found = true;
            break;
        }
    }
    if (!found) throw VulkanError("no Vulkan device with a graphics queue and RGBA32F/D32 attachments");
}

// The device, its queue, and the long-lived objects every render shares.
void createDevice(VulkanContext& ctx) {
    Cleanup& cleanup = ctx.cleanup;
    const float priority = 1;
    VkDeviceQueueCreateInfo queueInfo{};
    queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queueInfo.queueFamilyIndex = ctx.queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo deviceInfo{};
    deviceInfo.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    VK_CHECK(vkCreateDevice, ctx.physical, &deviceInfo, nullptr, &ctx.device);
    const VkDevice dev = ctx.device;
    cleanup.defer([dev] { vkDestroyDevice(dev, nullptr); });
    vkGetDeviceQueue(dev, ctx.queueFamily, 0, &ctx.queue);

    VkCommandPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    poolInfo.queueFamilyIndex = ctx.queueFamily;
    VK_CHECK(vkCreateCommandPool, dev, &poolInfo, nullptr, &ctx.commandPool);
    cleanup.defer([dev, pool = ctx.commandPool] { vkDestroyCommandPool(dev, pool, nullptr); });

    VkPipelineCacheCreateInfo cacheInfo{};
    cacheInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO;
    VK_CHECK(vkCreatePipelineCache, dev, &cacheInfo, nullptr, &ctx.pipelineCache);
    cleanup.defer([dev, cache = ctx.pipelineCache] { vkDestroyPipelineCache(dev, cache, nullptr); });

    VkSamplerCreateInfo samplerInfo{};
    samplerInfo.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
    samplerInfo.magFilter = VK_FILTER_LINEAR;
    samplerInfo.minFilter = VK_FILTER_LINEAR;
    samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    samplerInfo.addressModeU = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    samplerInfo.addressModeV = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    samplerInfo.mipLodBias = 0;
    samplerInfo.anisotropyEnable = VK_FALSE;
    samplerInfo.minLod = 0;
    samplerInfo.maxLod = VK_LOD_CLAMP_NONE;
    VK_CHECK(vkCreateSampler, dev, &samplerInfo, nullptr, &ctx.sampler);
    cleanup.defer([dev, sampler = ctx.sampler] { vkDestroySampler(dev, sampler, nullptr); });

    VkFenceCreateInfo fenceInfo{};
    fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    VK_CHECK(vkCreateFence, dev, &fenceInfo, nullptr, &ctx.fence);
    cleanup.defer([dev, fence = ctx.fence] { vkDestroyFence(dev, fence, nullptr); });
}

std::unique_ptr<VulkanContext> openContext() {
    auto ctx = std::make_unique<VulkanContext>();
    createInstance(*ctx);
    pickDevice(*ctx);
    vkGetPhysicalDeviceMemoryProperties(ctx->physical, &ctx->memory);
    createDevice(*ctx);
    return ctx;
}

}  // namespace

Runner::Runner(std::unique_ptr<VulkanContext> context) : ctx_(std::move(context)) {}
Runner::~Runner() = default;

std::unique_ptr<Runner> Runner::create(std::string* whyNot) {
    try {
        loadVulkan();
        return std::unique_ptr<Runner>(new Runner(openContext()));
    } catch (const std::exception& e) {
        if (whyNot) *whyNot = e.what();
        return nullptr;
    }
}

std::string Runner::deviceName() const { return ctx_->properties.deviceName; }

namespace {

// One descriptor the draw binds: hexc's (parameter block, sampler, textures) or one of the template's own.
struct Descriptor {
    uint32_t set = 0, binding = 0;
    VkDescriptorType type{};
    VkDescriptorBufferInfo buffer{};  // uniform buffers
    VkDescriptorImageInfo image{};    // samplers and images
};

// Every descriptor of the request: hexc's block, sampler and textures, then the template's resources in request
// order (what fillDescriptors relies on). Throws when two share a set and binding.
std::vector<Descriptor> descriptorsOf(const RenderRequest& req) {
    std::vector<Descriptor> d = {{req.set, req.paramsBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                 {req.set, req.samplerBinding, VK_DESCRIPTOR_TYPE_SAMPLER}};
    const VkDescriptorType texture = req.combinedSamplers ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    for (uint32_t i = 0; i < req.textures.size(); ++i) d.push_back({req.set, req.firstTextureBinding + i, texture});
    static const VkDescriptorType types[] = {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                             VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, VK_DESCRIPTOR_TYPE_SAMPLER};
    for (const TemplateResource& r : req.templateResources) d.push_back({r.set, r.binding, types[int(r.kind)]});
    std::set<std::pair<uint32_t, uint32_t>> taken;
    for (const Descriptor& x : d)
        if (!taken.emplace(x.set, x.binding).second)
            throw std::runtime_error("vk::Runner::render: set " + std::to_string(x.set) + ", binding " + std::to_string(x.binding) +
                                     " is bound twice");
    return d;
}

// One set layout per set up to the highest used (empty ones between), and the pipeline layout: those sets, the
// vertex shader's uv rectangle as push constant bytes 0..15 and the fragment shader's own bytes from 16.
std::pair<std::vector<VkDescriptorSetLayout>, VkPipelineLayout> createLayouts(VulkanContext& ctx,
                                                                              const std::vector<Descriptor>& descriptors,
                                                                              uint32_t fragmentPushBytes, Cleanup& cleanup) {
    const VkDevice dev = ctx.device;
    uint32_t sets = 0;
    for (const Descriptor& d : descriptors) sets = std::max(sets, d.set + 1);
    std::vector<std::vector<VkDescriptorSetLayoutBinding>> bySet(sets);
    for (const Descriptor& d : descriptors) bySet[d.set].push_back({d.binding, d.type, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
    std::vector<VkDescriptorSetLayout> setLayouts;
    for (const auto& bindings : bySet) {
        VkDescriptorSetLayoutCreateInfo setLayoutInfo{};
        setLayoutInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
        setLayoutInfo.bindingCount = uint32_t(bindings.size());
        setLayoutInfo.pBindings = bindings.data();
        VkDescriptorSetLayout setLayout;
        VK_CHECK(vkCreateDescriptorSetLayout, dev, &setLayoutInfo, nullptr, &setLayout);
        cleanup.defer([dev, setLayout] { vkDestroyDescriptorSetLayout(dev, setLayout, nullptr); });
        setLayouts.push_back(setLayout);
    }

    const VkPushConstantRange pushRanges[] = {{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(RenderRequest::uvRect)},
                                              {VK_SHADER_STAGE_FRAGMENT_BIT, kFragmentPushOffset, fragmentPushBytes}};
    VkPipelineLayoutCreateInfo layoutInfo{};
    layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layoutInfo.setLayoutCount = uint32_t(setLayouts.size());
    layoutInfo.pSetLayouts = setLayouts.data();
    layoutInfo.pushConstantRangeCount = fragmentPushBytes ? 2 : 1;
    layoutInfo.pPushConstantRanges = pushRanges;
    VkPipelineLayout layout;
    VK_CHECK(vkCreatePipelineLayout, dev, &layoutInfo, nullptr, &layout);
    cleanup.defer([dev, layout] { vkDestroyPipelineLayout(dev, layout, nullptr); });
    return {setLayouts, layout};
}

// The colour render target (also the copy source) and the framebuffer over it and a depth buffer.
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

// The parameter block: an empty block still gets a (zeroed) 16-byte buffer, so binding 0 is always valid.
HostBuffer createUniforms(VulkanContext& ctx, const std::vector<uint8_t>& data, Cleanup& cleanup) {
    const VkDeviceSize bytes = std::max<VkDeviceSize>(16, (data.size() + 15) / 16 * 16);
    const HostBuffer uniforms = createHostBuffer(ctx, bytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, cleanup);
    std::memset(uniforms.mapped, 0, bytes);
    if (!data.empty()) std::memcpy(uniforms.mapped, data.data(), data.size());
    return uniforms;
}

// Points each descriptor at what it binds: the parameter block, the shared sampler, hexc's texture views, then the
// template's buffers and views (one per resource; unused entries for samplers), in descriptorsOf's order.
void fillDescriptors(const VulkanContext& ctx, const RenderRequest& req, std::vector<Descriptor>& d, VkBuffer uniforms,
                     const std::vector<VkImageView>& textureViews, const std::vector<VkBuffer>& ownBuffers,
                     const std::vector<VkImageView>& ownViews) {
    d[0].buffer = {uniforms, 0, VK_WHOLE_SIZE};
    d[1].image = {ctx.sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED};
    for (size_t i = 0; i < textureViews.size(); ++i)
        d[2 + i].image = {req.combinedSamplers ? ctx.sampler : VK_NULL_HANDLE, textureViews[i], VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    for (size_t j = 0; j < req.templateResources.size(); ++j) {
        Descriptor& x = d[2 + textureViews.size() + j];
        if (x.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
            x.buffer = {ownBuffers[j], 0, VK_WHOLE_SIZE};
        else
            x.image = {x.type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE ? VK_NULL_HANDLE : ctx.sampler, ownViews[j],
                       VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    }
}

// Allocates every set from a pool of its own and writes the descriptors.
std::vector<VkDescriptorSet> createSets(VulkanContext& ctx, const std::vector<Descriptor>& descriptors,
                                        const std::vector<VkDescriptorSetLayout>& setLayouts, Cleanup& cleanup) {
    const VkDevice dev = ctx.device;
    std::map<VkDescriptorType, uint32_t> counts;
    for (const Descriptor& d : descriptors) ++counts[d.type];
    std::vector<VkDescriptorPoolSize> poolSizes;
    for (const auto& [type, count] : counts) poolSizes.push_back({type, count});
    VkDescriptorPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    poolInfo.maxSets = uint32_t(setLayouts.size());
    poolInfo.poolSizeCount = uint32_t(poolSizes.size());
    poolInfo.pPoolSizes = poolSizes.data();
    VkDescriptorPool descriptorPool;
    VK_CHECK(vkCreateDescriptorPool, dev, &poolInfo, nullptr, &descriptorPool);
    cleanup.defer([dev, descriptorPool] { vkDestroyDescriptorPool(dev, descriptorPool, nullptr); });
    VkDescriptorSetAllocateInfo setInfo{};
    setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    setInfo.descriptorPool = descriptorPool;
    setInfo.descriptorSetCount = uint32_t(setLayouts.size());
    setInfo.pSetLayouts = setLayouts.data();
    std::vector<VkDescriptorSet> sets(setLayouts.size());
    VK_CHECK(vkAllocateDescriptorSets, dev, &setInfo, sets.data());

    std::vector<VkWriteDescriptorSet> writes(descriptors.size());
    for (size_t i = 0; i < writes.size(); ++i) {
        const Descriptor& d = descriptors[i];
        writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        writes[i].dstSet = sets[d.set];
        writes[i].dstBinding = d.binding;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = d.type;
        if (d.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
            writes[i].pBufferInfo = &d.buffer;
        else
            writes[i].pImageInfo = &d.image;
    }
    vkUpdateDescriptorSets(dev, uint32_t(writes.size()), writes.data(), 0, nullptr);
    return sets;
}

// Everything one draw binds.
struct Draw {
    VkRenderPass pass;
    VkFramebuffer framebuffer;
    VkPipeline pipeline;
    VkPipelineLayout layout;
    std::vector<VkDescriptorSet> sets;  // set i at index i
    uint32_t width, height;
    std::array<float, 4> uvRect;
    std::vector<uint8_t> fragmentPush;
};

void recordDraw(VkCommandBuffer cb, const Draw& d) {
    VkClearValue clears[2]{};
    clears[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo passInfo{};
    passInfo.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
    passInfo.renderPass = d.pass;
    passInfo.framebuffer = d.framebuffer;
    passInfo.renderArea = {{0, 0}, {d.width, d.height}};
    passInfo.clearValueCount = 2;
    passInfo.pClearValues = clears;
    vkCmdBeginRenderPass(cb, &passInfo, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, d.pipeline);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, d.layout, 0, uint32_t(d.sets.size()), d.sets.data(), 0, nullptr);
    vkCmdPushConstants(cb, d.layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(d.uvRect), d.uvRect.data());
    if (!d.fragmentPush.empty())
        vkCmdPushConstants(cb, d.layout, VK_SHADER_STAGE_FRAGMENT_BIT, kFragmentPushOffset, uint32_t(d.fragmentPush.size()),
                           d.fragmentPush.data());
    vkCmdDraw(cb, 3, 1, 0, 0);
    vkCmdEndRenderPass(cb);
}

// Copies the rendered image into the host-visible read-back buffer, made visible to the host.
void recordReadback(VkCommandBuffer cb, VkImage color, VkBuffer readback, uint32_t width, uint32_t height) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {width, height, 1};
    vkCmdCopyImageToBuffer(cb, color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback, 1, &copy);
    VkBufferMemoryBarrier toHost{};
    toHost.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER;
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    toHost.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.buffer = readback;
    toHost.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &toHost, 0, nullptr);
}

// GPU time of `frames` draws, one submission each: one command buffer resets two timestamp queries, writes
// one, draws, writes the other.
std::vector<double> timeFrames(VulkanContext& ctx, const Draw& draw, int frames, Cleanup& cleanup) {
    const VkDevice dev = ctx.device;
    VkQueryPoolCreateInfo queryInfo{};
    queryInfo.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
    queryInfo.queryCount = 2;
    VkQueryPool queries;
    VK_CHECK(vkCreateQueryPool, dev, &queryInfo, nullptr, &queries);
    cleanup.defer([dev, queries] { vkDestroyQueryPool(dev, queries, nullptr); });

    const VkCommandBuffer timed = allocateCommandBuffer(ctx, cleanup);
    VkCommandBufferBeginInfo beginInfo{};
    beginInfo.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;  // no one-time flag: submitted once per frame
    VK_CHECK(vkBeginCommandBuffer, timed, &beginInfo);
    vkCmdResetQueryPool(timed, queries, 0, 2);
    vkCmdWriteTimestamp(timed, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queries, 0);
    recordDraw(timed, draw);
    vkCmdWriteTimestamp(timed, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries, 1);
    VK_CHECK(vkEndCommandBuffer, timed);

    std::vector<double> ms;
    const uint64_t mask = ctx.timestampValidBits >= 64 ? ~0ull : (1ull << ctx.timestampValidBits) - 1;
    for (int frame = 0; frame < frames; ++frame) {
        submitAndWait(ctx, timed);
        uint64_t ticks[2];
        VK_CHECK(vkGetQueryPoolResults, dev, queries, 0, 2, sizeof(ticks), ticks, sizeof(uint64_t),
                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT);
        // Masked subtraction stays right if the counter wrapped between the two timestamps.
        const uint64_t elapsed = (ticks[1] - ticks[0]) & mask;
        ms.push_back(double(elapsed) * ctx.properties.limits.timestampPeriod * 1e-6);
    }
    return ms;
}

}  // namespace

RenderResult Runner::render(const RenderRequest& req) {
    VulkanContext& ctx = *ctx_;
    validate(ctx, req);
    Cleanup cleanup;
    // Declared after `cleanup`, so destroyed before it: if a submission fails, wait before destroying its objects.
    struct WaitIdle {
        VkDevice dev;
        ~WaitIdle() { vkDeviceWaitIdle(dev); }
    } waitIdle{ctx.device};
    const uint32_t width = uint32_t(req.width), height = uint32_t(req.height);

    std::vector<Descriptor> descriptors = descriptorsOf(req);
    const auto [setLayouts, layout] = createLayouts(ctx, descriptors, uint32_t(req.fragmentPushConstants.size()), cleanup);
    const VkRenderPass pass = createRenderPass(ctx, cleanup);
    const VkPipeline pipeline = createPipeline(ctx, req, layout, pass, cleanup);
    const auto [color, framebuffer] = createTarget(ctx, pass, width, height, cleanup);
    const VkDeviceSize imageBytes = VkDeviceSize(width) * height * 4 * sizeof(float);
    const HostBuffer readback = createHostBuffer(ctx, imageBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, cleanup);
    const HostBuffer uniforms = createUniforms(ctx, req.uniformData, cleanup);
    std::vector<VkBuffer> ownBuffers;
    for (const TemplateResource& r : req.templateResources)
        ownBuffers.push_back(r.kind == TemplateResource::Kind::UniformBuffer ? createUniforms(ctx, r.data, cleanup).buffer
                                                                             : VK_NULL_HANDLE);

    // The first command buffer uploads the textures, draws, and copies the image out.
    const VkCommandBuffer first = allocateCommandBuffer(ctx, cleanup);
    VkCommandBufferBeginInfo beginInfo{};
    beginInfo.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer, first, &beginInfo);
    std::vector<VkImageView> textureViews;
    for (const Texture* t : req.textures) textureViews.push_back(uploadTexture(ctx, first, *t, cleanup));
    std::vector<VkImageView> ownViews;
    for (const TemplateResource& r : req.templateResources)
        ownViews.push_back(r.texture ? uploadTexture(ctx, first, *r.texture, cleanup) : VK_NULL_HANDLE);
    fillDescriptors(ctx, req, descriptors, uniforms.buffer, textureViews, ownBuffers, ownViews);
    const std::vector<VkDescriptorSet> sets = createSets(ctx, descriptors, setLayouts, cleanup);
    const Draw draw{pass, framebuffer, pipeline, layout, sets, width, height, req.uvRect, req.fragmentPushConstants};
    recordDraw(first, draw);
    recordReadback(first, color, readback.buffer, width, height);
    VK_CHECK(vkEndCommandBuffer, first);
    submitAndWait(ctx, first);

    RenderResult result;
    result.image.width = req.width;
    result.image.height = req.height;
    result.image.rgba.resize(size_t(width) * height * 4);
    std::memcpy(result.image.rgba.data(), readback.mapped, imageBytes);  // rows top first, tightly packed
    if (req.timedFrames > 0) result.frameMs = timeFrames(ctx, draw, req.timedFrames, cleanup);
    return result;
}

}  // namespace hexc::vk
