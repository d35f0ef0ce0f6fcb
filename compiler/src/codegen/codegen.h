#pragma once
// ShaderPlan -> Vulkan GLSL 450: the template with hexc's library, resources and per-slot functions
// injected at its `#include <hexc>` line.
#include <string>

#include "plan/plan.h"

namespace hexc {

// The returned source carries `#line` directives, so glslang reports errors at the template's own
// file and line; injected code is reported as "hexc/<file>".
std::string generateGlsl(const ShaderPlan& plan);

}  // namespace hexc
