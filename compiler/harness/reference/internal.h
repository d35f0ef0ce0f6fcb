#pragma once
// What the oracle's files share (reference.cpp, lattice.cpp, texture.cpp), not part of reference.h: linear
// interpolation and the masks' taps.
#include <array>

#include "reference/reference.h"

namespace hexc::reference {

// a + (b - a) * t rather than a * (1 - t) + b * t: returns a exactly when a == b, so constant textures and
// constant mip levels filter to exactly their value.
inline double lerp(double a, double b, double t) { return a + (b - a) * t; }

inline Rgba lerp(const Rgba& a, const Rgba& b, double t) {
    return {lerp(a[0], b[0], t), lerp(a[1], b[1], t), lerp(a[2], b[2], t), lerp(a[3], b[3], t)};
}

// What a mask decides at st (docs/material-format.md#mask): three tiles, tile i sampled at
// toTile(local[i]) / scale + shift[i] + offset with its own transform, and their weights before Eq. 1. The
// checker repeats its second tile, with weight 0, as the third.
struct Taps {
    std::array<TileId, 3> id;
    std::array<Vec2, 3> local;     // st relative to the point c the tile turns and scales about
    std::array<Vec2, 3> shift;     // c, added back after the transform: the paper's as is (Listing 3), else modulo 1
    std::array<double, 3> weight;  // the mask's weights
};

// The taps of hex.mask at st: the hex lattice's triangle, the checker's two grids, or the noise masks' three copies;
// `repeats` > 0: the hex and checker masks' periodic lattices over that many units of st (stable mode).
Taps maskTaps(Vec2 st, const HexTiling& hex, int repeats = 0);

}  // namespace hexc::reference
