#include "incremental.h"

#include <algorithm>
#include <fstream>

#include "hexc/files.h"
#include "hexc/cache.h"
#include "hexc/engines.h"
#include "hexc/hash.h"
#include "hexc/image.h"
#include "hexc/templates.h"

namespace hexc::cli {
namespace {

// Adds a file's bytes (nothing when it cannot be read: the compile will report it).
void addFile(ContentHash& h, const std::filesystem::path& file) { h.add(readFile(file).value_or("")); }

// Whether the compile reads slot `i`'s texels, not only its size: a histogram slot's derived textures are made from
// its pixels, and so is a packed texture (whose alpha a colour slot's opaque texels leave free); a layered material's
// splat maps give the manifest's expected fetches per pixel; the web engines' packages copy every texture.
bool texelsRead(const Material& material, size_t i, bool copied) {
    const bool splat =
        material.layers && std::find(material.layers->splats.begin(), material.layers->splats.end(), i) != material.layers->splats.end();
    return material.slots[i].hex.blend == Blend::Histogram || material.pack || copied || splat;
}

// Everything a texture's header says (TextureInfo), as one key.
std::string headerKey(const TextureInfo& t) {
    return std::to_string(t.width) + "x" + std::to_string(t.height) + "x" + std::to_string(t.layers) + "," + t.channelNames + "," +
           std::to_string(t.channels) + "," + std::to_string(t.mipLevels) + "," + (t.srgb ? (*t.srgb ? "srgb" : "linear") : "-") + "," +
           t.format + (t.eightBit ? ",8" : ",f");
}

}  // namespace

std::vector<std::filesystem::path> inputFiles(const Material& material, const CompileOptions& options) {
    std::vector<std::filesystem::path> files{material.sourceFile};
    for (const Slot& s : material.slots) files.push_back(s.texturePath);
    if (const TemplateRef t = effectiveTemplate(material, options); t.file) files.push_back(t.name);
    if (!options.layout.sourceFile.empty()) files.push_back(options.layout.sourceFile);
    return files;
}

std::string inputHash(const Material& material, const CompileOptions& options, const std::vector<std::string>& engines,
                      const std::vector<std::filesystem::path>& extra) {
    ContentHash h;
    h.add(version());
    h.add(buildId());
    h.add(toolchainVersions());  // also in the executable's bytes, unless a library is ever linked dynamically
    // Every option that changes an output.
    h.add(codeOptionsKey(options) + "," + std::to_string(options.specialise) + std::to_string(options.shareLattice) + "," +
          toString(options.layout) + "," + options.entryPoint + (options.vertex ? ",vertex" : "") +
          (options.emitGenerated ? ",generated" : "") + (options.manifestPathsFrom.empty() ? "" : ",paths"));
    for (const std::string& e : engines) h.add("engine " + e);
    // The variant's own name and slots (a scene pass restricts them; the material file alone does not say).
    h.add(material.name + "|" + material.templ.path());
    // The banner names the material file; --manifest-paths gives where every input was (the stamp's folder is the
    // output folder they are relative to).
    h.add(material.sourceFile.filename().string());
    if (!options.manifestPathsFrom.empty())
        for (const std::filesystem::path& f : inputFiles(material, options))
            h.add(std::filesystem::absolute(f).lexically_normal().string());
    // Of most textures the compile reads only what the header says (size, channels, format, colour space, a KTX2
    // array's layers: the manifest and whether a role's textures make one array follow them): new pixels leave the
    // outputs as they are. Where it reads the texels (texelsRead), their bytes count.
    const bool copied = std::any_of(engines.begin(), engines.end(), [](const std::string& e) {
        const std::optional<Engine> engine = engineNamed(e);
        return engine && isWebEngine(*engine);
    });
    for (size_t i = 0; i < material.slots.size(); ++i) {
        const Slot& s = material.slots[i];
        h.add(s.name + "|" + (s.file ? headerKey(s.file->info) : std::to_string(s.width) + "x" + std::to_string(s.height)));
        if (texelsRead(material, i, copied)) h.add(s.file ? s.file->bytes : "");  // as the parser read them
    }
    addFile(h, material.sourceFile);
    if (const TemplateRef t = effectiveTemplate(material, options); t.file) addFile(h, t.name);
    for (const auto& f : extra) addFile(h, f);
    // Built-in templates are part of the binary; hash their text too, not only the version.
    for (const std::string& f : {std::string("hextiling.glsl"), std::string("slots.glsl"), material.templ.name + ".glsl"})
        if (const std::string* text = embeddedText(f)) h.add(*text);
    return h.hex();
}

std::string stampName(const std::string& name) { return "." + name + ".hexc-stamp"; }

namespace {

// A stamp: its hash line, one line per output (its name, a tab, the hash of what it holds), and a seal: the hash of
// the lines above it. A stamp whose seal
// does not match (a list cut short or edited, a file from elsewhere) is not trusted, as if there were none: the
// material compiles again and writes every output. Only plain names (a file in the folder) are ever read from one.
std::string stampSeal(const std::vector<std::string>& lines) {
    ContentHash h;
    h.add("hexc stamp");
    for (const std::string& line : lines) h.add(line);
    return "seal " + h.hex();
}

}  // namespace

// An output's line in a stamp: its name and the hash of its bytes, so that a file another build replaced (a shared
// folder, two builds at once) is seen as not this stamp's.
std::string outputLine(const std::string& name, std::string_view contents) {
    ContentHash h;
    h.add(contents);
    return name + "\t" + h.hex();
}

std::string stampText(const std::string& hash, const std::vector<OutputFile>& outputs) {
    std::vector<std::string> lines{hash};
    for (const OutputFile& f : outputs) lines.push_back(outputLine(f.name, f.contents));
    std::string text;
    for (const auto& line : lines) text += line + "\n";
    return text + stampSeal(lines) + "\n";
}

namespace {

bool plainName(const std::string& name) {
    return !name.empty() && name != "." && name != ".." && name.find_first_of(std::string("/\0", 2)) == std::string::npos;
}

// A trusted stamp's hash line and output lines; empty for none, or one that is not trusted.
std::vector<std::string> stampLines(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    if (lines.size() < 2 || lines.back() != stampSeal({lines.begin(), lines.end() - 1})) return {};
    lines.pop_back();
    if (!std::all_of(lines.begin() + 1, lines.end(), [](const std::string& l) { return plainName(l.substr(0, l.find('\t'))); })) return {};
    return lines;
}

// The outputs a trusted stamp lists, by name.
std::vector<std::string> stampedNames(const std::filesystem::path& file) {
    std::vector<std::string> lines = stampLines(file), names;
    for (size_t i = 1; i < lines.size(); ++i) names.push_back(lines[i].substr(0, lines[i].find('\t')));
    return names;
}

}  // namespace

bool upToDate(const std::filesystem::path& dir, const std::string& name, const std::string& hash) {
    std::vector<std::string> lines = stampLines(dir / stampName(name));
    if (lines.empty() || lines[0] != hash) return false;
    return std::all_of(lines.begin() + 1, lines.end(), [&](const std::string& line) {
        const std::string output = line.substr(0, line.find('\t'));
        const std::optional<std::string> contents = readFile(dir / output);
        return contents && outputLine(output, *contents) == line;
    });
}

std::vector<std::string> stampedOutputs(const std::filesystem::path& dir, const std::string& name) {
    return stampedNames(dir / stampName(name));
}

void removeStaleOutputs(const std::filesystem::path& dir, const std::set<std::string>& before) {
    std::set<std::string> live;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
        const std::string file = entry.path().filename().string();
        if (!file.starts_with(".") || !file.ends_with(".hexc-stamp")) continue;
        for (std::string& o : stampedNames(entry.path())) live.insert(std::move(o));
    }
    for (const std::string& name : before)
        if (!live.contains(name) && std::filesystem::is_regular_file(dir / name, ec))  // plain names: from stampLines
            std::filesystem::remove(dir / name, ec);
}

}  // namespace hexc::cli
