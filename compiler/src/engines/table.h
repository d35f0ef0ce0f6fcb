#pragma once
// The engine table: one row per engine package (docs/engines.md), everything the engine layer knows of an engine.
// Each package is written from a compile's typed results (compile.h), never from text hexc wrote and read back.
// docs/internals.md, "Adding an engine", says what a new row needs.
#include <string>
#include <vector>

#include "compile.h"
#include "hexc/engines.h"
#include "plan/plan.h"

namespace spirv_cross {
class CompilerGLSL;
}  // namespace spirv_cross

namespace hexc {

inline constexpr size_t kEngineCount = size_t(kLastEngine) + 1;

// The language of the functions a package holds.
enum class EngineLanguage {
    Glsl330,    // Godot's shading language and Filament's .mat take GLSL 330's functions, in their dialect
    GlslEs300,  // WebGL 2's
    Hlsl,       // Shader Graph's and Unreal's Custom nodes
    Wgsl,       // three.js's WebGPURenderer (its node system's wgslFn)
};

// A texture the functions read, as every package binds it: the manifest's name ("<slot>", "<slot>.packed",
// "<slot>.lut", "<role>.array"), its GLSL uniform, whether its sampler decodes sRGB (docs/bind-a-manifest.md, step 3),
// and the slot, pack or layered role's array whose texture it is, or the slot whose histogram table it is.
struct EngineTexture {
    std::string name, uniform;
    bool srgb = false;
    const SlotPlan* slot = nullptr;
    const PackPlan* pack = nullptr;
    const SlotPlan* table = nullptr;
    const LayerArrayPlan* array = nullptr;
};

struct EngineRow;

// What a package is written from: the compile of the material's functions in the engine's language.
struct PackageInput {
    const Material& material;
    const EngineRow& engine;
    const CompiledMaterial& compiled;
    const CompileOptions& options;          // the compile's: the engine's language (packageOptions)
    std::vector<EngineFunction> functions;  // in the manifest's order
    std::vector<EngineTexture> textures;    // bound, in name order
};

// hexc --uv-bottom-left: the mesh's uv (0, 0) is the image's bottom-left.
inline bool bottomLeft(const PackageInput& input) { return input.options.uvOrigin == UvOrigin::BottomLeft; }

struct EngineRow {
    Engine engine;
    const char* name;   // --engine, the package's folder
    const char* shown;  // as messages name it
    EngineLanguage language;
    // The engine's templates (compiler/integrations/<engine>/, embedded) and the package file each becomes,
    // <material><suffix>; the first holds the functions (the manifest's targets name it).
    std::vector<std::pair<const char*, const char*>> files;
    bool uvBottomLeft;    // the engine's own uv origin is the image's bottom-left (OpenGL's)
    bool copiesTextures;  // the package holds copies of the slots' textures (a browser loads them beside the module)
    bool unrollLoops;     // its language has no arrays to copy or pass and only its own form of `for` (Godot 3)
    bool wgsl;            // --targets wgsl is taken (Babylon.js adds WGSL functions for WebGPU); else refused (HX300)
    // The package's own files, named without the "<engine>/" folder; a slot no input takes is a warning in
    // `diagnostics`, a texture the engine cannot load an error.
    std::vector<OutputFile> (*write)(const PackageInput& input, Diagnostics& diagnostics);
    // The layered roles whose textures its package assembles into one 2D array texture where a shader would read one
    // (CompileOptions::functionArrays); the others it binds a texture per slot.
    FunctionArrays arrays = FunctionArrays::None;
};

const EngineRow& engineRow(Engine engine);

// The writers of the three families of packages.
std::vector<OutputFile> glslPackage(const PackageInput& input, Diagnostics& diagnostics);  // engines/glsl.cpp
std::vector<OutputFile> webPackage(const PackageInput& input, Diagnostics& diagnostics);   // engines/web.cpp
std::vector<OutputFile> hlslPackage(const PackageInput& input, Diagnostics& diagnostics);  // engines/hlsl.cpp

// The functions as compile() cuts them from the whole module, printed by `c` (a compiler of the compile's SPIR-V whose
// subclass writes the engine's dialect) in the compile's GLSL version (engines/glsl.cpp).
std::string glslFunctions(spirv_cross::CompilerGLSL& c, const PackageInput& input);

// A slot's texture as a web package holds it: <material>.<slot>.<the file's extension>, beside the module.
std::string textureCopyName(const Material& material, const Slot& slot);

// Whether the package's functions take the vertex colour (a layered material's roles weighed by it).
bool takesVertexColor(const PackageInput& input);

// The slots whose files a texture is loaded from: its slot's, or a layered role's array's layers' in layer order.
std::vector<const SlotPlan*> loadedSlots(const ShaderPlan& plan, const EngineTexture& t);

}  // namespace hexc
