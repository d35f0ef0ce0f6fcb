// The functions output (CompileOptions::functions): a target's source of the `functions` template without its main,
// its stage input and output and the structs that carry them, which leaves the engine functions and the resources
// they read (MSL has no global resources: its functions take theirs as parameters). The cut is of SPIRV-Cross's own
// layout of each language (naga's for WGSL: wgsl.cpp), which the functions tests check on every target.
#include <sstream>

#include "backends/backends.h"

namespace hexc {
namespace {

// The structs holding the stage's inputs and outputs: HLSL's SPIRV_Cross_Input/Output, MSL's <entry>_in/_out.
bool stageStruct(const std::string& line, const std::string& entry) {
    return line == "struct SPIRV_Cross_Input" || line == "struct SPIRV_Cross_Output" || line == "struct " + entry + "_in" ||
           line == "struct " + entry + "_out";
}

}  // namespace

std::string functionsOnly(const std::string& source, Target target, const std::string& entry) {
    const TargetRow& row = targetRow(target);
    std::istringstream in(row.withoutStage(source, entry));
    std::string out, line;
    bool inStruct = false;
    while (std::getline(in, line) && !line.starts_with(row.entryLine)) {
        if (stageStruct(line, entry)) inStruct = true;
        const bool drop = inStruct || line.starts_with("#version") || line.find("hexcEngine") != std::string::npos;
        if (inStruct && line == "};") inStruct = false;
        if (!drop) out += line + "\n";
    }
    // The blank lines the cut lines leave, twice or more in a row, as one.
    for (size_t at; (at = out.find("\n\n\n")) != std::string::npos;) out.erase(at, 1);
    while (out.ends_with("\n\n")) out.pop_back();
    while (out.starts_with("\n")) out.erase(0, 1);
    return out;
}

}  // namespace hexc
