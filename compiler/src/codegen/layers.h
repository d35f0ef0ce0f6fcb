#pragma once
// A layered material's role functions (ShaderPlan::layers -> GLSL, templates/library/layers.glsl).
#include <functional>
#include <string>

#include "codegen/codegen.h"
#include "plan/plan.h"

namespace hexc {

// The layers' functions: the weights, then hexc_<role> for each role the template reads; empty without layers.
// `read` gives a parameter's read (ShaderPlan::params index), `uv` the expression for hexc's uv from the argument uv.
std::string layerFunctions(const ShaderPlan& plan, const std::function<std::string(size_t)>& read, const std::string& uv);

// The function computing the tiles of the layers' lattice `index` (LayersPlan::lattices) by `tiles` (a `lattice.*`
// section of slots.glsl) after `settings` (its HexcLattice in general code, else empty), and the tiles the fill of the
// weights keeps for its slots (not in the functions output).
std::string layerLattice(const ShaderPlan& plan, size_t index, const std::string& tiles, const std::string& settings);

// The vertex colour's tokens (templates/library/layers.glsl): ${color}, what the weights read, and ${color_param} and
// ${color_arg}, the parameter the functions output's functions take it by and its argument (else empty).
Tokens vertexColorTokens(const ShaderPlan& plan);

// A layered slot's tiles (its ${tiles}): those the fill kept, or in the functions output its own.
std::string layerLatticeCall(const ShaderPlan& plan, size_t index);

}  // namespace hexc
