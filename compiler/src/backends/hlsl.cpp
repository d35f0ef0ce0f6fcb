// HLSL: cbuffer in b0, the shared sampler in s0, slot i's texture in t<i>, all in space0.
#include <spirv_hlsl.hpp>

#include "backends/backends.h"

namespace hexc {

TargetOutput emitHlsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options) {
    spirv_cross::CompilerHLSL c(spirv);
    spirv_cross::CompilerHLSL::Options hlsl;
    hlsl.shader_model = options.hlslShaderModel;
    c.set_hlsl_options(hlsl);
    auto bind = [&](uint32_t binding, auto member, uint32_t reg) {
        spirv_cross::HLSLResourceBinding b;
        b.stage = spv::ExecutionModelFragment;
        b.desc_set = 0;
        b.binding = binding;
        (b.*member).register_binding = reg;
        c.add_hlsl_resource_binding(b);
    };
    bind(kParamsBinding, &spirv_cross::HLSLResourceBinding::cbv, 0);
    bind(kSamplerBinding, &spirv_cross::HLSLResourceBinding::sampler, 0);
    for (uint32_t i = 0; i < plan.slots.size(); ++i) bind(plan.slots[i].binding, &spirv_cross::HLSLResourceBinding::srv, i);

    TargetOutput out;
    out.source = c.compile();
    out.entryPoint = c.get_cleansed_entry_point_name("main", spv::ExecutionModelFragment);
    Locate locate = [](ResourceKind kind, uint32_t index) -> nlohmann::json {
        std::string reg = kind == ResourceKind::Params ? "b0" : kind == ResourceKind::Sampler ? "s0" : "t" + std::to_string(index);
        return {{"register", reg}, {"space", 0}};
    };
    // SPIRV-Cross names user varyings TEXCOORD<location>; the colour output is SV_Target<location>.
    IoName semantic = [](uint32_t location, bool input) -> nlohmann::json {
        return {{"semantic", (input ? "TEXCOORD" : "SV_Target") + std::to_string(location)}};
    };
    out.target = describeTarget(spirv, plan, out.entryPoint, locate, semantic);
    out.target["shader_model"] = std::to_string(options.hlslShaderModel / 10) + "_" + std::to_string(options.hlslShaderModel % 10);
    out.target["profile"] = "ps_" + out.target["shader_model"].get<std::string>();
    return out;
}

}  // namespace hexc
