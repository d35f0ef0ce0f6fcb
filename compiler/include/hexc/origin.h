#pragma once
// Split coordinates for large worlds (stable mode, "split_coordinates": true). Each frame, for each such
// slot, the engine turns its double-precision uv origin into the slot's two parameters
// <slot>_origin_cell (ivec2) and <slot>_origin_offset (vec2), and feeds the mesh uv relative to that
// origin. The lattice repeats exactly every (28, 1) in st = uv * tiling (docs/material-format.md#mode), so
// the shader adds cell * (28, 1) to the tile ids in integers and never sees the large number.
#include <array>
#include <cmath>
#include <cstdint>

namespace hexc {

struct SplitOrigin {
    std::array<int32_t, 2> cell;  // floor(st / (28, 1)), kept modulo 2^32 (the shader's ids wrap the same way)
    std::array<float, 2> offset;  // st - cell * (28, 1), in [0, 28) x [0, 1)
};

inline SplitOrigin splitOrigin(double u, double v, const std::array<double, 2>& tiling) {
    const double s = u * tiling[0], t = v * tiling[1];
    const double cx = std::floor(s / 28.0), cy = std::floor(t);
    auto wrap = [](double c) { return int32_t(uint32_t(uint64_t(int64_t(c)))); };
    return {{wrap(cx), wrap(cy)}, {float(s - 28.0 * cx), float(t - cy)}};
}

}  // namespace hexc
