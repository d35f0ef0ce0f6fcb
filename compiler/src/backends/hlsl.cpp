// HLSL: by default the cbuffer in b0, the shared sampler in s0, slot i's texture in t<i>, all in space0 (the
// layout moves each class and the space); the template's own resources after them, in the same space.
#include <spirv_hlsl.hpp>

#include "backends/backends.h"

namespace hexc {
namespace {

// The template's resources after hexc's, each register class counted on from hexc's last, in hexc's space.
template <typename Binding>
nlohmann::json placeTemplateResources(spirv_cross::CompilerHLSL& c, const ShaderPlan& plan, Binding binding) {
    const ResourceLayout::Hlsl& l = plan.layout.hlsl;
    uint32_t next[4] = {l.b + 1, l.t + uint32_t(plan.textureCount()), l.s + 1, l.u};  // b, t, s, u
    auto take = [&](char cls) { return next[std::string_view("btsu").find(cls)]++; };
    nlohmann::json placed = nlohmann::json::array();
    for (const TemplateResource& r : templateResources(c, plan)) {
        const bool push = r.cls == ResourceClass::PushConstant;
        spirv_cross::HLSLResourceBinding b =
            push ? binding(spirv_cross::ResourceBindingPushConstantDescriptorSet, spirv_cross::ResourceBindingPushConstantBinding)
                 : binding(r.set, r.binding);
        nlohmann::json where = describe(r);
        auto assign = [&](spirv_cross::HLSLResourceBinding::Binding& field, char cls, const char* key) {
            field.register_binding = take(cls);
            field.register_space = l.space;
            where[key] = cls + std::to_string(field.register_binding);
        };
        switch (r.cls) {
            case ResourceClass::UniformBuffer:
            case ResourceClass::PushConstant:
                assign(b.cbv, 'b', "register");
                break;
            case ResourceClass::CombinedImageSampler:
                assign(b.srv, 't', "register"), assign(b.sampler, 's', "sampler_register");
                break;
            case ResourceClass::SampledImage:
                assign(b.srv, 't', "register");
                break;
            case ResourceClass::Sampler:
                assign(b.sampler, 's', "register");
                break;
            case ResourceClass::StorageBuffer:
            case ResourceClass::StorageImage:
                assign(b.uav, 'u', "register");
                break;
        }
        where["space"] = l.space;
        c.add_hlsl_resource_binding(b);
        placed.push_back(std::move(where));
    }
    return placed;
}

}  // namespace

void renameHlslEntry(std::string& source, const std::string& entry) {
    for (std::string_view head : {"\nSPIRV_Cross_Output main(", "\nvoid main("})
        if (size_t at = source.find(head); at != std::string::npos) {
            source.replace(at + head.size() - 5, 4, entry);
            return;
        }
}

void configureHlsl(spirv_cross::CompilerHLSL& c, const CompileOptions& options) {
    spirv_cross::CompilerHLSL::Options hlsl;
    hlsl.shader_model = options.hlslShaderModel;
    c.set_hlsl_options(hlsl);
    spirv_cross::CompilerGLSL::Options common = c.get_common_options();
    common.emit_line_directives = options.debug;
    c.set_common_options(common);
}

TargetOutput emitHlsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options) {
    spirv_cross::CompilerHLSL c(spirv);
    configureHlsl(c, options);
    const ResourceLayout::Hlsl& l = plan.layout.hlsl;
    if (l.space != 0 && options.hlslShaderModel < 51)
        throw CompileError{{Diagnostic::make(
            Code::TargetUnsupported, {plan.layout.sourceFile.empty() ? "--hlsl-space" : plan.layout.sourceFile.string()}, "",
            "HLSL register space " + std::to_string(l.space) + " needs shader model 5.1 or later (--hlsl-sm 51); 5.0 has no spaces")}};
    auto binding = [](uint32_t set, uint32_t b) {
        spirv_cross::HLSLResourceBinding r;
        r.stage = spv::ExecutionModelFragment;
        r.desc_set = set;
        r.binding = b;
        return r;
    };
    const HexcBindings& hexcs = plan.bindings;
    spirv_cross::HLSLResourceBinding params = binding(hexcs.set, hexcs.params), sampler = binding(hexcs.set, hexcs.sampler);
    params.cbv = {l.space, l.b};
    sampler.sampler = {l.space, l.s};
    c.add_hlsl_resource_binding(params);
    c.add_hlsl_resource_binding(sampler);
    for (uint32_t i = 0; i < plan.textureCount(); ++i) {
        spirv_cross::HLSLResourceBinding texture = binding(hexcs.set, hexcs.firstTexture + i);
        texture.srv = {l.space, l.t + i};
        c.add_hlsl_resource_binding(texture);
    }
    nlohmann::json placed = placeTemplateResources(c, plan, binding);

    TargetOutput out;
    out.source = c.compile();
    renameHlslEntry(out.source, plan.entryPoint);
    out.entryPoint = plan.entryPoint;
    Locate locate = [&l](ResourceKind kind, uint32_t index) -> nlohmann::json {
        std::string reg = kind == ResourceKind::Params    ? "b" + std::to_string(l.b)
                          : kind == ResourceKind::Sampler ? "s" + std::to_string(l.s)
                                                          : "t" + std::to_string(l.t + index);
        return {{"register", reg}, {"space", l.space}};
    };
    // SPIRV-Cross names user varyings TEXCOORD<location>; the colour output is SV_Target<location>.
    IoName semantic = [](uint32_t location, bool input) -> nlohmann::json {
        return {{"semantic", (input ? "TEXCOORD" : "SV_Target") + std::to_string(location)}};
    };
    out.target = describeTarget(spirv, plan, out.entryPoint, locate, semantic, placed);
    out.target["shader_model"] = std::to_string(options.hlslShaderModel / 10) + "_" + std::to_string(options.hlslShaderModel % 10);
    out.target["profile"] = "ps_" + out.target["shader_model"].get<std::string>();
    return out;
}

}  // namespace hexc
