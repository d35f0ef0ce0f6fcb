// The Vulkan context (context.h): instance, physical device, device and the objects every render shares.
#include "vk/context.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

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

}  // namespace

void check(VkResult result, const char* call) {
    if (result != VK_SUCCESS) throw VulkanError(std::string(call) + " failed: " + resultName(result));
}

namespace {

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

}  // namespace

std::unique_ptr<VulkanContext> openContext() {
    auto ctx = std::make_unique<VulkanContext>();
    createInstance(*ctx);
    pickDevice(*ctx);
    vkGetPhysicalDeviceMemoryProperties(ctx->physical, &ctx->memory);
    createDevice(*ctx);
    return ctx;
}

}  // namespace hexc::vk
