#pragma once
// What machine the numbers come from, for the reports of both benchmarks.
#include <fstream>
#include <string>
#include <thread>

#include "strf.h"

namespace hexc::bench {

inline std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.starts_with("model name")) return line.substr(line.find(':') + 2);
    return "unknown";
}

// The 1-minute load average: other processes share the cores and inflate every time measured.
inline std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string oneMinute = "unknown";
    in >> oneMinute;
    return oneMinute;
}

inline std::string cpuSummary() {
    return strf("%s, %u cores, load average %s at the start", cpuModel().c_str(), std::thread::hardware_concurrency(),
                loadAverage().c_str());
}

}  // namespace hexc::bench
