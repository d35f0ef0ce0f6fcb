#pragma once
// The JSON material parser itself, for the MaterialX reader, which builds the JSON a document means and validates
// it here, so both formats follow one set of rules.
#include <filesystem>
#include <string_view>

#include "hexc/material.h"

namespace hexc {

// parseMaterial for JSON text, whatever the file's name.
ParseResult parseMaterialJson(std::string_view text, const std::filesystem::path& file);

}  // namespace hexc
