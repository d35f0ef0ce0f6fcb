#include "vk/precision.h"

#include <cmath>
#include <cstring>
#include <sstream>

#include "hexc/origin.h"
#include "reference/reference.h"
#include "vk/render.h"

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

const char* modeName(HashMode mode, bool split) { return mode == HashMode::Paper ? "paper" : split ? "stable, split" : "stable"; }

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
                                           bool split, const std::vector<double>& magnitudes) {
    std::filesystem::create_directories(workDir);
    const std::filesystem::path textures[] = {floatCopy(inputs.color, workDir), floatCopy(inputs.normal, workDir)};
    std::vector<PrecisionRow> rows;
    for (int path = 0; path < 2; ++path) {
        std::string json = std::string(R"({"name": "precision", "slots": [{"name": "s", "kind": ")") + (path ? "normal" : "color") +
                           R"(", "colorspace": "linear", "texture": ")" + textures[path].string() + R"(", "hextiling": {"tiling": 4, "mode": ")" +
                           (mode == HashMode::Paper ? "paper" : "stable") + R"(", "split_coordinates": )" + (split ? "true" : "false") + "}}]}";
        ParseResult parsed = parseMaterial(json, workDir / "precision.json");
        if (!parsed.material) throw CompileError{parsed.diagnostics};
        const Material& m = *parsed.material;
        const Slot& slot = m.slots[0];
        reference::SampledTexture texture(loadTexture(slot.texturePath, false));
        for (double x : magnitudes) {
            // A texel per pixel (tiling 4 on 256 texels: 1/1024 uv) unless float32 cannot resolve it at x.
            double ulp = x > 0 ? std::ldexp(1.0, std::ilogb(float(x)) - 23) : 0;
            double pixel = split ? 1.0 / 1024 : std::max(1.0 / 1024, ulp / 2);
            double base = split ? 0.3 : x;
            View view{64, 64, {base, base, base + 64 * pixel, base + 64 * pixel}};
            ParameterValues params;
            if (split) {
                SplitOrigin o = splitOrigin(x, x, slot.hex.tiling);
                params["s_origin_cell"] = {double(o.cell[0]), double(o.cell[1])};
                params["s_origin_offset"] = {double(o.offset[0]), double(o.offset[1])};
            }
            RenderOutput output = path ? RenderOutput::Derivative : RenderOutput::Albedo;
            Image gpu = render(runner, m, output, "", view, ExecutedTarget::Spirv, 0, nullptr, params);
            Image at = probe(runner, view, 0), dy = probe(runner, view, 1);
            Image cpu = gpu;
            for (size_t p = 0; p < gpu.rgba.size(); p += 4) {
                double origin = split ? x : 0;
                reference::SlotResult r = reference::evaluate(slot, texture, origin + at.rgba[p], origin + at.rgba[p + 1], at.rgba[p + 2],
                                                              at.rgba[p + 3], dy.rgba[p], dy.rgba[p + 1]);
                for (size_t c = 0; c < 4; ++c) cpu.rgba[p + c] = float(r.value[c]);
            }
            if (path) {
                derivativeToNormalMap(gpu);
                derivativeToNormalMap(cpu);
            }
            rows.push_back({modeName(mode, split), path ? "normal" : "color", x, compareImages(gpu, cpu, 3)});
        }
    }
    return rows;
}

std::string precisionTable(const std::vector<PrecisionRow>& rows) {
    std::ostringstream out;
    out << "| mode | path | |uv| | max error | mean error | pixels over 1/255 |\n|---|---|---|---|---|---|\n";
    char line[256];
    for (const PrecisionRow& r : rows) {
        std::snprintf(line, sizeof line, "| %s | %s | %.0e | %.2e (%.2f/255) | %.2e | %.1f%% |\n", r.mode.c_str(), r.path.c_str(), r.magnitude,
                      r.errors.max, r.errors.max * 255, r.errors.mean, r.errors.overOne255 * 100);
        out << line;
    }
    return out.str();
}

}  // namespace hexc::vk
