// MSL: by default the parameter block in [[buffer(0)]], the shared sampler in [[sampler(0)]], slot i's texture in
// [[texture(i)]] (the layout moves each base); the template's own resources after them. Or argument buffers.
#include <spirv_msl.hpp>

#include <algorithm>
#include <map>
#include <mutex>
#include <tuple>

#include "backends/backends.h"
#include "spirv/strings.h"

namespace hexc {

void configureMsl(spirv_cross::CompilerMSL& c, const CompileOptions& options) {
    spirv_cross::CompilerMSL::Options msl;
    msl.set_msl_version(options.mslMajor, options.mslMinor);
    msl.argument_buffers = options.layout.msl.argumentBuffers != 0;
    c.set_msl_options(msl);
    spirv_cross::CompilerGLSL::Options common = c.get_common_options();
    common.emit_line_directives = emitsLineDirectives(options);
    c.set_common_options(common);
}

std::string mslEntryName(const std::string& entry) {
    static std::mutex mutex;
    static std::map<std::string, std::string> known;
    std::lock_guard lock(mutex);
    if (auto it = known.find(entry); it != known.end()) return it->second;
    // SPIRV-Cross renames an entry point MSL reserves (`main` -> `main0`, Metal's library functions) when it
    // compiles: asked of an empty fragment shader of that name, so the list stays SPIRV-Cross's own.
    std::vector<uint32_t> words = {0x07230203, 0x00010000, 0, 5, 0};  // SPIR-V 1.0, ids below 5
    auto op = [&words](uint32_t opcode, const std::vector<uint32_t>& operands) {
        words.push_back(uint32_t(operands.size() + 1) << 16 | opcode);
        words.insert(words.end(), operands.begin(), operands.end());
    };
    std::vector<uint32_t> entryPoint = {4, 3};  // Fragment %3 "entry"
    const std::vector<uint32_t> name = spirvString(entry);
    entryPoint.insert(entryPoint.end(), name.begin(), name.end());
    op(17, {1});           // OpCapability Shader
    op(14, {0, 1});        // OpMemoryModel Logical GLSL450
    op(15, entryPoint);    // OpEntryPoint
    op(16, {3, 7});        // OpExecutionMode %3 OriginUpperLeft
    op(19, {1});           // %1 = OpTypeVoid
    op(33, {2, 1});        // %2 = OpTypeFunction %1
    op(54, {1, 3, 0, 2});  // %3 = OpFunction %1 None %2
    op(248, {4});          // %4 = OpLabel
    op(253, {});           // OpReturn
    op(56, {});            // OpFunctionEnd
    spirv_cross::CompilerMSL c(std::move(words));
    c.compile();
    return known[entry] = c.get_cleansed_entry_point_name(entry, spv::ExecutionModelFragment);
}

namespace {

spirv_cross::MSLResourceBinding fragmentBinding(uint32_t set, uint32_t binding) {
    spirv_cross::MSLResourceBinding b;
    b.stage = spv::ExecutionModelFragment;
    b.desc_set = set;
    b.binding = binding;
    b.count = 1;
    return b;
}

// What a template resource of class `c` takes in MSL: a texture, a sampler (a sampler2D both), else a buffer.
bool takesTexture(ResourceClass c) {
    return c == ResourceClass::CombinedImageSampler || c == ResourceClass::SampledImage || c == ResourceClass::StorageImage;
}
bool takesSampler(ResourceClass c) { return c == ResourceClass::CombinedImageSampler || c == ResourceClass::Sampler; }

// Where each resource went, by (set, binding): the manifest's address of it.
using Placed = std::map<std::pair<uint32_t, uint32_t>, nlohmann::json>;

// hexc's resources at the layout's bases; the template's from the layout's template bases, else after hexc's last
// buffer, texture and sampler. A template index hexc's resource takes is a located error (HX210).
Placed placeDirect(spirv_cross::CompilerMSL& c, const ShaderPlan& plan, const std::vector<TemplateResource>& own) {
    const ResourceLayout::Msl& l = plan.layout.msl;
    const uint32_t set = plan.bindings.set;
    Placed placed;
    auto bind = [&](uint32_t s, uint32_t binding, const char* kind, uint32_t index) {
        spirv_cross::MSLResourceBinding b = fragmentBinding(s, binding);
        (std::string_view(kind) == "buffer" ? b.msl_buffer : std::string_view(kind) == "texture" ? b.msl_texture : b.msl_sampler) = index;
        c.add_msl_resource_binding(b);
        placed[{s, binding}][kind] = index;
    };
    bind(set, plan.bindings.params, "buffer", l.buffer);
    bind(set, plan.bindings.sampler, "sampler", l.sampler);
    for (uint32_t i = 0; i < plan.textureCount(); ++i) bind(set, plan.bindings.firstTexture + i, "texture", l.texture + i);
    auto base = [](uint32_t templateBase, uint32_t after) { return templateBase != ResourceLayout::kAfterHexc ? templateBase : after; };
    uint32_t buffer = base(l.templateBuffer, l.buffer + 1), texture = base(l.templateTexture, l.texture + uint32_t(plan.textureCount())),
             sampler = base(l.templateSampler, l.sampler + 1);
    auto checked = [&](const TemplateResource& r, std::string_view kind, uint32_t index) {
        const bool hexcs = kind == "texture" ? index >= l.texture && index < l.texture + plan.textureCount()
                                             : index == (kind == "buffer" ? l.buffer : l.sampler);
        if (!hexcs) return index;
        const std::string file = plan.layout.sourceFile.string(), key = "template_" + std::string(kind);
        throw CompileError{{Diagnostic::make(
            Code::TemplateSetConflict, {file.empty() ? "--msl-template-" + std::string(kind) : file}, file.empty() ? "" : "/msl/" + key,
            "`" + r.name + "` would take MSL " + std::string(kind) + " index " + std::to_string(index) +
                ", which one of hexc's resources takes; move the template's (msl." + key + ") or hexc's (msl." + std::string(kind) + ")")}};
    };
    for (const TemplateResource& r : own) {
        const bool push = r.cls == ResourceClass::PushConstant;
        spirv_cross::MSLResourceBinding b =
            push ? fragmentBinding(spirv_cross::ResourceBindingPushConstantDescriptorSet, spirv_cross::ResourceBindingPushConstantBinding)
                 : fragmentBinding(r.set, r.binding);
        nlohmann::json& where = placed[{b.desc_set, b.binding}];
        const bool textured = takesTexture(r.cls), sampling = takesSampler(r.cls);
        if (textured) where["texture"] = b.msl_texture = checked(r, "texture", texture++);
        if (sampling) where["sampler"] = b.msl_sampler = checked(r, "sampler", sampler++);
        if (!textured && !sampling) where["buffer"] = b.msl_buffer = checked(r, "buffer", buffer++);
        c.add_msl_resource_binding(b);
    }
    return placed;
}

// Argument buffers (layout msl.argument_buffers): descriptor set N is the argument buffer at [[buffer(N)]]; in it,
// every resource, hexc's and the template's, takes the next [[id]] in binding order, a sampler2D two (its texture,
// then its sampler). Push constants stay a buffer, after the argument buffers.
Placed placeInArgumentBuffers(spirv_cross::CompilerMSL& c, const ShaderPlan& plan, const std::vector<TemplateResource>& own) {
    struct Entry {
        uint32_t set, binding;
        bool texture, sampler;
    };
    const uint32_t set = plan.bindings.set;
    std::vector<Entry> entries = {{set, plan.bindings.params, false, false}, {set, plan.bindings.sampler, false, true}};
    for (uint32_t i = 0; i < plan.textureCount(); ++i) entries.push_back({set, plan.bindings.firstTexture + i, true, false});
    uint32_t sets = set + 1;
    for (const TemplateResource& r : own)
        if (r.cls != ResourceClass::PushConstant) {
            entries.push_back({r.set, r.binding, takesTexture(r.cls), takesSampler(r.cls)});
            sets = std::max(sets, r.set + 1);
        }
    std::sort(entries.begin(), entries.end(),
              [](const Entry& a, const Entry& b) { return std::tie(a.set, a.binding) < std::tie(b.set, b.binding); });
    std::map<uint32_t, uint32_t> next;  // per set
    Placed placed;
    for (const Entry& e : entries) {
        spirv_cross::MSLResourceBinding b = fragmentBinding(e.set, e.binding);
        nlohmann::json& where = placed[{e.set, e.binding}];
        where["argument_buffer"] = e.set;
        where["id"] = b.msl_buffer = b.msl_texture = b.msl_sampler = next[e.set]++;
        if (e.texture && e.sampler) where["sampler_id"] = b.msl_sampler = next[e.set]++;
        c.add_msl_resource_binding(b);
    }
    spirv_cross::MSLResourceBinding push =
        fragmentBinding(spirv_cross::ResourceBindingPushConstantDescriptorSet, spirv_cross::ResourceBindingPushConstantBinding);
    placed[{push.desc_set, push.binding}]["buffer"] = push.msl_buffer = sets;
    c.add_msl_resource_binding(push);
    return placed;
}

}  // namespace

TargetOutput emitMsl(const std::vector<uint32_t>& spirv, const ShaderPlan& plan, const CompileOptions& options) {
    spirv_cross::CompilerMSL c(spirv);
    configureMsl(c, options);
    const std::vector<TemplateResource> own = templateResources(c, plan);
    const Placed where = plan.layout.msl.argumentBuffers ? placeInArgumentBuffers(c, plan, own) : placeDirect(c, plan, own);
    nlohmann::json placed = nlohmann::json::array();
    for (const TemplateResource& r : own) {
        nlohmann::json described = describe(r);
        const bool push = r.cls == ResourceClass::PushConstant;
        described.update(where.at(
            push ? std::pair{spirv_cross::ResourceBindingPushConstantDescriptorSet, spirv_cross::ResourceBindingPushConstantBinding}
                 : std::pair{r.set, r.binding}));
        placed.push_back(std::move(described));
    }

    TargetOutput out;
    out.source = c.compile();
    out.entryPoint = c.get_cleansed_entry_point_name(plan.entryPoint, spv::ExecutionModelFragment);
    Locate locate = [&](ResourceKind kind, uint32_t index) -> nlohmann::json {
        const uint32_t binding = kind == ResourceKind::Params    ? plan.bindings.params
                                 : kind == ResourceKind::Sampler ? plan.bindings.sampler
                                                                 : plan.bindings.firstTexture + index;
        return where.at({plan.bindings.set, binding});
    };
    // SPIRV-Cross gives user varyings [[user(locn<location>)]] and colour outputs [[color(<location>)]].
    IoName attribute = [](uint32_t location, bool input) -> nlohmann::json {
        return {{"attribute", (input ? "user(locn" : "color(") + std::to_string(location) + ")"}};
    };
    out.target = describeTarget(spirv, plan, out.entryPoint, locate, attribute, placed);
    out.target["msl_version"] = std::to_string(options.mslMajor) + "." + std::to_string(options.mslMinor);
    if (plan.layout.msl.argumentBuffers) out.target["argument_buffers"] = true;
    return out;
}

TargetOutput vertexMsl(const std::vector<uint32_t>& spirv, const CompileOptions& options, const std::string& entry) {
    spirv_cross::CompilerMSL c(spirv);
    configureMsl(c, options);
    TargetOutput out{c.compile(), "", {}};
    out.entryPoint = c.get_cleansed_entry_point_name(entry, spv::ExecutionModelVertex);
    return out;
}

std::string libraryMsl(const std::vector<uint32_t>& spirv) {
    spirv_cross::CompilerMSL c(spirv);
    configureMsl(c, CompileOptions());  // the default version, 2.0
    return c.compile();
}

std::string settingsMsl(const CompileOptions& options) {
    return "msl " + std::to_string(options.mslMajor) + "." + std::to_string(options.mslMinor);
}

}  // namespace hexc
