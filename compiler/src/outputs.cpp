// The names of the files compile() writes, found by planning alone (hexc --list-outputs): a build system declares
// them before the build runs.
#include <algorithm>
#include <set>

#include "hexc/compiler.h"
#include "hexc/histogram.h"
#include "plan/plan.h"

namespace hexc {

OutputNames outputNames(const Material& material, const CompileOptions& options) {
    OutputNames out;
    const ShaderPlan plan = planShader(material, options);
    out.diagnostics = plan.diagnostics;
    if (hasErrors(out.diagnostics)) return out;
    std::vector<std::string>& names = out.names;
    for (Target t : std::set<Target>(options.targets.begin(), options.targets.end())) {
        names.push_back(shaderFileName(material.name, t, options.functions ? "functions" : "frag"));
        if (options.vertex) names.push_back(shaderFileName(material.name, t, "vert"));
    }
    if (options.emitGenerated) names.push_back(material.name + ".generated.frag");
    for (size_t i : plan.luts)
        for (const char* which : {"gaussian", "lut"})
            names.push_back(histogramFileName(material.name, plan.slots[i].slot->name, which, plan.exrTables));
    for (const PackPlan& p : plan.packs) names.push_back(packedFileName(material.name, plan.slots[p.slots.front()].slot->name));
    names.push_back(material.name + ".manifest.json");
    std::sort(names.begin(), names.end());
    return out;
}

}  // namespace hexc
