// HLSL: by default the cbuffer in b0, the shared sampler in s0, slot i's texture in t<i>, all in space0 (the
// layout moves each class and the space); the template's own resources after them, in the same space, or where the
// layout's template bases and spaces put them.
#include <spirv_hlsl.hpp>

#include <map>
#include <set>
#include <tuple>

#include "backends/backends.h"

namespace hexc {
namespace {

// A located error for a layout that puts a template resource on one of hexc's registers (HX210).
CompileError registerConflict(const ShaderPlan& plan, const std::string& name, char cls, uint32_t reg, uint32_t space) {
    const std::string key = std::string("template_") + cls, file = plan.layout.sourceFile.string();
    return CompileError{{Diagnostic::make(Code::TemplateSetConflict, {file.empty() ? "--hlsl-template-" + std::string(1, cls) : file},
                                          file.empty() ? "" : "/hlsl/" + key,
                                          "`" + name + "` would take HLSL register " + cls + std::to_string(reg) + " in space " +
                                              std::to_string(space) + ", which one of hexc's resources takes; move the template's " + cls +
                                              " registers (hlsl." + key + ") or hexc's (hlsl." + cls + ")")}};
}

// The template's registers: in hexc's space, or with templateSpaces in the space of the resource's Vulkan set; each
// class from the layout's template base, else (in hexc's space) after hexc's last register of that class.
class TemplateRegisters {
public:
    explicit TemplateRegisters(const ShaderPlan& plan) : plan_(plan), l_(plan.layout.hlsl) {
        hexcs_ = {{l_.space, 'b', l_.b}, {l_.space, 's', l_.s}};
        for (uint32_t i = 0; i < plan.textureCount(); ++i) hexcs_.insert({l_.space, 't', l_.t + i});
    }
    uint32_t space(const TemplateResource& r) const { return l_.templateSpaces && r.cls != ResourceClass::PushConstant ? r.set : l_.space; }
    uint32_t take(const TemplateResource& r, char cls) {
        const uint32_t in = space(r);
        const uint32_t reg = next_.try_emplace({in, cls}, first(in, cls)).first->second++;
        if (hexcs_.count({in, cls, reg})) throw registerConflict(plan_, r.name, cls, reg, in);
        return reg;
    }

private:
    uint32_t first(uint32_t space, char cls) const {
        const size_t k = std::string_view("btsu").find(cls);
        const uint32_t bases[4] = {l_.templateB, l_.templateT, l_.templateS, l_.templateU};
        const uint32_t after[4] = {l_.b + 1, l_.t + uint32_t(plan_.textureCount()), l_.s + 1, l_.u};
        return bases[k] != ResourceLayout::kAfterHexc ? bases[k] : space == l_.space ? after[k] : 0;
    }
    const ShaderPlan& plan_;
    const ResourceLayout::Hlsl& l_;
    std::set<std::tuple<uint32_t, char, uint32_t>> hexcs_;  // space, class, register
    std::map<std::pair<uint32_t, char>, uint32_t> next_;    // the next free register per space and class
};

// The template's resources where TemplateRegisters puts them.
template <typename Binding>
nlohmann::json placeTemplateResources(spirv_cross::CompilerHLSL& c, const ShaderPlan& plan, Binding binding) {
    TemplateRegisters registers(plan);
    nlohmann::json placed = nlohmann::json::array();
    for (const TemplateResource& r : templateResources(c, plan)) {
        const bool push = r.cls == ResourceClass::PushConstant;
        spirv_cross::HLSLResourceBinding b =
            push ? binding(spirv_cross::ResourceBindingPushConstantDescriptorSet, spirv_cross::ResourceBindingPushConstantBinding)
                 : binding(r.set, r.binding);
        nlohmann::json where = describe(r);
        auto assign = [&](spirv_cross::HLSLResourceBinding::Binding& field, char cls, const char* key) {
            field.register_binding = registers.take(r, cls);
            field.register_space = registers.space(r);
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
        where["space"] = registers.space(r);
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
    common.emit_line_directives = emitsLineDirectives(options);
    c.set_common_options(common);
}

TargetOutput emitHlsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options) {
    spirv_cross::CompilerHLSL c(spirv);
    configureHlsl(c, options);
    const ResourceLayout::Hlsl& l = plan.layout.hlsl;
    if ((l.space != 0 || l.templateSpaces) && options.hlslShaderModel < 51)
        throw CompileError{{Diagnostic::make(
            Code::TargetUnsupported, {plan.layout.sourceFile.empty() ? "--hlsl-space" : plan.layout.sourceFile.string()}, "",
            (l.space != 0 ? "HLSL register space " + std::to_string(l.space) : std::string("hlsl.template_spaces")) +
                " needs shader model 5.1 or later (--hlsl-sm 51); 5.0 has no spaces")}};
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

TargetOutput vertexHlsl(const std::vector<uint32_t>& spirv, const CompileOptions& options, const std::string& entry) {
    spirv_cross::CompilerHLSL c(spirv);
    configureHlsl(c, options);
    TargetOutput out{c.compile(), entry, {}};
    renameHlslEntry(out.source, entry);
    return out;
}

std::string libraryHlsl(const std::vector<uint32_t>& spirv) {
    spirv_cross::CompilerHLSL c(spirv);
    configureHlsl(c, CompileOptions());  // the default shader model, 5.0
    return c.compile();
}

std::string settingsHlsl(const CompileOptions& options) {
    return "hlsl sm " + std::to_string(options.hlslShaderModel / 10) + "." + std::to_string(options.hlslShaderModel % 10);
}

}  // namespace hexc
