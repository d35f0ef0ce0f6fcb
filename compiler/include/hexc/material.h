#pragma once
// The material model: what a material JSON file means once parsed, validated and defaulted.
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hexc/diagnostics.h"

namespace hexc {

enum class SlotKind { Color, Scalar, Normal };
inline constexpr size_t kSlotKindCount = 3;
enum class ColorSpace { Srgb, Linear };

// What the code asks of a slot kind, one row per kind (kindRow; the table, in SlotKind order, is in
// material/names.cpp): code asks a property here, not which kind it is, so a new kind is a new row.
struct SlotKindRow {
    SlotKind kind;
    const char* name;       // as a material, a template and the manifest spell it
    const char* glslType;   // what its slot function returns (a triplanar derivative slot: a vec3 surface gradient)
    const char* mtlxType;   // its value's MaterialX type
    const char* reads;      // the texture channels it reads, as the manifest's `reads`; "" for a one-channel kind
    ColorSpace colorSpace;  // its default colour space
    // Samples a tangent-space normal map on the derivative path: blends slopes, takes `flip_y`, is linear only, and
    // engines take its normal function.
    bool derivative;
    // Reads the one channel its `channel` names: a scalar value, shown as grey; it can hold heights.
    bool oneChannel;
    bool mayPack;          // may share a packed texture with other slots (docs/material-format.md#pack)
    bool mayUseHistogram;  // may blend by histogram (docs/material-format.md#blend)
    // The kind it is read like: whose snippets (templates/library/slots.glsl's `<kind>.*` sections) it takes, and the
    // HEXC_FIRST_KIND_<kind> a template sees. Itself, or a kind with snippets of its own and the same GLSL type.
    SlotKind like;
};
const SlotKindRow& kindRow(SlotKind kind);
// Every row, in SlotKind order.
const std::array<SlotKindRow, kSlotKindCount>& kindRows();
// How tile offsets and rotations are derived from the lattice ids. `Stable` (the default): an integer
// hash of exactly reduced lattice ids, identical on every target and precise far from the origin
// (templates/library/hextiling/, docs/material-format.md). `Paper`: exactly Listings 1, 2, 5 and 6.
// `MaterialX`: MaterialX 1.39's hextiledimage and hextilednormalmap (templates/library/materialx.glsl,
// docs/materialx.md).
enum class HashMode { Stable, Paper, MaterialX };
// What decides the blend weights (docs/material-format.md#mask): the paper's hex lattice (3 taps), two offset
// square grids (2 taps), or three globally transformed copies under one or three value noises (3 taps).
enum class Mask { Hex, Checker, Noise, Noise3 };
// Where a slot's texture coordinate comes from: the mesh uv, or world position and normal on three planes.
enum class Projection { Uv, Triplanar };
// How a colour or scalar slot blends its tiles' samples (docs/material-format.md#blend): the paper's weighted average
// under its luminance falloff, or Heitz and Neyret's histogram-preserving blend of a transformed texture hexc derives.
enum class Blend { Falloff, Histogram };
// How a hex-tiled slot's fetches pick their mip level (docs/material-format.md#lod): each with its tile's rotated
// gradients (the sampler's own level and anisotropy), or one level of detail per slot computed in the shader and
// passed to every fetch (textureLod: cheaper, isotropic).
enum class Lod { Gradients, Shared };

// Hex-tiling settings, in two parts: what decides the lattice and what decides the blend. Names follow MaterialX
// <hextiledimage> where the meaning is the same; the paper's symbol is given for each. Each part compares every
// member (`= default`), so a setting added to it cannot be left out where slots are told apart by it.

// The lattice (Listing 1 and the per-tile transforms): slots whose lattice settings are equal share one
// (ShaderPlan::lattices) and may share a packed texture.
struct LatticeSettings {
    bool enabled = true;                 // false: plain tiling (one fetch), for comparison or cheap slots
    std::array<double, 2> tiling{1, 1};  // UV scale applied before the lattice (MaterialX `tiling`)
    double rotation = 1.0;               // rotStrength of Listings 3, 4, 6 (MaterialX `rotation`)
    HashMode mode = HashMode::Stable;
    Mask mask = Mask::Hex;
    int maskScale = 2;                       // checker and noise masks: cells per unit of st
    Projection projection = Projection::Uv;  // material-wide
    double planeSharpness = 4;               // triplanar: exponent on |normal| per plane
    // Stable mode only: the slot also reads an origin (cell, offset) that the engine fills each frame from a
    // double-precision origin, for worlds whose uv exceed what float32 resolves (docs/precision.md).
    bool splitCoordinates = false;
    // Per-tile transforms (stable mode; docs/material-format.md#per-tile-transforms).
    std::array<double, 2> rotationRange{-180, 180};  // degrees the tile angle is drawn from (times `rotation`)
    int rotationSteps = 0;                           // > 0: that many evenly spaced angles in the range
    std::array<double, 2> scaleRange{1, 1};          // texture scale drawn per tile
    double offset = 1.0;                             // amount of the random offset
    std::array<int, 2> offsetSteps{0, 0};            // > 0: offsets snapped to a grid of that many cells
    int maskTaps() const { return mask == Mask::Checker ? 2 : 3; }
    bool hasTransforms() const {
        return rotationRange != std::array<double, 2>{-180, 180} || rotationSteps != 0 || scaleRange != std::array<double, 2>{1, 1} ||
               offset != 1.0 || offsetSteps != std::array<int, 2>{0, 0};
    }
    bool operator==(const LatticeSettings&) const = default;
};

// How a slot fetches and weighs its tiles' samples on that lattice.
struct BlendSettings {
    double falloff = 0.5;          // r of Eq. 5 / Listing 8 gain; 0.5 = off (MaterialX `falloff`)
    double falloffcontrast = 0.6;  // beta of Eq. 3-4 (MaterialX `falloffcontrast`)
    double exponent = 7.0;         // gamma, exponent on the barycentric weights (Eq. 1)
    int taps = 0;  // 0: every tap of the mask, blended; 1: one dithered fetch; kAdaptiveTaps: each tap fetched when it can matter
    Blend blend = Blend::Falloff;  // normal slots always blend derivatives (Falloff)
    Lod lod = Lod::Gradients;
    // MaterialX mode: the luma weights of its colour blend (MaterialX `lumacoeffs`; its default, ACEScg's).
    std::array<double, 3> lumacoeffs{0.2722287, 0.6740818, 0.0536895};
    // `"taps": "adaptive"` (docs/material-format.md#taps): a tap is skipped when a bound on its weight, known before
    // sampling, shows it cannot move the result by more than kAdaptiveError.
    static constexpr int kAdaptiveTaps = -1;
    static constexpr double kAdaptiveError = 1.0 / 255;
    bool adaptive() const { return taps == kAdaptiveTaps; }
    bool operator==(const BlendSettings&) const = default;
};

// A slot's (or the material's) settings: both parts, their members read as `hex.tiling`, `hex.falloff`.
struct HexTiling : LatticeSettings, BlendSettings {
    const LatticeSettings& lattice() const { return *this; }
    const BlendSettings& blending() const { return *this; }
};

// Height blending (docs/material-format.md#height-blending): tiles weighed by the heights of a scalar slot.
struct HeightBlend {
    std::string slot;    // a scalar slot of the same material, possibly this one
    double width = 0.2;  // transition width, in (0, 1]
};

struct TextureFile;  // hexc/image.h

struct Slot {
    std::string name;                   // GLSL identifier; used in generated function and resource names
    std::string texture;                // as written in the JSON
    std::filesystem::path texturePath;  // resolved against the material file's folder
    SlotKind kind = SlotKind::Color;
    int channel = 0;  // scalar slots: 0..3 for r, g, b, a
    ColorSpace colorSpace = ColorSpace::Srgb;
    bool flipY = false;  // normal slots: green channel points down (DirectX convention)
    std::string role;    // the engine input it fills (docs/engines.md#slots-and-engine-inputs); empty: as its name says
    HexTiling hex;       // material settings with this slot's overrides applied
    std::optional<HeightBlend> heightBlend;
    int width = 0, height = 0;  // of the texture file
    std::string channelNames;   // the texture file's channels, from its header (TextureInfo::channelNames)
    bool eightBit = false;      // the file decodes to 8-bit texels (TextureInfo::eightBit)
    // `lint_skip`: the texture checks ("green", "tilt", "seam") whose warnings this slot does not report (docs/lint.md).
    std::vector<std::string> lintSkip;
    int textureLayer = 0;  // `layer`: the layer of a KTX2 array file this slot reads (a layered material's); 0 otherwise
    // The texture file as the parser read it, the compile's one read of it (its bytes, its header); null when the
    // slot is built in code or its texture could not be read.
    std::shared_ptr<const TextureFile> file;
    int line = 0, col = 0;   // where the slot's kind (else the slot) is in the material file; 0 when built in code
    bool kindStated = true;  // false in a partial material whose kind is not one hexc knows: not checked against a template

    // Whether the texture is bound as sRGB (the sampler decodes, filtering decoded texels). Not in MaterialX mode
    // (hex-tiled or plain), which filters and blends the stored (encoded) texels and decodes the result, as MaterialX
    // does: there the shader decodes, and the manifest says so (`"decode": "shader"`, docs/materialx.md#materialx-mode).
    bool samplerDecodes() const { return colorSpace == ColorSpace::Srgb && !shaderDecodes(); }
    bool shaderDecodes() const { return colorSpace == ColorSpace::Srgb && !kindRow(kind).derivative && hex.mode == HashMode::MaterialX; }
};

// A shader template as a material, a scene pass or --template names it, told apart once, where it is read: one of
// hexc's built-in templates (embedded; its source is templates/builtin/<name>.glsl) or a .glsl file of the user's.
struct TemplateRef {
    std::string name = "lit";  // a built-in's name, or the file's path resolved against the naming document's folder
    bool file = false;
    std::string asWritten;  // a file as the document names it (the manifest shows it so); empty for a built-in
    // How diagnostics, banners and #line directives name it: a built-in by its source's path in hexc
    // ("templates/builtin/lit.glsl"), a file by its resolved path.
    std::string path() const { return file ? name : "templates/builtin/" + name + ".glsl"; }
    // As a user named it: a built-in's name, a file as written.
    const std::string& written() const { return file ? asWritten : name; }
    // `written` as a document or command line gives it: a name ending in .glsl is a file, resolved against `dir`;
    // anything else a built-in's name (which the caller checks).
    static TemplateRef parse(const std::string& written, const std::filesystem::path& dir = {});
    static TemplateRef builtin(std::string name) { return {std::move(name), false, {}}; }
};

// Layers (docs/material-format.md#layers): sets of slots with the same roles (albedo, normal, ...), blended per role by
// weights painted in splat maps. Each layer's slot is an ordinary slot of the material named <layer>_<role>; the template
// reads the blend as hexc_<role>.
enum class LayerBlend { Linear, Height };
// Where the layers' weights come from: the splat maps, the vertex colour (channel i weighs layer i, so at most four
// layers), or their product per layer.
enum class LayerWeights { Splat, Vertex, Both };
struct Layers {
    struct Role {
        std::string name;  // hexc_<name> reads the blend
        SlotKind kind = SlotKind::Color;
        // A KTX2 array every layer's slot of the role reads at its own layer (docs/material-format.md#ktx2-arrays): the
        // file as written and where layer 0's slot names it; empty when each slot has its own file.
        std::string ktx2Array, ktx2ArrayPointer;
    };
    struct Layer {
        std::string name;
        std::vector<size_t> slots;  // per role (in `roles` order): its index in Material::slots
    };
    std::vector<Role> roles;     // in the first layer's order
    std::vector<Layer> layers;   // layer i's weight is channel i % 4 of splat map i / 4
    std::vector<size_t> splats;  // Material::slots indexes of the splat maps (linear, plain tiled, tiling 1)
    LayerWeights weights = LayerWeights::Splat;
    LayerBlend blend = LayerBlend::Linear;
    std::optional<size_t> heightRole;  // LayerBlend::Height: the scalar role holding each layer's height
    double width = 0.2;                // height blend: transition width in height units, in (0, 1]
    // A layer whose splat weight is below this is not fetched; the others are renormalised. 0.5/255: half an 8-bit step.
    double skipBelow = 0.5 / 255;
    // `arrays` "auto": a role's layer textures that one sampler can read alike are bound as one 2D array texture
    // (docs/material-format.md#texture-arrays); "off": one texture per slot.
    bool arrays = true;
    static constexpr size_t kMaxLayers = 8;
    static constexpr size_t kMaxVertexLayers = 4;  // one vec4 of vertex colour
};

// 16 = Vulkan's minimum guaranteed maxPerStageDescriptorSampledImages: a material's slots, a layer's slots and the
// textures a shader binds (a role's texture array once) are each held to it.
inline constexpr size_t kMaxTextures = 16;

struct Material {
    std::string name;   // output file stem
    TemplateRef templ;  // the built-in `lit` unless the material names another
    std::filesystem::path sourceFile;
    HexTiling hex;            // material-level settings (slots may override)
    std::vector<Slot> slots;  // in declaration order; binding order follows it
    // Channel packing (docs/material-format.md#pack): slots with the same lattice share one texture hexc writes.
    bool pack = false;
    std::optional<Layers> layers;
};

struct ParseResult {
    std::optional<Material> material;  // set only when there are no errors
    Diagnostics diagnostics;
    // With errors: what could be read, for the checks that need only its slots' names and kinds and its template
    // (checkTemplate in hexc/compiler.h), so that a run reports the template's problems beside the material's.
    std::optional<Material> partial;
};

// Parses and validates a material: JSON, or a MaterialX document when `file` ends in .mtlx (hexc/materialx.h).
// `file` names the document in diagnostics and anchors relative texture and template paths. Never throws on bad
// input.
ParseResult parseMaterial(std::string_view text, const std::filesystem::path& file);
ParseResult parseMaterialFile(const std::filesystem::path& file);

std::string_view toString(SlotKind kind);
std::string_view toString(ColorSpace space);
std::string_view toString(HashMode mode);
std::string_view toString(Mask mask);
std::string_view toString(Projection projection);
std::string_view toString(Blend blend);
std::string_view toString(Lod lod);
std::string_view toString(LayerBlend blend);
std::string_view toString(LayerWeights weights);

}  // namespace hexc
