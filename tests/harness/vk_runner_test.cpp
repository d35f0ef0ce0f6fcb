// Tests of the lavapipe runner (vk/runner.h), the full-screen vertex template, and image I/O (hexc/image.h).
// Vulkan tests skip when there is no Vulkan device; set HEXC_REQUIRE_VULKAN=1 (as CI should) to fail instead.
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

#include "vk/shaders.h"
#include "hexc/image.h"
#include "vk/runner.h"

namespace {

using hexc::Image;
using hexc::Texture;
using hexc::vk::RenderRequest;
using hexc::vk::Runner;

std::vector<uint32_t> compileGlsl(const std::string& source, EShLanguage stage) {
    static const bool initialized = glslang::InitializeProcess();  // once per process
    EXPECT_TRUE(initialized);
    glslang::TShader shader(stage);
    const char* text = source.c_str();
    shader.setStrings(&text, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    const auto messages = EShMessages(EShMsgSpvRules | EShMsgVulkanRules);
    if (!shader.parse(GetDefaultResources(), 100, false, messages)) {
        ADD_FAILURE() << shader.getInfoLog() << "\n" << source;
        return {};
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages)) {
        ADD_FAILURE() << program.getInfoLog();
        return {};
    }
    std::vector<uint32_t> spirv;
    glslang::GlslangToSpv(*program.getIntermediate(stage), spirv);
    return spirv;
}

std::string readFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    EXPECT_TRUE(in) << "cannot read " << file;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// A fragment shader body over the fixed interface: v_uv in, o_color out, set 0 as documented in runner.h.
std::vector<uint32_t> fragment(const std::string& declarations, const std::string& body) {
    return compileGlsl(
        "#version 450\n"
        "layout(location = 0) in vec2 v_uv;\n"
        "layout(location = 0) out vec4 o_color;\n" +
            declarations + "\nvoid main() {\n" + body + "\n}\n",
        EShLangFragment);
}

const char* kTextureDeclarations =
    "layout(set = 0, binding = 0, std140) uniform Params { float lod; } params;\n"
    "layout(set = 0, binding = 1) uniform sampler samp;\n"
    "layout(set = 0, binding = 2) uniform texture2D tex;\n";

std::vector<uint8_t> uniformFloats(std::initializer_list<float> values) {
    std::vector<uint8_t> bytes(values.size() * sizeof(float));
    std::memcpy(bytes.data(), values.begin(), bytes.size());
    return bytes;
}

class VkRunnerTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        runner_ = Runner::create(&whyNot_);
        if (runner_) vertex_ = compileGlsl(hexc::vk::harnessShaders().at("fullscreen.vert.glsl"), EShLangVertex);
    }
    static void TearDownTestSuite() { runner_.reset(); }

    void SetUp() override {
        if (runner_) return;
        const char* require = std::getenv("HEXC_REQUIRE_VULKAN");
        if (require && std::string(require) == "1") FAIL() << "no Vulkan device: " << whyNot_;
        GTEST_SKIP() << "no Vulkan device: " << whyNot_;
    }

    RenderRequest request(std::vector<uint32_t> fragmentSpirv, int width, int height) const {
        RenderRequest r;
        r.vertexSpirv = vertex_;
        r.fragmentSpirv = std::move(fragmentSpirv);
        r.width = width;
        r.height = height;
        return r;
    }

    static std::unique_ptr<Runner> runner_;
    static std::string whyNot_;
    static std::vector<uint32_t> vertex_;
};
std::unique_ptr<Runner> VkRunnerTest::runner_;
std::string VkRunnerTest::whyNot_;
std::vector<uint32_t> VkRunnerTest::vertex_;

TEST_F(VkRunnerTest, UvMatchesPixelCentreMapping) {
    RenderRequest r = request(fragment("", "o_color = vec4(v_uv, 0.0, 1.0);"), 8, 4);
    r.uvRect = {0.25f, 0.5f, 1.25f, 2.5f};
    const Image image = runner_->render(r).image;
    ASSERT_EQ(image.width, 8);
    ASSERT_EQ(image.height, 4);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 8; ++i) {
            // The mapping documented in templates/harness/fullscreen.vert.glsl; row j = 0 is the top.
            const double u = 0.25 + (i + 0.5) / 8 * (1.25 - 0.25);
            const double v = 0.5 + (j + 0.5) / 4 * (2.5 - 0.5);
            const float* p = image.at(i, j);
            EXPECT_NEAR(p[0], u, 1e-6) << "pixel " << i << "," << j;
            EXPECT_NEAR(p[1], v, 1e-6) << "pixel " << i << "," << j;
            EXPECT_EQ(p[2], 0.0f);
            EXPECT_EQ(p[3], 1.0f);
        }
}

TEST_F(VkRunnerTest, NormalAndTangentAreConstant) {
    const Image image = runner_
                            ->render(request(fragment("layout(location = 1) in vec3 v_normal;\n"
                                                      "layout(location = 2) in vec4 v_tangent;\n",
                                                      "o_color = vec4(v_normal.z, v_tangent.xw, v_normal.x + "
                                                      "v_normal.y + v_tangent.y + v_tangent.z);"),
                                             2, 2))
                            .image;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            const float* p = image.at(i, j);
            EXPECT_EQ(p[0], 1.0f);
            EXPECT_EQ(p[1], 1.0f);
            EXPECT_EQ(p[2], 1.0f);
            EXPECT_EQ(p[3], 0.0f);
        }
}

Texture texture8(int width, int height, bool srgb) {
    Texture t;
    t.width = width;
    t.height = height;
    t.srgb = srgb;
    for (int i = 0; i < width * height * 4; ++i) t.rgba8.push_back(uint8_t(i * 37 + 11));  // distinct per texel
    return t;
}

TEST_F(VkRunnerTest, TexelCentresSampleExactTexels) {
    const Texture texture = texture8(4, 4, false);
    RenderRequest r = request(fragment(kTextureDeclarations, "o_color = textureLod(sampler2D(tex, samp), v_uv, 0.0);"), 4, 4);
    r.textures = {&texture};
    const Image image = runner_->render(r).image;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            for (int c = 0; c < 4; ++c)
                EXPECT_NEAR(image.at(x, y)[c], texture.rgba8[(y * 4 + x) * 4 + c] / 255.0, 1e-6)
                    << "texel " << x << "," << y << " channel " << c;
}

TEST_F(VkRunnerTest, SrgbTexturesDecodeToLinear) {
    Texture texture = texture8(2, 2, true);
    std::fill(texture.rgba8.begin(), texture.rgba8.end(), uint8_t(128));
    RenderRequest r = request(fragment(kTextureDeclarations, "o_color = textureLod(sampler2D(tex, samp), v_uv, 0.0);"), 2, 2);
    r.textures = {&texture};
    const Image image = runner_->render(r).image;
    const double linear = std::pow((128 / 255.0 + 0.055) / 1.055, 2.4);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(1, 1)[c], linear, 1e-3);
    EXPECT_NEAR(image.at(1, 1)[3], 128 / 255.0, 1e-6);  // alpha is never sRGB-encoded
}

// Float texture: the mip chain is built by linear blits, which for even sizes are exact 2x2 averages.
TEST_F(VkRunnerTest, MipLevelsAreBoxAverages) {
    Texture texture;
    texture.width = texture.height = 4;
    for (int i = 0; i < 64; ++i) texture.rgba32f.push_back(float(i % 7) * 0.125f + float(i / 4) * 0.01f);
    auto texel = [&](int x, int y, int c) { return double(texture.rgba32f[(y * 4 + x) * 4 + c]); };

    RenderRequest r = request(fragment(kTextureDeclarations, "o_color = textureLod(sampler2D(tex, samp), v_uv, params.lod);"), 2, 2);
    r.textures = {&texture};
    r.uniformData = uniformFloats({1.0f});
    const Image level1 = runner_->render(r).image;  // 2x2 pixels land on the 2x2 level's texel centres
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
            for (int c = 0; c < 4; ++c) {
                const double box =
                    (texel(2 * x, 2 * y, c) + texel(2 * x + 1, 2 * y, c) + texel(2 * x, 2 * y + 1, c) + texel(2 * x + 1, 2 * y + 1, c)) / 4;
                EXPECT_NEAR(level1.at(x, y)[c], box, 1e-6) << "level 1 texel " << x << "," << y;
            }

    r.uniformData = uniformFloats({2.0f});
    const Image level2 = runner_->render(r).image;
    for (int c = 0; c < 4; ++c) {
        double mean = 0;
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) mean += texel(x, y, c) / 16;
        EXPECT_NEAR(level2.at(0, 0)[c], mean, 1e-6) << "level 2, channel " << c;
    }
}

TEST_F(VkRunnerTest, UniformDataReachesShader) {
    RenderRequest r =
        request(fragment("layout(set = 0, binding = 0, std140) uniform Params { vec4 a; vec4 b; } p;", "o_color = p.a * p.b;"), 3, 2);
    r.uniformData = uniformFloats({0.5f, -2.0f, 0.25f, 8.0f, 3.0f, 0.5f, -4.0f, 0.125f});
    const Image image = runner_->render(r).image;
    const float expected[4] = {1.5f, -1.0f, -1.0f, 1.0f};
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x)
            for (int c = 0; c < 4; ++c) EXPECT_EQ(image.at(x, y)[c], expected[c]);
}

TEST_F(VkRunnerTest, EmptyUniformDataReadsZeros) {
    RenderRequest r = request(
        fragment("layout(set = 0, binding = 0, std140) uniform Params { vec4 a; } p;", "o_color = p.a + vec4(0.0, 0.0, 0.0, 1.0);"), 1, 1);
    const Image image = runner_->render(r).image;
    EXPECT_EQ(image.at(0, 0)[0], 0.0f);
    EXPECT_EQ(image.at(0, 0)[3], 1.0f);
}

TEST_F(VkRunnerTest, TimedFramesReturnPositiveDurations) {
    RenderRequest r = request(fragment("", "o_color = vec4(sin(v_uv * 40.0), 0.0, 1.0);"), 256, 256);
    r.timedFrames = 10;
    const hexc::vk::RenderResult result = runner_->render(r);
    ASSERT_EQ(result.frameMs.size(), 10u);
    std::ostringstream report;
    for (double ms : result.frameMs) {
        EXPECT_GT(ms, 0.0);
        report << ' ' << ms;
    }
    std::cout << "[ timing   ] " << runner_->deviceName() << ", 256x256 frames (ms):" << report.str() << "\n";
}

// Renders many times with a texture and uniforms: every render must give the same image, and (checked with
// valgrind/ASan, or by watching memory) leave nothing behind.
TEST_F(VkRunnerTest, RepeatedRendersAreIdentical) {
    const Texture texture = texture8(16, 8, false);
    RenderRequest r =
        request(fragment(kTextureDeclarations, "o_color = textureLod(sampler2D(tex, samp), v_uv * 1.7, params.lod);"), 16, 16);
    r.textures = {&texture, &texture};
    r.uniformData = uniformFloats({0.6f});
    const Image first = runner_->render(r).image;
    for (int i = 0; i < 100; ++i) ASSERT_EQ(runner_->render(r).image.rgba, first.rgba) << "render " << i;
}

TEST_F(VkRunnerTest, InvalidRequestsThrow) {
    EXPECT_THROW(runner_->render(request(fragment("", "o_color = vec4(1.0);"), 0, 4)), std::runtime_error);
    RenderRequest r = request(fragment("", "o_color = vec4(1.0);"), 4, 4);
    Texture empty;
    r.textures = {&empty};
    EXPECT_THROW(runner_->render(r), std::runtime_error);
}

// --- Image I/O -------------------------------------------------------------------------------------------------

std::filesystem::path tempPath(const std::string& name) {
    return std::filesystem::path(::testing::TempDir()) / ("hexc_vk_runner_test_" + name);
}

TEST(ImageIo, PngRoundTripClampsAndKeepsOrientation) {
    Image image;
    image.width = 3;
    image.height = 2;
    for (int i = 0; i < 24; ++i) image.rgba.push_back(float(i * 10) / 255.0f);
    image.at(0, 0)[0] = 1.5f;   // clamps to 255
    image.at(1, 0)[1] = -0.2f;  // clamps to 0
    const auto file = tempPath("round_trip.png");
    hexc::writeImage(image, file);
    EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp"));

    const Texture t = hexc::loadTexture(file, true);
    ASSERT_FALSE(t.isFloat());
    EXPECT_TRUE(t.srgb);
    ASSERT_EQ(t.width, 3);
    ASSERT_EQ(t.height, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x)
            for (int c = 0; c < 4; ++c) {
                const float v = std::clamp(image.at(x, y)[c], 0.0f, 1.0f);
                EXPECT_EQ(t.rgba8[(y * 3 + x) * 4 + c], std::lround(v * 255)) << x << "," << y << "," << c;
            }
    std::filesystem::remove(file);
}

TEST(ImageIo, PfmRoundTripIsExactAndStoresBottomRowFirst) {
    Image image;
    image.width = 3;
    image.height = 2;
    for (int i = 0; i < 24; ++i) image.rgba.push_back(std::ldexp(float(i) - 7.3f, i % 9 - 4));
    const auto file = tempPath("round_trip.pfm");
    hexc::writeImage(image, file);

    const Texture t = hexc::loadTexture(file, false);
    ASSERT_TRUE(t.isFloat());
    ASSERT_EQ(t.width, 3);
    ASSERT_EQ(t.height, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) {
            for (int c = 0; c < 3; ++c) EXPECT_EQ(t.rgba32f[(y * 3 + x) * 4 + c], image.at(x, y)[c]);
            EXPECT_EQ(t.rgba32f[(y * 3 + x) * 4 + 3], 1.0f);  // PFM has no alpha
        }

    // The file itself: the header, then the bottom row (y = 1) first, as other PFM readers expect.
    const std::string bytes = readFile(file);
    const std::string header = "PF\n3 2\n-1.0\n";
    ASSERT_EQ(bytes.size(), header.size() + 3 * 2 * 3 * 4);
    EXPECT_EQ(bytes.substr(0, header.size()), header);
    float firstValue;
    std::memcpy(&firstValue, bytes.data() + header.size(), 4);
    EXPECT_EQ(firstValue, image.at(0, 1)[0]);
    std::filesystem::remove(file);
}

TEST(ImageIo, ErrorsNameTheFile) {
    Image image;
    image.width = image.height = 1;
    image.rgba = {0, 0, 0, 1};
    try {
        hexc::writeImage(image, tempPath("image.bmp"));
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("image.bmp"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(".pfm, .png"), std::string::npos) << e.what();
    }
    try {
        hexc::loadTexture(tempPath("missing.png"), false);
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos) << e.what();
    }
}

}  // namespace
