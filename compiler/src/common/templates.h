#pragma once
// Access to the shader templates and GLSL snippets in templates/, embedded at build time.
#include <map>
#include <string>
#include <vector>

namespace hexc {

// Names usable in a material's "template" key: the embedded templates that contain `#include <hexc>`.
std::vector<std::string> builtinTemplateNames();

// The text of an embedded file ("lit.glsl", "hextiling.glsl", ...); throws std::out_of_range if absent.
const std::string& embeddedText(const std::string& fileName);

// Sections of a snippet file, split at lines `//@ <name>`; each section's text runs to the next marker.
std::map<std::string, std::string> snippetSections(const std::string& fileName);

}  // namespace hexc
