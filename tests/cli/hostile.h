#pragma once
// The bounds every hostile case of the command line runs hexc under.
#include <sys/resource.h>

#include <string>

#include "support.h"

namespace hexc::test::hostile {

// A case's work is bounded by its processor time, which a loaded machine does not stretch as it does wall time (a
// case under ASan at a load of 8 once took over 20 s of wall time): 40 s, the 20 s of wall time on two cores that
// bound it before, all threads counted (a soft RLIMIT_CPU: the kernel stops the process with SIGXCPU). A case that needs more
// is a bug. The wall-time bound is only a guard against a hang (a process that waits without working), far above any
// real run.
constexpr int kCpuSeconds = 40;
constexpr int kHangSeconds = 600;

// The shell prefix that bounds a hexc run: processor time, no core file when it is exceeded, the hang guard; `env`:
// variable assignments for hexc's environment.
inline std::string bounds(const std::string& env = "") {
    return "ulimit -S -t " + std::to_string(kCpuSeconds) + "; ulimit -c 0; " + env + " timeout " + std::to_string(kHangSeconds);
}

// Processor time (user and system) of the children this process has waited for, in seconds.
inline double childrenCpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_CHILDREN, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct Outcome {
    int exit;           // 152: stopped by the processor-time bound (SIGXCPU); 124: by the hang guard
    std::string err;    // stderr
    double cpuSeconds;  // the run's processor time
};

inline Outcome runBounded(const std::string& args, const std::string& env = "") {
#ifdef HEXC_SANITIZED
    const std::string memory;  // ASan reserves terabytes of address space for its shadow; it checks memory itself
#else
    // The address-space bound includes the binary's own mappings (about 300 MiB with glslang and the C++ runtime).
    constexpr int kMiB = 1536;
    const std::string memory = "ulimit -v " + std::to_string(kMiB * 1024) + "; ";
#endif
    std::string err;
    const double before = childrenCpuSeconds();
    int exit = hexc::test::runHexc(args, &err, memory + bounds(env));
    return {exit, err, childrenCpuSeconds() - before};
}

}  // namespace hexc::test::hostile
