// WGSL: naga (backends/naga.h) translates the optimised module. naga keeps each resource's Vulkan set and binding as
// its @group and @binding, so hexc's resources are where the Vulkan layout puts them (layout section "vulkan"), and
// the parameter block keeps its offsets (naga writes @align/@size where WGSL's uniform rules would place a member
// elsewhere). What naga cannot take, a template's combined sampler or push constants, is refused with its location.
#include <spirv_cross.hpp>

#include <sstream>
#include <string_view>

#include "backends/backends.h"
#include "backends/naga.h"
#include "common/text.h"
#include "spirv/lines.h"
#include "spirv/strings.h"

namespace hexc {
namespace {

// The template line that declares `name`: the first line naming it as a word after the word `uniform`, for a located
// diagnostic (at `uniform`). The plan holds the template as read.
SourceLoc declaredAt(const ShaderPlan& plan, const std::string& name) {
    std::istringstream in(plan.templateSource);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
        for (size_t at = line.find("uniform"); at != std::string::npos; at = line.find("uniform", at + 1)) {
            const size_t end = at + 7;
            const bool word = (at == 0 || !isIdentifierChar(line[at - 1])) && (end == line.size() || !isIdentifierChar(line[end]));
            if (word && containsWord(std::string_view(line).substr(end), name)) return {plan.templateShown, n, int(at) + 1};
        }
    return {plan.templateShown, 0, 0};
}

void refuseUntranslatable(const std::vector<uint32_t>& spirv, const ShaderPlan& plan) {
    Diagnostics found;
    for (const TemplateResource& r : templateResources(spirv_cross::Compiler(spirv), plan)) {
        const char* what = r.cls == ResourceClass::CombinedImageSampler
                               ? "a combined image sampler (sampler2D), which WGSL does not have; declare a texture2D and a sampler"
                           : r.cls == ResourceClass::PushConstant
                               ? "a push-constant block, which WGSL does not have; declare a uniform block"
                               : nullptr;
        if (what)
            found.push_back(Diagnostic::make(Code::TargetUnsupported, declaredAt(plan, r.name), "",
                                             "the wgsl target cannot translate the template's `" + r.name + "`: " + what));
    }
    if (!found.empty()) throw CompileError{found};
}

// What naga reads: no OpLine, and function names without glslang's signatures.
NagaResult naga(const std::vector<uint32_t>& spirv) { return nagaWgsl(plainFunctionNames(withoutLines(spirv))); }

std::string translated(const std::vector<uint32_t>& spirv, const ShaderPlan& plan) {
    NagaResult r = naga(spirv);
    if (r.wgsl) return *r.wgsl;
    const SourceLoc at = r.unavailable ? SourceLoc{} : SourceLoc{plan.templateShown, 0, 0};  // a missing tool is no file's fault
    throw CompileError{{Diagnostic::make(Code::TargetUnsupported, at, "",
                                         r.unavailable ? r.error : "naga cannot translate the shader to WGSL: " + r.error)}};
}

}  // namespace

TargetOutput emitWgsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions&) {
    refuseUntranslatable(spirv, plan);
    TargetOutput out;
    out.source = translated(spirv, plan);
    out.entryPoint = plan.entryPoint;
    const HexcBindings& b = plan.bindings;
    Locate locate = [&b](ResourceKind kind, uint32_t index) -> nlohmann::json {
        const uint32_t binding = kind == ResourceKind::Params    ? b.params
                                 : kind == ResourceKind::Sampler ? b.sampler
                                                                 : b.firstTexture + index;
        return {{"group", b.set}, {"binding", binding}};
    };
    IoName none = [](uint32_t, bool) { return nlohmann::json(); };  // naga keeps each location: @location(N)
    nlohmann::json placed = nlohmann::json::array();
    for (const TemplateResource& r : templateResources(spirv_cross::Compiler(spirv), plan)) {
        nlohmann::json where = describe(r);
        where["group"] = r.set;
        where["binding"] = r.binding;
        placed.push_back(std::move(where));
    }
    out.target = describeTarget(spirv, plan, out.entryPoint, locate, none, placed);
    return out;
}

TargetOutput vertexWgsl(const std::vector<uint32_t>& spirv, const CompileOptions&, const std::string& entry) {
    NagaResult r = naga(spirv);
    if (!r.wgsl) throw CompileError{{Diagnostic::make(Code::TargetUnsupported, {}, "", "the wgsl vertex stage: " + r.error)}};
    return {*r.wgsl, entry, {}};
}

std::string wgslWithoutStage(const std::string& wgsl, const std::string& entry) {
    std::istringstream in(wgsl);
    std::string out, line, attributes;
    bool inBody = false;
    while (std::getline(in, line) && !line.starts_with("@fragment")) {
        if (line.starts_with("@group(")) {  // naga puts a resource's @group and @binding on a line of their own
            attributes = line;
            continue;
        }
        line = attributes + line, attributes.clear();
        if (line == "fn " + entry + "_1() {") inBody = true;
        if (!inBody && !line.starts_with("var<private> ")) out += line + "\n";
        if (inBody && line == "}") inBody = false;
    }
    return out;
}

std::string libraryWgsl(const std::vector<uint32_t>& spirv) {
    NagaResult r = naga(spirv);
    if (!r.wgsl) throw CompileError{{Diagnostic::make(Code::TargetUnsupported, {}, "", r.unavailable ? r.error : "naga: " + r.error)}};
    return wgslWithoutStage(*r.wgsl, "main");
}

}  // namespace hexc
