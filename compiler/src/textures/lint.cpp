// Texture checks (hexc/lint.h, docs/lint.md): a normal map's green convention and tilt, and whether a texture tiles,
// measured on the wrap-around grid hex-tiling samples.
#include "hexc/lint.h"

#include "textures/lint_measures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

namespace hexc {
namespace lint {
namespace {

// A texel's stored channel value (8-bit as a fraction of 255), as the checks compare them.
float channelAt(const Texture& t, size_t texel, int c) {
    return t.isFloat() ? t.rgba32f[texel * 4 + size_t(c)] : float(t.rgba8[texel * 4 + size_t(c)]) * (1.0f / 255.0f);
}

// The channels a slot of `kind` reads: a normal map's x, y and z, a scalar's one, a colour's RGB.
std::vector<int> readChannels(SlotKind kind, int channel) {
    if (kindRow(kind).oneChannel) return {channel};
    return {0, 1, 2};
}

void countNonFinite(const Texture& t, const std::vector<int>& channels, TextureFigures& f) {
    for (size_t i = 0; i < size_t(t.width) * t.height; ++i)
        for (int c : channels)
            if (!std::isfinite(channelAt(t, i, c))) {
                if (f.nonFinite++ == 0) f.firstNonFinite = {int(i % size_t(t.width)), int(i / size_t(t.width))};
                break;
            }
}

}  // namespace

// A normal map's slopes (dh/dx, dh/dy) with y down the rows, per texel. A normal of z near 0 would give an unbounded
// slope: z is kept at 0.1 or more (slopes up to 10, 84 degrees), so one bad texel cannot outweigh the map.
Slopes slopes(const Texture& t, bool flipY, int channels) {
    Slopes out(size_t(t.width) * t.height);
    for (size_t i = 0; i < out.size(); ++i) {
        const float x = 2 * channelAt(t, i, 0) - 1, y = 2 * channelAt(t, i, 1) - 1;
        float z = channels >= 3 ? 2 * channelAt(t, i, 2) - 1 : std::sqrt(std::max(0.0f, 1 - x * x - y * y));
        z = std::max(z, 0.1f);
        // Green up (OpenGL): +y points up the texture, against the rows, so dh/dy(down) = +y/z; green down, -y/z.
        out[i] = {-x / z, (flipY ? -y : y) / z};
    }
    return out;
}

std::array<double, 4> derivatives(const Slopes& pq, int w, int h, int x, int y) {
    const size_t row = size_t(y) * w, up = size_t(y == 0 ? h - 1 : y - 1) * w + x, down = size_t(y == h - 1 ? 0 : y + 1) * w + x;
    const size_t left = row + size_t(x == 0 ? w - 1 : x - 1), right = row + size_t(x == w - 1 ? 0 : x + 1);
    return {0.5 * (pq[right][1] - pq[left][1]), 0.5 * (pq[down][0] - pq[up][0]), 0.5 * (pq[right][0] - pq[left][0]),
            0.5 * (pq[down][1] - pq[up][1])};
}

// Flipping green negates dq/dx and keeps the Jacobian's norm, so one pass gives both conventions' curls:
// curl = s dq/dx - dp/dy, sum curl^2 = sum a^2 + b^2 - 2 s a b.
void curls(const Slopes& pq, int w, int h, TextureFigures& f) {
    double aa = 0, bb = 0, ab = 0, jacobian = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const auto [a, b, c, d] = derivatives(pq, w, h, x, y);
            aa += a * a, bb += b * b, ab += a * b, jacobian += a * a + b * b + c * c + d * d;
        }
    const double norm = jacobian > 0 ? jacobian : 1;
    f.curlDeclared = std::sqrt(std::max(0.0, aa + bb - 2 * ab) / norm);
    f.curlOther = std::sqrt(std::max(0.0, aa + bb + 2 * ab) / norm);
}

// The average slope, whose lean a tileable height field never has (its slopes sum to 0 around the wrap).
void tilt(const Slopes& pq, TextureFigures& f) {
    double p = 0, q = 0;
    for (const auto& s : pq) p += s[0], q += s[1];
    f.meanSlope = {p / double(pq.size()), q / double(pq.size())};
    f.tiltDegrees = std::atan(std::hypot(f.meanSlope[0], f.meanSlope[1])) * 180 / std::numbers::pi;
}

namespace {

// The wrap-around edge's difference (the last of `sums`) over the median of the eight boundaries nearest it, four
// each side (fewer in a texture under 9 texels across). Near, not all: a texture's detail varies across it (the
// rock's is denser near its edges), and a seam is a step against its own surroundings. Half an 8-bit step is added
// to both, so that a flat texture and an invisible seam read 1.
double seamRatio(const std::vector<double>& sums, double count) {
    const int n = int(sums.size());
    std::set<int> boundaries;  // the interior ones, 0 to n - 2
    for (int d = 1; d <= 4; ++d)
        for (int i : {n - 1 - d, d - 1})
            if (i >= 0 && i <= n - 2) boundaries.insert(i);
    std::vector<double> near;
    for (int i : boundaries) near.push_back(sums[size_t(i)]);
    std::sort(near.begin(), near.end());
    const double eps = 0.5 / 255;
    return (sums.back() / count + eps) / (near[near.size() / 2] / count + eps);
}

}  // namespace

// The mean difference of neighbouring texels across each column boundary (x | x+1, the last the wrap) and row
// boundary, over the read channels, as ratios of edge to interior.
std::array<double, 2> seams(const Texture& t, const std::vector<int>& channels) {
    const int w = t.width, h = t.height;
    std::vector<double> columns(size_t(w), 0), rows(size_t(h), 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x, right = size_t(y) * w + (x + 1) % w, down = size_t((y + 1) % h) * w + x;
            for (int c : channels) {
                const float v = channelAt(t, i, c);
                columns[size_t(x)] += std::abs(channelAt(t, right, c) - v);
                rows[size_t(y)] += std::abs(channelAt(t, down, c) - v);
            }
        }
    const double n = double(channels.size());
    return {seamRatio(columns, h * n), seamRatio(rows, w * n)};
}

}  // namespace lint

namespace {

using namespace lint;

std::string size(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

}  // namespace

std::string figure(double v, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", digits, v);
    return text;
}

TextureFigures measureTexture(const Texture& texture, SlotKind kind, int channel, bool flipY, int channels) {
    TextureFigures f;
    f.width = texture.width, f.height = texture.height;
    if (std::min(f.width, f.height) < LintLimits::kMinSide) {
        f.skipped = size(f.width, f.height) + " is too small to check (the checks need at least " +
                    size(LintLimits::kMinSide, LintLimits::kMinSide) + " texels)";
        return f;
    }
    countNonFinite(texture, readChannels(kind, channel), f);
    if (f.nonFinite > 0) return f;
    if (kindRow(kind).derivative) {
        const Slopes pq = slopes(texture, flipY, channels);
        curls(pq, f.width, f.height, f);
        tilt(pq, f);
        f.seam = seams(texture, {0, 1});  // a normal map's z follows from x and y
    } else {
        f.seam = seams(texture, readChannels(kind, channel));
    }
    return f;
}

TextureFigures measureSlot(const Slot& slot) {
    TextureFigures f;
    f.width = slot.width, f.height = slot.height;
    if (!slot.file) {
        f.skipped = "its texture was not read";
    } else if (int64_t(slot.width) * slot.height > kLintBudget.texels()) {
        f.skipped = size(slot.width, slot.height) + " is more than " + kLintBudget.what + " take: " + kLintBudget.text();
    } else {
        try {
            return measureTexture(decodeTexture(*slot.file, false, slot.textureLayer), slot.kind, slot.channel, slot.flipY,
                                  int(slot.file->info.channelNames.size()));
        } catch (const TextureError& e) {
            f.skipped = std::string("it does not decode: ") + e.what();
        }
    }
    return f;
}

namespace {

// The green check's warning: the declared convention curls clearly more than the other (docs/lint.md#green).
std::optional<Diagnostic> greenWarning(const Slot& slot, const TextureFigures& f, const SourceLoc& at, const std::string& path) {
    if (!f.curlDeclared || *f.curlDeclared < LintLimits::kCurlFloor || *f.curlDeclared < LintLimits::kCurlRatio * *f.curlOther)
        return std::nullopt;
    const char* declared = slot.flipY ? "green down (DirectX, flip_y)" : "green up (OpenGL)";
    const char* other = slot.flipY ? "green up (OpenGL)" : "green down (DirectX)";
    return Diagnostic::make(Code::NormalGreen, at, path,
                            "`" + slot.texture + "` reads as a " + other + " normal map, declared " + declared + ": its slopes curl " +
                                figure(*f.curlDeclared, 3) + " as declared and " + figure(*f.curlOther, 3) +
                                " the other way (a height field's slopes do not curl; warned over " + figure(LintLimits::kCurlRatio, 1) +
                                " times the other and " + figure(LintLimits::kCurlFloor, 2) + ")",
                            slot.flipY ? "remove `flip_y`, or flip the texture's green channel"
                                       : "set `\"flip_y\": true`, or flip the texture's green channel");
}

std::optional<Diagnostic> tiltWarning(const Slot& slot, const TextureFigures& f, const SourceLoc& at, const std::string& path) {
    if (!f.tiltDegrees || *f.tiltDegrees <= LintLimits::kTiltDegrees) return std::nullopt;
    return Diagnostic::make(Code::NormalTilt, at, path,
                            "`" + slot.texture + "`'s average normal leans " + figure(*f.tiltDegrees, 1) + " degrees (over " +
                                figure(LintLimits::kTiltDegrees, 0) + "): mean slope (dh/dx, dh/dy) = (" + figure(f.meanSlope[0], 3) +
                                ", " + figure(f.meanSlope[1], 3) + "), y down the rows; every rotated tile leans another way",
                            "re-centre it: subtract the mean slope from every texel's slope (-x/z, -y/z), or bake it from a height "
                            "field with no overall slope");
}

std::optional<Diagnostic> seamWarning(const Slot& slot, const TextureFigures& f, const SourceLoc& at, const std::string& path) {
    if (!f.seam || std::max((*f.seam)[0], (*f.seam)[1]) <= LintLimits::kSeamRatio) return std::nullopt;
    return Diagnostic::make(Code::TextureSeam, at, path,
                            "`" + slot.texture + "` does not tile: across its wrap-around edges neighbouring texels differ " +
                                figure((*f.seam)[0], 1) + " (left/right) and " + figure((*f.seam)[1], 1) +
                                " (top/bottom) times as much as inside it (over " + figure(LintLimits::kSeamRatio, 1) +
                                "); hex-tiling samples it with wrap-around, so the seam shows in every tile",
                            "make it seamless, e.g. offset it by half its size and paint out the cross");
}

}  // namespace

Diagnostics lintWarnings(const Slot& slot, const TextureFigures& f, const SourceLoc& at, const std::string& path) {
    if (f.nonFinite > 0)
        return {Diagnostic::make(Code::TextureNotFinite, at, path,
                                 "`" + slot.texture + "` has " + std::to_string(f.nonFinite) +
                                     " texels that are not finite (NaN or infinity), the first at (" + std::to_string(f.firstNonFinite[0]) +
                                     ", " + std::to_string(f.firstNonFinite[1]) +
                                     "): filtering spreads them into their neighbours; its other checks are not run")};
    auto skipped = [&](const char* check) { return std::find(slot.lintSkip.begin(), slot.lintSkip.end(), check) != slot.lintSkip.end(); };
    Diagnostics out;
    const std::pair<const char*, std::optional<Diagnostic>> checks[] = {
        {"green", greenWarning(slot, f, at, path)}, {"tilt", tiltWarning(slot, f, at, path)}, {"seam", seamWarning(slot, f, at, path)}};
    for (const auto& [name, d] : checks)
        if (d && !skipped(name)) out.push_back(*d);
    return out;
}

Diagnostics lintMaterial(const Material& material) {
    Diagnostics out;
    std::vector<bool> splat(material.slots.size(), false);  // a splat map covers the terrain once: it is not tiled
    for (size_t k = 0; material.layers && k < material.layers->splats.size(); ++k) splat[material.layers->splats[k]] = true;
    for (const Slot& s : material.slots)
        if (!splat[size_t(&s - material.slots.data())])
            for (Diagnostic& d :
                 lintWarnings(s, measureSlot(s), {material.sourceFile.string(), s.line, s.col}, texturePointer(material, s)))
                out.push_back(std::move(d));
    return out;
}

}  // namespace hexc
