#include "bake.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>

#include "hexc/image_files.h"
#include "options.h"
#include "progress.h"
#include "render.h"
#include "vk/render.h"

namespace hexc::cli {

namespace {

const char* const kBakeHelp = R"(hexc bake - bake each slot into a texture that repeats seamlessly, with hex-tiling's variety inside

For engines and pipelines that cannot run the hex-tiling shader: each slot of MATERIAL is rendered on Vulkan
(Mesa lavapipe) by hexc's own shader with a periodic lattice over K = --repeats repeats of its texture, so the
N x N result repeats seamlessly (its right edge continues its left, its bottom its top). The lattice is stable
mode's, its skew rounded so that it repeats over K (tiles stretched along u by at most 1 / (6.9 K): 1.0% at K = 4);
tile ids are wrapped before they are hashed. Written into DIR:
  DIR/<name>.<slot>.png       in its texture's format: PNG 8 or 16 bits (.png), OpenEXR (.exr), PFM (.pfm) or
  (.exr, .pfm, .ktx2)         KTX2 (.ktx2: RGBA8 UNORM or sRGB, RGBA32 float, with a full mip chain of 2x2 box
                              averages, sRGB ones in linear light); others (JPEG, DDS, compressed KTX2, ...) as
                              8-bit PNG; 8-bit files sRGB-encoded when the slot is sRGB, float files linear;
                              normal slots in the slot's convention (green down with flip_y); a scalar slot as
                              grey
  DIR/<name>_baked.json       a material that tiles them plainly ("enabled": false), each slot's tiling
                              divided by K, so a surface shows the same texel density as before
Not the compile flag --bake, which folds a material's settings into its shader's code.
Refused (HX134): layered materials, triplanar projection, paper and materialx modes, the noise masks.
)";

struct BakeArguments {
    std::string material, out, size, repeats = "4";
    bool quiet = false;
};

// A whole number from `least` to `most`, else a usage error naming the option.
int wholeNumber(const std::string& text, int least, int most, const std::string& option) {
    size_t used = 0;
    long value = 0;
    try {
        value = std::stol(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size() || value < least || value > most)
        throw UsageError{option + " expects a whole number from " + std::to_string(least) + " to " + std::to_string(most) + ", got `" +
                         text + "`"};
    return int(value);
}

std::optional<int> parseBake(const std::vector<std::string>& args, BakeArguments& b, const Messages& m) {
    CLI::App app(kBakeHelp, "hexc bake");
    app.add_option("material", b.material, "the material file")->type_name("MATERIAL.json");
    app.add_option("-o,--out", b.out, "the folder to write the textures and the baked material into")->type_name("DIR");
    app.add_option("--size", b.size, "each texture's width and height in pixels, 1 to 8192 (required)")->type_name("N");
    app.add_option("--repeats", b.repeats, "K, the slot's texture repeats across the bake, 1 to 64 (default 4)")->type_name("K");
    app.add_flag("-q,--quiet", b.quiet, "no progress line on a terminal");
    if (std::optional<int> done = parseWith(app, args, *m.text)) return done;
    if (b.material.empty()) throw UsageError{"no material given (see hexc bake --help)"};
    if (b.out.empty()) throw UsageError{"no output folder given: use -o DIR"};
    if (b.size.empty()) throw UsageError{"no size given: use --size N (the baked textures' width and height)"};
    return std::nullopt;
}

// The refusal of slot `index` for `what`, at the slot.
Diagnostic refusal(const Material& material, size_t index, const std::string& what) {
    const Slot& s = material.slots[index];
    return Diagnostic::make(Code::BakeUnsupported, {material.sourceFile.string(), s.line, s.col}, "/slots/" + std::to_string(index),
                            "slot `" + s.name + "`: hexc bake cannot make " + what + " periodic",
                            "hexc bake takes stable mode with the hex or checker mask on the uv projection, or plain tiling");
}

// The format a slot's bake is written in: its texture's (PNG 8 or 16 bits, OpenEXR, PFM, KTX2 8-bit or float RGBA),
// else 8-bit PNG.
ImageFormat bakedFormat(const Slot& slot) {
    const ImageFormat format = slot.file ? imageFormat(slot.file->bytes) : ImageFormat::Other;
    return format == ImageFormat::Other ? ImageFormat::Png8 : format;
}

// Float files hold linear values, as hexc reads them.
bool floatFormat(ImageFormat format) {
    return format == ImageFormat::Exr || format == ImageFormat::Pfm || format == ImageFormat::Ktx2Float;
}

std::string bakedFile(const Material& material, const Slot& s) { return material.name + "." + s.name + imageExtension(bakedFormat(s)); }

// The baked material's slot `s`: its baked texture, tiled plainly at 1/K of its tiling.
nlohmann::ordered_json bakedSlot(const Material& material, const Slot& s, int repeats) {
    nlohmann::ordered_json j;
    j["name"] = s.name;
    j["kind"] = std::string(toString(s.kind));
    j["texture"] = bakedFile(material, s);
    if (!s.role.empty()) j["role"] = s.role;
    if (kindRow(s.kind).derivative)
        j["flip_y"] = s.flipY;
    else
        j["colorspace"] = std::string(toString(floatFormat(bakedFormat(s)) ? ColorSpace::Linear : s.colorSpace));
    if (kindRow(s.kind).oneChannel) j["channel"] = "r";  // written as grey
    j["hextiling"] = {{"enabled", false}, {"tiling", {s.hex.tiling[0] / repeats, s.hex.tiling[1] / repeats}}};
    return j;
}

// The baked material, its template named as the source does (a template file relative to `dir`).
std::string bakedMaterial(const Material& material, int repeats, const std::filesystem::path& dir) {
    nlohmann::ordered_json j;
    j["name"] = material.name.substr(0, 58) + "_baked";
    const std::filesystem::path templ = std::filesystem::absolute(material.templ.name).lexically_normal();
    j["template"] = material.templ.file ? templ.lexically_relative(std::filesystem::absolute(dir)).generic_string() : material.templ.name;
    j["slots"] = nlohmann::ordered_json::array();
    for (const Slot& s : material.slots) j["slots"].push_back(bakedSlot(material, s, repeats));
    return j.dump(2) + "\n";
}

}  // namespace

Diagnostics bakeRefusals(const Material& material) {
    Diagnostics out;
    if (material.layers)
        return {Diagnostic::make(Code::BakeUnsupported, {material.sourceFile.string()}, "/layers",
                                 "hexc bake cannot bake a layered material (its splat maps do not repeat with the lattice)")};
    for (size_t i = 0; i < material.slots.size(); ++i) {
        const HexTiling& h = material.slots[i].hex;
        if (!h.enabled) continue;  // plain tiling repeats with its texture
        if (h.projection == Projection::Triplanar)
            out.push_back(refusal(material, i, "the triplanar projection"));
        else if (h.mode != HashMode::Stable)
            out.push_back(refusal(material, i, "mode `" + std::string(toString(h.mode)) + "`"));
        else if (h.mask == Mask::Noise || h.mask == Mask::Noise3)  // copies turned about the st origin: no period
            out.push_back(refusal(material, i, "the `" + std::string(toString(h.mask)) + "` mask"));
    }
    return out;
}

View bakeView(const Slot& slot, int size, int repeats) {
    return {size, size, {0, 0, repeats / slot.hex.tiling[0], repeats / slot.hex.tiling[1]}};
}

Image bakeSlot(vk::Runner& runner, const Material& material, const Slot& slot, int size, int repeats) {
    const bool normal = kindRow(slot.kind).derivative;
    CompileOptions options;
    options.periodicRepeats = repeats;
    Image image = vk::render(runner, material, normal ? vk::RenderOutput::Normal : vk::RenderOutput::Albedo, slot.name,
                             bakeView(slot, size, repeats), vk::ExecutedTarget::Spirv, 0, nullptr, {}, options);
    if (normal && slot.flipY)
        for (size_t i = 1; i < image.rgba.size(); i += 4) image.rgba[i] = 1.0f - image.rgba[i];  // green down
    if (!normal && slot.colorSpace == ColorSpace::Srgb && !floatFormat(bakedFormat(slot))) encodeSrgb(image);
    return image;
}

int bakeCommand(const std::vector<std::string>& args) {
    const Messages m;
    BakeArguments b;
    return guarded(b.material, m, [&] {
        if (std::optional<int> done = parseBake(args, b, m)) return *done;
        const int size = wholeNumber(b.size, 1, 8192, "--size"), repeats = wholeNumber(b.repeats, 1, 64, "--repeats");
        std::optional<Material> material = loadMaterial(b.material, m);
        if (!material) return int(kInvalidInput);
        if (Diagnostics refused = bakeRefusals(*material); !refused.empty()) throw CompileError{refused};
        checkTexelBudget(*material, vk::kRenderBudget);
        auto runner = makeRunner(m);
        if (!runner) return int(kNoVulkan);
        Progress progress(material->slots.size() + 1, b.quiet);
        std::vector<Image> images;  // every slot baked before anything is written: no half-written bake
        for (const Slot& s : material->slots) {
            progress.step("baking " + s.name + ", " + std::to_string(size) + "x" + std::to_string(size) + " pixels on " +
                          runner->deviceName());
            images.push_back(bakeSlot(*runner, *material, s, size, repeats));
        }
        progress.step("writing " + b.out);
        std::filesystem::create_directories(b.out);
        for (size_t i = 0; i < images.size(); ++i)
            writeImageAs(images[i], bakedFormat(material->slots[i]),
                         std::filesystem::path(b.out) / bakedFile(*material, material->slots[i]));
        writeAtomically(b.out, material->name + "_baked.json", bakedMaterial(*material, repeats, b.out));
        return int(kOk);
    });
}

}  // namespace hexc::cli
