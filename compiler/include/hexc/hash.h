#pragma once
// A content hash for caching and deduplication (not for security): XXH3, 128 bit, from Debian's libxxhash.
// Stable across runs and machines, so stamps and content-named files are deterministic.
// The state on the stack (its layout is exposed for that, for this library version only: linked statically or
// from the same package).
#define XXH_STATIC_LINKING_ONLY
#include <xxhash.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace hexc {

class ContentHash {
public:
    ContentHash() { XXH3_128bits_reset(&state_); }

    // Each field is length-prefixed, so ("ab", "c") and ("a", "bc") differ whatever bytes the fields hold.
    void add(std::string_view bytes) {
        uint64_t size = bytes.size();
        unsigned char prefix[8];
        for (int i = 0; i < 8; ++i) prefix[i] = static_cast<unsigned char>(size >> (8 * i));  // little-endian everywhere
        XXH3_128bits_update(&state_, prefix, sizeof prefix);
        XXH3_128bits_update(&state_, bytes.data(), bytes.size());
    }

    // The hash as hex digits (32 for the whole hash, fewer for a prefix).
    std::string hex(size_t digits = 32) const {
        XXH128_hash_t h = XXH3_128bits_digest(&state_);
        char buf[33];
        std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                      static_cast<unsigned long long>(h.low64));
        return std::string(buf, digits);
    }

private:
    XXH3_state_t state_;
};

}  // namespace hexc
