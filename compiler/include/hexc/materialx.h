#pragma once
// MaterialX documents in and out (docs/materialx.md): a .mtlx file whose surface shader reads hex-tiled (or plain)
// images is a hexc material.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "hexc/material.h"

namespace hexc {

// A .mtlx file name (any case): parseMaterial reads it as MaterialX.
bool isMaterialXFile(const std::filesystem::path& file);

// The material a MaterialX document means, validated by the same rules as JSON; diagnostics point at the
// document's elements (file:line:col and the element's name path).
ParseResult parseMaterialX(std::string_view text, const std::filesystem::path& file);

}  // namespace hexc
