#pragma once
// The MaterialX nodes the reader reads as slots (docs/materialx.md): their inputs, the types MaterialX defines them
// for, the inputs hexc reads at one value only, and the nodes between an image and a shader it refuses with advice.
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace hexc::mtlx::nodes {

// The inputs each texture node may have; anything else is reported rather than dropped.
inline const std::map<std::string, std::vector<std::string>, std::less<>> kNodeInputs = {
    {"hextiledimage",
     {"file", "default", "texcoord", "tiling", "rotation", "rotationrange", "scale", "scalerange", "offset", "offsetrange", "falloff",
      "falloffcontrast", "lumacoeffs"}},
    {"hextilednormalmap",
     {"file", "default", "texcoord", "tiling", "rotation", "rotationrange", "scale", "scalerange", "offset", "offsetrange", "falloff",
      "strength", "flip_g", "normal", "tangent", "bitangent"}},
    {"image",
     {"file", "layer", "default", "texcoord", "uaddressmode", "vaddressmode", "filtertype", "framerange", "frameoffset", "frameendaction"}},
    {"tiledimage",
     {"file", "default", "texcoord", "uvtiling", "uvoffset", "realworldimagesize", "realworldtilesize", "filtertype", "framerange",
      "frameoffset", "frameendaction"}},
};

// The types MaterialX defines each node read as a slot for (libraries/stdlib/stdlib_defs.mtlx); another type has
// no nodedef, so no MaterialX tool renders it.
inline const std::map<std::string, std::vector<std::string>, std::less<>> kNodeTypes = {
    {"hextiledimage", {"color3", "color4"}},
    {"hextilednormalmap", {"vector3"}},
    {"image", {"float", "color3", "color4", "vector2", "vector3", "vector4"}},
    {"tiledimage", {"float", "color3", "color4", "vector2", "vector3", "vector4"}},
    {"normalmap", {"vector3"}},
    {"extract", {"float"}},
    {"convert", {"color3"}},
};

// Nodes that scale or tint an image by a factor, which hexc does not carry; what the refusal suggests instead.
inline const std::map<std::string, std::string_view, std::less<>> kConstantFactors = {
    {"multiply", "factor"}, {"mix", "mix"}, {"add", "sum"}, {"subtract", "difference"}, {"divide", "factor"},
};

// Inputs hexc reads only at one value (what it does: repeat, filter linearly, one image, no normal scaling); an
// empty category applies to every node.
struct Fixed {
    std::string_view category, input, value, why;
};
inline constexpr Fixed kFixed[] = {
    {"", "layer", "", "hexc reads a whole image file"},
    {"", "uaddressmode", "periodic", "hex-tiling repeats the texture"},
    {"", "vaddressmode", "periodic", "hex-tiling repeats the texture"},
    {"", "filtertype", "linear", "hexc samples with trilinear filtering"},
    {"", "framerange", "", "hexc reads one image, not a sequence"},
    {"", "frameoffset", "0", "hexc reads one image, not a sequence"},
    {"", "uvoffset", "0, 0", "hexc has no uv offset"},
    {"", "realworldimagesize", "1, 1", "hexc has no real-world units; use uvtiling"},
    {"", "realworldtilesize", "1, 1", "hexc has no real-world units; use uvtiling"},
    {"hextilednormalmap", "strength", "1", "hexc does not scale normals; the template can"},
    {"normalmap", "scale", "1", "hexc does not scale normals; the template can"},
    {"normalmap", "space", "tangent", "hexc reads tangent-space normal maps"},
};

}  // namespace hexc::mtlx::nodes
