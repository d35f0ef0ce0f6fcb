#pragma once
// FNV-1a, 64 bit: a content hash for caching and deduplication (not for security), stable across runs and
// machines, so stamps and content-named files are deterministic.
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace hexc {

class Fnv1a {
public:
    void add(std::string_view bytes) {
        for (unsigned char c : bytes) hash_ = (hash_ ^ c) * 0x100000001b3ull;
        // A separator, so ("ab", "c") and ("a", "bc") differ.
        hash_ = (hash_ ^ 0xff) * 0x100000001b3ull;
    }
    // The hash as hex digits (16 for the whole hash, fewer for a prefix).
    std::string hex(size_t digits = 16) const {
        char buf[17];
        std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash_));
        return std::string(buf, digits);
    }

private:
    uint64_t hash_ = 0xcbf29ce484222325ull;
};

}  // namespace hexc
