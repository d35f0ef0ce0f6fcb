#pragma once
// The shader templates and the hex-tiling library built into libhexc (templates/builtin, templates/library).
#include <string>
#include <vector>

namespace hexc {

// Names usable in a material's "template" key: the embedded templates that contain `#include <hexc>`.
std::vector<std::string> builtinTemplateNames();

// The text of an embedded file ("lit.glsl", "hextiling.glsl", ...), or nullptr when there is none.
const std::string* embeddedText(const std::string& fileName);

}  // namespace hexc
