#pragma once
// Material -> ShaderPlan: which template, which code each slot needs, where every resource and
// parameter lives. Everything later stages emit is decided here.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hexc/compiler.h"
#include "hexc/diagnostics.h"
#include "hexc/material.h"

namespace hexc {

// hexc's descriptors in the Vulkan layout (CompileOptions::layout): parameter block, one shared sampler, then one
// texture per slot in declaration order, from the layout's first binding on.
struct HexcBindings {
    uint32_t set, params, sampler, firstTexture;
    explicit HexcBindings(const ResourceLayout::Vulkan& v)
        : set(v.set), params(v.binding), sampler(v.binding + 1), firstTexture(v.binding + 2) {}
};

// A numeric setting the shader reads: a member of the HexcParams block, or (baked) a specialisation
// constant that spirv-opt freezes.
//
// Slots that share a lattice read its settings from one member, named after the first of them, and the others'
// names for it are its `aliases`: the engine sets every slot's setting by the slot's own name (`normal_tiling`),
// whatever sharing the compiler chose. One member rather than one per slot, because the lattice is shared on the
// promise that the values are equal: a second member would be a setting the shader ignores, and reading each
// slot's own member would make the lattice per slot again. An engine that wants to give such slots different
// values at run time compiles without sharing (CompileOptions::shareLattice = false).
struct ParamMember {
    std::string name;                    // "<slot>_<setting>" of the first slot that reads it
    std::vector<std::string> aliases;    // "<slot>_<setting>" of the other slots that read it: the same storage
    std::string type;                    // "float", "vec2", "int" or "ivec2"
    std::vector<double> value;           // the material's value, what an engine writes by default
    std::vector<std::string> slots;      // the slots that read it
    std::string perFrame;                // set for values the engine computes each frame: how (the manifest says it)
    uint32_t offset = 0;                 // std140 byte offset, for block members
    std::optional<uint32_t> constantId;  // set when baked: its first specialisation constant id
};

// A setting's parameter: its index in ShaderPlan::params, or none when the code does not read the setting (its
// feature is left out, or its value is specialised into the code), so the library's neutral value stands.
using ParamRef = std::optional<size_t>;

// The lattice (Listing 1 plus the tile transforms) that one or more slots share: slots with the same
// coordinates, tiling, rotation and mode evaluate it once.
struct LatticePlan {
    std::string section;     // its `lattice.*` snippet in templates/library/slots.glsl (mode and mask)
    bool rotate = true;      // the rotation code is emitted
    bool transform = false;  // per-tile transforms (ranges, steps, scale, offset amount) are emitted
    int rotationSteps = 0;   // whole numbers fixed in the code (transform only)
    std::array<int, 2> offsetSteps{0, 0};
    int maskScale = 1;    // cells per st unit of the checker and noise masks
    bool triple = false;  // the noise mask draws three noises
    // The periodic lattices (CompileOptions::periodicRepeats): K, and for the hex mask ("lattice.periodic") the integer
    // matrix P nearest K times stable mode's skew, by columns ("lattice.checker.periodic" wraps its cells instead).
    int repeats = 0;
    std::array<int, 4> period{};
    ParamRef tiling, planeSharpness, rotation, rotationRange, scaleRange, offset, originCell, originOffset;
};

struct SlotPlan {
    const Slot* slot = nullptr;  // the texture's file and facts, for derived textures; codegen and manifest read the fields below
    std::string name;            // the slot's: hexc_<name>, its texture hexcTex_<name>
    SlotKind kind = SlotKind::Color;
    bool flipY = false;            // a normal slot's green channel points down (DirectX convention)
    bool srgb = false;             // the shader decodes sRGB itself (Slot::shaderDecodes)
    std::array<double, 3> luma{};  // MaterialX mode's luma weights of a colour blend
    int channel = 0;               // the channel a scalar slot reads of its texture, or of its packed texture
    std::string texture;           // the packed texture's variable it reads instead of its own; empty when not packed
    std::string section;           // sampling snippet in templates/library/slots.glsl, e.g. "color.hex"; empty when heightOnly
    std::string coordinates;       // coordinates snippet: "uv", "uv.split" or "triplanar"
    std::string type;              // the GLSL type hexc_<slot> returns
    Projection projection = Projection::Uv;
    uint32_t binding = 0;             // texture binding (in HexcBindings::set)
    size_t lattice = 0;               // index into ShaderPlan::lattices
    bool metric = true;               // the falloff metric code is emitted (falloffcontrast != 0)
    bool gain = true;                 // the gain code is emitted (falloff != 0.5)
    int exponentInt = 0;              // > 0: the exponent is this whole number, multiplied out (no pow, no uniform)
    int gainInt = 0;                  // > 0: the gain's k = log2(1 / (1 - falloff)) is this whole number, likewise
    int taps = 3;                     // the taps setting: 3, 2 for the checker mask, 1 dithered (the .hex1 snippet)
    bool adaptive = false;            // "taps": "adaptive": each of the mask's taps behind a branch on its weight bound
    bool explicitGradients = false;   // plain sampling with the given gradients (triplanar planes: non-uniform flow)
    std::optional<size_t> heightMap;  // index into ShaderPlan::slots of the slot it height-blends by
    std::string heightMapName;        // that slot's name (its own without height blending, where it is unread)
    int heightChannel = 0;            // that slot's channel, the height the blend reads
    bool heightOnly = false;          // only the texture is used, as another slot's height map (no function, no lattice)
    bool histogram = false;           // blend histogram: its texture is the Gaussian one, and it reads a look-up table
    bool sharedLod = false;           // lod "shared": one level of detail per slot, fetches with textureLod
    std::optional<size_t> pack;       // index into ShaderPlan::packs: the slot reads that packed texture
    int packedChannel = 0;            // a packed scalar slot's channel in it (0 = r ... 3 = a); a colour slot reads rgb
    double aspect = 1;                // its texture's width / height, which tiles turn in (not in paper mode): a literal
    // A layered role's slot read through the role's 2D array texture (LayersPlan::arrays): the array's variable
    // (hexcArr_<role>) and this slot's layer in it, a constant; empty when it reads its own texture.
    std::string array;
    int arrayLayer = 0;
    // A layered slot's tiles: index into LayersPlan::lattices, whose tiles every layer and role reading that lattice
    // share (computed once per pixel and coordinate); empty when it computes its own (not layered, or not hex-tiled).
    std::optional<size_t> layerLattice;
    ParamRef falloff, falloffContrast, exponent, heightWidth;
};

// A texture hexc packs from several slots' textures (docs/material-format.md#pack). Its slots share a lattice and a
// texture size, so the shader fetches it once per tap for all of them. It is bound at its first slot's binding; the
// others' bindings stay unused, so that packing moves no other texture.
struct PackPlan {
    std::vector<size_t> slots;          // indexes into ShaderPlan::slots, in declaration order
    std::vector<std::string> channels;  // per slot, the channels of the packed texture it reads: "rgb", or one of r, g, b, a
    bool srgb = false;                  // RGB holds an sRGB colour slot: an sRGB format, whose alpha stays linear
    int width = 0, height = 0;
};

// A layered material's blend (Material::layers, docs/material-format.md#layers), as codegen emits it: per role the
// template reads, hexc_<role> blends each layer's slot by the layers' weights.
struct LayerRolePlan {
    std::string name;  // the role: hexc_<name>
    SlotKind kind = SlotKind::Color;
    std::string type;           // the GLSL type hexc_<name> returns
    std::vector<size_t> slots;  // per layer: index into ShaderPlan::slots
};
// A role's textures across layers as one 2D array texture (docs/material-format.md#texture-arrays), or why not.
struct LayerArrayPlan {
    std::string role;
    std::vector<size_t> slots;  // per layer (its layer index): index into ShaderPlan::slots
    std::string refused;        // empty: bound as one array at its first slot's binding; else why each slot has its own
    // Where the material's settings expect an array and its textures refuse it: how to get one (HX129 says it), and
    // the slot whose texture is unlike the first layer's; empty where the settings ask for separate textures.
    std::string fix;
    size_t unlike = 0;
    std::string ktx2;  // the KTX2 array file the slots read, as the material names it; empty: assembled from theirs
};
// A lattice the layers' hex-tiled slots read: a LatticePlan and a texture aspect, which decide the tiles. The fill of
// the pixel's weights computes its tiles where one of its layers is kept; its slots read them.
struct LayerLatticePlan {
    size_t slot = 0;             // the first slot reading it (index into ShaderPlan::slots), whose settings build the tiles
    std::vector<size_t> layers;  // the layers with a slot reading it, in order
};
struct LayersPlan {
    std::vector<LayerRolePlan> roles;  // those the template reads, in the layers' role order
    std::vector<size_t> splats;        // indexes into ShaderPlan::slots; layer i weighs channel i % 4 of splat i / 4
    std::vector<size_t> heights;       // height blend: per layer, the slot holding its height (else empty)
    size_t count = 0;                  // layers
    LayerBlend blend = LayerBlend::Linear;
    double width = 0.2, skipBelow = 0;  // fixed in the code, unless general (below)
    // General code (--no-specialise): width and skipBelow are parameters, as a slot's settings are, so that hexc edit
    // sets them without compiling; else none, and the code holds the values above.
    ParamRef widthParam, skipBelowParam;
    bool skip = true;  // a layer of weight 0 at a pixel is not fetched (CompileOptions::skipLayers)
    LayerWeights weights = LayerWeights::Splat;
    // Weights from the vertex colour in a shader: the location of its stage input, hexcVertexColor (the functions output
    // takes the colour as its functions' parameter instead: -1 there).
    int vertexColorLocation = -1;
    // Texture fetches per pixel of the whole material: when every layer is fetched, and averaged over the splat maps'
    // texels (a layer counts where its weight is at least skipBelow); per layer that fraction of texels. With vertex
    // weights alone the plan cannot know the mesh: every layer counts (the manifest's expected is null).
    double worstFetches = 0, expectedFetches = 0;
    std::vector<double> coverage;
    std::vector<LayerArrayPlan> arrays;      // per role the shader reads (the height role's too), in role order
    std::vector<LayerLatticePlan> lattices;  // the distinct lattices the layers' hex-tiled slots read
};

struct ShaderPlan {
    std::string materialName;
    std::string templateName;            // as shown in diagnostics: "templates/builtin/lit.glsl" or the user's path
    std::string templateShown;           // as the manifest lists it: the built-in's name as above, else as the material wrote it
    std::filesystem::path templateFile;  // the template file read; empty for a built-in template
    std::string templateSource;
    std::vector<SlotPlan> slots;  // only the slots the template reads
    // The slots (indexes into `slots`) whose histogram blend reads a look-up table: texture slots.size() + i, after
    // every slot's texture, so that materials without one keep their bindings.
    std::vector<size_t> luts;
    std::vector<PackPlan> packs;  // only with Material::pack
    ResourceLayout layout;        // where hexc's resources go on each target
    std::string entryPoint;       // the SPIR-V entry point, which HLSL and MSL keep
    HexcBindings bindings{layout.vulkan};
    std::vector<LatticePlan> lattices;
    std::vector<ParamMember> params;       // block members first, in block order, then baked constants
    std::vector<ParamMember> specialised;  // settings fixed in the code as whole-number exponents
    uint32_t paramBlockSize = 0;           // std140 size, rounded up to 16
    // --no-specialise (CompileOptions::specialise false): the slots call the library's general functions with every
    // setting in their HexcLattice and HexcBlend, rather than functions with the settings folded in (codegen).
    bool general = false;
    bool slotTexturesDecoded = false;  // CompileOptions::slotTexturesDecoded: a KTX2 array role may take a texture per slot
    bool uvBottomLeft = false;         // CompileOptions::uvOrigin: the slots' functions take OpenGL's uv (v up)
    bool functions = false;            // CompileOptions::functions: the `functions` template, every slot read
    bool exrTables = false;            // CompileOptions::exrTables: the histogram tables' files are EXR, not PFM
    FunctionArrays functionArrays = FunctionArrays::None;  // CompileOptions::functionArrays
    std::optional<LayersPlan> layers;                      // a layered material's, when the template reads a role
    Diagnostics diagnostics;                               // warnings (e.g. a slot the template never reads) or errors

    // hexc's textures, bound at firstTexture + i: each slot's, then the look-up tables.
    size_t textureCount() const { return slots.size() + luts.size(); }
    // The manifest's name of texture i: the slot's, "<slot>.packed" for the first slot of a pack, "<role>.array" for
    // an array's slots, or "<slot>.lut" (a `.` no slot name has).
    std::string textureName(size_t i) const {
        if (i >= slots.size()) return slots[luts[i - slots.size()]].slot->name + ".lut";
        if (!slots[i].array.empty()) return slots[i].array.substr(std::string_view("hexcArr_").size()) + ".array";
        return slots[i].slot->name + (slots[i].pack ? ".packed" : "");
    }
    // Whether texture i is bound: all are but the packed slots' after the first of their pack and an array's slots
    // after its first layer's.
    bool textureBound(size_t i) const {
        if (i < slots.size() && !slots[i].array.empty()) return slots[i].arrayLayer == 0;
        return i >= slots.size() || !slots[i].pack || packs[*slots[i].pack].slots.front() == i;
    }
    // Its variable in the generated GLSL: hexcTex_<slot>, hexcArr_<role> or hexcLut_<slot>.
    std::string textureVariable(size_t i) const {
        if (i < slots.size() && !slots[i].array.empty()) return slots[i].array;
        return i < slots.size() ? "hexcTex_" + slots[i].slot->name : "hexcLut_" + slots[luts[i - slots.size()]].slot->name;
    }
};

ShaderPlan planShader(const Material& material, const CompileOptions& options);

// The functions output's functions (CompileOptions::functions), in slot order: hexc_<slot>, and hexc_<slot>_normal
// after a normal slot's; for a layered material, in role order: hexc_<role>, the blend, and hexc_<role>_normal after a
// normal role's. Each takes the texture coordinate (vec2 uv).
struct EngineFunction {
    std::string name;
    const SlotPlan* slot;
    bool tangentNormal;        // hexc_<slot>_normal: a normal slot's tangent-space normal, not its derivative
    std::string role;          // a layered material's function of a role, the layers' blend (`slot`: its first layer's slot)
    bool vertexColor = false;  // it takes the vertex colour after uv (its role's layers are weighed by it)
};
std::vector<EngineFunction> engineFunctions(const ShaderPlan& plan);

// The file hexc writes a pack's texture to: "<material>.<its first slot>.packed.png".
inline std::string packedFileName(const std::string& material, const std::string& firstSlot) {
    return material + "." + firstSlot + ".packed.png";
}

}  // namespace hexc
