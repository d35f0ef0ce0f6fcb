#pragma once
// `hexc export-mtlx`: write a material as a MaterialX document (docs/materialx.md).
#include <string>
#include <vector>

namespace hexc::cli {

int exportCommand(const std::vector<std::string>& args);

}  // namespace hexc::cli
