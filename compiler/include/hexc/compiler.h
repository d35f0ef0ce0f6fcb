#pragma once
// libhexc's entry point: a validated Material in, shader sources, SPIR-V and a manifest out.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hexc/diagnostics.h"
#include "hexc/layout.h"
#include "hexc/material.h"

namespace hexc {

class ShaderCache;

// One row each in the target table (backends/targets.cpp), in this order.
enum class Target { Spirv, Hlsl, Glsl, Msl, Wgsl };
inline constexpr size_t kTargetCount = 5;
std::string_view toString(Target target);
// The --targets names in target order, those a compile writes when it names none (and a functions compile, which has
// no binary form: those of them that are source), and the target a name or an alias (`metal`) names.
std::vector<std::string> targetNames();
std::vector<Target> defaultTargets();
std::vector<Target> defaultFunctionsTargets();
std::optional<Target> targetNamed(std::string_view name);
std::string_view targetAlias(Target target);  // "" for none

// Where the engine's texture coordinates put uv (0, 0) (docs/conventions.md). hexc's own convention is the top-left
// texel with v down the image; with BottomLeft (OpenGL's, v up) hexc samples at (u, 1 - v) itself.
enum class UvOrigin { TopLeft, BottomLeft };

std::string_view toString(UvOrigin origin);  // "top-left", "bottom-left"

// How often --debug's text outputs carry a `#line` (CompileOptions::lineDirectives), like Slang's -line-directive-mode.
enum class LineDirectives { None, Functions, Statements };

std::string_view toString(LineDirectives mode);  // "none", "functions", "statements"

// Which layered roles the functions output reads as one array texture (CompileOptions::functionArrays).
enum class FunctionArrays { None, Linear, All };

struct CompileOptions {
    std::vector<Target> targets = defaultTargets();
    std::filesystem::path templateFile;  // overrides the material's template when set (--template)
    uint32_t hlslShaderModel = 50;       // 50, 51, 60 ... 66
    uint32_t glslVersion = 450;          // 330, 450, 460 (desktop) or 300, 310 with glslEs
    bool glslEs = false;
    uint32_t mslMajor = 2, mslMinor = 0;
    // Emit only the code each slot's settings need (no rotation at rotation 0, no gain at falloff 0.5, no
    // falloff metric at falloffcontrast 0). Off: every feature is emitted and the uniforms decide at run time.
    bool specialise = true;
    // Slots with the same tiling, rotation and mode evaluate the lattice once.
    bool shareLattice = true;
    // Numeric settings become specialisation constants, frozen by spirv-opt so it can fold them, instead of
    // uniforms (one shader then serves one material only). Per-frame values stay uniforms.
    bool bake = false;
    // > 0: the lattice of stable-mode slots with the hex or checker mask is periodic over K = periodicRepeats units of
    // st (`hexc bake`, docs/cli.md#hexc-bake): the hex skew rounded to an integer matrix over K, tile ids wrapped. Not
    // `bake` above, which folds settings into code. Other slots are left as they are; `hexc bake` refuses them.
    int periodicRepeats = 0;
    // A layered material's layer of weight 0 at a pixel is not fetched (its slots' taps sit in a branch). Off: every
    // layer is fetched at every pixel, as naive per-layer hex-tiling does (the same image; the bench's baseline).
    bool skipLayers = true;
    // The consumer binds each slot's own texture and decodes a KTX2 array's layer itself (hexc edit's page): a role
    // read from a KTX2 array that the shader cannot read as one array takes a texture per slot, where an engine,
    // which loads the file as it is, gets HX128 (docs/material-format.md#ktx2-arrays).
    bool slotTexturesDecoded = false;
    // Write the textures hexc derives from the slots' (the histogram blend's Gaussian texture and look-up table, packed
    // scalar maps). Off: the shaders and the manifest only, which still names them (hexc edit's page, which is served
    // those textures apart, and its cost: computing them for a 2048 x 2048 texture takes seconds and 48 MB).
    bool derivedTextures = true;
    // The histogram blend's derived float textures as OpenEXR files (RGBA) instead of PFM (RGB): what engines import
    // (Godot, Unity and Unreal read EXR, none reads PFM); engine packages set it (hexc/engines.h).
    bool exrTables = false;
    // Check each slot's texture's content (hexc/lint.h) and report what fails as warnings (HX130-HX133). Off: hexc edit,
    // which compiles at every change, and whose textures `hexc lint` checks.
    bool lintTextures = true;
    ResourceLayout layout;  // where hexc's own resources go on each target
    // The fragment entry point on every target but OpenGL GLSL (always `main`); empty: defaultEntryPoint(material).
    std::string entryPoint;
    UvOrigin uvOrigin = UvOrigin::TopLeft;
    // Engine-ready functions instead of a shader (docs/engines.md): the material's specialised function per slot,
    // hexc_<slot>(uv) and for a normal slot also hexc_<slot>_normal(uv), with the resources they read declared, no
    // main and no stage inputs or outputs: "<material>.functions.{hlsl,glsl,metal}" (no SPIR-V target). The template
    // is the built-in `functions`.
    bool functions = false;
    // Every loop unrolled and the arrays it indexes made scalars (spirv/unroll.h): for an engine language with no array
    // copies, no array parameters and only `for` loops of its own form (Godot 3's; hexc/engines.h sets it).
    bool unrollLoops = false;
    // Which layered roles the functions output reads as one 2D array texture where a shader would
    // (docs/material-format.md#texture-arrays), for an engine package that assembles the array from the slots' files
    // (hexc/engines.h sets it): none (a texture per slot, as every engine can bind), the roles bound linear only (an
    // engine without sRGB array textures: Babylon.js), or all (three.js).
    FunctionArrays functionArrays = FunctionArrays::None;
    // Also emit the pass-through vertex stage that feeds the fragment shader's inputs ("<material>.vert.*").
    bool vertex = false;
    // Readable outputs (like glslc/dxc -O0): no optimisation, so hexc's functions keep their names, and #line
    // directives back to the template and library where the target has them. Not for shipping: slower.
    bool debug = false;
    // With debug, how often HLSL, GLSL and MSL say where their code came from (`#line`): never, at the start of each
    // function (hexc's functions, the template's), or before each statement, as the SPIR-V's OpLine always do.
    LineDirectives lineDirectives = LineDirectives::Functions;
    // Also write the generated Vulkan GLSL fed to glslang, "<material>.generated.frag" (glslangValidator reads it).
    bool emitGenerated = false;
    // When set (the output folder): the manifest's "source" gives the material file, its textures, a template file and
    // the layout file relative to it. Off by default, so that outputs do not depend on where they are built.
    std::filesystem::path manifestPathsFrom;
    // Shader code compiled before (by this or another process, see cache.h) is taken from here, and new code stored;
    // outputs are the same with or without. Not owned; null: compile everything.
    ShaderCache* cache = nullptr;
    // Emit the HLSL, GLSL and MSL targets at once, each on a thread, when the machine has more than one core; the
    // outputs are the same either way. A caller that already compiles several materials at once (the command line
    // does) turns it off, so as not to run more threads than cores.
    bool concurrentTargets = true;
};

struct OutputFile {
    std::string name;      // file name only, e.g. "rock.frag.hlsl"
    std::string contents;  // bytes (SPIR-V is binary)
};

struct CompileResult {
    std::vector<OutputFile> files;  // every requested target plus "<name>.manifest.json"
    Diagnostics diagnostics;        // warnings, or the errors that stopped compilation
    std::string glsl;               // the generated Vulkan GLSL fed to glslang (for debugging)
    std::vector<uint32_t> spirv;    // optimised SPIR-V
    bool ok() const { return !hasErrors(diagnostics); }
};

// Never throws on bad input: problems (template errors included) come back as diagnostics.
CompileResult compile(const Material& material, const CompileOptions& options = {});

// The names of the files compile() writes for `material` with `options`, sorted, found by planning it only (no shader
// is compiled): for a build system that declares every output before it runs hexc (hexc --list-outputs). Empty with
// the errors when the plan fails. The histogram tables and packed textures depend on the template (the slots it reads)
// and a pack on its textures' pixels (an opaque colour texture leaves alpha free).
struct OutputNames {
    std::vector<std::string> names;
    Diagnostics diagnostics;
};
OutputNames outputNames(const Material& material, const CompileOptions& options = {});

// The template a compile of `material` uses: --template's file (CompileOptions::templateFile), else the material's.
TemplateRef effectiveTemplate(const Material& material, const CompileOptions& options);

// The template's own problems and how the material fits it (the slots it declares and their kinds), without compiling:
// compile() reports them too, and a caller whose material has errors (ParseResult::partial) reports them beside those.
Diagnostics checkTemplate(const Material& material, const CompileOptions& options = {});

const char* version();

// A shader source without the two banner lines compile() writes on top (after GLSL's #version line), which name
// the material: two materials' identical code differs there only.
std::string withoutBanner(std::string source);

// The options that change what glslang, spirv-opt and SPIRV-Cross make of the generated GLSL, in one line for keys
// (the shader cache's, the stamps'): the targets, HLSL shader model, GLSL and MSL versions, --bake, --debug,
// --functions and the uv origin; with the wgsl target, the naga-wasm package and driver that translate it.
std::string codeOptionsKey(const CompileOptions& options);

// The shader tool chain hexc is built with, one per line: "glslang 12.0.0", "SPIRV-Tools v2022.4 ...",
// "SPIRV-Cross 1.3.239.0+dfsg1-1" (the Debian package's version; SPIRV-Cross has no version of its own).
std::string toolchainVersions();

// `<material>_frag`, with characters an identifier cannot hold (a scene variant's `.`, `-`) as `_`, so that
// materials and scene variants can share one library (a metallib, an HLSL effect) without a clash.
std::string defaultEntryPoint(std::string_view material);

// Whether `name` can be an entry point on every target: an identifier, not reserved by GLSL (`gl_`) or a language.
bool isEntryPointName(std::string_view name);

// The file a material's shader for `target` is written to: "<material>.frag.<its extension>"; its vertex
// stage's (CompileOptions::vertex), "<material>.vert.*".
std::string shaderFileName(std::string_view material, Target target, std::string_view stage = "frag");

}  // namespace hexc
