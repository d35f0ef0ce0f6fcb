// Combined image samplers for the SPIR-V output (layout vulkan.combined): hexc's textures become sampler2D
// descriptors at their bindings and the shared sampler goes. Done on the optimised module, where every sample is
// `OpSampledImage(load texture, load sampler)`: the texture variable's type becomes a pointer to the sampled image
// type, its load yields the sampled image, and each OpSampledImage is replaced by that load. The other targets are
// emitted from the separate module (HLSL and MSL have separate samplers only, OpenGL GLSL combined ones only).
#include "spirv/combined.h"
#include "spirv/module.h"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

namespace hexc {
namespace {

using spirv::Instruction;
using spirv::Module;

// Variables by (set, binding), from the decorations.
std::map<std::pair<uint32_t, uint32_t>, uint32_t> descriptors(const Module& m) {
    std::map<uint32_t, uint32_t> set, binding;
    for (const Instruction& i : m.code)
        if (i.opcode() == spv::OpDecorate && i.words.size() == 4) {
            if (i.words[2] == spv::DecorationDescriptorSet) set[i.words[1]] = i.words[3];
            if (i.words[2] == spv::DecorationBinding) binding[i.words[1]] = i.words[3];
        }
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> out;
    for (const auto& [id, b] : binding) out[{set[id], b}] = id;
    return out;
}

// The id of `OpTypePointer UniformConstant pointee`, added after the instruction defining `pointee` if missing.
uint32_t uniformPointer(Module& m, uint32_t pointee) {
    for (const Instruction& i : m.code)
        if (i.opcode() == spv::OpTypePointer && i.words[2] == spv::StorageClassUniformConstant && i.words[3] == pointee) return i.words[1];
    const uint32_t id = m.header[3]++;
    auto defined =
        std::find_if(m.code.begin(), m.code.end(), [&](const Instruction& i) { return i.words.size() > 1 && i.words[1] == pointee; });
    m.code.insert(defined + 1, spirv::instruction(spv::OpTypePointer, {id, spv::StorageClassUniformConstant, pointee}, {2}));
    return id;
}

// The sampled image type of image type `image` (optimised hexc modules sample every texture, so it exists).
uint32_t sampledImageType(const Module& m, uint32_t image) {
    for (const Instruction& i : m.code)
        if (i.opcode() == spv::OpTypeSampledImage && i.words[2] == image) return i.words[1];
    throw std::runtime_error("combined samplers: a texture is never sampled");
}

// hexc's texture variables (by their bindings) -> their image types.
std::map<uint32_t, uint32_t> textureImages(const Module& m, const std::map<std::pair<uint32_t, uint32_t>, uint32_t>& byBinding,
                                           const ShaderPlan& plan) {
    std::map<uint32_t, uint32_t> imageOf;
    for (size_t t = 0; t < plan.textureCount(); ++t) {
        const auto var = byBinding.find({plan.bindings.set, plan.bindings.firstTexture + uint32_t(t)});
        if (var == byBinding.end()) continue;  // a slot the shader does not read
        for (const Instruction& i : m.code)
            if (i.opcode() == spv::OpVariable && i.words[2] == var->second)
                for (const Instruction& p : m.code)
                    if (p.opcode() == spv::OpTypePointer && p.words[1] == i.words[1]) imageOf[var->second] = p.words[3];
    }
    return imageOf;
}

// The module's words from `code`, the texture variables `moved` to the end of the global declarations (their new
// type may be declared after them), validated.
std::vector<uint32_t> assemble(const std::vector<uint32_t>& header, std::vector<Instruction> code,
                               const std::map<uint32_t, uint32_t>& moved) {
    auto last = std::stable_partition(code.begin(), code.end(),
                                      [&](const Instruction& i) { return !(i.opcode() == spv::OpVariable && moved.count(i.words[2])); });
    std::vector<Instruction> variables(std::make_move_iterator(last), std::make_move_iterator(code.end()));
    code.erase(last, code.end());
    spirv::insertBeforeFunctions(code, std::move(variables));
    return spirv::validWords(Module{header, std::move(code)}, "combined samplers");
}

}  // namespace

std::vector<uint32_t> combineSamplers(const std::vector<uint32_t>& words, const ShaderPlan& plan) {
    Module m = spirv::parse(words, "combined samplers");
    const auto byBinding = descriptors(m);
    const auto found = byBinding.find({plan.bindings.set, plan.bindings.sampler});
    const uint32_t sampler = found == byBinding.end() ? 0 : found->second;
    std::map<uint32_t, uint32_t> pointerOf, sampledOf;  // texture variable -> its new pointer type, its sampled image type
    for (const auto& [var, image] : textureImages(m, byBinding, plan)) {
        sampledOf[var] = sampledImageType(m, image);
        pointerOf[var] = uniformPointer(m, sampledOf[var]);
    }
    std::map<uint32_t, uint32_t> loadType, replaced;  // texture load -> sampled image type; OpSampledImage -> its load
    std::set<uint32_t> samplerLoads;
    std::vector<Instruction> kept;
    for (Instruction& i : m.code) {
        const spv::Op op = i.opcode();
        if (op == spv::OpVariable && pointerOf.count(i.words[2])) i.words[1] = pointerOf[i.words[2]];
        if (op == spv::OpLoad && pointerOf.count(i.words[3])) {
            i.words[1] = sampledOf[i.words[3]];
            loadType[i.words[2]] = i.words[1];
        }
        if (op == spv::OpLoad && i.words[3] == sampler) {
            samplerLoads.insert(i.words[2]);
            continue;
        }
        if (op == spv::OpSampledImage && loadType.count(i.words[3]) && samplerLoads.count(i.words[4])) {
            replaced[i.words[2]] = i.words[3];
            continue;
        }
        const bool aboutSampler =
            (op == spv::OpVariable && i.words[2] == sampler) || ((op == spv::OpDecorate || op == spv::OpName) && i.words[1] == sampler);
        if (!aboutSampler || sampler == 0) kept.push_back(std::move(i));
    }
    for (Instruction& i : kept)
        for (uint16_t at : i.ids) {
            if (samplerLoads.count(i.words[at]) || (sampler != 0 && i.words[at] == sampler) || loadType.count(i.words[at]))
                throw CompileError{{Diagnostic::make(
                    Code::TargetUnsupported, {plan.layout.sourceFile.empty() ? "--combined" : plan.layout.sourceFile.string()}, "",
                    "combined samplers (layout vulkan.combined): the template reads hexcSampler or a hexcTex_ texture itself, "
                    "which a combined image sampler cannot give; sample its own textures with its own sampler, or keep "
                    "separate samplers")}};
        }
    for (Instruction& i : kept) i.replaceIds(replaced);
    return assemble(m.header, std::move(kept), pointerOf);
}

}  // namespace hexc
