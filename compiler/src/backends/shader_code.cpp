// The shader cache's entry for a ShaderCode: CBOR with the SPIR-V and each target's source and description.
#include "backends/shader_code.h"

#include "hexc/cache.h"
#include "hexc/hash.h"
#include "hexc/spirv.h"
#include "spirv/strings.h"

namespace hexc {
namespace {

nlohmann::json binary(std::string_view bytes) { return nlohmann::json::binary(std::vector<uint8_t>(bytes.begin(), bytes.end())); }

}  // namespace

std::string shaderCodeKey(const std::string& glsl, const ShaderPlan& plan, const CompileOptions& options) {
    ContentHash h;
    for (const std::string& part : {std::string("hexc shader code 1"), std::string(version()), buildId(), toolchainVersions(), glsl,
                                    plan.templateName, toString(plan.layout)})
        h.add(part);
    for (const SlotPlan& sp : plan.slots) h.add(sp.name);
    h.add(codeOptionsKey(options));
    return h.hex();
}

std::string toBytes(const ShaderCode& code) {
    nlohmann::json j = {{"spirv", binary(spirvBytes(code.spirv))}};
    for (const auto& [t, out] : code.targets)
        j["targets"][std::string(toString(t))] = {{"source", binary(out.source)}, {"entry_point", out.entryPoint}, {"target", out.target}};
    const std::vector<uint8_t> cbor = nlohmann::json::to_cbor(j);
    return std::string(cbor.begin(), cbor.end());
}

std::optional<ShaderCode> shaderCodeFromBytes(const std::string& bytes, const std::vector<Target>& targets) {
    try {
        const nlohmann::json j = nlohmann::json::from_cbor(bytes);
        const auto& spirv = j.at("spirv").get_binary();
        ShaderCode code{spirvWords(std::string_view(reinterpret_cast<const char*>(spirv.data()), spirv.size())), {}};
        for (Target t : targets) {
            const nlohmann::json& out = j.at("targets").at(std::string(toString(t)));
            const auto& source = out.at("source").get_binary();
            code.targets[t] = {std::string(source.begin(), source.end()), out.at("entry_point"), out.at("target")};
        }
        return code;
    } catch (const nlohmann::json::exception&) {
        return std::nullopt;
    }
}

void withEntryPoint(ShaderCode& code, const std::string& entry) {
    code.spirv = replaceInStrings(code.spirv, kEntryPlaceholder, entry);
    for (auto& [t, out] : code.targets) {
        const std::string name = targetRow(t).entryName(entry);
        if (targetRow(t).binary)
            out.source = spirvBytes(replaceInStrings(spirvWords(out.source), kEntryPlaceholder, entry));
        else
            for (size_t at = 0; (at = out.source.find(kEntryPlaceholder, at)) != std::string::npos; at += name.size())
                out.source.replace(at, kEntryPlaceholder.size(), name);
        if (out.entryPoint == kEntryPlaceholder) out.entryPoint = name;
        out.target["entry_point"] = out.entryPoint;
    }
}

}  // namespace hexc
