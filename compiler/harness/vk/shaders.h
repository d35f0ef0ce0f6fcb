#pragma once
// The harness's own shaders (templates/harness/), embedded at build time: file name -> text.
#include <map>
#include <string>

namespace hexc::vk {

const std::map<std::string, std::string>& harnessShaders();

}  // namespace hexc::vk
