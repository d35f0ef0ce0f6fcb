#include "spirv/unroll.h"

#include "spirv/module.h"

namespace hexc {

std::vector<uint32_t> unrollEveryLoop(const std::vector<uint32_t>& words) {
    spirv::Module module = spirv::parse(words, "unrollEveryLoop");
    for (spirv::Instruction& i : module.code)
        if (i.opcode() == spv::OpLoopMerge) i.words[3] = (i.words[3] & ~spv::LoopControlDontUnrollMask) | spv::LoopControlUnrollMask;
    return module.words();
}

}  // namespace hexc
