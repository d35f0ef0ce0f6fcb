#pragma once
// Arrays indexed by an enum's value (names, file extensions, Vulkan types): `byEnum<Last>` checks at compile time
// that there is one entry per value, `Last` being the enum's last, so appending a value without its entry does not
// compile. (The order cannot be checked: keep the entries in the enum's order.)
#include <array>
#include <cstddef>

namespace hexc {

template <auto Last, typename T, size_t N>
constexpr std::array<T, N> byEnum(const T (&entries)[N]) {
    static_assert(N == size_t(Last) + 1, "one entry per enum value, in enum order");
    return std::to_array(entries);
}

}  // namespace hexc
