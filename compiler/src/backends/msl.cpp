// MSL: by default the parameter block in [[buffer(0)]], the shared sampler in [[sampler(0)]], slot i's texture in
// [[texture(i)]] (the layout moves each base); the template's own resources after them.
#include <spirv_msl.hpp>

#include "backends/backends.h"

namespace hexc {

void configureMsl(spirv_cross::CompilerMSL& c, const CompileOptions& options) {
    spirv_cross::CompilerMSL::Options msl;
    msl.set_msl_version(options.mslMajor, options.mslMinor);
    c.set_msl_options(msl);
    spirv_cross::CompilerGLSL::Options common = c.get_common_options();
    common.emit_line_directives = options.debug;
    c.set_common_options(common);
}

TargetOutput emitMsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options) {
    spirv_cross::CompilerMSL c(spirv);
    configureMsl(c, options);
    const ResourceLayout::Msl& l = plan.layout.msl;
    auto bind = [&](uint32_t binding, uint32_t buffer, uint32_t texture, uint32_t sampler) {
        spirv_cross::MSLResourceBinding b;
        b.stage = spv::ExecutionModelFragment;
        b.desc_set = plan.bindings.set;
        b.binding = binding;
        b.count = 1;
        b.msl_buffer = buffer;
        b.msl_texture = texture;
        b.msl_sampler = sampler;
        c.add_msl_resource_binding(b);
    };
    bind(plan.bindings.params, l.buffer, 0, 0);
    bind(plan.bindings.sampler, 0, 0, l.sampler);
    for (uint32_t i = 0; i < plan.slots.size(); ++i) bind(plan.slots[i].binding, 0, l.texture + i, 0);
    // The template's resources after hexc's last buffer, texture and sampler.
    uint32_t buffer = l.buffer + 1, texture = l.texture + uint32_t(plan.slots.size()), sampler = l.sampler + 1;
    nlohmann::json placed = nlohmann::json::array();
    for (const TemplateResource& r : templateResources(c, plan)) {
        spirv_cross::MSLResourceBinding b;
        b.stage = spv::ExecutionModelFragment;
        const bool push = r.cls == ResourceClass::PushConstant;
        b.desc_set = push ? spirv_cross::ResourceBindingPushConstantDescriptorSet : r.set;
        b.binding = push ? spirv_cross::ResourceBindingPushConstantBinding : r.binding;
        b.count = 1;
        nlohmann::json where = describe(r);
        const bool textured = r.cls == ResourceClass::SampledImage || r.cls == ResourceClass::Image || r.cls == ResourceClass::StorageImage;
        const bool sampling = r.cls == ResourceClass::SampledImage || r.cls == ResourceClass::Sampler;
        if (textured) where["texture"] = b.msl_texture = texture++;
        if (sampling) where["sampler"] = b.msl_sampler = sampler++;
        if (!textured && !sampling) where["buffer"] = b.msl_buffer = buffer++;
        c.add_msl_resource_binding(b);
        placed.push_back(std::move(where));
    }

    TargetOutput out;
    out.source = c.compile();
    out.entryPoint = c.get_cleansed_entry_point_name(plan.entryPoint, spv::ExecutionModelFragment);
    Locate locate = [&l](ResourceKind kind, uint32_t index) -> nlohmann::json {
        if (kind == ResourceKind::Params) return {{"buffer", l.buffer}};
        if (kind == ResourceKind::Sampler) return {{"sampler", l.sampler}};
        return {{"texture", l.texture + index}};
    };
    // SPIRV-Cross gives user varyings [[user(locn<location>)]] and colour outputs [[color(<location>)]].
    IoName attribute = [](uint32_t location, bool input) -> nlohmann::json {
        return {{"attribute", (input ? "user(locn" : "color(") + std::to_string(location) + ")"}};
    };
    out.target = describeTarget(spirv, plan, out.entryPoint, locate, attribute, placed);
    out.target["msl_version"] = std::to_string(options.mslMajor) + "." + std::to_string(options.mslMinor);
    return out;
}

}  // namespace hexc
