#include "build.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <iostream>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <sys/stat.h>
#include <thread>
#include <unordered_map>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include "depfile.h"
#include "incremental.h"
#include "progress.h"
#include "hexc/cache.h"
#include "hexc/engines.h"
#include "hexc/files.h"
#include "hexc/materialx.h"
#include "hexc/suggest.h"
#include "hexc/hash.h"
#include "hexc/scene.h"
#include "hexc/spirv.h"

namespace hexc::cli {
namespace {

// One compile: a material given on the command line, or one variant of a scene.
struct Job {
    Material material;
    std::vector<std::filesystem::path> extraInputs = {};  // the scene file, for variants
    bool passReadsFewer = false;  // a scene pass with its own template and no slot list: leaving slots out is its purpose
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

// Errors always; warnings unless --no-warnings, and a slot a scene pass leaves out on purpose only with -v.
bool printDiagnostics(const Diagnostics& diags, const Arguments& a, bool passReadsFewer = false) {
    Diagnostics shown;
    for (const Diagnostic& d : byPosition(diags)) {
        const bool expected = passReadsFewer && d.code == Code::SlotNotRead && !a.verbose;
        if (d.severity == Diagnostic::Severity::Error || (a.warnings && !expected)) shown.push_back(d);
    }
    a.messages.report(shown);
    return !hasErrors(diags);
}

// A shader file's code without its entry point's name, which differs between variants whose code is the same: the
// name taken out of text, OpEntryPoint and OpName (the only instructions that hold it) skipped in SPIR-V. Text
// loses its banner too, which names the material.
std::string withoutEntryName(const std::string& file, std::string contents, const std::string& entry) {
    if (!file.ends_with(".spv")) {
        contents = withoutBanner(std::move(contents));
        if (entry.empty()) return contents;
        for (size_t at; (at = contents.find(entry)) != std::string::npos;) contents.erase(at, entry.size());
        return contents;
    }
    const std::vector<uint32_t> words = spirvWords(contents);
    std::string code(contents.data(), std::min<size_t>(contents.size(), 20));  // the header
    for (size_t at = 5; at < words.size();) {
        const uint32_t count = words[at] >> 16, opcode = words[at] & 0xffff;
        if (count == 0) break;  // not SPIR-V hexc wrote; hash what was read so far
        if (opcode != 15 && opcode != 5)
            code.append(reinterpret_cast<const char*>(&words[at]), std::min<size_t>(count, words.size() - at) * 4);
        at += count;
    }
    return code;
}

// A hash of a variant's shader code (its target files, not its manifest, which holds its own parameter values):
// variants with equal hashes have identical shaders but for the entry point's name (the same for all under --entry).
// An up-to-date variant's files are read back.
std::string shaderHash(const std::filesystem::path& dir, const Job& j, const CompileOptions& options) {
    // The default names' common part ("rock_depth_" of rock_depth_frag and rock_depth_vert).
    const std::string frag = defaultEntryPoint(j.material.name), entry = options.entryPoint.empty() ? frag.substr(0, frag.size() - 4) : "";
    ContentHash h;
    if (!j.upToDate) {
        for (const OutputFile& f : j.result.files)
            if (!f.name.ends_with(".manifest.json")) h.add(withoutEntryName(f.name, f.contents, entry));
        return h.hex(12);
    }
    for (const std::string& name : stampedOutputs(dir, j.material.name))
        if (!name.ends_with(".manifest.json")) h.add(withoutEntryName(name, readFile(dir / name).value_or(""), entry));
    return h.hex(12);
}

// The command line's inputs, each read once: the jobs to compile and the scenes they come from.
struct Inputs {
    std::vector<Job> jobs;
    std::vector<SceneSummary> scenes;
    bool failed = false;
    bool stopped = false;           // by the progress callback (Arguments::progress)
    ShaderCache::Stats cache = {};  // of the jobs compiled
};

// A scene's variants (those --variant asks for, or all) become jobs.
void addScene(const std::filesystem::path& path, std::string_view text, const Arguments& a, Inputs& in) {
    SceneParseResult parsed = parseScene(text, path);
    if (!printDiagnostics(parsed.diagnostics, a) || !parsed.scene) {
        in.failed = true;
        return;
    }
    SceneSummary summary{*parsed.scene, {}};
    const std::unordered_set<std::string> asked(a.variants.begin(), a.variants.end());
    for (Variant& v : sceneVariants(*parsed.scene)) {
        if (!asked.empty() && !asked.contains(v.name)) continue;
        summary.variants.push_back(v.name);
        const ScenePass& pass = *std::find_if(parsed.scene->passes.begin(), parsed.scene->passes.end(),
                                              [&](const ScenePass& p) { return p.name == v.passName; });
        in.jobs.push_back({std::move(v.material), {path}, pass.templ && !pass.slots});
    }
    in.scenes.push_back(std::move(summary));
}

// Reads, parses and checks the material, scene or MaterialX document at `path` into `in`.
void readInput(const std::filesystem::path& path, const Arguments& a, Inputs& in) {
    std::string why;
    std::optional<std::string> text = readFile(path, &why);
    if (text && isSceneDocument(*text)) {
        addScene(path, *text, a, in);
        return;
    }
    // A MaterialX document may hold several materials: each is a job.
    std::vector<ParseResult> parsed = !text                   ? std::vector<ParseResult>(1)
                                      : isMaterialXFile(path) ? parseMaterialXDocument(*text, path)
                                                              : std::vector<ParseResult>{parseMaterial(*text, path)};
    if (!text)
        parsed[0].diagnostics.push_back(Diagnostic::make(Code::InputUnreadable, {path.string()}, "", "cannot read material file: " + why));
    for (ParseResult& p : parsed) {
        if (p.partial) {  // the template's problems in the same run as the material's
            const Diagnostics t = checkTemplate(*p.partial, a.options);
            p.diagnostics.insert(p.diagnostics.end(), t.begin(), t.end());
        }
        if (printDiagnostics(p.diagnostics, a) && p.material)
            in.jobs.push_back({std::move(*p.material)});
        else
            in.failed = true;
    }
}

Inputs readInputs(const Arguments& a) {
    Inputs in;
    for (const auto& path : a.materials) {
        try {
            readInput(path, a, in);
        } catch (const std::bad_alloc&) {  // anywhere in reading, parsing or checking it: what it held is freed by now
            std::error_code ec;
            printDiagnostics({outOfMemoryReading(path.string(), std::filesystem::file_size(path, ec))}, a);
            in.failed = true;
        }
    }
    return in;
}

// Every --variant names a variant of a scene given, and no two jobs write files of the same name.
bool inputsFit(const Arguments& a, const Inputs& in) {
    bool ok = true;
    std::unordered_set<std::string_view> used;
    for (const SceneSummary& s : in.scenes) used.insert(s.variants.begin(), s.variants.end());
    for (const std::string& v : std::set<std::string>(a.variants.begin(), a.variants.end())) {
        if (used.contains(v)) continue;
        *a.messages.text << "hexc: error: --variant " << v << ": " << whyNotInScene(v, in.scenes) << "\n";
        ok = false;
    }
    // An engine package replaces the template with the engine's own, so a scene's passes (each a template of its own)
    // have no package: the engine is given the scene's material files instead.
    if (!a.engines.empty() && !in.scenes.empty()) {
        *a.messages.text << "hexc: error: --engine packages materials, not a scene's passes: pass " << in.scenes.front().scene.name
                         << "'s material files instead\n";
        ok = false;
    }
    std::set<std::string> sceneNames;
    for (const SceneSummary& s : in.scenes)
        if (!sceneNames.insert(s.scene.name).second) {
            *a.messages.text << "hexc: error: two scenes are named `" << s.scene.name << "`; their indexes (" << s.scene.name
                             << ".scene.json) would overwrite each other\n";
            ok = false;
        }
    std::set<std::string> names;
    for (const Job& j : in.jobs)
        if (!names.insert(j.material.name).second) {
            *a.messages.text << "hexc: error: two inputs produce outputs named `" << j.material.name
                             << "`; they would overwrite each other\n";
            ok = false;
        }
    return ok;
}

// Compiles the jobs on every core, with a progress line on a terminal (cleared before diagnostics are printed) or
// a.progress's calls: jobs are independent, and each keeps its own results, so the outputs do not depend on the
// order they finish in. A progress callback that says stop leaves the jobs not yet started (`stopped` set).
ShaderCache::Stats compileInParallel(const Arguments& a, const std::vector<Job*>& pending, bool& stopped) {
    if (pending.empty()) return {};
    std::optional<ShaderCache> own;
    ShaderCache& cache = a.cache ? *a.cache : own.emplace(a.cacheDir);
    CompileOptions options = a.options;
    options.cache = &cache;
    std::atomic<size_t> next = 0;
    std::atomic<bool> stop = false;
    std::mutex calls;  // one progress call at a time, `done` counted in the order they are made
    size_t done = 0;
    Progress progress(pending.size(), a.quiet || a.progress);
    auto worker = [&] {
        for (size_t i; !stop && (i = next++) < pending.size();) {
            progress.step("compiling " + pending[i]->material.name);
            pending[i]->result =
                a.engines.empty() ? compile(pending[i]->material, options) : compilePackages(pending[i]->material, a.engines, options);
            if (!a.progress) continue;
            std::lock_guard lock(calls);
            if (!stop && !a.progress(++done, pending.size(), pending[i]->material.name)) stop = true;
        }
    };
    const unsigned cores = a.jobs ? a.jobs : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> threads(std::min<size_t>(cores, pending.size()));
    // One compile at a time leaves the other cores to its targets; more already use them.
    options.concurrentTargets = threads.size() == 1 && cores > 1;
    for (auto& t : threads) t = std::thread(worker);
    for (auto& t : threads) t.join();
    stopped = stop;
    if (!a.cache && cache.stats().misses) cache.trim();  // only what was stored can take the folder past its bound
    return cache.stats();
}

// Compiles the jobs that are not up to date. False if any failed or the progress callback stopped the build.
bool compileJobs(const Arguments& a, std::vector<Job>& jobs, ShaderCache::Stats& stats, bool& stopped) {
    std::vector<Job*> pending;
    for (Job& j : jobs) {
        j.hash = inputHash(j.material, a.options, a.engines, j.extraInputs);
        j.upToDate = !a.force && upToDate(a.outDir, j.material.name, j.hash);
        if (!j.upToDate) pending.push_back(&j);
    }
    stats = compileInParallel(a, pending, stopped);
    if (stopped) return false;
    if (!stats.unwritable.empty() && a.warnings)
        *a.messages.text << "hexc: warning: the shader cache keeps nothing for later runs (" << stats.unwritable
                         << "); --cache-dir DIR names another folder, --no-cache turns it off\n";
    bool ok = true;
    for (Job* j : pending) ok &= printDiagnostics(j->result.diagnostics, a, j->passReadsFewer);
    return ok;
}

struct Outputs {
    std::vector<OutputFile> files;
    std::map<std::string, std::string> stamps;  // job name -> stamp text
    size_t deduplicated = 0;                    // scene variants whose shader code equals an earlier variant's
    std::map<std::string, std::string> shares;  // such a variant -> that earlier variant (for -v)
    std::vector<std::string> settled;           // outputs of up-to-date jobs: their times are refreshed (see below)
};

// A scene's index: each variant's manifest and shader hash. Variants with one hash have identical code, so an
// engine may build one pipeline for them; counted in `out` for the summary and -v.
void addSceneIndex(const Arguments& a, const SceneSummary& s, const std::vector<Job>& jobs, Outputs& out) {
    nlohmann::json index = {{"scene", s.scene.name}, {"variants", nlohmann::json::object()}};
    std::map<std::string, std::string> firstWith;             // shader hash -> the first variant with it
    std::unordered_map<std::string_view, const Job*> byName;  // not a search of every job per variant
    for (const Job& j : jobs) byName.emplace(j.material.name, &j);
    for (const std::string& v : s.variants) {
        const Job& j = *byName.at(v);
        const std::string hash = shaderHash(a.outDir, j, a.options);
        index["variants"][v] = {{"manifest", v + ".manifest.json"}, {"shader", hash}};
        if (auto [first, fresh] = firstWith.emplace(hash, v); !fresh) {
            ++out.deduplicated;
            out.shares[v] = first->second;
        }
    }
    out.files.push_back({s.scene.name + ".scene.json", index.dump(2) + "\n"});
}

Outputs collectOutputs(const Arguments& a, const Inputs& in) {
    Outputs out;
    for (const Job& j : in.jobs) {
        if (j.upToDate) {
            for (std::string& o : stampedOutputs(a.outDir, j.material.name)) out.settled.push_back(std::move(o));
            continue;
        }
        out.files.insert(out.files.end(), j.result.files.begin(), j.result.files.end());
        out.stamps[j.material.name] = stampText(j.hash, j.result.files);
    }
    for (const SceneSummary& s : in.scenes) addSceneIndex(a, s, in.jobs, out);
    return out;
}

// Every file the run writes, known from planning alone: each job's (outputNames) and the scene indexes, with what
// planning reported. They are what --list-outputs prints and the depfile's targets, so no depfile names an output a
// build system was not told of. Planned once a run: planning reads each job's template.
struct Planned {
    std::vector<std::filesystem::path> outputs;
    Diagnostics diagnostics;  // the compile reports them again; --list-outputs, which compiles nothing, prints them
};

Planned plannedOutputs(const Arguments& a, const Inputs& in) {
    Planned p;
    for (const SceneSummary& s : in.scenes) p.outputs.push_back(a.outDir / (s.scene.name + ".scene.json"));
    for (const Job& j : in.jobs) {
        OutputNames names = a.engines.empty() ? outputNames(j.material, a.options) : packageOutputNames(j.material, a.engines, a.options);
        p.diagnostics.insert(p.diagnostics.end(), names.diagnostics.begin(), names.diagnostics.end());
        for (const std::string& name : names.names) p.outputs.push_back(a.outDir / name);
    }
    return p;
}

// The files the jobs read, each once in the order first read (a scene's variants share their material's).
std::vector<std::filesystem::path> readFiles(const Arguments& a, const Inputs& in) {
    std::vector<std::filesystem::path> ins;
    std::unordered_set<std::string> seen;
    for (const Job& j : in.jobs) {
        std::vector<std::filesystem::path> files = inputFiles(j.material, a.options);
        files.insert(files.end(), j.extraInputs.begin(), j.extraInputs.end());
        for (auto& f : files)
            if (seen.insert(f.string()).second) ins.push_back(std::move(f));
    }
    return ins;
}

// Whether outputs named `name` (letters, digits, `_`, `-`) are Windows devices, whatever their extension: `con.frag.hlsl`
// cannot be created there.
bool reservedOnWindows(const std::string& name) {
    static const std::set<std::string> devices = {"con",  "prn",  "aux",  "nul",  "com1", "com2", "com3", "com4", "com5", "com6", "com7",
                                                  "com8", "com9", "lpt1", "lpt2", "lpt3", "lpt4", "lpt5", "lpt6", "lpt7", "lpt8", "lpt9"};
    return devices.contains(lowerCase(name));
}

// A file as the file system knows it, whatever path names it: links followed (as writing would), hard links alike.
using FileId = std::pair<dev_t, ino_t>;
std::optional<FileId> fileId(const std::filesystem::path& p) {
    struct stat s;
    if (::stat(p.c_str(), &s) != 0) return std::nullopt;
    return FileId{s.st_dev, s.st_ino};
}

// No file the run writes may be one it reads (writing it would destroy the build's own input: a template named like
// an output, a depfile pointed at the material); no two materials or scenes may name their outputs alike but for case
// (one file on macOS and Windows) or as a Windows device. Checked before anything is compiled or written, with one
// `stat` a distinct file: linear in the variants, which repeat their material's inputs.
bool outputsFit(const Arguments& a, const Inputs& in, const Planned& planned) {
    bool ok = true;
    auto refuse = [&](const std::string& why) {
        *a.messages.text << "hexc: error: " << why << "\n";
        ok = false;
    };
    std::map<FileId, std::filesystem::path> read;  // the first input path naming each file
    for (const std::filesystem::path& f : readFiles(a, in))
        if (std::optional<FileId> id = fileId(f)) read.try_emplace(*id, f);
    std::vector<std::filesystem::path> outs = planned.outputs;
    std::vector<std::string> names;
    for (const Job& j : in.jobs) {
        outs.push_back(a.outDir / stampName(j.material.name));
        names.push_back(j.material.name);
    }
    if (!a.depfile.empty()) outs.push_back(a.depfile);
    for (const std::filesystem::path& out : outs)
        if (std::optional<FileId> id = fileId(out); id && read.contains(*id))
            refuse("the output " + out.string() + " is the input " + read.at(*id).string() +
                   ": writing it would destroy it; choose another -o or --depfile");
    for (const SceneSummary& s : in.scenes) names.push_back(s.scene.name);
    std::map<std::string, std::string> folded;  // lower-cased name -> the name as written
    for (const std::string& name : names) {
        if (auto [it, added] = folded.try_emplace(lowerCase(name), name); !added && it->second != name)
            refuse("outputs named `" + it->second + "` and `" + name + "` differ only in case: one file on macOS and Windows");
        if (reservedOnWindows(name)) refuse("outputs named `" + name + "`: a device name on Windows, where they cannot be written");
    }
    return ok;
}

// --list-outputs: {"outputs": [...], "inputs": [...]}, the files a build would write and those the list is decided
// from (material and scene files, a user template, and a packing material's textures, whose pixels decide what packs:
// a build system lists again when one changes). Writes nothing.
int listOutputs(const Arguments& a, const Inputs& in, const Planned& planned) {
    nlohmann::json list = {{"outputs", nlohmann::json::array()}, {"inputs", nlohmann::json::array()}};
    for (const std::filesystem::path& f : planned.outputs) list["outputs"].push_back(f.generic_string());
    std::unordered_set<std::string> seen;
    for (const Job& j : in.jobs) {
        std::set<std::filesystem::path> textures;
        for (const Slot& s : j.material.slots) textures.insert(s.texturePath);
        std::vector<std::filesystem::path> files = inputFiles(j.material, a.options);
        files.insert(files.end(), j.extraInputs.begin(), j.extraInputs.end());
        for (const auto& f : files)
            if ((j.material.pack || !textures.contains(f)) && seen.insert(f.string()).second) list["inputs"].push_back(f.generic_string());
    }
    if (!printDiagnostics(planned.diagnostics, a)) return kInvalidInput;
    std::cout << list.dump(2) << "\n";
    return kOk;
}

// The output folder, created if missing; throws with the reason in a user's words when it cannot be.
void makeOutputFolder(const std::filesystem::path& dir) {
    std::error_code ec;
    if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
        throw std::runtime_error("cannot write to " + dir.string() + ": it is a file, not a folder");
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error("cannot create the output folder " + dir.string() + ": " + ec.message());
}

// Removes the temporaries of killed writers, writes every output, then the stamps (a crash before them leaves the
// jobs to be compiled again next time), removes what the replaced stamps listed and none lists now, then writes the
// depfile. Returns the bytes written; throws when something cannot be written.
size_t writeOutputs(const Arguments& a, const Outputs& out, const std::string& depfile) {
    size_t bytes = 0;
    makeOutputFolder(a.outDir);
    removeDeadTemporaries(a.outDir);
    std::set<std::string> before;  // what the stamps about to be replaced listed
    for (const auto& [name, text] : out.stamps)
        for (std::string& o : stampedOutputs(a.outDir, name)) before.insert(std::move(o));
    for (const OutputFile& f : out.files) {
        writeAtomically(a.outDir, f.name, f.contents);
        bytes += f.contents.size();
    }
    for (const auto& [name, text] : out.stamps) writeAtomically(a.outDir, stampName(name), text);
    removeStaleOutputs(a.outDir, before);
    // A build system ran hexc because an input looks newer than these outputs (a touched texture): with their
    // times refreshed, Make sees them up to date next time instead of running hexc on every build.
    std::error_code ec;
    for (const std::string& o : out.settled)  // plain names from trusted stamps; a symlink's target is not ours to touch
        if (std::filesystem::is_regular_file(std::filesystem::symlink_status(a.outDir / o, ec)))
            std::filesystem::last_write_time(a.outDir / o, std::filesystem::file_time_type::clock::now(), ec);
    if (!a.depfile.empty())
        writeAtomically(a.depfile.parent_path().empty() ? "." : a.depfile.parent_path(), a.depfile.filename().string(), depfile);
    return bytes;
}

// -v: each job's fate and why.
void printJobs(const Arguments& a, const Inputs& in, const Outputs& out) {
    for (const Job& j : in.jobs) {
        *a.messages.text << "hexc: " << j.material.name << ": ";
        if (j.upToDate) {
            *a.messages.text << "up to date (its inputs, options and hexc match the last build's stamp); not compiled\n";
            continue;
        }
        *a.messages.text << "compiled (no stamp from an earlier build matches its inputs, options and hexc)";
        if (auto s = out.shares.find(j.material.name); s != out.shares.end())
            *a.messages.text << "; its shader code is identical to " << s->second << "'s (one `shader` hash in the scene index)";
        *a.messages.text << "\n";
    }
}

void printSummary(const Arguments& a, const Inputs& in, const Outputs& out, size_t bytes) {
    if (a.verbose) printJobs(a, in, out);
    if (a.verbose && (in.cache.hits || in.cache.misses))
        *a.messages.text << "hexc: shader code: " << in.cache.misses << " compiled, " << in.cache.hits << " from the cache ("
                         << (a.cacheDir.empty() ? "this run only" : a.cacheDir.string()) << ")"
                         << (in.cache.corrupt ? ", " + std::to_string(in.cache.corrupt) + " damaged entries replaced" : "") << "\n";
    size_t upToDate = 0;
    for (const Job& j : in.jobs) upToDate += j.upToDate;
    for (const SceneSummary& s : in.scenes)
        *a.messages.text << "hexc: scene " << s.scene.name << ": " << s.scene.materials.size() * s.scene.passes.size()
                         << " variants possible, " << s.variants.size() << " used\n";
    *a.messages.text << "hexc: " << in.jobs.size() - upToDate << " compiled, " << upToDate << " up to date";
    if (!in.scenes.empty()) *a.messages.text << ", " << out.deduplicated << " scene variants share another's code";
    *a.messages.text << "; wrote " << out.files.size() << (out.files.size() == 1 ? " file (" : " files (") << bytes << " bytes) to "
                     << a.outDir.string() << "\n";
}

}  // namespace

int buildCommand(const Arguments& a) {
    try {  // before compiling anything
        if (std::error_code ec; std::filesystem::exists(a.outDir, ec)) makeOutputFolder(a.outDir);
    } catch (const std::exception& e) {
        *a.messages.text << "hexc: " << e.what() << "\nhexc: nothing written\n";
        return kWriteFailed;
    }
    Inputs in = readInputs(a);
    bool ok = inputsFit(a, in) && !in.failed;
    const Planned planned = ok ? plannedOutputs(a, in) : Planned{};
    ok = ok && outputsFit(a, in, planned);
    if (ok && a.listOutputs) return listOutputs(a, in, planned);
    if (!ok || !compileJobs(a, in.jobs, in.cache, in.stopped)) {
        *a.messages.text << (in.stopped ? "hexc: stopped by the progress callback; nothing written\n" : "hexc: nothing written\n");
        return in.stopped ? kStopped : kInvalidInput;
    }
    Outputs out = collectOutputs(a, in);
    std::string depfile;
    try {
        if (!a.depfile.empty()) depfile = depfileText(planned.outputs, readFiles(a, in));
    } catch (const std::invalid_argument& e) {
        *a.messages.text << "hexc: error: " << e.what() << "\nhexc: nothing written\n";
        return kInvalidInput;
    }
    size_t bytes = 0;
    try {
        bytes = writeOutputs(a, out, depfile);
    } catch (const std::exception& e) {
        *a.messages.text << "hexc: " << e.what() << "\n";
        return kWriteFailed;
    }
    if (!a.quiet) printSummary(a, in, out, bytes);
    return kOk;
}

}  // namespace hexc::cli
