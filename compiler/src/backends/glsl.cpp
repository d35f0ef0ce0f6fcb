// OpenGL GLSL (450, 330) and GLSL ES (310). OpenGL has no separate samplers, so each texture is
// combined with the shared sampler into a sampler2D named hexcTex_<slot> on texture unit i; the
// parameter block is uniform block binding 0. GLSL 330 has no layout(binding): the engine binds by
// name (the manifest says so), instead of hexc requiring GL_ARB_shading_language_420pack.
#include <spirv_glsl.hpp>

#include "backends/backends.h"

namespace hexc {
namespace {

bool hasBindingQualifiers(const CompileOptions& options) { return options.glslEs || options.glslVersion >= 420; }

}  // namespace

TargetOutput emitGlsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options) {
    spirv_cross::CompilerGLSL c(spirv);
    spirv_cross::CompilerGLSL::Options glsl;
    glsl.version = options.glslVersion;
    glsl.es = options.glslEs;
    glsl.vulkan_semantics = false;
    glsl.enable_420pack_extension = false;
    c.set_common_options(glsl);

    c.build_combined_image_samplers();
    for (const auto& combined : c.get_combined_image_samplers()) {
        uint32_t binding = c.get_decoration(combined.image_id, spv::DecorationBinding);
        c.set_name(combined.combined_id, c.get_name(combined.image_id));
        c.set_decoration(combined.combined_id, spv::DecorationBinding, binding - kFirstTextureBinding);
    }
    if (!hasBindingQualifiers(options)) {
        for (const auto& r : c.get_shader_resources().sampled_images) c.unset_decoration(r.id, spv::DecorationBinding);
        for (const auto& r : c.get_shader_resources().uniform_buffers) c.unset_decoration(r.id, spv::DecorationBinding);
    }

    TargetOutput out;
    out.source = c.compile();
    out.entryPoint = "main";
    Locate locate = hasBindingQualifiers(options)
                        ? Locate([](ResourceKind kind, uint32_t index) -> nlohmann::json {
                              if (kind == ResourceKind::Params) return {{"uniform_block", "HexcParams"}, {"binding", 0}};
                              if (kind == ResourceKind::Sampler) return {{"combined_into_textures", true}};
                              return {{"texture_unit", index}};
                          })
                        : Locate([](ResourceKind kind, uint32_t index) -> nlohmann::json {
                              if (kind == ResourceKind::Params) return {{"uniform_block", "HexcParams"}, {"bind_by_name", true}};
                              if (kind == ResourceKind::Sampler) return {{"combined_into_textures", true}};
                              return {{"texture_unit", index}, {"bind_by_name", true}};
                          });
    IoName none = [](uint32_t, bool) { return nlohmann::json(); };
    out.target = describeTarget(spirv, plan, out.entryPoint, locate, none);
    out.target["version"] = std::to_string(options.glslVersion) + (options.glslEs ? " es" : "");
    // Combined samplers keep the texture's name, so the uniform to bind is the slot's texture name.
    for (auto& [slot, where] : out.target["textures"].items()) where["uniform"] = "hexcTex_" + slot;
    return out;
}

}  // namespace hexc
