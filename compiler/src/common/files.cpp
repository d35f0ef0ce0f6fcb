#include "hexc/files.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <random>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace hexc {
namespace {

// Closes a POSIX file descriptor on every path out.
struct Fd {
    int fd;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

// The temporaries this process is writing, for removeOwnTemporaries, which a signal handler calls: fixed storage
// and atomics only. A writer past kInFlight (more threads than that writing at once) is not tracked: its temporary
// is removed by a later run as a dead writer's.
constexpr size_t kInFlight = 64;
struct InFlight {
    std::atomic<int> state{0};  // 0 free, 1 being filled, 2 holds a path
    char path[4096];
};
InFlight inFlight[kInFlight];

// Registers `temp`; returns its entry, or kInFlight when none was free or the path is too long.
size_t track(const std::filesystem::path& temp) {
    const std::string& path = temp.native();
    if (path.size() >= sizeof inFlight[0].path) return kInFlight;
    for (size_t i = 0; i < kInFlight; ++i) {
        int free = 0;
        if (!inFlight[i].state.compare_exchange_strong(free, 1)) continue;
        std::memcpy(inFlight[i].path, path.c_str(), path.size() + 1);
        inFlight[i].state = 2;
        return i;
    }
    return kInFlight;
}

void untrack(size_t entry) {
    if (entry < kInFlight) inFlight[entry].state = 0;
}

// A temporary's tag, 16 hex digits: random, so that writers on other machines or in other PID namespaces sharing a
// folder never pick the same name (a pid is unique only in its namespace). splitmix64 of a per-process random seed
// and a counter.
std::string temporaryTag() {
    static const uint64_t seed = (uint64_t(std::random_device{}()) << 32) ^ std::random_device{}();
    static std::atomic<uint64_t> counter{0};
    uint64_t z = seed + 0x9e3779b97f4a7c15ull * ++counter;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    char tag[17];
    std::snprintf(tag, sizeof tag, "%016llx", static_cast<unsigned long long>(z ^ (z >> 31)));
    return tag;
}

// Whether `file` is named as writeFileAtomically names temporaries: ".<name>.<16 hex digits>.tmp".
bool isTemporary(const std::string& file) {
    if (!file.starts_with(".") || !file.ends_with(".tmp") || file.size() < 23) return false;
    const std::string tag = file.substr(file.size() - 20, 16);
    return file[file.size() - 21] == '.' && tag.find_first_not_of("0123456789abcdef") == std::string::npos;
}

// A writer holds an exclusive lock on its temporary from creating it to renaming it; a temporary older than this that
// no one holds is a dead writer's (the age covers the moment between creating the file and locking it).
constexpr auto kTemporaryGrace = std::chrono::seconds(10);

}  // namespace

void removeOwnTemporaries() {
    for (InFlight& f : inFlight)
        if (f.state == 2) ::unlink(f.path);
}

void removeDeadTemporaries(const std::filesystem::path& dir) {
    std::error_code ec;
    const auto before = std::filesystem::file_time_type::clock::now() - kTemporaryGrace;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
        if (!isTemporary(entry.path().filename().string()) || !entry.is_regular_file(ec) || entry.last_write_time(ec) > before) continue;
        // The lock is the writer's, wherever it runs (another container, another machine over NFS): one that cannot be
        // taken belongs to a live writer, which keeps its file.
        Fd f{::open(entry.path().c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC)};
        if (f.fd >= 0 && ::flock(f.fd, LOCK_EX | LOCK_NB) == 0) std::filesystem::remove(entry.path(), ec);
    }
}

std::optional<std::string> readFile(const std::filesystem::path& file, std::string* whyNot, uint64_t limit) {
    auto fail = [&](std::string why) -> std::optional<std::string> {
        if (whyNot) *whyNot = std::move(why);
        return std::nullopt;
    };
    // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused below like any non-regular file.
    Fd in{::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
    if (in.fd < 0) return fail(std::strerror(errno));
    struct stat st;
    if (::fstat(in.fd, &st) != 0) return fail(std::strerror(errno));
    if (!S_ISREG(st.st_mode)) return fail(whyNotRegular(file));
    if (uint64_t(st.st_size) > limit) return fail("larger than hexc's input limit of " + std::to_string(limit >> 20) + " MiB");
    // Read what is there, up to the limit: a file that grows while read is cut off and reported, not followed.
    std::string bytes;
    bytes.reserve(size_t(st.st_size));  // one allocation for a file that does not grow
    char buffer[65536];
    for (;;) {
        ssize_t n = ::read(in.fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return fail(std::strerror(errno));
        if (n == 0) return bytes;
        if (bytes.size() + size_t(n) > limit) return fail("grew past hexc's input limit while being read");
        bytes.append(buffer, size_t(n));
    }
}

std::string whyNotRegular(const std::filesystem::path& file) {
    std::error_code ec;
    std::filesystem::file_status status = std::filesystem::status(file, ec);
    if (!std::filesystem::exists(status)) return "no such file";
    return std::filesystem::is_directory(status) ? "is a directory" : "not a regular file";
}

void writeFileAtomically(const std::filesystem::path& file, const std::function<bool(const std::filesystem::path&)>& write) {
    // Only a regular file (or nothing) is replaced: a symlink, device or FIFO given as an output is refused, so
    // `--depfile /dev/null` cannot replace /dev/null.
    std::error_code ec;
    std::filesystem::file_status status = std::filesystem::symlink_status(file, ec);
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        throw std::runtime_error("cannot write " + file.string() + ": it exists and is not a regular file");
    // A hidden name in the target folder, so the rename stays on one file system and is atomic; random, and created
    // exclusively, so concurrent writers into one folder never share or rename each other's temporary. Locked until
    // renamed, so that other writers' removeDeadTemporaries leave it alone. Tracked before it is created: a signal
    // that comes while open() creates it is handled when open() returns, and must find it (a name another writer
    // holds, EEXIST, is a 64-bit random tag met twice: then untracked before the next is tried).
    std::filesystem::path temp;
    Fd held{-1};
    size_t entry = kInFlight;
    for (int attempt = 0; held.fd < 0 && attempt < 8; ++attempt) {
        temp = file.parent_path() / ("." + file.filename().string() + "." + temporaryTag() + ".tmp");
        entry = track(temp);
        held.fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (held.fd >= 0) break;
        const int error = errno;
        untrack(entry);
        errno = error;
        if (error != EEXIST) break;
    }
    if (held.fd < 0) throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(errno));
    ::flock(held.fd, LOCK_EX);
    // A file replaced keeps its permissions (a material kept private stays private); a new one gets the umask's.
    if (struct stat st; ::stat(file.c_str(), &st) == 0) ::fchmod(held.fd, st.st_mode & 07777);
    const bool written = write(temp);
    if (written) std::filesystem::rename(temp, file, ec);
    untrack(entry);
    if (!written) {
        std::filesystem::remove(temp, ec);
        throw std::runtime_error("cannot write " + file.string());
    }
    if (ec) {
        std::string why = ec.message();
        std::filesystem::remove(temp, ec);
        throw std::runtime_error("cannot write " + file.string() + ": " + why);
    }
}

}  // namespace hexc
