#include "spirv/module.h"

#include <spirv-tools/libspirv.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

#include "hexc/spirv.h"

namespace hexc::spirv {

// Calls (OpFunctionCall) in the functions the entry points reach, before optimisation: the example materials' shaders,
// library included, make at most 99 (rock_triplanar); docs/cli.md#budgets.
constexpr size_t kMaxCalls = 5000;

namespace {

// The calls in the functions an entry point reaches, each function counted once: what spirv-opt's inliner works on
// once its first pass has dropped the functions nothing calls (a template's unused helpers cost next to nothing).
size_t reachableCalls(const std::vector<uint32_t>& words) {
    std::map<uint32_t, std::vector<uint32_t>> callees;  // function id -> the function of each of its calls
    std::vector<uint32_t> todo;
    uint32_t current = 0;
    for (size_t at = 5; at < words.size();) {
        const uint32_t count = words[at] >> 16, opcode = words[at] & 0xffff;
        if (count == 0 || at + count > words.size()) break;  // glslang's output always parses
        if (opcode == spv::OpEntryPoint && count > 2) todo.push_back(words[at + 2]);
        if (opcode == spv::OpFunction && count > 2) current = words[at + 2];
        if (opcode == spv::OpFunctionCall && count > 3) callees[current].push_back(words[at + 3]);
        at += count;
    }
    std::set<uint32_t> seen;
    size_t calls = 0;
    while (!todo.empty()) {
        const uint32_t f = todo.back();
        todo.pop_back();
        if (!seen.insert(f).second) continue;
        const std::vector<uint32_t>& called = callees[f];
        calls += called.size();
        todo.insert(todo.end(), called.begin(), called.end());
    }
    return calls;
}

}  // namespace

std::optional<Diagnostic> beyondOptimiserBound(const std::vector<uint32_t>& words, const std::string& templateName) {
    const size_t calls = reachableCalls(words);
    if (calls <= kMaxCalls) return std::nullopt;
    return Diagnostic::make(Code::TemplateTooLarge, {templateName}, "",
                            "the shader makes " + std::to_string(calls) +
                                " calls in the functions its entry point reaches; hexc optimises at most " + std::to_string(kMaxCalls) +
                                " (spirv-opt's inliner would take minutes), fewer in the template would do");
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

Instruction instruction(spv::Op op, std::vector<uint32_t> operands, std::vector<uint16_t> ids) {
    operands.insert(operands.begin(), uint32_t((operands.size() + 1) << spv::WordCountShift) | op);
    for (uint16_t& at : ids) ++at;
    return {std::move(operands), std::move(ids)};
}

void insertBeforeFunctions(std::vector<Instruction>& code, std::vector<Instruction> added) {
    auto first = std::find_if(code.begin(), code.end(), [](const Instruction& i) { return i.opcode() == spv::OpFunction; });
    code.insert(first, std::make_move_iterator(added.begin()), std::make_move_iterator(added.end()));
}

std::vector<uint32_t> validWords(const Module& m, const std::string& what) {
    std::vector<uint32_t> out = m.words();
    if (std::string errors = validationErrors(out); !errors.empty())
        throw std::runtime_error(what + ": the rewritten module is invalid:\n" + errors);
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
        Module& m = *static_cast<Module*>(user);
        if (parsed->type_id) m.types[parsed->result_id] = parsed->type_id;
        m.code.push_back(std::move(i));
        return SPV_SUCCESS;
    };
    const spv_result_t result = spvBinaryParse(context, &m, words.data(), words.size(), nullptr, onInstruction, nullptr);
    spvContextDestroy(context);
    if (result != SPV_SUCCESS) throw std::runtime_error(what + ": the module does not parse");
    return m;
}

}  // namespace hexc::spirv
