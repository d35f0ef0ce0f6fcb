// hexc edit's session on its own: what the page's requests answer and what they cost, linking only hexc_edit and the
// library (no server, no browser; tests/edit/*.py drive those).
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "session.h"

namespace hexc::edit {
namespace {

using Json = nlohmann::ordered_json;

Json readJson(const std::string& file) {
    std::ifstream in(file);
    return Json::parse(in);
}

// The page's compile request: the document.
std::string request(const Json& document) { return Json{{"document", document}}.dump(); }

class EditSession : public testing::Test {
protected:
    Session session{"materials/rock.json", "materials"};
    Json document = readJson("materials/rock.json");

    // Compiles `document` as the page asks; returns the shader compiles it cost.
    size_t compileCost() {
        const size_t before = session.compiles();
        const Json reply = Json::parse(session.compile(request(document)).body);
        EXPECT_TRUE(reply["ok"].get<bool>()) << reply.dump(2);
        for (const auto& [name, program] : reply["programs"].items()) EXPECT_TRUE(program.contains("fragment")) << name;
        EXPECT_EQ(reply["server"]["compiles"].get<size_t>(), session.compiles() - before);  // what the page reports
        return session.compiles() - before;
    }
};

TEST_F(EditSession, AnswersTheViewsAndPlainTiling) {
    const Json reply = Json::parse(session.compile(request(document)).body);
    ASSERT_TRUE(reply["ok"].get<bool>()) << reply.dump(2);
    EXPECT_EQ(reply["slots"], Json::parse(R"(["albedo", "normal", "roughness"])"));
    EXPECT_EQ(reply["template"], "lit");
    EXPECT_EQ(reply["note"], "");
    ASSERT_EQ(reply["programs"].size(), 2u);
    for (const char* name : {"views", "plain"})
        EXPECT_NE(reply["programs"][name]["fragment"].get<std::string>().find("#version 300 es"), std::string::npos) << name;
    // The page picks a view and a slot by defining the views' specialisation constants (templates/edit/views.glsl).
    const std::string views = reply["programs"]["views"]["fragment"];
    for (const char* macro : {"SPIRV_CROSS_CONSTANT_ID_1000", "SPIRV_CROSS_CONSTANT_ID_1001"})
        EXPECT_NE(views.find("#define " + std::string(macro)), std::string::npos) << macro;
    // The manifest names the template as the material does, not the composed copy.
    EXPECT_EQ(reply["programs"]["views"]["manifest"]["template"], "lit");
}

TEST_F(EditSession, AValueEditCompilesNothing) {
    compileCost();
    document["hextiling"]["falloff"] = 0.5;  // a parameter block member: the page's sliders set it without a compile
    EXPECT_EQ(compileCost(), 0u);
}

// A layered material's blend: its width and skip_below are parameter block members, as a slot's settings are (the page
// sets them without asking); its mode changes the code. Two layers of one role and the heights, to compile in little time.
TEST(EditSessionLayers, ALayerBlendValueCompilesNothingAndItsModeCompiles) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_edit_layer_blend";
    std::filesystem::create_directories(dir);
    const std::string textures = std::filesystem::absolute("materials/textures").string() + "/";
    auto layer = [&](const std::string& name, const std::string& texture) {
        return Json{{"name", name},
                    {"slots",
                     {{{"name", "albedo"}, {"kind", "color"}, {"texture", textures + texture + "_albedo.png"}},
                      {{"name", "height"}, {"kind", "scalar"}, {"channel", "a"}, {"texture", textures + texture + "_rh.png"}}}}};
    };
    Json document = {{"name", "two"},
                     {"template", "unlit"},
                     {"layers", {layer("grass", "terrain_grass"), layer("sand", "terrain_sand")}},
                     {"layer_blend", {{"splat", {textures + "terrain_splat.png"}}, {"mode", "height"}, {"height", "height"}}}};
    std::ofstream(dir / "two.json") << document.dump(2);
    Session session(dir / "two.json", "materials");
    auto cost = [&] {
        const size_t before = session.compiles();
        const Json reply = Json::parse(session.compile(request(document)).body);
        EXPECT_TRUE(reply["ok"].get<bool>()) << reply.dump(2);
        return session.compiles() - before;
    };
    cost();
    document["layer_blend"]["width"] = 0.5;
    document["layer_blend"]["skip_below"] = 0.01;
    EXPECT_EQ(cost(), 0u);
    document["layer_blend"]["mode"] = "linear";
    document["layer_blend"].erase("height");
    EXPECT_GE(cost(), 1u);  // the check can fail: a structural change of the blend compiles
    std::filesystem::remove_all(dir);
}

TEST_F(EditSession, AStructuralEditOfAnySlotCostsOneCompile) {
    compileCost();
    // Every view of every slot is one program: the slot shown makes no difference to the server.
    document["slots"][2]["hextiling"] = {{"taps", 1}};
    EXPECT_EQ(compileCost(), 1u);
    document["slots"][0]["hextiling"] = {{"taps", 1}};
    EXPECT_EQ(compileCost(), 1u);
}

TEST_F(EditSession, AMaterialWideStructuralEditCostsOneCompile) {
    compileCost();
    document["hextiling"]["mask"] = "checker";  // every slot's lattice; plain tiling reads none
    EXPECT_EQ(compileCost(), 1u);
}

TEST_F(EditSession, AnEditThatChangesPlainTilingToo) {
    compileCost();
    document["slots"][1]["flip_y"] = true;  // the normal map's green read the other way: hex-tiled and plain alike
    EXPECT_EQ(compileCost(), 2u);
}

TEST_F(EditSession, ATemplateWithResourcesOfItsOwnIsShownWithLitAskedOnce) {
    Session engine("materials/engine_rock.json", "materials");
    Json doc = readJson("materials/engine_rock.json");
    const Json reply = Json::parse(engine.compile(request(doc)).body);
    ASSERT_TRUE(reply["ok"].get<bool>()) << reply.dump(2);
    EXPECT_EQ(reply["template"], "lit");
    EXPECT_NE(reply["note"].get<std::string>().find("declares resources of its own"), std::string::npos) << reply["note"];
    // What the page shows of a template is asked once per template text: a later structural edit compiles one program.
    doc["hextiling"]["mask"] = "checker";
    const size_t before = engine.compiles();
    const Json again = Json::parse(engine.compile(request(doc)).body);
    ASSERT_TRUE(again["ok"].get<bool>()) << again.dump(2);
    EXPECT_EQ(again["note"], reply["note"]);
    EXPECT_EQ(engine.compiles() - before, 1u);
}

// A template whose resources depend on the material through hexc's macros: judged per material, not once by its text.
TEST_F(EditSession, ATemplatesResourcesAreJudgedPerMaterial) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("hexc-edit-template-" + std::to_string(getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::filesystem::copy("materials/textures", dir / "textures");
    std::ofstream(dir / "frame.glsl") << R"(#version 450
#include <hexc>
#ifdef HEXC_HAS_roughness
layout(set = 1, binding = 0, std140) uniform Frame { float exposure; } frame;
#endif
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;
void main() {
    o_color = hexc_albedo(v_uv);
#ifdef HEXC_HAS_roughness
    o_color *= hexc_roughness(v_uv) * frame.exposure;
#endif
}
)";
    Json doc = Json::parse(R"({"name": "framed", "template": "frame.glsl", "slots": [
        {"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png"}]})");
    std::ofstream(dir / "framed.json") << doc.dump(2);
    Session framed(dir / "framed.json", dir);
    const Json alone = Json::parse(framed.compile(request(doc)).body);
    ASSERT_TRUE(alone["ok"].get<bool>()) << alone.dump(2);
    EXPECT_EQ(alone["note"], "");  // no roughness slot: no block of the template's
    doc["slots"].push_back({{"name", "roughness"}, {"kind", "scalar"}, {"texture", "textures/rock_roughness.png"}});
    const Json both = Json::parse(framed.compile(request(doc)).body);
    ASSERT_TRUE(both["ok"].get<bool>()) << both.dump(2);
    EXPECT_EQ(both["template"], "lit");
    EXPECT_NE(both["note"].get<std::string>().find("declares resources of its own (Frame)"), std::string::npos) << both["note"];
    std::filesystem::remove_all(dir);
}

// A save SIGKILLed before its rename leaves its temporary beside the material; the next edit of the material removes
// it (a dead writer's: older than 10 s and locked by no one). A file merely named like one of another material's is
// left, as is anything that is not a temporary's name.
TEST(EditSessionFolder, DeadTemporariesBesideTheMaterialAreRemoved) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hexc_edit_dead_temporaries";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::filesystem::copy_file("materials/rock.json", dir / "rock.json");
    const auto old = std::filesystem::file_time_type::clock::now() - std::chrono::minutes(1);
    for (const char* name : {".rock.json.0123456789abcdef.tmp", "notes.tmp"}) {
        std::ofstream(dir / name) << "half a save";
        std::filesystem::last_write_time(dir / name, old);
    }
    Session session{dir / "rock.json", "materials"};
    EXPECT_FALSE(std::filesystem::exists(dir / ".rock.json.0123456789abcdef.tmp"));
    EXPECT_TRUE(std::filesystem::exists(dir / "notes.tmp"));
    EXPECT_TRUE(std::filesystem::exists(dir / "rock.json"));
}

TEST_F(EditSession, RefusesARequestWithoutADocument) {
    const Reply reply = session.compile("{\"slots\": []}");
    EXPECT_EQ(reply.status, 400);
    EXPECT_EQ(session.compiles(), 0u);
}

}  // namespace
}  // namespace hexc::edit
