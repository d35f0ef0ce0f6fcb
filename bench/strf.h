#pragma once
// printf-style formatting into a std::string (GCC 12 has no std::format).
#include <cstdarg>
#include <cstdio>
#include <string>

namespace hexc::bench {

[[gnu::format(printf, 1, 2)]] inline std::string strf(const char* format, ...) {
    va_list args, copy;
    va_start(args, format);
    va_copy(copy, args);
    std::string out(size_t(std::vsnprintf(nullptr, 0, format, copy)), '\0');
    va_end(copy);
    std::vsnprintf(out.data(), out.size() + 1, format, args);
    va_end(args);
    return out;
}

}  // namespace hexc::bench
