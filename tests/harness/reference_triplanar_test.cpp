// The CPU oracle's triplanar projection: each plane's evaluation, the plane weights, the surface gradient, the
// preview sphere.
#include <gtest/gtest.h>

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>

#include "harness/reference_support.h"
#include "reference/reference.h"

using namespace hexc;
using namespace hexc::reference;
using namespace hexc::reference::oracle;

namespace {

// --- Triplanar projection -----------------------------------------------------------------------------------

// The docs' planes written out: plane k samples at (P[kPlane[k][0]], P[kPlane[k][1]]) * tiling, and its derivative
// (d.x, d.y) is the world gradient with d.x on axis kPlane[k][0] and d.y on kPlane[k][1]: x (P.y, P.z) and
// (0, d.x, d.y); y (P.z, P.x) and (d.y, 0, d.x); z (P.x, P.y) and (d.x, d.y, 0).
constexpr std::array<std::array<size_t, 2>, 3> kPlane{{{1, 2}, {2, 0}, {0, 1}}};

Slot triplanarSlot(SlotKind kind, Mask mask = Mask::Hex) {
    Slot slot = maskSlot(kind, mask);
    slot.hex.projection = Projection::Triplanar;
    slot.hex.tiling = {2, 3};
    return slot;
}

std::array<double, 3> planeWeights(Vec3 n, double sharpness) {
    std::array<double, 3> b;
    for (size_t k = 0; k < 3; ++k) b[k] = std::pow(std::abs(n[k]), sharpness);
    const double sum = b[0] + b[1] + b[2];
    for (double& x : b) x /= sum;
    return b;
}

TEST(ReferenceTriplanar, AxisNormalsAreTheUvEvaluationOfTheirPlane) {
    const SampledTexture colour(floatTexture(64, 64, wave)), normalMap(loadTestTexture("rock_normal.png", false));
    std::mt19937 rng(71);
    std::uniform_real_distribution<double> coord(-3, 3), grad(-0.01, 0.01);
    for (SlotKind kind : {SlotKind::Color, SlotKind::Normal})
        for (Mask mask : {Mask::Hex, Mask::Checker}) {
            const Slot slot = triplanarSlot(kind, mask);
            const SampledTexture& tex = kind == SlotKind::Color ? colour : normalMap;
            for (int k = 0; k < 60; ++k) {
                const size_t axis = size_t(k % 3);
                const Vec3 P{coord(rng), coord(rng), coord(rng)}, dPdx{grad(rng), grad(rng), grad(rng)},
                    dPdy{grad(rng), grad(rng), grad(rng)};
                Vec3 N{0, 0, 0};
                N[axis] = k % 2 ? 2.5 : -0.5;  // any length, either side
                const auto [s, t] = kPlane[axis];
                const SlotResult r = evaluateTriplanar(slot, tex, {P, N, dPdx, dPdy}, {3, 4});
                const SlotResult e = evaluate(slot, tex, P[s], P[t], dPdx[s], dPdx[t], dPdy[s], dPdy[t], {3, 4});
                if (kind == SlotKind::Color) {
                    EXPECT_EQ(r.value, e.value);
                } else {
                    Rgba gradient{0, 0, 0, 1};
                    gradient[s] = e.value[0];
                    gradient[t] = -e.value[1];  // the derivative's y runs up the texture, along -t
                    EXPECT_EQ(r.value, gradient);
                }
                EXPECT_EQ(r.weights, e.weights);
                EXPECT_EQ(r.samples, e.samples);  // the only plane is the dominant one
                EXPECT_EQ(r.blend, e.blend);
            }
        }
}

// A linear ramp (red = s, green = t) without hex-tiling reads each plane's st back: the colour is the plane weights'
// mix of the three planes' coordinates.
TEST(ReferenceTriplanar, PlaneWeightsFollowTheNormal) {
    const SampledTexture ramp(floatTexture(256, 256, [](double s, double t) { return Rgba{s, t, 0, 1}; }));
    Slot slot = triplanarSlot(SlotKind::Color);
    slot.hex.enabled = false;
    slot.hex.tiling = {1, 1};
    std::mt19937 rng(73);
    std::uniform_real_distribution<double> inside(0.1, 0.9), direction(-1, 1);
    for (double sharpness : {1.0, 4.0, 9.5}) {
        slot.hex.planeSharpness = sharpness;
        for (int k = 0; k < 200; ++k) {
            const Vec3 P{inside(rng), inside(rng), inside(rng)}, N{direction(rng), direction(rng), direction(rng)};
            const double length = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
            const std::array<double, 3> b = planeWeights({N[0] / length, N[1] / length, N[2] / length}, sharpness);
            const SlotResult r = evaluateTriplanar(slot, ramp, {P, N, {1e-6, 0, 0}, {0, 1e-6, 0}});
            double red = 0, green = 0;
            for (size_t p = 0; p < 3; ++p) {
                red += b[p] * P[kPlane[p][0]];
                green += b[p] * P[kPlane[p][1]];
            }
            EXPECT_NEAR(r.value[0], red, 1e-6);
            EXPECT_NEAR(r.value[1], green, 1e-6);
            EXPECT_NEAR(r.value[3], 1, 1e-12);  // the plane weights sum to 1
            EXPECT_NEAR(r.weights[0], 1, 1e-12);
        }
    }
    // A zero normal weighs the planes equally.
    const Vec3 P{0.2, 0.3, 0.7};
    const SlotResult r = evaluateTriplanar(slot, ramp, {P, {0, 0, 0}, {1e-6, 0, 0}, {0, 1e-6, 0}});
    EXPECT_NEAR(r.value[0], (0.3 + 0.7 + 0.2) / 3, 1e-6);
    EXPECT_NEAR(r.value[1], (0.7 + 0.2 + 0.3) / 3, 1e-6);
}

// The surface gradient of the planes' world gradients: tangent to the surface, and the plane gradients as written.
TEST(ReferenceTriplanar, SurfaceGradientIsTangentToTheSurface) {
    const SampledTexture tex(loadTestTexture("rock_normal.png", false));
    for (Mask mask : {Mask::Hex, Mask::Noise}) {
        const Slot slot = triplanarSlot(SlotKind::Normal, mask);
        std::mt19937 rng(79);
        std::uniform_real_distribution<double> coord(-2, 2), direction(-1, 1), grad(-1e-3, 1e-3);
        for (int k = 0; k < 200; ++k) {
            const Vec3 P{coord(rng), coord(rng), coord(rng)}, N{direction(rng), direction(rng), direction(rng)};
            const Vec3 dPdx{grad(rng), grad(rng), grad(rng)}, dPdy{grad(rng), grad(rng), grad(rng)};
            const SlotResult r = evaluateTriplanar(slot, tex, {P, N, dPdx, dPdy});
            const double length = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
            const Vec3 n{N[0] / length, N[1] / length, N[2] / length};
            EXPECT_NEAR(r.value[0] * n[0] + r.value[1] * n[1] + r.value[2] * n[2], 0, 1e-12);
            EXPECT_EQ(r.value[3], 1);
            const std::array<double, 3> b = planeWeights(n, slot.hex.planeSharpness);
            Vec3 g{0, 0, 0};
            for (size_t p = 0; p < 3; ++p) {
                const auto [s, t] = kPlane[p];
                const SlotResult e = evaluate(slot, tex, P[s], P[t], dPdx[s], dPdx[t], dPdy[s], dPdy[t]);
                g[s] += b[p] * e.value[0];
                g[t] -= b[p] * e.value[1];
            }
            const double along = g[0] * n[0] + g[1] * n[1] + g[2] * n[2];
            for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(r.value[c], g[c] - along * n[c], 1e-12);
        }
    }
}

// The planes' weights and gradients do not see the normal's sign: the face opposite shows the same (mirrored) texture.
TEST(ReferenceTriplanar, OppositeFacesMatch) {
    const SampledTexture albedo(loadTestTexture("rock_albedo.png", true)), normalMap(loadTestTexture("rock_normal.png", false));
    std::mt19937 rng(83);
    std::uniform_real_distribution<double> coord(-2, 2), direction(-1, 1);
    for (SlotKind kind : {SlotKind::Color, SlotKind::Normal}) {
        const Slot slot = triplanarSlot(kind, Mask::Checker);
        const SampledTexture& tex = kind == SlotKind::Color ? albedo : normalMap;
        for (int k = 0; k < 100; ++k) {
            const Vec3 P{coord(rng), coord(rng), coord(rng)};
            const Vec3 N = k < 10 ? Vec3{0, 0, 1} : Vec3{direction(rng), direction(rng), direction(rng)};
            const SurfacePoint front{P, N, {0.01, 0, 0}, {0, 0.01, 0}}, back{P, {-N[0], -N[1], -N[2]}, front.dPdx, front.dPdy};
            const SlotResult a = evaluateTriplanar(slot, tex, front), b = evaluateTriplanar(slot, tex, back);
            EXPECT_EQ(a.value, b.value);
            EXPECT_EQ(a.weights, b.weights);
        }
    }
}

TEST(ReferenceTriplanar, PreviewSphereIsTheUnitSphereWithItsGradients) {
    const auto near = [](const Vec3& a, const Vec3& b, double tolerance) {
        for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], tolerance);
    };
    // u = 0, v = 0 faces +z; u = pi/2 turns to +x; v = pi/2 is the north pole, +y.
    near(previewSphere(0, 0, 0, 0, 0, 0).position, {0, 0, 1}, 1e-15);
    near(previewSphere(kPi / 2, 0, 0, 0, 0, 0).position, {1, 0, 0}, 1e-15);
    near(previewSphere(0.7, kPi / 2, 0, 0, 0, 0).position, {0, 1, 0}, 1e-15);
    std::mt19937 rng(89);
    std::uniform_real_distribution<double> angle(-3, 3), grad(-0.1, 0.1);
    for (int k = 0; k < 200; ++k) {
        const double u = angle(rng), v = angle(rng) / 2, dudx = grad(rng), dvdx = grad(rng), dudy = grad(rng), dvdy = grad(rng);
        const SurfacePoint p = previewSphere(u, v, dudx, dvdx, dudy, dvdy);
        EXPECT_NEAR(p.position[0] * p.position[0] + p.position[1] * p.position[1] + p.position[2] * p.position[2], 1, 1e-15);
        EXPECT_EQ(p.normal, p.position);
        near(p.position, {std::cos(v) * std::sin(u), std::sin(v), std::cos(v) * std::cos(u)}, 1e-15);
        // Central differences along the screen directions.
        const double h = 1e-5;
        const auto diff = [&](double du, double dv) {
            const Vec3 a = previewSphere(u + h * du, v + h * dv, 0, 0, 0, 0).position,
                       b = previewSphere(u - h * du, v - h * dv, 0, 0, 0, 0).position;
            return Vec3{(a[0] - b[0]) / (2 * h), (a[1] - b[1]) / (2 * h), (a[2] - b[2]) / (2 * h)};
        };
        near(p.dPdx, diff(dudx, dvdx), 1e-9);
        near(p.dPdy, diff(dudy, dvdy), 1e-9);
    }
}

TEST(ReferenceTriplanar, ViewEvaluatesThePreviewSphereAtEachPixel) {
    const SampledTexture tex(floatTexture(64, 64, wave));
    Slot slot = triplanarSlot(SlotKind::Color, Mask::Checker);
    slot.hex.taps = 1;  // the dither sees the pixel
    const View view{6, 4, {-3, -1.4, 3, 1.4}};
    const std::vector<SlotResult> results = evaluateView(slot, tex, view);
    const Image weights = render(slot, tex, view, Output::Weights);
    ASSERT_EQ(results.size(), 24u);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 6; ++i) {
            const double u = -3 + (i + 0.5) / 6 * 6, v = -1.4 + (j + 0.5) / 4 * 2.8;
            const SlotResult e = evaluateTriplanar(slot, tex, previewSphere(u, v, 1, 0, 0, 0.7), {uint32_t(i), uint32_t(j)});
            EXPECT_EQ(results[size_t(j * 6 + i)].value, e.value);
            for (size_t c = 0; c < 3; ++c) EXPECT_EQ(weights.at(i, j)[c], float(e.weights[c]));
        }
}

}  // namespace
