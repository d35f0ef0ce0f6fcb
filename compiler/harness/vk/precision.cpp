#include "vk/precision.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "hexc/origin.h"
#include "reference/reference.h"
#include "vk/render.h"
#include "vk/shaders.h"

namespace hexc::vk {
namespace {

// The example textures as float PFMs (8-bit value / 255, taken as linear).
std::filesystem::path floatCopy(const std::filesystem::path& png, const std::filesystem::path& workDir) {
    Texture t = loadTexture(png, false);
    Image image;
    image.width = t.width;
    image.height = t.height;
    for (uint8_t b : t.rgba8) image.rgba.push_back(b / 255.0f);
    std::filesystem::path out = workDir / (png.stem().string() + ".pfm");
    writeImage(image, out);
    return out;
}

Image probe(Runner& runner, const View& view, int32_t mode) {
    std::vector<uint8_t> uniforms(16, 0);
    std::memcpy(uniforms.data(), &mode, 4);
    return renderShader(runner, "probe.frag.glsl", uniforms, view);
}

const char* modeName(HashMode mode, Placement placement) {
    if (mode == HashMode::Paper) return "paper";
    return placement == Placement::Split ? "stable, split" : placement == Placement::Aligned ? "stable, aligned" : "stable";
}

// The probe material: one slot `s` of the given path at tiling 4; aligned views draw it with their own template.
Material probeMaterial(const std::filesystem::path& texture, bool normal, HashMode mode, Placement placement,
                       const std::filesystem::path& workDir) {
    nlohmann::json hex = {
        {"tiling", 4}, {"mode", mode == HashMode::Paper ? "paper" : "stable"}, {"split_coordinates", placement == Placement::Split}};
    nlohmann::json json = {{"name", "precision"},
                           {"slots",
                            {{{"name", "s"},
                              {"kind", normal ? "normal" : "color"},
                              {"colorspace", "linear"},
                              {"texture", texture.string()},
                              {"hextiling", hex}}}}};
    if (placement == Placement::Aligned) {
        std::filesystem::path shader = workDir / "aligned.frag.glsl";
        std::ofstream(shader, std::ios::binary) << harnessShaders().at("aligned.frag.glsl");
        json["template"] = shader.string();
    }
    ParseResult parsed = parseMaterial(json.dump(), workDir / "precision.json");
    if (!parsed.material) throw CompileError{parsed.diagnostics};
    return *parsed.material;
}

// A texel per pixel (tiling 4 on 256 texels: 1/1024 uv) where float32 resolves it at x; beyond, half an ulp of x
// per pixel, or for aligned views one ulp with the pixel centres on x + i ulp.
View probeView(double x, Placement placement) {
    const double texel = 1.0 / 1024;
    if (placement == Placement::Split) return View{64, 64, {0.3, 0.3, 0.3 + 64 * texel, 0.3 + 64 * texel}};
    double ulp = x > 0 ? std::ldexp(1.0, std::ilogb(float(x)) - 23) : 0;
    double pixel = std::max(texel, placement == Placement::Aligned ? ulp : ulp / 2);
    double base = placement == Placement::Aligned ? x - pixel / 2 : x;
    return View{64, 64, {base, base, base + 64 * pixel, base + 64 * pixel}};
}

// The reference at every pixel's float32 inputs: uv (plus a split origin) and its gradients as the rasteriser gave
// them, or for aligned views the one-texel gradients their template samples with.
Image referenceImage(Runner& runner, const Slot& slot, const reference::SampledTexture& texture, const View& view, double origin,
                     Placement placement) {
    Image at = probe(runner, view, 0), dy = probe(runner, view, 1);
    Image cpu = at;
    const bool aligned = placement == Placement::Aligned;
    for (size_t p = 0; p < at.rgba.size(); p += 4) {
        double dudx = aligned ? 1.0 / 1024 : at.rgba[p + 2], dvdx = aligned ? 0 : at.rgba[p + 3];
        double dudy = aligned ? 0 : dy.rgba[p], dvdy = aligned ? 1.0 / 1024 : dy.rgba[p + 1];
        reference::SlotResult r = reference::evaluate(slot, texture, origin + at.rgba[p], origin + at.rgba[p + 1], dudx, dvdx, dudy, dvdy);
        for (size_t c = 0; c < 4; ++c) cpu.rgba[p + c] = float(r.value[c]);
    }
    return cpu;
}

}  // namespace

ImageErrors compareImages(const Image& a, const Image& b, int channels) {
    ImageErrors e;
    size_t n = 0, over = 0;
    for (size_t i = 0; i < a.rgba.size(); i += 4)
        for (int c = 0; c < channels; ++c) {
            double d = std::fabs(double(a.rgba[i + size_t(c)]) - double(b.rgba[i + size_t(c)]));
            if (!(d == d)) d = INFINITY;  // NaN on one side only is an error, not a pass
            e.max = std::max(e.max, d);
            e.mean += d;
            over += d > 1.0 / 255;
            ++n;
        }
    e.mean /= double(n);
    e.overOne255 = double(over) / double(n);
    return e;
}

std::vector<PrecisionRow> measurePrecision(Runner& runner, const ProbeTextures& inputs, const std::filesystem::path& workDir, HashMode mode,
                                           Placement placement, const std::vector<double>& magnitudes, ExecutedTarget target) {
    std::filesystem::create_directories(workDir);
    const std::filesystem::path textures[] = {floatCopy(inputs.color, workDir), floatCopy(inputs.normal, workDir)};
    std::vector<PrecisionRow> rows;
    for (int path = 0; path < 2; ++path) {
        const Material m = probeMaterial(textures[path], path == 1, mode, placement, workDir);
        const Slot& slot = m.slots[0];
        reference::SampledTexture texture(loadTexture(slot.texturePath, false, slot.textureLayer));
        for (double x : magnitudes) {
            View view = probeView(x, placement);
            ParameterValues params;
            if (placement == Placement::Split) {
                SplitOrigin o = splitOrigin(x, x, slot.hex.tiling);
                params["s_origin_cell"] = {double(o.cell[0]), double(o.cell[1])};
                params["s_origin_offset"] = {double(o.offset[0]), double(o.offset[1])};
            }
            RenderOutput output = placement == Placement::Aligned ? RenderOutput::Shaded
                                  : path                          ? RenderOutput::Derivative
                                                                  : RenderOutput::Albedo;
            Image gpu = render(runner, m, output, "", view, target, 0, nullptr, params);
            Image cpu = referenceImage(runner, slot, texture, view, placement == Placement::Split ? x : 0, placement);
            if (path) {
                derivativeToNormalMap(gpu);
                derivativeToNormalMap(cpu);
            }
            rows.push_back({modeName(mode, placement), path ? "normal" : "color", x, compareImages(gpu, cpu, 3)});
        }
    }
    return rows;
}

std::string precisionTable(const std::vector<PrecisionRow>& rows) {
    std::ostringstream out;
    out << "| mode | path | |uv| | max error | mean error | pixels over 1/255 |\n|---|---|---|---|---|---|\n";
    char line[256];
    for (const PrecisionRow& r : rows) {
        std::snprintf(line, sizeof line, "| %s | %s | %.4g | %.2e (%.2f/255) | %.2e | %.1f%% |\n", r.mode.c_str(), r.path.c_str(),
                      r.magnitude, r.errors.max, r.errors.max * 255, r.errors.mean, r.errors.overOne255 * 100);
        out << line;
    }
    return out.str();
}

}  // namespace hexc::vk
