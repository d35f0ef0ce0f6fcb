#include "spirv/lines.h"

#include <spirv.hpp>

#include <stdexcept>

namespace hexc {

namespace {

// The module's instructions but those `drop` names, given each instruction's opcode and whether it is in a function.
template <typename Drop>
std::vector<uint32_t> filtered(const std::vector<uint32_t>& words, Drop drop) {
    constexpr size_t kHeader = 5;
    std::vector<uint32_t> out(words.begin(), words.begin() + std::ptrdiff_t(std::min(kHeader, words.size())));
    bool inFunction = false;
    for (size_t at = kHeader; at < words.size();) {
        const size_t count = words[at] >> 16;
        if (count == 0 || at + count > words.size()) throw std::runtime_error("the SPIR-V module does not parse");
        const auto op = spv::Op(words[at] & 0xffff);
        if (op == spv::OpFunction) inFunction = true;
        if (op == spv::OpFunctionEnd) inFunction = false;
        if (!drop(op, inFunction)) out.insert(out.end(), words.begin() + std::ptrdiff_t(at), words.begin() + std::ptrdiff_t(at + count));
        at += count;
    }
    return out;
}

}  // namespace

std::vector<uint32_t> functionLinesOnly(const std::vector<uint32_t>& words) {
    bool lined = false;
    return filtered(words, [&](spv::Op op, bool inFunction) {
        if (op == spv::OpFunction) lined = false;
        const bool drop = inFunction && (op == spv::OpNoLine || (op == spv::OpLine && lined));
        if (op == spv::OpLine && inFunction) lined = true;
        return drop;
    });
}

std::vector<uint32_t> withoutLines(const std::vector<uint32_t>& words) {
    return filtered(words, [](spv::Op op, bool) { return op == spv::OpLine || op == spv::OpNoLine; });
}

}  // namespace hexc
