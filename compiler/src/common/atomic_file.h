#pragma once
// Outputs appear whole or not at all: written under a temporary name in the same folder, then renamed.
#include <filesystem>
#include <functional>

namespace hexc {

// Calls write(temporary path) and renames the result to `file`; a failed write or rename removes the
// temporary and throws std::runtime_error naming `file`.
void writeFileAtomically(const std::filesystem::path& file, const std::function<bool(const std::filesystem::path&)>& write);

}  // namespace hexc
