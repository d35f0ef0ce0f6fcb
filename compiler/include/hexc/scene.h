#pragma once
// A scene: the materials a game level uses and the passes it renders them in. hexc compiles only the
// (material, pass) variants the scene uses, each specialised to the slots its pass reads.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hexc/diagnostics.h"
#include "hexc/material.h"

namespace hexc {

struct ScenePass {
    std::string name;                                   // identifier; variant files are "<material>.<pass>.*"
    std::optional<TemplateRef> templ;                   // unset: each material's own template
    std::optional<std::vector<std::string>> slots;      // the slots the pass reads; unset: all
    std::optional<std::vector<std::string>> materials;  // the materials it renders (by name); unset: all
};

struct Scene {
    std::string name;
    std::filesystem::path sourceFile;
    std::vector<Material> materials;  // parsed, in the scene's order
    std::vector<ScenePass> passes;
};

struct SceneParseResult {
    std::optional<Scene> scene;
    Diagnostics diagnostics;
};

// A JSON document with a top-level "scene" key is a scene, otherwise a material.
bool isSceneDocument(std::string_view text);

// Parses a scene and every material it lists (paths relative to the scene file), with located diagnostics.
SceneParseResult parseSceneFile(const std::filesystem::path& file);
// The same on text already read; `file` locates diagnostics and resolves the scene's material paths.
SceneParseResult parseScene(std::string_view text, const std::filesystem::path& file);

// One (material, pass) pair the scene renders: the material restricted to the pass's slots and template.
struct Variant {
    std::string name;  // "<material>.<pass>"
    std::string materialName, passName;
    Material material;  // named after the variant, so its outputs are "<material>.<pass>.*"
};

std::vector<Variant> sceneVariants(const Scene& scene);

}  // namespace hexc
