// hexc edit's session on its own: what the page's requests answer and what they cost, linking only hexc_edit and the
// library (no server, no browser; tests/edit/*.py drive those).
#include <gtest/gtest.h>

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

// The page's compile request: the document and the slot its weights and values views show.
std::string request(const Json& document, const std::string& slot) { return Json{{"document", document}, {"slot", slot}}.dump(); }

class EditSession : public testing::Test {
protected:
    Session session{"materials/rock.json", "materials"};
    Json document = readJson("materials/rock.json");

    // Compiles `document` as the page asks, showing `slot`; returns the shader compiles it cost.
    size_t compileCost(const std::string& slot = "albedo") {
        const size_t before = session.compiles();
        const Json reply = Json::parse(session.compile(request(document, slot)).body);
        EXPECT_TRUE(reply["ok"].get<bool>()) << reply.dump(2);
        for (const auto& [name, program] : reply["programs"].items()) EXPECT_TRUE(program.contains("fragment")) << name;
        return session.compiles() - before;
    }
};

TEST_F(EditSession, AnswersEveryProgramOfTheMaterial) {
    const Json reply = Json::parse(session.compile(request(document, "normal")).body);
    ASSERT_TRUE(reply["ok"].get<bool>()) << reply.dump(2);
    EXPECT_EQ(reply["slot"], "normal");
    EXPECT_EQ(reply["template"], "lit");
    EXPECT_EQ(reply["note"], "");
    for (const char* name : {"hex", "plain", "weights", "values"}) {
        ASSERT_TRUE(reply["programs"].contains(name)) << name;
        EXPECT_NE(reply["programs"][name]["fragment"].get<std::string>().find("#version 300 es"), std::string::npos) << name;
    }
}

TEST_F(EditSession, AValueEditCompilesNothing) {
    compileCost();
    document["hextiling"]["falloff"] = 0.5;  // a parameter block member: the page's sliders set it without a compile
    EXPECT_EQ(compileCost(), 0u);
}

TEST_F(EditSession, AStructuralEditOfAnUnshownSlotCostsOneCompile) {
    compileCost();
    document["slots"][2]["hextiling"] = {{"taps", 1}};  // roughness: only the hex-tiled program reads its taps
    EXPECT_EQ(compileCost("albedo"), 1u);
}

TEST_F(EditSession, AStructuralEditOfTheShownSlotRecompilesItsViews) {
    compileCost();
    // albedo: the hex-tiled program and the two views of the slot (weights, values) each read its taps.
    document["slots"][0]["hextiling"] = {{"taps", 1}};
    EXPECT_EQ(compileCost("albedo"), 3u);
}

TEST_F(EditSession, ATemplateWithResourcesOfItsOwnIsShownWithLit) {
    Session engine("materials/engine_rock.json", "materials");
    const Json reply = Json::parse(engine.compile(request(readJson("materials/engine_rock.json"), "")).body);
    ASSERT_TRUE(reply["ok"].get<bool>()) << reply.dump(2);
    EXPECT_EQ(reply["template"], "lit");
    EXPECT_NE(reply["note"].get<std::string>().find("declares resources of its own"), std::string::npos) << reply["note"];
}

TEST_F(EditSession, RefusesARequestWithoutADocument) {
    const Reply reply = session.compile("{\"slot\": \"albedo\"}");
    EXPECT_EQ(reply.status, 400);
    EXPECT_EQ(session.compiles(), 0u);
}

}  // namespace
}  // namespace hexc::edit
