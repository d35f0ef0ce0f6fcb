#include "render.h"

#include <stb_easy_font.h>

#include <iostream>
#include <map>
#include <sstream>

#include "options.h"
#include "hexc/material.h"
#include "reference/reference.h"
#include "vk/render.h"

namespace hexc::cli {

const char* const kRenderHelp = R"(hexc render - render one output of a material on Vulkan (Mesa lavapipe)

Usage:
  hexc render MATERIAL.json -o IMAGE.{pfm,png} [options]

Options:
  --output WHAT      shaded (default: the material's template), albedo, normal, derivative or weights
  --slot NAME        the slot albedo/normal/derivative/weights show (default: the slot named albedo or
                     normal, else the first slot of a fitting kind; weights: the first slot)
  --size WxH         image size in pixels (default 512x512)
  --uv-rect U0,V0,U1,V1  the UV rectangle the image covers (default 0,0,1,1)
  --target T         execute the emitted spirv (default), hlsl or glsl (re-compiled to SPIR-V by glslang)
  --reference        write the fp64 CPU reference instead (albedo, normal, derivative, weights; no Vulkan
                     needed): what the GPU image should be, up to texture filtering precision

Pixel (i, j), row j = 0 at the top, shows the material at its centre
  uv = (U0 + (i + 0.5) / W * (U1 - U0),  V0 + (j + 0.5) / H * (V1 - V0))
with exact screen-space UV derivatives (U1 - U0) / W and (V1 - V0) / H. Slot tiling applies on top of uv.
albedo: RGBA as sampled (linear); derivative: (dH/du, dH/dy, 0, 1), y = -v; normal: the tangent-space normal
encoded n * 0.5 + 0.5; weights: the three hex-tile weights (Listing 7). Triplanar materials are shown on
the unit sphere, uv being longitude and latitude in radians; their derivative output is the world-space
surface gradient (x, y, z, 1), and normal is not offered. PFM keeps floats exactly; PNG
clamps to [0, 1] and stores 8 bits without sRGB encoding.
)";

const char* const kPreviewHelp = R"(hexc preview - one labelled picture of a material: plain tiling, hex tiling, hex weights

Usage:
  hexc preview MATERIAL.json -o PREVIEW.png [--cell N]

Three columns (plain tiling, hex tiling, the hex-tile weights of the first slot) at two distances:
magnified (UV 0..0.5) and minified (UV 0..4, several texels per pixel, mip-mapped).
Each cell is N x N pixels (default 256). Shaded with the material's template.
)";

namespace {

std::vector<double> numbers(const std::string& text, char sep, size_t count, const std::string& option) {
    std::vector<double> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, sep);) {
        try {
            size_t used = 0;
            out.push_back(std::stod(item, &used));
            if (used != item.size()) throw std::invalid_argument(item);
        } catch (const std::exception&) {
            throw UsageError{option + " expects " + std::to_string(count) + " numbers, got `" + text + "`"};
        }
    }
    if (out.size() != count) throw UsageError{option + " expects " + std::to_string(count) + " numbers, got `" + text + "`"};
    return out;
}

// Parses the material, reporting diagnostics; nullopt on error.
std::optional<Material> loadMaterial(const std::string& path) {
    ParseResult r = parseMaterialFile(path);
    for (const Diagnostic& d : r.diagnostics) std::cerr << d.format() << "\n";
    return r.material;
}

std::unique_ptr<vk::Runner> makeRunner() {
    std::string why;
    auto runner = vk::Runner::create(&why);
    if (!runner) std::cerr << "hexc: no Vulkan device: " << why << " (install mesa-vulkan-drivers for lavapipe)\n";
    return runner;
}

// Runs a command body, mapping failures to the documented exit codes.
template <typename Body>
int guarded(Body body) {
    try {
        return body();
    } catch (const UsageError& e) {
        std::cerr << "hexc: " << e.message << "\n";
        return kUsage;
    } catch (const CompileError& e) {
        std::cerr << formatAll(e.diagnostics);
        return kInvalidInput;
    } catch (const std::invalid_argument& e) {
        std::cerr << "hexc: " << e.what() << "\n";
        return kInvalidInput;
    } catch (const vk::VulkanError& e) {
        std::cerr << "hexc: Vulkan: " << e.what() << "\n";
        return kNoVulkan;
    } catch (const std::exception& e) {
        std::cerr << "hexc: " << e.what() << "\n";
        return kWriteFailed;
    }
}

// Draws text with stb_easy_font's quads, scaled, in white on whatever is there.
void drawLabel(Image& image, int x0, int y0, const std::string& text, int scale) {
    std::vector<char> buffer(text.size() * 300);
    std::string copy = text;
    int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(), int(buffer.size()));
    const float* v = reinterpret_cast<const float*>(buffer.data());
    for (int q = 0; q < quads; ++q) {
        const float* a = v + q * 4 * 4;  // 4 vertices of x, y, z, colour (4 bytes as one float slot)
        const float* c = a + 2 * 4;
        for (int y = int(a[1]) * scale; y < int(c[1]) * scale; ++y)
            for (int x = int(a[0]) * scale; x < int(c[0]) * scale; ++x) {
                int px = x0 + x, py = y0 + y;
                if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
                float* p = image.at(px, py);
                p[0] = p[1] = p[2] = p[3] = 1.0f;
            }
    }
}

}  // namespace

int renderCommand(const std::vector<std::string>& args) {
    return guarded([&] {
        std::string materialPath, out, slot;
        View view{512, 512, {0, 0, 1, 1}};
        vk::RenderOutput output = vk::RenderOutput::Shaded;
        vk::ExecutedTarget target = vk::ExecutedTarget::Spirv;
        bool useReference = false;
        static const std::map<std::string, vk::RenderOutput> outputs = {
            {"shaded", vk::RenderOutput::Shaded}, {"albedo", vk::RenderOutput::Albedo}, {"normal", vk::RenderOutput::Normal},
            {"derivative", vk::RenderOutput::Derivative}, {"weights", vk::RenderOutput::Weights}};
        static const std::map<std::string, vk::ExecutedTarget> targets = {
            {"spirv", vk::ExecutedTarget::Spirv}, {"hlsl", vk::ExecutedTarget::Hlsl}, {"glsl", vk::ExecutedTarget::Glsl}};
        for (size_t i = 0; i < args.size(); ++i) {
            auto value = [&]() -> const std::string& {
                if (i + 1 >= args.size()) throw UsageError{args[i] + " needs a value"};
                return args[++i];
            };
            const std::string& a = args[i];
            if (a == "-h" || a == "--help") return std::cout << kRenderHelp, int(kOk);
            if (a == "-o" || a == "--out") out = value();
            else if (a == "--slot") slot = value();
            else if (a == "--size") {
                auto wh = numbers(value(), 'x', 2, "--size");
                if (wh[0] < 1 || wh[1] < 1 || wh[0] > 8192 || wh[1] > 8192 || wh[0] != int(wh[0]) || wh[1] != int(wh[1]))
                    throw UsageError{"--size expects WxH with whole numbers from 1 to 8192, got " + args[i]};
                view.width = int(wh[0]);
                view.height = int(wh[1]);
            } else if (a == "--uv-rect") {
                auto r = numbers(value(), ',', 4, "--uv-rect");
                view.uvRect = {r[0], r[1], r[2], r[3]};
            } else if (a == "--output") {
                auto it = outputs.find(value());
                if (it == outputs.end()) throw UsageError{"--output expects shaded, albedo, normal, derivative or weights, got " + args[i]};
                output = it->second;
            } else if (a == "--target") {
                auto it = targets.find(value());
                if (it == targets.end()) throw UsageError{"--target expects spirv, hlsl or glsl, got " + args[i]};
                target = it->second;
            } else if (a == "--reference") useReference = true;
            else if (!a.empty() && a[0] == '-') throw UsageError{"unknown option " + a + " (see hexc render --help)"};
            else if (materialPath.empty()) materialPath = a;
            else throw UsageError{"hexc render takes one material, got a second: " + a};
        }
        if (materialPath.empty()) throw UsageError{"no material given (see hexc render --help)"};
        if (out.empty()) throw UsageError{"no output image given: use -o IMAGE.pfm or IMAGE.png"};
        if (!slot.empty() && output == vk::RenderOutput::Shaded)
            throw UsageError{"--slot picks the slot of --output albedo, normal, derivative or weights; shaded shows the whole material"};
        if (useReference && output == vk::RenderOutput::Shaded)
            throw UsageError{"--reference covers the hex-tiled slots (albedo, normal, derivative, weights), not a template's shading"};
        auto material = loadMaterial(materialPath);
        if (!material) return int(kInvalidInput);
        if (useReference) {
            const Slot& s = vk::slotForOutput(*material, output, slot);
            reference::SampledTexture texture(loadTexture(s.texturePath, s.colorSpace == ColorSpace::Srgb));
            const reference::Heights heights(*material, s);
            Image image = reference::render(s, texture, view, output == vk::RenderOutput::Weights ? reference::Output::Weights : reference::Output::Value,
                                            heights.source());
            if (s.kind == SlotKind::Scalar)  // as the GPU shows it: (s, s, s, 1)
                for (size_t i = 0; i < image.rgba.size(); i += 4) image.rgba[i] = image.rgba[i + 1] = image.rgba[i + 2] = image.rgba[i + size_t(s.channel)];
            if (output == vk::RenderOutput::Normal) vk::derivativeToNormalMap(image);
            writeImage(image, out);
            return int(kOk);
        }
        auto runner = makeRunner();
        if (!runner) return int(kNoVulkan);
        writeImage(vk::render(*runner, *material, output, slot, view, target), out);
        return int(kOk);
    });
}

int previewCommand(const std::vector<std::string>& args) {
    return guarded([&] {
        std::string materialPath, out;
        int cell = 256;
        for (size_t i = 0; i < args.size(); ++i) {
            const std::string& a = args[i];
            auto value = [&]() -> const std::string& {
                if (i + 1 >= args.size()) throw UsageError{a + " needs a value"};
                return args[++i];
            };
            if (a == "-h" || a == "--help") return std::cout << kPreviewHelp, int(kOk);
            if (a == "-o" || a == "--out") out = value();
            else if (a == "--cell") {
                double n = numbers(value(), ',', 1, "--cell")[0];
                if (n < 32 || n > 2048 || n != int(n)) throw UsageError{"--cell expects a whole number from 32 to 2048"};
                cell = int(n);
            } else if (!a.empty() && a[0] == '-') throw UsageError{"unknown option " + a + " (see hexc preview --help)"};
            else if (materialPath.empty()) materialPath = a;
            else throw UsageError{"hexc preview takes one material, got a second: " + a};
        }
        if (materialPath.empty()) throw UsageError{"no material given (see hexc preview --help)"};
        if (out.empty()) throw UsageError{"no output image given: use -o PREVIEW.png"};
        auto material = loadMaterial(materialPath);
        if (!material) return int(kInvalidInput);
        auto runner = makeRunner();
        if (!runner) return int(kNoVulkan);

        Material plain = *material;
        for (Slot& s : plain.slots) s.hex.enabled = false;
        struct Column {
            const char* label;
            const Material* material;
            vk::RenderOutput output;
        };
        const Column columns[] = {{"plain", &plain, vk::RenderOutput::Shaded},
                                  {"hex", &*material, vk::RenderOutput::Shaded},
                                  {"weights", &*material, vk::RenderOutput::Weights}};
        struct Row {
            const char* label;
            double extent;
        };
        const Row rows[] = {{"uv 0..0.5", 0.5}, {"uv 0..4", 4.0}};
        const int band = 28, scale = 2;
        Image sheet;
        sheet.width = 3 * cell;
        sheet.height = 2 * (cell + band);
        sheet.rgba.assign(size_t(sheet.width) * sheet.height * 4, 0.12f);  // dark grey bands behind the labels
        for (size_t i = 3; i < sheet.rgba.size(); i += 4) sheet.rgba[i] = 1.0f;
        for (int r = 0; r < 2; ++r) {
            for (int c = 0; c < 3; ++c) {
                View view{cell, cell, {0, 0, rows[r].extent, rows[r].extent}};
                Image img = vk::render(*runner, *columns[c].material, columns[c].output, "", view);
                int y0 = r * (cell + band) + band;
                for (int y = 0; y < cell; ++y)
                    for (int x = 0; x < cell; ++x) std::copy_n(img.at(x, y), 4, sheet.at(c * cell + x, y0 + y));
                drawLabel(sheet, c * cell + 6, r * (cell + band) + 6, std::string(columns[c].label) + ", " + rows[r].label, scale);
            }
        }
        writeImage(sheet, out);
        return int(kOk);
    });
}

}  // namespace hexc::cli
