#pragma once
// Two rewrites of how a module's functions read its textures, for the HLSL engines' packages (engines/hlsl.cpp):
// Shader Graph's and Unreal's Custom nodes pass textures into a function, and Unity stores a texture's bottom row first.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace hexc {

// A module whose functions take the textures they read as parameters, and which those are.
struct TextureParameters {
    std::vector<uint32_t> words;
    // Each function given parameters, by name (without glslang's signature, "hexc_albedo"), and the names of the
    // texture variables it takes, in their declaration order.
    std::map<std::string, std::vector<std::string>> textures;
};

// The module with each function but the entry points taking every UniformConstant variable (texture, sampler) it
// reads, itself or through a function it calls, as a parameter after its own, named as the variable; each call passes
// them on. SPIRV-Cross then writes the textures as the functions' parameters, not as globals. std::runtime_error on a
// hexc bug (a module that does not parse, or an invalid result).
TextureParameters texturesAsParameters(const std::vector<uint32_t>& words);

// The module with every texture sample at (s, -t), its gradients' t negated, and every texel fetch of row y at row
// h - 1 - y: what a shader written for textures whose top row is at t = 0 reads from an engine that stores the bottom
// row first (exact with repeat wrapping: row r of the image is row h - 1 - r of the storage, and -t wraps to 1 - t). A
// read it cannot flip so (a gather, an offset, a projective or depth-compare sample) is a std::runtime_error.
std::vector<uint32_t> flipRows(const std::vector<uint32_t>& words);

}  // namespace hexc
