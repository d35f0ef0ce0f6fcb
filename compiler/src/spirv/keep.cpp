#include "spirv/keep.h"

#include <algorithm>
#include <set>

#include "spirv/module.h"

namespace hexc {

std::vector<uint32_t> keepFunctions(const std::vector<uint32_t>& words, const std::vector<std::string>& names) {
    spirv::Module module = spirv::parse(words, "keepFunctions");
    std::set<uint32_t> kept;
    for (const spirv::Instruction& i : module.code) {
        if (i.opcode() != spv::OpName) continue;
        const std::string name(reinterpret_cast<const char*>(i.words.data() + 2));
        if (std::find(names.begin(), names.end(), name) != names.end()) kept.insert(i.words[1]);
    }
    for (spirv::Instruction& i : module.code)
        if (i.opcode() == spv::OpFunction && kept.count(i.words[2])) i.words[3] |= spv::FunctionControlDontInlineMask;
    return module.words();
}

}  // namespace hexc
