#pragma once
// The SPIR-V stage, public because it is useful alone (the harness compiles its own shaders and the emitted
// HLSL/GLSL with it): glslang front ends (GLSL and HLSL, in process) and SPIRV-Tools validation and
// optimisation. Errors come back as diagnostics located at the file and line glslang reports.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "hexc/diagnostics.h"
#include "hexc/layout.h"

namespace hexc {

enum class ShaderStage { Vertex, Fragment };
// Glsl: Vulkan GLSL (what codegen writes). OpenGlGlsl: GLSL as emitted for OpenGL (combined samplers
// on texture units 0..N-1), brought into hexc's Vulkan layout so it can be executed and checked.
enum class SourceLanguage { Glsl, OpenGlGlsl, Hlsl };

struct SpirvResult {
    std::vector<uint32_t> words;  // empty on error
    Diagnostics diagnostics;
};

// Where HLSL registers land in Vulkan when compileToSpirv reads HLSL: b<n> at binding n, s<n> at kHlslSamplerShift + n,
// t<n> at kHlslTextureShift + n, u<n> at kHlslUavShift + n (dxc's -fvk-*-shift idea; registers below 32 of each
// class stay apart), register space N in set N.
constexpr unsigned kHlslSamplerShift = 32, kHlslTextureShift = 64, kHlslUavShift = 96;
// Where OpenGL GLSL's bindings land when compileToSpirv reads it, all in set 0: uniform block binding n at n, texture
// unit n at kGlTextureShift + n (OpenGL numbers the two apart), and the loose uniforms OpenGL has where Vulkan has
// push constants gathered in one block at kGlDefaultBlockBinding (block bindings below it stay apart).
constexpr unsigned kGlDefaultBlockBinding = 48, kGlTextureShift = 64;

// Compiles one Vulkan GLSL (or HLSL) shader to SPIR-V 1.0 for Vulkan 1.0, unoptimised. `name` labels
// the source in diagnostics when it has no #line names. HLSL registers land as above (HLSL 5.0 has no spaces: set
// `layout.hlsl.space`); OpenGL bindings as above. `entryPoint`: the HLSL function to compile, or the name a GLSL
// shader's `main` gets in the module. `debugName` non-empty: keep source lines (OpLine) for readable outputs, the
// source named `debugName` in them (where `name` may be a path only this machine has).
SpirvResult compileToSpirv(const std::string& source, ShaderStage stage, const std::string& name,
                           SourceLanguage language = SourceLanguage::Glsl, const std::string& entryPoint = "main",
                           const ResourceLayout& layout = {}, std::string_view debugName = {});

// Validates, optimises for performance and validates again. Diagnostics only on failure (a hexc bug).
// freezeConstants: specialisation constants become constants first, so the optimiser folds them.
// legalize: run the legalisation recipe first, which SPIR-V from glslang's HLSL front end needs.
// performance: the performance passes (-O's, reordered to specialise early: spirv.cpp); off (--debug), the module is only
// validated (and frozen if asked).
SpirvResult optimizeSpirv(const std::vector<uint32_t>& words, bool freezeConstants = false, bool legalize = false, bool performance = true);

// Validates a module for Vulkan 1.0 without friendly names, which cost more than the validation (quadratic in
// repeated names; glslang calls every call's temporary `param`). Empty when valid; else the validator's messages,
// from a second validation with names.
std::string validationErrors(const std::vector<uint32_t>& words);

// The words of a .spv file's bytes (a trailing partial word is dropped).
std::vector<uint32_t> spirvWords(std::string_view bytes);

// Human-readable SPIR-V, for tests and debugging.
std::string disassemble(const std::vector<uint32_t>& words);

// Per-pixel work of a shader without loops (spirv-opt inlines everything into main): every instruction
// executes at most once (a branch's, such as adaptive taps', at most). Counts come from disassemble's text.
struct ShaderOps {
    int instructions = 0;                 // inside function bodies
    int textureSamples = 0;               // OpImageSample*, OpImageFetch, OpImageGather: texture fetches per pixel
    std::map<std::string, int> extended;  // GLSL.std.450 instruction (e.g. "Pow") -> scalar operations
};
ShaderOps countOps(const std::string& disassembly);

}  // namespace hexc
