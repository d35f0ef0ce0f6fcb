// `hexc library`: entry.glsl (every public function of hextiling.glsl, called once) through glslang and each
// target's SPIRV-Cross without optimisation; the text from the entry point on and the lines of its resources (hexcLib*)
// are cut, which leaves the types, constants and functions: an include file.
#include "hexc/library.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <string_view>
#include <utility>

#include "backends/backends.h"
#include "codegen/codegen.h"
#include "common/text.h"
#include "hexc/templates.h"
#include "hexc/spirv.h"

namespace hexc {
namespace {

// `source` up to the line that starts with `entry`, without the lines naming the entry's resources or `#version`.
std::string cutEntry(const std::string& source, const std::string& entry) {
    std::istringstream in(source);
    std::string out, line;
    while (std::getline(in, line) && !line.starts_with(entry))
        if (line.find("hexcLib") == std::string::npos && !line.starts_with("#version")) out += line + "\n";
    while (out.ends_with("\n\n")) out.pop_back();
    return out;
}

// A settings struct's documentation in hextiling.glsl: the comment above it, and per field its comment and the
// value its neutral constructor (`X hexcX() { return X(...); }`) gives.
struct StructDoc {
    std::string above;
    std::map<std::string, std::string> fields;  // name -> "= default; comment"
};

// The arguments of `call`'s outermost parentheses, each without leading blanks: `vec2(-180.0, 180.0)` is one.
std::vector<std::string> arguments(std::string_view call) {
    std::vector<std::string> out(1);
    int depth = 0;
    for (char c : call.substr(call.find('(') + 1, call.rfind(')') - call.find('(') - 1)) {
        depth += c == '(' ? 1 : c == ')' ? -1 : 0;
        if (depth == 0 && c == ',')
            out.emplace_back();
        else if (c != ' ' || !out.back().empty())
            out.back() += c;
    }
    return out;
}

// The neutral values of struct `name`, in field order: the arguments of `return name(...);` on the line after
// `name hexc...() {`.
std::vector<std::string> neutralValues(const std::string& glsl, const std::string& name) {
    for (size_t at = glsl.find(name + " hexc"); at != std::string::npos; at = glsl.find(name + " hexc", at + 1)) {
        size_t end = at + name.size() + 5;
        while (end < glsl.size() && isIdentifierChar(glsl[end])) ++end;
        if (glsl.compare(end, 5, "() {\n") != 0) continue;
        const size_t line = end + 5, close = glsl.find('\n', line);
        const std::string_view body = trimmedStart(std::string_view(glsl).substr(line, close - line));
        if (body.starts_with("return " + name + "(") && body.ends_with(");")) return arguments(body.substr(7 + name.size()));
    }
    return {};
}

// A field line, `type name; // comment`: its name and comment ("" when the line is no field).
std::pair<std::string, std::string> field(std::string_view line) {
    line = trimmedStart(line);
    const size_t space = line.find(' '), semicolon = line.find(';');
    if (space == 0 || space == std::string_view::npos || semicolon == std::string_view::npos || semicolon < space) return {};
    const std::string_view type = line.substr(0, space), name = line.substr(space + 1, semicolon - space - 1);
    const auto word = [](std::string_view w) { return !w.empty() && std::all_of(w.begin(), w.end(), isIdentifierChar); };
    std::string_view rest = trimmedStart(line.substr(semicolon + 1));
    if (!word(type) || !word(name) || (!rest.empty() && !rest.starts_with("//"))) return {};
    return {std::string(name), std::string(rest.empty() ? rest : trimmedStart(rest.substr(2)))};
}

std::map<std::string, StructDoc> structDocs(const std::string& glsl) {
    std::map<std::string, StructDoc> docs;
    std::istringstream in(glsl);
    std::string above;  // the comment lines just read
    for (std::string line; std::getline(in, line);) {
        const size_t brace = line.find(" {");
        if (!line.starts_with("struct ") || brace == std::string::npos || brace + 2 != line.size()) {
            above = line.starts_with("//") ? above + line + "\n" : "";
            continue;
        }
        const std::string structName = line.substr(7, brace - 7);
        StructDoc& doc = docs[structName];
        doc.above = std::exchange(above, "");
        const std::vector<std::string> defaults = neutralValues(glsl, structName);
        size_t index = 0;
        while (std::getline(in, line) && !line.starts_with("};")) {
            const auto [name, comment] = field(line);
            if (name.empty()) continue;
            const std::string value = index < defaults.size() ? "= " + defaults[index] : "";
            doc.fields[name] = value + (!comment.empty() && !value.empty() ? "; " : "") + comment;
            ++index;
        }
    }
    return docs;
}

// The member a line of a struct declares: `type name;` (MSL: `name [[attribute]];`), or WGSL's `name: type,`.
std::string memberName(std::string_view line) {
    if (line.ends_with(";")) {
        line.remove_suffix(1);
        if (line.ends_with("]]") && line.rfind("[[") != std::string_view::npos && line.find(']', line.rfind("[[")) == line.size() - 2) {
            line = line.substr(0, line.rfind("[["));
            while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.remove_suffix(1);
        }
        size_t start = line.size();
        while (start > 0 && isIdentifierChar(line[start - 1])) --start;
        return std::string(line.substr(start));
    }
    const std::string_view trimmed = trimmedStart(line);
    const size_t colon = trimmed.find(": ");
    if (!line.ends_with(",") || colon == 0 || colon == std::string_view::npos) return "";
    const std::string_view name = trimmed.substr(0, colon);
    return std::all_of(name.begin(), name.end(), isIdentifierChar) ? std::string(name) : "";
}

// The emitted library with hextiling.glsl's documentation of each struct put back (SPIRV-Cross keeps no comments): the
// comment above it, and each field's default and meaning, so that a hand-written shader knows what it leaves on.
std::string documented(const std::string& emittedText, const std::string& glsl) {
    const std::map<std::string, StructDoc> docs = structDocs(glsl);
    std::istringstream in(emittedText);
    std::string out, line;
    const StructDoc* inside = nullptr;
    while (std::getline(in, line)) {
        if (line.starts_with("struct ")) {
            auto doc = docs.find(line.substr(7, line.find_first_of(" {", 7) - 7));  // WGSL: `struct Name {`
            inside = doc == docs.end() ? nullptr : &doc->second;
            if (inside) out += inside->above;
        } else if (line.starts_with("};")) {
            inside = nullptr;
        }
        const std::string name = memberName(line);
        if (inside && inside->fields.count(name) && !inside->fields.at(name).empty()) line += "  // " + inside->fields.at(name);
        out += line + "\n";
    }
    return out;
}

}  // namespace

std::vector<OutputFile> hexcLibrary(const std::vector<Target>& targets) {
    SpirvResult front = compileToSpirv(generateLibraryGlsl(), ShaderStage::Fragment, "hexc/entry.glsl");
    SpirvResult checked = front.words.empty() ? front : optimizeSpirv(front.words, false, false, false);
    if (checked.words.empty()) throw CompileError{checked.diagnostics};  // hexc's own code: a bug
    std::vector<OutputFile> files;
    for (Target target : targets) {
        const TargetRow& row = targetRow(target);
        const char* comment = row.binary ? "; " : "// ";  // a binary target's library is its assembly
        std::string banner =
            std::string(comment) + "Generated by hexc " + version() + ": its hex-tiling library (docs/library.md), from\n" + comment +
            "templates/library/hextiling/ (its parts, joined in order) through glslang and " + row.translator + ". Do not edit.\n";
        std::string text = row.library(checked.words);
        if (!row.binary) text = documented(cutEntry(text, row.entryLine), *embeddedText("hextiling.glsl"));
        files.push_back({std::string("hexc_hextiling.") + row.libraryExtension, banner + text});
    }
    return files;
}

std::optional<Target> libraryTargetNamed(std::string_view name) {
    for (const TargetRow& row : targetRows())
        if (row.libraryName && (name == row.libraryName || (*row.alias && name == row.alias))) return row.target;
    return std::nullopt;
}

std::vector<std::string> libraryTargetNames() {
    std::vector<std::string> names;
    for (const TargetRow& row : targetRows())
        if (row.libraryName) names.push_back(row.libraryName);
    return names;
}

}  // namespace hexc
