// hexc-bench-shaders [RESULTS_DIR]: run time against error of hex-tiling methods, on Mesa lavapipe.
//
// One representative material (albedo + normal map + roughness, 512x512 textures, template `lit`) is compiled
// once per method (a row of methods(): how the method is written in the material JSON) and rendered at
// 1024x1024 in a magnified and a minified view. Per method and view: median GPU time per frame and its ratio
// to plain tiling, texture samples and SPIR-V size, the albedo's error against the fp64 reference of the
// full-quality method, and how much of the texture's contrast survives the blend. Then op costs: what one pow,
// sin, texture sample... costs on this device, from the templates in bench/op-cost/, to say where the time of
// the full-quality shader goes.
//
// Writes RESULTS_DIR (default build/bench-results): results.csv, results.md, runtime-vs-error.svg and, under
// materials/, the textures and material files it measured (each renders with `hexc render`). Run it from the
// source root. It measures, it does not judge: targets are reported as met or not, and the exit code is 0
// whatever the numbers (1 only when it cannot run at all).
#include <stb_image_resize.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <future>
#include <iostream>
#include <limits>
#include <map>
#include <optional>

#include "hexc/compiler.h"
#include "hexc/material.h"
#include "machine.h"
#include "measures.h"
#include "plot.h"
#include "reference/layers.h"
#include "reference/reference.h"
#include "hexc/spirv.h"
#include "strf.h"
#include "vk/precision.h"
#include "vk/render.h"

namespace hexc::bench {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kTextureSize = 512;
constexpr int kFrameSize = 1024;
// Interleaved rounds: at least kRounds, repeated (up to kMaxRounds) until the full-quality rows' ratios to the paper
// listing and to plain tiling vary by at most kStableSpread between rounds.
constexpr int kRounds = 3, kMaxRounds = 8, kFramesPerRound = 5;
constexpr double kStableSpread = 0.05;              // (max - min) / median of a ratio's per-round values
const std::string kMinimal = "bench/minimal.glsl";  // the minimal shading template
constexpr double kTiling = 4;
// Run-time targets: a row's median time over plain tiling's in the same view, at most `limit`.
struct RatioTarget {
    const char* what;
    const char* row;
    double limit;
};
const RatioTarget kRatioTargets[] = {
    {"full quality, 3 slots", "stable-rot-gain", 3.2},
    {"full quality, one level of detail per slot", "stable-rot-gain-lod", 3.2},
    {"1 tap", "stable-rot-gain-1tap", 1.3},
    {"1 tap, one level of detail per slot", "stable-rot-gain-1tap-lod", 1.3},
};
// Adaptive taps on the full-quality material (issue 17): fetches per slot per pixel, and the albedo's largest change
// against exact 3-tap.
constexpr double kTargetFetches = 1.4, kTargetAdaptiveError = 1.0 / 255;
constexpr double kPackedTarget = 1.5;  // the paper listing's time over full quality's with the roughness packed
const char* const kPackedRows[] = {"stable-rot-gain-packed", "stable-rot-gain-packed-lod"};

// A method is what a user writes in the material's "hextiling" object (on top of "tiling": kTiling), applied
// to every slot. "rot": rotation on (1) instead of off (0); "gain": falloff 0.75 (the paper's choice for
// colour) instead of 0.5 (the gain's identity).
struct Method {
    std::string name;
    json hextiling;
    CompileOptions compile = {};            // how hexc compiles it: specialised and with a shared lattice by default
    json colourAndNormal = json::object();  // slot keys added to the albedo and normal slots (height_blend)
    std::string templ = "lit";              // a path (from the source root) for a bench template
    json top = json::object();              // material keys besides hextiling ("pack")
};

json with(json settings, const json& more) {
    settings.update(more);
    return settings;
}

CompileOptions withOption(bool CompileOptions::*option, bool value) {
    CompileOptions o;
    o.*option = value;
    return o;
}

// The best the material JSON can express in a hash mode: rotation and gain on.
json fullQuality(HashMode mode) { return {{"mode", toString(mode)}, {"rotation", 1}, {"falloff", 0.75}}; }

// A function, not a global: fullQuality() needs libhexc's globals, which may not be initialised before ours.
const std::vector<Method>& methods() {
    static const std::vector<Method> table = {
        {"plain", {{"enabled", false}}},
        {"paper", {{"mode", "paper"}, {"rotation", 0}, {"falloff", 0.5}}},
        {"paper-rot", {{"mode", "paper"}, {"rotation", 1}, {"falloff", 0.5}}},
        {"paper-gain", {{"mode", "paper"}, {"rotation", 0}, {"falloff", 0.75}}},
        {"paper-rot-gain", fullQuality(HashMode::Paper)},
        {"stable", {{"mode", "stable"}, {"rotation", 0}, {"falloff", 0.5}}},
        {"stable-rot", {{"mode", "stable"}, {"rotation", 1}, {"falloff", 0.5}}},
        {"stable-gain", {{"mode", "stable"}, {"rotation", 0}, {"falloff", 0.75}}},
        {"stable-rot-gain", fullQuality(HashMode::Stable)},
        // What the compiler's skipping buys, on the full-quality material: every feature emitted with the
        // uniforms deciding (--no-specialise), one lattice per slot (--no-shared-lattice), settings baked.
        {"stable-rot-gain-general", fullQuality(HashMode::Stable), withOption(&CompileOptions::specialise, false)},
        {"stable-rot-gain-per-slot", fullQuality(HashMode::Stable), withOption(&CompileOptions::shareLattice, false)},
        {"stable-rot-gain-baked", fullQuality(HashMode::Stable), withOption(&CompileOptions::bake, true)},
        // Every fetch at one level of detail per slot (textureLod) instead of each tile's gradients.
        {"stable-rot-gain-lod", with(fullQuality(HashMode::Stable), {{"lod", "shared"}})},
        // Full quality with channel packing: the roughness in the albedo's alpha, one set of fetches for both.
        {"stable-rot-gain-packed", fullQuality(HashMode::Stable), {}, json::object(), "lit", {{"pack", true}}},
        // Both savings: the packed fetches at one level of detail per slot.
        {"stable-rot-gain-packed-lod",
         with(fullQuality(HashMode::Stable), {{"lod", "shared"}}),
         {},
         json::object(),
         "lit",
         {{"pack", true}}},
        // The seeds' variants.
        {"stable-rot-gain-1tap", {{"mode", "stable"}, {"rotation", 1}, {"falloff", 0.75}, {"taps", 1}}},
        {"stable-rot-gain-1tap-lod", {{"mode", "stable"}, {"rotation", 1}, {"falloff", 0.75}, {"taps", 1}, {"lod", "shared"}}},
        // Each tap fetched only where its weight bound can move the result by 1/255 (docs/material-format.md#taps).
        {"stable-rot-gain-adaptive", with(fullQuality(HashMode::Stable), {{"taps", "adaptive"}})},
        {"stable-rot-gain-checker", with(fullQuality(HashMode::Stable), {{"mask", "checker"}})},
        {"stable-rot-gain-noise", with(fullQuality(HashMode::Stable), {{"mask", "noise"}, {"maskscale", 4}})},
        {"stable-rot-gain-noise3", with(fullQuality(HashMode::Stable), {{"mask", "noise3"}, {"maskscale", 4}})},
        // The tiles almost without a blend (exponent 64: borders a few pixels wide; no falloff metric): the contrast the
        // tiles' own sampling keeps in these views, which the blends below lose more or less of.
        {"stable-rot-unblended", {{"mode", "stable"}, {"rotation", 1}, {"falloff", 0.5}, {"exponent", 64}, {"falloffcontrast", 0}}},
        // Heitz and Neyret's histogram-preserving blend on the albedo and roughness (the normal map keeps its own).
        {"stable-rot-gain-histogram", with(fullQuality(HashMode::Stable), {{"blend", "histogram"}})},
        // Albedo and normal blended by the roughness map's values as heights.
        {"stable-rot-gain-height", fullQuality(HashMode::Stable), {}, {{"height_blend", {{"slot", "roughness"}, {"width", 0.2}}}}},
        // Triplanar on the bench's plane z = 0 facing +z: one plane is evaluated, and it shows what uv hex-tiling
        // shows. The oblique template gives every pixel a normal that weighs all three planes (its error is not
        // comparable and not measured).
        {"triplanar-face-on", with(fullQuality(HashMode::Stable), {{"projection", "triplanar"}})},
        // Plain tiling and full quality under bench/minimal.glsl, where the texture work is nearly all of the frame.
        {"plain-minimal", {{"enabled", false}}, {}, json::object(), kMinimal},
        {"stable-rot-gain-minimal", fullQuality(HashMode::Stable), {}, json::object(), kMinimal},
        {"stable-rot-gain-lod-minimal", with(fullQuality(HashMode::Stable), {{"lod", "shared"}}), {}, json::object(), kMinimal},
        {"triplanar-3-planes",
         with(fullQuality(HashMode::Stable), {{"projection", "triplanar"}}),
         {},
         json::object(),
         "bench/triplanar-oblique.glsl"},
    };
    return table;
}

// Texels per pixel: 512 * 4 * 0.375 / 1024 = 0.75 (magnified: level 0 only, as in the execution tests) and
// 512 * 4 * 8 / 1024 = 16 (minified: exactly mip level 4, where lavapipe's approximate log2 is exact).
struct NamedView {
    std::string name;
    View view;
};
const std::vector<NamedView> kViews = {
    {"magnified", {kFrameSize, kFrameSize, {0, 0, 0.375, 0.375}}},
    {"minified", {kFrameSize, kFrameSize, {0, 0, 8, 8}}},
};

// The example textures, upscaled to kTextureSize so that they are the size a real material's would be.
struct SourceTexture {
    std::string slot, kind, file;
    bool srgb;
};
const std::vector<SourceTexture> kTextures = {
    {"albedo", "color", "rock_albedo.png", true},
    {"normal", "normal", "rock_normal.png", false},
    {"roughness", "scalar", "rock_roughness.png", false},
};

// What one operation costs, measured with bench/op-cost/<name>.glsl against baseline.glsl, and which of the
// shader's SPIR-V instructions it prices (exp and log are exp2 and log2 with a scale; a normalisation is one
// inverse square root). No instructions: texture samples.
struct OpCost {
    std::string name;
    int perPixel;  // operations the template adds per pixel
    std::vector<std::string> spirvOps;
};
const std::vector<OpCost> kOpCosts = {
    {"sample", 16, {}},
    {"pow", 64, {"Pow"}},
    {"exp2", 64, {"Exp2", "Exp"}},
    {"log2", 64, {"Log2", "Log"}},
    {"sin", 64, {"Sin"}},
    {"cos", 64, {"Cos"}},
    {"sqrt", 64, {"Sqrt", "InverseSqrt", "Normalize", "Length", "Distance"}},
};

// Shown in the op-count table: the GLSL.std.450 instructions that cost more than a multiply on a CPU.
const std::vector<std::string> kTranscendentals = {"Pow", "Exp",  "Exp2", "Log",         "Log2",      "Sin",    "Cos",
                                                   "Tan", "Atan", "Sqrt", "InverseSqrt", "Normalize", "Length", "Distance"};

// A shader timed on one view. Timings interleave: each round times every shader once, so a burst of load from
// elsewhere on the machine lands on all of them rather than on one.
struct Timed {
    std::string name;  // the method, or the op-cost template
    size_t view = 0;
    Material material;
    std::vector<double> frameMs;  // from every round
    std::string failure;          // why there are no numbers
    CompileOptions compile = {};  // how the shader is compiled
    std::vector<uint32_t> spirv;  // a hand-written shader drawn on the material's textures instead of its own
    std::optional<View> over;     // drawn over this view instead of kViews[view] (the terrain table's)
};

struct Row : Timed {
    const Method* method = nullptr;  // the row of methods() whose name this is
    double medianMs = kNaN, ratio = kNaN;
    ShaderOps ops;
    HashMode errorReference = HashMode::Stable;
    ErrorStats error{kNaN, kNaN, kNaN};
    Contrast contrast{kNaN, kNaN};
    // Adaptive taps: fetches per slot per pixel (taps of non-zero weight in the weights output, which shows a skipped
    // tap as exactly 0), and the albedo's error against the full-quality row's on the GPU (exact 3-tap).
    double fetches = kNaN;
    ErrorStats againstThreeTaps{kNaN, kNaN, kNaN};
};

// A row's contrast in its view moved by (shift, shift) uv.
struct Shifted {
    const Row* row;
    double shift;
    Contrast contrast;
};

struct Results {
    std::string machine, settings;
    std::vector<Row> rows;
    std::vector<Shifted> shifted;  // contrast at other places (shiftedContrast)
    std::vector<Timed> opTimings;  // bench/op-cost/<name>.glsl
    std::vector<Timed> listing;    // bench/paper-listing.glsl, per view, with `lit`'s and the minimal shading
    int rounds = 0;                // timing rounds run
    std::string terrain;           // the terrain section (terrainSection)
    double referenceSeconds = 0, totalSeconds = 0;
};

double median(std::vector<double> v) {
    if (v.empty()) return kNaN;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

// A number for a table: "n/a" when it could not be measured.
std::string num(double v, const char* format = "%.3g") {
    if (std::isnan(v)) return "n/a";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return strf(format, v);
}

void writeFile(const fs::path& file, const std::string& contents) {
    std::ofstream out(file, std::ios::binary);
    out << contents;
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

// Upscales each example texture with wrap-around edges (so it still tiles), sRGB-aware for colour.
void makeTextures(const fs::path& dir) {
    fs::create_directories(dir);
    for (const SourceTexture& t : kTextures) {
        const Texture in = loadTexture(fs::path("materials/textures") / t.file, t.srgb);
        std::vector<uint8_t> out(size_t(kTextureSize) * kTextureSize * 4);
        if (!stbir_resize_uint8_generic(in.rgba8.data(), in.width, in.height, 0, out.data(), kTextureSize, kTextureSize, 0, 4, 3, 0,
                                        STBIR_EDGE_WRAP, STBIR_FILTER_DEFAULT, t.srgb ? STBIR_COLORSPACE_SRGB : STBIR_COLORSPACE_LINEAR,
                                        nullptr))
            throw std::runtime_error("cannot resize " + t.file);
        // writeImage stores round(v * 255), which gives back every byte exactly.
        Image image{kTextureSize, kTextureSize, std::vector<float>(out.begin(), out.end())};
        for (float& v : image.rgba) v /= 255.0f;
        writeImage(image, dir / t.file);
    }
}

// The bench material with the given hex-tiling settings, written to `dir` (so `hexc render` can show it) and parsed.
Material material(const fs::path& dir, const std::string& name, const json& hextiling, const std::string& templ = "lit",
                  const json& colourAndNormal = json::object(), const json& top = json::object()) {
    json hex = {{"tiling", kTiling}};
    hex.update(hextiling);
    json doc = {{"name", name}, {"template", templ}, {"hextiling", hex}, {"slots", json::array()}};
    doc.update(top);
    for (const SourceTexture& t : kTextures) {
        json slot = {{"name", t.slot}, {"texture", "textures/" + t.file}, {"kind", t.kind}};
        if (t.kind != "scalar") slot.update(colourAndNormal);
        doc["slots"].push_back(slot);
    }
    const fs::path file = dir / (name + ".json");
    const std::string text = doc.dump(2) + "\n";  // parsed as written, so diagnostics point into the file
    writeFile(file, text);
    ParseResult parsed = parseMaterial(text, file);
    if (!parsed.material) throw CompileError{parsed.diagnostics};
    return *parsed.material;
}

const Slot& albedoSlot(const Material& m) { return vk::slotForOutput(m, vk::RenderOutput::Albedo, "albedo"); }

ShaderOps shaderOps(const Material& m, CompileOptions options) {
    options.targets = {Target::Spirv};
    CompileResult compiled = compile(m, options);
    if (!compiled.ok()) throw CompileError{compiled.diagnostics};
    return countOps(disassemble(compiled.spirv));
}

double texelsPerPixel(const View& view, int textureWidth) {
    return (view.uvRect[2] - view.uvRect[0]) * kTiling * textureWidth / view.width;
}

// The mip level a view samples: log2 of texels per pixel, as the sampler computes it for these exact powers of two.
int viewLevel(const View& view, const reference::SampledTexture& texture) {
    return std::clamp(int(std::floor(std::log2(texelsPerPixel(view, texture.width(0))))), 0, texture.levels() - 1);
}

std::vector<double> levelLuminances(const reference::SampledTexture& texture, int level) {
    std::vector<double> out;
    for (int y = 0; y < texture.height(level); ++y)
        for (int x = 0; x < texture.width(level); ++x) {
            const reference::Rgba& t = texture.texel(level, x, y);
            out.push_back(luminance(t[0], t[1], t[2]));
        }
    return out;
}

// Runs f, turning an exception into the reason a measurement is missing: one broken method must not stop the bench.
template <class F>
void attempt(std::string& failure, F f) {
    try {
        f();
    } catch (const CompileError& e) {
        failure = formatAll(e.diagnostics);
    } catch (const std::exception& e) {
        failure = e.what();
    }
}

// Median ms per frame of an op-cost template, NaN if it failed.
double opTemplateMs(const Results& results, const std::string& name, size_t view) {
    for (const Timed& t : results.opTimings)
        if (t.name == name && t.view == view) return median(t.frameMs);
    return kNaN;
}

// What one operation per pixel adds to a frame, in ms: the template's time above the baseline's, per operation.
double opCostMs(const Results& results, const OpCost& op, size_t view) {
    return (opTemplateMs(results, op.name, view) - opTemplateMs(results, "baseline", view)) / op.perPixel;
}

struct References {
    std::map<std::pair<HashMode, size_t>, Image> albedo;  // per hash mode and view
    std::vector<std::vector<double>> sourceLuminance;     // per view, at the mip level the view samples
};

// The fp64 references of the full-quality albedo in each mode and view, on all cores (the GPU is idle meanwhile).
References references(const fs::path& materialDir) {
    std::map<HashMode, Material> best;
    for (HashMode mode : {HashMode::Stable, HashMode::Paper})
        best.emplace(mode, material(materialDir, "reference-" + std::string(toString(mode)), fullQuality(mode)));
    const Slot& albedo = albedoSlot(best.at(HashMode::Stable));
    const reference::SampledTexture texture(loadTexture(albedo.texturePath, albedo.colorSpace == ColorSpace::Srgb));
    std::map<std::pair<HashMode, size_t>, std::future<Image>> pending;
    for (const auto& [mode, m] : best)
        for (size_t v = 0; v < kViews.size(); ++v)
            pending[{mode, v}] = std::async(std::launch::async, [&, v, &m = m] {
                return reference::render(albedoSlot(m), texture, kViews[v].view, reference::Output::Value);
            });
    References refs;
    for (auto& [key, f] : pending) refs.albedo[key] = f.get();
    for (const NamedView& v : kViews) refs.sourceLuminance.push_back(levelLuminances(texture, viewLevel(v.view, texture)));
    return refs;
}

// Contrast is a statistic of the view as well as of the blend: how many tiles it holds (magnified: about 25), and whether
// its pixels land on texel centres (minified: plain tiling's do at the bench's place, so its samples are unfiltered).
// The same measure with the views moved elsewhere on the plane, for plain tiling, the falloff and histogram blends and
// the unblended tiles.
const std::vector<double> kShifts = {3.1, 7.7, 12.3};
const std::vector<std::string> kShiftedMethods = {"plain", "stable-rot-gain", "stable-rot-unblended", "stable-rot-gain-histogram"};

void shiftedContrast(vk::Runner& runner, const References& refs, Results& results) {
    for (const Row& row : results.rows) {
        if (!row.failure.empty() || std::find(kShiftedMethods.begin(), kShiftedMethods.end(), row.name) == kShiftedMethods.end()) continue;
        for (double shift : kShifts) {
            View view = kViews[row.view].view;
            for (double& uv : view.uvRect) uv += shift;
            const Image image = vk::render(runner, row.material, vk::RenderOutput::Albedo, "albedo", view, vk::ExecutedTarget::Spirv, 0,
                                           nullptr, {}, row.method->compile);
            results.shifted.push_back({&row, shift, contrast(luminances(image), refs.sourceLuminance[row.view])});
        }
    }
}

// The plain or full-quality row of a view and shading (`lit`, or kMinimal).
const Row* rowOf(const Results& results, size_t view, bool fullQualityRow, const std::string& templ = "lit") {
    for (const Row& row : results.rows)
        if (row.view == view && row.method->templ == templ && row.method->compile.specialise && row.method->compile.shareLattice &&
            !row.method->compile.bake && row.method->top.empty() &&
            row.method->hextiling == (fullQualityRow ? fullQuality(HashMode::Stable) : json{{"enabled", false}}))
            return &row;
    return nullptr;
}

const Row* fullQualityRow(const Results& results, size_t view) { return rowOf(results, view, true); }

// A listing's shading, as its rows' template.
std::string shadingOf(const Timed& listing) { return listing.name.ends_with("-minimal") ? kMinimal : "lit"; }

// bench/paper-listing.glsl, the paper's listings as written, optimised like hexc's shaders; `minimal`: with the
// minimal shading.
std::vector<uint32_t> listingSpirv(bool minimal) {
    const std::string file = "bench/paper-listing.glsl";
    std::ifstream in(file, std::ios::binary);
    std::string source((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (minimal) source.insert(source.find('\n') + 1, "#define PAPER_LISTING_MINIMAL\n");
    SpirvResult front = compileToSpirv(source, ShaderStage::Fragment, file);
    if (front.words.empty()) throw CompileError{front.diagnostics};
    SpirvResult optimized = optimizeSpirv(front.words);
    if (optimized.words.empty()) throw CompileError{optimized.diagnostics};
    return optimized.words;
}

// The median of each round's frames.
std::vector<double> roundMedians(const Timed& t) {
    std::vector<double> out;
    for (size_t i = 0; i + kFramesPerRound <= t.frameMs.size(); i += kFramesPerRound)
        out.push_back(median({t.frameMs.begin() + long(i), t.frameMs.begin() + long(i + kFramesPerRound)}));
    return out;
}

// `a`'s time over `b`'s, round by round (each round runs every shader once, side by side).
std::vector<double> roundRatios(const Timed& a, const Timed& b) {
    const std::vector<double> ra = roundMedians(a), rb = roundMedians(b);
    std::vector<double> ratios;
    for (size_t i = 0; i < std::min(ra.size(), rb.size()); ++i) ratios.push_back(ra[i] / rb[i]);
    return ratios;
}

// "median (min-max)" of the per-round ratios.
std::string ratioSpread(const Timed& a, const Timed& b) {
    const std::vector<double> ratios = roundRatios(a, b);
    if (ratios.empty()) return "n/a";
    const auto [lo, hi] = std::minmax_element(ratios.begin(), ratios.end());
    return strf("%.2f (%.2f-%.2f)", median(ratios), *lo, *hi);
}

// Whether each full-quality row's ratios to its listing and its plain row vary by at most kStableSpread.
bool ratiosStable(const Results& results) {
    for (const Timed& listing : results.listing) {
        const Row* full = rowOf(results, listing.view, true, shadingOf(listing));
        const Row* plain = rowOf(results, listing.view, false, shadingOf(listing));
        if (!listing.failure.empty() || !full || !plain) continue;
        for (const std::vector<double>& r : {roundRatios(*full, listing), roundRatios(*full, *plain)}) {
            const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
            if (r.empty() || (*hi - *lo) / median(r) > kStableSpread) return false;
        }
    }
    return true;
}

// A round of `t`'s frames: its material's shader, or its hand-written one on `textures` (the material's, in slot order,
// where hexc's default layout binds them).
void timeRound(vk::Runner& runner, Timed& t, const std::vector<Texture>& textures) {
    std::vector<double> frameMs;
    if (t.spirv.empty()) {
        vk::render(runner, t.material, vk::RenderOutput::Shaded, "", t.over ? *t.over : kViews[t.view].view, vk::ExecutedTarget::Spirv,
                   kFramesPerRound, &frameMs, {}, t.compile);
    } else {
        vk::RenderRequest request;
        request.fragmentSpirv = t.spirv;
        for (const Texture& texture : textures) request.textures.push_back(&texture);
        request.timedFrames = kFramesPerRound;
        vk::renderFragment(runner, request, t.over ? *t.over : kViews[t.view].view, &frameMs);
    }
    t.frameMs.insert(t.frameMs.end(), frameMs.begin(), frameMs.end());
}

// An adaptive row: the taps each slot fetches, counted on the GPU from its weights output (a tap is fetched exactly when
// its weight is non-zero, since a fetched tap's weight is at least its lower bound, > 0 for falloffcontrast < 1), and
// the albedo against the full-quality row's (the same settings with every tap).
void measureAdaptive(vk::Runner& runner, const Results& results, Row& row) {
    const View& view = kViews[row.view].view;
    size_t fetched = 0;
    for (const Slot& slot : row.material.slots) {
        const Image w = vk::render(runner, row.material, vk::RenderOutput::Weights, slot.name, view, vk::ExecutedTarget::Spirv, 0, nullptr,
                                   {}, row.method->compile);
        for (size_t p = 0; p < w.rgba.size(); p += 4) fetched += (w.rgba[p] > 0) + (w.rgba[p + 1] > 0) + (w.rgba[p + 2] > 0);
    }
    row.fetches = double(fetched) / (double(view.width) * view.height * double(row.material.slots.size()));
    const Row* full = fullQualityRow(results, row.view);
    const auto albedo = [&](const Row& r) {
        return vk::render(runner, r.material, vk::RenderOutput::Albedo, "albedo", view, vk::ExecutedTarget::Spirv, 0, nullptr, {},
                          r.method->compile);
    };
    row.againstThreeTaps = compareRgb(albedo(row), albedo(*full));
}

// Interleaved rounds over `timed`, each shader once per round: at least kRounds, until `stable` or kMaxRounds. Returns the
// rounds run.
int timeRounds(vk::Runner& runner, const std::vector<Timed*>& timed, const std::vector<Texture>& textures,
               const std::function<bool()>& stable) {
    for (int round = 1;; ++round) {
        std::cout << "  timing round " << round << std::endl;
        for (Timed* t : timed)
            if (t->failure.empty()) attempt(t->failure, [&] { timeRound(runner, *t, textures); });
        if (round >= kMaxRounds || (round >= kRounds && stable())) return round;
    }
}

void measure(vk::Runner& runner, const fs::path& materialDir, Results& results) {
    const auto start = std::chrono::steady_clock::now();
    const References refs = references(materialDir);
    results.referenceSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    for (const Method& method : methods())
        for (size_t v = 0; v < kViews.size(); ++v) {
            Row& row = results.rows.emplace_back();
            row.name = method.name;
            row.method = &method;
            row.compile = method.compile;
            row.view = v;
            attempt(row.failure, [&] {
                const std::string templ = method.templ == "lit" ? "lit" : (fs::current_path() / method.templ).string();
                row.material = material(materialDir, method.name, method.hextiling, templ, method.colourAndNormal, method.top);
                const Slot& slot = albedoSlot(row.material);
                row.errorReference = slot.hex.enabled ? slot.hex.mode : HashMode::Stable;
                row.ops = shaderOps(row.material, method.compile);
            });
        }
    // The op-cost templates read one plain-tiled slot; the material's other slots are left out with a warning.
    std::vector<std::string> opTemplates{"baseline"};
    for (const OpCost& op : kOpCosts) opTemplates.push_back(op.name);
    for (const std::string& name : opTemplates) {
        const std::string templ = (fs::current_path() / "bench/op-cost" / (name + ".glsl")).string();
        const Material m = material(materialDir, "op-cost-" + name, {{"enabled", false}}, templ);
        for (size_t v = 0; v < kViews.size(); ++v) results.opTimings.push_back({name, v, m, {}, {}, {}, {}, {}});
    }

    // The paper's listings on the full-quality row's material (its textures; the listing has its settings built in).
    std::vector<Texture> listingTextures;
    for (bool minimal : {false, true})
        for (size_t v = 0; v < kViews.size(); ++v) {
            Timed& t = results.listing.emplace_back(Timed{minimal ? "paper-listing-minimal" : "paper-listing", v, {}, {}, {}, {}, {}, {}});
            attempt(t.failure, [&] {
                t.material = fullQualityRow(results, v)->material;
                t.spirv = listingSpirv(minimal);
                if (listingTextures.empty())
                    for (const Slot& slot : t.material.slots)
                        listingTextures.push_back(loadTexture(slot.texturePath, slot.colorSpace == ColorSpace::Srgb));
            });
        }

    std::vector<Timed*> timed;
    for (Row& row : results.rows) timed.push_back(&row);
    for (Timed& t : results.opTimings) timed.push_back(&t);
    for (Timed& t : results.listing) timed.push_back(&t);
    results.rounds = timeRounds(runner, timed, listingTextures, [&] { return ratiosStable(results); });

    std::cout << "  albedo error and contrast" << std::endl;
    for (Row& row : results.rows) {
        if (!row.failure.empty()) continue;
        row.medianMs = median(row.frameMs);
        // Triplanar renders its albedo on the preview sphere, not the uv plane the reference shows.
        if (albedoSlot(row.material).hex.projection == Projection::Triplanar) continue;
        attempt(row.failure, [&] {
            const Image image = vk::render(runner, row.material, vk::RenderOutput::Albedo, "albedo", kViews[row.view].view,
                                           vk::ExecutedTarget::Spirv, 0, nullptr, {}, row.method->compile);
            // The histogram blend makes another image than the falloff reference: the execution tests compare it with its
            // own reference (tests/execution/cases/histogram_*.json); here, its contrast.
            if (albedoSlot(row.material).hex.blend == Blend::Falloff)
                row.error = compareRgb(image, refs.albedo.at({row.errorReference, row.view}));
            row.contrast = contrast(luminances(image), refs.sourceLuminance[row.view]);
        });
    }
    std::cout << "  adaptive taps" << std::endl;
    for (Row& row : results.rows)
        if (row.failure.empty() && albedoSlot(row.material).hex.adaptive())
            attempt(row.failure, [&] { measureAdaptive(runner, results, row); });
    std::cout << "  contrast at other places" << std::endl;
    shiftedContrast(runner, refs, results);
    for (Row& row : results.rows)
        if (const Row* plain = rowOf(results, row.view, false, row.method->templ)) row.ratio = row.medianMs / plain->medianMs;
    for (const Timed* t : timed)
        if (!t->failure.empty()) std::cout << "  failed: " << t->name << ", " << kViews[t->view].name << ": " << t->failure << "\n";
}

// The reference a row's error is measured against, "n/a" when it is not.
std::string errorVs(const Row& r) { return std::isnan(r.error.max) ? "n/a" : std::string(toString(r.errorReference)); }

int opCount(const ShaderOps& ops, const std::string& name) { return ops.extended.count(name) ? ops.extended.at(name) : 0; }

// The run-time targets, a line each per view.
std::vector<std::string> targetLines(const Results& results) {
    std::vector<std::string> lines;
    for (const RatioTarget& t : kRatioTargets)
        for (size_t view = 0; view < kViews.size(); ++view) {
            double ratio = kNaN;
            for (const Row& row : results.rows)
                if (row.view == view && row.name == t.row) ratio = row.ratio;
            lines.push_back(strf("%s (%s), %s: %sx plain tiling, target <= %.1fx: %s", t.what, t.row, kViews[view].name.c_str(),
                                 num(ratio, "%.2f").c_str(), t.limit,
                                 std::isnan(ratio)  ? "not measured"
                                 : ratio <= t.limit ? "MET"
                                                    : "NOT MET"));
        }
    return lines;
}

// The adaptive row's fetches and error against the targets, and what its fetch count promises a GPU with real branches
// (lavapipe runs both sides of a branch under a mask, so its time cannot show it).
std::string adaptiveLine(const Results& results, size_t view) {
    const Row* row = nullptr;
    for (const Row& r : results.rows)
        if (r.view == view && r.name == "stable-rot-gain-adaptive") row = &r;
    const double f = row ? row->fetches : kNaN, e = row ? row->againstThreeTaps.max : kNaN;
    const auto met = [](double v, double target) { return std::isnan(v) ? "not measured" : v <= target ? "MET" : "NOT MET"; };
    return strf(
        "adaptive taps (stable-rot-gain-adaptive), %s: %s fetches per slot per pixel, target <= %.1f: %s; max error against "
        "exact 3-tap %s/255, target <= 1/255: %s; fetch-bound speed-up of the texture work on a GPU with real branches "
        "3 / %s = %sx",
        kViews[view].name.c_str(), num(f, "%.3f").c_str(), kTargetFetches, met(f, kTargetFetches), num(e * 255, "%.3f").c_str(),
        met(e, kTargetAdaptiveError), num(f, "%.3f").c_str(), num(3 / f, "%.2f").c_str());
}

// A packed row (`name`) against the paper listing under `lit`, in the same rounds: how many times faster, per-round
// median.
std::string packedTargetLine(const Results& results, size_t view, const std::string& name) {
    const Row* packed = nullptr;
    for (const Row& row : results.rows)
        if (row.view == view && row.name == name && row.failure.empty()) packed = &row;
    double speedup = kNaN;
    for (const Timed& listing : results.listing)
        if (packed && listing.view == view && listing.name == "paper-listing" && listing.failure.empty())
            speedup = median(roundRatios(listing, *packed));
    return strf(
        "full quality with the roughness packed into the albedo's alpha (%s), %s: %sx faster than the paper listing, target >= "
        "%.1fx: %s",
        name.c_str(), kViews[view].name.c_str(), num(speedup, "%.2f").c_str(), kPackedTarget,
        std::isnan(speedup)        ? "not measured"
        : speedup >= kPackedTarget ? "MET"
                                   : "NOT MET");
}

std::string mainTable(const Results& results) {
    std::string md =
        "| view | method | ms/frame (median) | x plain | samples/px | SPIR-V instr. | error vs | max err | mean err | PSNR dB | "
        "variance ratio | histogram EMD |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : results.rows)
        md += strf("| %s | %s | %s | %s | %d | %d | %s | %s | %s | %s | %s | %s |\n", kViews[r.view].name.c_str(), r.name.c_str(),
                   num(r.medianMs, "%.2f").c_str(), num(r.ratio, "%.2f").c_str(), r.ops.textureSamples, r.ops.instructions,
                   errorVs(r).c_str(), num(r.error.max, "%.4f").c_str(), num(r.error.mean, "%.5f").c_str(),
                   num(r.error.psnrDb, "%.1f").c_str(), num(r.contrast.varianceRatio, "%.3f").c_str(),
                   num(r.contrast.histogramEmd, "%.4f").c_str());
    return md;
}

// Scalar operations per pixel by instruction, one line per method (the same SPIR-V in both views).
std::string opCountTable(const Results& results) {
    std::vector<std::string> shown;
    for (const std::string& name : kTranscendentals)
        for (const Row& r : results.rows)
            if (opCount(r.ops, name) && std::find(shown.begin(), shown.end(), name) == shown.end()) shown.push_back(name);
    std::string md = "| method | samples |", rule = "|---|---|";
    for (const std::string& name : shown) md += " " + name + " |", rule += "---|";
    md += "\n" + rule + "\n";
    for (const Row& r : results.rows) {
        if (r.view != 0) continue;
        md += "| " + r.name + " | " + std::to_string(r.ops.textureSamples) + " |";
        for (const std::string& name : shown) md += " " + std::to_string(opCount(r.ops, name)) + " |";
        md += "\n";
    }
    return md;
}

// Where the full-quality shader's time goes: each op's count times its measured cost, per view; what is left is
// the work no op-cost template prices (integer hash, lattice, blend weights, lighting).
std::string breakdownTable(const Results& results) {
    std::vector<const Row*> rows;
    std::vector<double> baseline, measured, rest;
    std::string md = "| | per px | one op/px, ms/frame |", rule = "|---|---|---|";
    for (size_t v = 0; v < kViews.size(); ++v) {
        rows.push_back(fullQualityRow(results, v));
        baseline.push_back(opTemplateMs(results, "baseline", v));
        measured.push_back(rows[v] ? rows[v]->medianMs : kNaN);
        rest.push_back(measured[v] - baseline[v]);
        md += " " + kViews[v].name + " ms | share |", rule += "---|---|";
    }
    md += "\n" + rule + "\n";
    auto line = [&](const std::string& what, const std::string& count, const std::string& unit, const std::vector<double>& ms) {
        md += "| " + what + " | " + count + " | " + unit + " |";
        for (size_t v = 0; v < kViews.size(); ++v) md += " " + num(ms[v], "%.1f") + " | " + num(ms[v] / measured[v] * 100, "%.0f%%") + " |";
        md += "\n";
    };
    line("draw, 1 sample, 16 multiply-adds (baseline.glsl)", "", "", baseline);
    for (const OpCost& op : kOpCosts) {
        const ShaderOps ops = rows[0] ? rows[0]->ops : ShaderOps{};  // the same SPIR-V in every view
        int count = op.spirvOps.empty() ? ops.textureSamples : 0;
        for (const std::string& name : op.spirvOps) count += opCount(ops, name);
        std::vector<double> ms;
        std::string unit;
        for (size_t v = 0; v < kViews.size(); ++v) {
            ms.push_back(count * opCostMs(results, op, v));
            rest[v] -= ms[v];
            unit += (v ? " / " : "") + num(opCostMs(results, op, v), "%.3f");
        }
        line(op.name, std::to_string(count), unit, ms);
    }
    line("everything else (integer hash, lattice, blend weights, lighting)", "", "", rest);
    line("measured, stable-rot-gain", "", "", measured);
    return md;
}

// Variance ratio / EMD of the shifted views, beside the bench's place.
std::string shiftedTable(const Results& r) {
    std::string md = "| view | method | at the bench's place |", rule = "|---|---|---|";
    for (double shift : kShifts) md += strf(" moved by %g |", shift), rule += "---|";
    md += "\n" + rule + "\n";
    const Row* last = nullptr;
    for (const Shifted& s : r.shifted) {
        if (s.row != last)
            md += (last ? "\n" : "") + strf("| %s | %s | %s / %s |", kViews[s.row->view].name.c_str(), s.row->name.c_str(),
                                            num(s.row->contrast.varianceRatio, "%.3f").c_str(),
                                            num(s.row->contrast.histogramEmd, "%.4f").c_str());
        md += strf(" %s / %s |", num(s.contrast.varianceRatio, "%.3f").c_str(), num(s.contrast.histogramEmd, "%.4f").c_str());
        last = s.row;
    }
    return md + (last ? "\n" : "");
}

// Every method against the paper's listings as written (bench/paper-listing.glsl), in the same rounds.
std::string listingTable(const Results& results) {
    std::string md = "| view | method | x paper listing | x plain |\n|---|---|---|---|\n";
    for (const Timed& listing : results.listing) {
        const Row* plain = rowOf(results, listing.view, false, shadingOf(listing));
        if (!listing.failure.empty() || !plain) continue;
        md += strf("| %s | **%s** (%s ms) | 1 | %s |\n", kViews[listing.view].name.c_str(), listing.name.c_str(),
                   num(median(listing.frameMs), "%.2f").c_str(), ratioSpread(listing, *plain).c_str());
        for (const Row& row : results.rows)
            if (row.view == listing.view && row.failure.empty() && row.method->templ == shadingOf(listing))
                md += strf("| %s | %s | %s | %s |\n", kViews[row.view].name.c_str(), row.name.c_str(), ratioSpread(row, listing).c_str(),
                           ratioSpread(row, *plain).c_str());
    }
    return md;
}

std::string markdown(const Results& r) {
    std::string md =
        "# hexc shader benchmark\n\n" + r.machine + "\n" + r.settings + "\n## Run time, error, contrast\n\n" + mainTable(r) + "\n";
    for (const std::string& line : targetLines(r)) md += "- " + line + "\n";
    for (size_t v = 0; v < kViews.size(); ++v) md += "- " + adaptiveLine(r, v) + "\n";
    for (const char* packed : kPackedRows)
        for (size_t v = 0; v < kViews.size(); ++v) md += "- " + packedTargetLine(r, v, packed) + "\n";
    md +=
        "\n## Against the paper's listings\n\nTime over bench/paper-listing.glsl's (Listings 1-10 as written, per slot, the same "
        "material and `lit` shading) and over plain tiling's, per round: median (min-max) of the " +
        std::to_string(r.rounds) + " rounds (" + std::to_string(kRounds) + " or more, until the full-quality ratios vary by at most " +
        strf("%.0f", kStableSpread * 100) + " % between rounds, at most " + std::to_string(kMaxRounds) + ").\n\n" + listingTable(r);
    md += "\n## Contrast at other places\n\nVariance ratio / histogram EMD of the albedo with the views moved by (d, d) uv.\n\n" +
          shiftedTable(r);
    md +=
        "\n## Operations per pixel\n\nScalar operations counted in the SPIR-V (a vec3 pow counts 3; there are no loops, so each runs at "
        "most once per pixel).\n\n" +
        opCountTable(r);
    md +=
        "\n## Where the full-quality shader's time goes\n\nOne operation per pixel costs the time of its bench/op-cost/*.glsl "
        "template above baseline.glsl's, per operation (magnified / minified); times how often stable-rot-gain does it.\n\n" +
        breakdownTable(r);
    return md + "\n" + r.terrain;
}

std::string csv(const Results& r) {
    std::string out =
        "view,method,median_ms,min_ms,max_ms,frames,ratio_to_plain,samples_per_px,spirv_instructions,error_reference,max_error,mean_error,"
        "psnr_db,variance_ratio,histogram_emd,failure\n";
    for (const Row& row : r.rows) {
        std::string failure = row.failure;
        std::replace(failure.begin(), failure.end(), '\n', ' ');
        std::replace(failure.begin(), failure.end(), ',', ';');
        const auto [fastest, slowest] = std::minmax_element(row.frameMs.begin(), row.frameMs.end());
        out += strf("%s,%s,%s,%s,%s,%zu,%s,%d,%d,%s,%s,%s,%s,%s,%s,%s\n", kViews[row.view].name.c_str(), row.name.c_str(),
                    num(row.medianMs, "%.4f").c_str(), num(row.frameMs.empty() ? kNaN : *fastest, "%.4f").c_str(),
                    num(row.frameMs.empty() ? kNaN : *slowest, "%.4f").c_str(), row.frameMs.size(), num(row.ratio, "%.4f").c_str(),
                    row.ops.textureSamples, row.ops.instructions, errorVs(row).c_str(), num(row.error.max, "%.6g").c_str(),
                    num(row.error.mean, "%.6g").c_str(), num(row.error.psnrDb, "%.4g").c_str(),
                    num(row.contrast.varianceRatio, "%.6g").c_str(), num(row.contrast.histogramEmd, "%.6g").c_str(), failure.c_str());
    }
    return out;
}

std::string plot(const Results& r) {
    std::vector<std::string> series;
    for (const NamedView& v : kViews) series.push_back(v.name);
    std::vector<PlotPoint> points;
    // Only errors measured against the same (stable) reference are comparable, so only those form the front.
    for (const Row& row : r.rows) points.push_back({row.name, row.view, row.ratio, row.error.mean, row.errorReference == HashMode::Stable});
    // The listings compute what paper mode computes (PaperListing in tests/execution/library_test.cpp, to 1e-5), so their error is
    // paper-rot-gain's; their run time is their own, over plain tiling under the same shading.
    for (const Timed& listing : r.listing) {
        const Row* plain = rowOf(r, listing.view, false, shadingOf(listing));
        for (const Row& paper : r.rows)
            if (listing.failure.empty() && plain && paper.view == listing.view && paper.name == "paper-rot-gain")
                points.push_back({listing.name, listing.view, median(roundRatios(listing, *plain)), paper.error.mean, false});
    }
    return scatterSvg("hexc on lavapipe: run time against error (albedo, 1024x1024)", "run time / plain tiling (same view)",
                      "mean abs error vs full-quality fp64 reference", series, points,
                      {{kRatioTargets[0].limit, strf("target: full quality <= %gx", kRatioTargets[0].limit)}},
                      {"filled: vs stable-rot-gain reference", "hollow: paper mode, vs paper-rot-gain", "reference (hash differs from",
                       "the GPU's sin beyond the origin)"});
}

// The terrain table (issue 48): materials/terrain/ (four layers, a painted splat map, the height blend) compiled four ways
// and drawn over the whole splat map. Fetches per pixel from the manifest (worst: every layer; expected: over the splat
// map's texels), time per frame in interleaved rounds as above, and the albedo role's error against the fp64 reference
// of naive per-layer hex-tiling (every layer, every tap: the blend as the material states it).
const std::string kTerrain = "materials/terrain/terrain.json";
// 256-texel layers tiled 4 to 8 times over 512 pixels (2 to 4 texels a pixel), the 256-texel splat map at 0.5.
const View kTerrainView{512, 512, {0, 0, 1, 1}};
// The every-lever row's skip_below: a layer painted below 2/255 at a pixel is dropped; the others renormalised, the
// result moves by at most (layers - 1) * skip_below / sum of the weights (docs/material-format.md#layers).
constexpr double kLeverSkip = 2.0 / 255;
struct TerrainVariant {
    std::string name, file;
    json hextiling = json::object();   // merged into the material's "hextiling"
    json layerBlend = json::object();  // merged into its "layer_blend"
    json top = json::object();         // other material keys ("pack")
    bool skipLayers = true;            // CompileOptions::skipLayers
};
const std::vector<TerrainVariant> kTerrainVariants = {
    {"naive per-layer hex-tiling", "naive", json::object(), {{"skip_below", 0}}, json::object(), false},
    {"hexc default", "default"},
    {"hexc, every lever", "levers", {{"taps", "adaptive"}, {"lod", "shared"}}, {{"skip_below", kLeverSkip}}, {{"pack", true}}},
    {"plain tiled layers", "plain", {{"enabled", false}}},
};

struct TerrainRow : Timed {
    double worstFetches = kNaN, expectedFetches = kNaN;
    ErrorStats error{kNaN, kNaN, kNaN};
};

// The example with a variant's settings, written to `dir` with its texture paths made absolute, and parsed.
Material terrainMaterial(const fs::path& dir, const TerrainVariant& v) {
    std::ifstream in(kTerrain);
    json doc = json::parse(in);
    const fs::path from = fs::absolute(kTerrain).parent_path();
    for (json& layer : doc["layers"])
        for (json& slot : layer["slots"]) slot["texture"] = (from / slot["texture"].get<std::string>()).lexically_normal().string();
    for (json& splat : doc["layer_blend"]["splat"]) splat = (from / splat.get<std::string>()).lexically_normal().string();
    doc.erase("$schema");
    doc["name"] = "terrain-" + v.file;
    doc["hextiling"].update(v.hextiling);
    doc["layer_blend"].update(v.layerBlend);
    doc.update(v.top);
    const fs::path file = dir / ("terrain-" + v.file + ".json");
    const std::string text = doc.dump(2) + "\n";
    writeFile(file, text);
    ParseResult parsed = parseMaterial(text, file);
    if (!parsed.material) throw CompileError{parsed.diagnostics};
    return *parsed.material;
}

// The manifest's fetches per pixel (layers.fetches_per_pixel).
void manifestFetches(TerrainRow& row) {
    CompileOptions options = row.compile;
    options.targets = {Target::Spirv};
    const CompileResult compiled = compile(row.material, options);
    if (!compiled.ok()) throw CompileError{compiled.diagnostics};
    for (const OutputFile& f : compiled.files)
        if (f.name.ends_with(".manifest.json")) {
            const json fetches = json::parse(f.contents).at("layers").at("fetches_per_pixel");
            row.worstFetches = fetches.at("worst");
            row.expectedFetches = fetches.at("expected");
        }
}

// The first role (albedo) through the `value` template: on the GPU, and the fp64 reference's.
Image terrainAlbedo(vk::Runner& runner, const TerrainRow& row) {
    Material m = row.material;
    m.templ = TemplateRef::builtin("value");
    return vk::render(runner, m, vk::RenderOutput::Shaded, "", kTerrainView, vk::ExecutedTarget::Spirv, 0, nullptr, {}, row.compile);
}
Image terrainReference(const Material& m) {
    const std::vector<reference::LayerResult> ref = reference::evaluateLayersView(m, 0, reference::LayerTextures(m), kTerrainView);
    Image image{kTerrainView.width, kTerrainView.height, std::vector<float>(ref.size() * 4, 1.0f)};
    for (size_t p = 0; p < ref.size(); ++p)
        for (size_t c = 0; c < 3; ++c) image.rgba[p * 4 + c] = float(ref[p].value[c]);
    return image;
}

// Whether every terrain row's ratio to the plain row varies by at most kStableSpread between rounds.
bool terrainStable(const std::vector<TerrainRow>& rows) {
    for (const TerrainRow& row : rows) {
        const std::vector<double> r = roundRatios(row, rows.back());
        if (r.empty()) return false;
        const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
        if ((*hi - *lo) / median(r) > kStableSpread) return false;
    }
    return true;
}

std::vector<TerrainRow> measureTerrain(vk::Runner& runner, const fs::path& materialDir, int& rounds, double& referenceSeconds) {
    std::vector<TerrainRow> rows;
    for (const TerrainVariant& v : kTerrainVariants) {
        TerrainRow& row = rows.emplace_back();
        row.name = v.name;
        row.over = kTerrainView;
        row.compile.skipLayers = v.skipLayers;
        attempt(row.failure, [&] {
            row.material = terrainMaterial(materialDir, v);
            manifestFetches(row);
        });
    }
    if (!rows.front().failure.empty()) throw std::runtime_error("terrain, naive row (the reference): " + rows.front().failure);
    std::cout << "  terrain: fp64 reference" << std::endl;
    const auto start = std::chrono::steady_clock::now();
    const Image reference = terrainReference(rows.front().material);
    referenceSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<Timed*> timed;
    for (TerrainRow& row : rows) timed.push_back(&row);
    rounds = timeRounds(runner, timed, {}, [&] { return terrainStable(rows); });
    for (TerrainRow& row : rows)
        if (row.failure.empty()) attempt(row.failure, [&] { row.error = compareRgb(terrainAlbedo(runner, row), reference); });
    return rows;
}

// "median (min-max)" of the per-round medians, in ms.
std::string msSpread(const Timed& t) {
    const std::vector<double> r = roundMedians(t);
    if (r.empty()) return "n/a";
    const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
    return strf("%.1f (%.1f-%.1f)", median(t.frameMs), *lo, *hi);
}

std::string terrainTable(const std::vector<TerrainRow>& rows) {
    std::string md =
        "| terrain | fetches/px worst | fetches/px expected | ms/frame median (round min-max) | x naive | x plain | max err | mean err |\n"
        "|---|---|---|---|---|---|---|---|\n";
    for (const TerrainRow& r : rows)
        md += strf("| %s | %s | %s | %s | %s | %s | %s | %s |\n", r.name.c_str(), num(r.worstFetches, "%.0f").c_str(),
                   num(r.expectedFetches, "%.2f").c_str(), msSpread(r).c_str(), ratioSpread(r, rows.front()).c_str(),
                   ratioSpread(r, rows.back()).c_str(), num(r.error.max, "%.4f").c_str(), num(r.error.mean, "%.5f").c_str());
    for (const TerrainRow& r : rows)
        if (!r.failure.empty()) md += "\n" + r.name + " failed: " + r.failure + "\n";
    return md;
}

std::string terrainSection(const std::vector<TerrainRow>& rows, int rounds, double referenceSeconds) {
    return strf(
               "## Terrain\n\n`%s` (4 layers, 3 maps each, height blend, painted splat map) drawn over the whole splat map at %dx%d, "
               "`lit` shading; fetches per pixel from the manifest (worst: every layer; expected: over the splat map's texels); "
               "time per frame from %d interleaved rounds of %d frames; error: the albedo role (RGB, linear) against the fp64 "
               "reference of the naive row (every layer, every tap; %.0f s). Levers: channel packing, `lod: shared`, adaptive "
               "taps, skip_below %.3g (2/255); the default skip_below is 0.5/255.\n\n",
               kTerrain.c_str(), kTerrainView.width, kTerrainView.height, rounds, kFramesPerRound, referenceSeconds, kLeverSkip) +
           terrainTable(rows);
}

// The terrain section, measured; `only`: written to RESULTS_DIR/terrain.md, as `--terrain` runs it alone.
std::string terrain(vk::Runner& runner, const fs::path& resultsDir, bool only) {
    fs::create_directories(resultsDir / "materials");
    const std::string machine = strf("Machine: %s on %s", runner.deviceName().c_str(), cpuSummary().c_str());
    int rounds = 0;
    double referenceSeconds = 0;
    const std::vector<TerrainRow> rows = measureTerrain(runner, resultsDir / "materials", rounds, referenceSeconds);
    std::string md = terrainSection(rows, rounds, referenceSeconds);
    std::cout << "\n" << md;
    if (only) {
        md = machine + "; load average " + loadAverage() + " at the end.\n\n" + md;
        writeFile(resultsDir / "terrain.md", md);
        std::cout << "\nWrote " << (resultsDir / "terrain.md").string() << "\n";
    }
    return md;
}

int run(const fs::path& resultsDir, bool terrainOnly) {
    const auto start = std::chrono::steady_clock::now();
    if (!fs::exists("materials/textures")) throw std::runtime_error("run from the source root (materials/textures not found)");
    std::string why;
    std::unique_ptr<vk::Runner> runner = vk::Runner::create(&why);
    if (!runner) throw std::runtime_error("no Vulkan device: " + why);
    if (terrainOnly) return terrain(*runner, resultsDir, true), 0;

    const fs::path materialDir = resultsDir / "materials";
    makeTextures(materialDir / "textures");
    Results results;
    const char* threads = std::getenv("LP_NUM_THREADS");
    results.machine = strf("Machine: %s on %s%s.\n", runner->deviceName().c_str(), cpuSummary().c_str(),
                           threads ? (std::string(", LP_NUM_THREADS=") + threads).c_str() : "");
    std::string views;
    for (const NamedView& v : kViews)
        views +=
            strf("%s uv %g..%g (%g texels/px); ", v.name.c_str(), v.view.uvRect[0], v.view.uvRect[2], texelsPerPixel(v.view, kTextureSize));
    results.settings = strf(
        "Settings: material albedo (sRGB colour) + normal map + roughness (scalar), %dx%d textures (the examples upscaled), template "
        "`lit` (`bench/minimal.glsl` for the -minimal rows), tiling %g, every slot with the method's settings; %dx%d frames; %sGPU time "
        "from timestamps, median of all frames (rounds over all shaders of %d frames, each after one warm-up frame, %d to %d rounds "
        "until the full-quality ratios are stable). Methods: rot = rotation 1 (else 0), gain = falloff 0.75 "
        "(else 0.5); other settings the defaults. Error: the "
        "albedo output against the fp64 reference of the full-quality method of the same hash mode (stable-rot-gain for plain and "
        "stable rows, paper-rot-gain for paper rows), RGB, linear. Contrast: luminance of the albedo against the source texture's "
        "at the mip level the view samples (so plain tiling scores about 1 and 0).\n",
        kTextureSize, kTextureSize, kTiling, kFrameSize, kFrameSize, views.c_str(), kFramesPerRound, kRounds, kMaxRounds);

    std::cout << results.machine << "Measuring\n";
    measure(*runner, materialDir, results);
    results.terrain = terrain(*runner, resultsDir, false);
    results.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    results.settings += strf(
        "Bench run time %.0f s, of which %.0f s for the four fp64 reference images; %d timing rounds; load average %s "
        "at the end.\n",
        results.totalSeconds, results.referenceSeconds, results.rounds, loadAverage().c_str());

    // The precision stress report (the same measurement as tests/execution/stress_test.cpp).
    std::cout << "  precision far from the origin" << std::endl;
    std::vector<vk::PrecisionRow> precision;
    const vk::ProbeTextures kProbe{"materials/textures/rock_albedo.png", "materials/textures/rock_normal.png"};
    for (HashMode mode : {HashMode::Stable, HashMode::Paper}) {
        auto rows =
            vk::measurePrecision(*runner, kProbe, resultsDir / "precision", mode, vk::Placement::Direct, {1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7});
        precision.insert(precision.end(), rows.begin(), rows.end());
    }
    auto aligned =
        vk::measurePrecision(*runner, kProbe, resultsDir / "precision", HashMode::Stable, vk::Placement::Aligned, {1e5, 1e6, 1e7});
    precision.insert(precision.end(), aligned.begin(), aligned.end());
    auto split =
        vk::measurePrecision(*runner, kProbe, resultsDir / "precision", HashMode::Stable, vk::Placement::Split, {0, 1e3, 1e6, 1e9});
    precision.insert(precision.end(), split.begin(), split.end());
    writeFile(resultsDir / "precision.md", vk::precisionTable(precision));
    std::cout << "\n" << vk::precisionTable(precision);

    writeFile(resultsDir / "results.csv", csv(results));
    writeFile(resultsDir / "results.md", markdown(results));
    writeFile(resultsDir / "runtime-vs-error.svg", plot(results));
    std::cout << "\n" << mainTable(results) << "\n";
    for (const std::string& line : targetLines(results)) std::cout << line << "\n";
    for (size_t v = 0; v < kViews.size(); ++v) std::cout << adaptiveLine(results, v) << "\n";
    for (const char* packed : kPackedRows)
        for (size_t v = 0; v < kViews.size(); ++v) std::cout << packedTargetLine(results, v, packed) << "\n";
    std::cout << "\nWrote " << (resultsDir / "results.md").string() << ", results.csv, runtime-vs-error.svg\n";
    return 0;
}

}  // namespace
}  // namespace hexc::bench

int main(int argc, char** argv) {
    const bool terrainOnly = argc > 1 && std::string_view(argv[1]) == "--terrain";
    const int rest = argc - terrainOnly;
    if (rest > 2 || (rest == 2 && argv[argc - 1][0] == '-')) {  // --help included: not a results folder
        std::cerr << "usage: hexc-bench-shaders [--terrain] [RESULTS_DIR]   (from the source root; default build/bench-results;\n"
                     "  --terrain: only the terrain table, into RESULTS_DIR/terrain.md)\n";
        return rest == 2 && std::string_view(argv[argc - 1]) == "--help" ? 0 : 2;
    }
    try {
        return hexc::bench::run(std::filesystem::absolute(rest > 1 ? argv[argc - 1] : "build/bench-results"), terrainOnly);
    } catch (const hexc::CompileError& e) {
        std::cerr << "hexc-bench-shaders:\n" << hexc::formatAll(e.diagnostics);
    } catch (const std::exception& e) {
        std::cerr << "hexc-bench-shaders: " << e.what() << "\n";
    }
    return 1;
}
