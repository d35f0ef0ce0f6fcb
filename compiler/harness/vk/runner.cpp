// Vulkan runner: see runner.h for the resource interface. Vulkan 1.0 only (render pass, no extensions), so it runs
// on any driver; lavapipe is the one it is tested on. Here: the request's descriptors, the draw, its read-back and
// timing; the device in context.cpp, the objects a render makes in resources.cpp.
#include "vk/runner.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include "vk/context.h"
#include "vk/resources.h"

namespace hexc::vk {
namespace {

// The vertex shader's uv rectangle takes push constant bytes 0..15; a fragment shader's own start after it.
constexpr uint32_t kFragmentPushOffset = sizeof(RenderRequest::uvRect);

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
    if (req.textureArrays.size() > req.textures.size()) fail("more texture arrays than textures");
    for (size_t i = 0; i < req.textureArrays.size(); ++i) {
        const std::vector<const Texture*>& layers = req.textureArrays[i];
        if (layers.size() > limits.maxImageArrayLayers) fail("a texture array has more layers than the device allows");
        for (const Texture* t : layers) {
            if (!t || !layers.front() || t->width != layers.front()->width || t->height != layers.front()->height ||
                t->isFloat() != layers.front()->isFloat() || t->srgb != layers.front()->srgb)
                fail("a texture array's layers differ in size or format");
            textures.push_back(t);
        }
    }
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
    static_assert(std::size(types) == size_t(TemplateResource::Kind::Sampler) + 1, "one Vulkan type per TemplateResource::Kind");
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
    for (size_t i = 0; i < req.textures.size(); ++i)
        textureViews.push_back(i < req.textureArrays.size() && !req.textureArrays[i].empty()
                                   ? uploadTextureArray(ctx, first, req.textureArrays[i], cleanup)
                                   : uploadTexture(ctx, first, *req.textures[i], cleanup));
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
