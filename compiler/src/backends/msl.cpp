// MSL: the parameter block in [[buffer(0)]], the shared sampler in [[sampler(0)]], slot i's texture in
// [[texture(i)]].
#include <spirv_msl.hpp>

#include "backends/backends.h"

namespace hexc {

TargetOutput emitMsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options) {
    spirv_cross::CompilerMSL c(spirv);
    spirv_cross::CompilerMSL::Options msl;
    msl.set_msl_version(options.mslMajor, options.mslMinor);
    c.set_msl_options(msl);
    auto bind = [&](uint32_t binding, uint32_t buffer, uint32_t texture, uint32_t sampler) {
        spirv_cross::MSLResourceBinding b;
        b.stage = spv::ExecutionModelFragment;
        b.desc_set = 0;
        b.binding = binding;
        b.count = 1;
        b.msl_buffer = buffer;
        b.msl_texture = texture;
        b.msl_sampler = sampler;
        c.add_msl_resource_binding(b);
    };
    bind(kParamsBinding, 0, 0, 0);
    bind(kSamplerBinding, 0, 0, 0);
    for (uint32_t i = 0; i < plan.slots.size(); ++i) bind(plan.slots[i].binding, 0, i, 0);

    TargetOutput out;
    out.source = c.compile();
    out.entryPoint = c.get_cleansed_entry_point_name("main", spv::ExecutionModelFragment);
    Locate locate = [](ResourceKind kind, uint32_t index) -> nlohmann::json {
        if (kind == ResourceKind::Params) return {{"buffer", 0}};
        if (kind == ResourceKind::Sampler) return {{"sampler", 0}};
        return {{"texture", index}};
    };
    // SPIRV-Cross gives user varyings [[user(locn<location>)]] and colour outputs [[color(<location>)]].
    IoName attribute = [](uint32_t location, bool input) -> nlohmann::json {
        return {{"attribute", (input ? "user(locn" : "color(") + std::to_string(location) + ")"}};
    };
    out.target = describeTarget(spirv, plan, out.entryPoint, locate, attribute);
    out.target["msl_version"] = std::to_string(options.mslMajor) + "." + std::to_string(options.mslMinor);
    return out;
}

}  // namespace hexc
