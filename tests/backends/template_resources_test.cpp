// Templates that bring their own resources (materials/templates/engine.glsl: two uniform blocks in sets 1 and 2,
// a sampler2D, a samplerCube, a separate texture and sampler, push constants): every target places them after
// hexc's without a collision, the manifest lists each where the target put it, and the outputs compile again.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <regex>
#include <set>

#include "hexc/compiler.h"
#include "hexc/layout.h"
#include "hexc/material.h"
#include "hexc/spirv.h"
#include "support.h"

using namespace hexc;
using hexc::test::outputFile;
using json = nlohmann::json;

namespace {

CompileResult compileEngine(const std::string& templ = "materials/templates/engine.glsl", const std::string& extraSlot = "",
                            const CompileOptions& options = {}) {
    std::string text = R"({"name": "engine_rock", "template": ")" + std::filesystem::absolute(templ).string() +
                       R"(", "hextiling": {"tiling": 4},
        "slots": [{"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png"},
                  {"name": "roughness", "kind": "scalar", "texture": "textures/rock_roughness.png"})" +
                       extraSlot + "]}";
    ParseResult parsed = parseMaterial(text, "materials/engine_rock.json");
    if (!parsed.material) throw std::runtime_error(formatAll(parsed.diagnostics));
    return compile(*parsed.material, options);
}

// Every match of `pattern` (its first group) in `text`, which must all differ.
std::multiset<std::string> matches(const std::string& text, const std::string& pattern) {
    std::multiset<std::string> out;
    std::regex re(pattern);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it) out.insert((*it)[1].str());
    return out;
}

void expectDistinct(const std::multiset<std::string>& found, size_t count, const std::string& what) {
    EXPECT_EQ(found.size(), count) << what;
    EXPECT_EQ(std::set<std::string>(found.begin(), found.end()).size(), found.size()) << what << " used twice";
}

// materials/templates/engine.glsl with `from` replaced by `to` (into `text`), written to a temporary file `name`.
std::filesystem::path engineTemplateWith(const std::string& from, const std::string& to, const std::string& name, std::string& text) {
    std::ifstream in("materials/templates/engine.glsl");
    text.assign(std::istreambuf_iterator<char>(in), {});
    text.replace(text.find(from), from.size(), to);
    const std::filesystem::path templ = std::filesystem::temp_directory_path() / name;
    std::ofstream(templ) << text;
    return templ;
}

}  // namespace

// The default layout, and materials/layouts/engine.json: hexc sharing the template's set 1 from binding 5, every
// target's bases moved, HLSL register space 1.
std::vector<CompileOptions> layouts() {
    CompileOptions moved;
    LayoutParseResult example = parseLayoutFile("materials/layouts/engine.json");
    if (!example.layout) throw std::runtime_error(formatAll(example.diagnostics));
    moved.layout = *example.layout;
    moved.hlslShaderModel = 51;
    return {CompileOptions{}, moved};
}

TEST(TemplateResources, EveryTargetPlacesThemWithoutCollisions) {
    for (const CompileOptions& options : layouts()) {
        SCOPED_TRACE("hexc in set " + std::to_string(options.layout.vulkan.set));
        CompileResult r = compileEngine("materials/templates/engine.glsl", "", options);
        ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
        // HLSL: 4 cbuffers (hexc's, Frame, Object, Push), 5 textures, 4 samplers, all in hexc's space.
        std::string hlsl = outputFile(r, "engine_rock.frag.hlsl").contents;
        const std::string space = options.layout.hlsl.space ? ", space" + std::to_string(options.layout.hlsl.space) : "";
        expectDistinct(matches(hlsl, R"(register\((b\d+))" + space + R"(\))"), 4, "HLSL b registers");
        expectDistinct(matches(hlsl, R"(register\((t\d+))" + space + R"(\))"), 5, "HLSL t registers");
        expectDistinct(matches(hlsl, R"(register\((s\d+))" + space + R"(\))"), 4, "HLSL s registers");
        std::string msl = outputFile(r, "engine_rock.frag.metal").contents;
        expectDistinct(matches(msl, R"(\[\[buffer\((\d+)\)\]\])"), 4, "MSL buffers");
        expectDistinct(matches(msl, R"(\[\[texture\((\d+)\)\]\])"), 5, "MSL textures");
        expectDistinct(matches(msl, R"(\[\[sampler\((\d+)\)\]\])"), 4, "MSL samplers");
        // GLSL: 3 uniform blocks, 5 combined samplers on texture units (push constants become a plain uniform).
        std::string glsl = outputFile(r, "engine_rock.frag.glsl").contents;
        expectDistinct(matches(glsl, R"(binding = (\d+), std140)"), 3, "GLSL uniform block bindings");
        expectDistinct(matches(glsl, R"(binding = (\d+)\) uniform sampler)"), 5, "GLSL texture units");
        // SPIR-V: the template's declarations as written, hexc's after them in set 1.
        json spirv = json::parse(outputFile(r, "engine_rock.manifest.json").contents)["targets"]["spirv"];
        EXPECT_EQ(spirv["textures"]["roughness"]["set"], options.layout.vulkan.set);
        EXPECT_EQ(spirv["textures"]["roughness"]["binding"], options.layout.vulkan.binding + 3);
    }
}

TEST(TemplateResources, TheManifestSaysWhereEachTargetPutThem) {
    CompileResult r = compileEngine();
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    json m = json::parse(outputFile(r, "engine_rock.manifest.json").contents);
    std::string hlsl = outputFile(r, "engine_rock.frag.hlsl").contents, msl = outputFile(r, "engine_rock.frag.metal").contents,
                glsl = outputFile(r, "engine_rock.frag.glsl").contents;
    for (const std::string target : {"spirv", "hlsl", "glsl", "msl"})
        ASSERT_EQ(m["targets"][target]["template_resources"].size(), 7u) << target;
    for (const json& res : m["targets"]["hlsl"]["template_resources"]) {
        std::string name = res["name"];
        // The declaration of `name` carries the register the manifest gives (cbuffers by their block name).
        std::string reg = res["register"];
        EXPECT_TRUE(std::regex_search(hlsl, std::regex("\\b" + name + "\\b[^;\\n]*register\\(" + reg + "\\)"))) << name << " " << reg;
        if (res.contains("sampler_register")) {
            std::regex sampler("_" + name + "_sampler : register\\(" + res["sampler_register"].get<std::string>() + "\\)");
            EXPECT_TRUE(std::regex_search(hlsl, sampler)) << name;
        }
    }
    for (const json& res : m["targets"]["msl"]["template_resources"]) {
        std::string name = res["name"], what = res.contains("buffer") ? "buffer" : res.contains("texture") ? "texture" : "sampler";
        int index = res[what].get<int>();
        EXPECT_TRUE(
            std::regex_search(msl, std::regex("\\b" + name + "\\b[^,)]*\\[\\[" + what + "\\(" + std::to_string(index) + "\\)\\]\\]")))
            << name;
    }
    for (const json& res : m["targets"]["glsl"]["template_resources"]) {
        if (!res.contains("texture_unit") || res["kind"] == "sampled_image") continue;  // combined images keep the image's name
        std::string name = res["name"];
        EXPECT_TRUE(std::regex_search(
            glsl, std::regex("binding = " + std::to_string(res["texture_unit"].get<int>()) + "\\) uniform \\w+ " + name + ";")))
            << name;
    }
    // One vocabulary for hexc's resources and the template's: each one's Vulkan descriptor type, its kind the same in
    // lower case; push constants give their byte range (engine.glsl: `layout(offset = 16) float ambient`).
    std::map<std::string, std::string> types;
    for (const json& res : m["targets"]["spirv"]["template_resources"]) {
        if (res["kind"] == "push_constant") {
            types[res["name"]] = res["offset"].dump() + "+" + res["size"].dump();
            continue;
        }
        std::string lower = res["vulkan"]["descriptor_type"];
        std::transform(lower.begin(), lower.end(), lower.begin(), [](char c) { return char(std::tolower(c)); });
        EXPECT_EQ(res["kind"], lower);
        types[res["name"]] = res["vulkan"]["descriptor_type"];
    }
    EXPECT_EQ(types, (std::map<std::string, std::string>{{"Frame", "UNIFORM_BUFFER"},
                                                         {"Object", "UNIFORM_BUFFER"},
                                                         {"Push", "16+4"},
                                                         {"shadowMap", "COMBINED_IMAGE_SAMPLER"},
                                                         {"environment", "COMBINED_IMAGE_SAMPLER"},
                                                         {"detail", "SAMPLED_IMAGE"},
                                                         {"detailSampler", "SAMPLER"}}));
    EXPECT_EQ(m["targets"]["spirv"]["sampler"]["descriptor_type"], "SAMPLER");
    // hexc's own resources keep their documented places.
    EXPECT_EQ(m["targets"]["hlsl"]["params"]["register"], "b0");
    EXPECT_EQ(m["targets"]["hlsl"]["textures"]["roughness"]["register"], "t1");
    EXPECT_EQ(m["targets"]["spirv"]["textures"]["albedo"]["binding"], 2);
}

TEST(TemplateResources, TheHlslOutputCompilesAgain) {
    CompileResult r = compileEngine();
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    json m = json::parse(outputFile(r, "engine_rock.manifest.json").contents);
    SpirvResult again = compileToSpirv(outputFile(r, "engine_rock.frag.hlsl").contents, ShaderStage::Fragment, "engine_rock.frag.hlsl",
                                       SourceLanguage::Hlsl, m["targets"]["hlsl"]["entry_point"]);
    EXPECT_FALSE(again.words.empty()) << formatAll(again.diagnostics);
}

TEST(TemplateResources, OneAtHexcsBindingsIsALocatedError) {
    std::string text;
    const std::filesystem::path templ =
        engineTemplateWith("layout(set = 1, binding = 1) uniform sampler2D shadowMap;",
                           "layout(set = 0, binding = 3) uniform sampler2D shadowMap;", "hexc_set0_template.glsl", text);
    CompileResult r = compileEngine(templ.string());
    ASSERT_FALSE(r.ok());
    const Diagnostic& d = r.diagnostics.back();
    EXPECT_EQ(d.loc.file, templ.string());
    int line = 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(text.find("shadowMap")), '\n'));
    EXPECT_EQ(d.loc.line, line);
    EXPECT_NE(d.message.find("`shadowMap` is in descriptor set 0, binding 3, which hexc's layout takes (set 0, bindings 0-3"),
              std::string::npos)
        << d.format();
    EXPECT_TRUE(r.files.empty());
}

TEST(TemplateResources, OneInHexcsSetPastItsBindingsIsTheTemplates) {
    std::string text;
    const std::filesystem::path templ =
        engineTemplateWith("layout(set = 1, binding = 1) uniform sampler2D shadowMap;",
                           "layout(set = 0, binding = 4) uniform sampler2D shadowMap;", "hexc_set0_free_template.glsl", text);
    CompileResult r = compileEngine(templ.string());
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    json placed = json::parse(outputFile(r, "engine_rock.manifest.json").contents)["targets"]["spirv"]["template_resources"];
    bool found = false;
    for (const json& res : placed)
        found |= res["name"] == "shadowMap" && res["kind"] == "combined_image_sampler" &&
                 res["vulkan"] == json{{"set", 0}, {"binding", 4}, {"descriptor_type", "COMBINED_IMAGE_SAMPLER"}};
    EXPECT_TRUE(found) << placed.dump();
}

// Combined image samplers (layout vulkan.combined) leave no sampler to share: a template that samples its own texture
// with hexc's sampler is told so, and nothing is written.
TEST(TemplateResources, CombinedSamplersAndATemplateReadingHexcsSampler) {
    std::string text;
    const std::filesystem::path templ =
        engineTemplateWith("sampler2D(detail, detailSampler)", "sampler2D(detail, hexcSampler)", "hexc_shares_sampler.glsl", text);
    CompileOptions combined;
    combined.layout.vulkan.combined = 1;
    ASSERT_TRUE(compileEngine(templ.string()).ok());  // separate samplers: the template may share hexc's
    CompileResult r = compileEngine(templ.string(), "", combined);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(formatAll(r.diagnostics).find("--combined: error[HX"), std::string::npos) << formatAll(r.diagnostics);
    EXPECT_NE(formatAll(r.diagnostics).find("reads hexcSampler or a hexcTex_ texture itself"), std::string::npos);
    EXPECT_TRUE(r.files.empty());
    EXPECT_TRUE(compileEngine("materials/templates/engine.glsl", "", combined).ok());
}

// The layout gives the template's resources bases of their own: an engine's per-frame block at b0 and buffer(0),
// hexc's moved out of the way; with template_spaces, Vulkan set N becomes HLSL space N.
TEST(TemplateResources, TheLayoutPlacesTheTemplatesOwn) {
    CompileOptions options;
    ResourceLayout& l = options.layout;
    l.hlsl.b = 3, l.hlsl.t = 4, l.hlsl.s = 3, l.hlsl.templateB = l.hlsl.templateT = l.hlsl.templateS = 0;
    l.msl.buffer = 4, l.msl.texture = 4, l.msl.sampler = 3, l.msl.templateBuffer = l.msl.templateTexture = l.msl.templateSampler = 0;
    CompileResult r = compileEngine("materials/templates/engine.glsl", "", options);
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    const std::string hlsl = outputFile(r, "engine_rock.frag.hlsl").contents, msl = outputFile(r, "engine_rock.frag.metal").contents;
    auto has = [](const std::string& text, const std::string& pattern) { return std::regex_search(text, std::regex(pattern)); };
    EXPECT_TRUE(has(hlsl, R"(cbuffer Frame : register\(b0\))")) << hlsl;
    EXPECT_TRUE(has(hlsl, R"(cbuffer Object : register\(b1\))"));
    EXPECT_TRUE(has(hlsl, R"(cbuffer HexcParams : register\(b3\))"));
    EXPECT_TRUE(has(hlsl, R"(\bshadowMap : register\(t0\))"));
    EXPECT_TRUE(has(hlsl, R"(\bhexcTex_albedo : register\(t4\))"));
    EXPECT_TRUE(has(msl, R"(constant Frame& frame \[\[buffer\(0\)\]\])")) << msl;
    EXPECT_TRUE(has(msl, R"(constant HexcParams& hexcParams \[\[buffer\(4\)\]\])"));
    EXPECT_TRUE(has(msl, R"(texture2d<float> shadowMap \[\[texture\(0\)\]\])"));
    const json m = json::parse(outputFile(r, "engine_rock.manifest.json").contents);
    EXPECT_EQ(m["targets"]["hlsl"]["template_resources"][0]["register"], "b0");
    EXPECT_EQ(m["targets"]["msl"]["template_resources"][0]["buffer"], 0);

    CompileOptions spaces;
    spaces.hlslShaderModel = 51;
    spaces.layout.hlsl.templateSpaces = 1;
    r = compileEngine("materials/templates/engine.glsl", "", spaces);
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    const std::string spaced = outputFile(r, "engine_rock.frag.hlsl").contents;
    EXPECT_TRUE(has(spaced, R"(cbuffer Frame : register\(b0, space1\))")) << spaced;
    EXPECT_TRUE(has(spaced, R"(cbuffer Object : register\(b0, space2\))"));
    EXPECT_TRUE(has(spaced, R"(\bshadowMap : register\(t0, space1\))"));
    EXPECT_TRUE(has(spaced, R"(cbuffer HexcParams : register\(b0, space0\))"));
}

// A template base onto hexc's registers or indices is an error naming both settings.
TEST(TemplateResources, TemplateBasesOntoHexcsAreErrors) {
    CompileOptions options;
    options.layout.hlsl.templateB = 0;
    CompileResult r = compileEngine("materials/templates/engine.glsl", "", options);
    EXPECT_EQ(formatAll(r.diagnostics),
              "--hlsl-template-b: error[HX210]: `Frame` would take HLSL register b0 in space 0, which one of hexc's resources takes; "
              "move the template's b registers (hlsl.template_b) or hexc's (hlsl.b)\n");
    options = {};
    options.layout.msl.templateTexture = 1;
    r = compileEngine("materials/templates/engine.glsl", "", options);
    EXPECT_EQ(formatAll(r.diagnostics),
              "--msl-template-texture: error[HX210]: `shadowMap` would take MSL texture index 1, which one of hexc's resources takes; "
              "move the template's (msl.template_texture) or hexc's (msl.texture)\n");
}

// Layout msl.argument_buffers: one argument buffer per descriptor set at [[buffer(set)]], every resource at the
// [[id]] the manifest gives, no id twice in one buffer, push constants a buffer after them.
TEST(TemplateResources, MslArgumentBuffersHoldWhatTheManifestSays) {
    CompileOptions options;
    options.layout.msl.argumentBuffers = 1;
    CompileResult r = compileEngine("materials/templates/engine.glsl", "", options);
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics);
    const std::string msl = outputFile(r, "engine_rock.frag.metal").contents;
    const json target = json::parse(outputFile(r, "engine_rock.manifest.json").contents)["targets"]["msl"];
    EXPECT_EQ(target["argument_buffers"], true);
    // Each struct's members and their ids.
    std::map<int, std::string> structs;
    for (int set = 0; set < 3; ++set) {
        const size_t at = msl.find("struct spvDescriptorSetBuffer" + std::to_string(set) + "\n");
        ASSERT_NE(at, std::string::npos) << set;
        structs[set] = msl.substr(at, msl.find("};", at) - at);
        expectDistinct(matches(structs[set], R"(\[\[id\((\d+)\)\]\])"), set == 0 ? 4u : set == 1 ? 7u : 1u, "ids");
        EXPECT_NE(msl.find("spvDescriptorSet" + std::to_string(set) + " [[buffer(" + std::to_string(set) + ")]]"), std::string::npos);
    }
    auto member = [&](const json& where, const std::string& name) {
        const std::string& text = structs[where["argument_buffer"].get<int>()];
        EXPECT_TRUE(
            std::regex_search(text, std::regex("\\b" + name + " \\[\\[id\\(" + std::to_string(where["id"].get<int>()) + "\\)\\]\\]")))
            << name << " " << where.dump();
    };
    member(target["params"], "hexcParams");
    member(target["sampler"], "hexcSampler");
    member(target["textures"]["roughness"], "hexcTex_roughness");
    for (const json& res : target["template_resources"]) {
        if (res["kind"] == "push_constant") {
            EXPECT_NE(msl.find("constant Push& push [[buffer(" + std::to_string(res["buffer"].get<int>()) + ")]]"), std::string::npos);
            continue;
        }
        const std::string name =
            res["kind"] == "uniform_buffer" ? std::string(res["name"] == "Frame" ? "frame" : "object") : res["name"].get<std::string>();
        member(res, name);
        if (res.contains("sampler_id")) {
            EXPECT_NE(structs[1].find(name + "Smplr [[id(" + std::to_string(res["sampler_id"].get<int>()) + ")]]"), std::string::npos);
        }
    }
}
