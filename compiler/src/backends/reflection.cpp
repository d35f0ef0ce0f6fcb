#include <spirv_cross.hpp>

#include "backends/backends.h"
#include "hexc/diagnostics.h"

namespace hexc {
namespace {

std::string typeName(const spirv_cross::SPIRType& type) {
    std::string base = type.basetype == spirv_cross::SPIRType::Float ? "" : type.basetype == spirv_cross::SPIRType::Int ? "i" : "u";
    return type.vecsize == 1 ? (base.empty() ? "float" : base == "i" ? "int" : "uint") : base + "vec" + std::to_string(type.vecsize);
}

nlohmann::json stageVariables(const spirv_cross::Compiler& c, const spirv_cross::SmallVector<spirv_cross::Resource>& vars,
                              bool input, IoName ioName) {
    std::vector<std::pair<uint32_t, nlohmann::json>> sorted;
    for (const auto& r : vars) {
        uint32_t location = c.get_decoration(r.id, spv::DecorationLocation);
        nlohmann::json v = {{"name", r.name}, {"location", location}, {"type", typeName(c.get_type(r.type_id))}};
        if (nlohmann::json extra = ioName(location, input); !extra.is_null()) v.update(extra);
        sorted.emplace_back(location, std::move(v));
    }
    std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    nlohmann::json out = nlohmann::json::array();
    for (auto& [location, v] : sorted) out.push_back(std::move(v));
    return out;
}

}  // namespace

nlohmann::json describeTarget(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const std::string& entryPoint,
                              Locate locate, IoName ioName) {
    spirv_cross::Compiler c(spirv);
    spirv_cross::ShaderResources res = c.get_shader_resources();
    nlohmann::json t = {{"entry_point", entryPoint}, {"stage", "fragment"}};
    if (!plan.slots.empty()) {
        // The block layout the optimiser kept must be the one the plan laid out: engines fill it by offset.
        for (const auto& ubo : res.uniform_buffers) {
            const auto& type = c.get_type(ubo.base_type_id);
            for (uint32_t i = 0; i < type.member_types.size(); ++i) {
                if (plan.params[i].constantId || c.type_struct_member_offset(type, i) != plan.params[i].offset)
                    throw CompileError{{{Diagnostic::Severity::Error, {"hexc", 0, 0}, "", "internal: parameter block layout differs from the plan", {}}}};
            }
        }
        if (!res.uniform_buffers.empty()) t["params"] = locate(ResourceKind::Params, 0);
        t["sampler"] = locate(ResourceKind::Sampler, 0);
        nlohmann::json textures = nlohmann::json::object();
        for (size_t i = 0; i < plan.slots.size(); ++i) textures[plan.slots[i].slot->name] = locate(ResourceKind::Texture, uint32_t(i));
        t["textures"] = textures;
    }
    t["inputs"] = stageVariables(c, res.stage_inputs, true, ioName);
    t["outputs"] = stageVariables(c, res.stage_outputs, false, ioName);
    return t;
}

TargetOutput describeSpirv(const std::vector<uint32_t>& spirv, const ShaderPlan& plan) {
    TargetOutput out;
    out.entryPoint = "main";
    Locate locate = [](ResourceKind kind, uint32_t index) -> nlohmann::json {
        uint32_t binding = kind == ResourceKind::Params ? kParamsBinding : kind == ResourceKind::Sampler ? kSamplerBinding : kFirstTextureBinding + index;
        return {{"set", 0}, {"binding", binding}};
    };
    IoName none = [](uint32_t, bool) { return nlohmann::json(); };
    out.target = describeTarget(spirv, plan, out.entryPoint, locate, none);
    return out;
}

}  // namespace hexc
