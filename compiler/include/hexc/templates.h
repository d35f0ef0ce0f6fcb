#pragma once
// The shader templates and the hex-tiling library built into libhexc (templates/builtin, templates/library).
#include <string>
#include <vector>

#include "hexc/compiler.h"

namespace hexc {

// Names usable in a material's "template" key: the embedded templates that contain `#include <hexc>`.
std::vector<std::string> builtinTemplateNames();

// The text of an embedded file ("lit.glsl", "hextiling.glsl", ...), or nullptr when there is none.
const std::string* embeddedText(const std::string& fileName);

// For a caller that shows what a material's template draws (`hexc render`, `hexc preview`): an error (HX208) at the
// material's first slot when the template reads none of its slots, so that the picture would show nothing of them,
// saying what the template reads; empty when it reads one (or cannot be read: compile() reports that).
Diagnostics checkTemplateReadsSlots(const Material& material, const CompileOptions& options = {});

}  // namespace hexc
