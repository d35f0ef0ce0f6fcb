#include "common/templates.h"

#include <sstream>

#include "common/embedded.h"

namespace hexc {

std::vector<std::string> builtinTemplateNames() {
    std::vector<std::string> names;
    for (const auto& [name, text] : embeddedTemplates())
        if (text.find("\n#include <hexc>") != std::string::npos) names.push_back(name.substr(0, name.size() - 5));  // drop ".glsl"
    return names;
}

const std::string* embeddedText(const std::string& fileName) {
    auto it = embeddedTemplates().find(fileName);
    return it == embeddedTemplates().end() ? nullptr : &it->second;
}

std::map<std::string, std::string> snippetSections(const std::string& fileName) {
    std::map<std::string, std::string> sections;
    std::istringstream in(*embeddedText(fileName));  // only hexc's own snippet files
    std::string line, current;
    while (std::getline(in, line)) {
        if (line.rfind("//@ ", 0) == 0) {
            current = line.substr(4);
            sections[current];
        } else if (!current.empty()) {
            sections[current] += line + "\n";
        }
    }
    // Trailing blank lines separate sections in the file; they are not part of the snippet.
    for (auto& [name, text] : sections)
        while (text.size() >= 2 && text.ends_with("\n\n")) text.pop_back();
    return sections;
}

}  // namespace hexc
