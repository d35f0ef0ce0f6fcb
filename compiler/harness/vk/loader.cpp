#include "vk/loader.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>
#include <string>

namespace hexc::vk {

#define HEXC_VK_DEFINE(fn) PFN_##fn fn = nullptr;
HEXC_VK_FUNCTIONS(HEXC_VK_DEFINE)
#undef HEXC_VK_DEFINE

namespace {

void resolve() {
    // The loader stays open for the life of the process: the functions point into it.
    void* loader = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!loader) throw std::runtime_error(std::string("cannot load the Vulkan loader libvulkan.so.1 (") + dlerror() + ")");
#define HEXC_VK_RESOLVE(fn)                              \
    fn = reinterpret_cast<PFN_##fn>(dlsym(loader, #fn)); \
    if (!fn) throw std::runtime_error("the Vulkan loader libvulkan.so.1 has no " #fn);
    HEXC_VK_FUNCTIONS(HEXC_VK_RESOLVE)
#undef HEXC_VK_RESOLVE
}

}  // namespace

void loadVulkan() {
    static std::once_flag once;
    static std::string failure;
    std::call_once(once, [] {
        try {
            resolve();
        } catch (const std::exception& e) {
            failure = e.what();
        }
    });
    if (!failure.empty()) throw std::runtime_error(failure);
}

}  // namespace hexc::vk
