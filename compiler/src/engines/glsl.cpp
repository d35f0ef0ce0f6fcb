// The GLSL family's packages (each engine's Dialect below; docs/engines.md): the functions in GLSL 330 in the engine's
// dialect, inside the engine's material template (compiler/integrations/<engine>/), with each slot fed to the engine
// input its role gives. The dialect is SPIRV-Cross's GLSL of the compile's SPIR-V, printed by a subclass of its
// compiler that writes what the engine takes (EngineGlsl): no text hexc wrote is read back.
#include <spirv_glsl.hpp>

#include <stdexcept>

#include <GLSL.std.450.h>

#include "backends/backends.h"
#include "codegen/codegen.h"
#include "common/templates.h"
#include "engines/roles.h"
#include "engines/table.h"

namespace hexc {
namespace {

// How a GLSL engine spells what hexc writes. Each engine of the family has one (a case of `dialect`): a row of the
// table that writes with glslPackage and has none is a std::logic_error, and -Wswitch names the missing case.
struct Dialect {
    bool godot;              // Godot's shading language: no fma, no `97u` literals, globals only as constants
    bool materialParams;     // Filament: a texture read as materialParams_<name>, the normal set before prepareMaterial
    const char *uv, *color;  // the engine's uv and vertex colour, as a statement of its fragment reads them
    const char* indent;      // of the template's statements
    std::string (*declare)(const EngineTexture& t);  // a texture's declaration, a line
};

std::string godot3Texture(const EngineTexture& t) { return "uniform sampler2D " + t.uniform + (t.srgb ? " : hint_albedo" : "") + ";\n"; }

std::string godot4Texture(const EngineTexture& t) {
    return std::string("uniform ") + (t.array ? "sampler2DArray " : "sampler2D ") + t.uniform + " : " + (t.srgb ? "source_color, " : "") +
           "filter_linear_mipmap, repeat_enable;\n";
}

std::string filamentTexture(const EngineTexture& t) { return "        { type : sampler2d, name : " + t.uniform + " },\n"; }

const Dialect& dialect(Engine engine) {
    static const Dialect godot3{true, false, "UV", "COLOR", "    ", godot3Texture};
    static const Dialect godot4{true, false, "UV", "COLOR", "    ", godot4Texture};
    static const Dialect filament{false, true, "uv", "getColor()", "        ", filamentTexture};
    switch (engine) {
        case Engine::Godot3:
            return godot3;
        case Engine::Godot4:
            return godot4;
        case Engine::Filament:
            return filament;
        case Engine::Threejs:
        case Engine::Babylon:
        case Engine::Unity:
        case Engine::Unreal:
        case Engine::ThreejsWebgpu:
            break;
    }
    throw std::logic_error("the " + std::string(toString(engine)) + " package has no GLSL dialect (engines/glsl.cpp)");
}

// SPIRV-Cross's GLSL of the functions as the engine's material takes them: no header and no uniforms (the engine's
// template declares the textures), in the engine's dialect. Godot's language has no fma, no `97u` literals and global
// variables only as constants: SPIRV-Cross's global for an undefined value (OpUndef) is a constant of value zero, as
// good as any. Filament names a sampler parameter materialParams_<name>.
class EngineGlsl : public spirv_cross::CompilerGLSL {
public:
    EngineGlsl(const std::vector<uint32_t>& spirv, const Dialect& d) : CompilerGLSL(spirv), d_(d) {}

    std::string compile() override {
        options.emit_line_directives = false;  // no #line for --debug: Godot 3's language has no preprocessor
        if (d_.materialParams)
            ir.for_each_typed_id<spirv_cross::SPIRVariable>([&](uint32_t id, const spirv_cross::SPIRVariable&) {
                const std::string name = get_name(id);
                if (name.starts_with("hexcTex_") || name.starts_with("hexcLut_")) set_name(id, "materialParams_" + name);
            });
        return CompilerGLSL::compile();
    }

protected:
    void emit_header() override {}
    void emit_uniform(const spirv_cross::SPIRVariable&) override {}

    void emit_glsl_op(uint32_t type, uint32_t id, uint32_t op, const uint32_t* args, uint32_t count) override {
        if (!d_.godot || op != GLSLstd450Fma) return CompilerGLSL::emit_glsl_op(type, id, op, args, count);
        const bool forward = should_forward(args[0]) && should_forward(args[1]) && should_forward(args[2]);
        emit_op(type, id,
                to_enclosed_unpacked_expression(args[0]) + " * " + to_enclosed_unpacked_expression(args[1]) + " + " +
                    to_enclosed_unpacked_expression(args[2]),
                forward);
        for (uint32_t i = 0; i < 3; ++i) inherit_expression_dependencies(id, args[i]);
    }

    // An unsigned constant as uint(97); a vector of them as uvec3(uint(1), uint(2), uint(3)), or uvec3(uint(1)) when
    // its components are equal.
    std::string constant_expression_vector(const spirv_cross::SPIRConstant& c, uint32_t vector) override {
        const spirv_cross::SPIRType& type = get<spirv_cross::SPIRType>(c.constant_type);
        if (!d_.godot || type.basetype != spirv_cross::SPIRType::UInt) return CompilerGLSL::constant_expression_vector(c, vector);
        const auto literal = [&](uint32_t i) { return "uint(" + std::to_string(c.scalar(vector, i)) + ")"; };
        bool splat = true;
        for (uint32_t i = 1; i < c.vector_size(); ++i) splat = splat && c.scalar(vector, i) == c.scalar(vector, 0);
        std::string out = literal(0);
        for (uint32_t i = 1; i < c.vector_size() && !splat; ++i) out += ", " + literal(i);
        return c.vector_size() == 1 ? out : type_to_glsl(type) + "(" + out + ")";
    }

    // An undefined value's global as a constant of value zero.
    std::string variable_decl(const spirv_cross::SPIRType& type, const std::string& name, uint32_t id) override {
        const std::string decl = CompilerGLSL::variable_decl(type, name, id);
        if (!d_.godot || !id || ir.ids[id].get_type() != spirv_cross::TypeUndef) return decl;
        return "const " + decl + " = " + to_zero_initialized_expression(get<spirv_cross::SPIRUndef>(id).basetype);
    }

private:
    const Dialect& d_;
};

std::string declarations(const std::vector<EngineTexture>& used, const Dialect& d) {
    std::string out;
    for (const EngineTexture& t : used) out += d.declare(t);
    if (d.materialParams && out.ends_with(",\n")) out.erase(out.size() - 2);  // Filament's template ends the line
    return out;
}

// The statements that set the engine's inputs from the functions (Filament's normal apart: it is set before
// prepareMaterial, as Filament requires).
struct Inputs {
    std::string inputs, normal;
};

// A layered role's function weighed by the vertex colour takes the engine's own after uv: Godot's COLOR, Filament's
// getColor() (its material requires the attribute: vertexColorRequired).
Inputs inputs(const PackageInput& in, const Dialect& d, Diagnostics& diagnostics) {
    Inputs out;
    for (const WiredFunction& w : wire(in.material, in.functions, in.engine, diagnostics)) {
        if (!w.input) continue;
        const std::string args = d.uv + (w.function.vertexColor ? std::string(", ") + d.color : "");
        const std::string statement = d.indent + filled(w.input, w.function.name + "(" + args + ")");
        if (d.materialParams && w.role == "normal")
            out.normal = statement;
        else
            out.inputs += statement + "\n";
    }
    if (out.inputs.ends_with('\n')) out.inputs.pop_back();
    return out;
}

}  // namespace

std::string glslFunctions(spirv_cross::CompilerGLSL& c, const PackageInput& in) {
    const ShaderPlan& plan = in.compiled.plan;
    return functionsOnly(emitGlsl(c, in.compiled.result.spirv, plan, in.options).source, Target::Glsl, plan.entryPoint);
}

std::vector<OutputFile> glslPackage(const PackageInput& in, Diagnostics& diagnostics) {
    const Dialect& d = dialect(in.engine.engine);
    const Inputs wired = inputs(in, d, diagnostics);
    const std::string declared = declarations(in.textures, d);
    EngineGlsl printer(in.compiled.result.spirv, d);
    Tokens tokens = {
        {"material", in.material.name},
        {"uvorigin",
         bottomLeft(in) ? "(0, 0) at the image's bottom-left, v up (hexc --uv-bottom-left)" : "(0, 0) at the image's top-left, v down"},
        {"uniforms", declared},
        {"parameters", declared},
        {"functions", glslFunctions(printer, in)},
        {"inputs", wired.inputs},
        {"normal", wired.normal},
        {"requires", takesVertexColor(in) ? "uv0, color" : "uv0"},
    };
    const auto& [templ, suffix] = in.engine.files.front();
    return {{in.material.name + suffix, expandTokens(*embeddedText(templ), tokens, templ)}};
}

}  // namespace hexc
