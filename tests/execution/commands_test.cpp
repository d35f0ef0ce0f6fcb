// `hexc render` and `hexc preview`, run as a user would, against the library and the reference.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <nlohmann/json.hpp>

#include "hexc/histogram.h"
#include "hexc/library.h"
#include "hexc/material.h"
#include "reference/reference.h"
#include "hexc/spirv.h"
#include "vk/precision.h"
#include "vk/render.h"
#include "support.h"
#include "execution/checks.h"

using namespace hexc;
using namespace hexc::exec;
using hexc::test::runHexc;
using hexc::test::runner;

namespace {

// ---- hexc render and hexc preview, run as a user would ------------------------------------------------------

TEST(RenderCommand, WritesWhatTheLibraryRenders) {
    REQUIRE_VULKAN();
    std::filesystem::path dir = std::filesystem::temp_directory_path();
    ASSERT_EQ(
        runHexc("render materials/rock.json --output derivative --size 40x24 --uv-rect 0.1,0.2,0.3,0.35 -o " + (dir / "r.pfm").string()),
        0);
    ASSERT_EQ(runHexc("render materials/rock.json --output derivative --size 40x24 --uv-rect 0.1,0.2,0.3,0.35 --reference -o " +
                      (dir / "c.pfm").string()),
              0);
    Material rock = *parseMaterialFile("materials/rock.json").material;
    const View view{40, 24, {0.1, 0.2, 0.3, 0.35}};
    Image lib = vk::render(*runner(&whyNoVulkan), rock, vk::RenderOutput::Derivative, "", view);
    Texture gpu = loadTexture(dir / "r.pfm", false), cpu = loadTexture(dir / "c.pfm", false);
    ASSERT_EQ(gpu.width, 40);
    ASSERT_EQ(gpu.height, 24);
    Image ref = reference::render(rock.slots[1], sampled(rock.slots[1]), view, reference::Output::Value);
    for (size_t i = 0; i < lib.rgba.size(); i += 4)
        for (size_t c = 0; c < 3; ++c) {  // PFM holds RGB
            ASSERT_EQ(gpu.rgba32f[i + c], lib.rgba[i + c]) << i;
            ASSERT_EQ(cpu.rgba32f[i + c], ref.rgba[i + c]) << i;
        }
}

TEST(RenderCommand, Errors) {
    std::string err;
    EXPECT_EQ(runHexc("render materials/rock.json --slot bark -o /tmp/x.png", &err), 2);
    EXPECT_EQ(runHexc("render materials/rock.json --output albedo --slot bark -o /tmp/x.png", &err), 1);
    EXPECT_EQ(err, "hexc: material `rock` has no slot `bark`\n");
    EXPECT_EQ(runHexc("render materials/rock.json --output derivative --slot albedo -o /tmp/x.png", &err), 1);
    EXPECT_EQ(err, "hexc: slot `albedo` is of kind color; this output needs a normal slot\n");
    EXPECT_EQ(runHexc("render materials/rock.json --size 0x5 -o /tmp/x.png", &err), 2);
    EXPECT_EQ(runHexc("render materials/rock.json --uv-rect 0,0,1 -o /tmp/x.png", &err), 2);
    EXPECT_EQ(err, "hexc: --uv-rect expects 4 finite numbers, got `0,0,1`\n");
    EXPECT_EQ(runHexc("render materials/rock.json --uv-rect 0,0,1,nan -o /tmp/x.png", &err), 2);
    EXPECT_EQ(err, "hexc: --uv-rect expects 4 finite numbers, got `0,0,1,nan`\n");
    EXPECT_EQ(runHexc("render materials/rock.json --output albedoo -o /tmp/x.png", &err), 2);
    EXPECT_EQ(err, "hexc: --output: albedoo not in {shaded,albedo,normal,derivative,weights} (see hexc render --help)\n");
    EXPECT_EQ(runHexc("preview materials/rock.json --cell 10 -o /tmp/x.png", &err), 2);
    EXPECT_EQ(err, "hexc: --cell: Value 10 not in range 32 to 2048 (see hexc preview --help)\n");
    EXPECT_EQ(runHexc("render materials/rock.json -o /tmp/x.tiff", &err), 2);  // refused before rendering
    EXPECT_EQ(err, "hexc: -o /tmp/x.tiff: hexc render writes .pfm or .png\n");
    EXPECT_EQ(runHexc("render materials/invalid/falloff_zero.json -o /tmp/x.png", &err), 1);
    EXPECT_EQ(runHexc("render materials/rock_triplanar.json --output normal -o /tmp/x.png", &err), 1);
    EXPECT_EQ(err, "hexc: slot `normal` is triplanar: it returns a world-space surface gradient; use the derivative output\n");
    // A template with resources of its own cannot be drawn without them (it crashed lavapipe): shaded with the
    // built-in lit, named in a note (tests/cli/preview_test.cpp); its slots as they are.
    EXPECT_EQ(runHexc("render materials/engine_rock.json --size 16x16 -o /tmp/x.png", &err), 0);
    EXPECT_NE(err.find("declares resources of its own (Frame, Object, Push, shadowMap"), std::string::npos) << err;
    EXPECT_EQ(runHexc("render materials/engine_rock.json --output albedo --size 16x16 -o /tmp/x.png", &err), 0) << err;
}

// A PNG whose header and chunks are sound (so the material validates and compiles) but whose image data does not
// decode: render reports the texture, exit 1 (bad input), and writes nothing.
TEST(RenderCommand, ATextureThatDoesNotDecodeIsBadInput) {
    std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_bad_texture";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::ifstream in("materials/textures/rock_albedo.png", std::ios::binary);
    std::string png((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t idat = png.find("IDAT");
    ASSERT_NE(idat, std::string::npos);
    std::fill(png.begin() + long(idat + 14), png.begin() + long(idat + 2014), '\xff');  // inside the deflate stream
    std::ofstream(dir / "bad.png", std::ios::binary) << png;
    std::ofstream(dir / "m.json")
        << R"({"name": "bad", "template": "unlit", "slots": [{"name": "albedo", "kind": "color", "texture": "bad.png"}]})";
    std::string err;
    EXPECT_EQ(runHexc((dir / "m.json").string() + " -q -o " + (dir / "out").string(), &err), 0) << err;
    EXPECT_EQ(runHexc("render " + (dir / "m.json").string() + " -o " + (dir / "x.png").string(), &err), 1) << err;
    EXPECT_NE(err.find("bad.png: "), std::string::npos) << err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

// No Vulkan device (the loader pointed at a driver manifest that does not exist) is its own exit code, 4, for
// render and preview alike, and nothing is written.
TEST(RenderCommand, NoVulkanDeviceExitsFour) {
    const std::string noDriver = "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json";
    std::filesystem::path out = std::filesystem::temp_directory_path() / "hexc_no_vulkan.png";
    std::filesystem::remove(out);
    std::string err;
    EXPECT_EQ(runHexc("render materials/rock.json -o " + out.string(), &err, noDriver), 4) << err;
    EXPECT_NE(err.find("hexc: no Vulkan device: "), std::string::npos) << err;
    EXPECT_EQ(runHexc("preview materials/rock.json -o " + out.string(), &err, noDriver), 4) << err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

// The reference of a height-blended slot reads its height slot (without it, the reference refuses to evaluate).
TEST(RenderCommand, ReferenceOfAHeightBlendedSlot) {
    std::filesystem::path file = std::filesystem::temp_directory_path() / "hb_cpu.pfm";
    ASSERT_EQ(
        runHexc("render materials/rock_blend.json --output albedo --size 32x32 --uv-rect 0.1,0.2,0.2,0.3 --reference -o " + file.string()),
        0);
    Material m = *parseMaterialFile("materials/rock_blend.json").material;
    const reference::Heights heights(m, m.slots[0]);
    ASSERT_NE(heights.source(), nullptr);
    Image ref =
        reference::render(m.slots[0], sampled(m.slots[0]), {32, 32, {0.1, 0.2, 0.2, 0.3}}, reference::Output::Value, heights.source());
    Texture cpu = loadTexture(file, false);
    for (size_t i = 0; i < ref.rgba.size(); i += 4)
        for (size_t c = 0; c < 3; ++c) ASSERT_EQ(cpu.rgba32f[i + c], ref.rgba[i + c]) << i;  // PFM holds RGB
}

TEST(PreviewCommand, WritesALabelledSheet) {
    REQUIRE_VULKAN();
    std::filesystem::path out = std::filesystem::temp_directory_path() / "hexc_preview.png";
    std::filesystem::remove(out);
    ASSERT_EQ(runHexc("preview materials/rock.json --cell 64 -o " + out.string()), 0);
    Texture sheet = loadTexture(out, false);
    EXPECT_EQ(sheet.width, 4 * 64);  // plain, falloff, histogram, weights
    EXPECT_EQ(sheet.height, 2 * (64 + 28));
}

}  // namespace
