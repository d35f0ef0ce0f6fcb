#pragma once
// Generated textures for the texture checks' tests (lint_test.cpp): periodic height fields of several kinds, their
// normal maps in either green convention, and seamless and non-seamless colour textures.
#include <stb_easy_font.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "hexc/image.h"

namespace hexc::test {

// A height field on a w x h wrap-around grid, row-major, row 0 at the top.
struct Field {
    int w = 0, h = 0;
    std::vector<double> v;
    Field(int width, int height) : w(width), h(height), v(size_t(width) * height, 0.0) {}
    double& at(int x, int y) { return v[size_t((y % h + h) % h) * w + size_t((x % w + w) % w)]; }
    double at(int x, int y) const { return v[size_t((y % h + h) % h) * w + size_t((x % w + w) % w)]; }
};

// The shortest wrapped offset from a to b on a period.
inline double wrapped(double d, int period) { return d - period * std::round(d / period); }

// Gaussian bumps and dents of radii 2 to w/6 at random places.
inline Field bumps(int w, int h, unsigned seed, int count) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    Field f(w, h);
    for (int k = 0; k < count; ++k) {
        const double cx = u(rng) * w, cy = u(rng) * h, r = 2 + u(rng) * (w / 6.0 - 2), a = u(rng) < 0.3 ? -1 : 1;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double dx = wrapped(x - cx, w), dy = wrapped(y - cy, h);
                f.at(x, y) += a * std::exp(-(dx * dx + dy * dy) / (2 * r * r));
            }
    }
    return f;
}

// Noise of power spectrum |k|^-beta: random phases on integer frequencies up to `most` cycles, periodic by construction.
// `period`: the field repeats every period texels (> w, h: a crop of a larger periodic field, which does not tile).
inline Field spectral(int w, int h, unsigned seed, double beta, int most, int period = 0) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> phase(0, 2 * std::numbers::pi);
    Field f(w, h);
    const double pw = period ? period : w, ph = period ? period : h;
    for (int ky = -most; ky <= most; ++ky)
        for (int kx = 0; kx <= most; ++kx) {
            if (kx == 0 && ky <= 0) continue;
            const double a = std::pow(std::hypot(kx, ky), -beta / 2), p = phase(rng);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) f.at(x, y) += a * std::cos(2 * std::numbers::pi * (kx * x / pw + ky * y / ph) + p);
        }
    return f;
}

// Grooves of V section along random segments (wrapped): cracks.
inline Field cracks(int w, int h, unsigned seed, int count) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    Field f(w, h);
    for (int k = 0; k < count; ++k) {
        const double x0 = u(rng) * w, y0 = u(rng) * h, angle = u(rng) * 2 * std::numbers::pi, length = (0.2 + 0.5 * u(rng)) * w;
        const double dx = std::cos(angle), dy = std::sin(angle), width = 1.5 + 2 * u(rng);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int copy = 0; copy < 9; ++copy) {  // the segment and its eight neighbouring periods
                    const double px = x - x0 + (copy % 3 - 1) * w, py = y - y0 + (copy / 3 - 1) * h;
                    const double t = std::clamp(px * dx + py * dy, 0.0, length), d = std::hypot(px - t * dx, py - t * dy);
                    f.at(x, y) = std::min(f.at(x, y), -std::max(0.0, 1 - d / width));
                }
    }
    return f;
}

// Raised text (stb_easy_font's glyphs at scale 2, rows of `text`), softened by two wrap-around box blurs.
inline Field glyphs(int w, int h, const std::string& text) {
    Field mask(w, h);
    std::vector<char> buffer(text.size() * 300);
    std::string copy = text;
    const int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(), int(buffer.size()));
    const float* v = reinterpret_cast<const float*>(buffer.data());
    for (int q = 0; q < quads; ++q)
        for (int y = int(v[q * 16 + 1]) * 2; y < int(v[q * 16 + 9]) * 2; ++y)
            for (int x = int(v[q * 16]) * 2; x < int(v[q * 16 + 8]) * 2; ++x) mask.at(x + 2, y + 2) = 1;
    for (int pass = 0; pass < 2; ++pass) {
        Field b(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int j = -1; j <= 1; ++j)
                    for (int i = -1; i <= 1; ++i) b.at(x, y) += mask.at(x + i, y + j) / 9;
        mask = b;
    }
    return mask;
}

// Ridges along one axis: a height field whose normal map reads alike in both green conventions.
inline Field ridges(int w, int h, int cycles) {
    Field f(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) f.at(x, y) = std::sin(2 * std::numbers::pi * cycles * x / w);
    return f;
}

// The field's normal map, 8-bit, green up (or down with `flipY`): slopes by central differences (or Sobel's 3x3, as
// many bakers do), scaled so that their root mean square is `slope`; `tilt` is added to dh/dx.
inline Texture normalMap(const Field& f, double slope, bool flipY, bool sobel = false, double tilt = 0) {
    std::vector<double> gx(f.v.size()), gy(f.v.size());
    double sum = 0;
    for (int y = 0; y < f.h; ++y)
        for (int x = 0; x < f.w; ++x) {
            auto dx = [&](int row) { return (f.at(x + 1, row) - f.at(x - 1, row)) / 2; };
            auto dy = [&](int col) { return (f.at(col, y + 1) - f.at(col, y - 1)) / 2; };
            const size_t i = size_t(y) * f.w + x;
            gx[i] = sobel ? (dx(y - 1) + 2 * dx(y) + dx(y + 1)) / 4 : dx(y);
            gy[i] = sobel ? (dy(x - 1) + 2 * dy(x) + dy(x + 1)) / 4 : dy(x);  // dh/drow, down the rows
            sum += gx[i] * gx[i] + gy[i] * gy[i];
        }
    const double scale = sum > 0 ? slope / std::sqrt(sum / double(f.v.size())) : 0;
    Texture t;
    t.width = f.w, t.height = f.h;
    t.rgba8.resize(f.v.size() * 4);
    for (size_t i = 0; i < f.v.size(); ++i) {
        // Green up: +y points up the texture, so y = +dh/drow; green down, -dh/drow.
        const double p = gx[i] * scale + tilt, q = gy[i] * scale * (flipY ? -1 : 1), n = std::sqrt(p * p + q * q + 1);
        const double c[4] = {-p / n, q / n, 1 / n, 1};
        for (int k = 0; k < 4; ++k) t.rgba8[i * 4 + size_t(k)] = uint8_t(std::lround((k < 3 ? c[k] * 0.5 + 0.5 : 1) * 255));
    }
    return t;
}

// The field as an 8-bit grey texture spanning [0, 255].
inline Texture greyTexture(const Field& f) {
    double lo = 1e300, hi = -1e300;
    for (double v : f.v) lo = std::min(lo, v), hi = std::max(hi, v);
    Texture t;
    t.width = f.w, t.height = f.h;
    t.rgba8.resize(f.v.size() * 4);
    for (size_t i = 0; i < f.v.size(); ++i)
        for (int k = 0; k < 4; ++k)
            t.rgba8[i * 4 + size_t(k)] = uint8_t(k < 3 ? std::lround((f.v[i] - lo) / (hi > lo ? hi - lo : 1) * 255) : 255);
    return t;
}

}  // namespace hexc::test
