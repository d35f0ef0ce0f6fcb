#pragma once
// A template's contract: the slots it reads and their kind, declared in comment lines
//   // hexc slot <name> <color|scalar|normal> [required]
// (docs/templates.md). A material that does not fit its template gets a diagnostic at its own slot, before
// glslang could report a type error inside a file the user may not have.
#include <string>
#include <vector>

#include "hexc/diagnostics.h"
#include "hexc/material.h"

namespace hexc {

struct TemplateSlot {
    std::string name;
    SlotKind kind = SlotKind::Color;
    bool required = false;
};

// The declared slots; a malformed declaration is an error at its line of `file`.
std::vector<TemplateSlot> readTemplateSlots(const std::string& source, const std::string& file, Diagnostics& diagnostics);

// Errors, located at the material's slots, for each slot the template reads as another kind and each required slot
// the material lacks.
Diagnostics checkTemplateFit(const std::vector<TemplateSlot>& declared, const Material& material, const std::string& templateName);

// The error (HX208, at the material's first slot) of a template that reads none of the material's slots, for a caller
// that shows what the template draws: what the template reads, and how to show the material.
Diagnostic readsNoSlot(const std::vector<TemplateSlot>& declared, const Material& material, const std::string& templateName);

}  // namespace hexc
