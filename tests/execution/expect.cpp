// hexc-expect (CASE.json | MATERIAL:SLOT | layers/FILE.json:CASE)... -o DIR: what a GPU that the execution tests do not drive (tests/wgsl:
// Dawn) is held to for a case of tests/execution/cases/ (its own check, checks.h checkCase), a case of a feature
// variant's table (odd_sizes/, packed/, adaptive/: the checks its table's test runs, checks.h "Feature variants as data";
// layers/FILE.json:CASE: a case of layers_test.cpp, layer_checks.h) or a slot of a material
// file (as outputs_test.cpp checks the examples': checkSlot), the check run with nothing drawn: the same reference and
// per-pixel tolerances, the texels the reference samples (every mip level as it models them) and the shader drawn,
// the WGSL of the material as the harness shows it (NAME.frag.wgsl, NAME.vert.wgsl, NAME.manifest.json).
// Writes, per case or slot NAME (the case's file name, a variant's table's folder and its file name, odd_sizes_3x3, or
// the material file's and the slot's, rock_mtlx_albedo),
// NAME.expect.json and the raw little-endian files it names:
//   {"output": "albedo" | "derivative" | "weights" | "shaded" (the material's own template: packed), "channels": N,
//    "compile_ms", "width", "height", "uv": [u0, v0, u1, v1], "reference": RGBA float32 a pixel, top row first,
//    "tolerance": "tolerance_channels" float32 a pixel: 1, or 4, one a channel (packed: each slot's in its channels),
//    "textures": {name as the manifest names it: {"format": a WebGPU format, "levels": [{"width", "height", "file"}]}, or
//    for a layers role's texture array {"format", "array": the textures of its layers, in layer order}},
//    adaptive taps only (cases_test.cpp AdaptiveTaps), "adaptive": {"weights": the weights output's NAME_weights
//    (.frag.wgsl, .manifest.json ...), "fetched": 3 bytes a pixel, 1 where the reference fetches a tap, "other_taps": the
//    tolerance (float32 a pixel) where the GPU fetches other taps than the reference}}
// An 8-bit texture's levels are the reference's exact ones rounded to 8 bits (in sRGB encoding for an sRGB one): within
// half a step of them, where lavapipe's blits may be a step off per level (sampleError). Float textures (the
// histogram's Gaussian texture and table) are float32.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>

#include "execution/checks.h"
#include "execution/layer_checks.h"
#include "vk/render.h"

using namespace hexc;
using namespace hexc::exec;

namespace {

void writeRaw(const std::filesystem::path& file, const void* data, size_t bytes) {
    std::ofstream out(file, std::ios::binary);
    out.write(static_cast<const char*>(data), std::streamsize(bytes));
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

uint8_t unorm8(double linear, bool srgb) {
    const double v = std::clamp(linear, 0.0, 1.0);
    const double encoded = !srgb ? v : v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    return uint8_t(std::lround(encoded * 255));
}

// Every level of `t` to files `stem`.N.raw; returns the texture's entry.
nlohmann::json writeLevels(const reference::SampledTexture& t, bool isFloat, bool srgb, const std::filesystem::path& dir,
                           const std::string& stem) {
    nlohmann::json levels = nlohmann::json::array();
    for (int l = 0; l < t.levels(); ++l) {
        const int w = t.width(l), h = t.height(l);
        std::vector<float> f;
        std::vector<uint8_t> b;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 4; ++c) {
                    const double v = t.texel(l, x, y)[size_t(c)];
                    if (isFloat)
                        f.push_back(float(v));
                    else
                        b.push_back(unorm8(v, srgb && c < 3));  // alpha is never encoded
                }
        const std::string file = stem + "." + std::to_string(l) + ".raw";
        isFloat ? writeRaw(dir / file, f.data(), f.size() * 4) : writeRaw(dir / file, b.data(), b.size());
        levels.push_back({{"width", w}, {"height", h}, {"file", file}});
    }
    return {{"format", isFloat ? "rgba32float" : srgb ? "rgba8unorm-srgb" : "rgba8unorm"}, {"levels", levels}};
}

// Each slot's textures as the reference samples them: SlotTextures (a histogram slot's Gaussian texture in the slot's
// place, its table as "<slot>.lut"), decoded by the sampler where the slot says; a packed texture as the compile wrote
// it, its levels made as the reference makes a texture's.
nlohmann::json writeTextures(const Material& m, const CompileResult& compiled, const std::filesystem::path& dir) {
    nlohmann::json textures = nlohmann::json::object();
    for (const Slot& slot : m.slots) {
        const reference::SlotTextures t(slot);
        const bool histogram = t.lut != nullptr;
        const std::string stem = m.name + "." + slot.name;
        textures[slot.name] = writeLevels(*t.texture, histogram, slot.samplerDecodes(), dir, stem);
        if (histogram) textures[slot.name + ".lut"] = writeLevels(*t.lut, true, false, dir, stem + ".lut");
    }
    const auto file = [&](const std::string& name) {
        return std::find_if(compiled.files.begin(), compiled.files.end(), [&](const OutputFile& f) { return f.name == name; })->contents;
    };
    const nlohmann::json manifest = nlohmann::json::parse(file(m.name + ".manifest.json"));
    for (const nlohmann::json& p : manifest.value("packed_textures", nlohmann::json::array())) {
        const bool srgb = p["colorspace"] == "srgb";
        const reference::SampledTexture t(decodeTexture(file(p["file"]), srgb));
        textures[p["name"].get<std::string>()] = writeLevels(t, false, srgb, dir, m.name + "." + p["name"].get<std::string>());
    }
    // A layers role's texture array: its layers are its slots' textures, in layer order.
    if (manifest.contains("layers"))
        for (const nlohmann::json& a : manifest["layers"]["arrays"])
            if (a["array"])
                textures[a["binding"]["texture"].get<std::string>()] = {{"format", textures[a["slots"][0].get<std::string>()]["format"]},
                                                                        {"array", a["slots"]}};
    return textures;
}

// What one GPU image is held to: the material checked (its first slot), the view and the check.
struct Expected {
    std::string name;
    Material material;
    View view;
    Check check;
    // Adaptive taps (checks.h, checkAdaptive; check.tolerance where the GPU fetches the reference's taps): the
    // tolerance where it fetches others, the taps the reference fetches (a byte a tap).
    struct Adaptive {
        std::vector<double> otherTaps;
        std::vector<uint8_t> fetched;
    };
    std::optional<Adaptive> adaptive;
};

// A case file of tests/execution/cases/, under its own rule and view.
Expected fromCase(const std::filesystem::path& file) {
    std::ifstream in(file);
    const nlohmann::json c = nlohmann::json::parse(in);
    const std::string name = file.stem().string();
    ParseResult r = parseMaterial(c.at("material").dump(), "materials/" + name + ".json");
    if (!r.material) throw std::runtime_error(formatAll(r.diagnostics));
    return {name, *r.material, caseView(c.at("view")).first, checkCase(c, *r.material, Draw()), {}};
}

// A case file of adaptive/, as its test checks it (cases_test.cpp AdaptiveTaps: checks 1 and 2; check 3, adaptive
// against exact 3-tap drawn on the same GPU, would cost a third shader a case), named adaptive_<case>.
Expected fromAdaptive(const ExecCase& c) {
    const AdaptiveCase a = adaptiveCase(c);
    const size_t pixels = size_t(a.view.width * a.view.height);
    Expected::Adaptive more{checkAdaptive(a, std::vector<bool>(pixels, true), Draw()).tolerance, {}};
    const Slot& slot = a.adaptive.slots[0];
    for (const reference::SlotResult& r : reference::evaluateView(slot, sampled(slot), a.view))
        for (size_t tap = 0; tap < 3; ++tap) more.fetched.push_back(fetchedByReference(r, tap));
    return {"adaptive_" + c.name, a.adaptive, a.view, checkAdaptive(a, std::vector<bool>(pixels, false), Draw()), std::move(more)};
}

// A case file of a feature variant's table (odd_sizes/ ...), under that table's check (checks.h, "Feature variants as
// data"), named <folder>_<case>, odd_sizes_127x80.
Expected fromVariant(const std::filesystem::path& file) {
    using VariantCheck = CaseCheck (*)(const ExecCase&, const Draw&);
    const std::map<std::string, VariantCheck> checks = {{"odd_sizes", checkOddSize}, {"packed", checkPackedCase}};
    const std::string folder = file.parent_path().filename().string();
    const ExecCase c{file.parent_path(), file.stem().string(), vk::ExecutedTarget::Spirv};  // the target is not read
    if (folder == "adaptive") return fromAdaptive(c);
    const auto check = checks.find(folder);
    if (check == checks.end()) throw std::runtime_error(file.string() + ": not a case of cases/ or of a feature variant's table");
    CaseCheck r = check->second(c, Draw());
    return {folder + "_" + c.name, r.material, r.view, r.check, {}};
}

// A case of tests/execution/layers_test.cpp (its check: layer_checks.h), by its material file and its name in the
// test's table, named layers_<case>.
Expected fromLayers(const std::filesystem::path& file, const std::string& name) {
    for (const LayerCase& c : kLayerCases)
        if (file.filename() == c.file && name == c.name) {
            CaseCheck r = checkLayers(c, Draw());
            return {"layers_" + name, r.material, r.view, r.check, {}};
        }
    throw std::runtime_error(file.string() + ": layers_test.cpp has no case " + name + " of it");
}

// A slot of a material file as tests/execution/outputs_test.cpp checks the examples': alone with the slot it
// height-blends by (slotOf), in its view (checkSlot).
Expected fromSlot(const std::string& file, const std::string& slot) {
    const Material one = slotOf(slot, file);
    const std::filesystem::path path(file);
    const std::string name = path.stem().string() + "_" + path.extension().string().substr(1) + "_" + slot;  // rock_mtlx_albedo
    return {name, one, slotView(one.slots[0]), checkSlot(one, Draw()), {}};
}

// A material's output as the harness shows it (vk::renderedMaterial: the `value` or `weights` template, or the
// material's own), named `name`, in WGSL, baked, with the vertex stage, written to `dir`: the material shown, its compile
// (SPIR-V and naga's translation, with the vertex stage) and that compile's time in ms.
struct Written {
    Material shown;
    CompileResult compiled;
    double compileMs;
};

Written writeWgsl(const Material& m, vk::RenderOutput output, const std::string& name, const std::filesystem::path& dir) {
    Written w{vk::renderedMaterial(m, output, m.slots[0].name), {}, 0};
    w.shown.name = name;
    CompileOptions options;
    options.targets = {Target::Wgsl};
    options.vertex = options.bake = true;
    const auto started = std::chrono::steady_clock::now();
    w.compiled = compile(w.shown, options);
    w.compileMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    if (!w.compiled.ok()) throw std::runtime_error(formatAll(w.compiled.diagnostics));
    for (const OutputFile& f : w.compiled.files) std::ofstream(dir / f.name, std::ios::binary) << f.contents;
    return w;
}

void writeFloats(const std::filesystem::path& file, const std::vector<double>& values) {
    const std::vector<float> f(values.begin(), values.end());
    writeRaw(file, f.data(), f.size() * 4);
}

// The checked output's WGSL; the reference and tolerances; every texture it binds; for adaptive taps, the weights
// output's WGSL.
void write(Expected e, const std::filesystem::path& dir) {
    const Written w = writeWgsl(e.material, e.check.output, e.name, dir);
    writeRaw(dir / (e.name + ".reference.raw"), e.check.reference.rgba.data(), e.check.reference.rgba.size() * 4);
    writeFloats(dir / (e.name + ".tolerance.raw"), e.check.tolerance);
    const vk::RenderOutput output = e.check.output;
    nlohmann::json out = {{"output", output == vk::RenderOutput::Derivative ? "derivative"
                                     : output == vk::RenderOutput::Weights  ? "weights"
                                     : output == vk::RenderOutput::Shaded   ? "shaded"
                                                                            : "albedo"},
                          {"channels", e.check.channels},
                          {"tolerance_channels", e.check.toleranceChannels},
                          {"compile_ms", w.compileMs},
                          {"width", e.view.width},
                          {"height", e.view.height},
                          {"uv", e.view.uvRect},
                          {"reference", e.name + ".reference.raw"},
                          {"tolerance", e.name + ".tolerance.raw"},
                          {"textures", writeTextures(w.shown, w.compiled, dir)}};
    if (e.adaptive) {
        writeWgsl(e.material, vk::RenderOutput::Weights, e.name + "_weights", dir);
        writeFloats(dir / (e.name + ".other_taps.raw"), e.adaptive->otherTaps);
        writeRaw(dir / (e.name + ".fetched.raw"), e.adaptive->fetched.data(), e.adaptive->fetched.size());
        out["adaptive"] = {
            {"weights", e.name + "_weights"}, {"fetched", e.name + ".fetched.raw"}, {"other_taps", e.name + ".other_taps.raw"}};
    }
    std::ofstream(dir / (e.name + ".expect.json")) << out.dump(1) << "\n";
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> inputs;
    std::filesystem::path dir;
    for (int i = 1; i < argc; ++i) std::string(argv[i]) == "-o" && i + 1 < argc ? void(dir = argv[++i]) : inputs.push_back(argv[i]);
    if (dir.empty() || inputs.empty()) {
        std::fprintf(stderr, "usage: hexc-expect (CASE.json | MATERIAL:SLOT | layers/FILE.json:CASE)... -o DIR   (from the source root)\n");
        return 2;
    }
    try {
        std::filesystem::create_directories(dir);
        for (const std::string& input : inputs) {
            const size_t colon = input.rfind(':');
            const std::filesystem::path file(input.substr(0, colon));
            const std::string after = colon == std::string::npos ? "" : input.substr(colon + 1);
            write(file.parent_path().filename() == "layers"  ? fromLayers(file, after)
                  : colon != std::string::npos               ? fromSlot(file.string(), after)
                  : file.parent_path().filename() == "cases" ? fromCase(file)
                                                             : fromVariant(file),
                  dir);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "hexc-expect: %s\n", e.what());
        return 1;
    }
    return 0;
}
