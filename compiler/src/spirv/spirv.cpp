#include "hexc/spirv.h"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include <algorithm>
#include <cstring>
#include <mutex>
#include <sstream>

#include "common/one_line.h"
#include "plan/plan.h"

namespace hexc {
namespace {

void initializeGlslang() {
    // glslang's process-wide tables; never finalised, the OS reclaims them at exit.
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

// The file and line of a glslang log line "file:line: message": the first `:digits: ` splits them (file names may
// hold colons). False when the line has no location.
bool splitLocated(std::string_view rest, std::string& file, int& line, std::string& message) {
    for (size_t colon = rest.find(':'); colon != std::string_view::npos; colon = rest.find(':', colon + 1)) {
        size_t digits = colon + 1;
        while (digits < rest.size() && rest[digits] >= '0' && rest[digits] <= '9') ++digits;
        if (digits == colon + 1 || digits > colon + 10 || rest.substr(digits, 2) != ": ") continue;
        file = std::string(rest.substr(0, colon));
        line = std::stoi(std::string(rest.substr(colon + 1, digits - colon - 1)));
        message = std::string(rest.substr(digits + 2));
        return true;
    }
    return false;
}

// glslang writes "ERROR: file:line: message" (or "0:line" for unnamed sources) one per line.
void appendGlslangLog(const std::string& log, const std::string& fallbackName, Diagnostics& out) {
    std::istringstream in(log);
    std::string line, file, message;
    int number = 0;
    while (std::getline(in, line)) {
        bool isError = line.starts_with("ERROR: "), isWarning = line.starts_with("WARNING: ");
        if (!isError && !isWarning) continue;
        Code code = isError ? Code::ShaderError : Code::ShaderWarning;
        std::string_view rest = std::string_view(line).substr(isError ? 7 : 9);
        if (splitLocated(rest, file, number, message)) {
            out.push_back(Diagnostic::make(code, {file == "0" ? fallbackName : file, number, 0}, "", message));
        } else if (isError && line.find("compilation errors") == std::string::npos) {
            out.push_back(Diagnostic::make(Code::ShaderError, {fallbackName}, "", std::string(rest)));
        }
    }
}

spv_target_env kTargetEnv = SPV_ENV_VULKAN_1_0;

// spirv-opt's -O (44 passes), reordered so that the library's branches on a slot's settings go right after inlining,
// and without the passes that then found nothing left to do on the examples. Each slot's settings reach the library
// as HexcLattice and HexcBlend structs built member by member and passed by value; -O sees through them only at its
// first instruction simplification, halfway through, so its first half walks the whole inlined library.
// tests/spirv/recipe_test.cpp holds this recipe to no bigger SPIR-V than -O's, opcode by opcode, on every example, scene
// variant and a generated set; on those it costs 0.8x of -O's instructions (docs/benchmarks.md).
const std::vector<std::string> kSpecialiseEarly = {
    "--wrap-opkill",                     // -O's preparation for inlining: a discard in a called function,
    "--merge-return",                    // and returns before a function's end, can then be inlined
    "--inline-entry-points-exhaustive",  // the slots' functions and the library into main
    "--eliminate-dead-functions",        // the library's uncalled functions
    "--private-to-local",                // a template's private globals become locals, which the next passes forward
    "--scalar-replacement=100",          // the settings structs into one variable per member
    "--convert-local-access-chains",     // member stores and loads become whole-variable ones
    "--eliminate-local-single-block",    // a setting stored and read in one block: forwarded (most are)
    "--eliminate-local-single-store",    // stored once: forwarded everywhere it dominates
    "--ssa-rewrite",                     // the rest into SSA; simplifying before this leaves more code (more OpExtInst)
    "--simplify-instructions",           // the settings' members read back from the structs built: constants
    "--eliminate-dead-branches",         // the library's branches on them: gone, with their code
    "--eliminate-dead-code-aggressive",  // what only the removed branches used
    "--loop-unroll",                     // loops a template asks to unroll ([[unroll]])
    "--merge-blocks",                    // the blocks inlining split: redundancy elimination copies its table per block
    "--redundancy-elimination",          // the lattice and samples repeated across slots and taps, computed once
    "--simplify-instructions",           // what the shared values fold into
    "--ssa-rewrite",                     // loads the folds exposed
    "--vector-dce",                      // vector components nothing reads
    "--eliminate-dead-branches",         // branches the folds made constant
    "--if-conversion",                   // small ifs into selects, as -O ends
    "--eliminate-dead-code-aggressive",
    "--merge-blocks",
    "--redundancy-elimination",
    "--eliminate-dead-branches",
    "--merge-blocks",
    "--simplify-instructions",
    "--vector-dce",  // components the last folds left unread (triplanar: the planes' extracts)
    "--eliminate-dead-code-aggressive",
};

// SPIRV-Tools' messages appended to `messages`, one line each, located by word.
spvtools::MessageConsumer collectInto(std::string& messages) {
    return [&messages](spv_message_level_t, const char*, const spv_position_t& pos, const char* message) {
        messages += "word " + std::to_string(pos.index) + ": " + message + "\n";
    };
}

// GLSL ES 3.00 (WebGL 2): glslang makes SPIR-V from ES 3.10 on, so it is checked by glslang's ES 3.00 rules alone
// (parse, no target), then compiled as ES 3.10, of which it is a subset. Returns the source to compile, or "".
constexpr std::string_view kEs300 = "#version 300 es\n";
std::string asEs310(const std::string& source, EShLanguage lang, const std::string& name, Diagnostics& out) {
    glslang::TShader shader(lang);
    const char* text = source.c_str();
    const char* names = name.c_str();
    shader.setStringsWithLengthsAndNames(&text, nullptr, &names, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientNone, 0);
    shader.setEnvTarget(glslang::EShTargetNone, glslang::EShTargetSpv_1_0);
    const bool ok = shader.parse(GetDefaultResources(), 300, true, EShMsgDefault);
    appendGlslangLog(shader.getInfoLog(), name, out);
    return ok ? "#version 310 es\n" + source.substr(kEs300.size()) : "";
}

// Where resources without a set, space or binding of their own go.
void mapResources(glslang::TShader& shader, SourceLanguage language, const ResourceLayout& layout) {
    const bool hlsl = language == SourceLanguage::Hlsl, openGl = language == SourceLanguage::OpenGlGlsl;
    // Sources without a set or space (HLSL 5.0, OpenGL) go to the layout's set or space, OpenGL's to set 0.
    shader.setResourceSetBinding({std::to_string(hlsl ? layout.hlsl.space : openGl ? 0 : HexcBindings(layout.vulkan).set)});
    if (hlsl) {
        shader.setShiftBinding(glslang::EResSampler, kHlslSamplerShift);
        shader.setShiftBinding(glslang::EResTexture, kHlslTextureShift);
        shader.setShiftBinding(glslang::EResUav, kHlslUavShift);
    } else if (openGl) {
        // GLSL 330 carries no binding or varying location qualifiers (OpenGL matches by name): glslang numbers
        // what is missing in declaration order. Relaxed rules take loose uniforms into one block.
        shader.setAutoMapBindings(true);
        shader.setAutoMapLocations(true);
        shader.setShiftBinding(glslang::EResTexture, kGlTextureShift);
        shader.setEnvInputVulkanRulesRelaxed();
        shader.setGlobalUniformSet(0);
        shader.setGlobalUniformBinding(kGlDefaultBlockBinding);
    }
}

}  // namespace

SpirvResult compileToSpirv(const std::string& source, ShaderStage stage, const std::string& name, SourceLanguage language,
                           const std::string& entryPoint, const ResourceLayout& layout, std::string_view debugName) {
    initializeGlslang();
    SpirvResult result;
    EShLanguage lang = stage == ShaderStage::Vertex ? EShLangVertex : EShLangFragment;
    glslang::TShader shader(lang);
    const bool es300 = language == SourceLanguage::OpenGlGlsl && source.starts_with(kEs300);
    const std::string es310 = es300 ? asEs310(source, lang, name, result.diagnostics) : "";
    if (es300 && es310.empty()) return result;
    const char* text = es300 ? es310.c_str() : source.c_str();
    const char* names = name.c_str();
    shader.setStringsWithLengthsAndNames(&text, nullptr, &names, 1);
    bool hlsl = language == SourceLanguage::Hlsl;
    shader.setEnvInput(hlsl ? glslang::EShSourceHlsl : glslang::EShSourceGlsl, lang, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    shader.setEntryPoint(entryPoint.c_str());
    // GLSL's function is `main` whatever the module calls its entry point.
    if (!hlsl) shader.setSourceEntryPoint("main");
    mapResources(shader, language, layout);
    auto messages = EShMessages(EShMsgSpvRules | EShMsgVulkanRules | (hlsl ? EShMsgReadHlsl | EShMsgHlslOffsets : 0));
    if (!shader.parse(GetDefaultResources(), 450, false, messages)) {
        appendGlslangLog(shader.getInfoLog(), name, result.diagnostics);
        return result;
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages) || !program.mapIO()) {
        appendGlslangLog(program.getInfoLog(), name, result.diagnostics);
        return result;
    }
    appendGlslangLog(shader.getInfoLog(), name, result.diagnostics);  // warnings
    glslang::SpvOptions options;
    options.disableOptimizer = true;  // SPIRV-Tools runs next, with passes chosen in optimizeSpirv
    options.validate = false;
    options.generateDebugInfo = !debugName.empty();
    // Source string 0 (the template) named in the module's lines, so a target's `#line` names it rather than "". A `"`
    // cannot stand in a `#line` name: it becomes `'` there; a line break would end the directive (oneLine).
    std::string lineName = oneLine(debugName);
    std::replace(lineName.begin(), lineName.end(), '"', '\'');
    if (options.generateDebugInfo) program.getIntermediate(lang)->setSourceFile(lineName.c_str());
    spv::SpvBuildLogger logger;
    glslang::GlslangToSpv(*program.getIntermediate(lang), result.words, &logger, &options);
    if (std::string log = logger.getAllMessages(); log.find("error") != std::string::npos) {
        result.diagnostics.push_back(Diagnostic::make(Code::Internal, {name}, "", "SPIR-V generation failed: " + log));
        result.words.clear();
    }
    return result;
}

SpirvResult optimizeSpirv(const std::vector<uint32_t>& words, bool freezeConstants, bool legalize, bool performance) {
    SpirvResult result;
    std::string messages;
    auto fail = [&](const std::string& what) {
        result.words.clear();
        result.diagnostics.push_back(Diagnostic::make(Code::Internal, {"hexc"}, "", what + ":\n" + messages));
        return result;
    };
    // Each module is validated once, here, before the passes read it (spirv-opt's own validation is off): glslang
    // writes invalid SPIR-V for some templates it accepts, and spirv-opt assumes valid input. What the passes write
    // from valid input is not validated again, as spirv-opt's command line does not; tests/spirv/recipe_test.cpp
    // validates it on every example, scene variant and generated material.
    if (messages = validationErrors(words); !messages.empty()) return fail("invalid SPIR-V before optimisation");

    spvtools::Optimizer optimizer(kTargetEnv);
    optimizer.SetMessageConsumer(collectInto(messages));
    // Baked settings arrive as specialisation constants; freezing turns them into constants at their
    // default values, which the passes below fold like literals.
    if (freezeConstants) optimizer.RegisterPass(spvtools::CreateFreezeSpecConstantValuePass());
    // Legalisation, for HLSL input only: glslang's HLSL front end passes opaque handles through locals
    // and parameters, which Vulkan only accepts once they are inlined and forwarded. GLSL from glslang
    // is legal already, and the recipe would add about a tenth to the compile.
    if (legalize) optimizer.RegisterLegalizationPasses();
    // Then the performance recipe: inlines the per-slot functions and the library, folds the settings and removes
    // library code the material never reaches, which is what keeps the emitted HLSL/GLSL/MSL short.
    if (performance && !optimizer.RegisterPassesFromFlags(kSpecialiseEarly)) return fail("unknown spirv-opt pass");
    std::vector<uint32_t> optimized;
    spvtools::OptimizerOptions once;
    once.set_run_validator(false);
    if (!optimizer.Run(words.data(), words.size(), &optimized, once)) return fail("spirv-opt failed");
    result.words = std::move(optimized);
    return result;
}

std::string validationErrors(const std::vector<uint32_t>& words) {
    spvtools::SpirvTools tools(kTargetEnv);
    std::string messages;
    tools.SetMessageConsumer(collectInto(messages));
    spvtools::ValidatorOptions quiet;
    quiet.SetFriendlyNames(false);
    if (tools.Validate(words.data(), words.size(), quiet)) return "";
    messages.clear();
    tools.Validate(words);
    return messages;
}

std::vector<uint32_t> spirvWords(std::string_view bytes) {
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    return words;
}

std::string disassemble(const std::vector<uint32_t>& words) {
    spvtools::SpirvTools tools(kTargetEnv);
    std::string text;
    tools.Disassemble(words, &text, SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES);
    return text;
}

}  // namespace hexc
