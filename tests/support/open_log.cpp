// Preloaded (LD_PRELOAD) into hexc by tests/cli/texture_reads_test.cpp: appends the real path of every file the process
// opens to the file HEXC_OPEN_LOG names, one a line, then opens it as asked. Test-only: hexc itself has no hook, and
// what is counted is what the C library is asked to open, whichever reader (stb_image, OpenEXR, a stream) asks.
#include <dlfcn.h>
#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <climits>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

void logOpen(const char* path) {
    const char* log = std::getenv("HEXC_OPEN_LOG");
    char real[PATH_MAX];
    if (!log || !path || !realpath(path, real)) return;  // a file that does not exist is not read
    // The raw system call: the log's own open must not come back here. One write of O_APPEND keeps threads' lines whole.
    const int fd = int(syscall(SYS_openat, AT_FDCWD, log, O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644));
    if (fd < 0) return;
    const size_t n = std::strlen(real);
    real[n] = '\n';
    [[maybe_unused]] ssize_t written = write(fd, real, n + 1);
    close(fd);
}

template <class F>
F next(const char* name) {
    return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
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

int __open_2(const char* path, int flags) { return open(path, flags); }
int __open64_2(const char* path, int flags) { return open64(path, flags); }
}
