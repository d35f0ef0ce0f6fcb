#pragma once
// Reading inputs whole, and writing outputs so they appear whole or not at all.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace hexc {

// The file's bytes, or nullopt when it cannot be opened.
std::optional<std::string> readFile(const std::filesystem::path& file);

// Outputs are written under a temporary name in the same folder, then renamed.
// Calls write(temporary path) and renames the result to `file`; a failed write or rename removes the
// temporary and throws std::runtime_error naming `file`.
void writeFileAtomically(const std::filesystem::path& file, const std::function<bool(const std::filesystem::path&)>& write);

}  // namespace hexc
