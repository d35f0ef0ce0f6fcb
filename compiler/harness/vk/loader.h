#pragma once
// The Vulkan 1.0 entry points the runner calls, resolved at run time from the system's Vulkan loader
// (libvulkan.so.1) instead of linked: binaries that link the harness (hexc among them) start and compile on
// machines without Vulkan, and only rendering needs it. Include this instead of <vulkan/vulkan.h>.
#define VK_NO_PROTOTYPES
#include <vulkan/vulkan.h>

namespace hexc::vk {

// Every function the runner uses; the loader exports each of them (core 1.0), so dlsym finds them all.
#define HEXC_VK_FUNCTIONS(X)                    \
    X(vkAllocateCommandBuffers)                 \
    X(vkAllocateDescriptorSets)                 \
    X(vkAllocateMemory)                         \
    X(vkBeginCommandBuffer)                     \
    X(vkBindBufferMemory)                       \
    X(vkBindImageMemory)                        \
    X(vkCmdBeginRenderPass)                     \
    X(vkCmdBindDescriptorSets)                  \
    X(vkCmdBindPipeline)                        \
    X(vkCmdBlitImage)                           \
    X(vkCmdCopyBufferToImage)                   \
    X(vkCmdCopyImageToBuffer)                   \
    X(vkCmdDraw)                                \
    X(vkCmdEndRenderPass)                       \
    X(vkCmdPipelineBarrier)                     \
    X(vkCmdPushConstants)                       \
    X(vkCmdResetQueryPool)                      \
    X(vkCmdWriteTimestamp)                      \
    X(vkCreateBuffer)                           \
    X(vkCreateCommandPool)                      \
    X(vkCreateDescriptorPool)                   \
    X(vkCreateDescriptorSetLayout)              \
    X(vkCreateDevice)                           \
    X(vkCreateFence)                            \
    X(vkCreateFramebuffer)                      \
    X(vkCreateGraphicsPipelines)                \
    X(vkCreateImage)                            \
    X(vkCreateImageView)                        \
    X(vkCreateInstance)                         \
    X(vkCreatePipelineCache)                    \
    X(vkCreatePipelineLayout)                   \
    X(vkCreateQueryPool)                        \
    X(vkCreateRenderPass)                       \
    X(vkCreateSampler)                          \
    X(vkCreateShaderModule)                     \
    X(vkDestroyBuffer)                          \
    X(vkDestroyCommandPool)                     \
    X(vkDestroyDescriptorPool)                  \
    X(vkDestroyDescriptorSetLayout)             \
    X(vkDestroyDevice)                          \
    X(vkDestroyFence)                           \
    X(vkDestroyFramebuffer)                     \
    X(vkDestroyImage)                           \
    X(vkDestroyImageView)                       \
    X(vkDestroyInstance)                        \
    X(vkDestroyPipeline)                        \
    X(vkDestroyPipelineCache)                   \
    X(vkDestroyPipelineLayout)                  \
    X(vkDestroyQueryPool)                       \
    X(vkDestroyRenderPass)                      \
    X(vkDestroySampler)                         \
    X(vkDestroyShaderModule)                    \
    X(vkDeviceWaitIdle)                         \
    X(vkEndCommandBuffer)                       \
    X(vkEnumerateInstanceLayerProperties)       \
    X(vkEnumeratePhysicalDevices)               \
    X(vkFreeCommandBuffers)                     \
    X(vkFreeMemory)                             \
    X(vkGetBufferMemoryRequirements)            \
    X(vkGetDeviceQueue)                         \
    X(vkGetImageMemoryRequirements)             \
    X(vkGetPhysicalDeviceFormatProperties)      \
    X(vkGetPhysicalDeviceMemoryProperties)      \
    X(vkGetPhysicalDeviceProperties)            \
    X(vkGetPhysicalDeviceQueueFamilyProperties) \
    X(vkGetQueryPoolResults)                    \
    X(vkMapMemory)                              \
    X(vkQueueSubmit)                            \
    X(vkResetFences)                            \
    X(vkUpdateDescriptorSets)                   \
    X(vkWaitForFences)

#define HEXC_VK_DECLARE(fn) extern PFN_##fn fn;
HEXC_VK_FUNCTIONS(HEXC_VK_DECLARE)
#undef HEXC_VK_DECLARE

// Resolves the functions above once per process (thread-safe); throws std::runtime_error saying what is
// missing when the loader cannot be opened or lacks a function.
void loadVulkan();

}  // namespace hexc::vk
