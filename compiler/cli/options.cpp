#include "options.h"

#include <map>
#include <sstream>

namespace hexc::cli {

const char* const kHelp = R"(hexc - compile hex-tiled materials to SPIR-V, HLSL, GLSL and MSL

Usage:
  hexc MATERIAL.json|SCENE.json [MORE.json ...] -o DIR [options]
  hexc render MATERIAL.json -o IMAGE.{pfm,png} [options]   (hexc render --help)
  hexc preview MATERIAL.json -o PREVIEW.png [--cell N]     (hexc preview --help)
  hexc --help | --version

Reads each material (JSON, see docs/material-format.md), injects hex-tiling into every texture slot of
its template, compiles with glslang, optimises with spirv-opt and emits through SPIRV-Cross:
  DIR/<name>.frag.spv  .frag.hlsl  .frag.glsl  .frag.metal  and  DIR/<name>.manifest.json
A scene (a JSON file with a "scene" key, see docs/scenes.md) compiles each (material, pass) variant it
uses, and writes shaders that several variants share once. Inputs unchanged since the last run (material,
textures, template, options, hexc version) are not compiled again. Nothing is written unless everything
compiles; each file is written atomically.

Options:
  -o, --out DIR            output folder (created if missing)
  --targets LIST           comma-separated subset of spirv,hlsl,glsl,msl (default: all four)
  --template FILE.glsl     use this template instead of the material's (see docs/templates.md)
  --hlsl-sm N              HLSL shader model: 50 (default), 51, 60, 61, 62, 63, 64, 65, 66
  --glsl-version V         450 (default), 330 or 310es
  --msl-version V          2.0 (default), 2.1, 2.2, 2.3 or 2.4
  --bake                   numeric settings become constants folded into the code (one shader per
                           material) instead of uniforms (one shader serves many materials)
  --no-specialize          emit every feature (rotation, gain, falloff metric) even when a setting
                           turns it off; the uniforms decide at run time
  --no-shared-lattice      evaluate the lattice per slot even where slots could share it
  --depfile FILE           write a make-style dependency file (outputs: inputs) for Make and Ninja
  --variant M.PASS         compile only this scene variant (repeatable); one the scene does not have is
                           an error
  -q, --quiet              print errors only
  -h, --help               this text
  --version                print the version

Exit codes:
  0  success (warnings may have been printed)
  1  a material or template is invalid, or compilation failed (diagnostics on stderr)
  2  bad command line
  3  an output could not be written
)";

namespace {

std::vector<std::string> split(const std::string& list) {
    std::vector<std::string> out;
    std::stringstream in(list);
    for (std::string item; std::getline(in, item, ',');) out.push_back(item);
    return out;
}

}  // namespace

Arguments parseArguments(const std::vector<std::string>& args) {
    Arguments a;
    auto value = [&](size_t& i) -> const std::string& {
        if (i + 1 >= args.size()) throw UsageError{args[i] + " needs a value"};
        return args[++i];
    };
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "-o" || arg == "--out") {
            a.outDir = value(i);
        } else if (arg == "--targets") {
            static const std::map<std::string, Target> names = {
                {"spirv", Target::Spirv}, {"hlsl", Target::Hlsl}, {"glsl", Target::Glsl}, {"msl", Target::Msl}};
            a.options.targets.clear();
            for (const std::string& t : split(value(i))) {
                auto it = names.find(t);
                if (it == names.end()) throw UsageError{"unknown target `" + t + "` in --targets; expected spirv, hlsl, glsl or msl"};
                a.options.targets.push_back(it->second);
            }
            if (a.options.targets.empty()) throw UsageError{"--targets needs at least one of spirv, hlsl, glsl, msl"};
        } else if (arg == "--template") {
            a.options.templateFile = value(i);
            if (a.options.templateFile.extension() != ".glsl") throw UsageError{"--template expects a .glsl file, got " + a.options.templateFile.string()};
        } else if (arg == "--hlsl-sm") {
            static const std::map<std::string, uint32_t> models = {{"50", 50}, {"51", 51}, {"60", 60}, {"61", 61}, {"62", 62},
                                                                   {"63", 63}, {"64", 64}, {"65", 65}, {"66", 66}};
            auto it = models.find(value(i));
            if (it == models.end()) throw UsageError{"--hlsl-sm expects 50, 51 or 60-66, got " + args[i]};
            a.options.hlslShaderModel = it->second;
        } else if (arg == "--glsl-version") {
            const std::string& v = value(i);
            if (v == "450" || v == "330") a.options.glslVersion = uint32_t(std::stoi(v));
            else if (v == "310es") a.options.glslVersion = 310, a.options.glslEs = true;
            else throw UsageError{"--glsl-version expects 450, 330 or 310es, got " + v};
        } else if (arg == "--msl-version") {
            const std::string& v = value(i);
            if (v.size() != 3 || v[0] != '2' || v[1] != '.' || v[2] < '0' || v[2] > '4') throw UsageError{"--msl-version expects 2.0 to 2.4, got " + v};
            a.options.mslMajor = 2;
            a.options.mslMinor = uint32_t(v[2] - '0');
        } else if (arg == "--depfile") {
            a.depfile = value(i);
        } else if (arg == "--variant") {
            a.variants.push_back(value(i));
        } else if (arg == "--bake") {
            a.options.bake = true;
        } else if (arg == "--no-specialize") {
            a.options.specialize = false;
        } else if (arg == "--no-shared-lattice") {
            a.options.shareLattice = false;
        } else if (arg == "-q" || arg == "--quiet") {
            a.quiet = true;
        } else if (!arg.empty() && arg[0] == '-') {
            throw UsageError{"unknown option " + arg + " (see hexc --help)"};
        } else {
            a.materials.emplace_back(arg);
        }
    }
    if (a.materials.empty()) throw UsageError{"no material or scene given (see hexc --help)"};
    if (a.outDir.empty()) throw UsageError{"no output folder given: use -o DIR"};
    return a;
}

}  // namespace hexc::cli
