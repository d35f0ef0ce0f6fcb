// The HLSL engines' packages (Unity, Unreal; docs/engines.md): the functions' HLSL with each function taking the
// textures it reads as parameters (Shader Graph's and Unreal's Custom nodes pass textures in; neither lets an include
// file declare global ones), inside the engine's templates (compiler/integrations/unity/, unreal/). The parameters are
// added to SPIRV-Cross's HLSL of the functions, compiled in the same step: text of a known grammar (a global
// `Texture2D<T> name : register(tN);` (`Texture2DArray<T>` for a layered role's array) or `SamplerState name :
// register(sN);` per line, a function's head on one line, texture reads `name.Method(sampler, `), which the plain
// searches below rely on. Which textures are arrays comes from the plan (PackageInput::textures), not from the text.
#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <sstream>

#include "codegen/codegen.h"
#include "common/templates.h"
#include "common/text.h"
#include "engines/roles.h"
#include "engines/table.h"

namespace hexc {
namespace {

// How an engine passes a texture into a function and reads it: Unity through its Core RP macros (with the row flip of
// its storage, HEXC_SAMPLE_GRAD in unity/hexc.hlsl), Unreal as HLSL's own objects, the sampler named as its Custom
// node names a Texture Object input's: <input>Sampler. {T}: the texture's name; {M}: the method; param and args per
// kind of texture: [0] a 2D texture, [1] a layered role's 2D array texture.
struct Style {
    Engine engine;
    std::array<std::string, 2> param, args;
    std::string sample;
    bool rowsBottomFirst;  // the engine stores a texture's bottom row first (Unity): the reads flip t, a texel fetch cannot
};

const Style& style(Engine engine) {
    static const Style unity = {Engine::Unity,
                                {"TEXTURE2D_PARAM({T}, sampler_{T})", "TEXTURE2D_ARRAY_PARAM({T}, sampler_{T})"},
                                {"TEXTURE2D_ARGS({T}, sampler_{T})", "TEXTURE2D_ARRAY_ARGS({T}, sampler_{T})"},
                                "HEXC_{M}({T}, sampler_{T}, ",
                                true};
    static const Style unreal = {Engine::Unreal,
                                 {"Texture2D {T}, SamplerState {T}Sampler", "Texture2DArray {T}, SamplerState {T}Sampler"},
                                 {"{T}, {T}Sampler", "{T}, {T}Sampler"},
                                 "{T}.{M}({T}Sampler, ",
                                 false};
    return engine == Engine::Unity ? unity : unreal;
}

std::string named(std::string pattern, const std::string& texture, const std::string& method = "") {
    for (const auto& [token, value] : {std::pair<std::string, std::string>{"{T}", texture}, {"{M}", method}})
        for (size_t at; (at = pattern.find(token)) != std::string::npos;) pattern.replace(at, token.size(), value);
    return pattern;
}

// The unity/hexc.hlsl macro (after HEXC_) for an HLSL texture method SPIRV-Cross writes, on a 2D or an array texture.
std::string unityMacro(const std::string& method, bool array) {
    static const std::map<std::string, std::string> macros = {{"SampleGrad", "_GRAD"}, {"SampleLevel", "_LEVEL"}, {"Sample", ""}};
    const auto m = macros.find(method);
    if (m == macros.end()) throw std::runtime_error("no Unity macro for " + method);  // a hexc bug
    return std::string(array ? "SAMPLE_ARRAY" : "SAMPLE") + m->second;
}

// SPIRV-Cross's HLSL of the functions output: its global textures (in declaration order), what precedes the first
// function (constants), and each function with the textures it reads, itself or through a function it calls.
struct Function {
    std::string name, text;
    std::vector<std::string> textures;
};

struct Functions {
    std::vector<std::string> textures;
    std::set<std::string> arrays;  // those of `textures` that are 2D array textures
    std::string constants;
    std::vector<Function> functions;
};

// The next place from `at` where `word` starts an identifier in `text`, or npos.
size_t findIdentifier(const std::string& text, const std::string& word, size_t at) {
    for (at = text.find(word, at); at != std::string::npos; at = text.find(word, at + 1))
        if (at == 0 || !isIdentifierChar(text[at - 1])) return at;
    return std::string::npos;
}

bool isIdentifier(std::string_view s) { return !s.empty() && std::all_of(s.begin(), s.end(), isIdentifierChar); }

// The global texture a line declares (`Texture2D<float4> name : register(t1);`, `Texture2DArray<float4> ...`), or ""
// (a sampler's too).
std::string declaredTexture(const std::string& line) {
    const size_t close = line.find("> "), colon = line.find(" : register(");
    if (!(line.starts_with("Texture2D<") || line.starts_with("Texture2DArray<")) || close == std::string::npos ||
        colon == std::string::npos || !line.ends_with(");"))
        return "";
    const std::string name = line.substr(close + 2, colon - close - 2);
    return isIdentifier(name) ? name : "";
}

// The function a line begins (`float4 hexc_albedo(float2 uv)`), or "".
std::string functionHead(const std::string& line) {
    const size_t space = line.find(' '), open = line.find('(');
    if (space == std::string::npos || open == std::string::npos || open < space || !line.ends_with(")")) return "";
    const std::string name = line.substr(space + 1, open - space - 1);
    return isIdentifier(line.substr(0, space)) && isIdentifier(name) ? name : "";
}

Functions parse(const std::string& hlsl, const std::vector<EngineTexture>& textures) {
    Functions out;
    for (const EngineTexture& t : textures)
        if (t.array) out.arrays.insert(t.uniform);
    std::istringstream in(hlsl);
    for (std::string line; std::getline(in, line);) {
        if (const std::string texture = declaredTexture(line); !texture.empty()) {
            out.textures.push_back(texture);
        } else if (line.starts_with("SamplerState ") && line.find(" : register(") != std::string::npos) {
            continue;
        } else if (const std::string name = functionHead(line); !name.empty()) {
            out.functions.push_back({name, line + "\n", {}});
        } else if (!out.functions.empty()) {
            out.functions.back().text += line + "\n";
        } else if (!line.empty()) {
            out.constants += line + "\n";
        }
    }
    return out;
}

// `texts` each as `patterns` says for its kind (2D or array), joined by commas.
std::string joined(const std::vector<std::string>& texts, const std::array<std::string, 2>& patterns, const Functions& f) {
    std::string out;
    for (const std::string& t : texts) out += (out.empty() ? "" : ", ") + named(patterns[f.arrays.count(t)], t);
    return out;
}

// `text` with `extra` added to the arguments of every call of `name` (whose arguments hold balanced parentheses).
std::string withArguments(const std::string& text, const std::string& name, const std::string& extra) {
    std::string out;
    size_t at = 0;
    for (size_t call = findIdentifier(text, name + "(", 0); call != std::string::npos; call = findIdentifier(text, name + "(", call + 1)) {
        size_t close = call + name.size() + 1;
        for (int depth = 0; depth > 0 || text[close] != ')'; ++close) depth += text[close] == '(' ? 1 : text[close] == ')' ? -1 : 0;
        out.append(text, at, close - at).append(", " + extra);
        at = close;
    }
    return out.append(text, at);
}

// `text` with each read of texture `t` (`t.Method(sampler, `) in the engine's style; false when it reads none.
bool readInStyle(std::string& text, const std::string& t, const Style& s, bool array) {
    std::string out;
    size_t at = 0;
    for (size_t read = findIdentifier(text, t + ".", 0); read != std::string::npos; read = findIdentifier(text, t + ".", read + 1)) {
        const size_t method = read + t.size() + 1, open = text.find('(', method), comma = text.find(", ", open);
        if (open == std::string::npos || comma == std::string::npos ||
            !isIdentifier(std::string_view(text).substr(method, open - method)) ||
            !isIdentifier(std::string_view(text).substr(open + 1, comma - open - 1)))
            continue;
        const std::string name = text.substr(method, open - method);
        out.append(text, at, read - at).append(named(s.sample, t, s.engine == Engine::Unity ? unityMacro(name, array) : name));
        at = comma + 2;
    }
    if (at == 0) return false;
    text = out.append(text, at);
    return true;
}

// Each function taking the textures it reads as parameters, and reading them in the engine's style.
void passTextures(Functions& f, const Style& s) {
    for (size_t i = 0; i < f.functions.size(); ++i) {
        Function& fn = f.functions[i];
        for (const std::string& t : f.textures)
            if (readInStyle(fn.text, t, s, f.arrays.count(t))) fn.textures.push_back(t);
        for (size_t j = 0; j < i; ++j) {
            const Function& callee = f.functions[j];
            if (callee.textures.empty() || findIdentifier(fn.text, callee.name + "(", 0) == std::string::npos) continue;
            fn.text = withArguments(fn.text, callee.name, joined(callee.textures, s.args, f));
            for (const std::string& t : callee.textures)
                if (std::find(fn.textures.begin(), fn.textures.end(), t) == fn.textures.end()) fn.textures.push_back(t);
        }
        std::sort(fn.textures.begin(), fn.textures.end(), [&](const std::string& a, const std::string& b) {
            return std::find(f.textures.begin(), f.textures.end(), a) < std::find(f.textures.begin(), f.textures.end(), b);
        });
        const size_t headEnd = fn.text.find(")\n");
        if (!fn.textures.empty()) fn.text.insert(headEnd, ", " + joined(fn.textures, s.param, f));
    }
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
    {"Texture 2D", "UnityTexture2D", "TEXTURE2D_ARGS({T}.tex, {T}.samplerstate)", "2D) = \"white\" {}", "TEXTURE2D", ""},
    {"Texture 2D Array", "UnityTexture2DArray", "TEXTURE2D_ARRAY_ARGS({T}.tex, {T}.samplerstate)", "2DArray) = \"\" {}", "TEXTURE2D_ARRAY",
     " (Texture2DArray)"},
}};

// One function's lines: its Custom node (Unity: the ports; Unreal: the pin, output type, inputs and code), Unity's
// node entry point, and the URP statement of the input its role fills ("" when it fills none). A function that takes the
// vertex colour has a Color input after UV (a Vertex Color node in Shader Graph, a VertexColor node in Unreal; the URP
// shader's own: input.color).
void addFunction(Lines& l, const Style& s, const Functions& f, const Function& fn, const std::string& returns, const WiredFunction& w,
                 const std::string& uv) {
    const std::string type = hlslType(returns), width = returns == "float" ? "1" : returns.substr(3);
    const bool color = w.function.vertexColor;
    std::string ports = "UV (Vector 2)", params = "float2 UV", args = uv, inputs = "UV";
    if (color) ports += ", Color (Vector 4)", params += ", float4 Color", args += ", Color", inputs += ", Color";
    for (const std::string& t : fn.textures) {
        const Kind& k = kKinds[f.arrays.count(t)];
        ports += ", " + t + " (" + k.port + ")";
        params += ", " + std::string(k.param) + " " + t;
        args += ", " + named(k.arg, t);
        inputs += ", " + t + k.unrealInput;
    }
    if (s.engine == Engine::Unity) {
        l.nodes += "//   " + fn.name + ": " + ports + " -> Out (Vector " + (width == "1" ? "1" : width) + ")\n";
        l.wrappers +=
            "void " + fn.name + "_float(" + params + ", out " + type + " Out)\n{\n    Out = " + fn.name + "(" + args + ");\n}\n\n";
        if (w.input)
            l.surface += "                " +
                         filled(w.input, fn.name + "(uv, " + (color ? "input.color, " : "") + joined(fn.textures, s.args, f) + ")") + "\n";
        return;
    }
    std::string code = "return " + fn.name + "(" + uv + (color ? ", Color" : "") +
                       (fn.textures.empty() ? "" : ", " + joined(fn.textures, s.args, f)) + ")";
    if (w.input && w.role == "normal") code += " * float3(1.0, -1.0, 1.0)";  // Unreal's tangent-space y runs down the image
    l.nodes += "//   " + std::string(w.input ? w.input : "(no pin)") + " <- CMOT Float " + width + " (" + inputs + "): " + code + ";\n";
}

// Each function's lines; a slot no input takes (a role the engine lacks, a second slot of one role) is reported.
Lines lines(const PackageInput& in, const Style& s, const Functions& f, Diagnostics& diagnostics) {
    Lines l;
    const std::string uv = in.uvBottomLeft == in.engine.uvBottomLeft ? "UV" : "float2(UV.x, 1.0 - UV.y)";
    for (const WiredFunction& w : wire(in.material, in.functions, in.engine, diagnostics)) {
        const Function& fn =
            *std::find_if(f.functions.begin(), f.functions.end(), [&](const Function& x) { return x.name == w.function.name; });
        addFunction(l, s, f, fn, w.function.tangentNormal ? "vec3" : w.function.slot->type, w, uv);
    }
    for (const std::string& t : f.textures) {
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

// A histogram slot's table is read texel by texel by row (its look-up rows), which an engine storing the bottom row
// first puts elsewhere: refused (HX300) there.
bool refusesTables(const PackageInput& in, const Style& s, Diagnostics& diagnostics) {
    for (const EngineTexture& t : in.textures)
        if (t.table && s.rowsBottomFirst) {
            diagnostics.push_back(Diagnostic::make(Code::TargetUnsupported, {in.material.sourceFile.string()}, "",
                                                   std::string(in.engine.shown) + " stores a texture's bottom row first, and the " +
                                                       "histogram blend reads its table's rows texel by texel (slot `" + t.table->name +
                                                       "`; blend it by falloff)"));
            return true;
        }
    return false;
}

}  // namespace

std::vector<OutputFile> hlslPackage(const PackageInput& in, Diagnostics& diagnostics) {
    const Style& s = style(in.engine.engine);
    if (refusesTables(in, s, diagnostics)) return {};
    Functions f = parse(in.compiled.sources.at(Target::Hlsl), in.textures);
    passTextures(f, s);
    std::string functions = f.constants;
    for (const Function& fn : f.functions) functions += "\n" + fn.text;
    Lines l = lines(in, s, f, diagnostics);
    const bool same = in.uvBottomLeft == in.engine.uvBottomLeft;
    const std::string uvNote = same ? "hexc's functions take it as it is (compiled for that origin)"
                                    : "hexc's functions were compiled for (0, 0) at the top-left: v flipped";
    Tokens tokens = {{"material", in.material.name},
                     {"uvorigin", in.uvBottomLeft ? "(0, 0) at the image's bottom-left, v up" : "(0, 0) at the image's top-left, v down"},
                     {"guard", guard(in.material.name)},
                     {"nodes", trimmed(l.nodes)},
                     {"functions", trimmed(functions)},
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
