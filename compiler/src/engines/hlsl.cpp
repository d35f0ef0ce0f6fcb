// The HLSL engines' packages (Unity, Unreal; docs/engines.md): the functions' HLSL with each function taking the
// textures it reads as parameters (Shader Graph's and Unreal's Custom nodes pass textures in; neither lets an include
// file declare global ones), inside the engine's templates (compiler/integrations/unity/, unreal/). The functions are
// SPIRV-Cross's HLSL of the compile's SPIR-V, rewritten first (spirv/textures.h): each texture with a sampler of its own
// (as both engines give one), passed as a parameter, and for Unity read at (s, -t). No text hexc wrote is read back.
#include <spirv_hlsl.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <stdexcept>

#include "backends/backends.h"
#include "codegen/codegen.h"
#include "common/templates.h"
#include "engines/roles.h"
#include "engines/table.h"
#include "spirv/combined.h"
#include "spirv/textures.h"

namespace hexc {
namespace {

// How an engine passes a texture into a function: Unity a texture and sampler it declares (sampler_<name>, the URP
// shader's), Unreal a Texture Object input and the sampler its Custom node names <input>Sampler. {T}: the texture's name.
struct Style {
    Engine engine;
    std::string args;
    bool rowsBottomFirst;  // the engine stores a texture's bottom row first (Unity): every read flips its row
};

const Style& style(Engine engine) {
    static const Style unity = {Engine::Unity, "{T}, sampler_{T}", true};
    static const Style unreal = {Engine::Unreal, "{T}, {T}Sampler", false};
    switch (engine) {  // an engine of the family without its case: -Wswitch, and a std::logic_error
        case Engine::Unity:
            return unity;
        case Engine::Unreal:
            return unreal;
        case Engine::Godot3:
        case Engine::Godot4:
        case Engine::Filament:
        case Engine::Threejs:
        case Engine::Babylon:
        case Engine::ThreejsWebgpu:
            break;
    }
    throw std::logic_error("the " + std::string(toString(engine)) + " package has no HLSL style (engines/hlsl.cpp)");
}

std::string named(std::string pattern, const std::string& texture) {
    for (size_t at; (at = pattern.find("{T}")) != std::string::npos;) pattern.replace(at, 3, texture);
    return pattern;
}

// SPIRV-Cross's HLSL of the functions without global resources: their textures are parameters.
class EngineHlsl : public spirv_cross::CompilerHLSL {
public:
    using CompilerHLSL::CompilerHLSL;

protected:
    void emit_uniform(const spirv_cross::SPIRVariable&) override {}
};

// The functions' HLSL, which textures each function takes (by name, in parameter order), all of them (in the
// manifest's order) and which are 2D array textures.
struct Functions {
    std::string text;
    std::map<std::string, std::vector<std::string>> textures;
    std::vector<std::string> all;
    std::set<std::string> arrays;
};

Functions functions(const PackageInput& in, const Style& s) {
    const ShaderPlan& plan = in.compiled.plan;
    std::vector<uint32_t> words = combineSamplers(in.compiled.result.spirv, plan);
    if (s.rowsBottomFirst) words = flipRows(words);
    TextureParameters p = texturesAsParameters(words);
    EngineHlsl c(p.words);
    configureHlsl(c, in.options);
    Functions f{functionsOnly(c.compile(), Target::Hlsl, plan.entryPoint), std::move(p.textures), {}, {}};
    for (const EngineTexture& t : in.textures) {
        if (t.array) f.arrays.insert(t.uniform);
        if (std::any_of(f.textures.begin(), f.textures.end(),
                        [&](const auto& fn) { return std::find(fn.second.begin(), fn.second.end(), t.uniform) != fn.second.end(); }))
            f.all.push_back(t.uniform);
    }
    return f;
}

// `texts` each as `pattern` says, joined by commas.
std::string joined(const std::vector<std::string>& texts, const std::string& pattern) {
    std::string out;
    for (const std::string& t : texts) out += (out.empty() ? "" : ", ") + named(pattern, t);
    return out;
}

std::string hlslType(const std::string& glsl) { return glsl == "float" ? "float" : "float" + glsl.substr(3); }

std::string guard(const std::string& name) {
    std::string out;
    for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) ? char(std::toupper(static_cast<unsigned char>(c))) : '_';
    return out;
}

// What the templates' tokens take from the functions, one line per function or texture.
struct Lines {
    std::string nodes, wrappers, properties, textures, surface;
};

// A texture in Unity's Shader Graph and URP shader, per kind ([0] 2D, [1] array): the Custom Function port, the entry
// point's parameter type and argument, the Properties entry's type and default, the declaration macro; and in Unreal's
// Custom node header, what follows the input's name.
struct Kind {
    const char *port, *param, *arg, *property, *declare, *unrealInput;
};
constexpr std::array<Kind, 2> kKinds = {{
    {"Texture 2D", "UnityTexture2D", "{T}.tex, {T}.samplerstate", "2D) = \"white\" {}", "TEXTURE2D", ""},
    {"Texture 2D Array", "UnityTexture2DArray", "{T}.tex, {T}.samplerstate", "2DArray) = \"\" {}", "TEXTURE2D_ARRAY", " (Texture2DArray)"},
}};

// One function's lines: its Custom node (Unity: the ports; Unreal: the pin, output type, inputs and code), Unity's
// node entry point, and the URP statement of the input its role fills ("" when it fills none). A function that takes the
// vertex colour has a Color input after UV (a Vertex Color node in Shader Graph, a VertexColor node in Unreal; the URP
// shader's own: input.color).
void addFunction(Lines& l, const Style& s, const Functions& f, const WiredFunction& w, const std::string& returns, const std::string& uv) {
    const std::string& name = w.function.name;
    const std::vector<std::string>& textures = f.textures.count(name) ? f.textures.at(name) : std::vector<std::string>{};
    const std::string type = hlslType(returns), width = returns == "float" ? "1" : returns.substr(3);
    const bool color = w.function.vertexColor;
    std::string ports = "UV (Vector 2)", params = "float2 UV", args = uv, inputs = "UV";
    if (color) ports += ", Color (Vector 4)", params += ", float4 Color", args += ", Color", inputs += ", Color";
    for (const std::string& t : textures) {
        const Kind& k = kKinds[f.arrays.count(t)];
        ports += ", " + t + " (" + k.port + ")";
        params += ", " + std::string(k.param) + " " + t;
        args += ", " + named(k.arg, t);
        inputs += ", " + t + k.unrealInput;
    }
    if (s.engine == Engine::Unity) {
        l.nodes += "//   " + name + ": " + ports + " -> Out (Vector " + (width == "1" ? "1" : width) + ")\n";
        l.wrappers += "void " + name + "_float(" + params + ", out " + type + " Out)\n{\n    Out = " + name + "(" + args + ");\n}\n\n";
        if (w.input)
            l.surface += "                " +
                         filled(w.input, name + "(uv, " + (color ? "input.color, " : "") + joined(textures, s.args) + ")") + "\n";
        return;
    }
    std::string code =
        "return " + name + "(" + uv + (color ? ", Color" : "") + (textures.empty() ? "" : ", " + joined(textures, s.args)) + ")";
    if (w.input && w.role == "normal") code += " * float3(1.0, -1.0, 1.0)";  // Unreal's tangent-space y runs down the image
    l.nodes += "//   " + std::string(w.input ? w.input : "(no pin)") + " <- CMOT Float " + width + " (" + inputs + "): " + code + ";\n";
}

// Each function's lines; a slot no input takes (a role the engine lacks, a second slot of one role) is reported.
Lines lines(const PackageInput& in, const Style& s, const Functions& f, Diagnostics& diagnostics) {
    Lines l;
    const std::string uv = bottomLeft(in) == in.engine.uvBottomLeft ? "UV" : "float2(UV.x, 1.0 - UV.y)";
    for (const WiredFunction& w : wire(in.material, in.functions, in.engine, diagnostics))
        addFunction(l, s, f, w, w.function.tangentNormal ? "vec3" : w.function.slot->type, uv);
    for (const std::string& t : f.all) {
        const Kind& k = kKinds[f.arrays.count(t)];
        l.properties += "        " + t + " (\"" + t.substr(t.find('_') + 1) + "\", " + k.property + "\n";
        l.textures += "            " + std::string(k.declare) + "(" + t + ");\n            SAMPLER(sampler_" + t + ");\n";
    }
    return l;
}

std::string trimmed(std::string text) {
    while (text.ends_with('\n')) text.pop_back();
    return text;
}

}  // namespace

std::vector<OutputFile> hlslPackage(const PackageInput& in, Diagnostics& diagnostics) {
    const Style& s = style(in.engine.engine);
    const Functions f = functions(in, s);
    Lines l = lines(in, s, f, diagnostics);
    const bool same = bottomLeft(in) == in.engine.uvBottomLeft;
    const std::string uvNote = same ? "hexc's functions take it as it is (compiled for that origin)"
                                    : "hexc's functions were compiled for (0, 0) at the top-left: v flipped";
    Tokens tokens = {{"material", in.material.name},
                     {"uvorigin", bottomLeft(in) ? "(0, 0) at the image's bottom-left, v up" : "(0, 0) at the image's top-left, v down"},
                     {"guard", guard(in.material.name)},
                     {"nodes", trimmed(l.nodes)},
                     {"functions", trimmed(f.text)},
                     {"wrappers", trimmed(l.wrappers)},
                     {"properties", trimmed(l.properties)},
                     {"textures", trimmed(l.textures)},
                     {"inputs", trimmed(l.surface)},
                     {"uv", same ? "input.uv" : "float2(input.uv.x, 1.0 - input.uv.y)"},
                     {"uvnote", uvNote}};
    std::vector<OutputFile> files;
    for (const auto& [templ, suffix] : in.engine.files)
        files.push_back({in.material.name + suffix, expandTokens(*embeddedText(templ), tokens, templ)});
    return files;
}

}  // namespace hexc
