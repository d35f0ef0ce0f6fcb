#include "progress.h"

#include <unistd.h>

#include <iostream>

namespace hexc::cli {

namespace {
constexpr const char* kClearLine = "\r\033[K";  // carriage return, erase to the end of the line
}

Progress::Progress(size_t total, bool quiet) : total_(total), on_(!quiet && ::isatty(STDERR_FILENO)) {}

Progress::~Progress() {
    if (on_ && done_ > 0) std::cerr << kClearLine << std::flush;
}

void Progress::step(const std::string& what) {
    if (!on_) return;
    std::lock_guard lock(mutex_);
    std::cerr << kClearLine << "hexc: [" << ++done_ << "/" << total_ << "] " << what << std::flush;
}

}  // namespace hexc::cli
