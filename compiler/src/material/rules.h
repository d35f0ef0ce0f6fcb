#pragma once
// The rules every JSON document hexc reads is checked by (materials, scenes, layout files): each problem a located
// diagnostic with its JSON path, and validation goes on after an error, so a user sees all problems in one run.
// Each document's validator (parse_material.cpp, parse_scene.cpp, parse_layout.cpp) builds on JsonRules.
#include <array>
#include <map>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "hexc/diagnostics.h"
#include "hexc/files.h"
#include "hexc/material.h"
#include "material/json_locator.h"

namespace hexc {

std::string typeName(const nlohmann::json& v);                  // "an object", "a string", ...
std::string ticked(const std::string& s);                       // `s`
std::string joinQuoted(const std::vector<std::string>& items);  // `a`, `b` or `c`

// 1-64 letters, digits, `_` or `-`: material, scene and pass names become file names.
bool isFileName(const std::string& name);

class JsonRules {
public:
    JsonRules(std::string_view text, const std::filesystem::path& file) : locator_(text), file_(file), dir_(file.parent_path()) {}

    Diagnostics diags;

    void report(Code code, const std::string& pointer, std::string message, std::string hint = {}, bool atKey = false) {
        report(code, pointer, atKey ? locator_.key(pointer) : locator_.value(pointer), std::move(message), std::move(hint));
    }

    void report(Code code, const std::string& pointer, TextPos p, std::string message, std::string hint = {}) {
        diags.push_back(Diagnostic::make(code, {file_.string(), p.line, p.col}, pointer, std::move(message), std::move(hint)));
    }

    // Keys nlohmann merged silently (the last one would win): in materials, scenes and layouts alike.
    void duplicateKeys();

protected:
    using json = nlohmann::json;

    struct Range {
        double lo, hi;
        bool loOpen, hiOpen;
        std::string text;  // as shown to the user, e.g. "in (0, 1)"
        bool contains(double x) const { return (loOpen ? x > lo : x >= lo) && (hiOpen ? x < hi : x <= hi); }
    };

    // Where else in the document a key is known: its keys and how to name the place ("the slot's `hextiling`").
    struct OtherLevel {
        const std::vector<std::string>* keys;
        std::string where;
    };

    // Unknown keys of `obj`, and a missing required one. An unknown key known at another level gets a hint naming where
    // it belongs (a user who writes `blend` in a slot meant its `hextiling`), else the closest known one.
    void checkKeys(const json& obj, const std::string& pointer, const std::vector<std::string>& known,
                   const std::vector<OtherLevel>& others = {});
    bool requireKey(const json& obj, const std::string& pointer, const std::string& key, const std::string& what);

    // Each value read as its type, or reported with `fallback` (or empty) returned.
    std::string string(const json& v, const std::string& pointer);
    bool boolean(const json& v, const std::string& pointer, bool fallback);
    // A choice among fixed strings; returns the index, or -1 after reporting, with a did-you-mean from the closest
    // spelling or, where one is given, from the words users write for an option (`meant`: "float" -> "scalar").
    int choice(const json& v, const std::string& pointer, const std::vector<std::string>& options,
               const std::map<std::string, std::string>& meant = {});
    double number(const json& v, const std::string& pointer, const Range& range, double fallback);
    // A whole number in `range`.
    double whole(const json& v, const std::string& pointer, const Range& range, double fallback);
    // An array of two numbers in `range` (whole numbers when `integer`).
    void pair(const json& v, const std::string& pointer, const Range& range, std::array<double, 2>& out, bool integer = false);
    std::optional<std::vector<std::string>> names(const json& obj, const std::string& pointer, const std::string& key);
    // A built-in template's name, or a .glsl file relative to the document (which must exist).
    TemplateRef templateRef(const json& v, const std::string& pointer);

    JsonLocator locator_;
    std::filesystem::path file_, dir_;
};

// Parses JSON text; on a syntax error returns nullopt with the located diagnostic in *diags.
std::optional<nlohmann::json> parseJson(std::string_view text, const std::filesystem::path& file, Diagnostics* diags);

// Parses `text` and validates the document with a `Validator`'s `run`, whose result lands in `field` only when there is
// no error, else in `partial` when given.
template <typename Validator, typename Result, typename T>
Result validate(std::string_view text, const std::filesystem::path& file, std::optional<T> Result::*field,
                T (Validator::*run)(const nlohmann::json&), std::optional<T> Result::*partial = nullptr) {
    Result result;
    try {
        std::optional<nlohmann::json> doc = parseJson(text, file, &result.diagnostics);
        if (!doc) return result;
        Validator v(text, file);
        T value = (v.*run)(*doc);
        result.diagnostics = std::move(v.diags);
        if (!hasErrors(result.diagnostics))
            result.*field = std::move(value);
        else if (partial)
            result.*partial = std::move(value);
    } catch (const std::bad_alloc&) {  // what was built is freed by now
        result = Result{};
        result.diagnostics.push_back(outOfMemoryReading(file.string(), text.size()));
    }
    return result;
}

// `file`'s text through `parse`, or a diagnostic saying why the `what` file cannot be read.
template <typename Result>
Result readAndParse(const std::filesystem::path& file, const std::string& what,
                    Result (*parse)(std::string_view, const std::filesystem::path&)) {
    std::string why;
    Result r;
    try {
        std::optional<std::string> text = readFile(file, &why);
        if (text) return parse(*text, file);
    } catch (const std::bad_alloc&) {  // the file's text alone is more than the memory left (parse reports the rest)
        std::error_code ec;
        r.diagnostics.push_back(outOfMemoryReading(file.string(), std::filesystem::file_size(file, ec)));
        return r;
    }
    r.diagnostics.push_back(Diagnostic::make(Code::InputUnreadable, {file.string()}, "", "cannot read " + what + " file: " + why));
    return r;
}

}  // namespace hexc
