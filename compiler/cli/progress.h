#pragma once
// A status line for long commands on a terminal: "hexc: [i/n] what", rewritten in place and cleared when the
// work is done. Silent when stderr is not a terminal (a pipe, a build log) or with -q.
#include <cstddef>
#include <mutex>
#include <string>

namespace hexc::cli {

class Progress {
public:
    Progress(size_t total, bool quiet);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    // Shows step i + 1 of total; safe to call from several threads.
    void step(const std::string& what);

private:
    std::mutex mutex_;
    size_t total_, done_ = 0;
    bool on_;
};

}  // namespace hexc::cli
