#pragma once
// `hexc library`: write hexc's hex-tiling functions as include files for hand-written shaders.
#include <string>
#include <vector>

namespace hexc::cli {

int libraryCommand(const std::vector<std::string>& args);

}  // namespace hexc::cli
