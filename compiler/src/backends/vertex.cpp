// The pass-through vertex stage on each target (its row's `vertex`): the same compiler options as the fragment
// shader, no resources, and the entry point renamed like the fragment's.
#include "backends/backends.h"

namespace hexc {

nlohmann::json emitVertexStage(const std::vector<uint32_t>& spirv, const std::vector<Varying>& inputs, const std::string& entry,
                               const std::string& material, const CompileOptions& options, const std::vector<Target>& targets,
                               std::vector<OutputFile>& files) {
    // SPIRV-Cross gives vertex inputs TEXCOORD<location> in HLSL and [[attribute(<location>)]] in MSL.
    auto attribute = [](const std::string& name, uint32_t location, const std::string& type, const std::string& feeds) {
        return nlohmann::json{{"name", name},
                              {"location", location},
                              {"type", type},
                              {"feeds", feeds},
                              {"hlsl_semantic", "TEXCOORD" + std::to_string(location)},
                              {"msl_attribute", location}};
    };
    nlohmann::json attributes = nlohmann::json::array();  // not `{one}`: clang makes that the object itself
    attributes.push_back(attribute("hexc_position", 0, "vec4", "gl_Position"));
    for (const Varying& v : inputs) attributes.push_back(attribute("hexc_in_" + v.name, uint32_t(attributes.size()), v.type, v.name));
    nlohmann::json vertex = {{"attributes", attributes}};
    for (Target t : targets) {
        TargetOutput out = targetRow(t).vertex(spirv, options, entry);
        OutputFile file{shaderFileName(material, t, "vert"), out.source};
        vertex[std::string(toString(t))] = {{"file", file.name}, {"entry_point", out.entryPoint}};
        files.push_back(std::move(file));
    }
    return vertex;
}

}  // namespace hexc
