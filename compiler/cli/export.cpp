#include "export.h"

#include <CLI/CLI.hpp>

#include <iostream>

#include "hexc/materialx.h"
#include "options.h"

namespace hexc::cli {

namespace {

const char* const kExportHelp = R"(hexc export-mtlx - write a material as a MaterialX document

  hexc export-mtlx MATERIAL.json -o MATERIAL.mtlx

Writes a MaterialX 1.39 document that MaterialX tools (MaterialXView, USD, DCC tools) can preview: one nodegraph
with a hextiledimage, hextilednormalmap or tiledimage node per slot, feeding a standard_surface (a `height` slot
feeds a displacement shader). Texture and template paths are made relative to the document's folder. Settings
MaterialX has no input for (mode, mask, taps, exponent, steps, height blending, the template) are kept as hexc_*
attributes, which MaterialX tools ignore and hexc reads back: `hexc MATERIAL.mtlx -o DIR` compiles the same
shaders as the JSON. docs/materialx.md has the mapping and its limits.
)";

}  // namespace

int exportCommand(const std::vector<std::string>& args) {
    CLI::App app{kExportHelp, "hexc export-mtlx"};
    std::filesystem::path material, out;
    app.add_option("material", material, "the material to export (JSON, or MaterialX)")->required()->type_name("MATERIAL.json");
    app.add_option("-o,--out", out, "the MaterialX document to write")->required()->type_name("FILE.mtlx");
    if (std::optional<int> done = parseWith(app, args)) return *done;
    if (!isMaterialXFile(out)) {
        std::cerr << "hexc: -o " << out.string() << ": expected a file name ending in .mtlx\n";
        return kUsage;
    }
    ParseResult parsed = parseMaterialFile(material);
    std::cerr << formatAll(parsed.diagnostics);
    if (!parsed.material) return kInvalidInput;
    MaterialXExport exported = exportMaterialX(*parsed.material, out);
    std::cerr << formatAll(exported.diagnostics);
    if (!exported.document) return kInvalidInput;
    try {
        const std::filesystem::path dir = out.has_parent_path() ? out.parent_path() : ".";
        std::filesystem::create_directories(dir);
        writeAtomically(dir, out.filename().string(), *exported.document);
    } catch (const std::exception& e) {
        std::cerr << "hexc: " << e.what() << "\n";
        return kWriteFailed;
    }
    std::cerr << "hexc: wrote " << out.string() << "\n";
    return kOk;
}

}  // namespace hexc::cli
