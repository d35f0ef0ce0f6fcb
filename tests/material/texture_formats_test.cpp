// KTX2, DDS and OpenEXR textures from a small generator: their headers as compiling reads them, their texels as
// render and preview decode them, and the located errors for what hexc does not read.
#include <gtest/gtest.h>
#include <tinyexr.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "hexc/compiler.h"
#include "hexc/engines.h"
#include "hexc/image.h"
#include "hexc/material.h"
#include "support.h"
#include "vk/render.h"

namespace fs = std::filesystem;
using namespace hexc;

namespace {

void put32(std::vector<unsigned char>& b, size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + size_t(i)] = (unsigned char)(v >> (8 * i));
}

// Texels that differ in every channel, so a swapped or shifted channel shows.
std::vector<unsigned char> texels(int w, int h) {
    std::vector<unsigned char> t(size_t(w) * h * 4);
    for (size_t i = 0; i < t.size(); ++i) t[i] = (unsigned char)(i * 37 + (i % 4) * 11);
    return t;
}

fs::path dir() {
    fs::path d = fs::temp_directory_path() / "hexc_texture_formats";
    fs::create_directories(d);
    return d;
}

fs::path save(const std::string& name, const std::vector<unsigned char>& bytes) {
    std::ofstream(dir() / name, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return dir() / name;
}

// KTX2 with one level: the 80-byte header and index, one level entry, then level 0 (a reader needs no more); an array
// of `layers` layers (level 0 holds them one after another) when layers > 0, a cube with `faces` 6.
fs::path ktx2(const std::string& name, uint32_t vkFormat, int w, int h, const std::vector<unsigned char>& data, uint32_t levels = 1,
              uint32_t layers = 0, uint32_t faces = 1) {
    std::vector<unsigned char> b(112, 0);
    const unsigned char magic[12] = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};
    std::memcpy(b.data(), magic, 12);
    put32(b, 12, vkFormat);
    put32(b, 16, 1);
    put32(b, 20, uint32_t(w));
    put32(b, 24, uint32_t(h));
    put32(b, 32, layers);
    put32(b, 36, faces);
    put32(b, 40, levels);
    put32(b, 80, 112);                    // level 0 byte offset
    put32(b, 88, uint32_t(data.size()));  // and length
    b.insert(b.end(), data.begin(), data.end());
    return save(name, b);
}

// DDS: the 128-byte legacy header, with a DX10 header when dxgi != 0, then level 0.
fs::path dds(const std::string& name, uint32_t dxgi, int w, int h, const std::vector<unsigned char>& data, uint32_t mips = 1) {
    std::vector<unsigned char> b(dxgi ? 148 : 128, 0);
    std::memcpy(b.data(), "DDS ", 4);
    put32(b, 4, 124);
    put32(b, 12, uint32_t(h));
    put32(b, 16, uint32_t(w));
    put32(b, 28, mips);
    put32(b, 76, 32);
    if (dxgi) {
        put32(b, 80, 0x4);
        std::memcpy(&b[84], "DX10", 4);
        put32(b, 128, dxgi);
        put32(b, 132, 3);  // a 2D texture
        put32(b, 140, 1);
    } else {  // 32-bit RGBA with alpha, in R, G, B, A byte order
        put32(b, 80, 0x41);
        put32(b, 88, 32);
        put32(b, 92, 0xff);
        put32(b, 96, 0xff00);
        put32(b, 100, 0xff0000);
        put32(b, 104, 0xff000000u);
    }
    b.insert(b.end(), data.begin(), data.end());
    return save(name, b);
}

TEST(TextureFormats, Ktx2HeaderAndTexels) {
    const std::vector<unsigned char> rgba = texels(37, 19);
    fs::path file = ktx2("a.ktx2", 43, 37, 19, rgba);  // R8G8B8A8_SRGB, odd sizes
    std::string why;
    std::optional<TextureInfo> info = textureInfo(file, &why);
    ASSERT_TRUE(info) << why;
    EXPECT_EQ(info->width, 37);
    EXPECT_EQ(info->height, 19);
    EXPECT_EQ(info->channelNames, "rgba");
    EXPECT_EQ(info->srgb, true);
    EXPECT_EQ(info->format, "KTX2 R8G8B8A8 sRGB");
    Texture t = loadTexture(file, true);
    EXPECT_EQ(t.width, 37);
    EXPECT_EQ(t.rgba8, rgba);
    EXPECT_TRUE(t.srgb);
}

TEST(TextureFormats, DdsUncompressedAndBlockCompressed) {
    const std::vector<unsigned char> rgba = texels(5, 3);
    std::string why;
    fs::path plain = dds("plain.dds", 0, 5, 3, rgba);
    ASSERT_TRUE(textureInfo(plain, &why)) << why;
    EXPECT_EQ(loadTexture(plain, false).rgba8, rgba);
    // BGRA through DX10: the loader swaps red and blue back.
    fs::path bgra = dds("bgra.dds", 87, 5, 3, rgba);
    std::vector<unsigned char> swapped = rgba;
    for (size_t i = 0; i < swapped.size(); i += 4) std::swap(swapped[i], swapped[i + 2]);
    EXPECT_EQ(loadTexture(bgra, false).rgba8, swapped);
    // BC7 sRGB, 64 x 30 (blocks of 4 x 4 round up to 16 x 8), with its mips declared: read, not decoded.
    fs::path bc7 = dds("bc7.dds", 99, 64, 30, std::vector<unsigned char>(16 * 8 * 16), 7);
    std::optional<TextureInfo> info = textureInfo(bc7, &why);
    ASSERT_TRUE(info) << why;
    EXPECT_EQ(info->height, 30);
    EXPECT_EQ(info->mipLevels, 7);
    EXPECT_EQ(info->srgb, true);
    EXPECT_EQ(info->format, "DDS BC7 sRGB");
    try {
        loadTexture(bc7, true);
        ADD_FAILURE() << "BC7 decoded";
    } catch (const TextureError& e) {
        EXPECT_NE(std::string(e.what()).find("do not decode BC7 sRGB"), std::string::npos) << e.what();
    }
}

TEST(TextureFormats, ExrThroughTinyexr) {
    std::vector<float> rgba(size_t(33) * 17 * 4);
    for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = float(i) * 0.37f - 40.0f;  // negative and above 1: HDR
    const fs::path file = dir() / "h.exr";
    const char* err = nullptr;
    ASSERT_EQ(SaveEXR(rgba.data(), 33, 17, 4, 0, file.c_str(), &err), TINYEXR_SUCCESS) << (err ? err : "");
    std::string why;
    std::optional<TextureInfo> info = textureInfo(file, &why);
    ASSERT_TRUE(info) << why;
    EXPECT_EQ(info->width, 33);
    EXPECT_EQ(info->height, 17);
    EXPECT_EQ(info->channels, 4);
    EXPECT_FALSE(info->srgb.has_value());               // float: the colour space does not apply
    EXPECT_EQ(loadTexture(file, false).rgba32f, rgba);  // fp32 storage: exact
}

// What hexc does not read is a located error at the slot's texture, saying why.
TEST(TextureFormats, UnreadableContainersAreLocatedErrors) {
    const fs::path basis = ktx2("basis.ktx2", 0, 8, 8, std::vector<unsigned char>(64));
    const fs::path cube = dds("short.dds", 98, 64, 64, std::vector<unsigned char>(100));  // level 0 needs 4096 bytes
    // A level offset near 2^64: offset + size would wrap around to a small number.
    const fs::path wrap = ktx2("wrap.ktx2", 37, 65536, 65536, std::vector<unsigned char>(64));
    {
        std::fstream f(wrap, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(80);
        const unsigned char offset[8] = {0, 0, 0, 0, 0xfc, 0xff, 0xff, 0xff};  // 2^64 - 2^34, and level 0 is 2^34 bytes
        f.write(reinterpret_cast<const char*>(offset), 8);
    }
    for (const auto& [file, why] : {std::pair{basis, "VK_FORMAT_UNDEFINED (Basis Universal) is not supported"},
                                    std::pair{cube, "the file is truncated (level 0 does not fit)"},
                                    std::pair{wrap, "the file is truncated (level 0 does not fit)"}}) {
        ParseResult r = parseMaterial(R"({"name": "m", "slots": [{"name": "a", "kind": "color", "texture": ")" + file.string() + "\"}]}",
                                      "materials/t.json");
        ASSERT_EQ(r.diagnostics.size(), 1u);
        EXPECT_NE(r.diagnostics[0].format().find("materials/t.json:1:67: error[HX121]: /slots/0/texture: cannot read texture"),
                  std::string::npos)
            << r.diagnostics[0].format();
        EXPECT_NE(r.diagnostics[0].format().find(why), std::string::npos) << r.diagnostics[0].format();
    }
}

// A KTX2 array's header gives its layer count; each layer decodes on its own; a truncated array and a cube are errors.
TEST(TextureFormats, Ktx2ArrayLayersDecodeOneByOne) {
    const std::vector<unsigned char> rgba = texels(5, 3 * 3);  // three 5x3 layers, each with texels of its own
    const fs::path file = ktx2("array.ktx2", 37, 5, 3, rgba, 1, 3);
    std::string why;
    std::optional<TextureInfo> info = textureInfo(file, &why);
    ASSERT_TRUE(info) << why;
    EXPECT_EQ(info->layers, 3);
    EXPECT_EQ(info->width, 5);
    EXPECT_EQ(info->height, 3);
    for (int layer = 0; layer < 3; ++layer) {
        const std::vector<unsigned char> own(rgba.begin() + layer * 60, rgba.begin() + (layer + 1) * 60);
        EXPECT_EQ(loadTexture(file, false, layer).rgba8, own) << layer;
    }
    EXPECT_THROW(loadTexture(file, false, 3), TextureError);
    const std::vector<float> floats = {0.25f, 0.5f, 1.5f, 1, -2, 3, 4, 1};  // two 1x1 RGBA32F layers
    std::vector<unsigned char> bytes(floats.size() * 4);
    std::memcpy(bytes.data(), floats.data(), bytes.size());
    EXPECT_EQ(loadTexture(ktx2("array_f.ktx2", 109, 1, 1, bytes, 1, 2), false, 1).rgba32f,
              std::vector<float>(floats.begin() + 4, floats.end()));
    EXPECT_EQ(textureInfo(ktx2("plain.ktx2", 37, 5, 3, texels(5, 3)), &why)->layers, 0);  // a 2D texture
    EXPECT_THROW(loadTexture(ktx2("plain.ktx2", 37, 5, 3, texels(5, 3)), false, 1), TextureError);
    for (const auto& [bad, problem] :
         {std::pair{ktx2("short_array.ktx2", 37, 5, 3, texels(5, 3 * 2), 1, 3), "the file is truncated (level 0 does not fit)"},
          std::pair{ktx2("cube.ktx2", 37, 4, 4, texels(4, 4 * 6), 1, 0, 6), "a KTX2 cube or 3D texture is not a 2D texture or 2D array"}}) {
        EXPECT_FALSE(textureInfo(bad, &why)) << bad;
        EXPECT_EQ(why, problem);
    }
}

// A two-layer material whose albedo slots are `first` and `second` (a slot's keys after its kind), over terrain's splat map.
ParseResult layered(const std::string& first, const std::string& second, const std::string& blend = "") {
    return parseMaterial(R"({"name": "m", "template": "unlit", "layers": [
        {"name": "grass", "slots": [{"name": "albedo", "kind": "color", )" +
                             first + R"(}]},
        {"name": "rock", "slots": [{"name": "albedo", "kind": "color", )" +
                             second + R"(}]}],
        "layer_blend": {"splat": ["textures/terrain_splat.png"])" +
                             blend + "}}",
                         "materials/t.json");
}

std::string arrayLayer(const fs::path& file, int layer) {
    return R"("texture": ")" + file.string() + R"(", "layer": )" + std::to_string(layer);
}

// Each misuse of a KTX2 array is HX128 at the key that is wrong, saying what is expected.
TEST(TextureFormats, Ktx2ArrayMisusesAreLocatedErrors) {
    const fs::path array = ktx2("misused.ktx2", 43, 4, 4, texels(4, 4 * 3), 1, 3), plain = ktx2("plain4.ktx2", 43, 4, 4, texels(4, 4));
    const std::string a = array.string(), p = plain.string();
    EXPECT_TRUE(layered(arrayLayer(array, 0), arrayLayer(array, 1)).material)
        << formatAll(layered(arrayLayer(array, 0), arrayLayer(array, 1)).diagnostics);
    auto own = [&](const std::string& keys) {
        return formatAll(
            parseMaterial(R"({"name": "m", "slots": [{"name": "a", "kind": "color", )" + keys + "}]}", "materials/t.json").diagnostics);
    };
    const std::pair<std::string, std::string> cases[] = {
        {own(arrayLayer(array, 0)), "error[HX128]: /slots/0/layer: a KTX2 array texture is read by a layered material's layers"},
        {own(R"("texture": ")" + a + "\""),
         "error[HX128]: /slots/0/texture: " + a + " is a KTX2 array of 3 layers; expected a 2D texture, or"},
        {formatAll(layered(arrayLayer(plain, 0), arrayLayer(array, 1)).diagnostics),
         "error[HX128]: /layers/0/slots/0/layer: `layer` names a layer of a KTX2 array texture; " + p + " is a 2D texture"},
        {formatAll(layered(arrayLayer(array, 0), arrayLayer(array, 3)).diagnostics),
         "error[HX128]: /layers/1/slots/0/layer: layer 3 of " + a + ", which has 3 layers; expected 0 to 2\n"},
        {formatAll(layered(arrayLayer(array, 0), R"("texture": "textures/terrain_splat.png")").diagnostics),
         "error[HX128]: /layers/1/slots/0/texture: role `albedo` reads the KTX2 array " + a +
             "; every layer's `albedo` names that array at its own layer, not another file"},
        {formatAll(layered(arrayLayer(array, 1), arrayLayer(array, 0)).diagnostics),
         "error[HX128]: /layers/1/slots/0/layer: layer `rock` is layer 1 of the layers, and its `albedo` reads layer 0 of " + a +
             "; expected `\"layer\": 1` (the array's layers in the layers' order)"},
        {formatAll(parseMaterial(R"({"name": "m", "layers": [{"name": "g", "slots": [{"name": "a", "kind": "color", "texture": ")" + p +
                                     R"("}]}], "layer_blend": {"splat": [")" + a + R"("]}})",
                                 "materials/t.json")
                       .diagnostics),
         "error[HX128]: /layer_blend/splat/0: splat map " + a + " is a KTX2 array; expected a 2D texture"},
        {own(R"("texture": ")" + a + R"(", "layr": 0)"), "error[HX103]: /slots/0/layr: unknown key"},
    };
    for (const auto& [diagnostics, expected] : cases) EXPECT_NE(diagnostics.find(expected), std::string::npos) << diagnostics;
    EXPECT_NE(own(R"("texture": ")" + a + R"(", "layr": 0)").find("did you mean `layer`?"), std::string::npos);
    // Out of order, both layers are wrong: each is reported, once.
    const std::string swapped = formatAll(layered(arrayLayer(array, 1), arrayLayer(array, 0)).diagnostics);
    EXPECT_NE(swapped.find("/layers/0/slots/0/layer: layer `grass` is layer 0 of the layers"), std::string::npos) << swapped;
    EXPECT_EQ(std::count(swapped.begin(), swapped.end(), '\n'), 2) << swapped;
}

// A role read from a KTX2 array is bound as that array; where the shader needs a texture per slot, HX128 says why.
TEST(TextureFormats, Ktx2ArrayRolesBindTheFileOrAreRefused) {
    std::vector<unsigned char> opaque = texels(4, 4 * 3);  // alpha 255: packing may put a scalar there
    for (size_t i = 3; i < opaque.size(); i += 4) opaque[i] = 255;
    const fs::path array = ktx2("bound.ktx2", 43, 4, 4, opaque, 1, 3);
    ParseResult r = layered(arrayLayer(array, 0), arrayLayer(array, 1));
    ASSERT_TRUE(r.material) << formatAll(r.diagnostics);
    CompileResult c = compile(*r.material);
    ASSERT_TRUE(c.ok()) << formatAll(c.diagnostics);
    nlohmann::json manifest;
    for (const OutputFile& f : c.files)
        if (f.name.ends_with(".manifest.json")) manifest = nlohmann::json::parse(f.contents);
    const nlohmann::json& albedo = manifest["layers"]["arrays"][0];
    EXPECT_EQ(albedo["array"], true);
    EXPECT_EQ(albedo["file"], array.string());
    EXPECT_EQ(albedo["size"], nlohmann::json::array({4, 4, 3}));  // the file's layers, all bound
    EXPECT_EQ(albedo["colorspace"], "srgb");
    EXPECT_NE(c.glsl.find("texture2DArray hexcArr_albedo"), std::string::npos);
    Material off = *r.material;
    off.layers->arrays = false;
    CompileOptions functions, general;
    functions.functions = true;
    general.specialise = false;
    // Packed: each layer's albedo shares its texture with the layer's roughness (the same size and lattice).
    std::ofstream(dir() / "rough.png", std::ios::binary) << pngBytes(Texture{4, 4, false, texels(4, 4), {}});
    const std::string rough = R"(}, {"name": "roughness", "kind": "scalar", "texture": ")" + (dir() / "rough.png").string() + "\"";
    ParseResult packed = layered(arrayLayer(array, 0) + rough, arrayLayer(array, 1) + rough);
    ASSERT_TRUE(packed.material) << formatAll(packed.diagnostics);
    packed.material->pack = true;
    packed.material->templ = TemplateRef::builtin("lit");
    // Tiles blended by height: the albedo's layer i reads the height role's layer i alike, and that role's files differ
    // in size, so they stay separate textures.
    std::ofstream(dir() / "small.png", std::ios::binary) << pngBytes(Texture{2, 2, false, texels(2, 2), {}});
    auto heights = [&](const char* file) {
        return R"(, "height_blend": {"slot": "height"}}, {"name": "height", "kind": "scalar", "texture": ")" + (dir() / file).string() +
               "\"";
    };
    ParseResult blended = layered(arrayLayer(array, 0) + heights("rough.png"), arrayLayer(array, 1) + heights("small.png"));
    ASSERT_TRUE(blended.material) << formatAll(blended.diagnostics);
    for (const auto& [m, options, why] :
         {std::tuple{off, CompileOptions{}, "layer_blend.arrays is \"off\""},
          std::tuple{*r.material, functions, "the functions output (engine packages) binds one texture"},
          std::tuple{*r.material, general, "--no-specialise: the library's general functions read 2D"},
          std::tuple{*packed.material, CompileOptions{}, "slot `grass_albedo` reads a packed texture"},
          std::tuple{*blended.material, CompileOptions{}, "slot `grass_albedo` height-blends its tiles by"}}) {
        const std::string d = formatAll(compile(m, options).diagnostics);
        EXPECT_NE(d.find("materials/t.json:2:64: error[HX128]: /layers/0/slots/0/texture: role `albedo` reads the KTX2 array " +
                         array.string() + ", bound as one array texture, and this shader needs a texture per slot: " + why),
                  std::string::npos)
            << d;
    }
    // hexc edit's page compiles unspecialised and uploads each slot's texture, a layer it decodes: a texture per slot.
    general.slotTexturesDecoded = true;
    const CompileResult page = compile(*r.material, general);
    EXPECT_TRUE(page.ok()) << formatAll(page.diagnostics);
    EXPECT_EQ(page.glsl.find("texture2DArray"), std::string::npos);
    // An engine package that binds arrays binds the file too, and its manifest names it from the package's folder.
    CompileOptions package;
    package.manifestPathsFrom = dir() / "out";
    const CompileResult godot4 = compileForEngine(*r.material, Engine::Godot4, package);
    ASSERT_TRUE(godot4.ok()) << formatAll(godot4.diagnostics);
    for (const OutputFile& f : godot4.files)
        if (f.name.ends_with(".manifest.json")) manifest = nlohmann::json::parse(f.contents);
    EXPECT_EQ(manifest["layers"]["arrays"][0]["file"], manifest["source"]["textures"]["grass_albedo"]);
    EXPECT_NE(manifest["layers"]["arrays"][0]["file"], array.string());
}

// A two-channel BC5 map has r and g: a scalar slot may read g, not b.
TEST(TextureFormats, ChannelsFollowTheFormat) {
    const fs::path bc5 = dds("bc5.dds", 83, 8, 8, std::vector<unsigned char>(4 * 16));
    auto parse = [&](const char* channel) {
        return parseMaterial(R"({"name": "m", "slots": [{"name": "a", "kind": "scalar", "channel": ")" + std::string(channel) +
                                 R"(", "texture": ")" + bc5.string() + "\"}]}",
                             "materials/t.json");
    };
    EXPECT_TRUE(parse("g").material) << formatAll(parse("g").diagnostics);
    ParseResult b = parse("b");
    ASSERT_EQ(b.diagnostics.size(), 1u);
    EXPECT_NE(b.diagnostics[0].format().find("has 2 channels; expected `r` or `g`"), std::string::npos) << b.diagnostics[0].format();
}

// A container's format says whether it is sRGB; a slot that says otherwise gets a warning, as the engine's
// upload would either decode what should stay linear or leave sRGB values encoded.
TEST(TextureFormats, AColourSpaceThatDisagreesWithTheFormatWarns) {
    const fs::path unorm = ktx2("unorm.ktx2", 37, 4, 4, texels(4, 4)), srgb = ktx2("srgb.ktx2", 43, 4, 4, texels(4, 4));
    auto diagnose = [](const fs::path& tex, const std::string& kind, const std::string& colorspace) {
        ParseResult r = parseMaterial(R"({"name": "m", "slots": [{"name": "a", "kind": ")" + kind + R"(", "texture": ")" + tex.string() +
                                          "\"" + (colorspace.empty() ? "" : R"(, "colorspace": ")" + colorspace + "\"") + "}]}",
                                      "materials/t.json");
        EXPECT_TRUE(r.material) << formatAll(r.diagnostics);
        return formatAll(r.diagnostics);
    };
    EXPECT_NE(diagnose(unorm, "color", "")
                  .find("warning[HX123]: /slots/0/texture: " + unorm.string() + " is KTX2 R8G8B8A8, but the slot's colorspace is \"srgb\""),
              std::string::npos);
    EXPECT_EQ(diagnose(unorm, "color", "linear"), "");
    EXPECT_EQ(diagnose(srgb, "color", ""), "");
    EXPECT_NE(diagnose(srgb, "scalar", "").find("warning[HX123]"), std::string::npos);
    // A legacy DDS (no DX10 header) has no sRGB flag: an 8-bit texture may be either, so neither colour space warns;
    // a DX10 header says, and is held to it.
    const fs::path legacy = dds("legacy.dds", 0, 4, 4, texels(4, 4)), dx10 = dds("dx10.dds", 28, 4, 4, texels(4, 4));
    EXPECT_EQ(diagnose(legacy, "color", ""), "");
    EXPECT_EQ(diagnose(legacy, "color", "linear"), "");
    EXPECT_EQ(diagnose(dx10, "color", ""),
              "materials/t.json:1:67: warning[HX123]: /slots/0/texture: " + dx10.string() +
                  " is DDS R8G8B8A8, but the slot's colorspace is \"srgb\"; its format stores linear values\n");
}

// Each container compiles from the command line; the decodable ones render (the fp64 reference needs no GPU).
TEST(TextureFormats, CompileAndRenderFromTheCommandLine) {
    const fs::path k = ktx2("m.ktx2", 37, 16, 16, texels(16, 16));
    const fs::path d = dds("m.dds", 98, 16, 16, std::vector<unsigned char>(16 * 16));
    const fs::path e = dir() / "m.exr";
    const std::vector<float> grey(16 * 16 * 4, 0.5f);
    ASSERT_EQ(SaveEXR(grey.data(), 16, 16, 4, 1, e.c_str(), nullptr), TINYEXR_SUCCESS);
    for (const fs::path& tex : {k, d, e}) {
        const fs::path m = dir() / ("m" + tex.extension().string() + ".json");
        std::ofstream(m) << R"({"name": "m", "template": "unlit", "slots": [{"name": "albedo", "kind": "color", "texture": ")" +
                                tex.filename().string() + "\"}]}";
        const fs::path out = dir() / ("out" + tex.extension().string());
        fs::remove_all(out);
        std::string err;
        ASSERT_EQ(hexc::test::runHexc(m.string() + " -o " + out.string(), &err), 0) << err;
        std::ifstream manifest(out / "m.manifest.json");
        EXPECT_EQ(nlohmann::json::parse(manifest)["slots"][0]["size"], nlohmann::json::array({16, 16}));
        const int render =
            hexc::test::runHexc("render " + m.string() + " --reference --output albedo --size 8x8 -o " + (out / "r.pfm").string(), &err);
        EXPECT_EQ(render, tex == d ? 1 : 0) << err;
        if (tex == d) {
            EXPECT_NE(err.find("do not decode BC7"), std::string::npos) << err;
        }
    }
}

// On the GPU a container renders exactly like a file of the same texels: a KTX2 like the PNG it was made from,
// an EXR like a PFM of the same floats (same upload, same mips, same sampler).
TEST(TextureFormats, ContainersRenderOnTheGpuLikeTheFilesTheyHold) {
    REQUIRE_VULKAN();
    const Texture png = loadTexture("materials/textures/tiles_albedo.png", true);
    const fs::path ktx = ktx2("tiles.ktx2", 43, png.width, png.height, png.rgba8);
    Image floats{19, 13, std::vector<float>(19 * 13 * 4)};
    for (size_t i = 0; i < floats.rgba.size(); ++i) floats.rgba[i] = i % 4 == 3 ? 1.0f : float((i * 7919) % 1000) / 250.0f;
    writeImage(floats, dir() / "f.pfm");
    ASSERT_EQ(SaveEXR(floats.rgba.data(), 19, 13, 4, 0, (dir() / "f.exr").c_str(), nullptr), TINYEXR_SUCCESS);
    auto render = [&](const fs::path& texture) {
        ParseResult r = parseMaterial(R"({"name": "m", "template": "unlit", "hextiling": {"tiling": 3},
            "slots": [{"name": "albedo", "kind": "color", "colorspace": "srgb", "texture": ")" +
                                          texture.string() + "\"}]}",
                                      "materials/m.json");
        EXPECT_TRUE(r.material) << formatAll(r.diagnostics);
        return vk::render(*hexc::test::runner(&whyNoVulkan), *r.material, vk::RenderOutput::Albedo, "", View{48, 40, {0, 0, 1.3, 0.9}})
            .rgba;
    };
    EXPECT_EQ(render(ktx), render(fs::absolute("materials/textures/tiles_albedo.png")));
    EXPECT_EQ(render(dir() / "f.exr"), render(dir() / "f.pfm"));
}

}  // namespace
