// OpenGL GLSL (460, 450, 330) and GLSL ES (310, 300 for WebGL 2). OpenGL has no separate samplers, so each texture is
// combined with the shared sampler into a sampler2D named hexcTex_<slot> on texture unit base + i; the
// parameter block is uniform block binding base (the layout's GLSL binding, 0 by default). GLSL 330 has no layout(binding): the engine binds by
// name (the manifest says so), instead of hexc requiring GL_ARB_shading_language_420pack; nor has GLSL ES 3.00.
#include <spirv_glsl.hpp>

#include <map>
#include <string_view>

#include "backends/backends.h"
#include "common/text.h"

namespace hexc {
namespace {

bool hasBindingQualifiers(const CompileOptions& options) { return options.glslVersion >= (options.glslEs ? 310u : 420u); }

// The template's blocks after hexc's (uniform block binding `base`), storage buffers and images from 0, its
// sampler2Ds on the texture units after `unit`; `units` holds those SPIRV-Cross combined from separate images.
nlohmann::json placeTemplateResources(spirv_cross::CompilerGLSL& c, const std::vector<TemplateResource>& own,
                                      std::map<uint32_t, uint32_t>& units, uint32_t base, uint32_t unit) {
    uint32_t block = base + 1, storage = 0, image = 0;
    nlohmann::json placed = nlohmann::json::array();
    for (const TemplateResource& r : own) {
        nlohmann::json where = describe(r);
        auto bind = [&](const char* key, uint32_t value) {
            c.set_decoration(r.id, spv::DecorationBinding, value);
            where[key] = value;
        };
        switch (r.cls) {
            case ResourceClass::UniformBuffer:
                bind("binding", block++);
                break;
            case ResourceClass::StorageBuffer:
                bind("binding", storage++);
                break;
            case ResourceClass::StorageImage:
                bind("image_unit", image++);
                break;
            case ResourceClass::CombinedImageSampler:
                bind("texture_unit", unit++);
                break;
            case ResourceClass::SampledImage:
                where["texture_unit"] = units[r.id];
                break;
            case ResourceClass::Sampler:
                where["combined_into_textures"] = true;
                break;
            case ResourceClass::PushConstant:
                where["uniform"] = c.get_name(r.id);
                break;  // a plain uniform struct in OpenGL
        }
        placed.push_back(std::move(where));
    }
    return placed;
}

}  // namespace

void configureGlsl(spirv_cross::CompilerGLSL& c, const CompileOptions& options) {
    spirv_cross::CompilerGLSL::Options glsl;
    glsl.version = options.glslVersion;
    glsl.es = options.glslEs;
    glsl.vulkan_semantics = false;
    glsl.enable_420pack_extension = false;
    glsl.emit_line_directives = emitsLineDirectives(options);
    c.set_common_options(glsl);
}

TargetOutput emitGlsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options) {
    spirv_cross::CompilerGLSL c(spirv);
    return emitGlsl(c, spirv, plan, options);
}

TargetOutput emitGlsl(spirv_cross::CompilerGLSL& c, const std::vector<uint32_t>& spirv, const ShaderPlan& plan,
                      const CompileOptions& options) {
    configureGlsl(c, options);

    std::vector<TemplateResource> own = templateResources(c, plan);
    c.build_combined_image_samplers();
    // hexc's textures on units base..base+n-1; the template's textures (combined by SPIRV-Cross or its own
    // sampler2D) after.
    const uint32_t base = plan.layout.glsl.binding;
    uint32_t unit = base + uint32_t(plan.textureCount());
    std::map<uint32_t, uint32_t> units;  // template image or sampled image id -> texture unit
    for (const auto& combined : c.get_combined_image_samplers()) {
        uint32_t binding = c.get_decoration(combined.image_id, spv::DecorationBinding);
        bool hexcs = c.get_decoration(combined.image_id, spv::DecorationDescriptorSet) == plan.bindings.set &&
                     binding >= plan.bindings.firstTexture && binding < plan.bindings.firstTexture + plan.textureCount();
        c.set_name(combined.combined_id, c.get_name(combined.image_id));
        if (!hexcs && !units.count(combined.image_id)) units[combined.image_id] = unit++;
        c.set_decoration(combined.combined_id, spv::DecorationBinding,
                         hexcs ? base + binding - plan.bindings.firstTexture : units[combined.image_id]);
    }
    for (const auto& ubo : c.get_shader_resources().uniform_buffers)
        if (c.get_decoration(ubo.id, spv::DecorationDescriptorSet) == plan.bindings.set &&
            c.get_decoration(ubo.id, spv::DecorationBinding) == plan.bindings.params)
            c.set_decoration(ubo.id, spv::DecorationBinding, base);
    nlohmann::json placed = placeTemplateResources(c, own, units, base, unit);
    if (!hasBindingQualifiers(options)) {
        for (const auto& r : c.get_shader_resources().sampled_images) c.unset_decoration(r.id, spv::DecorationBinding);
        for (const auto& r : c.get_shader_resources().uniform_buffers) c.unset_decoration(r.id, spv::DecorationBinding);
    }

    TargetOutput out;
    out.source = c.compile();
    out.entryPoint = "main";  // OpenGL has no other
    const bool byName = !hasBindingQualifiers(options);
    Locate locate = [base, byName](ResourceKind kind, uint32_t index) -> nlohmann::json {
        if (kind == ResourceKind::Sampler) return {{"combined_into_textures", true}};
        nlohmann::json where = kind == ResourceKind::Params ? nlohmann::json{{"uniform_block", "HexcParams"}, {"binding", base}}
                                                            : nlohmann::json{{"texture_unit", base + index}};
        if (byName) {
            where.erase("binding");
            where["bind_by_name"] = true;
        }
        return where;
    };
    IoName none = [](uint32_t, bool) { return nlohmann::json(); };
    out.target = describeTarget(spirv, plan, out.entryPoint, locate, none, placed);
    out.target["version"] = std::to_string(options.glslVersion) + (options.glslEs ? " es" : "");
    // Combined samplers keep the texture's name, so the uniform to bind is the texture's variable.
    for (size_t i = 0; i < plan.textureCount(); ++i)
        if (plan.textureBound(i)) out.target["textures"][plan.textureName(i)]["uniform"] = plan.textureVariable(i);
    return out;
}

TargetOutput vertexGlsl(const std::vector<uint32_t>& spirv, const CompileOptions& options, const std::string&) {
    spirv_cross::CompilerGLSL c(spirv);
    configureGlsl(c, options);
    return {c.compile(), "main", {}};
}

std::string libraryGlsl(const std::vector<uint32_t>& spirv) {
    spirv_cross::CompilerGLSL c(spirv);
    configureGlsl(c, CompileOptions());  // the default version, 450
    c.build_combined_image_samplers();
    // The entry's own combinations are globals named by SPIRV-Cross (`uniform sampler2D _3133;`): named after
    // their texture, hexcLib*, they are cut with the entry's other resources (GLSL compilers refuse orphans).
    for (const spirv_cross::CombinedImageSampler& s : c.get_combined_image_samplers())
        if (c.get_name(s.image_id).starts_with("hexcLib")) c.set_name(s.combined_id, c.get_name(s.image_id));
    // A function's combined parameter (SPIRV_Cross_Combined<texture><sampler>, the sampler hexc's `samp`) takes its
    // texture's name.
    const std::string text = c.compile(), prefix = "SPIRV_Cross_Combined", sampler = "samp";
    std::string out;
    size_t at = 0;
    for (size_t found; (found = text.find(prefix, at)) != std::string::npos;) {
        size_t end = found + prefix.size();
        while (end < text.size() && isIdentifierChar(text[end])) ++end;
        const std::string_view name(text.data() + found + prefix.size(), end - found - prefix.size());
        out.append(text, at, found - at);
        if (name.size() > sampler.size() && name.ends_with(sampler))
            out.append(name.substr(0, name.size() - sampler.size()));
        else
            out.append(text, found, end - found);
        at = end;
    }
    return out.append(text, at);
}

std::string settingsGlsl(const CompileOptions& options) {
    return "glsl " + std::to_string(options.glslVersion) + (options.glslEs ? " es" : "");
}

}  // namespace hexc
