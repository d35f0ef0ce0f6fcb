// `hexc library`: entry.glsl (every public function of hextiling.glsl, called once) through glslang and each
// target's SPIRV-Cross without optimisation; the text from the entry point on and the lines of its resources (hexcLib*)
// are cut, which leaves the types, constants and functions: an include file.
#include "hexc/library.h"

#include <spirv_glsl.hpp>
#include <spirv_hlsl.hpp>
#include <spirv_msl.hpp>

#include <map>
#include <regex>
#include <sstream>

#include "backends/backends.h"
#include "codegen/codegen.h"
#include "hexc/templates.h"
#include "hexc/spirv.h"

namespace hexc {
namespace {

// `source` up to the line that starts with `entry`, without the lines naming the entry's resources or `#version`.
std::string cutEntry(const std::string& source, const std::string& entry) {
    std::istringstream in(source);
    std::string out, line;
    while (std::getline(in, line) && !line.starts_with(entry))
        if (line.find("hexcLib") == std::string::npos && !line.starts_with("#version")) out += line + "\n";
    while (out.ends_with("\n\n")) out.pop_back();
    return out;
}

std::string emitted(const std::vector<uint32_t>& spirv, LibraryTarget target) {
    CompileOptions options;  // the default versions: HLSL SM 5.0, GLSL 450, MSL 2.0
    switch (target) {
        case LibraryTarget::Hlsl: {
            spirv_cross::CompilerHLSL c(spirv);
            configureHlsl(c, options);
            return cutEntry(c.compile(), "void frag_main()");
        }
        case LibraryTarget::Glsl: {
            spirv_cross::CompilerGLSL c(spirv);
            configureGlsl(c, options);
            c.build_combined_image_samplers();
            // The entry's own combinations are globals named by SPIRV-Cross (`uniform sampler2D _3133;`): named after
            // their texture, hexcLib*, they are cut with the entry's other resources (GLSL compilers refuse orphans).
            for (const spirv_cross::CombinedImageSampler& s : c.get_combined_image_samplers())
                if (c.get_name(s.image_id).starts_with("hexcLib")) c.set_name(s.combined_id, c.get_name(s.image_id));
            // A function's combined parameter (SPIRV_Cross_Combined<texture><sampler>) takes its texture's name.
            static const std::regex combined("SPIRV_Cross_Combined(\\w+?)samp\\b");
            return std::regex_replace(cutEntry(c.compile(), "void main()"), combined, "$1");
        }
        case LibraryTarget::Msl: {
            spirv_cross::CompilerMSL c(spirv);
            configureMsl(c, options);
            return cutEntry(c.compile(), "fragment ");
        }
        case LibraryTarget::SpirvAsm:
            return disassemble(spirv);
    }
    return {};
}

// A settings struct's documentation in hextiling.glsl: the comment above it, and per field its comment and the
// value its neutral constructor (`X hexcX() { return X(...); }`) gives.
struct StructDoc {
    std::string above;
    std::map<std::string, std::string> fields;  // name -> "= default; comment"
};

std::map<std::string, StructDoc> structDocs(const std::string& glsl) {
    static const std::regex head(R"(((?://[^\n]*\n)*)struct (\w+) \{\n([^}]*)\};)"), field(R"(^ *\w+ (\w+); *(?:// *(.*))?$)"),
        argument(R"([^,(]+(\([^)]*\))?)");  // one constructor argument: vec2(-180.0, 180.0) whole
    std::map<std::string, StructDoc> docs;
    for (std::sregex_iterator it(glsl.begin(), glsl.end(), head), end; it != end; ++it) {
        StructDoc& doc = docs[(*it)[2]];
        doc.above = (*it)[1];
        // The neutral values, in field order.
        std::smatch values;
        const std::string name = (*it)[2];
        std::vector<std::string> defaults;
        if (std::regex_search(glsl, values, std::regex(name + " hexc\\w*\\(\\) \\{\\n *return " + name + "\\((.*)\\);")))
            for (std::sregex_iterator v(values[1].first, values[1].second, argument), e; v != e; ++v)
                defaults.push_back(std::regex_replace(v->str(), std::regex("^ +"), ""));
        std::istringstream lines((*it)[3].str());
        size_t index = 0;
        for (std::string line; std::getline(lines, line);) {
            std::smatch f;
            if (!std::regex_match(line, f, field)) continue;
            const std::string value = index < defaults.size() ? "= " + defaults[index] : "";
            doc.fields[f[1]] = value + (f[2].length() && !value.empty() ? "; " : "") + f[2].str();
            ++index;
        }
    }
    return docs;
}

// The emitted library with hextiling.glsl's documentation of each struct put back (SPIRV-Cross keeps no comments): the
// comment above it, and each field's default and meaning, so that a hand-written shader knows what it leaves on.
std::string documented(const std::string& emittedText, const std::string& glsl) {
    const std::map<std::string, StructDoc> docs = structDocs(glsl);
    std::istringstream in(emittedText);
    std::string out, line;
    const StructDoc* inside = nullptr;
    static const std::regex member(R"((\w+)(\s*\[\[[^\]]*\]\])?;$)");
    while (std::getline(in, line)) {
        if (line.starts_with("struct ")) {
            auto doc = docs.find(line.substr(7));
            inside = doc == docs.end() ? nullptr : &doc->second;
            if (inside) out += inside->above;
        } else if (line.starts_with("};")) {
            inside = nullptr;
        }
        std::smatch m;
        if (inside && std::regex_search(line, m, member) && inside->fields.count(m[1]) && !inside->fields.at(m[1]).empty())
            line += "  // " + inside->fields.at(m[1]);
        out += line + "\n";
    }
    return out;
}

}  // namespace

std::vector<OutputFile> hexcLibrary(const std::vector<LibraryTarget>& targets) {
    SpirvResult front = compileToSpirv(generateLibraryGlsl(), ShaderStage::Fragment, "hexc/entry.glsl");
    SpirvResult checked = front.words.empty() ? front : optimizeSpirv(front.words, false, false, false);
    if (checked.words.empty()) throw CompileError{checked.diagnostics};  // hexc's own code: a bug
    static const char* const names[] = {"hexc_hextiling.hlsl", "hexc_hextiling.glsl", "hexc_hextiling.metal", "hexc_hextiling.spvasm"};
    std::vector<OutputFile> files;
    for (LibraryTarget target : targets) {
        const char* comment = target == LibraryTarget::SpirvAsm ? "; " : "// ";
        std::string banner = std::string(comment) + "Generated by hexc " + version() +
                             ": its hex-tiling library (docs/library.md), from\n" + comment +
                             "templates/library/hextiling.glsl through glslang and SPIRV-Cross. Do not edit.\n";
        std::string text = emitted(checked.words, target);
        if (target != LibraryTarget::SpirvAsm) text = documented(text, *embeddedText("hextiling.glsl"));
        files.push_back({names[int(target)], banner + text});
    }
    return files;
}

}  // namespace hexc
