// Preloaded (LD_PRELOAD) into hexc by tests/cli/texture_reads_test.cpp: appends the real path of every file the process
// opens to the file HEXC_OPEN_LOG names, one a line, then opens it as asked. Test-only: hexc itself has no hook, and
// what is counted is what the C library is asked to open, whichever reader (stb_image, OpenEXR, a stream) asks.
// With HEXC_STAT_LOG (tests/cli/hostile_test.cpp, a scene's planning), every path asked about by stat or lstat (and
// std::filesystem's queries, which use them) is appended there as given, one a line.
#include <dlfcn.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

// Appends `path` and a line break to the log named by the environment variable `log`, in one write.
void append(const char* log, const char* path, size_t n) {
    // The raw system call: the log's own open must not come back here. One write of O_APPEND keeps threads' lines whole.
    const int fd = int(syscall(SYS_openat, AT_FDCWD, log, O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644));
    if (fd < 0) return;
    char line[PATH_MAX + 1];
    n = std::min<size_t>(n, PATH_MAX);
    std::memcpy(line, path, n);
    line[n] = '\n';
    [[maybe_unused]] ssize_t written = write(fd, line, n + 1);
    close(fd);
}

void logStat(const char* path) {
    if (const char* log = std::getenv("HEXC_STAT_LOG"); log && path) append(log, path, std::strlen(path));
}

template <class F>
F next(const char* name) {
    return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}

void logOpen(const char* path) {
    const char* log = std::getenv("HEXC_OPEN_LOG");
    char real[PATH_MAX];
    if (!log || !path || !realpath(path, real)) return;  // a file that does not exist is not read
    append(log, real, std::strlen(real));
}

mode_t modeOf(int flags, va_list args) { return (flags & (O_CREAT | O_TMPFILE)) ? mode_t(va_arg(args, int)) : 0; }

}  // namespace

extern "C" {

#define HEXC_OPEN(name)                                                        \
    int name(const char* path, int flags, ...) {                               \
        va_list args;                                                          \
        va_start(args, flags);                                                 \
        const mode_t mode = modeOf(flags, args);                               \
        va_end(args);                                                          \
        logOpen(path);                                                         \
        return next<int (*)(const char*, int, ...)>(#name)(path, flags, mode); \
    }
#define HEXC_OPENAT(name)                                                                \
    int name(int dir, const char* path, int flags, ...) {                                \
        va_list args;                                                                    \
        va_start(args, flags);                                                           \
        const mode_t mode = modeOf(flags, args);                                         \
        va_end(args);                                                                    \
        if (dir == AT_FDCWD || path[0] == '/') logOpen(path);                            \
        return next<int (*)(int, const char*, int, ...)>(#name)(dir, path, flags, mode); \
    }
#define HEXC_FOPEN(name)                                                     \
    FILE* name(const char* path, const char* mode) {                         \
        logOpen(path);                                                       \
        return next<FILE* (*)(const char*, const char*)>(#name)(path, mode); \
    }

HEXC_OPEN(open)
HEXC_OPEN(open64)
HEXC_OPENAT(openat)
HEXC_OPENAT(openat64)
HEXC_FOPEN(fopen)
HEXC_FOPEN(fopen64)

#define HEXC_STAT(name, type)                                              \
    int name(const char* path, struct type* out) {                         \
        logStat(path);                                                     \
        return next<int (*)(const char*, struct type*)>(#name)(path, out); \
    }

HEXC_STAT(stat, stat)
HEXC_STAT(lstat, stat)
HEXC_STAT(stat64, stat64)
HEXC_STAT(lstat64, stat64)

int __open_2(const char* path, int flags) { return open(path, flags); }
int __open64_2(const char* path, int flags) { return open64(path, flags); }
}
