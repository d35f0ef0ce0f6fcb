// The texture checks (hexc/lint.h): generated normal maps in both green conventions, tilted and non-tiling textures
// must be found, and every texture of the repository must pass. The figures printed here are docs/lint.md's.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>

#include "hexc/lint.h"
#include "lint_cases.h"
#include "support.h"

namespace hexc::test {
namespace {

struct Case {
    std::string kind;
    Field field;
    bool oneAxis = false;  // varies along one axis: its normal map reads alike either way
};

// The height fields: bumps, noise of three spectra, cracks and glyphs at a square and an odd, non-square size, and
// ridges along one axis.
std::vector<Case> heightFields() {
    std::vector<Case> out;
    for (auto [w, h] : {std::pair{64, 64}, std::pair{96, 80}}) {
        for (unsigned seed = 1; seed <= 3; ++seed) {
            out.push_back({"bumps", bumps(w, h, seed, 12)});
            for (double beta : {1.0, 2.0, 3.0}) out.push_back({"noise k^-" + std::to_string(int(beta)), spectral(w, h, seed, beta, 8)});
            out.push_back({"cracks", cracks(w, h, seed, 6)});
        }
        out.push_back({"glyphs", glyphs(w, h, "HEX\nTILE\n0123")});
        out.push_back({"ridges", ridges(w, h, 3), true});
    }
    return out;
}

Slot normalSlot(bool flipY) {
    Slot s;
    s.name = "normal", s.texture = "n.png", s.kind = SlotKind::Normal, s.flipY = flipY;
    return s;
}

bool warns(const Slot& slot, const TextureFigures& f, Code code) {
    for (const Diagnostic& d : lintWarnings(slot, f, {"m.json", 1, 1}, "/slots/0/texture"))
        if (d.code == code) return true;
    return false;
}

// Each generated normal map in each convention, declared right and wrong: the rates per kind of height field, and the
// curl ratios closest to the threshold from either side (docs/lint.md#green).
TEST(Lint, GreenConventionFromCurl) {
    struct Tally {
        int right = 0, falsePositive = 0, wrong = 0, falseNegative = 0;
        double highestRight = 0, lowestWrong = 1e9;
    };
    std::map<std::string, Tally> tally;
    double highestRightCurl = 0, lowestWrongCurl = 1e9;
    for (const Case& c : heightFields())
        for (double slope : {0.15, 0.5, 2.0})
            for (bool sobel : {false, true})
                for (bool down : {false, true}) {
                    const Texture t = normalMap(c.field, slope, down, sobel);
                    Tally& k = tally[c.kind + " slope " + std::to_string(slope).substr(0, 4)];
                    for (bool declared : {false, true}) {
                        const TextureFigures f = measureTexture(t, SlotKind::Normal, 0, declared, 3);
                        const bool warned = warns(normalSlot(declared), f, Code::NormalGreen);
                        const double ratio = *f.curlDeclared / std::max(*f.curlOther, 1e-9);
                        if (declared == down) {
                            ++k.right, k.falsePositive += warned, k.highestRight = std::max(k.highestRight, ratio);
                            highestRightCurl = std::max(highestRightCurl, *f.curlDeclared);
                        } else if (!c.oneAxis) {
                            ++k.wrong, k.falseNegative += !warned, k.lowestWrong = std::min(k.lowestWrong, ratio);
                            lowestWrongCurl = std::min(lowestWrongCurl, *f.curlDeclared);
                        }
                        if (c.oneAxis) {
                            EXPECT_FALSE(warned) << c.kind;
                        }
                    }
                }
    int right = 0, falsePositive = 0, wrong = 0, falseNegative = 0;
    for (const auto& [kind, k] : tally) {
        std::printf("%-22s right %3d false positives %2d (highest ratio %.2f)  wrong %3d false negatives %2d (lowest ratio %.2f)\n",
                    kind.c_str(), k.right, k.falsePositive, k.highestRight, k.wrong, k.falseNegative, k.lowestWrong);
        right += k.right, falsePositive += k.falsePositive, wrong += k.wrong, falseNegative += k.falseNegative;
    }
    std::printf(
        "all: %d of %d right declarations warned, %d of %d wrong ones not warned; curl read right at most %.3f, wrong at "
        "least %.3f\n",
        falsePositive, right, falseNegative, wrong, highestRightCurl, lowestWrongCurl);
    EXPECT_EQ(falsePositive, 0);
    EXPECT_EQ(falseNegative, 0);
}

// A tilt added to a bump map's slopes is read back as its angle; the untilted map reads under half a degree.
TEST(Lint, TiltInDegrees) {
    const Field f = bumps(64, 64, 7, 12);
    const TextureFigures level = measureTexture(normalMap(f, 0.5, false), SlotKind::Normal, 0, false, 3);
    EXPECT_LT(*level.tiltDegrees, 0.5);
    EXPECT_FALSE(warns(normalSlot(false), level, Code::NormalTilt));
    for (double degrees : {3.0, 10.0}) {
        const Texture t = normalMap(f, 0.5, false, false, std::tan(degrees * std::numbers::pi / 180));
        const TextureFigures tilted = measureTexture(t, SlotKind::Normal, 0, false, 3);
        // 8-bit rounding moves the mean slope by at most half a step of x/z: about 0.3 degrees.
        EXPECT_NEAR(*tilted.tiltDegrees, degrees, 0.3);
        EXPECT_TRUE(warns(normalSlot(false), tilted, Code::NormalTilt)) << degrees;
    }
}

// Seamless textures (periodic noise of four spectra, bumps, cracks) against crops of noise of the same spectra and a
// longer period, which do not tile: the edge-to-interior ratios closest to the threshold from either side
// (docs/lint.md#seams). The noise has frequencies up to 8 cycles, so even its flat spectrum (0) is smooth enough
// at the texel scale for a seam to show.
TEST(Lint, SeamFromEdgeDifference) {
    double highestSeamless = 0, lowestSeam = 1e9;
    int seamless = 0, falsePositive = 0, seams = 0, falseNegative = 0;
    Slot colour;
    colour.texture = "c.png";
    for (auto [w, h] : {std::pair{64, 64}, std::pair{96, 80}})
        for (unsigned seed = 1; seed <= 3; ++seed) {
            std::vector<Field> tiling = {bumps(w, h, seed, 12), cracks(w, h, seed, 6)}, crops;
            for (double beta : {0.0, 1.0, 2.0, 3.0}) tiling.push_back(spectral(w, h, seed, beta, 8));
            for (double beta : {0.0, 1.0, 2.0, 3.0}) crops.push_back(spectral(w, h, seed, beta, 8, int(1.6 * std::max(w, h))));
            for (const Field& f : tiling) {
                const TextureFigures m = measureTexture(greyTexture(f), SlotKind::Color, 0, false, 3);
                ++seamless, falsePositive += warns(colour, m, Code::TextureSeam);
                highestSeamless = std::max({highestSeamless, (*m.seam)[0], (*m.seam)[1]});
            }
            for (const Field& f : crops) {
                const TextureFigures m = measureTexture(greyTexture(f), SlotKind::Color, 0, false, 3);
                ++seams, falseNegative += !warns(colour, m, Code::TextureSeam);
                lowestSeam = std::min(lowestSeam, std::max((*m.seam)[0], (*m.seam)[1]));
            }
        }
    std::printf("seamless: %d of %d warned, highest ratio %.2f; crops: %d of %d not warned, lowest ratio %.2f\n", falsePositive, seamless,
                highestSeamless, falseNegative, seams, lowestSeam);
    EXPECT_EQ(falsePositive, 0);
    EXPECT_EQ(falseNegative, 0);
}

// A normal map's seam is in its x and y; a scalar's in its channel only.
TEST(Lint, SeamOfNormalAndScalarMaps) {
    const Field crop = spectral(64, 64, 5, 2, 8, 100);
    EXPECT_TRUE(warns(normalSlot(false), measureTexture(normalMap(crop, 0.5, false), SlotKind::Normal, 0, false, 3), Code::TextureSeam));
    Texture t = greyTexture(spectral(64, 64, 5, 2, 8));
    const Texture seam = greyTexture(crop);
    for (size_t i = 0; i < t.rgba8.size(); i += 4) t.rgba8[i + 1] = seam.rgba8[i];  // green does not tile, red does
    Slot scalar;
    scalar.kind = SlotKind::Scalar;
    EXPECT_FALSE(warns(scalar, measureTexture(t, SlotKind::Scalar, 0, false, 4), Code::TextureSeam));
    EXPECT_TRUE(warns(scalar, measureTexture(t, SlotKind::Scalar, 1, false, 4), Code::TextureSeam));
}

// NaN and infinite texels are counted and located, and stop the other checks; sizes under 4 are not measured.
TEST(Lint, NonFiniteAndTinyTextures) {
    Texture t;
    t.width = 8, t.height = 6;
    t.rgba32f.assign(size_t(8 * 6 * 4), 0.5f);
    t.rgba32f[(size_t(2) * 8 + 5) * 4 + 1] = std::nanf("");
    t.rgba32f[(size_t(4) * 8 + 1) * 4] = INFINITY;
    const TextureFigures f = measureTexture(t, SlotKind::Normal, 0, false, 3);
    EXPECT_EQ(f.nonFinite, 2);
    EXPECT_EQ(f.firstNonFinite, (std::array<int, 2>{5, 2}));
    EXPECT_FALSE(f.curlDeclared || f.seam);
    const Diagnostics d = lintWarnings(normalSlot(false), f, {"m.json", 3, 4}, "/slots/0/texture");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].format(),
              "m.json:3:4: warning[HX133]: /slots/0/texture: `n.png` has 2 texels that are not finite (NaN or infinity), the first at "
              "(5, 2): filtering spreads them into their neighbours; its other checks are not run");
    for (auto [w, h] : {std::pair{3, 3}, std::pair{1, 64}}) {
        Texture tiny;
        tiny.width = w, tiny.height = h;
        tiny.rgba8.assign(size_t(w * h * 4), 128);
        const TextureFigures s = measureTexture(tiny, SlotKind::Normal, 0, false, 3);
        EXPECT_EQ(s.skipped, std::to_string(w) + "x" + std::to_string(h) + " is too small to check (the checks need at least 4x4 texels)");
        EXPECT_TRUE(lintWarnings(normalSlot(false), s, {}, "").empty());
    }
}

// Every texture file of the repository (materials/, tests/) passes as a colour texture, and a normal map (named so)
// as a green-up normal map; every example material compiles without a texture warning.
TEST(Lint, RepositoryTexturesPass) {
    int files = 0;
    for (const char* root : {"materials", "tests"})
        for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
            const std::string ext = e.path().extension().string();
            if (e.path().string().find("node_modules") != std::string::npos || (ext != ".png" && ext != ".pfm")) continue;
            const bool normal = e.path().filename().string().find("normal") != std::string::npos;
            const bool splat = e.path().filename().string().find("splat") != std::string::npos;  // covers a terrain once: not tiled
            Slot s = normalSlot(false);
            s.kind = normal ? SlotKind::Normal : SlotKind::Color;
            s.texture = e.path().string();
            const TextureFigures f = measureTexture(loadTexture(e.path(), false), s.kind, 0, false, 3);
            std::printf("%-48s", e.path().string().c_str());
            if (f.curlDeclared) std::printf(" curl %.3f / %.3f, tilt %.2f deg,", *f.curlDeclared, *f.curlOther, *f.tiltDegrees);
            if (f.seam) std::printf(" seam %.2f %.2f", (*f.seam)[0], (*f.seam)[1]);
            std::printf("\n");
            // The MaterialX corpus's stand-in normal map writes the slopes (-g, -g) of a height whose y slope is +g read
            // green up (materials/mtlx/corpus/textures/generate.py): it reads as green down, and is found.
            const bool standIn = e.path().filename() == "stone_normal.png";
            const Diagnostics d = lintWarnings(s, f, {}, "");
            if (standIn) {
                EXPECT_TRUE(d.size() == 1 && d[0].code == Code::NormalGreen) << formatAll(d);
            } else if (!splat) {
                EXPECT_TRUE(d.empty()) << formatAll(d);
            }
            ++files;
        }
    EXPECT_GE(files, 20);
    int materials = 0;
    for (const char* dir : {"materials", "materials/terrain"})
        for (const auto& e : std::filesystem::directory_iterator(dir)) {
            if (e.path().extension() != ".json" || e.path().filename() == "material.schema.json") continue;
            const Diagnostics d = lintMaterial(loadMaterial(e.path()));
            EXPECT_TRUE(d.empty()) << formatAll(d);
            ++materials;
        }
    EXPECT_GE(materials, 8);
}

// `hexc lint`: a material's figures on stdout and exit 0; a wrong-green normal map found (exit 1, HX130); a slot's
// `lint_skip` silences it.
TEST(Lint, CommandLine) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("hexc_lint_" + testLogName());
    std::filesystem::create_directories(dir);
    writeImage(
        [] {
            const Texture t = normalMap(bumps(64, 64, 3, 12), 0.5, true);  // green down
            Image image{t.width, t.height, {}};
            for (uint8_t b : t.rgba8) image.rgba.push_back(b / 255.0f);
            return image;
        }(),
        dir / "dx.png");
    std::string err;
    EXPECT_EQ(runHexc("lint materials/rock.json", &err), 0) << err;
    EXPECT_NE(runHexcStdout("lint materials/rock.json").find("green  curl"), std::string::npos);
    EXPECT_EQ(runHexc("lint --kind normal " + (dir / "dx.png").string(), &err), 1);
    EXPECT_NE(err.find("warning[HX130]"), std::string::npos) << err;
    EXPECT_EQ(runHexc("lint --kind normal --flip-y " + (dir / "dx.png").string(), &err), 0) << err;
    std::ofstream(dir / "m.json") << R"({"name": "m", "slots": [{"name": "normal", "kind": "normal", "texture": "dx.png"}]})";
    EXPECT_EQ(runHexc("lint " + (dir / "m.json").string(), &err), 1);
    EXPECT_NE(err.find("m.json:1:52: warning[HX130]: /slots/0/texture: `dx.png` reads as a green down"), std::string::npos) << err;
    std::ofstream(dir / "m.json")
        << R"({"name": "m", "slots": [{"name": "normal", "kind": "normal", "texture": "dx.png", "lint_skip": ["green"]}]})";
    EXPECT_EQ(runHexc("lint " + (dir / "m.json").string(), &err), 0) << err;
    std::ofstream(dir / "m.json")
        << R"({"name": "m", "slots": [{"name": "normal", "kind": "normal", "texture": "dx.png", "lint_skip": ["gren"]}]})";
    EXPECT_EQ(runHexc("lint " + (dir / "m.json").string(), &err), 1);
    EXPECT_NE(err.find("error[HX107]: /slots/0/lint_skip/0"), std::string::npos) << err;
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hexc::test
