#pragma once
// `hexc edit`: a local page that renders a material live as it is tuned (docs/edit.md).
#include <string>
#include <vector>

namespace hexc::edit {

int editCommand(const std::vector<std::string>& args);

}  // namespace hexc::edit
