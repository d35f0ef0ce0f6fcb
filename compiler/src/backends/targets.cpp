// The target table (one row per target, backends.h's TargetRow), the entry points every target accepts, and the
// emission of every requested target from the optimised module.
#include <algorithm>
#include <cctype>
#include <cstring>
#include <exception>
#include <future>
#include <set>
#include <thread>

#include "backends/backends.h"
#include "backends/naga.h"
#include "common/by_enum.h"
#include "spirv/combined.h"
#include "spirv/lines.h"
#include "hexc/spirv.h"

namespace hexc {

namespace {

// The SPIR-V target, from the optimised module itself; with the layout's combined samplers (combined.h), which the
// other targets, emitted from the separate module, do not take.
TargetOutput emitSpirv(const std::vector<uint32_t>& spirv, const std::vector<uint32_t>&, const ShaderPlan& plan, const CompileOptions&) {
    const std::vector<uint32_t> words = plan.layout.vulkan.combined ? combineSamplers(spirv, plan) : spirv;
    TargetOutput out = describeSpirv(words, plan);
    out.source = spirvBytes(words);
    return out;
}

TargetOutput vertexSpirv(const std::vector<uint32_t>& spirv, const CompileOptions&, const std::string& entry) {
    return {spirvBytes(spirv), entry, {}};
}

std::string sameName(const std::string& entry) { return entry; }
std::string noSettings(const CompileOptions&) { return ""; }
std::string settingsWgsl(const CompileOptions&) { return nagaVersion(); }
// SPIRV-Cross's stage is in the lines the functions output cuts (functions.cpp).
std::string stageInCut(const std::string& source, const std::string&) { return source; }
// SPIRV-Tools and SPIRV-Cross are linked into hexc: its build id holds them.
std::string inBuild() { return ""; }

// The text targets are written from `text`, the module with the source lines they are to show.
constexpr std::array<TargetRow, kTargetCount> kRows = {{
    {Target::Spirv, "spirv", "", "spv", "vulkan", true, true, "", stageInCut, emitSpirv, vertexSpirv, sameName, noSettings,
     "SPIRV-Tools' disassembler", inBuild, "spirv-asm", "spvasm", disassemble},
    {Target::Hlsl, "hlsl", "", "hlsl", "hlsl", false, true, "void frag_main()", stageInCut,
     [](const auto&, const auto& text, const auto& plan, const auto& options) { return emitHlsl(text, plan, options); }, vertexHlsl,
     sameName, settingsHlsl, "SPIRV-Cross", inBuild, "hlsl", "hlsl", libraryHlsl},
    {Target::Glsl, "glsl", "", "glsl", "glsl", false, true, "void main()", stageInCut,
     [](const auto&, const auto& text, const auto& plan, const auto& options) { return emitGlsl(text, plan, options); }, vertexGlsl,
     sameName, settingsGlsl, "SPIRV-Cross", inBuild, "glsl", "glsl", libraryGlsl},
    {Target::Msl, "msl", "metal", "metal", "msl", false, true, "fragment ", stageInCut,
     [](const auto&, const auto& text, const auto& plan, const auto& options) { return emitMsl(text, plan, options); }, vertexMsl,
     mslEntryName, settingsMsl, "SPIRV-Cross", inBuild, "msl", "metal", libraryMsl},
    // naga reads no OpLine, so --debug's lines do not reach WGSL; not a default target: a build may lack naga (naga.h).
    {Target::Wgsl, "wgsl", "", "wgsl", "vulkan", false, false, "@fragment", wgslWithoutStage,
     [](const auto& spirv, const auto&, const auto& plan, const auto& options) { return emitWgsl(spirv, plan, options); }, vertexWgsl,
     sameName, settingsWgsl, "naga", nagaIdentity, "wgsl", "wgsl", libraryWgsl},
}};

// A row per Target, in its order (a missing row is zero: the Spirv target without a name).
constexpr bool inTargetOrder() {
    for (size_t i = 0; i < kRows.size(); ++i)
        if (size_t(kRows[i].target) != i || kRows[i].name == nullptr) return false;
    return true;
}
static_assert(inTargetOrder(), "the target table has one row per Target, in Target order");

}  // namespace

const std::array<TargetRow, kTargetCount>& targetRows() { return kRows; }

const TargetRow& targetRow(Target target) { return kRows.at(size_t(target)); }

std::string_view toString(Target target) { return targetRow(target).name; }

std::vector<std::string> targetNames() {
    std::vector<std::string> names;
    for (const TargetRow& row : kRows) names.push_back(row.name);
    return names;
}

std::vector<Target> defaultTargets() {
    std::vector<Target> targets;
    for (const TargetRow& row : kRows)
        if (row.byDefault) targets.push_back(row.target);
    return targets;
}

std::vector<Target> defaultFunctionsTargets() {
    std::vector<Target> targets;
    for (Target t : defaultTargets())
        if (!targetRow(t).binary) targets.push_back(t);
    return targets;
}

std::optional<Target> targetNamed(std::string_view name) {
    for (const TargetRow& row : kRows)
        if (name == row.name || (*row.alias && name == row.alias)) return row.target;
    return std::nullopt;
}

std::string_view targetAlias(Target target) { return targetRow(target).alias; }

std::string shaderFileName(std::string_view material, Target target, std::string_view stage) {
    return std::string(material) + "." + std::string(stage) + "." + targetRow(target).extension;
}

std::string_view toString(LineDirectives mode) {
    static constexpr auto names = byEnum<LineDirectives::Statements>({"none", "functions", "statements"});
    return names[size_t(mode)];
}

std::string_view toString(UvOrigin origin) { return origin == UvOrigin::TopLeft ? "top-left" : "bottom-left"; }

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

std::string codeOptionsKey(const CompileOptions& options) {
    std::string key, translators;  // another naga writes other WGSL
    for (Target t : std::set<Target>(options.targets.begin(), options.targets.end())) {
        key += std::string(toString(t)) + ",";
        if (std::string identity = targetRow(t).translatorIdentity(); !identity.empty()) translators += "," + identity;
    }
    return key + std::to_string(options.hlslShaderModel) + "," + std::to_string(options.glslVersion) + (options.glslEs ? "es," : ",") +
           std::to_string(options.mslMajor) + "." + std::to_string(options.mslMinor) + (options.bake ? ",bake" : "") +
           (options.debug ? ",debug," + std::string(toString(options.lineDirectives)) : "") + (options.functions ? ",functions" : "") +
           (options.functionArrays == FunctionArrays::None ? "" : ",arrays " + std::to_string(int(options.functionArrays))) +
           (options.unrollLoops ? ",unroll" : "") +
           (options.uvOrigin == UvOrigin::TopLeft ? "" : ",uv " + std::string(toString(options.uvOrigin))) + translators;
}

std::vector<Target> sortedTargets(const CompileOptions& options) {
    std::vector<Target> targets = options.targets;
    std::sort(targets.begin(), targets.end());
    targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
    return targets;
}

std::string spirvBytes(const std::vector<uint32_t>& words) {
    std::string bytes(words.size() * 4, '\0');
    std::memcpy(bytes.data(), words.data(), bytes.size());
    return bytes;
}

// With CompileOptions::concurrentTargets and more than one core, each target but the last gets a thread of its own
// (each has its own SPIRV-Cross compiler, which SPIRV-Cross allows) and this thread emits the last one and SPIR-V,
// which is quick. Results, and the first error in target order, are taken in target order, so the outputs and
// diagnostics are those of one thread.
std::map<Target, TargetOutput> emitTargets(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options,
                                           const std::vector<Target>& targets) {
    std::map<Target, TargetOutput> out;
    const bool fewerLines = options.debug && options.lineDirectives == LineDirectives::Functions;
    const std::vector<uint32_t> text = fewerLines ? functionLinesOnly(spirv) : std::vector<uint32_t>();
    const std::vector<uint32_t>& textSpirv = fewerLines ? text : spirv;
    if (!options.concurrentTargets || targets.size() < 2 || std::thread::hardware_concurrency() < 2) {
        for (Target t : targets) out[t] = targetRow(t).emit(spirv, textSpirv, plan, options);
        return out;
    }
    auto here = [&](Target t) { return t == Target::Spirv || t == targets.back(); };
    std::map<Target, std::future<TargetOutput>> pending;
    for (Target t : targets)
        pending[t] = std::async(here(t) ? std::launch::deferred : std::launch::async, targetRow(t).emit, std::cref(spirv),
                                std::cref(textSpirv), std::cref(plan), std::cref(options));
    for (Target t : targets)
        if (here(t)) pending[t].wait();  // runs it, while the others run on theirs
    std::exception_ptr first;
    for (Target t : targets) try {
            out[t] = pending[t].get();
        } catch (...) {
            if (!first) first = std::current_exception();
        }
    if (first) std::rethrow_exception(first);
    return out;
}

}  // namespace hexc
