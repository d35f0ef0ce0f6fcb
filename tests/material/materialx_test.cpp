// MaterialX in and out (docs/materialx.md): documents compile to the shaders of the equivalent JSON material, the
// export reads back to the same shaders, MaterialX's parameters mean in hexc what they mean in MaterialX, and what
// hexc cannot express is a located diagnostic. Execution on lavapipe: tests/execution/outputs_test.cpp (MaterialX suites).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <regex>

#include <nlohmann/json.hpp>

#include "hexc/compiler.h"
#include "hexc/materialx.h"
#include "support.h"

#include <unistd.h>

using namespace hexc;
using hexc::test::loadMaterial;

namespace {

// `text` (b's manifest) with b's texture and template paths as written replaced by a's, which differ by format and folder.
std::string pathsOf(const Material& a, const Material& b, std::string text) {
    auto replace = [&](const std::string& from, const std::string& to) {
        for (size_t at = from.empty() ? std::string::npos : text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
            text.replace(at, from.size(), to);
    };
    for (size_t i = 0; i < a.slots.size() && i < b.slots.size(); ++i) replace(b.slots[i].texture, a.slots[i].texture);
    replace(b.templ.asWritten, a.templ.asWritten);
    return text;
}

// Both materials compile to byte-identical SPIR-V, sources identical below their banners, and the same manifest.
void expectSameShaders(const Material& a, const Material& b) {
    CompileResult ra = compile(a), rb = compile(b);
    ASSERT_TRUE(ra.ok()) << formatAll(ra.diagnostics);
    ASSERT_TRUE(rb.ok()) << formatAll(rb.diagnostics);
    ASSERT_EQ(ra.files.size(), rb.files.size());
    EXPECT_EQ(ra.spirv, rb.spirv) << a.name;
    for (size_t i = 0; i < ra.files.size(); ++i) {
        const OutputFile &fa = ra.files[i], &fb = rb.files[i];
        ASSERT_EQ(fa.name, fb.name);
        if (fa.name.ends_with(".json"))
            EXPECT_EQ(nlohmann::json::parse(fa.contents), nlohmann::json::parse(pathsOf(a, b, fb.contents))) << fa.name;
        else if (fa.name.ends_with(".spv"))
            EXPECT_EQ(fa.contents, fb.contents) << fa.name;
        else
            EXPECT_EQ(withoutBanner(fa.contents), withoutBanner(fb.contents)) << fa.name;
    }
}

std::filesystem::path scratch(const std::string& name) {
    std::filesystem::path dir = std::filesystem::temp_directory_path() / ("hexc_mtlx_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir / name;
}

std::string withoutComment(std::string document) {
    const size_t begin = document.find("<!--"), end = document.find("-->");
    return begin == std::string::npos || end == std::string::npos ? document : document.erase(begin, end + 3 - begin);
}

}  // namespace

TEST(MaterialX, AHandWrittenDocumentCompilesToTheShadersOfItsJsonMaterial) {
    expectSameShaders(loadMaterial("materials/rock.json"), loadMaterial("materials/mtlx/rock.mtlx"));
}

// JSON -> mtlx -> JSON: every example, whatever settings it uses (masks, steps, height blending, triplanar, a
// template file with its own resources), reads back to the same shaders.
TEST(MaterialX, TheExportOfEveryExampleReadsBackToTheSameShaders) {
    // Beyond the examples, rock variants: the histogram blend on albedo and roughness, a y-down (DirectX) normal map
    // hex-tiled (flip_g), the same map plain-tiled (the normalmap node has no flip: hexc_flip_y), lod "shared" and packing.
    const std::map<std::string, std::function<void(Material&)>> variants = {
        {"histogram", [](Material& m) { m.slots[0].hex.blend = m.slots[2].hex.blend = Blend::Histogram; }},
        {"normal_y_down", [](Material& m) { m.slots[1].flipY = true; }},
        {"normal_y_down_plain", [](Material& m) { m.slots[1].flipY = true, m.slots[1].hex.enabled = false; }},
        {"shared_lod", [](Material& m) { m.slots[0].hex.lod = m.slots[1].hex.lod = Lod::Shared; }},
        {"pack", [](Material& m) { m.pack = true; }},
        {"materialx",
         [](Material& m) {
             for (Slot& s : m.slots) s.hex.mode = HashMode::MaterialX, s.hex.lumacoeffs = {0.2126, 0.7152, 0.0722};
         }},
    };
    for (const char* name : {"rock", "rock_normal", "rock_blend", "rock_triplanar", "tiles", "tiles_stepped", "engine_rock", "histogram",
                             "normal_y_down", "normal_y_down_plain", "shared_lod", "pack", "materialx"}) {
        SCOPED_TRACE(name);
        const auto variant = variants.find(name);
        Material json = loadMaterial(std::string("materials/") + (variant != variants.end() ? "rock" : name) + ".json");
        if (variant != variants.end()) {
            json.name = name;
            variant->second(json);
        }
        const std::filesystem::path out = scratch(std::string(name) + ".mtlx");
        MaterialXExport exported = exportMaterialX(json, out);
        ASSERT_TRUE(exported.document) << formatAll(exported.diagnostics);
        EXPECT_TRUE(exported.diagnostics.empty()) << formatAll(exported.diagnostics);
        std::ofstream(out, std::ios::binary) << *exported.document;
        expectSameShaders(json, loadMaterial(out));
        // The same material gives the same document (but for the comment naming the file it came from).
        EXPECT_EQ(withoutComment(*exported.document), withoutComment(*exportMaterialX(loadMaterial(out), out).document));
    }
}

// MaterialX draws a tile's angle as A + (B - A) u R (degrees), its scale as 1 + (lo + (hi - lo) u - 1) S and its
// offset as olo + (ohi - olo) u O; hexc as (a + (b - a) u) rotation, a + (b - a) u and u offset. For each u the
// material read must give MaterialX's values.
TEST(MaterialX, TileTransformsMeanWhatTheyMeanInMaterialX) {
    struct Case {
        double R, A, B, S, lo, hi, O, ohi;
    };
    for (const Case& c : {Case{0.5, 30, 90, 0.25, 0.5, 2, 0.5, 0.8}, Case{1, 0, 360, 1, 0.5, 2, 1, 1},
                          Case{0.3, -180, 180, 2, 0.9, 1.1, 1, 0.5}, Case{0, 0, 360, 0, 0.5, 2, 0, 1}, Case{0, 45, 90, 1, 1, 1, 1, 1}}) {
        char text[2048];
        std::snprintf(text, sizeof text, R"(<?xml version="1.0"?>
<materialx version="1.39">
  <hextiledimage name="albedo_image" type="color3">
    <input name="file" type="filename" value="../textures/rock_albedo.png" />
    <input name="rotation" type="float" value="%.17g" />
    <input name="rotationrange" type="vector2" value="%.17g, %.17g" />
    <input name="scale" type="float" value="%.17g" />
    <input name="scalerange" type="vector2" value="%.17g, %.17g" />
    <input name="offset" type="float" value="%.17g" />
    <input name="offsetrange" type="vector2" value="0, %.17g" />
  </hextiledimage>
  <standard_surface name="surface" type="surfaceshader">
    <input name="base_color" type="color3" nodename="albedo_image" />
  </standard_surface>
  <surfacematerial name="m" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="surface" />
  </surfacematerial>
</materialx>)",
                      c.R, c.A, c.B, c.S, c.lo, c.hi, c.O, c.ohi);
        ParseResult r = parseMaterial(text, "materials/mtlx/t.mtlx");
        ASSERT_TRUE(r.material) << formatAll(r.diagnostics);
        const HexTiling& h = r.material->slots[0].hex;
        for (double u : {0.0, 0.25, 0.5, 0.75, 1.0}) {
            SCOPED_TRACE(testing::Message() << "R " << c.R << " A " << c.A << " u " << u);
            const double angle = (h.rotationRange[0] + (h.rotationRange[1] - h.rotationRange[0]) * u) * h.rotation;
            EXPECT_NEAR(angle, c.A + (c.B - c.A) * u * c.R, 1e-9);
            EXPECT_NEAR(h.scaleRange[0] + (h.scaleRange[1] - h.scaleRange[0]) * u, 1 + (c.lo + (c.hi - c.lo) * u - 1) * c.S, 1e-12);
            EXPECT_NEAR(u * h.offset, c.ohi * u * c.O, 1e-12);
        }
    }
}

// What MaterialX leaves out means MaterialX's defaults, not hexc's: a colour image's falloffcontrast is 0.5, the
// rotation range 0-360 degrees, tile scales 0.5-2; plain images are plain tiling; colour spaces come from the file.
TEST(MaterialX, AbsentInputsTakeMaterialXsDefaults) {
    const Material m = loadMaterial("materials/mtlx/preview_surface.mtlx");
    ASSERT_EQ(m.slots.size(), 3u);
    const Slot &albedo = m.slots[0], &roughness = m.slots[1], &normal = m.slots[2];
    EXPECT_EQ(m.name, "preview_tiles");
    EXPECT_EQ(albedo.name, "albedo");
    EXPECT_EQ(albedo.colorSpace, ColorSpace::Srgb);
    EXPECT_EQ(albedo.hex.falloffcontrast, 0.5);
    EXPECT_EQ(albedo.hex.falloff, 0.5);
    EXPECT_EQ(albedo.hex.rotation, 0.5);
    EXPECT_EQ(albedo.hex.rotationRange, (std::array<double, 2>{0, 360}));
    EXPECT_EQ(albedo.hex.scaleRange, (std::array<double, 2>{0.5, 2}));
    EXPECT_EQ(albedo.hex.tiling, (std::array<double, 2>{3, 3}));
    EXPECT_EQ(roughness.name, "roughness");
    EXPECT_EQ(roughness.kind, SlotKind::Scalar);
    EXPECT_EQ(roughness.colorSpace, ColorSpace::Linear);
    EXPECT_FALSE(roughness.hex.enabled);
    EXPECT_EQ(roughness.hex.tiling, (std::array<double, 2>{2, 2}));
    EXPECT_EQ(normal.kind, SlotKind::Normal);
    EXPECT_FALSE(normal.hex.enabled);
    EXPECT_EQ(normal.texturePath, std::filesystem::path("materials/mtlx/../textures/rock_normal.png"));
}

// Inline documents, located as if they were materials/mtlx/t.mtlx.
std::vector<std::string> diagnose(const std::string& graph, const std::string& shaderInputs) {
    const std::string text = "<materialx version=\"1.39\">\n" + graph + "\n<standard_surface name=\"s\" type=\"surfaceshader\">\n" +
                             shaderInputs +
                             "\n</standard_surface>\n<surfacematerial name=\"m\" type=\"material\">\n"
                             "<input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"s\" />\n</surfacematerial>\n</materialx>\n";
    std::vector<std::string> out;
    for (const Diagnostic& d : parseMaterial(text, "materials/mtlx/t.mtlx").diagnostics) out.push_back(d.format());
    return out;
}

const char* kAlbedo = R"(<input name="base_color" type="color3" nodename="img" />)";

TEST(MaterialX, WhatHexcCannotExpressIsReportedWhereItIs) {
    auto image = [](const std::string& extra, const char* category = "hextiledimage") {
        return std::string("<") + category + " name=\"img\" type=\"color3\">\n<input name=\"file\" type=\"filename\" " +
               "value=\"../textures/rock_albedo.png\" />\n" + extra + "\n</" + category + ">";
    };
    EXPECT_EQ(diagnose(image(R"(<input name="offsetrange" type="vector2" value="0.25, 1" />)"), kAlbedo),
              std::vector<std::string>{"materials/mtlx/t.mtlx:4:1: error[HX118]: img/offsetrange: `offsetrange` must start at 0: hexc "
                                       "offsets tiles by u * offset"});
    EXPECT_EQ(diagnose(image(R"(<input name="filtertype" type="string" value="closest" />)", "image"), kAlbedo),
              std::vector<std::string>{"materials/mtlx/t.mtlx:4:1: error[HX118]: img/filtertype: `filtertype` must be \"linear\": "
                                       "hexc samples with trilinear filtering"});
    // MaterialX mode (a document's default) weighs by `lumacoeffs`; hexc's own modes by Rec. 601 luma.
    EXPECT_EQ(diagnose(image(R"(<input name="lumacoeffs" type="color3" value="0.2126, 0.7152, 0.0722" />)"), kAlbedo),
              std::vector<std::string>{});
    EXPECT_EQ(diagnose(std::regex_replace(image(R"(<input name="lumacoeffs" type="color3" value="0.2126, 0.7152, 0.0722" />)"),
                                          std::regex("type=\"color3\">"), "type=\"color3\" hexc_mode=\"stable\">"),
                       kAlbedo),
              std::vector<std::string>{"materials/mtlx/t.mtlx:4:1: warning[HX119]: img/lumacoeffs: hexc weighs colour samples by Rec. 601 "
                                       "luma (0.299, 0.587, 0.114); `lumacoeffs` is not used"});
    EXPECT_EQ(diagnose("<noise2d name=\"img\" type=\"color3\" />", kAlbedo),
              std::vector<std::string>{"materials/mtlx/t.mtlx:2:1: error[HX118]: img: node <noise2d> cannot feed a slot (hexc compiles "
                                       "image, tiledimage, hextiledimage and hextilednormalmap nodes, optionally under extract, "
                                       "normalmap or a convert to color3)"});
    // Value nodes that feed one another in a cycle: a diagnostic, not a hang.
    EXPECT_EQ(diagnose(image(R"(<input name="tiling" type="vector2" nodename="a" />)") +
                           R"(<add name="a" type="vector2"><input name="in1" type="vector2" nodename="b" /></add>
<add name="b" type="vector2"><input name="in1" type="vector2" nodename="a" /></add>)",
                       kAlbedo),
              std::vector<std::string>{"materials/mtlx/t.mtlx:4:1: error[HX118]: img/tiling: `tiling` is not a constant: a/in1: the nodes "
                                       "feeding it form a cycle or a chain deeper than 32 (hexc reads texture settings as values: "
                                       "constants, interface inputs, and convert, combine2-4, add, subtract, multiply or divide of "
                                       "those)"});
    // A value the JSON rules refuse is reported at the MaterialX input it came from.
    EXPECT_EQ(diagnose(image(R"(<input name="falloff" type="float" value="2" />)"), kAlbedo),
              std::vector<std::string>{"materials/mtlx/t.mtlx:4:36: error[HX106]: img/falloff: expected a number in [0.000001, 0.999999] "
                                       "(0.5 = off), got 2.0"});
}

TEST(MaterialX, TheExportRefusesASlotNoSurfaceInputCarries) {
    Material m = loadMaterial("materials/rock.json");
    m.slots[0].name = "detail";
    MaterialXExport exported = exportMaterialX(m, scratch("detail.mtlx"));
    EXPECT_FALSE(exported.document);
    ASSERT_EQ(exported.diagnostics.size(), 1u);
    EXPECT_EQ(exported.diagnostics[0].code, Code::MaterialXUnsupported);
    EXPECT_EQ(exported.diagnostics[0].path, "/slots/0");
    EXPECT_EQ(exported.diagnostics[0].loc.line, 14);  // the slot's `kind`
}

TEST(MaterialX, TheExportRefusesALayeredMaterialRatherThanFlattenIt) {
    MaterialXExport exported = exportMaterialX(loadMaterial("materials/terrain/terrain.json"), scratch("terrain.mtlx"));
    EXPECT_FALSE(exported.document);
    ASSERT_EQ(exported.diagnostics.size(), 1u);
    EXPECT_EQ(exported.diagnostics[0].code, Code::MaterialXUnsupported);
    EXPECT_EQ(exported.diagnostics[0].path, "/layers");
    EXPECT_GT(exported.diagnostics[0].loc.line, 0);  // at the first layer's first slot
}

std::string fileText(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(MaterialX, TheCommandLineExportsAndCompilesDocuments) {
    using test::runHexc;
    const std::filesystem::path dir = scratch("cli");
    std::filesystem::remove_all(dir);
    const std::string out = (dir / "rock.mtlx").string();
    ASSERT_EQ(runHexc("export-mtlx materials/rock.json -o " + out), 0);
    const std::string first = fileText(out);
    ASSERT_EQ(runHexc("export-mtlx materials/rock.json -o " + out), 0);
    EXPECT_EQ(fileText(out), first);  // byte-identical
    EXPECT_NE(first.find("<hextiledimage name=\"albedo\" type=\"color3\" hexc_mode=\"stable\">"), std::string::npos);
    std::string err;
    EXPECT_EQ(runHexc(out + " -o " + (dir / "shaders").string() + " --no-cache", &err), 0) << err;
    EXPECT_TRUE(std::filesystem::exists(dir / "shaders" / "rock.frag.spv"));
    // Bad input: a located error, exit 1, nothing written; a file name that is not .mtlx: exit 2.
    EXPECT_EQ(runHexc("export-mtlx materials/invalid/falloff_out_of_range.json -o " + (dir / "bad.mtlx").string(), &err), 1);
    EXPECT_NE(err.find("falloff_out_of_range.json:6:16: error[HX106]"), std::string::npos) << err;
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.mtlx"));
    EXPECT_EQ(runHexc("export-mtlx materials/rock.json -o " + (dir / "rock.xml").string()), 2);
}

// A document of several materials: the compiler makes each one's shaders; what reads one material says why not.
TEST(MaterialX, EveryMaterialOfADocumentIsCompiled) {
    std::string text = fileText("materials/mtlx/rock.mtlx");
    const std::string prefix = std::filesystem::absolute("materials/textures").string() + "/";
    text.replace(text.find("../textures/"), 12, prefix);
    const std::string second = R"(<surfacematerial name="rock_copy" type="material" hexc_mode="stable">
    <input name="surfaceshader" type="surfaceshader" nodename="SR_rock" />
  </surfacematerial>
</materialx>)";
    text.replace(text.find("</materialx>"), 12, second);
    const std::filesystem::path doc = scratch("two.mtlx");
    std::ofstream(doc, std::ios::binary) << text;
    std::vector<ParseResult> all = parseMaterialXDocument(text, doc);
    ASSERT_EQ(all.size(), 2u);
    ASSERT_TRUE(all[0].material && all[1].material);
    EXPECT_EQ(all[1].material->name, "rock_copy");
    std::string err;
    const std::filesystem::path out = scratch("two");
    EXPECT_EQ(test::runHexc(doc.string() + " -o " + out.string() + " --no-cache", &err), 0) << err;
    // The same code under another name: OpenGL GLSL's entry point is `main` for both.
    EXPECT_TRUE(withoutBanner(fileText(out / "rock.frag.glsl")) == withoutBanner(fileText(out / "rock_copy.frag.glsl")));
    EXPECT_EQ(test::runHexc("export-mtlx " + doc.string() + " -o " + scratch("one.mtlx").string(), &err), 1);
    EXPECT_NE(err.find("error[HX118]: several <surfacematerial> elements (`rock`, `rock_copy`) where one material is read"),
              std::string::npos)
        << err;
}

// materials/mtlx/corpus/: documents in the shapes MaterialX tools write, with stand-in textures of their own
// (textures/generate.py). Beside each x.mtlx, x.expected holds a line `material NAME: SLOT ...` for each material
// read (its slots in binding order), then every diagnostic of the document in order; a material read compiles.
std::vector<std::string> corpusFiles() {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator("materials/mtlx/corpus"))
        if (entry.path().extension() == ".mtlx") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

class Corpus : public testing::TestWithParam<std::string> {};

TEST_P(Corpus, ReadsAsExpectedAndCompiles) {
    std::filesystem::path file = GetParam();
    const std::vector<ParseResult> results = parseMaterialXDocument(fileText(file), file);
    std::vector<std::string> lines;
    for (const ParseResult& r : results) {
        if (r.material) {
            std::string line = "material " + r.material->name + ":";
            for (const Slot& s : r.material->slots) line += " " + s.name;
            lines.push_back(line);
        }
        for (const Diagnostic& d : r.diagnostics) lines.push_back(d.format());
    }
    std::vector<std::string> expected;
    std::ifstream in(file.replace_extension(".expected"));
    ASSERT_TRUE(in) << file << " is missing";
    for (std::string line; std::getline(in, line);) expected.push_back(line);
    EXPECT_EQ(lines, expected);
    // Each material read compiles, and its export reads back to the same shaders (a slot no standard_surface input
    // carries, such as gltf_pbr's `occlusion`, is the export's refusal, HX118).
    for (const ParseResult& r : results)
        if (r.material) {
            CompileResult c = compile(*r.material);
            EXPECT_TRUE(c.ok()) << formatAll(c.diagnostics);
            const std::filesystem::path out = scratch(r.material->name + ".mtlx");
            MaterialXExport exported = exportMaterialX(*r.material, out);
            if (!exported.document) {
                ASSERT_FALSE(exported.diagnostics.empty());
                EXPECT_EQ(exported.diagnostics[0].code, Code::MaterialXUnsupported);
                continue;
            }
            std::ofstream(out, std::ios::binary) << *exported.document;
            expectSameShaders(*r.material, loadMaterial(out));
        }
}

INSTANTIATE_TEST_SUITE_P(Documents, Corpus, testing::ValuesIn(corpusFiles()),
                         [](const auto& info) { return std::filesystem::path(info.param).stem().string(); });

TEST(Corpus, EveryExpectationHasItsDocument) {
    for (const auto& entry : std::filesystem::directory_iterator("materials/mtlx/corpus"))
        if (entry.path().extension() == ".expected") {
            std::filesystem::path file = entry.path();
            EXPECT_TRUE(std::filesystem::exists(file.replace_extension(".mtlx"))) << entry.path();
        }
}

// What the corpus's value nodes compute is what hexc reads: the onyx shape's converted interface float and
// colorspace="none", the folded document's combine2, multiply, subtract, add and divide.
TEST(Corpus, ValueNodesFeedingSettingsAreComputed) {
    const Material onyx = loadMaterial("materials/mtlx/corpus/onyx_shape.mtlx");
    ASSERT_EQ(onyx.slots.size(), 2u);
    EXPECT_EQ(onyx.slots[0].hex.tiling, (std::array<double, 2>{3.5, 3.5}));
    EXPECT_EQ(onyx.slots[0].hex.rotation, 0.75);
    EXPECT_EQ(onyx.slots[0].hex.falloff, 0.7);
    EXPECT_EQ(onyx.slots[0].hex.scaleRange, (std::array<double, 2>{0.75, 1.5}));  // 1 + (0.5 - 1) 0.5, 1 + (2 - 1) 0.5
    EXPECT_EQ(onyx.slots[1].colorSpace, ColorSpace::Linear);
    EXPECT_EQ(onyx.slots[1].channel, 1);
    const Material folded = loadMaterial("materials/mtlx/corpus/folded_settings.mtlx");
    ASSERT_EQ(folded.slots.size(), 2u);
    EXPECT_EQ(folded.slots[0].hex.tiling, (std::array<double, 2>{3, 5}));
    EXPECT_EQ(folded.slots[0].hex.rotationRange, (std::array<double, 2>{-30, 50}));
    EXPECT_EQ(folded.slots[0].hex.falloff, 0.75);
    EXPECT_EQ(folded.slots[1].hex.tiling, (std::array<double, 2>{1.5, 2.5}));
}
