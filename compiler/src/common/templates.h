#pragma once
// Snippet files among the embedded templates (see hexc/templates.h for the public part).
#include <map>
#include <string>

#include "hexc/templates.h"

namespace hexc {

// Sections of an embedded snippet file, split at lines `//@ <name>`; each section's text runs to the next marker.
std::map<std::string, std::string> snippetSections(const std::string& fileName);

}  // namespace hexc
