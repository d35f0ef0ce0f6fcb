#include "build.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <iostream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "depfile.h"
#include "incremental.h"
#include "outputs.h"
#include "hexc/files.h"
#include "hash.h"
#include "hexc/scene.h"

namespace hexc::cli {
namespace {

// One compile: a material given on the command line, or one variant of a scene.
struct Job {
    Material material;
    std::vector<std::filesystem::path> extraInputs = {};  // the scene file, for variants
    std::string scene = {};                               // set for scene variants (their shaders are deduplicated)
    std::string hash = {};
    CompileResult result = {};
    bool upToDate = false;
};

struct SceneSummary {
    Scene scene;
    std::vector<std::string> variants;  // in the scene (after --variant filtering)
};

// Why a requested variant "<material>.<pass>" is not in any scene given.
std::string whyNotInScene(const std::string& variant, const std::vector<SceneSummary>& scenes) {
    size_t dot = variant.rfind('.');
    std::string material = variant.substr(0, dot), pass = dot == std::string::npos ? "" : variant.substr(dot + 1);
    for (const SceneSummary& s : scenes)
        for (const ScenePass& p : s.scene.passes) {
            if (p.name != pass || !p.materials) continue;
            std::string list;
            for (const std::string& m : *p.materials) list += (list.empty() ? "" : ", ") + m;
            return "pass `" + pass + "` of scene `" + s.scene.name + "` renders only " + list + ", not `" + material + "`";
        }
    return scenes.empty() ? "no scene given" : "no scene on the command line has a pass `" + pass + "` for a material `" + material + "`";
}

bool printDiagnostics(const Diagnostics& diags, bool quiet) {
    for (const Diagnostic& d : diags)
        if (!quiet || d.severity == Diagnostic::Severity::Error) std::cerr << d.format() << "\n";
    return !hasErrors(diags);
}

// A hash of a shader's target sources: variants with equal hashes share one set of files.
std::string shaderHash(const CompileResult& r) {
    ContentHash h;
    for (const OutputFile& f : r.files)
        if (!f.name.ends_with(".manifest.json")) h.add(f.contents);
    return h.hex(12);
}

// The command line's inputs, each read once: the jobs to compile and the scenes they come from.
struct Inputs {
    std::vector<Job> jobs;
    std::vector<SceneSummary> scenes;
    bool failed = false;
};

// A scene's variants (those --variant asks for, or all) become jobs.
void addScene(const std::filesystem::path& path, std::string_view text, const Arguments& a, Inputs& in) {
    SceneParseResult parsed = parseScene(text, path);
    if (!printDiagnostics(parsed.diagnostics, a.quiet) || !parsed.scene) {
        in.failed = true;
        return;
    }
    SceneSummary summary{*parsed.scene, {}};
    for (Variant& v : sceneVariants(*parsed.scene)) {
        if (!a.variants.empty() && std::find(a.variants.begin(), a.variants.end(), v.name) == a.variants.end()) continue;
        summary.variants.push_back(v.name);
        in.jobs.push_back({std::move(v.material), {path}, parsed.scene->name});
    }
    in.scenes.push_back(std::move(summary));
}

Inputs readInputs(const Arguments& a) {
    Inputs in;
    for (const auto& path : a.materials) {
        std::string why;
        std::optional<std::string> text = readFile(path, &why);
        if (text && isSceneDocument(*text)) {
            addScene(path, *text, a, in);
            continue;
        }
        ParseResult parsed = text ? parseMaterial(*text, path) : ParseResult{};
        if (!text)
            parsed.diagnostics.push_back(Diagnostic::make(Code::InputUnreadable, {path.string()}, "", "cannot read material file: " + why));
        if (!printDiagnostics(parsed.diagnostics, a.quiet) || !parsed.material) {
            in.failed = true;
            continue;
        }
        in.jobs.push_back({std::move(*parsed.material)});
    }
    return in;
}

// Every --variant names a variant of a scene given, and no two jobs write files of the same name.
bool inputsFit(const Arguments& a, const Inputs& in) {
    bool ok = true;
    for (const std::string& v : std::set<std::string>(a.variants.begin(), a.variants.end())) {
        bool found = false;
        for (const SceneSummary& s : in.scenes) found |= std::find(s.variants.begin(), s.variants.end(), v) != s.variants.end();
        if (found) continue;
        std::cerr << "hexc: error: --variant " << v << ": " << whyNotInScene(v, in.scenes) << "\n";
        ok = false;
    }
    std::set<std::string> sceneNames;
    for (const SceneSummary& s : in.scenes)
        if (!sceneNames.insert(s.scene.name).second) {
            std::cerr << "hexc: error: two scenes are named `" << s.scene.name << "`; their indexes (" << s.scene.name
                      << ".scene.json) would overwrite each other\n";
            ok = false;
        }
    std::set<std::string> names;
    for (const Job& j : in.jobs)
        if (!names.insert(j.material.name).second) {
            std::cerr << "hexc: error: two inputs produce outputs named `" << j.material.name << "`; they would overwrite each other\n";
            ok = false;
        }
    return ok;
}

// Compiles the jobs that are not up to date on every core: jobs are independent, and each keeps its own
// results, so the outputs do not depend on the order they finish in. False if any failed.
bool compileJobs(const Arguments& a, std::vector<Job>& jobs) {
    std::vector<Job*> pending;
    for (Job& j : jobs) {
        j.hash = inputHash(j.material, a.options, j.extraInputs);
        j.upToDate = upToDate(a.outDir, j.material.name, j.hash);
        if (!j.upToDate) pending.push_back(&j);
    }
    std::atomic<size_t> next = 0;
    auto worker = [&] {
        for (size_t i; (i = next++) < pending.size();) pending[i]->result = compile(pending[i]->material, a.options);
    };
    std::vector<std::thread> threads(std::min<size_t>(std::max(1u, std::thread::hardware_concurrency()), pending.size()));
    for (auto& t : threads) t = std::thread(worker);
    for (auto& t : threads) t.join();
    bool ok = true;
    for (Job* j : pending) ok &= printDiagnostics(j->result.diagnostics, a.quiet);
    return ok;
}

struct Outputs {
    std::vector<OutputFile> files;
    std::map<std::string, std::string> stamps;  // job name -> stamp text
    size_t deduplicated = 0;                    // scene variants that reuse another variant's shader files
};

// A manifest whose target files are renamed from `from` to `to` (the same suffixes).
std::string renamedManifest(const std::string& contents, const std::string& from, const std::string& to) {
    auto manifest = nlohmann::json::parse(contents);
    for (auto& [target, t] : manifest["targets"].items()) t["file"] = to + t["file"].get<std::string>().substr(from.size());
    return manifest.dump(2) + "\n";
}

// A scene variant's files: shaders named by the hash of their code, written once per scene however many
// variants share them; each variant keeps its own manifest (its parameter values differ), pointing at them.
void addVariantFiles(const Job& j, std::set<std::string>& sceneShaders, Outputs& out, std::vector<std::string>& written) {
    std::string stem = j.scene + "." + shaderHash(j.result);
    bool fresh = sceneShaders.insert(stem).second;
    out.deduplicated += fresh ? 0 : 1;
    for (OutputFile f : j.result.files) {
        bool manifest = f.name.ends_with(".manifest.json");
        if (manifest)
            f.contents = renamedManifest(f.contents, j.material.name, stem);
        else
            f.name = stem + f.name.substr(j.material.name.size());
        written.push_back(f.name);
        if (manifest || fresh) out.files.push_back(std::move(f));
    }
}

Outputs collectOutputs(const Inputs& in) {
    Outputs out;
    std::set<std::string> sceneShaders;
    for (const Job& j : in.jobs) {
        if (j.upToDate) continue;
        std::vector<std::string> written;
        if (!j.scene.empty()) {
            addVariantFiles(j, sceneShaders, out, written);
        } else {
            for (const OutputFile& f : j.result.files) written.push_back(f.name);
            out.files.insert(out.files.end(), j.result.files.begin(), j.result.files.end());
        }
        out.stamps[j.material.name] = stampText(j.hash, written);
    }
    // Each scene's index of its variants and their manifests.
    for (const SceneSummary& s : in.scenes) {
        nlohmann::json index = {{"scene", s.scene.name}, {"variants", nlohmann::json::object()}};
        for (const std::string& v : s.variants) index["variants"][v] = {{"manifest", v + ".manifest.json"}};
        out.files.push_back({s.scene.name + ".scene.json", index.dump(2) + "\n"});
    }
    return out;
}

std::string depfileFor(const Arguments& a, const std::vector<Job>& jobs) {
    std::vector<std::filesystem::path> outs, ins;
    std::set<std::filesystem::path> seenIn;
    for (const Job& j : jobs) {
        outs.push_back(a.outDir / (j.material.name + ".manifest.json"));
        std::vector<std::filesystem::path> files = inputFiles(j.material, a.options);
        files.insert(files.end(), j.extraInputs.begin(), j.extraInputs.end());
        for (const auto& f : files)
            if (seenIn.insert(f).second) ins.push_back(f);
    }
    return depfileText(outs, ins);
}

// Writes every output, then the stamps (a crash before them leaves the jobs to be compiled again next time),
// then the depfile. Returns the bytes written; throws when something cannot be written.
size_t writeOutputs(const Arguments& a, const Outputs& out, const std::string& depfile) {
    size_t bytes = 0;
    std::filesystem::create_directories(a.outDir);
    for (const OutputFile& f : out.files) {
        writeAtomically(a.outDir, f.name, f.contents);
        bytes += f.contents.size();
    }
    for (const auto& [name, text] : out.stamps) writeAtomically(a.outDir, stampName(name), text);
    if (!a.depfile.empty())
        writeAtomically(a.depfile.parent_path().empty() ? "." : a.depfile.parent_path(), a.depfile.filename().string(), depfile);
    return bytes;
}

void printSummary(const Arguments& a, const Inputs& in, const Outputs& out, size_t bytes) {
    size_t upToDate = 0;
    for (const Job& j : in.jobs) upToDate += j.upToDate;
    for (const SceneSummary& s : in.scenes)
        std::cerr << "hexc: scene " << s.scene.name << ": " << s.scene.materials.size() * s.scene.passes.size() << " variants possible, "
                  << s.variants.size() << " used\n";
    std::cerr << "hexc: " << in.jobs.size() - upToDate << " compiled, " << upToDate << " up to date";
    if (!in.scenes.empty()) std::cerr << ", " << out.deduplicated << " scene shaders deduplicated";
    std::cerr << "; wrote " << out.files.size() << " files (" << bytes << " bytes) to " << a.outDir.string() << "\n";
}

}  // namespace

int buildCommand(const Arguments& a) {
    Inputs in = readInputs(a);
    bool ok = inputsFit(a, in) && !in.failed;
    if (!ok || !compileJobs(a, in.jobs)) {
        std::cerr << "hexc: nothing written\n";
        return kInvalidInput;
    }
    Outputs out = collectOutputs(in);
    std::string depfile;
    try {
        if (!a.depfile.empty()) depfile = depfileFor(a, in.jobs);
    } catch (const std::invalid_argument& e) {
        std::cerr << "hexc: error: " << e.what() << "\nhexc: nothing written\n";
        return kInvalidInput;
    }
    size_t bytes = 0;
    try {
        bytes = writeOutputs(a, out, depfile);
    } catch (const std::exception& e) {
        std::cerr << "hexc: " << e.what() << "\n";
        return kWriteFailed;
    }
    if (!a.quiet) printSummary(a, in, out, bytes);
    return kOk;
}

}  // namespace hexc::cli
