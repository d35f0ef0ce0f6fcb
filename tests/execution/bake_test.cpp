// hexc bake (docs/cli.md#hexc-bake): the periodic lattice on lavapipe against the fp64 reference of the same lattice,
// the baked textures' wrap edges against their interior, the baked material, the files' formats, and what the
// command refuses.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "checks.h"
#include "hexc/image_files.h"

namespace hexc::exec {
namespace {

using hexc::test::runHexc;

constexpr int kRepeats = 4;

// A bake's view of `slot` (bakeView in compiler/cli/bake.h): st over [0, K]^2. At 128 pixels for K = 4 and tiling 4 a
// pixel spans 4 / 128 st, 8 texels of the rock's 256^2 textures: exactly mip level 3, a power of two, so lavapipe's
// piecewise-linear log2 is exact and no level blend is involved (checks.h, kMinified).
View bakeWindow(const Slot& slot, int size) { return {size, size, {0, 0, kRepeats / slot.hex.tiling[0], kRepeats / slot.hex.tiling[1]}}; }

Check bakeCheck(const Material& one, const Draw& draw) {
    const Slot& slot = one.slots[0];
    const View view = bakeWindow(slot, 128);
    const int level = deepestLevel(slot, view);
    return kindRow(slot.kind).derivative ? checkNormal(one, view, level, draw, kRepeats) : checkColor(one, view, level, draw, kRepeats);
}

Draw periodic() {
    CompileOptions options;
    options.periodicRepeats = kRepeats;
    return on(vk::ExecutedTarget::Spirv, options);
}

// hexc's shader with the periodic lattice against the reference's periodic lattice, written apart from it
// (reference/lattice.cpp, periodicTaps), within the execution tests' derived bounds: colour, scalar and normal slots;
// the checker mask, height blending, per-tile transforms and the histogram blend on the periodic tiles.
TEST(BakeCommand, PeriodicLatticeMatchesTheReference) {
    REQUIRE_VULKAN();
    for (const char* name : {"albedo", "roughness", "normal"}) {
        const Check c = bakeCheck(slotOf(name), periodic());
        report(name, c);
        EXPECT_LE(c.worstRatio, 1.0) << name;
    }
    // The checker mask's wrapped cells (checkerTaps), height blending (rock_blend) and stepped per-tile transforms
    // (tiles_stepped) on the periodic tiles.
    const std::pair<const char*, const char*> variants[] = {{"checker mask", "tests/execution/bake/checker.json"},
                                                            {"height blend", "materials/rock_blend.json"},
                                                            {"tile transforms", "materials/tiles_stepped.json"}};
    for (const auto& [what, file] : variants) {
        const Check c = bakeCheck(slotOf("albedo", file), periodic());
        report(what, c);
        EXPECT_LE(c.worstRatio, 1.0) << what;
    }
    Material histogram = slotOf("albedo");
    histogram.slots[0].hex.blend = Blend::Histogram;
    const View view = bakeWindow(histogram.slots[0], 128);
    const Check h = checkHistogram(histogram, view, deepestLevel(histogram.slots[0], view), periodic(), kRepeats);
    report("albedo, histogram blend", h);
    EXPECT_LE(h.worstRatio, 1.0);
}

// Negative controls: the plain (non-periodic) lattices drawn against the periodic reference fail the same check.
TEST(BakeCommand, PlainLatticeFailsThePeriodicReference) {
    REQUIRE_VULKAN();
    const Check c = bakeCheck(slotOf("albedo"), on(vk::ExecutedTarget::Spirv));
    report("albedo, plain lattice", c);
    EXPECT_GT(c.worstRatio, 1.0);
    const Check checker = bakeCheck(slotOf("albedo", "tests/execution/bake/checker.json"), on(vk::ExecutedTarget::Spirv));
    report("albedo, checker, plain", checker);
    EXPECT_GT(checker.worstRatio, 1.0);
    Material histogram = slotOf("albedo");
    histogram.slots[0].hex.blend = Blend::Histogram;
    const View view = bakeWindow(histogram.slots[0], 128);
    const Check h = checkHistogram(histogram, view, deepestLevel(histogram.slots[0], view), on(vk::ExecutedTarget::Spirv), kRepeats);
    report("albedo, histogram, plain", h);
    EXPECT_GT(h.worstRatio, 1.0);
}

// How far an image is from repeating: each wrap edge's mean difference across it (last column to first, last row to
// first) over the largest mean difference between neighbouring interior columns or rows. <= 1: the seam is no
// different from a step inside the texture.
double seamRatio(const Texture& t) {
    const auto diff = [&](int x0, int y0, int x1, int y1) {
        double d = 0;
        for (size_t c = 0; c < 4; ++c)
            d += std::abs(int(t.rgba8[(size_t(y0) * t.width + x0) * 4 + c]) - int(t.rgba8[(size_t(y1) * t.width + x1) * 4 + c]));
        return d;
    };
    double worst = 0;
    for (bool columns : {true, false}) {
        const int n = columns ? t.width : t.height, m = columns ? t.height : t.width;
        const auto across = [&](int a, int b) {  // mean over the line pair (a, b)
            double sum = 0;
            for (int k = 0; k < m; ++k) sum += columns ? diff(a, k, b, k) : diff(k, a, k, b);
            return sum / m;
        };
        double interior = 0;
        for (int a = 0; a + 1 < n; ++a) interior = std::max(interior, across(a, a + 1));
        worst = std::max(worst, across(n - 1, 0) / interior);
    }
    return worst;
}

// The baked textures repeat: every wrap edge of every slot's PNG (colour sRGB, scalar, normal) is within the texture's
// own neighbour steps. 512 pixels for K = 4: 2 texels a pixel, so neighbouring pixels are alike and a cut is not.
TEST(BakeCommand, BakedTexturesRepeatSeamlessly) {
    REQUIRE_VULKAN();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_bake_rock";
    std::filesystem::remove_all(dir);
    std::string err;
    ASSERT_EQ(runHexc("bake materials/rock.json -q --size 512 -o " + dir.string(), &err), 0) << err;
    for (const char* slot : {"albedo", "roughness", "normal"}) {
        const Texture baked = loadTexture(dir / ("rock." + std::string(slot) + ".png"), false);
        ASSERT_EQ(baked.width, 512);
        const double ratio = seamRatio(baked);
        std::printf("  %-10s seam / largest interior step %.3f\n", slot, ratio);
        EXPECT_LE(ratio, 1.0) << slot;
    }
    // The baked material tiles them plainly, at 1/K of the tiling: the same texel density.
    const Material baked = test::loadMaterial(dir / "rock_baked.json");
    ASSERT_EQ(baked.slots.size(), 3u);
    for (const Slot& s : baked.slots) {
        EXPECT_FALSE(s.hex.enabled) << s.name;
        EXPECT_EQ(s.hex.tiling, (std::array<double, 2>{1, 1})) << s.name;
        EXPECT_EQ(s.width, 512) << s.name;
    }
    // The checker mask's bake too.
    ASSERT_EQ(runHexc("bake tests/execution/bake/checker.json -q --size 512 -o " + dir.string(), &err), 0) << err;
    const double checker = seamRatio(loadTexture(dir / "checker.albedo.png", false));
    std::printf("  checker    seam / largest interior step %.3f\n", checker);
    EXPECT_LE(checker, 1.0);
}

// Negative control: the same window rendered with the plain lattice (hexc render) has seams.
TEST(BakeCommand, APlainRenderOfTheWindowHasSeams) {
    REQUIRE_VULKAN();
    const std::pair<const char*, const char*> renders[] = {
        {"materials/rock.json", "albedo"}, {"materials/rock.json", "normal"}, {"tests/execution/bake/checker.json", "albedo"}};
    for (const auto& [material, slot] : renders) {
        const std::filesystem::path out = std::filesystem::temp_directory_path() / "hexc_bake_plain.png";
        std::string err;
        ASSERT_EQ(runHexc(std::string("render ") + material + " -q --output " + (slot[0] == 'n' ? "normal" : "albedo") + " --slot " + slot +
                              " --size 512x512 --uv-rect 0,0,1,1 -o " + out.string(),
                          &err),
                  0)
            << err;
        const double ratio = seamRatio(loadTexture(out, false));
        std::printf("  %s %-10s plain render: seam / largest interior step %.3f\n", material, slot, ratio);
        EXPECT_GT(ratio, 1.0) << material << " " << slot;
    }
}

// A fresh folder holding the rock's albedo as rock8.png, and its texels as floats (value / 255) to write in other formats.
Image rockTexels(const std::filesystem::path& dir) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::filesystem::copy_file("materials/textures/rock_albedo.png", dir / "rock8.png");
    const Texture rock = loadTexture(dir / "rock8.png", false);
    Image texels{rock.width, rock.height, std::vector<float>(rock.rgba8.size())};
    for (size_t i = 0; i < texels.rgba.size(); ++i) texels.rgba[i] = float(rock.rgba8[i]) / 255.0f;
    return texels;
}

// The rock's albedo (rockTexels) written into `dir` as each of `inputs`, the material `slots` reading them (and
// rock8.png) baked at 128 x 128 into dir/out.
void bakeRockAs(const std::filesystem::path& dir, const std::vector<std::pair<ImageFormat, std::string>>& inputs,
                const std::string& slots) {
    const Image texels = rockTexels(dir);
    for (const auto& [format, file] : inputs) writeImageAs(texels, format, dir / file);
    std::ofstream(dir / "m.json") << R"({"name": "m", "template": "unlit", "hextiling": {"tiling": 4}, "slots": [)" + slots + "]}";
    std::string err;
    ASSERT_EQ(runHexc("bake " + (dir / "m.json").string() + " -q --size 128 -o " + (dir / "out").string(), &err), 0) << err;
}

// How far a float bake and the 8-bit PNG bake of the same texels may differ (the derivation is at
// BakeCommand.WritesTheTexturesFormat): twice e_s (1 + 1.5) at mip level 3, plus the 8-bit file's rounding.
double floatAgainstPngBound() { return 2 * 2.5 * sampleError(3, false) + 0.5 / 255; }

// A bake is written in its texture's format: a 16-bit PNG as 16-bit PNG, an OpenEXR file as OpenEXR (linear floats,
// the baked material then linear), an 8-bit PNG as 8-bit PNG. The same texels in an EXR and an 8-bit PNG (both
// linear) bake alike: each bake is within blendTolerance of the reference (checks.h) with e_x = e_m = e_s, the gain's
// slope k = 1 (falloff 0.5), beta = 0.6 and sum_j W_j |x_j - R| <= 1 (values in [0, 1]): e_s (1 + 1.5); so the two
// differ by at most twice that plus the 8-bit file's rounding, 0.5/255. e_s = sampleError(3): mip level 3, as in
// BakeCommand.PeriodicLatticeMatchesTheReference. Negative control: against the PNG bake mirrored, the bound fails.
TEST(BakeCommand, WritesTheTexturesFormat) {
    REQUIRE_VULKAN();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_bake_formats";
    bakeRockAs(dir, {{ImageFormat::Png16, "rock16.png"}, {ImageFormat::Exr, "rock.exr"}},
               R"({"name": "albedo", "kind": "color", "texture": "rock16.png"},
        {"name": "exr", "kind": "color", "colorspace": "linear", "texture": "rock.exr"},
        {"name": "png", "kind": "color", "colorspace": "linear", "texture": "rock8.png"})");
    if (HasFatalFailure()) return;
    EXPECT_EQ(imageFormat(test::readFile(dir / "out/m.albedo.png")), ImageFormat::Png16);
    EXPECT_EQ(imageFormat(test::readFile(dir / "out/m.exr.exr")), ImageFormat::Exr);
    EXPECT_EQ(imageFormat(test::readFile(dir / "out/m.png.png")), ImageFormat::Png8);
    const Material baked = test::loadMaterial(dir / "out/m_baked.json");
    EXPECT_EQ(baked.slots[0].colorSpace, ColorSpace::Srgb);
    EXPECT_EQ(baked.slots[1].colorSpace, ColorSpace::Linear);
    const Texture exr = loadTexture(dir / "out/m.exr.exr", false), png = loadTexture(dir / "out/m.png.png", false);
    ASSERT_TRUE(exr.isFloat());
    EXPECT_EQ(loadTexture(dir / "out/m.albedo.png", false).width, 128);  // the 16-bit PNG reads back (stb)
    const auto worst = [&](bool mirrored) {
        double e = 0;
        for (int y = 0; y < png.height; ++y)
            for (int x = 0; x < png.width; ++x)
                for (size_t c = 0; c < 4; ++c) {
                    const size_t at = (size_t(y) * png.width + x) * 4 + c,
                                 from = (size_t(y) * png.width + (mirrored ? png.width - 1 - x : x)) * 4 + c;
                    e = std::max(e, std::fabs(exr.rgba32f[at] - png.rgba8[from] / 255.0));
                }
        return e;
    };
    const double bound = floatAgainstPngBound();
    std::printf("  EXR bake against the 8-bit PNG bake of the same texels: max %.2f/255, bound %.2f/255, mirrored %.2f/255\n",
                worst(false) * 255, bound * 255, worst(true) * 255);
    EXPECT_LE(worst(false), bound);
    EXPECT_GT(worst(true), bound);
}

// A KTX2 file's levels as its level index gives them (read here apart from the writer): level i is max(1, N >> i) a
// side, `texel` bytes a texel.
struct Ktx2Level {
    int size = 0;
    std::string bytes;
};

// A little-endian field of a KTX2 file.
uint64_t ktx2Word(const std::string& b, size_t at, int bytes) {
    uint64_t v = 0;
    for (int i = bytes - 1; i >= 0; --i) v = v << 8 | uint8_t(b[at + size_t(i)]);
    return v;
}

std::vector<Ktx2Level> ktx2Levels(const std::string& b) {
    std::vector<Ktx2Level> levels;
    const int size = int(ktx2Word(b, 20, 4));
    for (size_t i = 0; i < ktx2Word(b, 40, 4); ++i)
        levels.push_back({std::max(1, size >> i), b.substr(ktx2Word(b, 80 + 24 * i, 8), ktx2Word(b, 88 + 24 * i, 8))});
    return levels;
}

// The largest distance of a level's texels from the 2x2 box average of the level above (`shift`ed by a texel, for the
// negative control), in units of the stored value: 8-bit sRGB colour averaged in linear light (`linearLight`), else
// as stored; floats as stored.
double worstBoxAverage(const std::vector<Ktx2Level>& levels, bool isFloat, bool linearLight, int shift = 0) {
    const auto value = [&](const Ktx2Level& l, int x, int y, int c) {
        const size_t at = (size_t(y % l.size) * l.size + size_t(x % l.size)) * 4 + size_t(c);
        float f = 0;
        if (isFloat) std::memcpy(&f, &l.bytes[at * 4], 4);
        return isFloat ? double(f) : uint8_t(l.bytes[at]) / 255.0;
    };
    double worst = 0;
    for (size_t i = 1; i < levels.size(); ++i)
        for (int y = 0; y < levels[i].size; ++y)
            for (int x = 0; x < levels[i].size; ++x)
                for (int c = 0; c < 4; ++c) {
                    const bool decode = linearLight && c < 3;
                    double sum = 0;
                    for (int k = 0; k < 4; ++k) {
                        const double v = value(levels[i - 1], 2 * x + k % 2 + shift, 2 * y + k / 2, c);
                        sum += decode ? reference::decodeSrgb(v) : v;
                    }
                    const double mean = decode ? std::pow(sum / 4, 1 / 2.4) : sum / 4;  // encoded below
                    const double expected = decode ? (sum / 4 <= 0.0031308 ? 12.92 * sum / 4 : 1.055 * mean - 0.055) : sum / 4;
                    worst = std::max(worst, std::fabs(value(levels[i], x, y, c) - expected));
                }
    return worst;
}

// A KTX2 texture bakes to KTX2 of its format (R8G8B8A8 sRGB and UNORM, R32G32B32A32 float), level 0 read back by hexc's
// reader equal to the PNG bake of the same texels: the same 8-bit texels sampled by the same shader on the same
// device give the same floats, rounded alike, so the 8-bit bakes are equal to the bit; the float bake is within the
// EXR-against-PNG bound of BakeCommand.WritesTheTexturesFormat. Every level below 0 is the 2x2 box average of the level
// above, rounded: within half a step of 8 bits (1e-6 for floats, the float average of four values); sRGB averaged in
// linear light. Negative controls: level 0 against the PNG bake a texel off, the sRGB chain checked as averaged in
// encoded values, and every chain checked against the level above shifted by a texel, exceed those bounds.
TEST(BakeCommand, WritesKtx2WithItsMipChain) {
    REQUIRE_VULKAN();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_bake_ktx2";
    bakeRockAs(dir,
               {{ImageFormat::Ktx2Srgb8, "srgb.ktx2"}, {ImageFormat::Ktx2Unorm8, "unorm.ktx2"}, {ImageFormat::Ktx2Float, "float.ktx2"}},
               R"({"name": "srgb", "kind": "color", "texture": "srgb.ktx2"},
        {"name": "unorm", "kind": "color", "colorspace": "linear", "texture": "unorm.ktx2"},
        {"name": "float", "kind": "color", "colorspace": "linear", "texture": "float.ktx2"},
        {"name": "png", "kind": "color", "texture": "rock8.png"},
        {"name": "linear", "kind": "color", "colorspace": "linear", "texture": "rock8.png"})");
    if (HasFatalFailure()) return;
    const std::pair<const char*, const char*> against[] = {{"srgb", "png"}, {"unorm", "linear"}, {"float", "linear"}};
    const double floatBound = floatAgainstPngBound();
    for (const auto& [slot, png] : against) {
        const std::string bytes = test::readFile(dir / "out" / ("m." + std::string(slot) + ".ktx2"));
        const ImageFormat format = imageFormat(bytes);
        EXPECT_TRUE(isKtx2(format)) << slot;
        const Texture baked = loadTexture(dir / "out" / ("m." + std::string(slot) + ".ktx2"), false);
        const Texture other = loadTexture(dir / "out" / ("m." + std::string(png) + ".png"), false);
        ASSERT_EQ(baked.width, 128);
        const auto level0Against = [&](size_t shift) {  // the PNG bake `shift` values on (a texel: 4), for the control
            double worst = 0;
            for (size_t i = 0; i < other.rgba8.size(); ++i) {
                const double v = baked.isFloat() ? baked.rgba32f[i] : baked.rgba8[i] / 255.0;
                worst = std::max(worst, std::fabs(v - other.rgba8[(i + shift) % other.rgba8.size()] / 255.0));
            }
            return worst;
        };
        const double level0 = level0Against(0), level0Shifted = level0Against(4);
        const std::vector<Ktx2Level> levels = ktx2Levels(bytes);
        const bool isFloat = format == ImageFormat::Ktx2Float, srgb = format == ImageFormat::Ktx2Srgb8;
        const double step = isFloat ? 1e-6 : 0.5 / 255 + 1e-9, chain = worstBoxAverage(levels, isFloat, srgb),
                     shifted = worstBoxAverage(levels, isFloat, srgb, 1);
        std::printf(
            "  %-5s level 0 against the PNG bake: max %.2f/255 (a texel off: %.2f/255); %zu levels, worst off the box average "
            "%.3g, shifted %.3g\n",
            slot, level0 * 255, level0Shifted * 255, levels.size(), chain, shifted);
        EXPECT_LE(level0, isFloat ? floatBound : 0.0) << slot;
        EXPECT_GT(level0Shifted, isFloat ? floatBound : 0.0) << slot;
        EXPECT_EQ(levels.size(), 8u) << slot;  // 128 down to 1
        EXPECT_LE(chain, step) << slot;
        EXPECT_GT(shifted, step) << slot;
        if (srgb) {
            const double encoded = worstBoxAverage(levels, false, false);  // averaged as encoded values: not this chain
            std::printf("  srgb  checked as averaged in encoded values: worst %.3g\n", encoded);
            EXPECT_GT(encoded, step);
        }
    }
    const Material baked = test::loadMaterial(dir / "out/m_baked.json");
    EXPECT_EQ(baked.slots[0].colorSpace, ColorSpace::Srgb);
    EXPECT_EQ(baked.slots[2].colorSpace, ColorSpace::Linear);
}

// hexc's KTX2 reader refuses what a broken writer would write: a descriptor of another transfer function or format,
// and a level that does not fit in the file; the file as written reads.
TEST(BakeCommand, TheKtx2ReaderRefusesABrokenDescriptorOrLevel) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_bake_ktx2_broken";
    std::filesystem::create_directories(dir);
    Image image{16, 16, std::vector<float>(16 * 16 * 4, 0.5f)};
    writeImageAs(image, ImageFormat::Ktx2Srgb8, dir / "good.ktx2");
    const std::string good = test::readFile(dir / "good.ktx2");
    const size_t dfd = ktx2Word(good, 48, 4), level1 = 80 + 24;
    const auto refused = [&](const std::string& name, std::string bytes, const std::string& why) {
        std::ofstream(dir / name, std::ios::binary) << bytes;
        try {
            loadTexture(dir / name, true);
        } catch (const TextureError& e) {
            EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
            return;
        }
        ADD_FAILURE() << name << " was read";
    };
    EXPECT_EQ(loadTexture(dir / "good.ktx2", true).width, 16);
    // The descriptors as the Khronos Data Format 1.3 spells R8G8B8A8 sRGB and R32G32B32A32 SFLOAT (KTX-Software's
    // createDFDUnpacked writes the same): dfdTotalSize; vendor and type 0; version 2, block size 88; RGBSDA, BT.709,
    // sRGB or linear, straight alpha; 1x1 block; bytes in plane 0; then per sample offset | (bits - 1) << 16 |
    // channel << 24 (A = 15; qualifiers linear 0x10, signed 0x40, float 0x80), position 0, lower, upper.
    // clang-format off
    const std::vector<uint32_t> srgbDfd = {92, 0, 0x00580002, 0x00020101, 0, 4, 0,
        0x00070000, 0, 0, 255, 0x01070008, 0, 0, 255, 0x02070010, 0, 0, 255, 0x1F070018, 0, 0, 255};
    const std::vector<uint32_t> floatDfd = {92, 0, 0x00580002, 0x00010101, 0, 16, 0,
        0xC01F0000, 0, 0xBF800000, 0x3F800000, 0xC11F0020, 0, 0xBF800000, 0x3F800000,
        0xC21F0040, 0, 0xBF800000, 0x3F800000, 0xCF1F0060, 0, 0xBF800000, 0x3F800000};
    // clang-format on
    writeImageAs(image, ImageFormat::Ktx2Float, dir / "float.ktx2");
    for (const auto& [bytes, words] : {std::pair{good, srgbDfd}, std::pair{test::readFile(dir / "float.ktx2"), floatDfd}}) {
        ASSERT_EQ(ktx2Word(bytes, 52, 4), words.size() * 4);
        for (size_t i = 0; i < words.size(); ++i)
            EXPECT_EQ(ktx2Word(bytes, ktx2Word(bytes, 48, 4) + 4 * i, 4), words[i]) << "DFD word " << i;
    }
    std::string linear = good;
    linear[dfd + 4 + 8 + 2] = 1;  // transfer: linear
    refused("linear_dfd.ktx2", linear, "Data Format Descriptor does not describe its vkFormat (R8G8B8A8 sRGB)");
    std::string unorm = good;
    unorm[12] = 37;  // vkFormat R8G8B8A8 UNORM under the sRGB descriptor
    refused("unorm_format.ktx2", unorm, "Data Format Descriptor does not describe its vkFormat (R8G8B8A8)");
    std::string shortLevel = good;
    shortLevel.replace(level1 + 8, 2, std::string("\xFC\x00", 2));  // level 1: 252 bytes, a texel short of 8 x 8
    refused("short_level.ktx2", shortLevel, "the file is truncated (level 1 does not fit)");
    std::string past = good;
    past[level1 + 1] = char(0x7f);  // level 1 starting past the end
    refused("past_level.ktx2", past, "the file is truncated (level 1 does not fit)");
    refused("cut.ktx2", good.substr(0, good.size() - 1), "the file is truncated");
}

// A green-down (flip_y) normal map's bake, read back through its baked material (plain tiling at 1/K, so pixel i reads
// texel i at its centre, level 0), gives the normals hexc's runtime shader gives with the periodic lattice: the slot's
// convention survives the round trip, and relighting either lights the same normals. The bake's 8-bit rounding puts
// each encoded component within 0.5/255, so n = 2 texel - 1 within e = 1/255; Listing 9's d = -n_xy / z then moves by
// at most e (1 + max|d|) / min z a component (the baked texture's bounds), sqrt(2) times that in length, and the
// encoded normal (n * 0.5 + 0.5, normalize(-d, 1) having slope <= 1 in d) by half the length. Negative control: the
// baked material read as green-up fails.
TEST(BakeCommand, ANormalMapsBakeRelightsAsTheRuntimeShader) {
    REQUIRE_VULKAN();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_bake_normal";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "n.json") << R"({"name": "n", "hextiling": {"tiling": 4}, "slots": [{"name": "normal", "kind": "normal",
        "flip_y": true, "texture": ")" + std::filesystem::absolute("materials/textures/rock_normal.png").string() +
                                         R"("}]})";
    std::string err;
    ASSERT_EQ(runHexc("bake " + (dir / "n.json").string() + " -q --size 128 -o " + (dir / "out").string(), &err), 0) << err;
    const Material source = test::loadMaterial(dir / "n.json");
    Material baked = test::loadMaterial(dir / "out/n_baked.json");
    CompileOptions options;
    options.periodicRepeats = kRepeats;
    vk::Runner& gpu = *test::runner(&err);
    const Image runtime = vk::render(gpu, source, vk::RenderOutput::Normal, "", bakeWindow(source.slots[0], 128), vk::ExecutedTarget::Spirv,
                                     0, nullptr, {}, options);
    const TextureBounds b = bounds(sampled(baked.slots[0]));
    const double bound = 0.5 * std::sqrt(2.0) * (1.0 / 255) * (1 + b.maxDeriv) / b.minZ;
    const auto worst = [&](const Material& m) {
        const Image read = vk::render(gpu, m, vk::RenderOutput::Normal, "", {128, 128, {0, 0, 1, 1}});
        return compare(read, runtime, 3).max;
    };
    const double same = worst(baked);
    baked.slots[0].flipY = false;
    const double upsideDown = worst(baked);
    std::printf("  baked normals read back: max %.2f/255 (bound %.2f/255); read green-up: %.2f/255\n", same * 255, bound * 255,
                upsideDown * 255);
    EXPECT_LE(same, bound);
    EXPECT_GT(upsideDown, bound);
}

// What bake refuses, located, and writes nothing for: a mask with no periodic form, a bad size or repeat count.
TEST(BakeCommand, RefusalsAreLocatedAndWriteNothing) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_bake_refused";
    std::filesystem::remove_all(dir);
    std::string err;
    EXPECT_EQ(runHexc("bake tests/execution/bake/noise.json -q --size 64 -o " + dir.string(), &err), 1);
    EXPECT_NE(err.find("noise.json:8:15: error[HX134]: /slots/0: slot `albedo`: hexc bake cannot make the `noise` mask periodic"),
              std::string::npos)
        << err;
    EXPECT_EQ(runHexc("bake materials/rock.json -q --size 0 -o " + dir.string(), &err), 2);
    EXPECT_EQ(err, "hexc: --size expects a whole number from 1 to 8192, got `0`\n");
    EXPECT_EQ(runHexc("bake materials/rock.json -q --size 64 --repeats 2.5 -o " + dir.string(), &err), 2);
    EXPECT_EQ(err, "hexc: --repeats expects a whole number from 1 to 64, got `2.5`\n");
    EXPECT_FALSE(std::filesystem::exists(dir));
}

}  // namespace
}  // namespace hexc::exec
