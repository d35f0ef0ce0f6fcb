// Parsing and validation: every rule has a bad input with its exact expected diagnostic.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "hexc/material.h"

using namespace hexc;

namespace {

std::vector<std::string> formatted(const ParseResult& r) {
    std::vector<std::string> out;
    for (const Diagnostic& d : r.diagnostics) out.push_back(d.format());
    return out;
}

// Each file in materials/invalid/ (JSON) and materials/mtlx/invalid/ (MaterialX) breaks exactly one rule; the
// diagnostic hexc must give for it, code included, sits next to it in <name>.expected (tests run from the source root).
const std::pair<const char*, const char*> kInvalidFolders[] = {{"materials/invalid", ".json"}, {"materials/mtlx/invalid", ".mtlx"}};

std::vector<std::string> invalidFiles() {
    std::vector<std::string> files;
    for (const auto& [folder, extension] : kInvalidFolders)
        for (const auto& entry : std::filesystem::directory_iterator(folder))
            if (entry.path().extension() == extension) files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

std::string readText(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

class InvalidMaterial : public testing::TestWithParam<std::string> {};

TEST_P(InvalidMaterial, GivesExactlyItsDiagnostic) {
    std::filesystem::path file = GetParam();
    ParseResult r = parseMaterialFile(file);
    EXPECT_FALSE(r.material.has_value());
    std::string expected = readText(file.replace_extension(".expected"));
    ASSERT_FALSE(expected.empty()) << file << " is missing or empty";
    EXPECT_EQ(formatted(r), std::vector<std::string>{expected.substr(0, expected.find_last_not_of('\n') + 1)});
}

// materials/invalid/x.json: x; materials/mtlx/invalid/x.mtlx: mtlx_x.
INSTANTIATE_TEST_SUITE_P(Files, InvalidMaterial, testing::ValuesIn(invalidFiles()), [](const auto& info) {
    const std::filesystem::path p = info.param;
    return (p.extension() == ".mtlx" ? "mtlx_" : "") + p.stem().string();
});

TEST(InvalidMaterial, EveryExpectationHasItsFile) {
    size_t expectations = 0;
    for (const auto& [folder, extension] : kInvalidFolders)
        for (const auto& entry : std::filesystem::directory_iterator(folder))
            if (entry.path().extension() == ".expected") {
                ++expectations;
                std::filesystem::path file = entry.path();
                EXPECT_TRUE(std::filesystem::exists(file.replace_extension(extension))) << entry.path();
            }
    EXPECT_EQ(expectations, invalidFiles().size());
}

// Inline documents, located as if they were materials/t.json (textures resolve against materials/).
std::vector<std::string> diagnose(const std::string& text) { return formatted(parseMaterial(text, "materials/t.json")); }

const char* kSlot = R"({"name": "albedo", "texture": "textures/rock_albedo.png", "kind": "color"})";

TEST(Validation, SyntaxErrorIsLocated) {
    EXPECT_EQ(diagnose("{\n  \"name\" \"x\"\n}"),
              std::vector<std::string>{"materials/t.json:2:12: error[HX101]: invalid JSON: syntax error while parsing object separator - "
                                       "unexpected string literal; expected ':'"});
}

// nlohmann stops at the bracket after a trailing comma; the diagnostic points at the comma and names it.
TEST(Validation, ATrailingCommaIsReportedWhereItIs) {
    EXPECT_EQ(
        diagnose("{\n  \"name\": \"x\",\n}"),
        std::vector<std::string>{"materials/t.json:2:14: error[HX101]: invalid JSON: a trailing comma before `}` (JSON allows none)"});
    EXPECT_EQ(
        diagnose("{\"slots\": [1, 2 , \t\r\n  ]}"),
        std::vector<std::string>{"materials/t.json:1:17: error[HX101]: invalid JSON: a trailing comma before `]` (JSON allows none)"});
    // A comma with nothing before the bracket but the comma itself is still that comma.
    EXPECT_EQ(diagnose("[,]"), std::vector<std::string>{"materials/t.json:1:2: error[HX101]: invalid JSON: syntax error while parsing "
                                                        "value - unexpected ','; expected '[', '{', or a literal"});
}

// A document holds at most 100,000 values (kMaxJsonValues; a material of 16 slots holds about 600): the value past the
// bound is a located error before parsing. Keys are not values; brackets, commas and colons in strings are nothing.
TEST(Validation, TheValuePastTheBoundIsLocated) {
    // The root, `name`'s string and the array: 3 values; then one a line, each a string of JSON's punctuation.
    auto padded = [](size_t n) {
        std::string text = R"({"name": "m", "[k,{:": [)";
        for (size_t i = 0; i < n; ++i) text += i ? ",\n\"],{:[\"" : "\"],{:[\"";
        return text + "]}";
    };
    const std::vector<std::string> parsed = diagnose(padded(100000 - 3));  // the unknown key, slots missing: read, not refused
    EXPECT_FALSE(parsed.empty());
    for (const std::string& d : parsed) EXPECT_EQ(d.find("HX101"), std::string::npos) << d;
    EXPECT_EQ(diagnose(padded(100000 - 2)),
              std::vector<std::string>{"materials/t.json:99998:1: error[HX101]: JSON of more than 100000 values (a material of 16 "
                                       "slots holds about 600)"});
}

TEST(Validation, EmptyFile) {
    EXPECT_EQ(diagnose(""), std::vector<std::string>{"materials/t.json:1:1: error[HX101]: invalid JSON: syntax error while parsing "
                                                     "value - unexpected end of input; expected '[', '{', or a literal"});
}

TEST(Validation, TopLevelMustBeAnObject) {
    EXPECT_EQ(diagnose("[1, 2]"), std::vector<std::string>{"materials/t.json:1:1: error[HX105]: expected a material object, got an array"});
}

TEST(Validation, DuplicateKeyIsReportedAtTheSecondKey) {
    EXPECT_EQ(diagnose(std::string("{\"name\": \"a\",\n \"name\": \"b\", \"slots\": [") + kSlot + "]}"),
              std::vector<std::string>{"materials/t.json:2:2: error[HX102]: /name: duplicate key `name` (first at line 1)"});
}

TEST(Validation, MissingTexture) {
    EXPECT_EQ(diagnose(R"({"name": "m", "slots": [{"name": "a", "kind": "color", "texture": "textures/none.png"}]})"),
              std::vector<std::string>{
                  "materials/t.json:1:67: error[HX120]: /slots/0/texture: texture file not found: materials/textures/none.png"});
}

TEST(Validation, TextureThatIsNotAnImage) {
    EXPECT_EQ(diagnose(R"({"name": "m", "slots": [{"name": "a", "kind": "color", "texture": "rock.json"}]})"),
              std::vector<std::string>{"materials/t.json:1:67: error[HX121]: /slots/0/texture: cannot read texture materials/rock.json: "
                                       "unknown image type (expected PNG, JPEG, TGA, BMP, PSD, GIF, HDR, PNM, PFM, OpenEXR, KTX2 or DDS)"});
}

TEST(Validation, NormalMapNeedsThreeChannels) {
    EXPECT_EQ(diagnose(R"({"name": "m", "slots": [{"name": "n", "kind": "normal", "texture": "textures/rock_roughness.png"}]})"),
              std::vector<std::string>{"materials/t.json:1:68: error[HX122]: /slots/0/texture: a normal map needs 3 channels (xyz), "
                                       "materials/textures/rock_roughness.png has 1"});
}

TEST(Validation, TemplateTypoSuggestsTheBuiltin) {
    EXPECT_EQ(diagnose(std::string(R"({"name": "m", "template": "litt", "slots": [)") + kSlot + "]}"),
              std::vector<std::string>{"materials/t.json:1:27: error[HX200]: /template: unknown template \"litt\"; expected a built-in "
                                       "template (`depth`, `functions`, `lit`, `shadow`, `unlit`, `value`, `weights`) or a path to a .glsl "
                                       "file (did you mean `lit`?)"});
}

TEST(Validation, MissingTemplateFile) {
    EXPECT_EQ(diagnose(std::string(R"({"name": "m", "template": "mine.glsl", "slots": [)") + kSlot + "]}"),
              std::vector<std::string>{
                  "materials/t.json:1:27: error[HX201]: /template: cannot read template file materials/mine.glsl: no such file"});
}

TEST(Validation, WrongTypes) {
    EXPECT_EQ(diagnose(R"({"name": 3, "slots": {}, "hextiling": {"tiling": "big"}})"),
              (std::vector<std::string>{
                  "materials/t.json:1:10: error[HX105]: /name: expected a string, got a number",
                  "materials/t.json:1:50: error[HX105]: /hextiling/tiling: expected a number in [2^-24, 2^24] or an array [u, v] of two, "
                  "got a string",
                  "materials/t.json:1:22: error[HX105]: /slots: expected an array of slots, got an object",
              }));
}

TEST(Validation, AllProblemsInAFileAreReported) {
    auto d = diagnose(R"({"name": "m", "hextiling": {"falloff": 2, "exponent": 0},
  "slots": [{"name": "A", "kind": "colour", "texture": "textures/rock_albedo.png", "chanel": "r"}]})");
    EXPECT_EQ(
        d, (std::vector<std::string>{
               "materials/t.json:1:40: error[HX106]: /hextiling/falloff: expected a number in [0.000001, 0.999999] (0.5 = off), got 2",
               "materials/t.json:1:55: error[HX106]: /hextiling/exponent: expected a number in [1, 64], got 0",
               "materials/t.json:2:84: error[HX103]: /slots/0/chanel: unknown key `chanel`; expected `name`, `texture`, `kind`, "
               "`channel`, `colorspace`, `flip_y`, `role`, `hextiling`, `height_blend`, `layer` or `lint_skip` (did you mean `channel`?)",
               "materials/t.json:2:22: error[HX108]: /slots/0/name: expected a lower-case identifier of 1-32 characters "
               "([a-z][a-z0-9_]*, no `__`, not starting with `gl_`), got \"A\" (it becomes the GLSL function hexc_<name>)",
               "materials/t.json:2:35: error[HX107]: /slots/0/kind: expected one of `color`, `scalar` or `normal`, got "
               "\"colour\" (did you mean `color`?)",
           }));
}

TEST(Validation, SplitCoordinatesNeedStableMode) {
    EXPECT_EQ(diagnose(R"({"name": "m", "hextiling": {"split_coordinates": true, "mode": "paper"},
  "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"}]})"),
              std::vector<std::string>{"materials/t.json:2:13: error[HX112]: /slots/0: `split_coordinates` needs mode `stable`; the "
                                       "paper's lattice has no exact period to split at"});
}

TEST(Validation, PerTileTransforms) {
    EXPECT_EQ(
        diagnose(R"({"name": "m", "hextiling": {"rotationsteps": 2.5, "scalerange": [0, 2], "offsetsteps": 4, "offset": 2},
  "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"}]})"),
        (std::vector<std::string>{
            "materials/t.json:1:66: error[HX106]: /hextiling/scalerange/0: expected a number in [0.01, 100], got 0",
            "materials/t.json:1:101: error[HX106]: /hextiling/offset: expected a number in [0, 1], got 2",
            "materials/t.json:1:46: error[HX106]: /hextiling/rotationsteps: expected a whole number in 0..360 (0: continuous), got 2.5",
            "materials/t.json:1:88: error[HX105]: /hextiling/offsetsteps: expected an array of two numbers in 0..4096 (0: continuous), got "
            "a number",
        }));
    EXPECT_EQ(diagnose(R"({"name": "m", "hextiling": {"mode": "paper", "rotationsteps": 4},
  "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"}]})"),
              std::vector<std::string>{"materials/t.json:2:13: error[HX112]: /slots/0: per-tile transforms (rotationrange, rotationsteps, "
                                       "scalerange, offset, offsetsteps) need mode `stable`; mode `paper` is exactly the paper's "
                                       "Listings 2 and 6"});
    ParseResult ok = parseMaterial(R"({"name": "m", "hextiling": {"rotationrange": [0, 360], "rotationsteps": 4, "offsetsteps": [4, 2]},
  "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"}]})",
                                   "materials/t.json");
    ASSERT_TRUE(ok.material);
    EXPECT_EQ(ok.material->slots[0].hex.rotationSteps, 4);
    EXPECT_EQ(ok.material->slots[0].hex.offsetSteps, (std::array<int, 2>{4, 2}));
    EXPECT_TRUE(ok.material->slots[0].hex.hasTransforms());
}

TEST(Validation, TapsAreOneOrTheMasksCount) {
    // Checked per slot on the merged settings: a material-level mismatch is reported at each slot.
    EXPECT_EQ(
        diagnose(
            R"({"name": "m", "hextiling": {"taps": 2}, "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"}]})"),
        std::vector<std::string>{"materials/t.json:1:51: error[HX112]: /slots/0: `taps` 2 does not fit mask `hex`, which has 3 taps; "
                                 "expected 3 or 1 (one dithered fetch)"});
    EXPECT_EQ(
        diagnose(R"({"name": "m", "hextiling": {"mask": "noise3"},
  "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"taps": 2}}]})"),
        std::vector<std::string>{"materials/t.json:2:96: error[HX112]: /slots/0/hextiling: `taps` 2 does not fit mask `noise3`, which has "
                                 "3 taps; expected 3 or 1 (one dithered fetch)"});
    EXPECT_EQ(diagnose(R"({"name": "m", "hextiling": {"taps": 1.5},
  "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"}]})"),
              std::vector<std::string>{
                  "materials/t.json:1:37: error[HX106]: /hextiling/taps: expected a whole number in 1..3 or \"adaptive\", got 1.5"});
    EXPECT_EQ(diagnose(R"({"name": "m", "hextiling": {"taps": "adaptiv"},
  "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"}]})"),
              std::vector<std::string>{"materials/t.json:1:37: error[HX107]: /hextiling/taps: expected one of `adaptive`, got \"adaptiv\" "
                                       "(did you mean `adaptive`?)"});
    // A slot may set the taps that fit its own mask, and taps 1 fits every mask.
    ParseResult ok = parseMaterial(R"({"name": "m", "hextiling": {"taps": 3}, "slots": [
  {"name": "a", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"mask": "checker", "taps": 2}},
  {"name": "b", "kind": "color", "texture": "textures/rock_albedo.png"},
  {"name": "c", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"mask": "noise", "taps": 1}},
  {"name": "d", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"mask": "checker", "taps": 1}},
  {"name": "e", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"mask": "checker", "taps": "adaptive"}}]})",
                                   "materials/t.json");
    ASSERT_TRUE(ok.material) << ok.diagnostics.size();
    EXPECT_EQ(ok.material->slots[0].hex.mask, Mask::Checker);
    EXPECT_EQ(ok.material->slots[0].hex.taps, 2);
    EXPECT_EQ(ok.material->slots[0].hex.maskTaps(), 2);
    EXPECT_EQ(ok.material->slots[1].hex.taps, 3);
    EXPECT_EQ(ok.material->slots[2].hex.taps, 1);
    EXPECT_EQ(ok.material->slots[3].hex.taps, 1);
    EXPECT_TRUE(ok.material->slots[4].hex.adaptive());
}

TEST(Validation, MasksOtherThanHexNeedStableMode) {
    EXPECT_EQ(diagnose(R"({"name": "m", "hextiling": {"mode": "paper", "mask": "noise"},
  "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"},
            {"name": "b", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"mask": "hex"}}]})"),
              std::vector<std::string>{"materials/t.json:2:13: error[HX112]: /slots/0: mask `noise` needs mode `stable`; the paper defines "
                                       "only the hex lattice"});
}

TEST(Validation, ProjectionAndPlaneSharpnessAreMaterialWide) {
    EXPECT_EQ(diagnose(R"({"name": "m", "hextiling": {"projection": "triplanar"},
  "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"planesharpness": 8, "projection": "uv"}}]})"),
              (std::vector<std::string>{
                  "materials/t.json:2:118: error[HX111]: /slots/0/hextiling/projection: `projection` is material-wide (every slot function "
                  "takes the "
                  "same inputs); set it in the top-level `hextiling`",
                  "materials/t.json:2:97: error[HX111]: /slots/0/hextiling/planesharpness: `planesharpness` is material-wide (every slot "
                  "function "
                  "takes the same inputs); set it in the top-level `hextiling`",
              }));
    EXPECT_EQ(
        diagnose(R"({"name": "m", "hextiling": {"planesharpness": 65}, "slots": [)" + std::string(kSlot) + "]}"),
        std::vector<std::string>{"materials/t.json:1:47: error[HX106]: /hextiling/planesharpness: expected a number in [1, 64], got 65"});
}

TEST(Validation, SplitCoordinatesWithNoiseMasksOrTriplanar) {
    // Each slot is checked on its merged settings; the checker mask supports split coordinates.
    EXPECT_EQ(
        diagnose(R"({"name": "m", "hextiling": {"split_coordinates": true, "mask": "noise3"}, "slots": [
  {"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"},
  {"name": "b", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"mask": "checker"}},
  {"name": "c", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"split_coordinates": false}}]})"),
        std::vector<std::string>{"materials/t.json:2:3: error[HX112]: /slots/0: `split_coordinates` does not work with the noise masks: "
                                 "their copies are transformed about the origin"});
    EXPECT_EQ(
        diagnose(R"({"name": "m", "hextiling": {"split_coordinates": true, "projection": "triplanar"}, "slots": [)" + std::string(kSlot) +
                 "]}"),
        std::vector<std::string>{"materials/t.json:1:94: error[HX112]: /slots/0: `split_coordinates` does not work with the triplanar "
                                 "projection: it reads world positions, not uv"});
}

// Stable mode is exact while |u * tiling| < 2^26 (hex) or |uv * tiling| < 2^31 (checker): a tiling that brings
// that under 2^16 uv warns, unless split coordinates keep uv small; noise masks and paper mode have no such range.
TEST(Validation, TilingThatBringsStableModesRangeNearWarns) {
    const char* hint =
        " (for larger uv set \"split_coordinates\": true and pass uv relative to a per-frame origin "
        "(docs/precision.md#stable-modes-range))";
    EXPECT_EQ(diagnose(R"({"name": "m", "slots": [
  {"name": "a", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": [2048, 1]}},
  {"name": "b", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 1024}},
  {"name": "c", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": [1, 4096]}},
  {"name": "d", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 4096, "split_coordinates": true}},
  {"name": "e", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 4096, "mode": "paper"}},
  {"name": "f", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 4096, "mask": "checker"}},
  {"name": "g", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 40000, "mask": "checker"}},
  {"name": "h", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 4096, "enabled": false}},
  {"name": "i", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"tiling": 1e7}}]})"),
              (std::vector<std::string>{
                  "materials/t.json:2:86: warning[HX116]: /slots/0/hextiling: with tiling 2048, stable mode's lattice is exact "
                  "only for |u| < 32768 (2^26 / tiling); beyond, tiles come out wrong" +
                      std::string(hint),
                  "materials/t.json:8:86: warning[HX116]: /slots/6/hextiling: with tiling 40000, stable mode's checker is "
                  "exact only for |uv| < 53687 (2^31 / tiling); beyond, tiles come out wrong" +
                      std::string(hint),
                  "materials/t.json:10:86: warning[HX116]: /slots/8/hextiling: with tiling 1e+07, stable mode's lattice is exact "
                  "only for |u| < 6.71 (2^26 / tiling); beyond, tiles come out wrong" +
                      std::string(hint)}));
}

// A tiling the slots inherit is warned about once, at the material's hextiling.
TEST(Validation, AnInheritedTilingIsWarnedAboutOnceWhereItIsSet) {
    const std::vector<std::string> d = diagnose(R"({"name": "m",
  "hextiling": {"tiling": 2048},
  "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"},
            {"name": "b", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"rotation": 0.5}}]})");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_TRUE(d[0].starts_with("materials/t.json:2:16: warning[HX116]: /hextiling: with tiling 2048, stable mode's lattice is exact"))
        << d[0];
}

// Generated parameters are <slot>_<setting>: `a` + `a_origin` would both declare a_origin_offset (split
// coordinates' origin of `a`, the per-tile offset of `a_origin`), so a name that extends another with `_` is refused.
TEST(Validation, ASlotNameThatExtendsAnotherWithAnUnderscoreIsRefused) {
    EXPECT_EQ(diagnose(R"({"name": "m", "hextiling": {"split_coordinates": true}, "slots": [
  {"name": "a_origin", "kind": "color", "texture": "textures/rock_albedo.png"},
  {"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"},
  {"name": "ab", "kind": "color", "texture": "textures/rock_albedo.png"}]})"),
              std::vector<std::string>{"materials/t.json:2:12: error[HX108]: /slots/0/name: slot name \"a_origin\" starts with slot `a`'s "
                                       "name and `_`, so their generated parameters (<slot>_tiling, <slot>_origin_offset, ...) could "
                                       "collide (rename one of them)"});
}

TEST(Validation, HeightBlend) {
    const std::string height = R"({"name": "height", "kind": "scalar", "texture": "textures/rock_roughness.png"})";
    EXPECT_EQ(diagnose(R"({"name": "m", "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png",
  "height_blend": "height"}, )" +
                       height + "]}"),
              std::vector<std::string>{"materials/t.json:2:19: error[HX105]: /slots/0/height_blend: expected an object {\"slot\": name, "
                                       "\"width\": number}, got a string"});
    // taps 1 from the slot's own settings; the height slot may come later in the array.
    EXPECT_EQ(
        diagnose(R"({"name": "m", "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png",
  "hextiling": {"taps": 1}, "height_blend": {"slot": "hieght", "width": 1.5}}, )" +
                 height + "]}"),
        (std::vector<std::string>{
            "materials/t.json:2:73: error[HX106]: /slots/0/height_blend/width: expected a number in (0, 1], got 1.5",
            "materials/t.json:2:29: error[HX112]: /slots/0/height_blend: `height_blend` needs every tile's height; it cannot be combined "
            "with `taps` 1",
            "materials/t.json:2:54: error[HX113]: /slots/0/height_blend/slot: no slot named `hieght` in this material (did you mean "
            "`height`?)",
        }));  // Plain tiling has one tile, nothing to weigh.
    EXPECT_EQ(diagnose(R"({"name": "m", "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png",
  "hextiling": {"enabled": false}, "height_blend": {"slot": "height"}}, )" +
                       height + "]}"),
              std::vector<std::string>{
                  "materials/t.json:2:36: error[HX112]: /slots/0/height_blend: `height_blend` weighs tiles, and this slot has "
                  "hex-tiling disabled (`enabled`: false)"});
}

TEST(Material, HexTilingDefaults) {
    ParseResult r = parseMaterial(std::string(R"({"name": "m", "slots": [)") + kSlot + "]}", "materials/t.json");
    ASSERT_TRUE(r.material);
    for (const HexTiling& hex : {r.material->hex, r.material->slots[0].hex}) {
        EXPECT_EQ(hex.mask, Mask::Hex);
        EXPECT_EQ(hex.taps, 0);  // every tap of the mask
        EXPECT_EQ(hex.maskTaps(), 3);
        EXPECT_EQ(hex.maskScale, 2);
        EXPECT_EQ(hex.projection, Projection::Uv);
        EXPECT_EQ(hex.planeSharpness, 4.0);
    }
    EXPECT_FALSE(r.material->slots[0].heightBlend);
}

TEST(Material, SlotOverridesMask) {
    ParseResult r = parseMaterial(R"({"name": "m", "hextiling": {"mask": "checker", "maskscale": 4}, "slots": [
  {"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"},
  {"name": "b", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"mask": "noise3"}},
  {"name": "c", "kind": "color", "texture": "textures/rock_albedo.png", "hextiling": {"mask": "hex", "maskscale": 1}}]})",
                                  "materials/t.json");
    ASSERT_TRUE(r.material) << r.diagnostics.size();
    const auto& s = r.material->slots;
    EXPECT_EQ(s[0].hex.mask, Mask::Checker);
    EXPECT_EQ(s[0].hex.maskScale, 4);
    EXPECT_EQ(s[1].hex.mask, Mask::Noise3);
    EXPECT_EQ(s[1].hex.maskScale, 4);  // inherited
    EXPECT_EQ(s[2].hex.mask, Mask::Hex);
    EXPECT_EQ(s[2].hex.maskScale, 1);
    EXPECT_EQ(toString(s[1].hex.mask), "noise3");
}

TEST(Material, HeightBlendIsParsed) {
    ParseResult r = parseMaterial(R"({"name": "m", "slots": [
  {"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png", "height_blend": {"slot": "height"}},
  {"name": "normal", "kind": "normal", "texture": "textures/rock_normal.png", "height_blend": {"slot": "height", "width": 0.5}},
  {"name": "height", "kind": "scalar", "texture": "textures/rock_roughness.png", "height_blend": {"slot": "height", "width": 1}}]})",
                                  "materials/t.json");
    ASSERT_TRUE(r.material) << r.diagnostics.size();
    const auto& s = r.material->slots;
    ASSERT_TRUE(s[0].heightBlend);
    EXPECT_EQ(s[0].heightBlend->slot, "height");
    EXPECT_EQ(s[0].heightBlend->width, 0.2);  // default
    ASSERT_TRUE(s[1].heightBlend);
    EXPECT_EQ(s[1].heightBlend->width, 0.5);
    ASSERT_TRUE(s[2].heightBlend);  // a scalar slot may be its own height map
    EXPECT_EQ(s[2].heightBlend->slot, "height");
    EXPECT_EQ(s[2].heightBlend->width, 1.0);
}

TEST(Material, TriplanarProjectionAppliesToEverySlot) {
    ParseResult r = parseMaterial(R"({"name": "m", "hextiling": {"projection": "triplanar", "planesharpness": 8}, "slots": [
  {"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"},
  {"name": "b", "kind": "normal", "texture": "textures/rock_normal.png", "hextiling": {"falloff": 0.5}},
  {"name": "c", "kind": "scalar", "texture": "textures/rock_roughness.png", "hextiling": {"mask": "checker"}}]})",
                                  "materials/t.json");
    ASSERT_TRUE(r.material) << r.diagnostics.size();
    EXPECT_EQ(r.material->hex.projection, Projection::Triplanar);
    for (const Slot& s : r.material->slots) {
        EXPECT_EQ(s.hex.projection, Projection::Triplanar) << s.name;
        EXPECT_EQ(s.hex.planeSharpness, 8.0) << s.name;
    }
}

TEST(Validation, ColumnsCountCharactersNotBytes) {
    // "é" is two bytes in UTF-8; the error column must still be the character column.
    auto d = diagnose(R"({"name": "é", "x": 1, "slots": []})");
    ASSERT_EQ(d.size(), 3u);
    EXPECT_EQ(d[0],
              "materials/t.json:1:15: error[HX103]: /x: unknown key `x`; expected `$schema`, `name`, `template`, `hextiling`, `pack`, "
              "`slots`, `layers` or `layer_blend`");
}

TEST(Material, ExamplesParseWithDefaultsAndOverrides) {
    ParseResult r = parseMaterialFile("materials/rock.json");
    ASSERT_TRUE(r.material) << r.diagnostics.size();
    EXPECT_TRUE(r.diagnostics.empty());
    const Material& m = *r.material;
    EXPECT_EQ(m.name, "rock");
    EXPECT_EQ(m.templ.path(), "templates/builtin/lit.glsl");
    ASSERT_EQ(m.slots.size(), 3u);
    EXPECT_EQ(m.slots[0].kind, SlotKind::Color);
    EXPECT_EQ(m.slots[0].colorSpace, ColorSpace::Srgb);
    EXPECT_EQ(m.slots[0].hex.falloff, 0.75);
    EXPECT_EQ(m.slots[0].hex.falloffcontrast, 0.6);  // paper default
    EXPECT_EQ(m.slots[0].hex.exponent, 7.0);
    EXPECT_EQ(m.slots[1].kind, SlotKind::Normal);
    EXPECT_EQ(m.slots[1].colorSpace, ColorSpace::Linear);
    EXPECT_EQ(m.slots[1].hex.falloff, 0.5);                           // slot override
    EXPECT_EQ(m.slots[1].hex.tiling, (std::array<double, 2>{4, 4}));  // inherited
    EXPECT_EQ(m.slots[2].kind, SlotKind::Scalar);
    EXPECT_EQ(m.slots[2].channel, 0);
    EXPECT_EQ(m.slots[0].width, 256);
    for (const char* f : {"materials/tiles.json", "materials/rock_normal.json"}) {
        ParseResult other = parseMaterialFile(f);
        EXPECT_TRUE(other.material) << f;
    }
}

TEST(Material, ScalarTilingAppliesToBothAxes) {
    ParseResult r = parseMaterialFile("materials/tiles.json");
    ASSERT_TRUE(r.material);
    EXPECT_EQ(r.material->slots[0].hex.tiling, (std::array<double, 2>{3, 3}));
}

}  // namespace

TEST(Validation, AScalarSlotReadsOnlyChannelsItsTextureHas) {
    // rock_roughness.png is grey (1 channel), rock_albedo.png RGB (3).
    auto scalar = [](const char* channel, const char* texture) {
        return diagnose(std::string(R"({"name": "m", "slots": [{"name": "rough", "kind": "scalar", "channel": ")") + channel +
                        R"(", "texture": "textures/)" + texture + R"("}]})");
    };
    EXPECT_EQ(scalar("a", "rock_albedo.png"),
              std::vector<std::string>{
                  "materials/t.json:1:72: error[HX122]: /slots/0/channel: channel `a` of materials/textures/rock_albedo.png, which "
                  "has 3 channels; expected `r`, `g` or `b`"});
    EXPECT_EQ(scalar("g", "rock_roughness.png"),
              std::vector<std::string>{
                  "materials/t.json:1:72: error[HX122]: /slots/0/channel: channel `g` of materials/textures/rock_roughness.png, which "
                  "has 1 channel; expected `r`"});
    EXPECT_TRUE(scalar("b", "rock_albedo.png").empty());
    EXPECT_TRUE(scalar("r", "rock_roughness.png").empty());
}

namespace {

// The catalogue is the contract scripts match on: unique ids, each listed in docs/cli.md with its severity, and
// the docs list no code the library lacks.
TEST(DiagnosticCodes, CatalogueMatchesTheDocs) {
    std::string docs = readText("docs/cli.md");
    std::set<std::string> ids;
    for (const CodeInfo& c : codeCatalogue()) {
        std::string id(c.id);
        EXPECT_TRUE(ids.insert(id).second) << id << " is used twice";
        std::string row = "| " + id + " | " + (c.severity == Diagnostic::Severity::Error ? "error" : "warning") + " | ";
        EXPECT_NE(docs.find(row), std::string::npos) << id << " is not documented as " << row;
        EXPECT_EQ(toString(c.code), c.id);
    }
    size_t rows = 0;
    for (size_t at = 0; (at = docs.find("\n| HX", at)) != std::string::npos; ++at) ++rows;
    EXPECT_EQ(rows, ids.size());
}

// A code decides its severity, and the formatted diagnostic shows it.
TEST(DiagnosticCodes, TheCodeDecidesSeverityAndIsPrinted) {
    Diagnostic w = Diagnostic::make(Code::SlotNotRead, {"m.json", 3, 4}, "/slots/1", "left out");
    EXPECT_EQ(w.severity, Diagnostic::Severity::Warning);
    EXPECT_EQ(w.format(), "m.json:3:4: warning[HX204]: /slots/1: left out");
    EXPECT_FALSE(hasErrors({w}));
    EXPECT_TRUE(hasErrors({w, Diagnostic::make(Code::Internal, {"hexc"}, "", "boom")}));
}

}  // namespace
