// hexc-bench-compiler [RESULTS_DIR] [--benchmark_* flags]: how fast hexc compiles, stage by stage.
//
// Google Benchmark times each stage on materials/rock.json (parse, plan, codegen, glslang, spirv-opt, each
// target's emit, manifest), the whole compile to all four targets, and a batch of the three example materials
// twice: in process (hexc::compile) and as the chain of external tools a user would otherwise script
// (glslangValidator, spirv-opt, spirv-cross three times, on the GLSL hexc generates). Writes the figures and the
// ratio external / in-process to RESULTS_DIR (default build/bench-results): compiler.md, compiler.csv. Then the
// command line as a build runs it: one material cold against the external chain, a shader cache hit, 100 materials
// generated from the examples, and a rebuild with nothing to do; each against the targets of the compile-speed work.
// Run it from the source root (the materials' paths are relative). It reports, it does not judge: the exit
// code is 0 whatever the numbers.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "backends/backends.h"
#include "codegen/codegen.h"
#include "hexc/cache.h"
#include "hexc/compiler.h"
#include "hexc/material.h"
#include "plan/plan.h"
#include "machine.h"
#include "hexc/spirv.h"

namespace hexc::bench {
namespace {

namespace fs = std::filesystem;

const char* const kStageMaterial = "materials/rock.json";
const std::vector<std::string> kBatch = {"materials/rock.json", "materials/tiles.json", "materials/rock_normal.json"};
constexpr double kTargetSpeedup = 5.0;  // in process against the external chain

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

Material parsedOrExit(const std::string& file) {
    ParseResult parsed = parseMaterialFile(file);
    if (!parsed.material) {
        std::cerr << formatAll(parsed.diagnostics);
        std::exit(1);
    }
    return *parsed.material;
}

// Each stage's input for kStageMaterial, made once by running the stages before it. Not copyable: the plan points
// into the material.
struct Stages {
    std::string json = readFile(kStageMaterial);
    Material material = parsedOrExit(kStageMaterial);
    ShaderPlan plan = planShader(material, {});
    std::string glsl = generateGlsl(plan);
    std::vector<uint32_t> spirv =
        compileToSpirv(glsl, ShaderStage::Fragment, plan.templateName, SourceLanguage::Glsl, plan.entryPoint).words;
    std::vector<uint32_t> optimized = optimizeSpirv(spirv).words;
    CompileOptions options;
    nlohmann::json targets = {{"spirv", describeSpirv(optimized, plan).target},
                              {"hlsl", emitHlsl(optimized, plan, options).target},
                              {"glsl", emitGlsl(optimized, plan, options).target},
                              {"msl", emitMsl(optimized, plan, options).target}};
    Stages() {
        if (optimized.empty()) {
            std::cerr << kStageMaterial << " does not compile\n";
            std::exit(1);
        }
    }
    Stages(const Stages&) = delete;
};

const Stages& stages() {
    static const Stages s;
    return s;
}

void Parse(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(parseMaterial(stages().json, kStageMaterial));
}
void Plan(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(planShader(stages().material, {}));
}
void Codegen(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(generateGlsl(stages().plan));
}
void Glslang(benchmark::State& state) {
    for (auto _ : state)
        benchmark::DoNotOptimize(compileToSpirv(stages().glsl, ShaderStage::Fragment, stages().plan.templateName, SourceLanguage::Glsl,
                                                stages().plan.entryPoint));
}
void SpirvOpt(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(optimizeSpirv(stages().spirv));
}
void EmitSpirv(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(describeSpirv(stages().optimized, stages().plan));
}
void EmitHlsl(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(emitHlsl(stages().optimized, stages().plan, stages().options));
}
void EmitGlsl(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(emitGlsl(stages().optimized, stages().plan, stages().options));
}
void EmitMsl(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(emitMsl(stages().optimized, stages().plan, stages().options));
}
void Manifest(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(buildManifest(stages().material, stages().plan, stages().targets));
}
void CompileAllTargets(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(compile(stages().material));
}

// What `hexc A.json B.json C.json -o DIR` does, less writing the files: read, parse, compile to all four targets.
void BatchInProcess(benchmark::State& state) {
    for (auto _ : state)
        for (const std::string& file : kBatch) benchmark::DoNotOptimize(compile(parsedOrExit(file)));
    state.SetItemsProcessed(state.iterations() * int64_t(kBatch.size()));
}

// Compiles `materials` as a script would from hexc's generated GLSL, one process per tool. Parsing, planning and
// code generation are not counted: the script starts from the GLSL.
void externalChain(benchmark::State& state, const std::vector<std::string>& materials) {
    const fs::path dir = fs::temp_directory_path() / "hexc-bench-compiler";
    fs::create_directories(dir);
    std::vector<std::pair<fs::path, std::string>> sources;
    for (const std::string& file : materials) {
        const Material m = parsedOrExit(file);
        sources.emplace_back(dir / (m.name + ".frag"), compile(m).glsl);
    }
    for (auto _ : state) {
        for (const auto& [frag, glsl] : sources) {
            std::ofstream(frag, std::ios::binary) << glsl;
            const std::string stem = (dir / frag.stem()).string();
            const std::string chain = "glslangValidator -V --target-env vulkan1.0 -o " + stem + ".spv " + frag.string() + " >/dev/null" +
                                      " && spirv-opt -O " + stem + ".spv -o " + stem + ".opt.spv" + " && spirv-cross " + stem +
                                      ".opt.spv --hlsl --shader-model 50 --output " + stem + ".hlsl" + " && spirv-cross " + stem +
                                      ".opt.spv --version 450 --output " + stem + ".glsl" + " && spirv-cross " + stem +
                                      ".opt.spv --msl --output " + stem + ".metal";
            if (const int status = std::system(chain.c_str()); status != 0) {
                state.SkipWithError(("external chain failed with status " + std::to_string(status) + ": " + chain).c_str());
                break;
            }
        }
    }
    state.SetItemsProcessed(state.iterations() * int64_t(materials.size()));
    fs::remove_all(dir);
}
void BatchExternalTools(benchmark::State& state) { externalChain(state, kBatch); }
void ExternalChainOneMaterial(benchmark::State& state) { externalChain(state, {kStageMaterial}); }

// A compile whose code is in the cache: plan, codegen and the key's hash, then the entry point named and the manifest.
void CacheHitInProcess(benchmark::State& state) {
    ShaderCache cache;
    CompileOptions options;
    options.cache = &cache;
    compile(stages().material, options);
    for (auto _ : state) benchmark::DoNotOptimize(compile(stages().material, options));
}

// A material of `slots` colour slots (rock's albedo, one hex-tiling setting) and a template that adds them all up.
Material slotsMaterial(int slots) {
    const fs::path dir = fs::temp_directory_path() / "hexc-bench-slots";
    fs::create_directories(dir);
    std::string sum = "vec4(0.0)";
    nlohmann::json m = {{"name", "slots" + std::to_string(slots)},
                        {"template", "sum" + std::to_string(slots) + ".glsl"},
                        {"slots", nlohmann::json::array()}};
    for (int i = 0; i < slots; ++i) {
        m["slots"].push_back(
            {{"name", "s" + std::to_string(i)}, {"texture", fs::absolute("materials/textures/rock_albedo.png")}, {"kind", "color"}});
        sum += " + hexc_s" + std::to_string(i) + "(v_uv)";
    }
    std::ofstream(dir / ("sum" + std::to_string(slots) + ".glsl")) << "#version 450\n#include <hexc>\nlayout(location = 0) in vec2 v_uv;\n"
                                                                      "layout(location = 0) out vec4 o_color;\nvoid main() { o_color = "
                                                                   << sum << "; }\n";
    const fs::path file = dir / (m["name"].get<std::string>() + ".json");
    std::ofstream(file) << m.dump(2);
    return parsedOrExit(file.string());
}

// The whole compile of a material of N slots: the cost of a slot should not grow with the number of slots.
void SlotScaling(benchmark::State& state) {
    const Material m = slotsMaterial(int(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(compile(m));
}

// Runs `hexc <args>` (quiet); an error ends the benchmark.
void runHexc(benchmark::State& state, const std::string& args) {
    const std::string command = std::string(HEXC_EXE) + " -q " + args;
    if (const int status = std::system(command.c_str()); status != 0)
        state.SkipWithError(("hexc failed with status " + std::to_string(status) + ": " + command).c_str());
}

const fs::path kCliDir = fs::temp_directory_path() / "hexc-bench-cli";
constexpr size_t kGenerated = 100;

// kGenerated materials from the examples, in kCliDir with a copy of the textures: each its own name and tiling (a
// uniform), and one of six combinations of rotation (0, 0.5, 1) and falloff (0.5, 0.75), which change the code.
const std::string& generatedMaterials() {
    static const std::string files = [] {
        fs::create_directories(kCliDir / "gen");
        fs::copy("materials/textures", kCliDir / "gen" / "textures", fs::copy_options::recursive | fs::copy_options::overwrite_existing);
        std::string list;
        for (size_t i = 0; i < kGenerated; ++i) {
            nlohmann::json m = nlohmann::json::parse(readFile(kBatch[i % kBatch.size()]));
            m["name"] = "gen" + std::to_string(i);
            m["hextiling"]["tiling"] = 2 + i % 7;
            m["hextiling"]["rotation"] = double((i / 3) % 3) * 0.5;
            m["hextiling"]["falloff"] = (i / 9) % 2 ? 0.75 : 0.5;
            const fs::path file = kCliDir / "gen" / ("gen" + std::to_string(i) + ".json");
            std::ofstream(file) << m.dump(2);
            list += " " + file.string();
        }
        return list;
    }();
    return files;
}

void CliColdOneMaterial(benchmark::State& state) {
    for (auto _ : state) runHexc(state, std::string(kStageMaterial) + " --force --no-cache -o " + (kCliDir / "cold").string());
}
void CliCacheHitOneMaterial(benchmark::State& state) {
    const std::string args =
        std::string(kStageMaterial) + " --force --cache-dir " + (kCliDir / "cache").string() + " -o " + (kCliDir / "hit").string();
    runHexc(state, args);
    for (auto _ : state) runHexc(state, args);
}
// No cache folder: identical code within the batch is still compiled once.
void CliGeneratedBatch(benchmark::State& state) {
    for (auto _ : state) runHexc(state, generatedMaterials() + " --force --no-cache -o " + (kCliDir / "batch").string());
    state.SetItemsProcessed(state.iterations() * int64_t(kGenerated));
}
// Every stamp up to date: what a build system's no-op build costs.
void CliNoOpRebuild(benchmark::State& state) {
    const std::string args = generatedMaterials() + " -o " + (kCliDir / "noop").string();
    runHexc(state, args + " --no-cache");
    for (auto _ : state) runHexc(state, args);
    state.SetItemsProcessed(state.iterations() * int64_t(kGenerated));
}

BENCHMARK(Parse)->Unit(benchmark::kMicrosecond);
BENCHMARK(Plan)->Unit(benchmark::kMicrosecond);
BENCHMARK(Codegen)->Unit(benchmark::kMicrosecond);
BENCHMARK(Glslang)->Unit(benchmark::kMicrosecond);
BENCHMARK(SpirvOpt)->Unit(benchmark::kMicrosecond);
BENCHMARK(EmitSpirv)->Unit(benchmark::kMicrosecond);
BENCHMARK(EmitHlsl)->Unit(benchmark::kMicrosecond);
BENCHMARK(EmitGlsl)->Unit(benchmark::kMicrosecond);
BENCHMARK(EmitMsl)->Unit(benchmark::kMicrosecond);
BENCHMARK(Manifest)->Unit(benchmark::kMicrosecond);
BENCHMARK(CompileAllTargets)->Unit(benchmark::kMillisecond);
// Wall-clock time: the external chain's work happens in child processes, which the CPU timer does not see.
BENCHMARK(BatchInProcess)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);
BENCHMARK(BatchExternalTools)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);
BENCHMARK(CacheHitInProcess)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(ExternalChainOneMaterial)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);
BENCHMARK(CliColdOneMaterial)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);
BENCHMARK(CliCacheHitOneMaterial)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(0.5);
BENCHMARK(CliGeneratedBatch)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(SlotScaling)->Unit(benchmark::kMillisecond)->UseRealTime()->Arg(1)->Arg(2)->Arg(4)->Arg(8)->Arg(16);
BENCHMARK(CliNoOpRebuild)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(0.5);

// Prints as usual and keeps each benchmark's wall-clock time per iteration, in milliseconds, for the report.
class Recorder : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> ms;
    std::map<std::string, std::string> errors;
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& run : runs) {
            // Without the /min_time:... suffixes; with the argument, if any ("SlotScaling/4").
            const std::string name = run.run_name.function_name + (run.run_name.args.empty() ? "" : "/" + run.run_name.args);
            const double time = run.GetAdjustedRealTime() * 1000.0 / benchmark::GetTimeUnitMultiplier(run.time_unit);
            if (run.error_occurred) errors[name] = run.error_message;
            // With repetitions, the median over them (reported after the repetitions themselves) is kept.
            else if (run.run_type == Run::RT_Iteration || run.aggregate_name == "median")
                ms[name] = time;
            if (!run.error_occurred && run.run_type == Run::RT_Iteration) repetitions[name].push_back(time);
        }
        ConsoleReporter::ReportRuns(runs);
    }
    double get(const std::string& name) const { return ms.count(name) ? ms.at(name) : NAN; }
    // (max - min) / median of the repetitions: how far one run's figure could move on this machine now.
    double spread(const std::string& name) const {
        if (!repetitions.count(name) || repetitions.at(name).size() < 2) return NAN;
        const auto [low, high] = std::minmax_element(repetitions.at(name).begin(), repetitions.at(name).end());
        return (*high - *low) / get(name);
    }

private:
    std::map<std::string, std::vector<double>> repetitions;
};

std::string fixed(double v, int decimals) {
    if (std::isnan(v)) return "n/a";
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(decimals);
    out << v;
    return out.str();
}

// The compile-speed targets, each measured in this run, met or not.
void reportTargets(const Recorder& r, std::string& md) {
    struct Row {
        std::string what;
        double value, spread;
        std::string unit;
        double target;
        bool atLeast;
    };
    const double chain = r.get("ExternalChainOneMaterial"), cold = r.get("CliColdOneMaterial");
    const double first = r.get("SlotScaling/2") - r.get("SlotScaling/1"), last = (r.get("SlotScaling/16") - r.get("SlotScaling/8")) / 8;
    // A ratio's spread is at most the sum of its two figures' spreads.
    auto spread = [&r](std::initializer_list<const char*> names) {
        double sum = 0;
        for (const char* n : names) sum += r.spread(n);
        return sum;
    };
    const std::vector<Row> rows = {
        {"warm, in process: external chain / hexc, 3-material batch", r.get("BatchExternalTools") / r.get("BatchInProcess"),
         spread({"BatchExternalTools", "BatchInProcess"}), "x", kTargetSpeedup, true},
        {"warm, in process: one 3-slot material (rock), four targets", r.get("CompileAllTargets"), spread({"CompileAllTargets"}), "ms", 25,
         false},
        {"cold command line, one material: external chain / hexc", chain / cold, spread({"ExternalChainOneMaterial", "CliColdOneMaterial"}),
         "x", 1.5, true},
        {"shader cache hit, in process, per material", r.get("CacheHitInProcess"), spread({"CacheHitInProcess"}), "ms", 2, false},
        {std::to_string(kGenerated) + " generated materials, command line, no cache folder", r.get("CliGeneratedBatch"),
         spread({"CliGeneratedBatch"}), "ms", 2000, false},
        {"no-op rebuild, per material (" + std::to_string(kGenerated) + " up to date)", r.get("CliNoOpRebuild") / kGenerated,
         spread({"CliNoOpRebuild"}), "ms", 5, false},
        {"cost linear in slots: ms per added slot from 8 to 16 slots / from 1 to 2", last / first,
         spread({"SlotScaling/1", "SlotScaling/2", "SlotScaling/8", "SlotScaling/16"}), "", 1.25, false},
    };
    md += "\n| compile-speed target | measured | spread | target | |\n|---|---|---|---|---|\n";
    for (const Row& row : rows) {
        const bool met = row.atLeast ? row.value >= row.target : row.value <= row.target;
        md += "| " + row.what + " | " + fixed(row.value, 2) + " " + row.unit + " | " + fixed(row.spread * 100, 0) + "% | " +
              (row.atLeast ? ">= " : "<= ") + fixed(row.target, 2) + " " + row.unit + " | " +
              (std::isnan(row.value) ? "not measured"
               : met                 ? "MET"
                                     : "NOT MET") +
              " |\n";
    }
    md += "\nSpread: (max - min) / median over the repetitions; for a ratio, the sum of its two figures' spreads.\n";
    md += "\nWhole compile by number of colour slots (one lattice, a template adding them up):";
    for (int n : {1, 2, 4, 8, 16}) md += " " + std::to_string(n) + ": " + fixed(r.get("SlotScaling/" + std::to_string(n)), 1) + " ms;";
    md += "\n";
    md += "\nAlso measured: one material cold " + fixed(cold, 1) + " ms, its external chain " + fixed(chain, 1) +
          " ms; a cache hit through the command line (a process: start, hashing the executable for its build id, writing "
          "five files) " +
          fixed(r.get("CliCacheHitOneMaterial"), 1) + " ms.\n";
}

void report(const Recorder& r, const fs::path& dir, const std::string& machine) {
    const char* const stageNames[] = {"Parse",     "Plan",     "Codegen",  "Glslang", "SpirvOpt",
                                      "EmitSpirv", "EmitHlsl", "EmitGlsl", "EmitMsl", "Manifest"};
    std::string md = "Machine: " + machine +
                     ". Wall-clock time per call, Google Benchmark, median of 3 repetitions in random order.\n\n| stage "
                     "(materials/rock.json) | ms | share of the stages |\n|---|---|---|\n",
                csv = "benchmark,ms_per_iteration\n";
    double sum = 0;
    for (const char* name : stageNames) sum += r.get(name);
    for (const char* name : stageNames)
        md += "| " + std::string(name) + " | " + fixed(r.get(name), 3) + " | " + fixed(r.get(name) / sum * 100, 0) + "% |\n";
    md += "| sum of the stages | " + fixed(sum, 3) + " | |\n| whole compile, four targets (CompileAllTargets) | " +
          fixed(r.get("CompileAllTargets"), 3) + " | |\n";
    for (const auto& [name, ms] : r.ms) csv += name + "," + fixed(ms, 4) + "\n";

    const double inProcess = r.get("BatchInProcess"), external = r.get("BatchExternalTools");
    const std::string batch = std::to_string(kBatch.size()) + " example materials";
    md += "\n| batch of " + batch + " | ms per batch | materials/s |\n|---|---|---|\n";
    md += "| in process (read, parse, compile to four targets) | " + fixed(inProcess, 1) + " | " +
          fixed(kBatch.size() / inProcess * 1000, 1) + " |\n";
    md += "| external tools (glslangValidator, spirv-opt, spirv-cross x3 per material) | " + fixed(external, 1) + " | " +
          fixed(kBatch.size() / external * 1000, 1) + " |\n";
    reportTargets(r, md);
    for (const auto& [name, error] : r.errors) md += "- " + name + " failed: " + error + "\n";

    std::ofstream(dir / "compiler.md") << md;
    std::ofstream(dir / "compiler.csv") << csv;
    std::cout << "\n" << md << "\nWrote " << (dir / "compiler.md").string() << ", compiler.csv\n";
}

}  // namespace
}  // namespace hexc::bench

int main(int argc, char** argv) {
    // Defaults that the user's own --benchmark_* flags override (the last one given wins): three repetitions in
    // random order, so that load from elsewhere on the machine spreads over all benchmarks; reported: the median,
    // and how far the repetitions are apart.
    std::string defaults[] = {"--benchmark_repetitions=3", "--benchmark_enable_random_interleaving=true"};
    std::vector<char*> args{argv[0]};
    for (std::string& flag : defaults) args.push_back(flag.data());
    args.insert(args.end(), argv + 1, argv + argc);
    int count = int(args.size());
    benchmark::Initialize(&count, args.data());  // takes the --benchmark_* flags out of args
    const std::filesystem::path dir = count > 1 ? args[1] : "build/bench-results";
    std::filesystem::create_directories(dir);
    hexc::bench::stages();  // compile the stages' inputs before anything is timed
    const std::string machine = hexc::bench::cpuSummary();
    hexc::bench::Recorder recorder;
    benchmark::RunSpecifiedBenchmarks(&recorder);
    hexc::bench::report(recorder, dir, machine + ", " + hexc::bench::loadAverage() + " at the end");
    benchmark::Shutdown();
    return 0;
}
