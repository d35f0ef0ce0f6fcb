#include "hexc/files.h"

#include <fcntl.h>
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

}  // namespace

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
    if (!write(temp)) {
        std::filesystem::remove(temp, ec);
        throw std::runtime_error("cannot write " + file.string());
    }
    std::filesystem::rename(temp, file, ec);
    if (ec) {
        std::string why = ec.message();
        std::filesystem::remove(temp, ec);
        throw std::runtime_error("cannot write " + file.string() + ": " + why);
    }
}

}  // namespace hexc
