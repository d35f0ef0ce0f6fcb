#pragma once
// `hexc lint`: the texture checks (hexc/lint.h) on a material's slots or on one texture, with their figures.
#include <string>
#include <vector>

namespace hexc::cli {

int lintCommand(const std::vector<std::string>& args);

}  // namespace hexc::cli
