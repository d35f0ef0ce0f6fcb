#pragma once
// A layered material's role functions (ShaderPlan::layers -> GLSL, templates/library/layers.glsl).
#include <functional>
#include <string>

#include "plan/plan.h"

namespace hexc {

// The layers' functions: the weights, then hexc_<role> for each role the template reads; empty without layers.
// `read` gives a parameter's read (ShaderPlan::params index), `uv` the expression for hexc's uv from the argument uv.
std::string layerFunctions(const ShaderPlan& plan, const std::function<std::string(size_t)>& read, const std::string& uv);

}  // namespace hexc
