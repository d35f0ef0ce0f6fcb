#include "spirv/module.h"

#include <spirv-tools/libspirv.h>

#include <stdexcept>

namespace hexc::spirv {

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
