#pragma once
// The texture checks' measures one by one (textures/lint.cpp), for measureTexture and the benchmark that times each.
#include <array>
#include <vector>

#include "hexc/lint.h"

namespace hexc::lint {

// A normal map's slopes (dh/dx, dh/dy) per texel, y down the rows.
using Slopes = std::vector<std::array<float, 2>>;
Slopes slopes(const Texture& t, bool flipY, int channels);
// The slopes' derivatives (dq/dx, dp/dy, dp/dx, dq/dy) at texel (x, y), by central differences on the wrap-around
// grid: the curl is dq/dx - dp/dy, and with green flipped -dq/dx - dp/dy.
std::array<double, 4> derivatives(const Slopes& pq, int w, int h, int x, int y);
// The green check's figures: the normalised curl, sqrt(sum curl^2 / sum |Jacobian|^2), as declared and flipped.
void curls(const Slopes& pq, int w, int h, TextureFigures& f);
// The tilt check's figures: the mean slope and its angle.
void tilt(const Slopes& pq, TextureFigures& f);
// The seam check's figures: edge over interior difference across the left/right and top/bottom edges.
std::array<double, 2> seams(const Texture& t, const std::vector<int>& channels);

}  // namespace hexc::lint
