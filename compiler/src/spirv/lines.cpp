#include "spirv/lines.h"

#include <spirv.hpp>

#include <stdexcept>

namespace hexc {

std::vector<uint32_t> functionLinesOnly(const std::vector<uint32_t>& words) {
    constexpr size_t kHeader = 5;
    std::vector<uint32_t> out(words.begin(), words.begin() + std::ptrdiff_t(std::min(kHeader, words.size())));
    bool inFunction = false, lined = false;
    for (size_t at = kHeader; at < words.size();) {
        const size_t count = words[at] >> 16;
        if (count == 0 || at + count > words.size()) throw std::runtime_error("functionLinesOnly: the module does not parse");
        const auto op = spv::Op(words[at] & 0xffff);
        if (op == spv::OpFunction) inFunction = true, lined = false;
        if (op == spv::OpFunctionEnd) inFunction = false;
        const bool drop = inFunction && (op == spv::OpNoLine || (op == spv::OpLine && lined));
        if (op == spv::OpLine && inFunction) lined = true;
        if (!drop) out.insert(out.end(), words.begin() + std::ptrdiff_t(at), words.begin() + std::ptrdiff_t(at + count));
        at += count;
    }
    return out;
}

}  // namespace hexc
