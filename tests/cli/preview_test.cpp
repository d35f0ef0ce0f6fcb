// hexc preview and hexc render as a technical artist uses them: display encoding, engine templates, layouts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <vector>
#include <filesystem>

#include "hexc/material.h"
#include "support.h"
#include "vk/render.h"

namespace hexc {
namespace {

using hexc::test::runHexc;
using hexc::test::runner;

// IEC 61966-2-1's encoding, written from the standard: what an sRGB swapchain stores for a linear value.
double srgbEncoded(double linear) {
    if (linear <= 0) return 0;
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
}

int byteOf(double v) { return int(std::lround(std::clamp(v, 0.0, 1.0) * 255)); }

// An engine's material (its template declares per-frame blocks, shadow and environment maps, push constants) is
// previewed with the built-in `lit`, which the note names; the PNG holds the sRGB encoding of what lit renders.
TEST(PreviewCommand, AnEngineMaterialInDisplayEncoding) {
    REQUIRE_VULKAN();
    const std::filesystem::path out = std::filesystem::temp_directory_path() / "hexc_preview_engine.png";
    std::filesystem::remove(out);
    std::string err;
    const int cell = 40, band = 28;  // an odd cell size: two-line labels at scale 1
    ASSERT_EQ(runHexc("preview materials/engine_rock.json -q --cell " + std::to_string(cell) + " -o " + out.string(), &err), 0) << err;
    EXPECT_EQ(err,
              "hexc: note: template `templates/engine.glsl` declares resources of its own (Frame, Object, Push, shadowMap, "
              "environment, detail, detailSampler): shown with the built-in template `lit` (--template picks another)\n");
    const Texture sheet = loadTexture(out, false);
    ASSERT_EQ(sheet.width, 4 * cell);

    // The plain column, top row (uv 0..0.5), as the library renders it in linear values.
    Material m = *parseMaterialFile("materials/engine_rock.json").material;
    m.templ = TemplateRef::builtin("lit");
    for (Slot& s : m.slots) s.hex.enabled = false;
    const Image linear = vk::render(*runner(&whyNoVulkan), m, vk::RenderOutput::Shaded, "", {cell, cell, {0, 0, 0.5, 0.5}});
    int darker = 0, offByOne = 0;
    for (int y = 0; y < cell; ++y)
        for (int x = 0; x < cell; ++x)
            for (int c = 0; c < 3; ++c) {
                const double v = linear.at(x, y)[c];
                const int png = sheet.rgba8[(size_t(band + y) * sheet.width + x) * 4 + size_t(c)];
                // One step: hexc rounds the encoded value to float before quantising; only a value within 2^-24 of
                // a step boundary can land on the other side.
                ASSERT_NEAR(png, byteOf(srgbEncoded(v)), 1) << x << "," << y << " channel " << c << " linear " << v;
                darker += byteOf(v) + 20 < png;  // what the linear bytes would have shown
                offByOne += png != byteOf(srgbEncoded(v));
            }
    std::printf("  %d of %d channels one step off the double-precision encoding; %d more than 20 steps above the linear byte\n", offByOne,
                3 * cell * cell, darker);
    EXPECT_GT(darker, cell * cell);  // most of the rock is mid-dark: linear bytes lose a third of their value
}

// --encoding linear keeps the values; render's default is linear, --encoding srgb matches preview.
TEST(RenderCommand, EncodingAndTemplate) {
    REQUIRE_VULKAN();
    const std::filesystem::path dir = std::filesystem::temp_directory_path();
    std::string err;
    ASSERT_EQ(runHexc("render materials/engine_rock.json -q --size 24x16 --template unlit -o " + (dir / "lin.png").string(), &err), 0)
        << err;
    EXPECT_EQ(err, "");  // unlit declares no resources of its own: no note
    ASSERT_EQ(
        runHexc("render materials/engine_rock.json -q --size 24x16 --template unlit --encoding srgb -o " + (dir / "srgb.png").string(),
                &err),
        0)
        << err;
    const Texture lin = loadTexture(dir / "lin.png", false), srgb = loadTexture(dir / "srgb.png", false);
    for (size_t i = 0; i < lin.rgba8.size(); ++i) {
        if (i % 4 == 3) {
            EXPECT_EQ(srgb.rgba8[i], lin.rgba8[i]);  // alpha stays linear
            continue;
        }
        // The linear byte is the value up to half a step (1/510); encoding it moves it by at most the slope of
        // the curve times that, plus half a step of its own rounding, plus one for the float rounding above.
        const double v = lin.rgba8[i] / 255.0,
                     slope = v > 0.0031308 ? 1.055 / 2.4 * std::pow(std::max(v - 1 / 510.0, 1e-3), 1 / 2.4 - 1) : 12.92;
        EXPECT_NEAR(srgb.rgba8[i], srgbEncoded(v) * 255, slope * 0.5 + 1.5) << i;
    }
    EXPECT_EQ(runHexc("render materials/engine_rock.json --encoding gamma -o /tmp/x.png", &err), 2);
    EXPECT_EQ(err, "hexc: --encoding: gamma not in {linear,srgb} (see hexc render --help)\n");
}

// A material none of whose slots can take the histogram blend says so in that column's label instead of silently
// repeating the falloff column; the layout options are taken (and a bad layout file is reported).
TEST(PreviewCommand, AColumnThatCannotApplySaysSo) {
    REQUIRE_VULKAN();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_preview_na";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "m.json") << R"({"name": "onetap", "template": "unlit", "hextiling": {"taps": 1},
        "slots": [{"name": "albedo", "kind": "color", "texture": ")"
                                  << std::filesystem::absolute("materials/textures/rock_albedo.png").string() << R"("}]})";
    std::string err;
    ASSERT_EQ(runHexc("preview -q --cell 300 --set 3 --binding 2 " + (dir / "m.json").string() + " -o " + (dir / "na.png").string(), &err),
              0)
        << err;
    ASSERT_EQ(runHexc("preview -q --cell 300 " + (dir / "m.json").string() + " -o " + (dir / "na.png").string(), &err), 0) << err;
    const Texture sheet = loadTexture(dir / "na.png", false);
    // Whether a column's label has two lines: white label rows with a blank row between them. The n/a label, too
    // long for one line at scale 2 in a 300-pixel cell, is drawn on two lines at scale 1; the others fit one line.
    auto twoLines = [&](int column) {
        std::vector<bool> white(28);
        for (int y = 0; y < 28; ++y)
            for (int x = column * 300; x < column * 300 + 300; ++x)
                white[size_t(y)] = white[size_t(y)] || sheet.rgba8[(size_t(y) * sheet.width + x) * 4] == 255;
        const auto first = std::find(white.begin(), white.end(), true), last = std::find(white.rbegin(), white.rend(), true).base();
        return first < last && std::find(first, last, false) != last;
    };
    EXPECT_FALSE(twoLines(1));  // falloff
    EXPECT_TRUE(twoLines(2));   // histogram n/a: no slot takes it
    EXPECT_FALSE(twoLines(3));  // weights
    EXPECT_EQ(runHexc("preview --layout /nonexistent/layout.json materials/rock.json -o /tmp/x.png", &err), 1);
    EXPECT_NE(err.find("/nonexistent/layout.json"), std::string::npos) << err;
}

}  // namespace
}  // namespace hexc
