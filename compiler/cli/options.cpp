#include "options.h"

#include "hexc/cache.h"
#include "hexc/engines.h"
#include "hexc/library.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <map>
#include <set>

namespace hexc::cli {
namespace {

// The engines --engine accepts, as CLI11 checks them.
std::vector<std::string> engineList() {
    std::vector<std::string> out;
    for (std::string_view name : engineNames()) out.emplace_back(name);
    return out;
}

std::string joined(const std::vector<std::string>& names, const char* separator) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : separator) + n;
    return out;
}

// The description on top of --help; its lists of targets, their files and the library's targets from the target
// table.
std::string description() {
    const std::vector<Target> defaults = defaultTargets();
    std::vector<std::string> files, also;
    for (Target t : defaults) files.push_back(shaderFileName("", t));
    for (const std::string& name : targetNames())
        if (const Target t = *targetNamed(name); std::find(defaults.begin(), defaults.end(), t) == defaults.end())
            also.push_back("with --targets " + name + " also DIR/<name>" + shaderFileName("", t));
    also.push_back("with --vertex also DIR/<name>.vert.*, a pass-through vertex stage feeding the fragment shader");
    also.push_back("with --emit-generated also DIR/<name>.generated.frag, the Vulkan GLSL hexc generated and compiled");
    return "hexc - compile hex-tiled materials to shaders: " + joined(targetNames(), ", ") + R"(

  hexc MATERIAL.json|MATERIAL.mtlx|SCENE.json [MORE ...] -o DIR [options]
  hexc render MATERIAL.json -o IMAGE.{pfm,png} [options]   (hexc render --help)
  hexc preview MATERIAL.json -o PREVIEW.png [--cell N]     (hexc preview --help)
  hexc bake MATERIAL.json -o DIR --size N [--repeats K]    (hexc bake --help: seamless textures, no shader)
  hexc library --target )" +
           joined(libraryTargetNames(), "|") + R"( -o DIR   (hexc library --help)
  hexc export-mtlx MATERIAL.json -o MATERIAL.mtlx          (hexc export-mtlx --help)
  hexc lint MATERIAL.json|TEXTURE                          (hexc lint --help: check its textures' content)
  hexc edit MATERIAL.json [--port N]                       (hexc edit --help: tune it live in a browser)

Reads each material (JSON, docs/material-format.md, or MaterialX, docs/materialx.md), injects hex-tiling
into every texture slot of its template, compiles with glslang, optimises with spirv-opt and emits through SPIRV-Cross (wgsl: naga):
  DIR/<name>)" +
           joined(files, "  ") + R"(  and  DIR/<name>.manifest.json
  ()" + joined(also, ";\n   ") +
           R"()
A scene (a JSON file with a "scene" key, see docs/scenes.md) compiles each (material, pass) variant it
uses into DIR/<material>.<pass>.*, with an index (DIR/<scene>.scene.json) that marks variants whose code is
identical. Inputs unchanged since the last run (material, textures' headers, template, options, hexc build)
are not compiled again (--force compiles them anyway); shader code compiled before, in this batch or an
earlier run, comes from the cache (--cache-dir). Nothing is written unless everything compiles; each file is
written atomically.
)";
}

// Fills the compile options from the checked names of --target, --glsl-version, --msl-version and --line-directives.
void applyNames(const std::vector<std::string>& targets, const std::string& glsl, const std::string& msl, const std::string& lines,
                CompileOptions& o) {
    if (!targets.empty()) o.targets.clear();
    for (const std::string& t : targets) o.targets.push_back(*targetNamed(t));
    if (!glsl.empty()) {
        o.glslEs = glsl.ends_with("es");
        o.glslVersion = uint32_t(std::stoi(glsl));
    }
    if (!msl.empty()) o.mslMinor = uint32_t(msl[2] - '0');
    for (LineDirectives mode : {LineDirectives::None, LineDirectives::Functions, LineDirectives::Statements})
        if (toString(mode) == lines) o.lineDirectives = mode;
}

// --targets' help: the names, and the default set.
std::string targetsHelp() {
    std::string defaults;
    for (Target t : defaultTargets()) defaults += (defaults.empty() ? "" : ", ") + std::string(toString(t));
    return targetList(targetNames(), targetNamed) + "; repeatable or comma-separated\n(default: " + defaults + ")";
}

}  // namespace

void LayoutOptions::add(CLI::App& app) {
    const char* group = "Resource layout (docs/cli.md; flags override the file)";
    app.add_option("--layout", file, "where hexc's resources go on each target, as a JSON file")->type_name("FILE.json")->group(group);
    for (const LayoutField& f : layoutFields()) {
        std::string name = std::string("--") + (std::string_view(f.target) == "vulkan" ? "" : std::string(f.target) + "-") + f.key;
        std::replace(name.begin(), name.end(), '_', '-');  // argument_buffers: --msl-argument-buffers
        flags.push_back({name, &f});
    }
    for (Flag& f : flags)  // bound once the vector is complete: its elements no longer move
        app.add_option(f.name, f.value, f.field->help)->type_name("N")->check(CLI::Range(0u, f.field->max).description(""))->group(group);
}

void Messages::report(const Diagnostics& diagnostics) const {
    *text << formatAll(diagnostics);
    if (located) located->insert(located->end(), diagnostics.begin(), diagnostics.end());
}

bool LayoutOptions::resolve(ResourceLayout& out, const Messages& m) const {
    if (!file.empty()) {
        LayoutParseResult parsed = parseLayoutFile(file);
        m.report(parsed.diagnostics);
        if (!parsed.layout) return false;
        out = *parsed.layout;
    }
    for (const Flag& f : flags)
        if (f.value) f.field->field(out) = *f.value;
    return true;
}

std::string targetList(const std::vector<std::string>& names, std::optional<Target> (*named)(std::string_view)) {
    std::string out;
    for (const std::string& t : names) {
        std::string_view alias = targetAlias(*named(t));
        out += (out.empty() ? "" : ", ") + t + (alias.empty() ? "" : " (or " + std::string(alias) + ")");
    }
    return out;
}

CLI::Validator targetCheck(const std::vector<std::string>& names, std::optional<Target> (*named)(std::string_view)) {
    std::string list;
    for (const std::string& t : names) list += (list.empty() ? "" : ",") + t;
    return CLI::Validator([=](std::string& t) { return named(t) ? "" : t + " not in {" + list + "}"; }, "");
}

namespace {

// What some of the compile mode's options are bound to, checked and applied to the Arguments after parsing
// (resolveArguments).
struct Unresolved {
    std::vector<std::string> materials, targets;
    std::string glsl, msl, lines;  // names CLI11 has checked (applyNames)
    bool manifestPaths = false;
    LayoutOptions layout;
};

// The inputs, the output folder, the targets, the template and the entry point.
void addInputOptions(CLI::App& app, Arguments& a, Unresolved& u) {
    // Required by hand (resolveArguments), after CLI11 has reported unknown options (it checks requirements first).
    app.add_option("materials", u.materials, "material or scene files")->type_name("FILE.json");
    app.add_option("-o,--out", a.outDir, "output folder (created if missing)")->type_name("DIR");
    app.add_option("--target,--targets", u.targets, targetsHelp())
        ->delimiter(',')
        ->allow_extra_args(false)
        ->check(targetCheck(targetNames(), targetNamed));
    app.add_option("--template", a.options.templateFile, "use this template instead of the material's (docs/templates.md)")
        ->type_name("FILE.glsl")
        ->check(CLI::Validator([](std::string& f) { return f.ends_with(".glsl") ? "" : "expected a .glsl file, got " + f; }, ""));
    app.add_option("--entry", a.options.entryPoint, "fragment entry point on every target but OpenGL GLSL (default <material>_frag)")
        ->type_name("NAME")
        ->check(CLI::Validator([](std::string& n) { return isEntryPointName(n) ? "" : "expected an identifier (not reserved), got " + n; },
                               ""));
}

// The targets' versions: HLSL shader model, GLSL and MSL versions.
void addVersionOptions(CLI::App& app, Arguments& a, Unresolved& u) {
    // dxc and Slang write shader models 6_0 or 6.0; glslc-style tools 60: all name the same model.
    app.add_option("--hlsl-sm", a.options.hlslShaderModel, "HLSL shader model: 50, 51, 60 ... 66, also as 6.0 or 6_0 (default 50)")
        ->transform(CLI::Validator(
            [](std::string& v) {  // checked here, so that an error quotes what was written, not "69" for 6.9
                std::string model = v;
                if (model.size() == 3 && (model[1] == '.' || model[1] == '_')) model.erase(1, 1);
                static const std::set<std::string> models = {"50", "51", "60", "61", "62", "63", "64", "65", "66"};
                if (!models.count(model)) return "`" + v + "` is not a shader model hexc emits: 50, 51, 60 ... 66 (or 5.0, 6_0 ...)";
                v = model;
                return std::string();
            },
            ""))
        ->type_name("MODEL");
    app.add_option("--glsl-version", u.glsl, "GLSL version: 460, 450 (default), 330, 310es, 300es (WebGL 2)")
        ->transform(CLI::Validator(
            [](std::string& v) {  // "300 es", "300_es" as other tools write it
                if (v.size() == 6 && (v[3] == ' ' || v[3] == '_') && v.ends_with("es")) v.erase(3, 1);
                return std::string();
            },
            ""))
        ->check(CLI::IsMember({"460", "450", "330", "310es", "300es"}));
    app.add_option("--msl-version", u.msl, "MSL version (default 2.0)")->check(CLI::IsMember({"2.0", "2.1", "2.2", "2.3", "2.4"}));
}

// What the outputs hold: the vertex stage, debug code and its #line directives, the generated GLSL, the manifest's
// paths, baked settings, specialisation and the shared lattice.
void addShaderOptions(CLI::App& app, Arguments& a, Unresolved& u) {
    app.add_flag("--vertex", a.options.vertex,
                 "also write the pass-through vertex stage <name>.vert.* that feeds the\nfragment shader's inputs");
    CLI::Option* debug = app.add_flag("--debug", a.options.debug,
                                      "readable outputs (like glslc/dxc -O0): no optimisation, hexc's\n"
                                      "functions kept by name, #line references to the template and library");
    app.add_option("--line-directives", u.lines,
                   "with --debug: a #line at the start of each function (functions, the\n"
                   "default), before each statement (statements) or nowhere (none)")
        ->check(CLI::IsMember({"none", "functions", "statements"}))
        ->needs(debug);
    app.add_flag("--emit-generated", a.options.emitGenerated, "also write the generated Vulkan GLSL fed to glslang: <name>.generated.frag");
    app.add_flag("--manifest-paths", u.manifestPaths,
                 "the manifest also gives where the material, its textures, template and\nlayout file are, relative to the output folder "
                 "(always with --engine:\nrelative to each package's folder)");
    app.add_flag("--bake", a.options.bake,
                 "numeric settings become constants folded into the code (one shader\nper material) instead of uniforms (not `hexc bake`, "
                 "which bakes textures)");
    app.add_flag_callback(
        "--no-specialise", [&] { a.options.specialise = false; },
        "emit every feature even when a setting turns it off; the uniforms decide");
    app.add_flag_callback(
        "--no-shared-lattice", [&] { a.options.shareLattice = false; }, "evaluate the lattice per slot even where slots could share it");
    app.add_flag("--functions", a.options.functions,
                 "write the material's functions for an engine's own material instead of a\n"
                 "shader: hexc_<slot>(uv), hexc_<slot>_normal(uv); no main (docs/engines.md)");
    app.add_option("--engine,--engines", a.engines,
                   "write a package for each engine instead of shaders: " + joined(engineList(), ", ") +
                       "\n(DIR/<engine>/...; functions with every setting baked; docs/engines.md)")
        ->delimiter(',')
        ->check(CLI::IsMember(engineList()));
    app.add_flag_callback(
        "--uv-bottom-left", [&] { a.options.uvOrigin = UvOrigin::BottomLeft; },
        "the engine's uv (0,0) is the image's bottom-left, v up (OpenGL's); hexc\nsamples at (u, 1 - v) itself (docs/conventions.md)");
}

// How a build runs and what it prints: the depfile, the outputs' list, scene variants, messages, stamps and jobs.
void addBuildOptions(CLI::App& app, Arguments& a) {
    app.add_option("--depfile", a.depfile, "write a make-style dependency file for Make and Ninja")->type_name("FILE");
    app.add_flag("--list-outputs", a.listOutputs,
                 "print, as JSON, the files a build would write (\"outputs\") and those that\n"
                 "list depends on (\"inputs\"); compile and write nothing (docs/cli.md)");
    app.add_option("--variant", a.variants, "compile only this scene variant (repeatable)")
        ->type_name("MATERIAL.PASS")
        ->allow_extra_args(false);
    app.add_flag("-q,--quiet", a.quiet, "print errors and warnings only (no summary)");
    app.add_flag("-v,--verbose", a.verbose, "say what was compiled, what was up to date or shared, and why")->excludes("-q");
    app.add_flag_callback(
        "--no-warnings", [&] { a.warnings = false; }, "do not print warnings");
    app.add_flag("--force", a.force, "compile every material, even those whose stamp says they are up to date");
    app.add_option("-j,--jobs", a.jobs, "compile N materials at once (default: one per core; -j 1 also emits targets on one thread)")
        ->check(CLI::Range(1u, 256u))
        ->type_name("N");
}

// The shader cache's folder, or none.
void addCacheOptions(CLI::App& app, Arguments& a) {
    a.cacheDir = defaultCacheDir();
    app.add_option("--cache-dir", a.cacheDir,
                   "keep compiled shader code here, shared by runs and processes (default:\n$XDG_CACHE_HOME/hexc or ~/.cache/hexc; " +
                       std::to_string(kDefaultCacheBytes >> 20) + " MiB, least recently used\nentries removed)")
        ->type_name("DIR");
    app.add_flag_callback(
        "--no-cache", [&] { a.cacheDir.clear(); },
        "no cache folder: compile all code anew (identical code in one batch is\nstill compiled once)");
}

// The checks CLI11 cannot make, then the names and the layout applied to `a`.
std::optional<int> resolveArguments(const Unresolved& u, Arguments& a) {
    if (u.materials.empty() || a.outDir.empty()) {
        *a.messages.text << "hexc: " << (u.materials.empty() ? "no material or scene given" : "no output folder given: use -o DIR")
                         << " (see hexc --help)\n";
        return kUsage;
    }
    a.materials.assign(u.materials.begin(), u.materials.end());
    a.warnings &= !a.listOutputs;  // a build system lists at configure time; the build itself prints the warnings
    // An engine package's manifest gives the textures the package does not hold from its own folder in the output folder.
    if (u.manifestPaths || !a.engines.empty()) a.options.manifestPathsFrom = a.outDir;
    applyNames(u.targets, u.glsl, u.msl, u.lines, a.options);
    if (a.options.functions && u.targets.empty()) a.options.targets = defaultFunctionsTargets();
    if (!u.layout.resolve(a.options.layout, a.messages)) return kInvalidInput;
    if (uint32_t space = a.options.layout.hlsl.space; space != 0 && a.options.hlslShaderModel < 51) {
        *a.messages.text << "hexc: HLSL register space " << space << " needs --hlsl-sm 51 or later (shader model 5.0 has no spaces)\n";
        return kUsage;
    }
    return std::nullopt;
}

}  // namespace

std::optional<int> parseArguments(const std::vector<std::string>& args, Arguments& a) {
    CLI::App app(description(), "hexc");
    Unresolved u;
    addInputOptions(app, a, u);
    addVersionOptions(app, a, u);
    u.layout.add(app);
    addShaderOptions(app, a, u);
    addBuildOptions(app, a);
    addCacheOptions(app, a);
    app.set_version_flag("--version",
                         [] { return std::string("hexc ") + version() + " (build " + buildId() + ")\n" + toolchainVersions(); });
    if (std::optional<int> done = parseWith(app, args, *a.messages.text)) return done;
    return resolveArguments(u, a);
}

}  // namespace hexc::cli
