// Parsing and validation: every rule has a bad input with its exact expected diagnostic.
#include <gtest/gtest.h>

#include <fstream>

#include "hexc/material.h"

using namespace hexc;

namespace {

std::vector<std::string> formatted(const ParseResult& r) {
    std::vector<std::string> out;
    for (const Diagnostic& d : r.diagnostics) out.push_back(d.format());
    return out;
}

// Each file in materials/invalid/ breaks exactly one rule (tests run from the source root).
struct InvalidFile {
    const char* name;
    const char* diagnostic;  // after "materials/invalid/<name>.json:"
};

const InvalidFile kInvalidFiles[] = {
    {"channel_on_color_slot", "10:7: error: /slots/0/channel: `channel` applies only to slots of kind `scalar`"},
    {"duplicate_slot_name", "12:15: error: /slots/1/name: duplicate slot name \"normal\" (first at line 7)"},
    {"enabled_not_boolean", "6:16: error: /hextiling/enabled: expected true or false, got a string"},
    {"exponent_above_64", "6:17: error: /hextiling/exponent: expected a number in [1, 64], got 80"},
    {"exponent_below_one", "6:17: error: /hextiling/exponent: expected a number in [1, 64], got 0.5"},
    {"falloff_out_of_range", "6:16: error: /hextiling/falloff: expected a number in [0.000001, 0.999999] (0.5 = off), got 1.0"},
    {"falloff_zero", "6:16: error: /hextiling/falloff: expected a number in [0.000001, 0.999999] (0.5 = off), got 0"},
    {"falloffcontrast_out_of_range", "6:24: error: /hextiling/falloffcontrast: expected a number in [0, 1], got 1.5"},
    {"flip_y_on_color_slot", "10:7: error: /slots/0/flip_y: `flip_y` applies only to slots of kind `normal`"},
    {"kind_misspelled",
     "9:15: error: /slots/0/kind: expected one of `color`, `scalar` or `normal`, got \"colour\" (did you mean `color`?)"},
    {"material_name_invalid",
     "3:11: error: /name: expected 1-64 letters, digits, `_` or `-` (it names the output files), got \"rock stone\""},
    {"missing_name", "1:1: error: missing required key `name` (a string)"},
    {"mode_unknown", "6:13: error: /hextiling/mode: expected one of `stable` or `paper`, got \"fast\""},
    {"rotation_negative", "6:17: error: /hextiling/rotation: expected a number >= 0, got -1"},
    {"rotation_not_finite", "6:17: error: number 1e999 is out of range (expected a finite number)"},
    {"scalar_channel_invalid", "10:18: error: /slots/0/channel: expected one of `r`, `g`, `b` or `a`, got \"rgb\""},
    {"slot_missing_texture", "6:5: error: /slots/0: missing required key `texture` (a path to an image file)"},
    {"slot_name_double_underscore",
     "7:15: error: /slots/0/name: expected a lower-case identifier of 1-32 characters ([a-z][a-z0-9_]*, no `__`), got "
     "\"albedo__base\" (it becomes the GLSL function hexc_<name>)"},
    {"slot_name_too_long",
     "7:15: error: /slots/0/name: expected a lower-case identifier of 1-32 characters ([a-z][a-z0-9_]*, no `__`), got "
     "\"abbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbb\" (it becomes the GLSL function hexc_<name>)"},
    {"slot_name_uppercase",
     "7:15: error: /slots/0/name: expected a lower-case identifier of 1-32 characters ([a-z][a-z0-9_]*, no `__`), got "
     "\"Albedo\" (it becomes the GLSL function hexc_<name>)"},
    {"slots_empty", "5:12: error: /slots: expected 1 to 16 slots, got 0"},
    {"srgb_normal", "10:21: error: /slots/0/colorspace: a normal map holds vectors and must be `linear`, got \"srgb\""},
    {"template_unknown",
     "4:15: error: /template: unknown template \"pbr\"; expected a built-in template (`lit`, `unlit`, `weights`, `value`, `depth`, `shadow`) or a path "
     "to a .glsl file"},
    {"tiling_wrong_length",
     "6:15: error: /hextiling/tiling: expected a number > 0 or an array [u, v] of two numbers > 0, got an array of 1"},
    {"tiling_zero", "6:16: error: /hextiling/tiling/0: expected a number > 0, got 0"},
    {"too_many_slots", "5:12: error: /slots: expected 1 to 16 slots, got 17"},
    {"unknown_key_in_slot",
     "10:7: error: /slots/0/color_space: unknown key `color_space`; expected `name`, `texture`, `kind`, `channel`, "
     "`colorspace`, `flip_y` or `hextiling` (did you mean `colorspace`?)"},
    {"unknown_key_misspelled",
     "6:5: error: /hextiling/rotaton: unknown key `rotaton`; expected `enabled`, `tiling`, `rotation`, `falloff`, "
     "`falloffcontrast`, `exponent`, `mode`, `split_coordinates`, `rotationrange`, `rotationsteps`, `scalerange`, `offset`, `offsetsteps` or `taps` (did you mean `rotation`?)"},
    {"unknown_key_top_level",
     "12:3: error: /description: unknown key `description`; expected `$schema`, `name`, `template`, `hextiling` or `slots`"},
};

class InvalidMaterial : public testing::TestWithParam<InvalidFile> {};

TEST_P(InvalidMaterial, GivesExactlyItsDiagnostic) {
    std::string file = std::string("materials/invalid/") + GetParam().name + ".json";
    ParseResult r = parseMaterialFile(file);
    EXPECT_FALSE(r.material.has_value());
    EXPECT_EQ(formatted(r), std::vector<std::string>{file + ":" + GetParam().diagnostic});
}

INSTANTIATE_TEST_SUITE_P(Files, InvalidMaterial, testing::ValuesIn(kInvalidFiles),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(InvalidMaterial, EveryFileInTheFolderIsCovered) {
    size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator("materials/invalid")) files += entry.path().extension() == ".json";
    EXPECT_EQ(files, std::size(kInvalidFiles));
}

// Inline documents, located as if they were materials/t.json (textures resolve against materials/).
std::vector<std::string> diagnose(const std::string& text) { return formatted(parseMaterial(text, "materials/t.json")); }

const char* kSlot = R"({"name": "albedo", "texture": "textures/rock_albedo.png", "kind": "color"})";

TEST(Validation, SyntaxErrorIsLocated) {
    EXPECT_EQ(diagnose("{\n  \"name\": \"x\",\n}"),
              std::vector<std::string>{"materials/t.json:3:1: error: invalid JSON: syntax error while parsing object key - "
                                       "unexpected '}'; expected string literal"});
}

TEST(Validation, EmptyFile) {
    EXPECT_EQ(diagnose(""), std::vector<std::string>{"materials/t.json:1:1: error: invalid JSON: syntax error while parsing "
                                                     "value - unexpected end of input; expected '[', '{', or a literal"});
}

TEST(Validation, TopLevelMustBeAnObject) {
    EXPECT_EQ(diagnose("[1, 2]"), std::vector<std::string>{"materials/t.json:1:1: error: expected a material object, got an array"});
}

TEST(Validation, DuplicateKeyIsReportedAtTheSecondKey) {
    EXPECT_EQ(diagnose(std::string("{\"name\": \"a\",\n \"name\": \"b\", \"slots\": [") + kSlot + "]}"),
              std::vector<std::string>{"materials/t.json:2:2: error: /name: duplicate key `name` (first at line 1)"});
}

TEST(Validation, MissingTexture) {
    EXPECT_EQ(diagnose(R"({"name": "m", "slots": [{"name": "a", "kind": "color", "texture": "textures/none.png"}]})"),
              std::vector<std::string>{"materials/t.json:1:67: error: /slots/0/texture: texture file not found: materials/textures/none.png"});
}

TEST(Validation, TextureThatIsNotAnImage) {
    EXPECT_EQ(diagnose(R"({"name": "m", "slots": [{"name": "a", "kind": "color", "texture": "rock.json"}]})"),
              std::vector<std::string>{"materials/t.json:1:67: error: /slots/0/texture: cannot read texture materials/rock.json: "
                                       "unknown image type (expected PNG, JPEG, TGA, BMP, PSD, GIF, HDR, PNM or PFM)"});
}

TEST(Validation, NormalMapNeedsThreeChannels) {
    EXPECT_EQ(diagnose(R"({"name": "m", "slots": [{"name": "n", "kind": "normal", "texture": "textures/rock_roughness.png"}]})"),
              std::vector<std::string>{"materials/t.json:1:68: error: /slots/0/texture: a normal map needs 3 channels (xyz), "
                                       "materials/textures/rock_roughness.png has 1"});
}

TEST(Validation, TemplateTypoSuggestsTheBuiltin) {
    EXPECT_EQ(diagnose(std::string(R"({"name": "m", "template": "litt", "slots": [)") + kSlot + "]}"),
              std::vector<std::string>{"materials/t.json:1:27: error: /template: unknown template \"litt\"; expected a built-in "
                                       "template (`lit`, `unlit`, `weights`, `value`, `depth`, `shadow`) or a path to a .glsl file (did you mean `lit`?)"});
}

TEST(Validation, MissingTemplateFile) {
    EXPECT_EQ(diagnose(std::string(R"({"name": "m", "template": "mine.glsl", "slots": [)") + kSlot + "]}"),
              std::vector<std::string>{"materials/t.json:1:27: error: /template: cannot read template file materials/mine.glsl"});
}

TEST(Validation, WrongTypes) {
    EXPECT_EQ(diagnose(R"({"name": 3, "slots": {}, "hextiling": {"tiling": "big"}})"),
              (std::vector<std::string>{
                  "materials/t.json:1:10: error: /name: expected a string, got a number",
                  "materials/t.json:1:50: error: /hextiling/tiling: expected a number > 0 or an array [u, v] of two numbers > 0, got a string",
                  "materials/t.json:1:22: error: /slots: expected an array of slots, got an object",
              }));
}

TEST(Validation, AllProblemsInAFileAreReported) {
    auto d = diagnose(R"({"name": "m", "hextiling": {"falloff": 2, "exponent": 0},
  "slots": [{"name": "A", "kind": "colour", "texture": "textures/rock_albedo.png", "chanel": "r"}]})");
    EXPECT_EQ(d, (std::vector<std::string>{
                     "materials/t.json:1:40: error: /hextiling/falloff: expected a number in [0.000001, 0.999999] (0.5 = off), got 2",
                     "materials/t.json:1:55: error: /hextiling/exponent: expected a number in [1, 64], got 0",
                     "materials/t.json:2:84: error: /slots/0/chanel: unknown key `chanel`; expected `name`, `texture`, `kind`, "
                     "`channel`, `colorspace`, `flip_y` or `hextiling` (did you mean `channel`?)",
                     "materials/t.json:2:22: error: /slots/0/name: expected a lower-case identifier of 1-32 characters "
                     "([a-z][a-z0-9_]*, no `__`), got \"A\" (it becomes the GLSL function hexc_<name>)",
                     "materials/t.json:2:35: error: /slots/0/kind: expected one of `color`, `scalar` or `normal`, got "
                     "\"colour\" (did you mean `color`?)",
                 }));
}

TEST(Validation, SplitCoordinatesNeedStableMode) {
    EXPECT_EQ(diagnose(R"({"name": "m", "hextiling": {"split_coordinates": true, "mode": "paper"},
  "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"}]})"),
              std::vector<std::string>{"materials/t.json:2:13: error: /slots/0: `split_coordinates` needs mode `stable`; the "
                                       "paper's lattice has no exact period to split at"});
}

TEST(Validation, PerTileTransforms) {
    EXPECT_EQ(diagnose(R"({"name": "m", "hextiling": {"rotationsteps": 2.5, "scalerange": [0, 2], "offsetsteps": 4, "offset": 2},
  "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"}]})"),
              (std::vector<std::string>{
                  "materials/t.json:1:66: error: /hextiling/scalerange/0: expected a number in [0.01, 100], got 0",
                  "materials/t.json:1:101: error: /hextiling/offset: expected a number in [0, 1], got 2",
                  "materials/t.json:1:46: error: /hextiling/rotationsteps: expected a whole number in 0..360 (0: continuous), got 2.5",
                  "materials/t.json:1:88: error: /hextiling/offsetsteps: expected an array of two numbers in 0..4096 (0: continuous), got a number",
              }));
    EXPECT_EQ(diagnose(R"({"name": "m", "hextiling": {"mode": "paper", "rotationsteps": 4},
  "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"}]})"),
              std::vector<std::string>{"materials/t.json:2:13: error: /slots/0: per-tile transforms (rotationrange, rotationsteps, "
                                       "scalerange, offset, offsetsteps) need mode `stable`; mode `paper` is exactly the paper's "
                                       "Listings 2 and 6"});
    ParseResult ok = parseMaterial(R"({"name": "m", "hextiling": {"rotationrange": [0, 360], "rotationsteps": 4, "offsetsteps": [4, 2]},
  "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"}]})", "materials/t.json");
    ASSERT_TRUE(ok.material);
    EXPECT_EQ(ok.material->slots[0].hex.rotationSteps, 4);
    EXPECT_EQ(ok.material->slots[0].hex.offsetSteps, (std::array<int, 2>{4, 2}));
    EXPECT_TRUE(ok.material->slots[0].hex.hasTransforms());
}

TEST(Validation, TapsAreOneOrThree) {
    EXPECT_EQ(diagnose(R"({"name": "m", "hextiling": {"taps": 2}, "slots": [{"name": "a", "kind": "color", "texture": "textures/rock_albedo.png"}]})"),
              std::vector<std::string>{"materials/t.json:1:37: error: /hextiling/taps: expected 1 or 3, got 2"});
}

TEST(Validation, ColumnsCountCharactersNotBytes) {
    // "é" is two bytes in UTF-8; the error column must still be the character column.
    auto d = diagnose(R"({"name": "é", "x": 1, "slots": []})");
    ASSERT_EQ(d.size(), 3u);
    EXPECT_EQ(d[0], "materials/t.json:1:15: error: /x: unknown key `x`; expected `$schema`, `name`, `template`, `hextiling` or `slots`");
}

TEST(Material, ExamplesParseWithDefaultsAndOverrides) {
    ParseResult r = parseMaterialFile("materials/rock.json");
    ASSERT_TRUE(r.material) << r.diagnostics.size();
    EXPECT_TRUE(r.diagnostics.empty());
    const Material& m = *r.material;
    EXPECT_EQ(m.name, "rock");
    EXPECT_EQ(m.templateName, "lit");
    ASSERT_EQ(m.slots.size(), 3u);
    EXPECT_EQ(m.slots[0].kind, SlotKind::Color);
    EXPECT_EQ(m.slots[0].colorSpace, ColorSpace::Srgb);
    EXPECT_EQ(m.slots[0].hex.falloff, 0.75);
    EXPECT_EQ(m.slots[0].hex.falloffcontrast, 0.6);  // paper default
    EXPECT_EQ(m.slots[0].hex.exponent, 7.0);
    EXPECT_EQ(m.slots[1].kind, SlotKind::Normal);
    EXPECT_EQ(m.slots[1].colorSpace, ColorSpace::Linear);
    EXPECT_EQ(m.slots[1].hex.falloff, 0.5);  // slot override
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
