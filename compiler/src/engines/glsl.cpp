// The GLSL engines' packages (Godot 3, Godot 4, Filament; docs/engines.md): the functions in GLSL 330 in the engine's
// dialect, inside the engine's material template (compiler/integrations/<engine>/), with each slot fed to the engine
// input its role gives. The dialect is made from SPIRV-Cross's GLSL 330 of the functions, compiled in the same step:
// text of a known grammar (its declarations one to a line, calls with balanced parentheses, literals as it prints
// them), which the plain transforms below rely on.
#include <map>
#include <sstream>

#include "codegen/codegen.h"
#include "common/templates.h"
#include "common/text.h"
#include "engines/roles.h"
#include "engines/table.h"

namespace hexc {
namespace {

// `text` with every `fma(a, b, c)` as `((a) * (b) + (c))`: Godot's shading language has no fma. SPIRV-Cross writes
// the arguments with balanced parentheses, so a count of them finds each argument's end.
std::string withoutFma(const std::string& text) {
    std::string out;
    size_t at = 0;
    for (size_t call; (call = text.find("fma(", at)) != std::string::npos;) {
        if (call > 0 && isIdentifierChar(text[call - 1])) {
            out.append(text, at, call + 4 - at);
            at = call + 4;
            continue;
        }
        std::vector<std::string> args(1);
        size_t i = call + 4;
        for (int depth = 0; i < text.size() && !(depth == 0 && text[i] == ')'); ++i) {
            depth += text[i] == '(' ? 1 : text[i] == ')' ? -1 : 0;
            if (depth == 0 && text[i] == ',')
                args.emplace_back();
            else
                args.back() += text[i];
        }
        if (args.size() != 3) throw std::runtime_error("fma with " + std::to_string(args.size()) + " arguments");  // a hexc bug
        for (std::string& a : args) a = withoutFma(a.substr(a.find_first_not_of(' ')));
        out.append(text, at, call - at).append("((" + args[0] + ") * (" + args[1] + ") + (" + args[2] + "))");
        at = i + 1;
    }
    return out.append(text, at);
}

// `text` with every unsigned literal (`97u`) as `uint(97)`: Godot 3.2 rejects the suffix.
std::string withoutUnsignedLiterals(const std::string& text) {
    std::string out;
    for (size_t i = 0; i < text.size();) {
        size_t end = i;
        while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
        const bool literal = end > i && (i == 0 || !isIdentifierChar(text[i - 1])) && end < text.size() && text[end] == 'u' &&
                             (end + 1 == text.size() || !isIdentifierChar(text[end + 1]));
        if (literal) {
            out += "uint(" + text.substr(i, end - i) + ")";
            i = end + 1;
        } else if (end > i) {
            out.append(text, i, end - i);
            i = end;
        } else {
            out += text[i++];
        }
    }
    return out;
}

// `text` with each of hexc's textures (hexcTex_*, hexcLut_*) read as Filament names a sampler parameter:
// materialParams_<name>.
std::string asMaterialParams(const std::string& text) {
    std::string out;
    size_t at = 0;
    for (size_t found; (found = text.find("hexc", at)) != std::string::npos;) {
        const bool texture = (text.compare(found, 8, "hexcTex_") == 0 || text.compare(found, 8, "hexcLut_") == 0) &&
                             (found == 0 || !isIdentifierChar(text[found - 1]));
        out.append(text, at, found - at).append(texture ? "materialParams_hexc" : "hexc");
        at = found + 4;
    }
    return out.append(text, at);
}

// The functions without what the engine declares itself: #version and #extension lines and the texture uniforms (the
// engine template declares them); layout qualifiers dropped.
std::string functionsBody(const std::string& glsl) {
    std::istringstream in(glsl);
    std::string out;
    for (std::string line; std::getline(in, line);) {
        if (line.starts_with("uniform ") || line.starts_with("#")) continue;
        for (size_t at; (at = line.find("layout(")) != std::string::npos;) {
            size_t end = line.find(')', at);
            if (end++ == std::string::npos) break;
            while (end < line.size() && std::isspace(static_cast<unsigned char>(line[end]))) ++end;
            line.erase(at, end - at);
        }
        out += line + "\n";
    }
    for (size_t at; (at = out.find("\n\n\n")) != std::string::npos;) out.erase(at, 1);  // where declarations were
    while (out.starts_with("\n")) out.erase(0, 1);
    return out;
}

// `body` with each global SPIRV-Cross declares for an undefined value (OpUndef: `uint _3163;`, no initialiser) as a
// constant of value zero (`const uint _3163 = uint(0);`): Godot's language takes a global only as a constant with
// its value ("Expected initialization of constant"). The value is undefined, so zero is as good as any.
std::string withConstantUndefs(const std::string& body) {
    static const std::map<std::string, std::string> zeros = {{"float", "0.0"}, {"int", "0"},    {"uint", "uint(0)"},   {"bool", "false"},
                                                             {"vec", "(0.0)"}, {"ivec", "(0)"}, {"uvec", "(uint(0))"}, {"bvec", "(false)"}};
    std::istringstream in(body);
    std::string out, line;
    while (std::getline(in, line)) {
        const size_t space = line.find(' ');
        const std::string type = line.substr(0, space), base = type.substr(0, type.find_first_of("234"));
        const bool undef = space != std::string::npos && zeros.count(base) && line.compare(space, 2, " _") == 0 && line.ends_with(";") &&
                           line.find_first_of("=(", space) == std::string::npos;
        if (undef) line = "const " + line.substr(0, line.size() - 1) + " = " + (base == type ? "" : type) + zeros.at(base) + ";";
        out += line + "\n";
    }
    return out;
}

// The engine's dialect of the functions: Godot has no `97u` literals, no fma and no global variables; Filament reads
// its textures as materialParams_<name>.
std::string dialect(const std::string& body, Engine engine) {
    if (engine == Engine::Filament) return asMaterialParams(body);
    return withConstantUndefs(withoutFma(withoutUnsignedLiterals(body)));
}

std::string declarations(const std::vector<EngineTexture>& used, Engine engine) {
    std::string out;
    for (const EngineTexture& t : used) {
        if (engine == Engine::Filament)
            out += "        { type : sampler2d, name : " + t.uniform + " },\n";
        else if (engine == Engine::Godot3)
            out += "uniform sampler2D " + t.uniform + (t.srgb ? " : hint_albedo" : "") + ";\n";
        else
            out += std::string("uniform ") + (t.array ? "sampler2DArray " : "sampler2D ") + t.uniform + " : " +
                   (t.srgb ? "source_color, " : "") + "filter_linear_mipmap, repeat_enable;\n";
    }
    if (engine == Engine::Filament && out.ends_with(",\n")) out.erase(out.size() - 2);  // the template ends the line
    return out;
}

// The statements that set the engine's inputs from the functions (Filament's normal apart: it is set before
// prepareMaterial, as Filament requires).
struct Inputs {
    std::string inputs, normal;
};

// A layered role's function weighed by the vertex colour takes the engine's own after uv: Godot's COLOR, Filament's
// getColor() (its material requires the attribute: vertexColorRequired).
Inputs inputs(const PackageInput& in, Diagnostics& diagnostics) {
    const bool filament = in.engine.engine == Engine::Filament;
    const std::string indent = filament ? "        " : "    ", uv = filament ? "uv" : "UV", color = filament ? "getColor()" : "COLOR";
    Inputs out;
    for (const WiredFunction& w : wire(in.material, in.functions, in.engine, diagnostics)) {
        if (!w.input) continue;
        const std::string args = uv + (w.function.vertexColor ? ", " + color : "");
        const std::string statement = indent + filled(w.input, w.function.name + "(" + args + ")");
        if (filament && w.role == "normal")
            out.normal = statement;
        else
            out.inputs += statement + "\n";
    }
    if (out.inputs.ends_with('\n')) out.inputs.pop_back();
    return out;
}

}  // namespace

std::vector<OutputFile> glslPackage(const PackageInput& in, Diagnostics& diagnostics) {
    const Engine engine = in.engine.engine;
    const Inputs wired = inputs(in, diagnostics);
    const std::string declared = declarations(in.textures, engine);
    Tokens tokens = {
        {"material", in.material.name},
        {"uvorigin",
         in.uvBottomLeft ? "(0, 0) at the image's bottom-left, v up (hexc --uv-bottom-left)" : "(0, 0) at the image's top-left, v down"},
        {"uniforms", declared},
        {"parameters", declared},
        {"functions", dialect(functionsBody(in.compiled.sources.at(Target::Glsl)), engine)},
        {"inputs", wired.inputs},
        {"normal", wired.normal},
        {"requires", takesVertexColor(in) ? "uv0, color" : "uv0"},
    };
    const auto& [templ, suffix] = in.engine.files.front();
    return {{in.material.name + suffix, expandTokens(*embeddedText(templ), tokens, templ)}};
}

}  // namespace hexc
