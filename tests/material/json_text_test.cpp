// rewriteJsonText: an edited material written back keeps every byte of what did not change.
#include <gtest/gtest.h>

#include "hexc/json_text.h"

using hexc::rewriteJsonText;
using Json = nlohmann::ordered_json;

namespace {

const char* const kMaterial = R"({
  "name": "rock",
  "hextiling": {
    "tiling": [4, 4],
    "rotation": 1.0,
    "falloff": 0.75
  },
  "slots": [
    { "name": "albedo", "texture": "a.png", "kind": "color" },
    {
      "name": "normal",
      "texture": "n.png",
      "kind": "normal",
      "hextiling": { "falloff": 0.5 }
    }
  ]
}
)";

std::string rewritten(const std::function<void(Json&)>& edit) {
    Json j = Json::parse(kMaterial);
    edit(j);
    std::string why;
    std::optional<std::string> out = rewriteJsonText(kMaterial, j, &why);
    EXPECT_TRUE(out) << why;
    return out.value_or("");
}

// The text with `from` replaced by `to` once: what an edit of one value must give.
std::string replaced(const std::string& from, const std::string& to) {
    std::string text = kMaterial;
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

TEST(JsonText, UnchangedDocumentKeepsEveryByte) {
    // 1.0 parses as a float and is written back as written, not as 1.
    EXPECT_EQ(rewritten([](Json& j) { j["hextiling"]["rotation"] = 1; }), kMaterial);
}

TEST(JsonText, ChangedValueIsReplacedInPlace) {
    EXPECT_EQ(rewritten([](Json& j) { j["hextiling"]["falloff"] = 0.6; }), replaced("\"falloff\": 0.75", "\"falloff\": 0.6"));
    EXPECT_EQ(rewritten([](Json& j) { j["hextiling"]["tiling"][1] = 2; }), replaced("[4, 4]", "[4, 2]"));
    EXPECT_EQ(rewritten([](Json& j) { j["hextiling"]["tiling"] = 3; }), replaced("[4, 4]", "3"));
}

TEST(JsonText, AddedMemberFollowsItsSiblingsStyle) {
    EXPECT_EQ(rewritten([](Json& j) { j["hextiling"]["exponent"] = 5; }),
              replaced("\"falloff\": 0.75\n", "\"falloff\": 0.75,\n    \"exponent\": 5\n"));
    EXPECT_EQ(rewritten([](Json& j) { j["slots"][1]["hextiling"]["mask"] = "checker"; }),
              replaced("{ \"falloff\": 0.5 }", "{ \"falloff\": 0.5, \"mask\": \"checker\" }"));
    EXPECT_EQ(rewritten([](Json& j) {
                  j["slots"][0]["hextiling"] = {{"rotation", 0}};
              }),
              replaced("\"kind\": \"color\" }", "\"kind\": \"color\", \"hextiling\": { \"rotation\": 0 } }"));
}

TEST(JsonText, RemovedMemberTakesItsComma) {
    EXPECT_EQ(rewritten([](Json& j) { j["hextiling"].erase("falloff"); }), replaced(",\n    \"falloff\": 0.75", ""));
    EXPECT_EQ(rewritten([](Json& j) { j["hextiling"].erase("tiling"); }), replaced("\"tiling\": [4, 4],\n    ", ""));
    EXPECT_EQ(rewritten([](Json& j) { j["slots"][1]["hextiling"].erase("falloff"); }), replaced("{ \"falloff\": 0.5 }", "{}"));
}

TEST(JsonText, WhatIsNotJsonIsRefused) {
    std::string why;
    EXPECT_FALSE(rewriteJsonText("{\"name\": ", Json::object(), &why));
    EXPECT_EQ(why, "it is not JSON");
    EXPECT_FALSE(rewriteJsonText(std::string(40, '[') + std::string(40, ']'), Json::array(), &why));
    EXPECT_NE(why.find("nests deeper"), std::string::npos) << why;
}

// An edit nested past the limit is refused rather than walked: 100,000 levels (a 200 KB request) overflowed the
// stack in the rewrite's recursion.
TEST(JsonText, EditsNestingTooDeeplyAreRefused) {
    Json deep = Json::array();
    for (int i = 0; i < 100000; ++i) deep = Json::array({std::move(deep)});
    Json edited = Json::parse(kMaterial);
    edited["extra"] = std::move(deep);
    std::string why;
    EXPECT_FALSE(rewriteJsonText(kMaterial, edited, &why));
    EXPECT_NE(why.find("nests deeper"), std::string::npos) << why;
    EXPECT_TRUE(hexc::nestsTooDeep(std::string(100000, '[')));
    EXPECT_FALSE(hexc::nestsTooDeep(kMaterial));
}

// A key spelled with escapes is the key it decodes to: its member is rewritten in place like any other.
TEST(JsonText, KeysSpelledWithEscapesAreTheirDecodedKeys) {
    const std::string text = R"({ "n\u0061me": "rock", "hextiling": { "r\u006ftation": 1.0 } })";
    Json edited = Json::parse(text);
    edited["hextiling"]["rotation"] = 0.5;
    edited["extra"] = 1;
    std::string why;
    std::optional<std::string> out = rewriteJsonText(text, edited, &why);
    ASSERT_TRUE(out) << why;
    EXPECT_EQ(*out, R"({ "n\u0061me": "rock", "hextiling": { "r\u006ftation": 0.5 }, "extra": 1 })");
    edited.erase("name");
    out = rewriteJsonText(text, edited, &why);
    ASSERT_TRUE(out) << why;
    EXPECT_EQ(*out, R"({ "hextiling": { "r\u006ftation": 0.5 }, "extra": 1 })");
}

}  // namespace
