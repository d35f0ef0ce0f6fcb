// countOps (hexc/spirv.h): what a shader executes per pixel, read from its disassembly.
#include <iterator>
#include <sstream>
#include <vector>

#include "hexc/spirv.h"

namespace hexc {

ShaderOps countOps(const std::string& disassembly) {
    ShaderOps ops;
    std::istringstream lines(disassembly);
    bool inFunction = false;
    for (std::string line; std::getline(lines, line);) {
        // "%id = OpName operands..." or "OpName operands...".
        std::istringstream words(line);
        std::vector<std::string> w{std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()};
        if (w.size() >= 2 && w[1] == "=") w.erase(w.begin(), w.begin() + 2);
        if (w.empty() || !w[0].starts_with("Op")) continue;
        const std::string& op = w[0];
        if (op == "OpFunction") inFunction = true;
        if (inFunction) ++ops.instructions;
        if (op == "OpFunctionEnd") inFunction = false;
        if (op.starts_with("OpImageSample") || op == "OpImageFetch" || op == "OpImageGather") ++ops.textureSamples;
        // OpExtInst %type %set Name ...: a vector result is that many scalar operations (the GPU's SIMD lanes are
        // pixels, not components), except a normalisation, which takes one square root whatever the width.
        if (op == "OpExtInst" && w.size() >= 4) {
            const std::string& type = w[1];
            const bool oneRoot = w[3] == "Normalize" || w[3] == "Length" || w[3] == "Distance";
            ops.extended[w[3]] += !oneRoot && type.starts_with("%v") && type.size() > 2 ? type[2] - '0' : 1;
        }
    }
    return ops;
}

}  // namespace hexc
