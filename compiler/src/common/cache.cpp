#include "hexc/cache.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <vector>

#if __has_include(<link.h>)
#include <link.h>
#endif

#include "hexc/hash.h"
#include "hexc/files.h"

namespace hexc {
namespace {

// An entry file: this header line, the key, the payload's checksum, then the payload. A reader that finds anything
// else (another format, a file cut short, flipped bits) treats the entry as missing.
constexpr std::string_view kEntryHeader = "hexc-cache 1\n";

std::string checksum(std::string_view payload) {
    ContentHash h;
    h.add(payload);
    return h.hex();
}

// The object hexc's code is in: the executable, or a shared object that links libhexc (the Python module).
struct CodeObject {
    std::string buildId;  // the linker's NT_GNU_BUILD_ID note (a hash it takes of the whole file it writes); empty: none
    std::string file;     // its file, for a hash of the file when it has no build id
};

// Found by the address of this function among the loaded objects' segments, and read in memory: the executable's
// identity would not change when a module loaded into it (Python's) is rebuilt.
CodeObject codeObject() {
    CodeObject found{"", "/proc/self/exe"};
#if __has_include(<link.h>)
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void* out) {
            const auto self = reinterpret_cast<ElfW(Addr)>(&codeObject);
            bool mine = false;
            for (int i = 0; i < info->dlpi_phnum; ++i) {
                const ElfW(Phdr)& p = info->dlpi_phdr[i];
                mine |= p.p_type == PT_LOAD && self - info->dlpi_addr - p.p_vaddr < p.p_memsz;
            }
            if (!mine) return 0;
            auto* object = static_cast<CodeObject*>(out);
            if (info->dlpi_name && *info->dlpi_name) object->file = info->dlpi_name;
            for (int i = 0; i < info->dlpi_phnum; ++i) {
                if (info->dlpi_phdr[i].p_type != PT_NOTE) continue;
                const char* at = reinterpret_cast<const char*>(info->dlpi_addr + info->dlpi_phdr[i].p_vaddr);
                for (const char* end = at + info->dlpi_phdr[i].p_memsz; at + sizeof(ElfW(Nhdr)) <= end;) {
                    const auto* note = reinterpret_cast<const ElfW(Nhdr)*>(at);
                    const char* name = at + sizeof(ElfW(Nhdr));
                    const char* desc = name + ((note->n_namesz + 3) & ~3u);
                    if (note->n_type == NT_GNU_BUILD_ID && note->n_namesz == 4 && std::memcmp(name, "GNU", 4) == 0)
                        object->buildId.assign(desc, note->n_descsz);
                    at = desc + ((note->n_descsz + 3) & ~3u);
                }
            }
            return 1;
        },
        &found);
#endif
    return found;
}

}  // namespace

const std::string& buildId() {
    static const std::string id = [] {
        // Without a linker's build id, a hash of the object's file (14 MB: 30 M instructions of a cold start).
        const CodeObject object = codeObject();
        std::string bytes = object.buildId;
        if (bytes.empty()) {
            std::ifstream in(object.file, std::ios::binary | std::ios::ate);
            bytes.assign(size_t(std::max<std::streamoff>(in.tellg(), 0)), '\0');
            in.seekg(0).read(bytes.data(), std::streamsize(bytes.size()));
        }
        ContentHash h;
        h.add(bytes);
        return h.hex(16);
    }();
    return id;
}

std::filesystem::path defaultCacheDir() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "hexc";
    if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "hexc";
    return {};
}

ShaderCache::ShaderCache(std::filesystem::path dir, uint64_t maxBytes) : dir_(std::move(dir)), maxBytes_(maxBytes) {}

std::optional<std::string> ShaderCache::getOrCompute(const std::string& key, const std::function<std::optional<std::string>()>& compute,
                                                     const std::function<bool(const std::string&)>& usable) {
    {
        std::unique_lock lock(mutex_);
        done_.wait(lock, [&] {
            auto it = memory_.find(key);
            return it == memory_.end() || it->second;
        });
        if (auto it = memory_.find(key); it != memory_.end()) {
            ++stats_.hits;
            return it->second;
        }
        memory_.emplace(key, std::nullopt);  // this thread computes it; others wait
    }
    std::optional<std::string> value = dir_.empty() ? std::nullopt : loadFromFolder(key, usable);
    const bool found = value.has_value();
    if (!found) {
        try {
            value = compute();
        } catch (...) {
            std::lock_guard lock(mutex_);
            memory_.erase(key);
            done_.notify_all();
            throw;
        }
        if (value && !dir_.empty()) storeInFolder(key, *value);
    }
    std::lock_guard lock(mutex_);
    ++(found ? stats_.hits : stats_.misses);
    if (value) {
        memory_[key] = value;
        memoryOrder_.push_back(key);
        memoryBytes_ += value->size();
        while (memoryBytes_ > maxBytes_ && memoryOrder_.size() > 1) {  // the newest stays, whatever its size
            auto oldest = memory_.find(memoryOrder_.front());
            memoryBytes_ -= oldest->second->size();
            memory_.erase(oldest);
            memoryOrder_.pop_front();
        }
    } else {
        memory_.erase(key);  // a failed compile: the next caller tries again
    }
    done_.notify_all();
    return value;
}

std::filesystem::path ShaderCache::entryPath(const std::string& key) const { return dir_ / key.substr(0, 2) / key; }

std::optional<std::string> ShaderCache::loadFromFolder(const std::string& key, const std::function<bool(const std::string&)>& usable) {
    const std::filesystem::path path = entryPath(key);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return std::nullopt;
    std::optional<std::string> bytes = readFile(path);
    const std::string head = std::string(kEntryHeader) + key + "\n";
    const size_t payloadAt = head.size() + 33;  // the checksum's 32 digits and a newline
    if (bytes && bytes->starts_with(head) && bytes->size() >= payloadAt && (*bytes)[payloadAt - 1] == '\n') {
        std::string payload = bytes->substr(payloadAt);
        if (bytes->compare(head.size(), 32, checksum(payload)) == 0 && (!usable || usable(payload))) {
            // Its time marks it used, for trim().
            std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now(), ec);
            return payload;
        }
    }
    std::filesystem::remove(path, ec);
    std::lock_guard lock(mutex_);
    ++stats_.corrupt;
    return std::nullopt;
}

void ShaderCache::storeInFolder(const std::string& key, const std::string& value) {
    const std::filesystem::path path = entryPath(key);
    std::string why;
    std::error_code ec;
    if (std::filesystem::create_directories(path.parent_path(), ec); ec)
        why = "cannot create " + path.parent_path().string() + ": " + ec.message();
    else
        try {
            writeFileAtomically(path, [&](const std::filesystem::path& temporary) {
                std::ofstream out(temporary, std::ios::binary);
                out << kEntryHeader << key << "\n" << checksum(value) << "\n" << value;
                return bool(out.flush());
            });
        } catch (const std::exception& e) {
            why = e.what();
        }
    // A cache that cannot be written (read-only, full disk) costs speed, not correctness: reported, not fatal.
    std::lock_guard lock(mutex_);
    if (!why.empty() && stats_.unwritable.empty()) stats_.unwritable = why;
}

void ShaderCache::trim() const {
    if (dir_.empty()) return;
    struct Entry {
        std::filesystem::file_time_type time;
        uint64_t size;
        std::filesystem::path path;
    };
    std::vector<Entry> entries;
    uint64_t total = 0;
    std::error_code ec;
    for (auto it = std::filesystem::recursive_directory_iterator(dir_, ec); !ec && it != std::filesystem::recursive_directory_iterator();
         it.increment(ec)) {
        // Another process's temporary (a dot name) is not an entry yet.
        if (!it->is_regular_file(ec) || it->path().filename().string().starts_with(".")) continue;
        Entry e{it->last_write_time(ec), it->file_size(ec), it->path()};
        if (ec) continue;  // removed meanwhile by another process
        total += e.size;
        entries.push_back(std::move(e));
    }
    std::sort(entries.begin(), entries.end(),
              [](const Entry& a, const Entry& b) { return a.time < b.time || (a.time == b.time && a.path < b.path); });
    for (const Entry& e : entries) {
        if (total <= maxBytes_) break;
        std::filesystem::remove(e.path, ec);
        total -= e.size;
    }
}

ShaderCache::Stats ShaderCache::stats() const {
    std::lock_guard lock(mutex_);
    return stats_;
}

}  // namespace hexc
