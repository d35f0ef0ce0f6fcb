// Code generation per slot: the library's pieces, their specialisation by a slot's settings, and which of them a
// shader gets.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "codegen/assembly.h"
#include "codegen/codegen.h"
#include "hexc/compiler.h"
#include "plan/plan.h"

using namespace hexc;

namespace {

std::vector<SourceLine> numbered(const std::vector<std::string>& texts) {
    std::vector<SourceLine> out;
    for (const std::string& t : texts) out.push_back({int(out.size()) + 1, t});
    return out;
}

std::vector<std::string> texts(const std::vector<SourceLine>& lines) {
    std::vector<std::string> out;
    for (const SourceLine& l : lines) out.push_back(l.text);
    return out;
}

const Settings kSettings = {{"l.rotate", "true"}, {"l.aspect", "1.0"}, {"b.gainInt", "2"}, {"b.metric", "false"}, {"b.taps", "3"}};

TEST(Specialise, DecidesConditionsOnTheSettingsOnly) {
    EXPECT_EQ(decide("l.rotate", kSettings).taken, 1);
    EXPECT_EQ(decide("!l.rotate", kSettings).taken, 0);
    EXPECT_EQ(decide("l.aspect == 1.0 && b.gainInt > 0", kSettings).taken, 1);
    EXPECT_EQ(decide("b.metric || (b.taps > 2 && !b.metric)", kSettings).taken, 1);
    // One decided operand decides || and &&; otherwise a run-time value leaves it open.
    EXPECT_EQ(decide("b.gainInt > 0 || b.falloff != 0.5", kSettings).taken, 1);
    EXPECT_EQ(decide("b.metric && sum > 0.0", kSettings).taken, 0);
    EXPECT_EQ(decide("b.gain && (b.gainInt > 0 || b.falloff != 0.5)", kSettings).taken, -1);
    EXPECT_EQ(decide("f.x", kSettings).taken, -1);
    EXPECT_EQ(decide("b.taps + 1 > 2", kSettings).taken, -1);  // arithmetic: not decided here
}

// What the settings decide drops out of a condition they leave open; one not read here is left as it is.
TEST(Specialise, KeepsWhatTheSettingsLeaveOpen) {
    const Settings s = {{"b.adaptive", "false"}, {"b.taps", "3"}, {"b.gain", "true"}, {"b.gainInt", "0"}, {"b.falloff", "hexcParams.r"}};
    EXPECT_EQ(decide("!b.adaptive || f.x", {{"b.adaptive", "true"}}).rest, "f.x");
    EXPECT_EQ(decide("(b.adaptive && f.z) || (!b.adaptive && b.taps > 2)", {{"b.adaptive", "true"}, {"b.taps", "3"}}).rest, "(f.z)");
    EXPECT_EQ(decide("(b.adaptive && f.z) || (!b.adaptive && b.taps > 2)", s).taken, 1);
    EXPECT_EQ(decide("b.gain && (b.gainInt > 0 || b.falloff != 0.5)", s).rest, "(hexcParams.r != 0.5)");
    EXPECT_EQ(decide("!(b.gain && x)", s).rest, "!(x)");
    EXPECT_EQ(decide("b.taps + 1 > 2", s).rest, "");
    const std::vector<SourceLine> in = numbered({
        "    if (!b.adaptive || f.x) c = t(0);  // a tap",
        "    W = b.gain && (b.gainInt > 0 || b.falloff != 0.5) ? g(W) : W;",
    });
    EXPECT_EQ(texts(specialise(in, {{"b.adaptive", "true"}, {"b.gain", "true"}, {"b.gainInt", "0"}, {"b.falloff", "hexcParams.r"}})),
              (std::vector<std::string>{"    if (f.x) c = t(0);  // a tap", "    W = (hexcParams.r != 0.5) ? g(W) : W;"}));
}

TEST(Specialise, KeepsTheBranchTaken) {
    const std::vector<SourceLine> in = numbered({
        "vec2 f(vec2 v, HexcLattice l) {",
        "    if (l.rotate) {",
        "        if (l.aspect == 1.0) {",
        "            v = r(v);  // square",
        "        } else {",
        "            v = s(v, l.aspect);",
        "        }",
        "    }",
        "    if (!l.rotate) v = -v;",
        "    if (v.x > 0.0) v = l.offset * v;",
        "    return l.transform ? v * 2.0 : v;",
        "}",
    });
    const std::vector<SourceLine> out = specialise(in, {{"l.rotate", "true"}, {"l.aspect", "1.0"}, {"l.transform", "false"}});
    EXPECT_EQ(texts(out), (std::vector<std::string>{"vec2 f(vec2 v, HexcLattice l) {", "    v = r(v);  // square",
                                                    "    if (v.x > 0.0) v = l.offset * v;", "    return v;", "}"}));
    EXPECT_EQ(out[1].number, 4);  // where it is in the library, for #line
}

TEST(Specialise, FoldsSelectsAndReadsOfSettings) {
    const std::vector<SourceLine> in = numbered({
        "    vec3 wg = b.gainInt > 0 ? p(w, b.gainInt) : pow(w, vec3(b.exponent));",
        "    float lo = b.metric ? 1.0 - b.falloffContrast : (c ? 1.0 : 2.0);",
        "    int a = d == 0 ? 1 : 0;",
        "    x = q(b.taps > 2, p.b.taps);  // b.taps stays in a comment",
    });
    EXPECT_EQ(texts(specialise(in, kSettings)), (std::vector<std::string>{
                                                    "    vec3 wg = p(w, 2);",
                                                    "    float lo = (c ? 1.0 : 2.0);",
                                                    "    int a = d == 0 ? 1 : 0;",
                                                    "    x = q(3 > 2, p.b.taps);  // b.taps stays in a comment",
                                                }));
}

// An `else if` chain keeps its branches; only its reads of settings become values.
TEST(Specialise, LeavesElseIfChainsAsTheyAre) {
    const std::vector<SourceLine> in = numbered({"    if (b.metric) {", "        a();", "    } else if (x) {", "        b();", "    }"});
    EXPECT_EQ(texts(specialise(in, kSettings)),
              (std::vector<std::string>{"    if (false) {", "        a();", "    } else if (x) {", "        b();", "    }"}));
}

// The library's conventions the specialisation relies on: every piece parsed, settings read through `l` and `b`, and
// never written (a specialised function reads its slot's settings as constants).
TEST(Specialise, TheLibraryFollowsItsConventions) {
    const Library& lib = library();
    ASSERT_GT(lib.pieces.size(), 50u);
    for (const Piece& p : lib.pieces) {
        SCOPED_TRACE(p.name);
        EXPECT_TRUE(p.name.starts_with("hexc") || p.name.starts_with("Hexc"));
        for (const SourceLine& line : p.lines) {
            const std::string code(codeOf(line.text));
            for (const char* setting : {" l.", "(l.", " b.", "(b.", "!b.", "!l."})
                for (size_t at = code.find(setting); at != std::string::npos; at = code.find(setting, at + 1)) {
                    const size_t end = code.find_first_of(" ;,)", at + 3);
                    EXPECT_FALSE(end != std::string::npos && code.compare(end, 3, " = ") == 0) << "a setting written: " << code;
                }
            EXPECT_EQ(code.find("HexcLattice lattice"), std::string::npos) << code;
            EXPECT_EQ(code.find("HexcBlend blend"), std::string::npos) << code;
        }
    }
    EXPECT_TRUE(lib.pieces[lib.byName.at("hexcColor")].blend);
    EXPECT_TRUE(lib.pieces[lib.byName.at("hexcTilesStable")].lattice);
    for (const char* overloaded : {"hexcLift", "hexcFinish"}) {  // three overloads each, one piece
        const Piece& p = lib.pieces[lib.byName.at(overloaded)];
        EXPECT_EQ(std::count_if(p.lines.begin(), p.lines.end(),
                                [&](const SourceLine& l) { return l.text.find(" " + p.name + "(") != l.text.npos; }),
                  3);
    }
    EXPECT_EQ(lib.neutral.at("HexcLattice").front(), (std::pair<std::string, std::string>{"rotation", "0.0"}));
}

ShaderPlan rockPlan(const CompileOptions& options, Material& storage) {
    ParseResult r = parseMaterialFile("materials/rock.json");
    EXPECT_TRUE(r.material) << formatAll(r.diagnostics);
    storage = *r.material;
    return planShader(storage, options);
}

// rock: each slot's functions carry its fixed settings, its parameters in the structs; what no slot uses is not there;
// a form two slots make alike is emitted once.
TEST(Specialise, EachSlotGetsOnlyWhatItUses) {
    Material m;
    const std::string glsl = generateGlsl(rockPlan({}, m));
    for (const char* name : {"vec4 hexcColor_albedo(", "vec2 hexcDeriv_normal(", "hexcTilesStable_albedo("})
        EXPECT_NE(glsl.find(name), std::string::npos) << name;
    // No settings struct: a parameter's setting is read where the function used it, a literal's folded away.
    EXPECT_NE(glsl.find("* hexcPi * hexcParams.albedo_rotation;"), std::string::npos);
    for (const char* name : {"hexcAdaptiveTaps(", "hexcHeightBlend", "hexcTilesPaper", "hexcHistogram", "hexcMx", "HexcPlanes",
                             "textureLod", "hexcColor(", "hexcTilesStable(", "HexcLattice", "HexcBlend", "lattice.", "blend."})
        EXPECT_EQ(glsl.find(name), std::string::npos) << name;
    // Its three slots share a lattice: its functions are the albedo's, once. Albedo and roughness blend alike but for
    // their falloffcontrast parameters: the roughness's own colour function shares the albedo's weights.
    for (const char* name : {"hexcTilesStable_normal", "hexcTilesStable_roughness", "hexcBlendWeights_roughness"})
        EXPECT_EQ(glsl.find(name), std::string::npos) << name;
    EXPECT_NE(glsl.find("hexcColor_roughness(hexcTex_roughness, hexcSampler, hexcTilesStable_albedo(st, dx, dy, cell), hexcChannel(0)"),
              std::string::npos);
    EXPECT_EQ(generateGlsl(rockPlan({}, m)), glsl);
}

TEST(Specialise, WithoutSpecialisationTheGeneralFunctions) {
    Material m;
    CompileOptions options;
    options.specialise = false;
    const std::string glsl = generateGlsl(rockPlan(options, m));
    EXPECT_NE(glsl.find("vec4 hexcColor(texture2D tex"), std::string::npos);
    EXPECT_NE(glsl.find("blend.metric = true;"), std::string::npos);
    EXPECT_EQ(glsl.find("hexcColor_"), std::string::npos);
    EXPECT_EQ(glsl.find("hexcMx"), std::string::npos);  // only what the slots and the template reach
}

// Every example (materials/) and feature variant (tests/golden/materials/, the execution cases' materials), as hexc
// plans it by default.
std::vector<std::pair<std::string, Material>> examplesAndVariants() {
    std::vector<std::pair<std::string, Material>> out;
    auto add = [&](const std::string& name, const ParseResult& r) {
        ASSERT_TRUE(r.material) << name << ": " << formatAll(r.diagnostics);
        out.emplace_back(name, *r.material);
    };
    std::vector<std::filesystem::path> files;
    for (const char* dir : {"materials", "tests/golden/materials", "tests/execution/cases"})
        for (const auto& entry : std::filesystem::directory_iterator(dir))
            if (entry.path().extension() == ".json" && !entry.path().string().ends_with("schema.json")) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const std::filesystem::path& file : files) {
        if (file.parent_path() != "tests/execution/cases") {
            add(file.string(), parseMaterialFile(file));
            continue;
        }
        std::ifstream in(file);  // a case: its material inline, its paths read from materials/ (tests/execution/cases_test.cpp)
        add(file.string(), parseMaterial(nlohmann::json::parse(in).at("material").dump(), "materials/" + file.stem().string() + ".json"));
    }
    return out;
}

// Whether code[i] is an assignment's `=` (not one of ==, !=, <=, >=).
bool assigns(const std::string& code, size_t i) {
    return code[i] == '=' && (i + 1 == code.size() || code[i + 1] != '=') &&
           (i == 0 || std::string_view("=!<>").find(code[i - 1]) == std::string_view::npos);
}

// The condition of each `if (c)` and select `c ? x : y` in `code`.
std::vector<std::string> conditions(const std::string& code) {
    std::vector<std::string> out;
    for (size_t at = code.find("if ("); at != std::string::npos; at = code.find("if (", at + 1))
        if (size_t end = closingBracket(code, at + 3); end != std::string::npos) out.push_back(code.substr(at + 4, end - at - 5));
    for (size_t question = code.find('?'); question != std::string::npos; question = code.find('?', question + 1)) {
        size_t start = question;  // back to what opens the select: `(`, `=`, `,`, `return`, or another select's `?` or `:`
        for (int depth = 0; start > 0; --start) {
            const char c = code[start - 1];
            depth += c == ')' ? 1 : c == '(' ? -1 : 0;
            if (depth < 0 || (depth == 0 && (c == ',' || c == '?' || c == ':' || assigns(code, start - 1)))) break;
        }
        std::string c = code.substr(start, question - start);
        if (c.find("return ") != std::string::npos) c = c.substr(c.find("return ") + 7);
        out.push_back(c);
    }
    return out;
}

// The folding rules (templates/library/hextiling/overview.glsl): a slot's copy of a library function, `<function>_<slot>`,
// takes no settings struct and reads none of its fields, and every branch a fixed setting decided is gone. A condition
// that reads no variable (`if (3 - 2 == 0)`, `false ? x : y`) or keeps a `true` or `false` operand (`!false && f.z`)
// is one the fold left behind: a library edit that writes a setting's test in a form codegen/specialise.cpp does not
// decide makes every slot's shader carry it.
TEST(Specialise, EveryExampleAndVariantFoldsWhatItsSettingsFix) {
    const Library& lib = library();
    std::set<std::string> fields;  // "l.rotate", "b.taps", ...
    for (const auto& [settings, values] : lib.neutral)
        for (const auto& [field, value] : values) fields.insert((settings == "HexcLattice" ? "l." : "b.") + field);
    static const std::regex copy(R"(^\w+ (hexc[A-Z]\w*)_\w+\()"), read(R"((?:^|[^\w.])([lb]\.\w+))");
    static const std::set<std::string_view> constants = {"true", "false", "int", "uint", "float", "bool"};
    size_t copies = 0;
    for (auto& [name, material] : examplesAndVariants()) {
        SCOPED_TRACE(name);
        std::istringstream glsl(generateGlsl(planShader(material, {})));
        std::string line, function;
        for (bool inside = false; std::getline(glsl, line);) {
            std::smatch m;
            if (!inside && std::regex_search(line, m, copy) && lib.byName.count(m[1].str())) {
                const Piece& p = lib.pieces[lib.byName.at(m[1].str())];
                inside = p.lattice || p.blend, function = m[0].str(), copies += inside;
            }
            if (!inside) continue;
            const std::string code(codeOf(line));
            EXPECT_EQ(code.find("HexcLattice"), std::string::npos) << function << ": " << line;
            EXPECT_EQ(code.find("HexcBlend"), std::string::npos) << function << ": " << line;
            for (std::sregex_iterator r(code.begin(), code.end(), read), end; r != end; ++r)
                EXPECT_FALSE(fields.count((*r)[1].str())) << function << " reads " << (*r)[1] << ": " << line;
            for (const std::string& c : conditions(code)) {
                const std::vector<std::string_view> words = identifiers(c);
                EXPECT_FALSE(std::all_of(words.begin(), words.end(), [](std::string_view w) { return constants.count(w); }))
                    << function << " keeps a decided condition `" << c << "`: " << line;
                EXPECT_EQ(std::count_if(words.begin(), words.end(), [](std::string_view w) { return w == "true" || w == "false"; }), 0)
                    << function << " keeps a decided operand in `" << c << "`: " << line;
            }
            inside = !line.starts_with("}");
        }
    }
    EXPECT_GT(copies, 100u);  // the check saw the copies: tens of materials, several per slot
}

}  // namespace
