#include "spirv/module.h"

#include <spirv-tools/libspirv.h>

#include <stdexcept>

namespace hexc::spirv {

// Functions (OpFunction) and calls (OpFunctionCall) before optimisation: the example materials' shaders, library
// included, have at most 47 and 99 (rock_triplanar); docs/cli.md#budgets.
constexpr size_t kMaxFunctions = 1000, kMaxCalls = 5000;

std::optional<Diagnostic> beyondOptimiserBound(const std::vector<uint32_t>& words, const std::string& templateName) {
    size_t functions = 0, calls = 0;
    for (size_t at = 5; at < words.size();) {
        const uint32_t count = words[at] >> 16, opcode = words[at] & 0xffff;
        if (count == 0) break;  // glslang's output always parses; nothing more to count in one that does not
        functions += opcode == spv::OpFunction;
        calls += opcode == spv::OpFunctionCall;
        at += count;
    }
    if (functions <= kMaxFunctions && calls <= kMaxCalls) return std::nullopt;
    return Diagnostic::make(Code::TemplateTooLarge, {templateName}, "",
                            "the shader has " + std::to_string(functions) + " functions and " + std::to_string(calls) +
                                " calls; hexc optimises at most " + std::to_string(kMaxFunctions) + " functions and " +
                                std::to_string(kMaxCalls) +
                                " calls (spirv-opt's inliner would take minutes), fewer in the template would do");
}

void Instruction::replaceIds(const std::map<uint32_t, uint32_t>& replaced) {
    for (uint16_t at : ids)
        if (auto r = replaced.find(words[at]); r != replaced.end()) words[at] = r->second;
}

std::vector<uint32_t> Module::words() const {
    std::vector<uint32_t> out = header;
    for (const Instruction& i : code) out.insert(out.end(), i.words.begin(), i.words.end());
    return out;
}

Module parse(const std::vector<uint32_t>& words, const std::string& what) {
    Module m;
    m.header.assign(words.begin(), words.begin() + 5);
    spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_0);
    auto onInstruction = [](void* user, const spv_parsed_instruction_t* parsed) {
        Instruction i{{parsed->words, parsed->words + parsed->num_words}, {}};
        for (uint16_t k = 0; k < parsed->num_operands; ++k) {
            const spv_operand_type_t type = parsed->operands[k].type;
            if (type == SPV_OPERAND_TYPE_ID || type == SPV_OPERAND_TYPE_TYPE_ID || type == SPV_OPERAND_TYPE_MEMORY_SEMANTICS_ID ||
                type == SPV_OPERAND_TYPE_SCOPE_ID)
                i.ids.push_back(parsed->operands[k].offset);
        }
        static_cast<Module*>(user)->code.push_back(std::move(i));
        return SPV_SUCCESS;
    };
    const spv_result_t result = spvBinaryParse(context, &m, words.data(), words.size(), nullptr, onInstruction, nullptr);
    spvContextDestroy(context);
    if (result != SPV_SUCCESS) throw std::runtime_error(what + ": the module does not parse");
    return m;
}

}  // namespace hexc::spirv
