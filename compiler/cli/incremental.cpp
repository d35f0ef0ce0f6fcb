#include "incremental.h"

#include <fstream>

#include "hexc/files.h"
#include "hash.h"
#include "hexc/templates.h"

namespace hexc::cli {
namespace {

// Adds a file's bytes (nothing when it cannot be read: the compile will report it).
void addFile(Fnv1a& h, const std::filesystem::path& file) { h.add(readFile(file).value_or("")); }

}  // namespace

std::vector<std::filesystem::path> inputFiles(const Material& material, const CompileOptions& options) {
    std::vector<std::filesystem::path> files{material.sourceFile};
    for (const Slot& s : material.slots) files.push_back(s.texturePath);
    std::string templ = options.templateFile.empty() ? material.templateName : options.templateFile.string();
    if (templ.ends_with(".glsl")) files.push_back(templ);
    return files;
}

std::string inputHash(const Material& material, const CompileOptions& options, const std::vector<std::filesystem::path>& extra) {
    Fnv1a h;
    h.add(version());
    // Every option that changes an output.
    std::string opts;
    for (Target t : options.targets) opts += std::string(toString(t)) + ",";
    opts += std::to_string(options.hlslShaderModel) + "," + std::to_string(options.glslVersion) + (options.glslEs ? "es," : ",") +
            std::to_string(options.mslMajor) + "." + std::to_string(options.mslMinor) + "," + std::to_string(options.specialize) +
            std::to_string(options.shareLattice) + std::to_string(options.bake);
    h.add(opts);
    // The variant's own name and slots (a scene pass restricts them; the material file alone does not say).
    h.add(material.name + "|" + material.templateName);
    for (const Slot& s : material.slots) h.add(s.name);
    for (const auto& f : inputFiles(material, options)) addFile(h, f);
    for (const auto& f : extra) addFile(h, f);
    // Built-in templates are part of the binary; hash their text too, not only the version.
    for (const std::string& f : {std::string("hextiling.glsl"), std::string("slots.glsl"), material.templateName + ".glsl"})
        if (const std::string* text = embeddedText(f)) h.add(*text);
    return h.hex();
}

std::string stampName(const std::string& name) { return "." + name + ".hexc-stamp"; }

std::string stampText(const std::string& hash, const std::vector<std::string>& outputs) {
    std::string text = hash + "\n";
    for (const auto& o : outputs) text += o + "\n";
    return text;
}

bool upToDate(const std::filesystem::path& dir, const std::string& name, const std::string& hash) {
    std::ifstream in(dir / stampName(name));
    std::string line;
    if (!std::getline(in, line) || line != hash) return false;
    while (std::getline(in, line))
        if (!std::filesystem::exists(dir / line)) return false;
    return true;
}

}  // namespace hexc::cli
