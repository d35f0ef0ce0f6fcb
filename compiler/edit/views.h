#pragma once
// The page's views of a material in one program: the material's template, its `main` renamed, and
// templates/edit/views.glsl's `main` after it, which draws the template's shading, or a slot's values or weights, as two
// specialisation constants say. The page links each view from the one fragment shader (page/view.js), so a structural
// edit costs one compile for all of them, and showing another view or slot costs none.
#include <filesystem>
#include <optional>
#include <string>

#include "hexc/material.h"

namespace hexc::edit {

// The text of a material's template (a built-in's or a file's), or nullopt when it cannot be read (a compile says why).
std::optional<std::string> templateText(const TemplateRef& templ);

class ViewsProgram {
public:
    ViewsProgram();   // makes a folder of its own for the composed templates
    ~ViewsProgram();  // and removes it
    ViewsProgram(const ViewsProgram&) = delete;
    ViewsProgram& operator=(const ViewsProgram&) = delete;

    // `shown` under its template with the views appended, written into the folder (the manifest still names the
    // template as the material wrote it). A template that cannot be read is left as it is, for the compile to report;
    // one without a `vec4` output at location 0, which the views write, is a CompileError.
    Material composed(const Material& shown) const;

private:
    std::filesystem::path dir_;
};

}  // namespace hexc::edit
