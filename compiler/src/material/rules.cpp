// The rules every JSON document hexc reads is checked by (rules.h), and JSON text parsed with located syntax errors.
#include "material/rules.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <new>
#include <sstream>

#include "common/suggest.h"
#include "common/templates.h"
#include "common/text.h"
#include "hexc/files.h"

namespace hexc {

using nlohmann::json;

bool isFileName(const std::string& name) {
    return !name.empty() && name.size() <= 64 &&
           std::all_of(name.begin(), name.end(), [](char c) { return isIdentifierChar(c) || c == '-'; });
}

std::string typeName(const json& v) {
    switch (v.type()) {
        case json::value_t::object:
            return "an object";
        case json::value_t::array:
            return "an array";
        case json::value_t::string:
            return "a string";
        case json::value_t::boolean:
            return "a boolean";
        case json::value_t::null:
            return "null";
        default:
            return "a number";
    }
}

std::string ticked(const std::string& s) { return "`" + s + "`"; }

std::string joinQuoted(const std::vector<std::string>& items) {
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) {
        if (i) out += i + 1 == items.size() ? " or " : ", ";
        out += ticked(items[i]);
    }
    return out;
}

std::optional<std::vector<std::string>> JsonRules::names(const json& obj, const std::string& pointer, const std::string& key) {
    if (!obj.contains(key)) return std::nullopt;
    std::vector<std::string> out;
    const json& v = obj[key];
    if (!v.is_array()) {
        report(Code::WrongType, pointer + "/" + key, "expected an array of names, got " + typeName(v));
        return out;
    }
    for (size_t i = 0; i < v.size(); ++i) out.push_back(string(v[i], pointerAppend(pointer + "/" + key, i)));
    return out;
}

void JsonRules::duplicateKeys() {
    for (const auto& d : locator_.duplicates())
        report(Code::DuplicateKey, d.pointer, d.second,
               "duplicate key " + ticked(d.pointer.substr(d.pointer.rfind('/') + 1)) + " (first at line " + std::to_string(d.first.line) +
                   ")");
}

void JsonRules::checkKeys(const json& obj, const std::string& pointer, const std::vector<std::string>& known,
                          const std::vector<OtherLevel>& others) {
    const auto has = [](const std::vector<std::string>& keys, const std::string& key) {
        return std::find(keys.begin(), keys.end(), key) != keys.end();
    };
    for (const auto& item : obj.items()) {
        const std::string& key = item.key();
        if (has(known, key)) continue;
        std::string hint;
        const auto other = std::find_if(others.begin(), others.end(), [&](const OtherLevel& o) { return has(*o.keys, key); });
        if (other != others.end())
            hint = ticked(key) + " belongs in " + other->where;
        else if (auto best = closestMatch(key, known))
            hint = "did you mean " + ticked(*best) + "?";
        report(Code::UnknownKey, pointerAppend(pointer, key), "unknown key " + ticked(key) + "; expected " + joinQuoted(known), hint, true);
    }
}

bool JsonRules::requireKey(const json& obj, const std::string& pointer, const std::string& key, const std::string& what) {
    if (obj.contains(key)) return true;
    report(Code::MissingKey, pointer, "missing required key " + ticked(key) + " (" + what + ")");
    return false;
}

std::string JsonRules::string(const json& v, const std::string& pointer) {
    if (v.is_string()) return v.get<std::string>();
    report(Code::WrongType, pointer, "expected a string, got " + typeName(v));
    return {};
}

bool JsonRules::boolean(const json& v, const std::string& pointer, bool fallback) {
    if (v.is_boolean()) return v.get<bool>();
    report(Code::WrongType, pointer, "expected true or false, got " + typeName(v));
    return fallback;
}

int JsonRules::choice(const json& v, const std::string& pointer, const std::vector<std::string>& options,
                      const std::map<std::string, std::string>& meant) {
    if (!v.is_string()) {
        report(Code::WrongType, pointer, "expected one of " + joinQuoted(options) + ", got " + typeName(v));
        return -1;
    }
    std::string s = v.get<std::string>();
    for (size_t i = 0; i < options.size(); ++i)
        if (options[i] == s) return int(i);
    std::string hint;
    if (auto it = meant.find(lowerCase(s)); it != meant.end())
        hint = "did you mean " + ticked(it->second) + "?";
    else if (auto best = closestMatch(s, options))
        hint = "did you mean " + ticked(*best) + "?";
    report(Code::UnknownValue, pointer, "expected one of " + joinQuoted(options) + ", got \"" + s + "\"", hint);
    return -1;
}

double JsonRules::number(const json& v, const std::string& pointer, const Range& range, double fallback) {
    if (!v.is_number()) {
        report(Code::WrongType, pointer, "expected a number " + range.text + ", got " + typeName(v));
        return fallback;
    }
    double x = v.get<double>();
    if (!std::isfinite(x) || !range.contains(x)) {
        std::ostringstream s;
        s << "expected a number " << range.text << ", got " << v.dump();
        report(Code::OutOfRange, pointer, s.str());
        return fallback;
    }
    return x;
}

double JsonRules::whole(const json& v, const std::string& pointer, const Range& range, double fallback) {
    if (v.is_number() && v.get<double>() != std::floor(v.get<double>())) {
        report(Code::OutOfRange, pointer, "expected a whole number " + range.text + ", got " + v.dump());
        return fallback;
    }
    return number(v, pointer, range, fallback);
}

void JsonRules::pair(const json& v, const std::string& pointer, const Range& range, std::array<double, 2>& out, bool integer) {
    if (!v.is_array() || v.size() != 2) {
        report(Code::WrongType, pointer,
               "expected an array of two numbers " + range.text + ", got " +
                   (v.is_array() ? "an array of " + std::to_string(v.size()) : typeName(v)));
        return;
    }
    for (size_t i = 0; i < 2; ++i)
        out[i] = integer ? whole(v[i], pointerAppend(pointer, i), range, out[i]) : number(v[i], pointerAppend(pointer, i), range, out[i]);
}

TemplateRef TemplateRef::parse(const std::string& written, const std::filesystem::path& dir) {
    if (written.size() > 5 && written.ends_with(".glsl")) return {(dir / written).string(), true, written};
    return builtin(written);
}

TemplateRef JsonRules::templateRef(const json& v, const std::string& pointer) {
    std::string name = string(v, pointer);
    if (!v.is_string()) return {};
    const TemplateRef ref = TemplateRef::parse(name, dir_);
    if (ref.file) {
        // A status check, not an open: opening a FIFO would block; the plan reads the file (readFile refuses
        // what is not a regular file).
        std::error_code ec;
        if (!std::filesystem::is_regular_file(ref.name, ec))
            report(Code::TemplateUnreadable, pointer, "cannot read template file " + ref.name + ": " + whyNotRegular(ref.name));
        return ref;
    }
    std::vector<std::string> names = builtinTemplateNames();
    if (std::find(names.begin(), names.end(), name) != names.end()) return ref;
    std::string hint;
    if (auto best = closestMatch(name, names)) hint = "did you mean " + ticked(*best) + "?";
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + ticked(n);
    report(Code::UnknownTemplate, pointer,
           "unknown template \"" + name + "\"; expected a built-in template (" + list + ") or a path to a .glsl file", hint);
    return {};
}

namespace {

// A comma right before the `]` or `}` at `offset` (JSON allows no trailing comma): where it is, to report it there
// rather than at the bracket nlohmann stops on.
std::optional<size_t> trailingComma(std::string_view text, size_t offset) {
    if (offset == 0 || offset >= text.size() || (text[offset] != ']' && text[offset] != '}')) return std::nullopt;
    size_t at = text.find_last_not_of(" \t\r\n", offset - 1);
    if (at == std::string_view::npos || text[at] != ',') return std::nullopt;
    return at;
}

// nlohmann's destructor frees a document without recursion, moving its values onto a stack that it allocates: up to
// the document's every value (at most kMaxJsonValues, checked before parsing, and one for every two bytes of text: a
// value takes at least two, itself and a comma or a bracket), 16 bytes each, in a vector that holds up to 3 times that
// while it grows. A parse that runs out of memory would abort there, unwinding (exit 134). So a parse holds a reserve of
// 48 bytes a value of that bound (at most 4.8 MB), released by the new-handler when memory runs out, before the
// bad_alloc unwinds the partial document. The reserve is only allocated, never touched: it takes address space,
// not resident memory.
thread_local std::unique_ptr<char[]> parseReserve;

void releaseReserveAndFail() {
    if (!parseReserve) throw std::bad_alloc();
    parseReserve.reset();
    throw std::bad_alloc();
}

json parseWithReserve(std::string_view text) {
    static const bool installed = (std::set_new_handler(releaseReserveAndFail), true);
    (void)installed;
    parseReserve.reset(new char[48 * std::min(kMaxJsonValues, text.size() / 2 + 1)]);
    try {
        json doc = json::parse(text);
        parseReserve.reset();
        return doc;
    } catch (...) {
        parseReserve.reset();
        throw;
    }
}

}  // namespace

std::optional<json> parseJson(std::string_view text, const std::filesystem::path& file, Diagnostics* diags) {
    auto syntaxError = [&](size_t offset, std::string message) {
        TextPos p = textPosition(text, offset);
        diags->push_back(Diagnostic::make(Code::JsonSyntax, {file.string(), p.line, p.col}, "", std::move(message)));
        return std::nullopt;
    };
    if (std::optional<JsonExcess> e = excessiveShape(text, kMaxJsonValues))
        return syntaxError(
            e->offset, e->tooDeep
                           ? "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels (a material needs 5)"
                           : "JSON of more than " + std::to_string(kMaxJsonValues) + " values (a material of 16 slots holds about 600)");
    try {
        return parseWithReserve(text);
    } catch (const json::parse_error& e) {
        // nlohmann's message carries its own "[json.exception...] parse error at line L, column C: " prefix;
        // the position is recomputed from the byte offset (one past the offending character).
        const size_t offset = e.byte > 0 ? e.byte - 1 : 0;
        if (std::optional<size_t> comma = trailingComma(text, offset))
            return syntaxError(*comma, std::string("invalid JSON: a trailing comma before `") + text[offset] + "` (JSON allows none)");
        std::string what = e.what();
        if (auto colon = what.find(": ", what.find("column")); colon != std::string::npos) what = what.substr(colon + 2);
        return syntaxError(offset, "invalid JSON: " + what);
    } catch (const json::out_of_range& e) {
        // The only range error the parser raises: a number literal beyond double, e.g. 1e999.
        // nlohmann gives no offset here, so the literal is found in the text.
        std::string what = e.what();
        size_t q = what.find('\'');
        std::string literal = q == std::string::npos ? "" : what.substr(q + 1, what.rfind('\'') - q - 1);
        size_t at = literal.empty() ? 0 : text.find(literal);
        return syntaxError(at == std::string_view::npos ? 0 : at, "number " + literal + " is out of range (expected a finite number)");
    }
}

}  // namespace hexc
