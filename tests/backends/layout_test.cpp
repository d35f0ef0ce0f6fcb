// Resource layouts (CompileOptions::layout, `--layout`, `--set` ...): each target puts hexc's resources where the
// layout says, the manifest says the same, and a shader moved by a layout renders exactly what the default one does
// on lavapipe, bound where the manifest says (render.cpp), on SPIR-V, HLSL and GLSL.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstring>
#include <fstream>

#include "hexc/compiler.h"
#include "hexc/layout.h"
#include "hexc/spirv.h"
#include "support.h"
#include "vk/render.h"

using namespace hexc;
using hexc::test::loadMaterial;
using hexc::test::outputFile;
using hexc::test::runner;
using json = nlohmann::json;

namespace {

Material rock() { return loadMaterial("materials/rock.json"); }

struct NamedLayout {
    const char* name;
    ResourceLayout layout;
    uint32_t shaderModel;
};

// Default; hexc in set 3 from binding 4 with combined image samplers in SPIR-V and every other target's bases
// moved; HLSL register spaces (space = set, as dxc -spirv and glslang read them back).
std::vector<NamedLayout> layouts() {
    ResourceLayout shifted;
    shifted.vulkan = {3, 4, 1};
    shifted.hlsl = {0, 2, 5, 3, 1};
    shifted.msl = {2, 3, 1};
    shifted.glsl = {3};
    ResourceLayout spaces;
    spaces.vulkan = {2, 0};
    spaces.hlsl = {2, 1, 4, 2, 0};
    return {{"default", {}, 50}, {"shifted", shifted, 50}, {"spaces", spaces, 51}};
}

CompileResult compileWith(const NamedLayout& l) {
    CompileOptions options;
    options.layout = l.layout;
    options.hlslShaderModel = l.shaderModel;
    CompileResult r = compile(rock(), options);
    EXPECT_TRUE(r.ok()) << formatAll(r.diagnostics);
    return r;
}

}  // namespace

TEST(Layout, EveryTargetAndTheManifestPutHexcsResourcesWhereItSays) {
    for (const NamedLayout& l : layouts()) {
        SCOPED_TRACE(l.name);
        CompileResult r = compileWith(l);
        const ResourceLayout& L = l.layout;
        json targets = json::parse(outputFile(r, ".manifest.json").contents)["targets"];
        // rock's slots in order: albedo, normal, roughness.
        EXPECT_EQ(targets["spirv"]["params"],
                  (json{{"set", L.vulkan.set}, {"binding", L.vulkan.binding}, {"descriptor_type", "UNIFORM_BUFFER"}}));
        EXPECT_EQ(targets["spirv"]["textures"]["roughness"]["binding"], L.vulkan.binding + 4);
        EXPECT_EQ(targets["spirv"]["textures"]["roughness"]["descriptor_type"],
                  L.vulkan.combined ? "COMBINED_IMAGE_SAMPLER" : "SAMPLED_IMAGE");
        EXPECT_EQ(targets["spirv"]["sampler"].contains("combined_into_textures"), L.vulkan.combined == 1);
        // Combined: no sampler variable is left in the module, and each texture is a sampler2D.
        const std::string spirv = disassemble(spirvWords(outputFile(r, ".spv").contents));
        EXPECT_EQ(spirv.find("%hexcSampler = OpVariable"), L.vulkan.combined ? std::string::npos : spirv.find("%hexcSampler = OpVariable"));
        EXPECT_EQ(spirv.find("OpSampledImage") == std::string::npos, L.vulkan.combined == 1);
        const std::string space = L.hlsl.space ? ", space" + std::to_string(L.hlsl.space) : "";
        const std::string hlsl = outputFile(r, ".hlsl").contents;
        EXPECT_NE(hlsl.find("hexcTex_roughness : register(t" + std::to_string(L.hlsl.t + 2) + space + ")"), std::string::npos);
        EXPECT_NE(hlsl.find("hexcSampler : register(s" + std::to_string(L.hlsl.s) + space + ")"), std::string::npos);
        EXPECT_NE(hlsl.find("HexcParams : register(b" + std::to_string(L.hlsl.b) + space + ")"), std::string::npos);
        EXPECT_EQ(targets["hlsl"]["textures"]["roughness"],
                  (json{{"register", "t" + std::to_string(L.hlsl.t + 2)}, {"space", L.hlsl.space}}));
        const std::string msl = outputFile(r, ".metal").contents;
        EXPECT_NE(msl.find("hexcTex_roughness [[texture(" + std::to_string(L.msl.texture + 2) + ")]]"), std::string::npos);
        EXPECT_NE(msl.find("hexcSampler [[sampler(" + std::to_string(L.msl.sampler) + ")]]"), std::string::npos);
        EXPECT_NE(msl.find("hexcParams [[buffer(" + std::to_string(L.msl.buffer) + ")]]"), std::string::npos);
        EXPECT_EQ(targets["msl"]["textures"]["roughness"]["texture"], L.msl.texture + 2);
        const std::string glsl = outputFile(r, ".frag.glsl").contents;
        EXPECT_NE(glsl.find("layout(binding = " + std::to_string(L.glsl.binding + 2) + ") uniform sampler2D hexcTex_roughness"),
                  std::string::npos);
        EXPECT_EQ(targets["glsl"]["params"]["binding"], L.glsl.binding);
    }
}

TEST(Layout, AMovedShaderRendersWhatTheDefaultOneDoes) {
    REQUIRE_VULKAN();
    const View view{48, 48, {0.1, 0.2, 0.6, 0.7}};
    const std::vector<NamedLayout> all = layouts();
    for (vk::ExecutedTarget target : {vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl}) {
        Image base;
        for (const NamedLayout& l : all) {
            SCOPED_TRACE(std::string(l.name) + " on target " + std::to_string(int(target)));
            CompileOptions options;
            options.layout = l.layout;
            options.hlslShaderModel = l.shaderModel;
            Image image = vk::render(*runner(&whyNoVulkan), rock(), vk::RenderOutput::Shaded, "", view, target, 0, nullptr, {}, options);
            if (&l == &all.front()) {
                base = image;
                // Not a blank image: three textures were read (a wrongly bound one would fail validation or read black).
                double sum = 0;
                for (float v : image.rgba) sum += v;
                EXPECT_GT(sum / double(image.rgba.size()), 0.05);
                continue;
            }
            ASSERT_EQ(image.rgba.size(), base.rgba.size());
            EXPECT_EQ(std::memcmp(image.rgba.data(), base.rgba.data(), base.rgba.size() * sizeof(float)), 0);
        }
    }
}

TEST(Layout, FileErrorsAreLocated) {
    LayoutParseResult r =
        parseLayout("{\n  \"vulkan\": {\"set\": 40},\n  \"hlsl\": {\"spcae\": 1},\n  \"metal\": {}\n}", "engine.layout.json");
    ASSERT_FALSE(r.layout);
    std::string all = formatAll(r.diagnostics);
    EXPECT_NE(all.find("engine.layout.json:2:21: error[HX106]: /vulkan/set: expected a number in [0, 31], got 40"), std::string::npos)
        << all;
    EXPECT_NE(all.find("engine.layout.json:3:12: error[HX103]: /hlsl/spcae"), std::string::npos) << all;
    EXPECT_NE(all.find("did you mean `space`?"), std::string::npos) << all;
    EXPECT_NE(all.find("/metal"), std::string::npos) << all;
}

TEST(Layout, CommandLineFlagsOverrideTheFileAndNeedSpacesInShaderModel51) {
    std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_layout_cli";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "layout.json") << R"({"vulkan": {"set": 1, "binding": 8}, "msl": {"texture": 4}})";
    std::string err;
    ASSERT_EQ(test::runHexc("materials/rock.json -o " + (dir / "out").string() + " --layout " + (dir / "layout.json").string() +
                                " --binding 2 --depfile " + (dir / "rock.d").string(),
                            &err),
              0)
        << err;
    json targets = json::parse(std::ifstream(dir / "out" / "rock.manifest.json"))["targets"];
    EXPECT_EQ(targets["spirv"]["sampler"]["set"], 1);
    EXPECT_EQ(targets["spirv"]["sampler"]["binding"], 3);
    EXPECT_EQ(targets["msl"]["textures"]["albedo"]["texture"], 4);
    // The layout file is an input: the depfile names it.
    std::ifstream dep(dir / "rock.d");
    EXPECT_NE(std::string(std::istreambuf_iterator<char>(dep), {}).find("layout.json"), std::string::npos);

    EXPECT_EQ(test::runHexc("materials/rock.json -o " + (dir / "out2").string() + " --hlsl-space 1", &err), 2);
    EXPECT_NE(err.find("needs --hlsl-sm 51"), std::string::npos) << err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out2"));
    EXPECT_EQ(test::runHexc("materials/rock.json -o " + (dir / "out3").string() + " --set 32", &err), 2);
    std::ofstream(dir / "bad.json") << R"({"glsl": {"binding": -1}})";
    EXPECT_EQ(test::runHexc("materials/rock.json -o " + (dir / "out4").string() + " --layout " + (dir / "bad.json").string(), &err), 1);
    EXPECT_NE(err.find("bad.json:1:22: error[HX106]: /glsl/binding"), std::string::npos) << err;
}

namespace {

// A w x h float texture of one colour: every mip level and every filtered sample is that colour exactly.
Texture flat(float r, float g, float b) {
    Texture t;
    t.width = t.height = 4;
    for (int i = 0; i < 16; ++i) t.rgba32f.insert(t.rgba32f.end(), {r, g, b, 1.0f});
    return t;
}

std::vector<uint8_t> bytes(std::initializer_list<float> values) {
    std::vector<uint8_t> out(values.size() * 4);
    std::memcpy(out.data(), values.begin(), out.size());
    return out;
}

}  // namespace

// materials/templates/engine.glsl on lavapipe from its SPIR-V, HLSL and OpenGL GLSL, its per-frame and per-object
// blocks, shadow map, environment map, separate texture and sampler, and push constants bound where each target's
// manifest entry says, under three layouts: the default; every base shifted (hexc in set 3 from binding 4, HLSL
// registers b2 t5 s3 in space 0, GLSL from 3); materials/layouts/engine.json (hexc sharing the template's set 1 from
// binding 5, HLSL register space 1 under SM 5.1). Every pixel is what the template computes from hexc's albedo
// (rendered alone, and checked against the fp64 reference by the ColorPath tests) and the template's values.
namespace {

// engine_rock's template, shaded on every target in three layouts: its own resources and hexc's all read right.
void expectTheEngineTemplateReadsBoth(const Material& m) {
    std::string why;
    vk::Runner& gpu = *runner(&why);
    const View view{40, 40, {0.1, 0.2, 0.5, 0.6}};
    Image albedo = vk::render(gpu, m, vk::RenderOutput::Albedo, "albedo", view);

    const Texture shadow = flat(0.5f, 0, 0), environment = flat(0.5f, 0.25f, 1.0f), detail = flat(0.75f, 0, 0);
    // Data and images only: each resource's descriptor type, set and binding come from the manifest alone (its
    // `descriptor_type`), as an engine building its descriptor set layouts from it takes them.
    auto data = [](std::vector<uint8_t> bytes) { return vk::TemplateResource{{}, 0, 0, std::move(bytes), nullptr}; };
    auto image = [](const Texture& t) { return vk::TemplateResource{{}, 0, 0, {}, &t}; };
    vk::TemplateInputs own;
    own.resources = {{"Frame", data(bytes({0, 0, 1, 2.0f}))},             // lightDir +z, exposure 2
                     {"Object", data(bytes({1.0f, 0.5f, 0.25f, 1.0f}))},  // tint
                     {"shadowMap", image(shadow)},
                     {"environment", image(environment)},
                     {"detail", image(detail)},
                     {"detailSampler", {}}};
    own.pushConstants = bytes({0.25f});  // ambient
    std::vector<std::pair<std::string, CompileOptions>> all(4);
    all[0].first = "default";
    all[1] = {"shifted", {}};
    all[1].second.layout = layouts()[1].layout;
    LayoutParseResult example = parseLayoutFile("materials/layouts/engine.json");
    ASSERT_TRUE(example.layout) << formatAll(example.diagnostics);
    all[2] = {"engine.json", {}};
    all[2].second.layout = *example.layout;
    all[2].second.hlslShaderModel = 51;
    // The template's per-frame block at b0 (in HLSL space 1, its Vulkan set) and buffer(0), hexc's after it.
    all[3] = {"template bases", {}};
    ResourceLayout& bases = all[3].second.layout;
    bases.hlsl.b = 3, bases.hlsl.t = 4, bases.hlsl.s = 3, bases.hlsl.templateB = bases.hlsl.templateT = bases.hlsl.templateS = 0;
    bases.hlsl.templateSpaces = 1;
    bases.msl.buffer = 4, bases.msl.texture = 4, bases.msl.sampler = 3, bases.msl.templateBuffer = 0;
    all[3].second.hlslShaderModel = 51;
    for (const auto& [name, options] : all)
        for (vk::ExecutedTarget target : {vk::ExecutedTarget::Spirv, vk::ExecutedTarget::Hlsl, vk::ExecutedTarget::Glsl}) {
            const char* targetName = target == vk::ExecutedTarget::Hlsl ? "HLSL" : target == vk::ExecutedTarget::Glsl ? "GLSL" : "SPIR-V";
            SCOPED_TRACE(name + " layout, " + targetName);
            Image image = vk::render(gpu, m, vk::RenderOutput::Shaded, "", view, target, 0, nullptr, {}, options, own);
            // N = light = +z: diffuse = shadow = 0.5; the sky term reads the environment's colour. Both shaders compute the
            // albedo from the same GLSL; the rest is a few float32 operations on values below 4, so 1e-5 covers any
            // contraction or reordering the optimisers choose (about 30 ulps at 4).
            const float tint[3] = {1.0f, 0.5f, 0.25f}, sky[3] = {0.5f, 0.25f, 1.0f};
            double worst = 0;
            for (size_t p = 0; p < image.rgba.size(); p += 4)
                for (size_t c = 0; c < 3; ++c) {
                    const double expected = (albedo.rgba[p + c] * tint[c] * (0.25 + 0.5) + sky[c] * 0.04) * 0.75 * 2.0;
                    worst = std::max(worst, std::fabs(double(image.rgba[p + c]) - expected));
                }
            std::printf("  %s layout, %s: worst difference %.2e\n", name.c_str(), targetName, worst);
            EXPECT_LE(worst, 1e-5);
        }
}

}  // namespace

TEST(Layout, AnEngineTemplateReadsItsOwnResourcesAndHexcs) {
    REQUIRE_VULKAN();
    ParseResult parsed = parseMaterialFile("materials/engine_rock.json");
    ASSERT_TRUE(parsed.material) << formatAll(parsed.diagnostics);
    // Both blends: the histogram blend's look-up tables take bindings after every slot's texture, which the template's
    // own resources must still avoid on every target.
    for (Blend blend : {Blend::Falloff, Blend::Histogram}) {
        Material m = *parsed.material;
        for (Slot& s : m.slots)
            if (s.kind != SlotKind::Normal) s.hex.blend = blend;
        SCOPED_TRACE(std::string("blend ") + std::string(toString(blend)));
        expectTheEngineTemplateReadsBoth(m);
    }
}
