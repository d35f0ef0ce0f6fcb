#pragma once
// Reading inputs whole, and writing outputs so they appear whole or not at all.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace hexc {

// Inputs (materials, scenes, templates) are small; the limit keeps a wrong path or hostile file from taking
// the machine's memory.
constexpr uint64_t kMaxInputBytes = 64ull << 20;

// The file's bytes, read once; nullopt when it cannot be opened, is not a regular file (a FIFO, a device such
// as /dev/zero, a folder) or exceeds `limit` bytes, with the reason in *whyNot when given.
std::optional<std::string> readFile(const std::filesystem::path& file, std::string* whyNot = nullptr, uint64_t limit = kMaxInputBytes);

// Why `file` is not a regular file, in a user's words: "no such file", "is a directory" or "not a regular
// file" (a FIFO, a device).
std::string whyNotRegular(const std::filesystem::path& file);

// Outputs are written under a random temporary name in the same folder (created exclusively, and locked by the writer
// until it is renamed), then renamed, keeping the permissions of a file it replaces; an existing
// target that is not a regular file (symlink, device, FIFO, folder) is refused with std::runtime_error.
// Calls write(temporary path) and renames the result to `file`; a failed write or rename removes the
// temporary and throws std::runtime_error naming `file`.
void writeFileAtomically(const std::filesystem::path& file, const std::function<bool(const std::filesystem::path&)>& write);

// Removes the temporaries writeFileAtomically is writing in this process, for a SIGINT or SIGTERM handler before the
// process ends: async-signal-safe (no allocation, no locks; unlink only).
void removeOwnTemporaries();

// Removes from `dir` the temporaries of writers that are no longer running (killed before they could rename or
// remove them): those older than a few seconds whose lock no writer holds, wherever it runs (a lock is seen across
// PID namespaces, and over NFS).
void removeDeadTemporaries(const std::filesystem::path& dir);

}  // namespace hexc
