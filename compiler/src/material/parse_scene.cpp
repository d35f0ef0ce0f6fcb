// A scene document -> Scene: its keys, its passes, and each material file it lists, parsed on its own.
#include <algorithm>
#include <set>

#include "common/suggest.h"
#include "hexc/scene.h"
#include "material/parse.h"
#include "material/rules.h"

namespace hexc {
namespace {

class SceneValidator : public JsonRules {
public:
    using JsonRules::JsonRules;

    // A scene: its own keys, then each material file it lists, parsed on its own (their diagnostics name
    // their own files).
    Scene runScene(const json& doc) {
        Scene scene;
        scene.sourceFile = file_;
        duplicateKeys();
        static const std::vector<std::string> kSceneKeys = {"$schema", "scene", "materials", "passes"};
        if (!doc.is_object()) {
            report(Code::WrongType, "", "expected a scene object, got " + typeName(doc));
            return scene;
        }
        checkKeys(doc, "", kSceneKeys);
        if (requireKey(doc, "", "scene", "the scene's name")) {
            scene.name = string(doc["scene"], "/scene");
            if (doc["scene"].is_string() && !isFileName(scene.name))
                report(Code::InvalidName, "/scene", "expected 1-64 letters, digits, `_` or `-`, got \"" + scene.name + "\"");
        }
        if (requireKey(doc, "", "materials", "an array of material files")) sceneMaterials(doc["materials"], scene);
        if (requireKey(doc, "", "passes", "an array of passes")) {
            const json& passes = doc["passes"];
            if (!passes.is_array() || passes.empty())
                report(passes.is_array() ? Code::WrongCount : Code::WrongType, "/passes", "expected a non-empty array of passes");
            for (size_t i = 0; passes.is_array() && i < passes.size(); ++i) scenePass(passes[i], pointerAppend("/passes", i), scene);
        }
        return scene;
    }

private:
    // The scene's materials, each parsed (paths relative to the scene file) with its own diagnostics first.
    void sceneMaterials(const json& list, Scene& scene) {
        const SharedTextureFiles shared;  // the materials' textures, each read once
        if (!list.is_array() || list.empty())
            report(list.is_array() ? Code::WrongCount : Code::WrongType, "/materials", "expected a non-empty array of material file paths");
        for (size_t i = 0; list.is_array() && i < list.size(); ++i) {
            std::string p = pointerAppend("/materials", i);
            std::string path = string(list[i], p);
            if (list[i].is_string() && path.empty()) report(Code::InputUnreadable, p, "an empty path names no material file");
            if (path.empty()) continue;
            // Normalised, so messages name `sub/rock.json`, not `sub/../sub/rock.json`.
            const std::filesystem::path file = (dir_ / path).lexically_normal();
            ParseResult r = parseMaterialFile(file);
            diags.insert(diags.end(), r.diagnostics.begin(), r.diagnostics.end());
            if (!r.material) {
                report(Code::InvalidSceneMaterial, p, "material " + file.string() + " is invalid (see above)");
                continue;
            }
            if (!names_.insert(r.material->name).second)
                report(Code::DuplicateName, p, "two materials are named `" + r.material->name + "`; variant files would collide");
            scene.materials.push_back(std::move(*r.material));
        }
    }

    void scenePass(const json& v, const std::string& p, Scene& scene) {
        static const std::vector<std::string> kPassKeys = {"name", "template", "slots", "materials"};
        if (!v.is_object()) {
            report(Code::WrongType, p, "expected a pass object, got " + typeName(v));
            return;
        }
        checkKeys(v, p, kPassKeys);
        ScenePass pass;
        if (requireKey(v, p, "name", "a string")) {
            pass.name = string(v["name"], p + "/name");
            if (v["name"].is_string() && !isFileName(pass.name))
                report(Code::InvalidName, p + "/name", "expected 1-64 letters, digits, `_` or `-`, got \"" + pass.name + "\"");
            for (const ScenePass& other : scene.passes)
                if (other.name == pass.name) report(Code::DuplicateName, p + "/name", "duplicate pass name \"" + pass.name + "\"");
        }
        if (v.contains("template")) pass.templ = templateRef(v["template"], p + "/template");
        pass.slots = names(v, p, "slots");
        pass.materials = names(v, p, "materials");
        for (size_t j = 0; pass.materials && j < pass.materials->size(); ++j) {
            const std::string& name = (*pass.materials)[j];
            if (names_.contains(name)) continue;
            std::vector<std::string> all;
            for (const Material& m : scene.materials) all.push_back(m.name);
            std::string hint;
            if (auto best = closestMatch(name, all)) hint = "did you mean " + ticked(*best) + "?";
            report(Code::UnknownReference, pointerAppend(p + "/materials", j), "no material named `" + name + "` in the scene", hint);
        }
        passSlots(pass, p, scene);
        scene.passes.push_back(std::move(pass));
    }

    // Each slot a pass keeps is a slot of one of the pass's materials (else it keeps nothing: a misspelling).
    void passSlots(const ScenePass& pass, const std::string& p, const Scene& scene) {
        const std::set<std::string_view> listed =
            pass.materials ? std::set<std::string_view>(pass.materials->begin(), pass.materials->end()) : std::set<std::string_view>{};
        std::set<std::string> all;  // each name once: the materials of a scene mostly share their slots' names
        for (const Material& m : scene.materials)
            if (!pass.materials || listed.contains(m.name))
                for (const Slot& s : m.slots) all.insert(s.name);
        for (size_t j = 0; pass.slots && !all.empty() && j < pass.slots->size(); ++j) {
            const std::string& name = (*pass.slots)[j];
            if (all.contains(name)) continue;
            std::string hint;
            if (auto best = closestMatch(name, {all.begin(), all.end()})) hint = "did you mean " + ticked(*best) + "?";
            report(Code::UnknownReference, pointerAppend(p + "/slots", j), "no material of this pass has a slot named `" + name + "`",
                   hint);
        }
    }

    std::set<std::string> names_;  // of the scene's materials
};

}  // namespace

namespace {

// Looks for a top-level "scene" key while the text is read (SAX), without building the document: a material is
// then parsed once, by its own parser, however large.
struct SceneKeyFinder : nlohmann::json_sax<nlohmann::json> {
    int depth = 0;
    bool found = false;
    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return ++depth, true; }
    bool end_object() override { return --depth, true; }
    bool start_array(std::size_t) override { return ++depth, true; }
    bool end_array() override { return --depth, true; }
    bool key(string_t& k) override {
        found = depth == 1 && k == "scene";
        return !found;  // stops reading once found
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }
};

}  // namespace

bool isSceneDocument(std::string_view text) {
    SceneKeyFinder finder;
    nlohmann::json::sax_parse(text, &finder);
    return finder.found;
}

SceneParseResult parseSceneFile(const std::filesystem::path& file) { return readAndParse(file, "scene", &parseScene); }

SceneParseResult parseScene(std::string_view text, const std::filesystem::path& file) {
    return validate(text, file, &SceneParseResult::scene, &SceneValidator::runScene);
}

}  // namespace hexc
