// Histogram tables as PFM (or EXR) and packed textures as PNG, each through the shader cache.
#include "precompute/derived.h"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "hexc/budgets.h"
#include "hexc/cache.h"
#include "hexc/hash.h"
#include "hexc/histogram.h"
#include "hexc/image.h"
#include "hexc/image_files.h"

namespace hexc {
namespace {

nlohmann::json binary(std::string_view bytes) { return nlohmann::json::binary(std::vector<uint8_t>(bytes.begin(), bytes.end())); }

// A histogram slot's derived textures (hexc/histogram.h) as PFM files' bytes: float32 keeps T and its inverse exact,
// and hexc reads and writes PFM byte for byte. A texture that cannot be read stops the compile.
HistogramTransform transformOf(const Material& material, const Slot& s) {
    if (std::optional<Diagnostic> d = overTexelBudget(material, s, kHistogramBudget)) throw CompileError{{*d}};
    try {
        return histogramTransform(decodeTexture(*s.file, s.colorSpace == ColorSpace::Srgb), s);
    } catch (const TextureError& e) {
        throw CompileError{{Diagnostic::make(Code::TextureUnreadable, {material.sourceFile.string()}, "", e.what())}};
    }
}

// The source texture is gone once the transform exists, and each texture's floats move into the image written (a
// large texture's intermediate copies are what its memory goes to). `exr`: OpenEXR's bytes (CompileOptions::exrTables).
nlohmann::json histogramFiles(const Material& material, const Slot& s, bool exr) {
    HistogramTransform t = transformOf(material, s);
    nlohmann::json files;
    for (auto& [which, texture] : {std::pair{"gaussian", &t.gaussian}, std::pair{"lut", &t.lut}}) {
        const Image image{texture->width, texture->height, std::move(texture->rgba32f)};
        files[which] = binary(exr ? exrBytes(image) : pfmBytes(image));
    }
    return files;
}

// Everything a slot's derived textures depend on: the texture's bytes, how they are decoded (the file's extension, the
// colour space) and which channels are transformed (kind, channel), the files' format, and hexc's build.
std::string histogramKey(const Slot& s, bool exr) {
    ContentHash h;
    for (const std::string& part :
         {std::string("hexc histogram 1"), std::string(version()), buildId(), s.file->bytes, s.texturePath.extension().string(),
          std::string(toString(s.colorSpace)), std::string(toString(s.kind)), std::to_string(s.channel), std::string(exr ? "exr" : "pfm")})
        h.add(part);
    return h.hex();
}

// Whether `bytes` are a whole RGB PFM file as pfmBytes writes it (its header, then width x height float triples), of
// `width` texels a row if given.
bool wholePfm(const std::vector<uint8_t>& bytes, int width = 0) {
    const std::string text(bytes.begin(), bytes.begin() + std::ptrdiff_t(std::min<size_t>(bytes.size(), 64)));
    int w = 0, h = 0, read = 0;
    // The header's last newline is matched by hand: a "\n" in the format takes any whitespace, so the first float's
    // bytes would go with it when they begin with one (0x09-0x0d, 0x20).
    if (std::sscanf(text.c_str(), "PF\n%d %d\n-1.0%n", &w, &h, &read) != 2 || read == 0 || size_t(read) >= text.size() ||
        text[size_t(read)] != '\n' || w <= 0 || h <= 0)
        return false;
    ++read;
    return (width == 0 || w == width) && bytes.size() == size_t(read) + size_t(w) * size_t(h) * 12;
}

// A cache entry's two tables, or nothing when its payload is not two whole PFM files (another format, or damage that
// kept its checksum): the table kHistogramLutWidth entries wide. EXR tables are taken by their signature.
std::optional<nlohmann::json> histogramEntry(const std::string& payload, bool exr) {
    nlohmann::json files = nlohmann::json::from_cbor(payload, true, false);
    const auto holds = [&](const char* which, int width) {
        if (!files.is_object() || !files.contains(which) || !files[which].is_binary()) return false;
        const std::vector<uint8_t>& bytes = files[which].get_binary();
        return exr ? imageFormat(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size())) == ImageFormat::Exr
                   : wholePfm(bytes, width);
    };
    if (!holds("gaussian", 0) || !holds("lut", kHistogramLutWidth)) return std::nullopt;
    return files;
}

void addHistogramFiles(const Material& material, const ShaderPlan& plan, ShaderCache* cache, std::vector<OutputFile>& out) {
    for (size_t i : plan.luts) {
        const Slot& s = *plan.slots[i].slot;
        const bool exr = plan.exrTables;
        auto compute = [&]() -> std::optional<std::string> {
            const std::vector<uint8_t> cbor = nlohmann::json::to_cbor(histogramFiles(material, s, exr));
            return std::string(cbor.begin(), cbor.end());
        };
        const auto usable = [exr](const std::string& payload) { return histogramEntry(payload, exr).has_value(); };
        const std::optional<std::string> cached = cache ? cache->getOrCompute(histogramKey(s, exr), compute, usable) : compute();
        nlohmann::json files = histogramEntry(*cached, exr).value();  // computed here, or a folder entry `usable` accepted
        for (const char* which : {"gaussian", "lut"}) {
            const auto& bytes = files[which].get_binary();
            out.push_back({histogramFileName(material.name, s.name, which, exr), std::string(bytes.begin(), bytes.end())});
        }
    }
}

// A pack's texture (docs/material-format.md#pack) as PNG bytes: each slot's 8-bit texels, decoded from the file the
// parser read (the plan packed it from the same bytes' header), copied into the pack's channels; alpha 255 where no slot fills it, the other unused channels 0. Level 0 only:
// the mip chain is the engine's to build, as for any texture.
std::string packedPng(const Material& material, const ShaderPlan& plan, const PackPlan& p) {
    Texture packed{p.width, p.height, p.srgb, std::vector<uint8_t>(size_t(p.width) * p.height * 4, 0), {}};
    for (size_t k = 3; k < packed.rgba8.size(); k += 4) packed.rgba8[k] = 255;
    for (size_t k = 0; k < p.slots.size(); ++k) {
        const Slot& s = *plan.slots[p.slots[k]].slot;
        Texture source;
        try {
            source = decodeTexture(*s.file, false);
        } catch (const TextureError& e) {
            throw CompileError{{Diagnostic::make(Code::TextureUnreadable, {material.sourceFile.string()}, "", e.what())}};
        }
        // To: the pack's channels (the plan's packedChannel, 0 for RGB); from: the slot's (a colour slot's RGB, a scalar's channel).
        const size_t to = size_t(plan.slots[p.slots[k]].packedChannel), count = p.channels[k].size();
        const size_t from = kindRow(s.kind).oneChannel ? size_t(s.channel) : 0;
        for (size_t t = 0; t < packed.rgba8.size(); t += 4)
            for (size_t c = 0; c < count; ++c) packed.rgba8[t + to + c] = source.rgba8[t + from + c];
    }
    return pngBytes(packed);
}

// Everything a packed texture depends on: its slots' textures' bytes and extensions (how they decode), which channels
// go where, and hexc's build.
std::string packedKey(const ShaderPlan& plan, const PackPlan& p) {
    ContentHash h;
    for (const std::string& part : {std::string("hexc packed texture 1"), std::string(version()), buildId()}) h.add(part);
    for (size_t k = 0; k < p.slots.size(); ++k) {
        const Slot& s = *plan.slots[p.slots[k]].slot;
        for (const std::string& part :
             {s.file->bytes, s.texturePath.extension().string(), std::string(toString(s.kind)), std::to_string(s.channel), p.channels[k]})
            h.add(part);
    }
    return h.hex();
}

void addPackedFiles(const Material& material, const ShaderPlan& plan, ShaderCache* cache, std::vector<OutputFile>& out) {
    for (const PackPlan& p : plan.packs) {
        auto compute = [&]() -> std::optional<std::string> { return packedPng(material, plan, p); };
        // An entry is used if it is a PNG of the pack's size: its signature, then IHDR's big-endian width and height.
        const auto usable = [&](const std::string& png) {
            const auto at = [&](size_t i) {
                return uint32_t(uint8_t(png[i])) << 24 | uint32_t(uint8_t(png[i + 1])) << 16 | uint32_t(uint8_t(png[i + 2])) << 8 |
                       uint8_t(png[i + 3]);
            };
            return png.size() > 24 && png.starts_with("\x89PNG\r\n\x1a\n") && png.compare(12, 4, "IHDR") == 0 &&
                   at(16) == uint32_t(p.width) && at(20) == uint32_t(p.height);
        };
        const std::optional<std::string> bytes = cache ? cache->getOrCompute(packedKey(plan, p), compute, usable) : compute();
        out.push_back({packedFileName(material.name, plan.slots[p.slots.front()].slot->name), *bytes});
    }
}

}  // namespace

std::vector<OutputFile> derivedTextureFiles(const Material& material, const ShaderPlan& plan, ShaderCache* cache) {
    std::vector<OutputFile> files;
    addHistogramFiles(material, plan, cache, files);
    addPackedFiles(material, plan, cache, files);
    return files;
}

}  // namespace hexc
