// The pass-through vertex stage on each target: the same compiler options as the fragment shader, no resources,
// and the entry point renamed like the fragment's.
#include <spirv_glsl.hpp>
#include <spirv_hlsl.hpp>
#include <spirv_msl.hpp>

#include "backends/backends.h"

namespace hexc {

TargetOutput emitVertex(const std::vector<uint32_t>& spirv, Target target, const CompileOptions& options, const std::string& entry) {
    TargetOutput out;
    out.entryPoint = entry;
    if (target == Target::Hlsl) {
        spirv_cross::CompilerHLSL c(spirv);
        configureHlsl(c, options);
        out.source = c.compile();
        renameHlslEntry(out.source, entry);
    } else if (target == Target::Glsl) {
        spirv_cross::CompilerGLSL c(spirv);
        configureGlsl(c, options);
        out.source = c.compile();
        out.entryPoint = "main";
    } else if (target == Target::Msl) {
        spirv_cross::CompilerMSL c(spirv);
        configureMsl(c, options);
        out.source = c.compile();
        out.entryPoint = c.get_cleansed_entry_point_name(entry, spv::ExecutionModelVertex);
    }
    return out;
}

}  // namespace hexc
