#include "hexc/files.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
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

// A temporary writeFileAtomically names: ".<name>.<pid>.<n>.tmp"; the writer's pid, or 0 when `file` is not one.
pid_t temporaryWriter(const std::string& file) {
    if (!file.starts_with(".") || !file.ends_with(".tmp")) return 0;
    const size_t counter = file.rfind('.', file.size() - 5), pid = counter == std::string::npos ? counter : file.rfind('.', counter - 1);
    if (pid == std::string::npos || pid == 0) return 0;
    const std::string digits = file.substr(pid + 1, counter - pid - 1);
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return 0;
    return pid_t(std::stol(digits));
}

}  // namespace

void removeOwnTemporaries() {
    for (InFlight& f : inFlight)
        if (f.state == 2) ::unlink(f.path);
}

void removeDeadTemporaries(const std::filesystem::path& dir) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
        const pid_t writer = temporaryWriter(entry.path().filename().string());
        // kill(pid, 0) fails with ESRCH only when no such process exists; a live one (even another program that
        // reused the pid) keeps its file.
        if (writer > 0 && writer != ::getpid() && ::kill(writer, 0) != 0 && errno == ESRCH && entry.is_regular_file(ec))
            std::filesystem::remove(entry.path(), ec);
    }
}

std::optional<std::string> readFile(const std::filesystem::path& file, std::string* whyNot) {
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
    if (uint64_t(st.st_size) > kMaxInputBytes)
        return fail("larger than hexc's input limit of " + std::to_string(kMaxInputBytes >> 20) + " MiB");
    // Read what is there, up to the limit: a file that grows while read is cut off and reported, not followed.
    std::string bytes;
    bytes.reserve(size_t(st.st_size));  // one allocation for a file that does not grow
    char buffer[65536];
    for (;;) {
        ssize_t n = ::read(in.fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return fail(std::strerror(errno));
        if (n == 0) return bytes;
        if (bytes.size() + size_t(n) > kMaxInputBytes) return fail("grew past hexc's input limit while being read");
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
    // A hidden name in the target folder, so the rename stays on one file system and is atomic; unique per
    // process and call, so concurrent writers into one folder never share or rename each other's temporary.
    static std::atomic<unsigned> counter{0};
    std::filesystem::path temp =
        file.parent_path() / ("." + file.filename().string() + "." + std::to_string(::getpid()) + "." + std::to_string(counter++) + ".tmp");
    const size_t entry = track(temp);
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
