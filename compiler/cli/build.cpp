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
    std::vector<std::string> variants;   // in the scene (after --variant filtering)
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

}  // namespace

int buildCommand(const Arguments& a) {
    std::vector<Job> jobs;
    std::vector<SceneSummary> scenes;
    std::set<std::string> requested(a.variants.begin(), a.variants.end()), found;
    bool failed = false;
    for (const auto& path : a.materials) {
        std::optional<std::string> text = readFile(path);
        if (text && isSceneDocument(*text)) {
            SceneParseResult parsed = parseSceneFile(path);
            if (!printDiagnostics(parsed.diagnostics, a.quiet) || !parsed.scene) {
                failed = true;
                continue;
            }
            SceneSummary summary{*parsed.scene, {}};
            for (Variant& v : sceneVariants(*parsed.scene)) {
                if (!requested.empty() && !requested.count(v.name)) continue;
                found.insert(v.name);
                summary.variants.push_back(v.name);
                jobs.push_back({std::move(v.material), {path}, parsed.scene->name});
            }
            scenes.push_back(std::move(summary));
            continue;
        }
        ParseResult parsed = parseMaterialFile(path);
        if (!printDiagnostics(parsed.diagnostics, a.quiet) || !parsed.material) {
            failed = true;
            continue;
        }
        jobs.push_back({std::move(*parsed.material)});
    }
    for (const std::string& v : requested)
        if (!found.count(v)) {
            std::cerr << "hexc: error: --variant " << v << ": " << whyNotInScene(v, scenes) << "\n";
            failed = true;
        }
    std::set<std::string> names;
    for (const Job& j : jobs)
        if (!names.insert(j.material.name).second) {
            std::cerr << "hexc: error: two inputs produce outputs named `" << j.material.name << "`; they would overwrite each other\n";
            failed = true;
        }

    // Compile what is not up to date, on every core: jobs are independent, and each keeps its own
    // results, so the outputs do not depend on the order they finish in.
    size_t upToDateCount = 0;
    std::vector<Job*> pending;
    for (Job& j : jobs) {
        if (failed) break;
        j.hash = inputHash(j.material, a.options, j.extraInputs);
        j.upToDate = upToDate(a.outDir, j.material.name, j.hash);
        if (j.upToDate) ++upToDateCount;
        else pending.push_back(&j);
    }
    std::atomic<size_t> next = 0;
    auto worker = [&] {
        for (size_t i; (i = next++) < pending.size();) pending[i]->result = compile(pending[i]->material, a.options);
    };
    std::vector<std::thread> threads(std::min<size_t>(std::max(1u, std::thread::hardware_concurrency()), pending.size()));
    for (auto& t : threads) t = std::thread(worker);
    for (auto& t : threads) t.join();
    for (Job* j : pending) failed |= !printDiagnostics(j->result.diagnostics, a.quiet);
    if (failed) {
        std::cerr << "hexc: nothing written\n";
        return kInvalidInput;
    }

    // Scene variants with the same shader code share one set of shader files, named by that code's hash;
    // each variant keeps its own manifest (its parameter values differ), pointing at the shared files.
    std::vector<OutputFile> outputs;
    std::map<std::string, std::string> stamps;  // job name -> stamp text
    std::set<std::string> sceneShaders;
    size_t deduplicated = 0;
    for (Job& j : jobs) {
        if (j.upToDate) continue;
        std::vector<std::string> written;
        if (j.scene.empty()) {
            for (const OutputFile& f : j.result.files) {
                outputs.push_back(f);
                written.push_back(f.name);
            }
        } else {
            std::string stem = j.scene + "." + shaderHash(j.result);
            bool fresh = sceneShaders.insert(stem).second;
            deduplicated += fresh ? 0 : 1;
            for (OutputFile f : j.result.files) {
                if (f.name.ends_with(".manifest.json")) {
                    auto manifest = nlohmann::json::parse(f.contents);
                    for (auto& [target, t] : manifest["targets"].items()) {
                        std::string file = t["file"];
                        t["file"] = stem + file.substr(j.material.name.size());
                    }
                    f.contents = manifest.dump(2) + "\n";
                } else {
                    f.name = stem + f.name.substr(j.material.name.size());
                    if (!fresh) {
                        written.push_back(f.name);
                        continue;
                    }
                }
                written.push_back(f.name);
                outputs.push_back(std::move(f));
            }
        }
        stamps[j.material.name] = stampText(j.hash, written);
    }
    // Each scene's index of its variants and their manifests.
    for (const SceneSummary& s : scenes) {
        nlohmann::json index = {{"scene", s.scene.name}, {"variants", nlohmann::json::object()}};
        for (const std::string& v : s.variants) index["variants"][v] = {{"manifest", v + ".manifest.json"}};
        outputs.push_back({s.scene.name + ".scene.json", index.dump(2) + "\n"});
    }

    size_t bytes = 0;
    try {
        std::filesystem::create_directories(a.outDir);
        for (const OutputFile& f : outputs) {
            writeAtomically(a.outDir, f.name, f.contents);
            bytes += f.contents.size();
        }
        // Stamps last: a crash before this point leaves the job to be compiled again next time.
        for (const auto& [name, text] : stamps) writeAtomically(a.outDir, stampName(name), text);
        if (!a.depfile.empty()) {
            std::vector<std::filesystem::path> outs, ins;
            std::set<std::filesystem::path> seenIn;
            for (const Job& j : jobs) {
                outs.push_back(a.outDir / (j.material.name + ".manifest.json"));
                std::vector<std::filesystem::path> files = inputFiles(j.material, a.options);
                files.insert(files.end(), j.extraInputs.begin(), j.extraInputs.end());
                for (const auto& f : files)
                    if (seenIn.insert(f).second) ins.push_back(f);
            }
            writeAtomically(a.depfile.parent_path().empty() ? "." : a.depfile.parent_path(), a.depfile.filename().string(), depfileText(outs, ins));
        }
    } catch (const std::exception& e) {
        std::cerr << "hexc: " << e.what() << "\n";
        return kWriteFailed;
    }
    if (!a.quiet) {
        for (const SceneSummary& s : scenes)
            std::cerr << "hexc: scene " << s.scene.name << ": " << s.scene.materials.size() * s.scene.passes.size() << " variants possible, "
                      << s.variants.size() << " used\n";
        std::cerr << "hexc: " << jobs.size() - upToDateCount << " compiled, " << upToDateCount << " up to date";
        if (!scenes.empty()) std::cerr << ", " << deduplicated << " scene shaders deduplicated";
        std::cerr << "; wrote " << outputs.size() << " files (" << bytes << " bytes) to " << a.outDir.string() << "\n";
    }
    return kOk;
}

}  // namespace hexc::cli
