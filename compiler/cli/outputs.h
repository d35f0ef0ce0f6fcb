#pragma once
#include <filesystem>
#include <string>

namespace hexc::cli {

// Writes `contents` to dir/name through a temporary file in the same folder and a rename, so a reader
// never sees a half-written file. Throws std::runtime_error naming the file on failure.
void writeAtomically(const std::filesystem::path& dir, const std::string& name, const std::string& contents);

}  // namespace hexc::cli
