#include "render.h"

#include <stb_easy_font.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <new>
#include <sstream>
#include <tuple>
#include <variant>

#include "options.h"
#include "hexc/budgets.h"
#include "progress.h"
#include "hexc/material.h"
#include "hexc/templates.h"
#include "reference/layers.h"
#include "reference/reference.h"
#include "vk/render.h"

namespace hexc::cli {

namespace {

const char* const kRenderHelp = R"(hexc render - render one output of a material on Vulkan (Mesa lavapipe)

Pixel (i, j), row j = 0 at the top, shows the material at its centre
  uv = (U0 + (i + 0.5) / W * (U1 - U0),  V0 + (j + 0.5) / H * (V1 - V0))
with exact screen-space UV derivatives (U1 - U0) / W and (V1 - V0) / H. Slot tiling applies on top of uv.
albedo: RGBA as sampled (linear); derivative: (dH/du, dH/dy, 0, 1), y = -v; normal: the tangent-space normal
encoded n * 0.5 + 0.5; weights: the three hex-tile weights (Listing 7). Triplanar materials are shown on
the unit sphere, uv being longitude and latitude in radians; their derivative output is the world-space
surface gradient (x, y, z, 1), and normal is not offered. PFM keeps floats exactly; PNG
clamps to [0, 1] and stores 8 bits. --encoding srgb writes what an engine's sRGB swapchain shows (the sRGB
transfer function on RGB, alpha linear); the default, linear, writes the values the shader returns.
A template that declares resources of its own (an engine's per-frame blocks, shadow maps...) is replaced by
the built-in `lit` for --output shaded, with a note; --template picks another.
)";

const char* const kPreviewHelp = R"(hexc preview - one labelled picture of a material: plain tiling, both hex blends, hex weights

Four columns (plain tiling, hex tiling with the falloff blend, hex tiling with the histogram-preserving blend
on its colour and scalar slots, the hex-tile weights of the first slot) at two distances: magnified
(UV 0..0.5) and minified (UV 0..4, several texels per pixel, mip-mapped).
Each cell is N x N pixels (default 256). Shaded with the material's template (or --template); one that
declares resources of its own (an engine's) is replaced by the built-in `lit`, with a note. Written for display:
sRGB-encoded, as an engine's sRGB swapchain shows the shader's values (--encoding linear: the values).
A column that cannot apply (no slot can take the histogram blend) says so in its label.
)";

std::vector<double> numbers(const std::string& text, char sep, size_t count, const std::string& option) {
    std::vector<double> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, sep);) {
        try {
            size_t used = 0;
            out.push_back(std::stod(item, &used));
            if (used != item.size() || !std::isfinite(out.back())) throw std::invalid_argument(item);  // nan, inf: no view
        } catch (const std::exception&) {
            throw UsageError{option + " expects " + std::to_string(count) + " finite numbers, got `" + text + "`"};
        }
    }
    if (out.size() != count) throw UsageError{option + " expects " + std::to_string(count) + " finite numbers, got `" + text + "`"};
    return out;
}

}  // namespace

std::optional<Material> loadMaterial(const std::string& path, const Messages& m) {
    ParseResult r = parseMaterialFile(path);
    m.report(byPosition(r.diagnostics));
    return r.material;
}

std::unique_ptr<vk::Runner> makeRunner(const Messages& m) {
    std::string why;
    auto runner = vk::Runner::create(&why);
    if (!runner) *m.text << "hexc: no Vulkan device: " << why << " (install mesa-vulkan-drivers for lavapipe)\n";
    return runner;
}

void checkTexelBudget(const Material& material, const TexelBudget& budget, const Slot* only) {
    Diagnostics over;
    for (const Slot& s : material.slots) {
        if (only && s.name != only->name && !(only->heightBlend && s.name == only->heightBlend->slot)) continue;
        if (&budget == &kHistogramBudget && s.hex.blend != Blend::Histogram) continue;  // the slots it runs for
        if (std::optional<Diagnostic> d = overTexelBudget(material, s, budget)) over.push_back(*d);
    }
    if (!over.empty()) throw CompileError{over};
}

void encodeSrgb(Image& image) {
    for (size_t i = 0; i < image.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const double v = std::max(0.0, double(image.rgba[i]));
        image.rgba[i] = float(v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055);
    }
}

namespace {

// What render and preview share beyond the image: the resource layout, a template and the encoding.
struct ShowOptions {
    LayoutOptions layout;
    std::string templateFile, encoding;
    void add(CLI::App& app, const char* defaultEncoding) {
        encoding = defaultEncoding;
        app.add_option("--template", templateFile, "shade with this template instead of the material's (a .glsl file or a built-in name)")
            ->type_name("TEMPLATE");
        app.add_option("--encoding", encoding,
                       std::string("how colour is written: srgb (for display) or linear (default ") + defaultEncoding + ")")
            ->check(CLI::IsMember({"linear", "srgb"}));
        layout.add(app);
    }
    // The compile options they give; false after reporting a layout file's errors.
    bool resolve(CompileOptions& options, const Messages& m) const { return layout.resolve(options.layout, m); }
};

}  // namespace

namespace {

struct RenderArguments {
    std::string material, out, slot;
    View view{512, 512, {0, 0, 1, 1}};
    vk::RenderOutput output = vk::RenderOutput::Shaded;
    vk::ExecutedTarget target = vk::ExecutedTarget::Spirv;
    bool reference = false;
    bool quiet = false;
    ShowOptions show;
};

// `hexc render`'s command line; nullopt with `r` filled when it should run, else the exit code. -o is needed when
// `toFile`.
std::optional<int> parseRender(const std::vector<std::string>& args, RenderArguments& r, bool toFile, const Messages& m) {
    static const std::map<std::string, vk::RenderOutput> outputs = {{"shaded", vk::RenderOutput::Shaded},
                                                                    {"albedo", vk::RenderOutput::Albedo},
                                                                    {"normal", vk::RenderOutput::Normal},
                                                                    {"derivative", vk::RenderOutput::Derivative},
                                                                    {"weights", vk::RenderOutput::Weights}};
    static const std::map<std::string, vk::ExecutedTarget> targets = {
        {"spirv", vk::ExecutedTarget::Spirv}, {"hlsl", vk::ExecutedTarget::Hlsl}, {"glsl", vk::ExecutedTarget::Glsl}};
    CLI::App app(kRenderHelp, "hexc render");
    std::string size, uvRect, output = "shaded", target = "spirv";
    app.add_option("material", r.material, "the material file")->type_name("MATERIAL.json");
    app.add_option("-o,--out", r.out, "the image to write")->type_name("IMAGE.{pfm,png}");
    app.add_option("--output", output, "what to show (default: shaded, with the material's template)")
        ->check(CLI::IsMember({"shaded", "albedo", "normal", "derivative", "weights"}));
    app.add_option("--slot", r.slot,
                   "the slot albedo/normal/derivative/weights show (default: the slot\n"
                   "named albedo or normal, else the first of a fitting kind); a layered\n"
                   "material's role name shows the layers' blend of that role")
        ->type_name("NAME");
    app.add_option("--size", size, "image size in pixels (default 512x512)")->type_name("WxH");
    app.add_option("--uv-rect", uvRect, "the UV rectangle the image covers (default 0,0,1,1)")->type_name("U0,V0,U1,V1");
    app.add_option("--target,--targets", target, "the emitted source executed (HLSL and GLSL re-compiled by glslang)")
        ->check(CLI::IsMember({"spirv", "hlsl", "glsl"}));
    app.add_flag("--reference", r.reference,
                 "write the fp64 CPU reference instead (no Vulkan needed): what the\n"
                 "GPU image should be, up to texture filtering precision");
    app.add_flag("-q,--quiet", r.quiet, "no progress line on a terminal");
    r.show.add(app, "linear");
    if (std::optional<int> done = parseWith(app, args, *m.text)) return done;
    r.output = outputs.at(output);
    r.target = targets.at(target);
    if (!size.empty()) {
        const std::optional<std::pair<int, int>> wh = parseSize(size, 1, 8192);
        if (!wh) throw UsageError{"--size expects WxH with whole numbers from 1 to 8192, got " + size};
        std::tie(r.view.width, r.view.height) = *wh;
    }
    if (!uvRect.empty()) {
        auto u = numbers(uvRect, ',', 4, "--uv-rect");
        r.view.uvRect = {u[0], u[1], u[2], u[3]};
    }
    if (r.material.empty()) throw UsageError{"no material given (see hexc render --help)"};
    if (r.out.empty() && toFile) throw UsageError{"no output image given: use -o IMAGE.pfm or IMAGE.png"};
    if (!r.out.empty() && !isImageExtension(r.out)) throw UsageError{"-o " + r.out + ": hexc render writes .pfm or .png"};
    if (!r.slot.empty() && r.output == vk::RenderOutput::Shaded)
        throw UsageError{"--slot picks the slot of --output albedo, normal, derivative or weights; shaded shows the whole material"};
    if (r.reference && r.output == vk::RenderOutput::Shaded)
        throw UsageError{"--reference covers the hex-tiled slots (albedo, normal, derivative, weights), not a template's shading"};
    return std::nullopt;
}

// The fp64 reference of a layered material's role (reference/layers.h), as the GPU shows it.
Image layerRoleReference(const Material& material, size_t role, const RenderArguments& r) {
    checkTexelBudget(material, reference::kReferenceBudget);
    const reference::LayerTextures textures(material);
    const std::vector<reference::LayerResult> pixels = reference::evaluateLayersView(material, role, textures, r.view);
    const bool oneChannel = kindRow(material.layers->roles[role].kind).oneChannel;
    Image image{r.view.width, r.view.height, std::vector<float>(pixels.size() * 4)};
    for (size_t p = 0; p < pixels.size(); ++p)
        for (size_t c = 0; c < 4; ++c) image.rgba[p * 4 + c] = float(pixels[p].value[oneChannel && c < 3 ? 0 : c]);
    if (r.output == vk::RenderOutput::Normal) vk::derivativeToNormalMap(image);
    return image;
}

// The fp64 reference image of the slot (or layered material's role) `r` shows, as the GPU would show it.
Image referenceImage(const Material& material, const RenderArguments& r) {
    if (const std::optional<size_t> role = vk::layerRole(material, r.slot); role && r.output != vk::RenderOutput::Weights) {
        vk::renderedMaterial(material, r.output, r.slot);  // refuses a role of a kind the output does not show
        return layerRoleReference(material, *role, r);
    }
    const Slot& s = vk::slotForOutput(material, r.output, r.slot);
    checkTexelBudget(material, reference::kReferenceBudget, &s);
    const reference::SlotTextures textures(s);  // a histogram slot's: its Gaussian texture and table, as hexc derives them
    const reference::Heights heights(material, s);
    Image image = reference::render(s, *textures.texture, r.view,
                                    r.output == vk::RenderOutput::Weights ? reference::Output::Weights : reference::Output::Value,
                                    heights.source(), textures.lut.get());
    if (kindRow(s.kind).oneChannel && r.output != vk::RenderOutput::Weights)  // as the GPU shows a value: (s, s, s, 1)
        for (size_t i = 0; i < image.rgba.size(); i += 4)
            image.rgba[i] = image.rgba[i + 1] = image.rgba[i + 2] = image.rgba[i + size_t(s.channel)];
    if (r.output == vk::RenderOutput::Normal) vk::derivativeToNormalMap(image);
    return image;
}

}  // namespace

namespace {

// shownMaterial, its note printed as the command line says it, with what picks another template.
// Refuses (HX208) a template that reads none of the material's slots: its picture would show nothing of them.
Material shownWithNote(const Material& material, const std::string& templateName, const CompileOptions& options, const Messages& m) {
    std::string note;
    Material shown = vk::shownMaterial(material, templateName, options, &note);
    if (!note.empty()) *m.text << "hexc: note: " << note << " (--template picks another)\n";
    if (Diagnostics none = checkTemplateReadsSlots(shown, options); !none.empty()) throw CompileError{none};
    return shown;
}

}  // namespace

// The image of `hexc render`'s arguments `r`, or the exit code when there is none.
std::variant<Image, int> renderedImage(RenderArguments& r, const Messages& m) {
    auto material = loadMaterial(r.material, m);
    if (!material) return int(kInvalidInput);
    Progress progress(2, r.quiet);
    const std::string size = std::to_string(r.view.width) + "x" + std::to_string(r.view.height);
    CompileOptions options;
    if (!r.show.resolve(options, m)) return int(kInvalidInput);
    Image image;
    if (r.reference) {
        progress.step("computing the fp64 reference, " + size + " pixels");
        image = referenceImage(*material, r);
    } else {
        if (r.output == vk::RenderOutput::Shaded) *material = shownWithNote(*material, r.show.templateFile, options, m);
        checkTexelBudget(*material, vk::kRenderBudget);
        auto runner = makeRunner(m);
        if (!runner) return int(kNoVulkan);
        progress.step("rendering " + size + " pixels on " + runner->deviceName());
        image = vk::render(*runner, *material, r.output, r.slot, r.view, r.target, 0, nullptr, {}, options);
    }
    if (r.show.encoding == "srgb") encodeSrgb(image);
    return image;
}

int render(const std::vector<std::string>& args, const Messages& m, Image* into) {
    RenderArguments r;
    return guarded(r.material, m, [&] {
        if (std::optional<int> done = parseRender(args, r, !into, m)) return *done;
        std::variant<Image, int> image = renderedImage(r, m);
        if (const int* code = std::get_if<int>(&image)) return *code;
        if (into) {
            *into = std::move(std::get<Image>(image));
            return int(kOk);
        }
        writeImage(std::get<Image>(image), r.out);
        return int(kOk);
    });
}

int renderCommand(const std::vector<std::string>& args) { return render(args, {}, nullptr); }

// Whether a slot can take a blend other than its own: hex-tiled colour and scalar slots blending every tap without
// height blending (the parser's rules).
bool takesBlend(const Slot& s) {
    return s.hex.enabled && kindRow(s.kind).mayUseHistogram && s.hex.taps != 1 && !s.hex.adaptive() && !s.heightBlend;
}

Material withBlend(Material material, Blend blend) {
    if (material.layers) return material;  // a layered material's layers take no histogram blend
    for (Slot& s : material.slots)
        if (takesBlend(s)) s.hex.blend = blend;
    return material;
}

// A cell's label: on one line at scale 2 where it fits the cell, else on two lines at scale 1.
void labelCell(Image& sheet, int x0, int y0, int cell, const std::string& column, const std::string& row) {
    std::string line = column + ", " + row;
    if (stb_easy_font_width(line.data()) * 2 <= cell - 12) return drawLabel(sheet, x0 + 6, y0 + 6, line, 2);
    drawLabel(sheet, x0 + 6, y0 + 6, column + "\n" + row, 1);
}

// The preview sheet: plain tiling, both hex blends and the hex weights (columns) at two distances (rows), labelled;
// each cell rendered under `options`, sRGB-encoded when `srgb`.
Image previewSheet(vk::Runner& runner, const Material& material, int cell, const CompileOptions& options, bool srgb, Progress& progress) {
    const Material plain = vk::plainTiled(material);
    const Material falloff = withBlend(material, Blend::Falloff), histogram = withBlend(material, Blend::Histogram);
    const bool histogramApplies = !material.layers && std::any_of(material.slots.begin(), material.slots.end(), takesBlend);
    struct Column {
        std::string label;
        const Material* material;
        vk::RenderOutput output;
    };
    const Column columns[] = {{"plain", &plain, vk::RenderOutput::Shaded},
                              {"falloff", &falloff, vk::RenderOutput::Shaded},
                              {histogramApplies ? "histogram" : "histogram n/a: no slot takes it", &histogram, vk::RenderOutput::Shaded},
                              {"weights", &material, vk::RenderOutput::Weights}};
    const std::pair<const char*, double> rows[] = {{"uv 0..0.5", 0.5}, {"uv 0..4", 4.0}};  // label, UV extent
    const int band = 28;
    Image sheet;
    sheet.width = 4 * cell;
    sheet.height = 2 * (cell + band);
    sheet.rgba.assign(size_t(sheet.width) * sheet.height * 4, 0.12f);  // dark grey bands behind the labels
    for (size_t i = 3; i < sheet.rgba.size(); i += 4) sheet.rgba[i] = 1.0f;
    for (int r = 0; r < 2; ++r) {
        for (int c = 0; c < 4; ++c) {
            progress.step("rendering " + columns[c].label + ", " + rows[r].first);
            View view{cell, cell, {0, 0, rows[r].second, rows[r].second}};
            Image img =
                vk::render(runner, *columns[c].material, columns[c].output, "", view, vk::ExecutedTarget::Spirv, 0, nullptr, {}, options);
            if (srgb) encodeSrgb(img);
            int y0 = r * (cell + band) + band;
            for (int y = 0; y < cell; ++y)
                for (int x = 0; x < cell; ++x) std::copy_n(img.at(x, y), 4, sheet.at(c * cell + x, y0 + y));
            labelCell(sheet, c * cell, r * (cell + band), cell, columns[c].label, rows[r].first);
        }
    }
    return sheet;
}

int preview(const std::vector<std::string>& args, const Messages& m, Image* into) {
    std::string materialPath;
    return guarded(materialPath, m, [&] {
        std::string out;
        int cell = 256;
        bool quiet = false;
        ShowOptions show;
        CLI::App app(kPreviewHelp, "hexc preview");
        app.add_option("material", materialPath, "the material file")->type_name("MATERIAL.json");
        app.add_option("-o,--out", out, "the PNG to write")->type_name("PREVIEW.png");
        app.add_option("--cell", cell, "each cell's size in pixels (default 256)")->check(CLI::Range(32, 2048))->type_name("N");
        app.add_flag("-q,--quiet", quiet, "no progress line on a terminal");
        show.add(app, "srgb");
        if (std::optional<int> done = parseWith(app, args, *m.text)) return *done;
        if (materialPath.empty()) throw UsageError{"no material given (see hexc preview --help)"};
        if (out.empty() && !into) throw UsageError{"no output image given: use -o PREVIEW.png"};
        if (!out.empty() && !isImageExtension(out)) throw UsageError{"-o " + out + ": hexc preview writes .png or .pfm"};
        auto material = loadMaterial(materialPath, m);
        if (!material) return int(kInvalidInput);
        CompileOptions options;
        if (!show.resolve(options, m)) return int(kInvalidInput);
        const Material shown = shownWithNote(*material, show.templateFile, options, m);
        checkTexelBudget(shown, vk::kRenderBudget);
        checkTexelBudget(withBlend(shown, Blend::Histogram), kHistogramBudget);  // its histogram column
        auto runner = makeRunner(m);
        if (!runner) return int(kNoVulkan);

        Progress progress(9, quiet);
        Image sheet = previewSheet(*runner, shown, cell, options, show.encoding == "srgb", progress);
        if (into) {
            *into = std::move(sheet);
            return int(kOk);
        }
        progress.step("writing " + out);
        writeImage(sheet, out);
        return int(kOk);
    });
}

int previewCommand(const std::vector<std::string>& args) { return preview(args, {}, nullptr); }

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

}  // namespace hexc::cli
