// The one place the stages are chained: plan -> codegen -> glslang -> spirv-opt -> SPIRV-Cross -> manifest.
#include <glslang/build_info.h>
#include <spirv-tools/libspirv.h>

#include <spirv_cross_error_handling.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <set>

#include "backends/backends.h"
#include "codegen/codegen.h"
#include "hexc/compiler.h"
#include "plan/plan.h"
#include "hexc/spirv.h"

namespace hexc {

const char* version() { return HEXC_VERSION; }

std::string toolchainVersions() {
    return "glslang " + std::to_string(GLSLANG_VERSION_MAJOR) + "." + std::to_string(GLSLANG_VERSION_MINOR) + "." +
           std::to_string(GLSLANG_VERSION_PATCH) + GLSLANG_VERSION_FLAVOR + "\nSPIRV-Tools " + spvSoftwareVersionString() +
           "\nSPIRV-Cross " + HEXC_SPIRV_CROSS_VERSION;
}

std::string defaultEntryPoint(std::string_view material) {
    std::string name(material);
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    // An identifier cannot start with a digit; material names may.
    return (std::isdigit(static_cast<unsigned char>(name[0])) ? "m" : "") + name + "_frag";
}

bool isEntryPointName(std::string_view name) {
    static const std::set<std::string_view> reserved = {
        "main0",  "void",      "float", "int",      "bool",    "struct", "return",   "if",      "else",    "for",    "while",
        "do",     "in",        "out",   "inout",    "uniform", "const",  "true",     "false",   "discard", "vertex", "fragment",
        "kernel", "namespace", "using", "template", "class",   "static", "register", "texture", "sampler"};
    if (name.empty() || name.size() > 64 || std::isdigit(static_cast<unsigned char>(name[0])) || name.starts_with("gl_") ||
        name.starts_with("__") || reserved.count(name))
        return false;
    return std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

std::string shaderFileName(std::string_view material, Target target, std::string_view stage) {
    static const char* const extensions[] = {"spv", "hlsl", "glsl", "metal"};
    return std::string(material) + "." + std::string(stage) + "." + extensions[int(target)];
}

std::string_view toString(Target target) {
    static const char* names[] = {"spirv", "hlsl", "glsl", "msl"};
    return names[int(target)];
}

namespace {

void append(Diagnostics& to, const Diagnostics& from) { to.insert(to.end(), from.begin(), from.end()); }

std::string spirvBytes(const std::vector<uint32_t>& words) {
    std::string bytes(words.size() * 4, '\0');
    std::memcpy(bytes.data(), words.data(), bytes.size());
    return bytes;
}

// The pass-through vertex stage feeding the fragment shader's inputs, on every target: its files into `result`, its
// description (files, entry points, attributes) returned for the manifest.
nlohmann::json emitVertexStage(const Material& material, const ShaderPlan& plan, const CompileOptions& options,
                               const std::vector<Target>& targets, CompileResult& result) {
    const std::vector<Varying> inputs = fragmentInputs(result.spirv);
    const std::string& frag = plan.entryPoint;
    const std::string entry = (frag.ends_with("_frag") ? frag.substr(0, frag.size() - 5) : frag) + "_vert";
    SpirvResult front = compileToSpirv(generateVertexGlsl(inputs), ShaderStage::Vertex, "hexc/vertex.glsl", SourceLanguage::Glsl, entry);
    SpirvResult optimized = front.words.empty() ? front : optimizeSpirv(front.words);
    if (optimized.words.empty()) throw CompileError{optimized.diagnostics};  // hexc's own code: a bug
    // SPIRV-Cross gives vertex inputs TEXCOORD<location> in HLSL and [[attribute(<location>)]] in MSL.
    auto attribute = [](const std::string& name, uint32_t location, const std::string& type, const std::string& feeds) {
        return nlohmann::json{{"name", name},
                              {"location", location},
                              {"type", type},
                              {"feeds", feeds},
                              {"hlsl_semantic", "TEXCOORD" + std::to_string(location)},
                              {"msl_attribute", location}};
    };
    nlohmann::json attributes = nlohmann::json::array();  // not `{one}`: clang makes that the object itself
    attributes.push_back(attribute("hexc_position", 0, "vec4", "gl_Position"));
    for (const Varying& v : inputs) attributes.push_back(attribute("hexc_in_" + v.name, uint32_t(attributes.size()), v.type, v.name));
    nlohmann::json vertex = {{"attributes", attributes}};
    for (Target t : targets) {
        TargetOutput out = emitVertex(optimized.words, t, options, entry);
        OutputFile file{shaderFileName(material.name, t, "vert"), t == Target::Spirv ? spirvBytes(optimized.words) : out.source};
        vertex[std::string(toString(t))] = {{"file", file.name}, {"entry_point", out.entryPoint}};
        result.files.push_back(std::move(file));
    }
    return vertex;
}

void run(const Material& material, const CompileOptions& options, CompileResult& result) {
    ShaderPlan plan = planShader(material, options);
    append(result.diagnostics, plan.diagnostics);
    if (hasErrors(plan.diagnostics)) return;

    result.glsl = generateGlsl(plan);
    SpirvResult front = compileToSpirv(result.glsl, ShaderStage::Fragment, plan.templateName, SourceLanguage::Glsl, plan.entryPoint);
    append(result.diagnostics, front.diagnostics);
    if (front.words.empty()) return;
    SpirvResult optimized = optimizeSpirv(front.words, options.bake);
    append(result.diagnostics, optimized.diagnostics);
    if (optimized.words.empty()) return;
    result.spirv = std::move(optimized.words);

    std::vector<Target> targets = options.targets;
    std::sort(targets.begin(), targets.end());
    targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
    nlohmann::json described = nlohmann::json::object();
    for (Target t : targets) {
        TargetOutput out;
        OutputFile file;
        switch (t) {
            case Target::Spirv:
                out = describeSpirv(result.spirv, plan);
                file = {shaderFileName(material.name, Target::Spirv), spirvBytes(result.spirv)};
                break;
            case Target::Hlsl:
                out = emitHlsl(result.spirv, plan, options);
                file = {shaderFileName(material.name, Target::Hlsl), out.source};
                break;
            case Target::Glsl:
                out = emitGlsl(result.spirv, plan, options);
                file = {shaderFileName(material.name, Target::Glsl), out.source};
                break;
            case Target::Msl:
                out = emitMsl(result.spirv, plan, options);
                file = {shaderFileName(material.name, Target::Msl), out.source};
                break;
        }
        out.target["file"] = file.name;
        described[std::string(toString(t))] = std::move(out.target);
        result.files.push_back(std::move(file));
    }
    nlohmann::json manifest = buildManifest(material, plan, described);
    if (options.vertex) manifest["vertex"] = emitVertexStage(material, plan, options, targets, result);
    result.files.push_back({material.name + ".manifest.json", manifest.dump(2) + "\n"});
    std::sort(result.files.begin(), result.files.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
}

}  // namespace

CompileResult compile(const Material& material, const CompileOptions& options) {
    CompileResult result;
    try {
        run(material, options, result);
    } catch (const CompileError& e) {
        append(result.diagnostics, e.diagnostics);
    } catch (const spirv_cross::CompilerError& e) {
        result.diagnostics.push_back(
            Diagnostic::make(Code::TargetUnsupported, {material.sourceFile.string()}, "", std::string("SPIRV-Cross: ") + e.what()));
    } catch (const std::exception& e) {
        // compile() never throws: anything else is hexc's own fault, reported as such.
        result.diagnostics.push_back(
            Diagnostic::make(Code::Internal, {material.sourceFile.string()}, "", std::string("internal error: ") + e.what()));
    }
    if (!result.ok()) result.files.clear();
    return result;
}

}  // namespace hexc
