// The target table (backends/targets.cpp) is the one list of targets: the CMake and Bazel packages, the manifest
// schema and the layout file's sections name exactly its targets, so a row added there and forgotten in one of them
// fails here rather than silently.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <map>
#include <regex>
#include <set>

#include "backends/backends.h"
#include "support.h"

using namespace hexc;
using hexc::test::readFile;

namespace {

// The words of the first `set(<variable> word...)` in a CMake file.
std::vector<std::string> cmakeList(const std::string& text, const std::string& variable) {
    std::smatch m;
    EXPECT_TRUE(std::regex_search(text, m, std::regex("set\\(" + variable + " ([^)]*)\\)"))) << variable;
    std::vector<std::string> words;
    std::istringstream in(m[1].str());
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

// The quoted strings of the first `<variable> = <value>` line of a Starlark file, in order.
std::vector<std::string> starlarkStrings(const std::string& text, const std::string& variable) {
    std::smatch line;
    EXPECT_TRUE(std::regex_search(text, line, std::regex("\\n" + variable + " = ([^\\n]*)"))) << variable;
    std::vector<std::string> out;
    const std::string value = line[1];
    static const std::regex quoted("\"([^\"]*)\"");
    for (std::sregex_iterator it(value.begin(), value.end(), quoted), end; it != end; ++it) out.push_back((*it)[1]);
    return out;
}

std::vector<std::string> namesOf(const std::vector<Target>& targets) {
    std::vector<std::string> names;
    for (Target t : targets) names.push_back(std::string(toString(t)));
    return names;
}

std::vector<std::string> defaultNames() { return namesOf(defaultTargets()); }

// The first list of targets, `a,b,c` in backquotes, after `pattern` in docs/cli.md.
std::string docsList(const std::string& pattern) {
    const std::string docs = readFile("docs/cli.md");
    std::smatch m;
    EXPECT_TRUE(std::regex_search(docs, m, std::regex(pattern + "`([^`]*)`"))) << pattern;
    return m[1].str();
}

std::string commaSeparated(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& name : names) out += (out.empty() ? "" : ",") + name;
    return out;
}

}  // namespace

TEST(TargetTable, CMakePackageListsTheTable) {
    const std::string cmake = readFile("compiler/integrations/cmake/hexcMaterials.cmake");
    EXPECT_EQ(cmakeList(cmake, "_HEXC_TARGETS"), targetNames());
    EXPECT_EQ(cmakeList(cmake, "_HEXC_DEFAULT_TARGETS"), defaultNames());
}

TEST(TargetTable, BazelPackageListsTheTable) {
    const std::string bzl = readFile("compiler/integrations/bazel/hexc.bzl");
    std::vector<std::string> pairs;  // name, extension, name, extension ...
    for (const TargetRow& row : targetRows()) {
        pairs.push_back(row.name);
        pairs.push_back(row.extension);
    }
    EXPECT_EQ(starlarkStrings(bzl, "_EXTENSIONS"), pairs);
    EXPECT_EQ(starlarkStrings(bzl, "_DEFAULT_TARGETS"), defaultNames());
}

TEST(TargetTable, CommandLineDocsListTheTable) {
    EXPECT_EQ(docsList("`--target LIST` [^\\n]*comma-separated subset of "), commaSeparated(targetNames()));
}

// `--functions` without `--targets`: the default targets that are source (defaultFunctionsTargets), as the docs say.
TEST(TargetTable, CommandLineDocsStateTheFunctionsDefault) {
    EXPECT_EQ(docsList("`--functions` [^\\n]*the default targets become "), commaSeparated(namesOf(defaultFunctionsTargets())));
}

TEST(TargetTable, ManifestSchemaDescribesEveryTarget) {
    const nlohmann::json schema = nlohmann::json::parse(readFile("docs/manifest.schema.json"));
    std::vector<std::string> keys;
    for (const auto& [key, value] : schema["properties"]["targets"]["properties"].items()) keys.push_back(key);
    std::vector<std::string> names = targetNames();
    std::sort(names.begin(), names.end());
    EXPECT_EQ(keys, names);  // the library's json keeps keys sorted
}

TEST(TargetTable, EveryLayoutSectionPlacesATarget) {
    std::set<std::string> sections, used;
    for (const LayoutField& f : layoutFields()) sections.insert(f.target);
    for (const TargetRow& row : targetRows()) used.insert(row.layout);
    EXPECT_EQ(sections, used);
}

TEST(TargetTable, NamesAndAliasesFindTheirRow) {
    for (const TargetRow& row : targetRows()) {
        EXPECT_EQ(targetNamed(row.name), row.target);
        if (*row.alias) {
            EXPECT_EQ(targetNamed(row.alias), row.target);
        }
        EXPECT_EQ(shaderFileName("m", row.target), std::string("m.frag.") + row.extension);
    }
    EXPECT_EQ(targetNamed("dxil"), std::nullopt);
}
