#include "spirv/strings.h"

#include <spirv-tools/libspirv.h>

#include <cstring>
#include <set>
#include <stdexcept>
#include <string>

#include "spirv/module.h"

namespace hexc {
namespace {

struct Rewrite {
    std::string_view from, to;
    std::vector<uint32_t> out;
};

spv_result_t rewriteInstruction(void* user, const spv_parsed_instruction_t* parsed) {
    Rewrite& r = *static_cast<Rewrite*>(user);
    const size_t start = r.out.size();
    r.out.push_back(0);  // the word count and opcode, set below
    uint16_t next = 1;   // the first word not yet copied
    for (uint16_t k = 0; k < parsed->num_operands; ++k) {
        const spv_parsed_operand_t& operand = parsed->operands[k];
        if (operand.type != SPV_OPERAND_TYPE_LITERAL_STRING) continue;
        r.out.insert(r.out.end(), parsed->words + next, parsed->words + operand.offset);
        std::string text(reinterpret_cast<const char*>(parsed->words + operand.offset));
        for (size_t at = 0; (at = text.find(r.from, at)) != std::string::npos; at += r.to.size()) text.replace(at, r.from.size(), r.to);
        const std::vector<uint32_t> encoded = spirvString(text);
        r.out.insert(r.out.end(), encoded.begin(), encoded.end());
        next = uint16_t(operand.offset + operand.num_words);
    }
    r.out.insert(r.out.end(), parsed->words + next, parsed->words + parsed->num_words);
    r.out[start] = uint32_t(r.out.size() - start) << 16 | parsed->opcode;
    return SPV_SUCCESS;
}

}  // namespace

std::vector<uint32_t> spirvString(std::string_view text) {
    std::vector<uint32_t> words(text.size() / 4 + 1, 0);
    std::memcpy(words.data(), text.data(), text.size());
    return words;
}

std::vector<uint32_t> replaceInStrings(const std::vector<uint32_t>& words, std::string_view from, std::string_view to) {
    Rewrite r{from, to, {words.begin(), words.begin() + std::min<size_t>(5, words.size())}};
    spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_0);
    const spv_result_t result = spvBinaryParse(context, &r, words.data(), words.size(), nullptr, rewriteInstruction, nullptr);
    spvContextDestroy(context);
    if (result != SPV_SUCCESS) throw std::runtime_error("SPIR-V strings: the module does not parse");
    return r.out;
}

std::vector<uint32_t> plainFunctionNames(const std::vector<uint32_t>& words) {
    spirv::Module m = spirv::parse(words, "function names");
    std::set<uint32_t> functions;
    for (const spirv::Instruction& i : m.code)
        if (i.opcode() == spv::OpFunction) functions.insert(i.words[2]);
    for (spirv::Instruction& i : m.code) {
        if (i.opcode() != spv::OpName || !functions.count(i.words[1])) continue;
        const std::string name(reinterpret_cast<const char*>(i.words.data() + 2));
        if (name.find('(') == std::string::npos) continue;
        const std::vector<uint32_t> plain = spirvString(name.substr(0, name.find('(')));
        i.words.resize(2);
        i.words.insert(i.words.end(), plain.begin(), plain.end());
        i.words[0] = uint32_t(i.words.size()) << 16 | spv::OpName;
    }
    return m.words();
}

}  // namespace hexc
