#pragma once
// `hexc render` and `hexc preview`: run a material on the Vulkan runner (lavapipe) and write images.
#include <string>
#include <vector>

namespace hexc::cli {

int renderCommand(const std::vector<std::string>& args);
int previewCommand(const std::vector<std::string>& args);

}  // namespace hexc::cli
