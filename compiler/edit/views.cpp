#include "views.h"

#include <cstdlib>
#include <functional>
#include <regex>
#include <stdexcept>

#include "hexc/compiler.h"
#include "hexc/files.h"
#include "hexc/templates.h"
#include "command.h"
#include "page_files.h"

namespace hexc::edit {

namespace fs = std::filesystem;

namespace {

// A section of templates/edit/views.glsl: the lines after `//@ name` up to the next section.
std::string section(const std::string& name) {
    const std::string& text = pageFiles().at("views.glsl");
    const size_t start = text.find("\n//@ " + name + "\n") + name.size() + 6;
    const size_t end = text.find("\n//@ ", start);
    return text.substr(start, end == std::string::npos ? std::string::npos : end - start + 1);
}

std::string replaced(std::string text, const std::string& token, const std::string& value) {
    for (size_t at = text.find(token); at != std::string::npos; at = text.find(token, at + value.size()))
        text.replace(at, token.size(), value);
    return text;
}

// The name of the template's colour output (`layout(location = 0) out vec4 NAME;`), or "" when it has none.
std::string colorOutput(const std::string& templateText) {
    static const std::regex output(R"(layout\s*\(\s*location\s*=\s*0\s*\)\s*out\s+(?:\w+p\s+)?vec4\s+(\w+)\s*;)");
    std::smatch m;
    return std::regex_search(templateText, m, output) ? m[1].str() : "";
}

// The template with its main renamed and the views after it, for a material's slots.
std::string composedText(const std::string& templateText, const std::string& output, const Material& m) {
    std::string slots;
    for (size_t i = 0; i < m.slots.size(); ++i)
        slots += replaced(replaced(section("slot"), "${index}", std::to_string(i)), "${name}", m.slots[i].name);
    // Layers are uv only (no triplanar projection), and every layer has the first layer's roles.
    const std::string layer = m.layers && !m.layers->roles.empty() ? replaced(section("layer"), "${role}", m.layers->roles[0].name) : "";
    const size_t firstLine = templateText.find('\n') + 1;  // the #version line, which a template starts with
    return templateText.substr(0, firstLine) + section("rename") + templateText.substr(firstLine) + "\n" +
           replaced(replaced(replaced(section("views"), "${layer}", layer), "${output}", output), "${slots}", slots);
}

}  // namespace

std::optional<std::string> templateText(const TemplateRef& templ) {
    if (templ.file) return readFile(templ.name);
    const std::string* text = embeddedText(templ.name + ".glsl");
    return text ? std::optional<std::string>(*text) : std::nullopt;
}

ViewsProgram::ViewsProgram() {
    std::string dir = (fs::temp_directory_path() / "hexc-edit-XXXXXX").string();
    if (!mkdtemp(dir.data())) throw std::runtime_error("cannot make a temporary folder in " + fs::temp_directory_path().string());
    dir_ = dir;
}

ViewsProgram::~ViewsProgram() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
}

Material ViewsProgram::composed(const Material& shown) const {
    const std::optional<std::string> text = templateText(shown.templ);
    if (!text || text->find('\n') == std::string::npos) return shown;
    const std::string output = colorOutput(*text);
    if (output.empty())
        throw CompileError{{Diagnostic::make(Code::TemplateMismatch, {shown.templ.path()}, "",
                                             "hexc edit's views write the template's colour output, and it declares none "
                                             "(`layout(location = 0) out vec4 NAME;`)")}};
    const std::string composed = composedText(*text, output, shown);
    // Named by its text: the same template and slots give the same file, and the shader cache's key stays the same.
    const std::string name = "views-" + std::to_string(std::hash<std::string>{}(composed)) + ".glsl";
    if (readFile(dir_ / name) != composed) command::writeAtomically(dir_, name, composed);
    Material m = shown;
    m.templ = {(dir_ / name).string(), true, shown.templ.written()};
    return m;
}

}  // namespace hexc::edit
