#pragma once
// Compiled shader code by content (CompileOptions::cache): a shader whose generated code, options and hexc build were
// compiled before is not compiled again. In memory for one batch; with a folder, across runs and processes.
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace hexc {

// The identity (16 hex digits) of the executable or shared object (a Python module) that holds libhexc's code: a hash of
// the linker's build id, which is a hash of the whole file, or of the file itself when it has none. libhexc, glslang,
// SPIRV-Tools and SPIRV-Cross are linked into it statically, so a rebuilt or upgraded hexc never trusts a stamp or cache
// entry of another build, nor does a rebuilt module loaded by the same Python.
const std::string& buildId();

// Where the folder cache goes unless told: $XDG_CACHE_HOME/hexc, else $HOME/.cache/hexc; empty when neither is set.
std::filesystem::path defaultCacheDir();

constexpr uint64_t kDefaultCacheBytes = 256ull << 20;

class ShaderCache {
public:
    // `dir` empty: in memory only. Several processes may share one folder: entries are written whole under a
    // temporary name and renamed, and an entry that is cut short or altered is found out by its checksum and
    // compiled again. The entries kept in memory stay within maxBytes too (a long `hexc edit` session makes many),
    // the oldest dropped first.
    explicit ShaderCache(std::filesystem::path dir = {}, uint64_t maxBytes = kDefaultCacheBytes);

    // The value under `key`: from memory, else from the folder, else compute()'s, stored. Threads asking for a key
    // another thread is computing wait for it, so a batch computes each key once. compute() returning nullopt
    // (a failed compile) stores nothing. `usable` (if given) checks a folder entry's payload as its reader will read
    // it: an entry whose checksum holds but whose payload does not decode (written by another build of hexc with the
    // same identity, or by hand) is removed and computed again like a damaged one, not returned on every run.
    std::optional<std::string> getOrCompute(const std::string& key, const std::function<std::optional<std::string>()>& compute,
                                            const std::function<bool(const std::string&)>& usable = {});

    // Removes the folder's least recently used entries until it holds at most maxBytes. Run after a batch.
    void trim() const;

    struct Stats {
        size_t hits = 0;         // found in memory or in the folder
        size_t misses = 0;       // computed
        size_t corrupt = 0;      // folder entries that failed their checksum or `usable` (removed, computed again)
        std::string unwritable;  // why the first entry could not be written to the folder, if one could not
    };
    Stats stats() const;

private:
    std::optional<std::string> loadFromFolder(const std::string& key, const std::function<bool(const std::string&)>& usable);
    void storeInFolder(const std::string& key, const std::string& value);
    std::filesystem::path entryPath(const std::string& key) const;

    std::filesystem::path dir_;
    uint64_t maxBytes_;
    mutable std::mutex mutex_;
    std::condition_variable done_;
    std::map<std::string, std::optional<std::string>> memory_;  // nullopt: being computed
    std::deque<std::string> memoryOrder_;                       // the keys with values, oldest first
    uint64_t memoryBytes_ = 0;                                  // their values' sizes
    Stats stats_;
};

}  // namespace hexc
