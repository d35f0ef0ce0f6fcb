#pragma once
// What `hexc edit` serves about its one material: the document, its shaders compiled for the page (GLSL ES 3.00), its
// textures as uploaded, the cost of the shader as it ships, and saving. Every answer is JSON or pixels; bad input from
// the page is an answer with diagnostics, never an exception out of here.
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "hexc/cache.h"
#include "hexc/compiler.h"
#include "hexc/image.h"
#include "hexc/material.h"
#include "views.h"

namespace hexc::edit {

// An HTTP answer: its status, body and content type, and headers beside them.
struct Reply {
    int status = 200;
    std::string body;
    std::string contentType = "application/json";
    std::map<std::string, std::string> headers = {};
};

class Session {
public:
    // `material`: the JSON material edited; `root`: the folder whose files may be served (its textures must be inside).
    Session(std::filesystem::path material, std::filesystem::path root);

    // {"file", "text", "version"}: the material file as it is on disk.
    Reply material();
    // POST {"document": the material as JSON}: the document as it would be saved, parsed and compiled into the page's
    // programs (views.h's, which shows every view of every slot of "slots", and plain tiling); or its diagnostics.
    // "server": the shaders this request compiled (the rest came from the cache) and the milliseconds its parse and
    // compiles took, for the page to tell them from the transfer.
    Reply compile(const std::string& body);
    // POST {"document"}: texture fetches per pixel and SPIR-V instructions of the shader `hexc MATERIAL -o DIR` writes,
    // and the time its compile took (the first time: a structure seen before is answered from a cache of its own).
    Reply cost(const std::string& body);
    // POST {"document", "version"}: writes the document into the material file, keeping its text where unchanged; refused
    // when the file changed on disk since `version` or the document does not compile.
    Reply save(const std::string& body);
    // A texture of the last compiled document as the page uploads it, RGBA texels: a slot's ("albedo"), or the Gaussian
    // texture or look-up table its histogram blend reads ("albedo.gaussian", "albedo.lut").
    Reply texture(const std::string& name);
    // Changes whenever the material file or one of its textures does (size and modification time). Cheap: the file is
    // parsed for its textures only when its own stamp changed.
    std::string version();
    // The shaders compiled for the page so far (its cache's misses; cost() compiles apart): what its edits cost.
    size_t compiles() const { return cache_.stats().misses; }
    // Diagnostics for textures outside the served folder (or reached through a link that leaves it), located in the file.
    Diagnostics confined(const Material& material) const;

private:
    struct Parsed {
        std::string text;  // the document as it would be written
        std::optional<Material> material;
        Diagnostics diagnostics;
    };
    Parsed parse(const nlohmann::ordered_json& edited);
    std::optional<Texture> loadSlotTexture(const std::string& name, std::string* whyNot);
    CompileResult viewsCompile(const Material& m, Material* shown, std::string* note);

    std::filesystem::path file_, root_;
    std::mutex mutex_;                    // the page's requests come on several threads
    std::mutex costMutex_;                // cost() is apart: it reads only the file and the document
    ShaderCache costCache_;               // the shipped shaders of cost()
    std::map<size_t, double> costTimes_;  // their first compile's milliseconds, by a hash of the generated code
    ShaderCache cache_;
    ViewsProgram views_;
    struct ShownTemplate {
        TemplateRef templ;
        std::string note;
    };
    std::map<std::string, ShownTemplate> shownTemplates_;  // by templateKey(): what the page shows
    std::optional<Material> compiled_;                     // the last document that compiled: its textures are served
    std::mutex versionMutex_;                              // version(): the file's stamp and the textures it named then
    std::string versionFile_;
    std::vector<std::filesystem::path> versionTextures_;
};

}  // namespace hexc::edit
