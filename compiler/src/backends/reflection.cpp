#include <spirv_cross.hpp>

#include <algorithm>
#include <tuple>

#include "backends/backends.h"
#include "common/by_enum.h"
#include "hexc/diagnostics.h"

namespace hexc {
namespace {

std::string typeName(const spirv_cross::SPIRType& type) {
    std::string base = type.basetype == spirv_cross::SPIRType::Float ? "" : type.basetype == spirv_cross::SPIRType::Int ? "i" : "u";
    return type.vecsize == 1 ? (base.empty() ? "float" : base == "i" ? "int" : "uint") : base + "vec" + std::to_string(type.vecsize);
}

nlohmann::json stageVariables(const spirv_cross::Compiler& c, const spirv_cross::SmallVector<spirv_cross::Resource>& vars, bool input,
                              IoName ioName) {
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

// The line of the template that first names `name` (1 when none does), for a located error.
int lineNaming(const std::string& source, const std::string& name) {
    size_t at = source.find(name);
    return at == std::string::npos ? 1 : 1 + int(std::count(source.begin(), source.begin() + std::ptrdiff_t(at), '\n'));
}

// hexc's own resources: its block, sampler and textures at their bindings in hexc's set, under its names.
bool isHexcs(const TemplateResource& r, const HexcBindings& b, size_t textures) {
    const bool named = r.set == b.set && (r.name.starts_with("hexc") || r.name == "HexcParams");
    switch (r.cls) {
        case ResourceClass::UniformBuffer:
            return named && r.binding == b.params;
        case ResourceClass::Sampler:
            return named && r.binding == b.sampler;
        case ResourceClass::SampledImage:
        case ResourceClass::CombinedImageSampler:  // the SPIR-V output's, with layout vulkan.combined
            return named && r.binding >= b.firstTexture && r.binding < b.firstTexture + textures;
        default:
            return false;
    }
}

// A template resource at one of the bindings hexc's layout takes (HX210).
CompileError bindingConflict(const TemplateResource& t, const ShaderPlan& plan) {
    const HexcBindings& b = plan.bindings;
    const std::string last = std::to_string(b.firstTexture + plan.textureCount() - 1);
    return CompileError{{Diagnostic::make(
        Code::TemplateSetConflict, {plan.templateName, lineNaming(plan.templateSource, t.name), 0}, "",
        "`" + t.name + "` is in descriptor set " + std::to_string(t.set) + ", binding " + std::to_string(t.binding) +
            ", which hexc's layout takes (set " + std::to_string(b.set) + ", bindings " + std::to_string(b.params) + "-" +
            (plan.slots.empty() ? std::to_string(b.sampler) : last) +
            ": parameter block, sampler, textures); give it another set or binding, or move hexc's with --set/--binding")}};
}

// The manifest's `kind` of a resource: Vulkan's descriptor type in lower case (push_constant apart).
const char* toString(ResourceClass cls) {
    static constexpr auto names = byEnum<ResourceClass::StorageImage>(
        {"uniform_buffer", "storage_buffer", "push_constant", "combined_image_sampler", "sampled_image", "sampler", "storage_image"});
    return names[size_t(cls)];
}

// Vulkan's name of a descriptor type, without VK_DESCRIPTOR_TYPE_: "COMBINED_IMAGE_SAMPLER".
std::string descriptorType(ResourceClass cls) {
    std::string name = toString(cls);
    std::transform(name.begin(), name.end(), name.begin(), [](char c) { return char(std::toupper(c)); });
    return name;
}

// A push constant block's byte range: from its first member's offset to the end of its last.
void pushConstantRange(const spirv_cross::Compiler& c, const spirv_cross::Resource& r, TemplateResource& t) {
    const spirv_cross::SPIRType& type = c.get_type(r.base_type_id);
    t.offset = type.member_types.empty() ? 0 : c.type_struct_member_offset(type, 0);
    t.size = uint32_t(c.get_declared_struct_size(type)) - t.offset;
}

}  // namespace

std::vector<TemplateResource> templateResources(const spirv_cross::Compiler& c, const ShaderPlan& plan) {
    spirv_cross::ShaderResources res = c.get_shader_resources();
    const std::pair<ResourceClass, const spirv_cross::SmallVector<spirv_cross::Resource>*> lists[] = {
        {ResourceClass::UniformBuffer, &res.uniform_buffers},      {ResourceClass::StorageBuffer, &res.storage_buffers},
        {ResourceClass::PushConstant, &res.push_constant_buffers}, {ResourceClass::CombinedImageSampler, &res.sampled_images},
        {ResourceClass::SampledImage, &res.separate_images},       {ResourceClass::Sampler, &res.separate_samplers},
        {ResourceClass::StorageImage, &res.storage_images}};
    std::vector<TemplateResource> out;
    for (const auto& [cls, list] : lists)
        for (const spirv_cross::Resource& r : *list) {
            TemplateResource t{r.id, r.name, cls, c.get_decoration(r.id, spv::DecorationDescriptorSet),
                               c.get_decoration(r.id, spv::DecorationBinding)};
            if (cls == ResourceClass::PushConstant) {
                t.name = c.get_name(r.base_type_id);  // its block's name, as for the other blocks
                pushConstantRange(c, r, t);
                out.push_back(std::move(t));
                continue;
            }
            if (isHexcs(t, plan.bindings, plan.textureCount())) continue;
            const uint32_t end = plan.bindings.firstTexture + uint32_t(plan.textureCount());
            if (t.set == plan.bindings.set && t.binding >= plan.bindings.params && t.binding < end) throw bindingConflict(t, plan);
            out.push_back(std::move(t));
        }
    std::stable_sort(out.begin(), out.end(), [](const TemplateResource& a, const TemplateResource& b) {
        return std::tie(a.cls, a.set, a.binding) < std::tie(b.cls, b.set, b.binding);
    });
    return out;
}

nlohmann::json describe(const TemplateResource& r) {
    nlohmann::json j = {{"name", r.name}, {"kind", toString(r.cls)}};
    if (r.cls == ResourceClass::PushConstant) {
        j["offset"] = r.offset;
        j["size"] = r.size;
    } else {
        j["vulkan"] = {{"set", r.set}, {"binding", r.binding}, {"descriptor_type", descriptorType(r.cls)}};
    }
    return j;
}

nlohmann::json describeTarget(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const std::string& entryPoint, Locate locate,
                              IoName ioName, const nlohmann::json& placed) {
    spirv_cross::Compiler c(spirv);
    spirv_cross::ShaderResources res = c.get_shader_resources();
    nlohmann::json t = {{"entry_point", entryPoint}, {"stage", "fragment"}};
    if (!plan.slots.empty()) {
        // The block layout the optimiser kept must be the one the plan laid out: engines fill it by offset. Only
        // hexc's own block: the template's are the template's.
        bool hexcBlock = false;
        for (const auto& ubo : res.uniform_buffers) {
            if (c.get_decoration(ubo.id, spv::DecorationDescriptorSet) != plan.bindings.set ||
                c.get_decoration(ubo.id, spv::DecorationBinding) != plan.bindings.params)
                continue;
            hexcBlock = true;
            const auto& type = c.get_type(ubo.base_type_id);
            for (uint32_t i = 0; i < type.member_types.size(); ++i) {
                if (plan.params[i].constantId || c.type_struct_member_offset(type, i) != plan.params[i].offset)
                    throw CompileError{
                        {Diagnostic::make(Code::Internal, {"hexc"}, "", "internal: parameter block layout differs from the plan")}};
            }
        }
        if (hexcBlock) t["params"] = locate(ResourceKind::Params, 0);
        t["sampler"] = locate(ResourceKind::Sampler, 0);
        nlohmann::json textures = nlohmann::json::object();
        for (size_t i = 0; i < plan.textureCount(); ++i)
            if (plan.textureBound(i)) textures[plan.textureName(i)] = locate(ResourceKind::Texture, uint32_t(i));
        t["textures"] = textures;
    }
    if (!placed.empty()) t["template_resources"] = placed;
    t["inputs"] = stageVariables(c, res.stage_inputs, true, ioName);
    t["outputs"] = stageVariables(c, res.stage_outputs, false, ioName);
    return t;
}

std::vector<Varying> fragmentInputs(const std::vector<uint32_t>& spirv) {
    spirv_cross::Compiler c(spirv);
    std::vector<Varying> out;
    for (const auto& r : c.get_shader_resources().stage_inputs)
        out.push_back({r.name, typeName(c.get_type(r.type_id)), c.get_decoration(r.id, spv::DecorationLocation)});
    std::sort(out.begin(), out.end(), [](const Varying& a, const Varying& b) { return a.location < b.location; });
    return out;
}

TargetOutput describeSpirv(const std::vector<uint32_t>& spirv, const ShaderPlan& plan) {
    TargetOutput out;
    out.entryPoint = plan.entryPoint;
    const HexcBindings& b = plan.bindings;
    const bool combined = plan.layout.vulkan.combined != 0;
    Locate locate = [&b, combined](ResourceKind kind, uint32_t index) -> nlohmann::json {
        if (kind == ResourceKind::Sampler && combined) return {{"combined_into_textures", true}};
        uint32_t binding = kind == ResourceKind::Params ? b.params : kind == ResourceKind::Sampler ? b.sampler : b.firstTexture + index;
        const ResourceClass cls = kind == ResourceKind::Params    ? ResourceClass::UniformBuffer
                                  : kind == ResourceKind::Sampler ? ResourceClass::Sampler
                                  : combined                      ? ResourceClass::CombinedImageSampler
                                                                  : ResourceClass::SampledImage;
        return {{"set", b.set}, {"binding", binding}, {"descriptor_type", descriptorType(cls)}};
    };
    IoName none = [](uint32_t, bool) { return nlohmann::json(); };
    nlohmann::json placed = nlohmann::json::array();
    for (const TemplateResource& r : templateResources(spirv_cross::Compiler(spirv), plan)) placed.push_back(describe(r));
    out.target = describeTarget(spirv, plan, out.entryPoint, locate, none, placed);
    return out;
}

}  // namespace hexc
