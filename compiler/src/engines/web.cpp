#include "engines/web.h"

#include <algorithm>
#include <map>
#include <sstream>

#include "common/templates.h"
#include "engines/roles.h"
#include "hexc/image.h"
#include "hexc/suggest.h"

namespace hexc {
namespace {

struct WebEngine {
    Engine engine;
    const char* shown;               // as messages name it
    const char* suffix;              // its module is <material>.<suffix>.js, its template package.<suffix>.js
    std::vector<std::string> roles;  // the roles (engines/roles.h) its template gives an input
};

const std::vector<WebEngine>& webEngines() {
    static const std::vector<WebEngine> engines = {
        {Engine::Threejs, "three.js", "three", {"albedo", "ao", "emission", "metallic", "normal", "roughness"}},
        {Engine::Babylon, "Babylon.js", "babylon", {"albedo", "normal", "roughness"}},
    };
    return engines;
}

const WebEngine& webEngine(Engine engine) {
    return *std::find_if(webEngines().begin(), webEngines().end(), [&](const WebEngine& e) { return e.engine == engine; });
}

const Slot& slotNamed(const Material& material, const std::string& name) {
    return *std::find_if(material.slots.begin(), material.slots.end(), [&](const Slot& s) { return s.name == name; });
}

std::string moduleName(const Material& material, const WebEngine& web) { return material.name + "." + web.suffix + ".js"; }

// The browser decodes the textures (an Image element): PNG, JPEG or WebP, 8 bits per channel.
bool browserImage(const std::filesystem::path& file) {
    const std::string extension = lowerCase(file.extension().string());
    return extension == ".png" || extension == ".jpg" || extension == ".jpeg" || extension == ".webp";
}

Diagnostic unloadable(const Material& material, const WebEngine& web, const std::string& what) {
    return Diagnostic::make(
        Code::TargetUnsupported, {material.sourceFile.string()}, "",
        std::string(web.shown) + " packages load textures with the browser's image decoder (PNG, JPEG or WebP): " + what);
}

// Each texture the functions read, as the module loads it: its file beside the module, its sampler uniform, its
// colour space as the sampler decodes it, as the manifest says (samplerDecodesSrgb).
nlohmann::json textures(const Material& material, const WebEngine& web, const nlohmann::json& manifest, Diagnostics& diagnostics) {
    std::map<std::string, nlohmann::json> packed;
    for (const auto& p : manifest.value("packed_textures", nlohmann::json::array())) packed[p["name"]] = p;
    const std::set<std::string> srgb = samplerDecodesSrgb(manifest);
    nlohmann::json out = nlohmann::json::array();
    for (const auto& [name, where] : manifest["targets"]["glsl"]["textures"].items()) {
        if (name.ends_with(".lut")) {
            diagnostics.push_back(
                unloadable(material, web,
                           "the histogram blend's tables are float (slot `" + name.substr(0, name.size() - 4) + "`; blend it by falloff)"));
            continue;
        }
        const bool isPacked = packed.count(name) > 0;
        const Slot* slot = isPacked ? nullptr : &slotNamed(material, name);
        if (slot && !browserImage(slot->texturePath))
            diagnostics.push_back(
                unloadable(material, web, "slot `" + slot->name + "` reads `" + slot->texturePath.filename().string() + "`"));
        out.push_back({{"file", isPacked ? packed[name]["file"].get<std::string>() : textureCopyName(material, *slot)},
                       {"uniform", where["uniform"]},
                       {"colorspace", srgb.count(name) ? "srgb" : "linear"}});
    }
    return out;
}

// The uniform of the texture a slot reads: its own, or the packed texture that holds it.
std::string uniformOf(const std::string& slot, const nlohmann::json& manifest) {
    const nlohmann::json& where = manifest["targets"]["glsl"]["textures"];
    if (where.contains(slot)) return where[slot]["uniform"];
    for (const auto& p : manifest.value("packed_textures", nlohmann::json::array()))
        if (p["slots"].contains(slot)) return where[p["name"].get<std::string>()]["uniform"];
    return "";  // a slot that reads no texture of its own (none does today)
}

// The functions output without its precision statements: each declaration carries its own, and a default precision
// statement would change the engine's own code after it.
std::string withoutPrecision(const std::string& glsl) {
    std::istringstream in(glsl);
    std::string out, line;
    while (std::getline(in, line))
        if (!line.starts_with("precision ")) out += line + "\n";
    return out;
}

// The slots the engine fills (name, role, the call of their function with UV for the uv, their texture's uniform),
// and those it has no input for: a role the engine lacks, or a second slot of one role (each input takes one slot).
void wire(const Material& material, const WebEngine& web, const nlohmann::json& manifest, nlohmann::json& data, Diagnostics& diagnostics) {
    data["slots"] = data["unmapped"] = nlohmann::json::array();
    for (const auto& f : manifest["functions"]) {
        const Slot& slot = slotNamed(material, f["slot"]);
        if (kindRow(slot.kind).derivative && f["returns"] != "vec3") continue;  // the derivative: the engine takes the normal
        const std::string role = slotRole(slot);
        const bool taken =
            std::any_of(data["slots"].begin(), data["slots"].end(), [&](const nlohmann::json& s) { return s["role"] == role; });
        if (taken || std::find(web.roles.begin(), web.roles.end(), role) == web.roles.end()) {
            data["unmapped"].push_back(slot.name);
            diagnostics.push_back(unusedSlot(material, slot, web.shown, f["name"]));
            continue;
        }
        data["slots"].push_back({{"name", slot.name},
                                 {"role", role},
                                 {"call", f["name"].get<std::string>() + "(UV)"},
                                 {"uniform", uniformOf(slot.name, manifest)}});
    }
}

}  // namespace

std::string textureCopyName(const Material& material, const Slot& slot) {
    return material.name + "." + slot.name + slot.texturePath.extension().string();
}

bool isWebEngine(Engine engine) {
    return std::any_of(webEngines().begin(), webEngines().end(), [&](const WebEngine& e) { return e.engine == engine; });
}

std::vector<std::string> webPackageNames(const Material& material, Engine engine, const std::vector<const Slot*>& copied) {
    std::vector<std::string> names = {moduleName(material, webEngine(engine))};
    for (const Slot* slot : copied) names.push_back(textureCopyName(material, *slot));
    return names;
}

std::vector<OutputFile> webPackage(const Material& material, Engine engine, const nlohmann::json& manifest, const WebFunctions& functions,
                                   bool uvBottomLeft, Diagnostics& diagnostics) {
    const WebEngine& web = webEngine(engine);
    nlohmann::json data = {{"material", material.name},
                           {"uv_origin", toString(uvBottomLeft ? UvOrigin::BottomLeft : UvOrigin::TopLeft)},
                           {"glsl", withoutPrecision(functions.glsl)},
                           {"textures", textures(material, web, manifest, diagnostics)}};
    if (functions.wgsl) data["wgsl"] = *functions.wgsl;
    wire(material, web, manifest, data, diagnostics);
    const std::string templ = std::string("package.") + web.suffix + ".js", marker = "/* hexc:data */ null";
    std::string module = *embeddedText(templ);
    module.replace(module.find(marker), marker.size(), data.dump(2));
    std::vector<OutputFile> files = {{moduleName(material, web), std::move(module)}};
    for (const auto& t : data["textures"]) {
        const std::string file = t["file"];
        const auto slot =
            std::find_if(material.slots.begin(), material.slots.end(), [&](const Slot& s) { return textureCopyName(material, s) == file; });
        if (slot == material.slots.end()) continue;  // a packed texture, written by the compile
        files.push_back({file, slot->file->bytes});  // the bytes the parser read
    }
    return files;
}

}  // namespace hexc
