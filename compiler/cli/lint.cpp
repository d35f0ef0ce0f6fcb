#include "lint.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include "hexc/lint.h"
#include "hexc/materialx.h"
#include "hexc/suggest.h"
#include "options.h"
#include "render.h"
#include "textures/lint_measures.h"

namespace hexc::cli {

namespace {

const char* const kLintHelp = R"(hexc lint - check what hex-tiling needs of a material's textures

  hexc lint MATERIAL.json|.mtlx        every slot's texture, as its slot reads it
  hexc lint TEXTURE [--kind K] [--flip-y] [--channel C]    one texture

Prints each texture's figures and, as warnings, the checks it fails (docs/lint.md): a normal map whose green
convention is not the declared one (HX130: its slopes curl, as no height field's do), a normal map whose average
normal leans (HX131), a texture that does not tile (HX132: its wrap-around edge differs more than its interior),
texels that are NaN or infinite (HX133). A compile reports the same warnings; a slot's `lint_skip` silences them.
With --image, also a picture of the report: per texture, the texture tiled 2 x 2 about its wrap-around edges (a seam
shows as a cross in the middle) and, for a normal map, its curl read as declared and with green flipped.
Exit 0 when every check passes, 1 when one warns or an input is invalid.
)";

constexpr int kPanel = 256, kBand = 40;  // the picture's panels and the label band above each row

// The figures of one texture, a line a check, each saying whether it passes.
std::string figureLines(const TextureFigures& f, bool warnedGreen, bool warnedTilt, bool warnedSeam) {
    auto verdict = [](bool warned) { return warned ? "WARNING\n" : "ok\n"; };
    if (!f.skipped.empty()) return "  not checked: " + f.skipped + "\n";
    if (f.nonFinite > 0) return "  not checked: " + std::to_string(f.nonFinite) + " texels are not finite\n";
    std::string out;
    if (f.curlDeclared)
        out += "  green  curl " + figure(*f.curlDeclared, 3) + " as declared, " + figure(*f.curlOther, 3) + " flipped (warns at " +
               figure(LintLimits::kCurlRatio, 1) + "x flipped and " + figure(LintLimits::kCurlFloor, 2) + "): " + verdict(warnedGreen);
    if (f.tiltDegrees)
        out += "  tilt   " + figure(*f.tiltDegrees, 2) + " degrees (warns over " + figure(LintLimits::kTiltDegrees, 0) +
               "): " + verdict(warnedTilt);
    if (f.seam)
        out += "  seam   edge " + figure((*f.seam)[0], 2) + "x (left/right), " + figure((*f.seam)[1], 2) +
               "x (top/bottom) the interior (warns over " + figure(LintLimits::kSeamRatio, 1) + "): " + verdict(warnedSeam);
    return out;
}

// One panel of the picture: texel (x, y) of `at` for pixel (i, j), `periods` periods across, starting `shift` in.
template <typename Texel>
void panel(Image& image, int x0, int y0, int w, int h, double periods, double shift, const Texel& at) {
    for (int j = 0; j < kPanel; ++j)
        for (int i = 0; i < kPanel; ++i) {
            const int x = int(std::floor((i + 0.5) / kPanel * periods * w + shift * w)) % w;
            const int y = int(std::floor((j + 0.5) / kPanel * periods * h + shift * h)) % h;
            const std::array<float, 3> c = at(x, y);
            float* p = image.at(x0 + i, y0 + j);
            p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 1;
        }
}

// A row of the picture for one slot's texture: the texture 2 x 2 about its edges, and a normal map's |curl| as declared
// and flipped on one scale (white at three times the larger root mean square).
void reportRow(Image& image, int y0, const Slot& s, const Texture& t, const TextureFigures& f) {
    const int w = t.width, h = t.height;
    panel(image, 0, y0 + kBand, w, h, 2, 0.5, [&](int x, int y) {
        std::array<float, 3> c;
        for (int k = 0; k < 3; ++k)
            c[size_t(k)] = t.isFloat() ? t.rgba32f[(size_t(y) * w + x) * 4 + k] : t.rgba8[(size_t(y) * w + x) * 4 + k] / 255.0f;
        return c;
    });
    std::string label = s.texture + "  " + std::to_string(w) + "x" + std::to_string(h);
    if (f.seam) label += "\nseam " + figure((*f.seam)[0], 2) + "x, " + figure((*f.seam)[1], 2) + "x";
    if (f.tiltDegrees) label += "\ntilt " + figure(*f.tiltDegrees, 2) + " degrees";
    drawLabel(image, 6, y0 + 4, label, 1);
    if (!f.curlDeclared) return;
    const lint::Slopes pq = lint::slopes(t, s.flipY, int(s.file->info.channelNames.size()));
    double jacobian = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const auto d = lint::derivatives(pq, w, h, x, y);
            jacobian += d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + d[3] * d[3];
        }
    const double white = 2 * std::sqrt(std::max(jacobian / (double(w) * h), 1e-18));
    for (int sign : {1, -1}) {
        const int x0 = sign > 0 ? kPanel : 2 * kPanel;
        panel(image, x0, y0 + kBand, w, h, 1, 0, [&](int x, int y) {
            const auto d = lint::derivatives(pq, w, h, x, y);
            const float v = float(std::min(1.0, std::abs(sign * d[0] - d[1]) / white));
            return std::array<float, 3>{v, v, v};
        });
        const char* green = (sign > 0) != s.flipY ? "green up" : "green down";
        drawLabel(image, x0 + 6, y0 + 4,
                  std::string(sign > 0 ? "|curl| as declared, " : "|curl| flipped, ") + green + "\n" +
                      figure(sign > 0 ? *f.curlDeclared : *f.curlOther, 3),
                  1);
    }
}

// The picture with a row for the slot below what it holds (dark grey behind the labels and empty panels).
void addRow(Image& picture, const Slot& s, const TextureFigures& f) {
    const int y0 = picture.height;
    picture.width = 3 * kPanel, picture.height += kBand + kPanel;
    picture.rgba.resize(size_t(picture.width) * picture.height * 4, 0.12f);
    for (int y = y0; y < picture.height; ++y)
        for (int x = 0; x < picture.width; ++x) picture.at(x, y)[3] = 1;
    reportRow(picture, y0, s, decodeTexture(*s.file, false, s.textureLayer), f);
}

// One slot: its heading and figures to stdout, its warnings to stderr, its row of the picture when there is one;
// whether it warned.
bool lintSlot(const Slot& s, const std::string& heading, const SourceLoc& at, const std::string& path, Image* picture) {
    const TextureFigures f = measureSlot(s);
    const Diagnostics warnings = lintWarnings(s, f, at, path);
    auto warned = [&](Code code) {
        for (const Diagnostic& d : warnings)
            if (d.code == code) return true;
        return false;
    };
    std::string kind(toString(s.kind));
    if (kindRow(s.kind).derivative) kind += s.flipY ? ", green down" : ", green up";
    if (kindRow(s.kind).oneChannel) kind += std::string(", channel ") + "rgba"[s.channel];
    std::cout << heading << s.width << "x" << s.height << ", " << kind << "\n"
              << figureLines(f, warned(Code::NormalGreen), warned(Code::NormalTilt), warned(Code::TextureSeam)) << std::flush;
    std::cerr << formatAll(warnings) << std::flush;
    if (picture && f.skipped.empty() && f.nonFinite == 0) addRow(*picture, s, f);
    return !warnings.empty();
}

// A texture file on its own, read as a slot of `kind` would read it.
int lintTexture(const std::filesystem::path& file, SlotKind kind, bool flipY, int channel, Image* picture) {
    std::string error;
    std::optional<TextureFile> read = readTextureFile(file, &error);
    if (!read) {
        std::cerr << formatAll({Diagnostic::make(Code::TextureUnreadable, {file.string()}, "", error)});
        return kInvalidInput;
    }
    Slot s;
    s.texture = file.string(), s.texturePath = file, s.kind = kind, s.flipY = flipY, s.channel = channel;
    s.width = read->info.width, s.height = read->info.height;
    s.file = std::make_shared<const TextureFile>(std::move(*read));
    return lintSlot(s, file.string() + ": ", {file.string()}, "", picture) ? kInvalidInput : kOk;
}

int lintMaterialFile(const std::filesystem::path& file, Image* picture) {
    ParseResult parsed = parseMaterialFile(file);
    std::cerr << formatAll(parsed.diagnostics);
    if (!parsed.material) return kInvalidInput;
    const Material& m = *parsed.material;
    bool warned = false;
    for (const Slot& s : m.slots)
        warned |= lintSlot(s, file.string() + ": slot `" + s.name + "`: " + s.texture + ", ", {m.sourceFile.string(), s.line, s.col},
                           texturePointer(m, s), picture);
    return warned ? kInvalidInput : kOk;
}

}  // namespace

int lintCommand(const std::vector<std::string>& args) {
    CLI::App app{kLintHelp, "hexc lint"};
    std::filesystem::path input, imageFile;
    std::string kind = "color", channel = "r";
    bool flipY = false;
    app.add_option("input", input, "a material (JSON or MaterialX), or a texture")->required()->type_name("MATERIAL|TEXTURE");
    app.add_option("--kind", kind, "a texture's slot kind: color, scalar or normal (a material's slots say theirs)")
        ->check(CLI::IsMember({"color", "scalar", "normal"}))
        ->capture_default_str();
    app.add_flag("--flip-y", flipY, "a normal texture's green points down (DirectX), as a slot's flip_y");
    app.add_option("--channel", channel, "a scalar texture's channel: r, g, b or a")
        ->check(CLI::IsMember({"r", "g", "b", "a"}))
        ->capture_default_str();
    app.add_option("--image", imageFile, "also write the report as a picture (PNG)")->type_name("REPORT.png");
    if (std::optional<int> done = parseWith(app, args)) return *done;
    if (!imageFile.empty() && lowerCase(imageFile.extension().string()) != ".png") {
        std::cerr << "hexc: --image " << imageFile.string() << ": expected a file name ending in .png\n";
        return kUsage;
    }
    Image picture;
    const SlotKind k = kind == "normal" ? SlotKind::Normal : kind == "scalar" ? SlotKind::Scalar : SlotKind::Color;
    const int code = input.extension() == ".json" || isMaterialXFile(input)
                         ? lintMaterialFile(input, imageFile.empty() ? nullptr : &picture)
                         : lintTexture(input, k, flipY, int(std::string("rgba").find(channel)), imageFile.empty() ? nullptr : &picture);
    if (imageFile.empty() || picture.height == 0) return code;
    try {
        writeImage(picture, imageFile);
    } catch (const std::exception& e) {
        std::cerr << "hexc: " << e.what() << "\n";
        return kWriteFailed;
    }
    return code;
}

}  // namespace hexc::cli
