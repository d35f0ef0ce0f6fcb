#pragma once
// What the runner's files share (runner.cpp, context.cpp, resources.cpp), not part of runner.h: the Vulkan context a
// Runner owns, the one check of a VkResult, and the cleanup that destroys what a render makes.
#include <functional>
#include <memory>
#include <vector>

#include "vk/loader.h"
#include "vk/runner.h"

namespace hexc::vk {

// The one place a VkResult is checked: anything but VK_SUCCESS throws, naming the call.
void check(VkResult result, const char* call);
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

// Picks the physical device and queue family, creates the device and the objects every render shares.
std::unique_ptr<VulkanContext> openContext();

}  // namespace hexc::vk
