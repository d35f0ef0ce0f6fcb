#pragma once
// ShaderPlan -> Vulkan GLSL 450: the template with hexc's library, resources and per-slot functions
// injected at its `#include <hexc>` line.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "plan/plan.h"

namespace hexc {

// The values of a snippet's `${name}` tokens.
using Tokens = std::map<std::string, std::string>;

// `text` (the snippet `section` of templates/library/slots.glsl) with each `${name}` token replaced by its value, in
// one pass (a value is never scanned again). A token without a value is a hexc bug: CompileError, naming the section.
std::string expandTokens(const std::string& text, const Tokens& values, const std::string& section);

// Snippet `section` of a library file's `sections` (snippetSections), expanded, without its final newline.
std::string expandSection(const std::map<std::string, std::string>& sections, const std::string& section, const Tokens& values);

// A GLSL float literal that reads back as the same float32.
std::string floatLiteral(double v);

// The returned source carries `#line` directives, so glslang reports errors at the template's own
// file and line; injected code is reported as "hexc/<file>".
std::string generateGlsl(const ShaderPlan& plan);

// templates/library/entry.glsl with hextiling.glsl at its `#include <hexc/hextiling.glsl>`: a shader that calls every public
// function of the library, which `hexc library` emits (backends/library.cpp).
std::string generateLibraryGlsl();

// A fragment shader input: what the pass-through vertex stage writes.
struct Varying {
    std::string name, type;  // GLSL type, e.g. "vec2"
    uint32_t location = 0;
};

// The pass-through vertex stage (templates/library/vertex.glsl) that feeds `inputs` (in location order) from vertex
// attributes 1, 2, ..., the clip-space position being attribute 0.
std::string generateVertexGlsl(const std::vector<Varying>& inputs);

}  // namespace hexc
