#pragma once
// MaterialX documents in and out (docs/materialx.md): a .mtlx file whose surface shader reads hex-tiled (or plain)
// images is a hexc material, and a hexc material can be written as one, for MaterialX tools to preview.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hexc/material.h"

namespace hexc {

// A .mtlx file name (any case): parseMaterial reads it as MaterialX.
bool isMaterialXFile(const std::filesystem::path& file);

// The material a MaterialX document means, validated by the same rules as JSON; diagnostics point at the
// document's elements (file:line:col and the element's name path).
// The document must hold one <surfacematerial>.
ParseResult parseMaterialX(std::string_view text, const std::filesystem::path& file);
// Every <surfacematerial> of the document, each read and validated on its own (what `hexc DOC.mtlx -o DIR` compiles);
// a problem of the whole document (XML, no material) is the only result.
std::vector<ParseResult> parseMaterialXDocument(std::string_view text, const std::filesystem::path& file);

struct MaterialXExport {
    std::optional<std::string> document;  // set only when there are no errors
    Diagnostics diagnostics;
};

// The MaterialX document of `m`, to be written at `outFile` (texture and template paths are made relative to its
// folder). Settings MaterialX has no input for are kept as hexc_* attributes, so that reading the document back
// gives the same shaders; a slot no surface shader input can carry is an error.
MaterialXExport exportMaterialX(const Material& m, const std::filesystem::path& outFile);

}  // namespace hexc
