// The shader code cache (hexc/cache.h): hits give the bytes a compile gives, entries that are damaged or from
// another hexc build are not used, and several threads or processes can share one folder.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "backends/backends.h"
#include "codegen/codegen.h"
#include "hexc/cache.h"
#include "hexc/compiler.h"
#include "hexc/files.h"
#include "hexc/hash.h"
#include "hexc/spirv.h"
#include "plan/plan.h"
#include "support.h"

using namespace hexc;
using hexc::test::outputFile;
using hexc::test::runHexc;

namespace {

namespace fs = std::filesystem;

// rock.json, renamed and with another tiling (a uniform): the same shader code but for the entry point's name.
Material material(const std::string& name, int tiling = 4) {
    std::string text = readFile("materials/rock.json").value();
    text.replace(text.find("\"rock\""), 6, "\"" + name + "\"");
    text.replace(text.find("[4, 4]"), 6, "[" + std::to_string(tiling) + ", " + std::to_string(tiling) + "]");
    ParseResult parsed = parseMaterial(text, "materials/" + name + ".json");
    EXPECT_TRUE(parsed.material) << (parsed.diagnostics.empty() ? "" : parsed.diagnostics[0].format());
    return *parsed.material;
}

fs::path freshFolder(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / name;
    fs::remove_all(dir);
    return dir;
}

CompileResult compileWith(const Material& m, ShaderCache* cache, CompileOptions options = {}) {
    options.cache = cache;
    CompileResult r = compile(m, options);
    EXPECT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].format());
    return r;
}

void expectSameFiles(const CompileResult& a, const CompileResult& b) {
    ASSERT_EQ(a.files.size(), b.files.size());
    for (size_t i = 0; i < a.files.size(); ++i) {
        EXPECT_EQ(a.files[i].name, b.files[i].name);
        EXPECT_TRUE(a.files[i].contents == b.files[i].contents) << a.files[i].name << " differs";
    }
    EXPECT_EQ(a.spirv, b.spirv);
}

// The folder's entry files (not temporaries).
std::vector<fs::path> entries(const fs::path& dir) {
    std::vector<fs::path> out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) out.push_back(e.path());
    return out;
}

}  // namespace

// Code is compiled with a stand-in entry point and named afterwards, so that materials share it: the result must be
// what compiling with the name gives, MSL's renaming of reserved names (`main` -> `main0`) and debug info included.
TEST(ShaderCache, NamingTheEntryPointAfterwardsGivesWhatCompilingWithItGives) {
    struct Case {
        const char* material;
        std::string entry;
        bool debug, argumentBuffers;
    };
    // engine_rock's template brings its own blocks, textures and push constants.
    const Case cases[] = {{"rock", "", false, false},           {"rock", "main", false, false},
                          {"rock", "abs", false, false},        {"rock", "terrainPS", true, false},
                          {"rock", "main", true, false},        {"engine_rock", "", false, true},
                          {"engine_rock", "main", false, true}, {"engine_rock", "terrainPS", true, false}};
    for (const Case& c : cases) {
        SCOPED_TRACE(std::string(c.material) + " " + c.entry + (c.debug ? " debug" : "") + (c.argumentBuffers ? " argument buffers" : ""));
        const Material m = *parseMaterialFile("materials/" + std::string(c.material) + ".json").material;
        CompileOptions options;
        options.entryPoint = c.entry;
        options.debug = c.debug;
        // Every OpLine to the text targets, as emitting them straight from the module below does.
        options.lineDirectives = LineDirectives::Statements;
        options.layout.msl.argumentBuffers = c.argumentBuffers;
        const CompileResult r = compileWith(m, nullptr, options);
        const ShaderPlan plan = planShader(m, options);
        SpirvResult front = compileToSpirv(generateGlsl(plan), ShaderStage::Fragment, plan.templateName, SourceLanguage::Glsl,
                                           plan.entryPoint, {}, c.debug ? plan.templateShown : "");
        SpirvResult direct = optimizeSpirv(front.words, false, false, !c.debug);
        EXPECT_EQ(direct.words, r.spirv);
        EXPECT_EQ(spirvWords(outputFile(r, ".frag.spv").contents), direct.words);
        EXPECT_EQ(emitMsl(direct.words, plan, options).source, withoutBanner(outputFile(r, ".frag.metal").contents));
        EXPECT_EQ(emitHlsl(direct.words, plan, options).source, withoutBanner(outputFile(r, ".frag.hlsl").contents));
        EXPECT_EQ(emitGlsl(direct.words, plan, options).source, withoutBanner(outputFile(r, ".frag.glsl").contents));
    }
    EXPECT_EQ(mslEntryName("main"), "main0");
    EXPECT_EQ(mslEntryName("rock_frag"), "rock_frag");
}

// Another material with the same code (another name, another tiling: a uniform) is a hit, and its outputs are the
// bytes compiling it alone gives: its own entry point, manifest and banner.
TEST(ShaderCache, MaterialsWithTheSameCodeAreCompiledOnce) {
    {
        ShaderCache cache;
        CompileOptions options;
        const Material rock = material("rock"), stone = material("stone", 6);
        compileWith(rock, &cache, options);
        const CompileResult hit = compileWith(stone, &cache, options);
        EXPECT_EQ(cache.stats().misses, 1u);
        EXPECT_EQ(cache.stats().hits, 1u);
        expectSameFiles(hit, compileWith(stone, nullptr));
        EXPECT_NE(outputFile(hit, ".frag.metal").contents.find("fragment stone_frag_out stone_frag("), std::string::npos);
        // Other options are other code: a miss.
        options.hlslShaderModel = 60;
        compileWith(stone, &cache, options);
        EXPECT_EQ(cache.stats().misses, 2u);
    }
}

TEST(ShaderCache, AFolderServesLaterRunsAndDamagedEntriesAreCompiledAgain) {
    const fs::path dir = freshFolder("hexc_cache_folder");
    const Material rock = material("rock");
    const CompileResult fresh = compileWith(rock, nullptr);
    {
        ShaderCache first(dir);
        expectSameFiles(compileWith(rock, &first), fresh);
        EXPECT_EQ(first.stats().misses, 1u);
    }
    ASSERT_EQ(entries(dir).size(), 1u);
    const fs::path entry = entries(dir)[0];
    const std::string good = readFile(entry).value();
    {
        ShaderCache later(dir);
        expectSameFiles(compileWith(rock, &later), fresh);
        EXPECT_EQ(later.stats().hits, 1u);
        EXPECT_EQ(later.stats().misses, 0u);
    }
    // Cut short, one bit flipped in the payload, another file's bytes: each found out, compiled again, replaced.
    std::string flipped = good;
    flipped[flipped.size() - 100] ^= 1;
    for (const std::string& damaged : {good.substr(0, good.size() / 2), flipped, std::string("not an entry")}) {
        std::ofstream(entry, std::ios::binary | std::ios::trunc) << damaged;
        ShaderCache again(dir);
        expectSameFiles(compileWith(rock, &again), fresh);
        EXPECT_EQ(again.stats().corrupt, 1u);
        EXPECT_EQ(again.stats().misses, 1u);
        EXPECT_TRUE(readFile(entry).value() == good);
    }
}

// An entry whose checksum holds but whose payload does not decode as its reader needs (here: shader code whose SPIR-V
// is zeros, written with its checksum as another build of hexc, or a person, could) is removed, compiled again and
// replaced, not used or failed on by every later build.
TEST(ShaderCache, AnEntryWithAGoodChecksumButBadContentsIsReplaced) {
    const fs::path dir = freshFolder("hexc_cache_bad_contents");
    const Material rock = material("rock");
    const CompileResult fresh = compileWith(rock, nullptr);
    {
        ShaderCache first(dir);
        compileWith(rock, &first);
    }
    ASSERT_EQ(entries(dir).size(), 1u);
    const fs::path entry = entries(dir)[0];
    const std::string good = readFile(entry).value(), key = entry.filename().string();
    const size_t payloadAt = good.find('\n', good.find('\n', good.find('\n') + 1) + 1) + 1;  // after header, key, checksum
    nlohmann::json code = nlohmann::json::from_cbor(good.substr(payloadAt));
    code["spirv"] = nlohmann::json::binary(std::vector<uint8_t>(code["spirv"].get_binary().size(), 0));
    const std::vector<uint8_t> cbor = nlohmann::json::to_cbor(code);
    const std::string payload(cbor.begin(), cbor.end());
    ContentHash sum;
    sum.add(payload);
    std::ofstream(entry, std::ios::binary | std::ios::trunc) << good.substr(0, payloadAt - 33) << sum.hex() << "\n" << payload;
    for (int run = 0; run < 2; ++run) {  // the second run finds the entry the first replaced it with
        ShaderCache again(dir);
        expectSameFiles(compileWith(rock, &again), fresh);
        EXPECT_EQ(again.stats().corrupt, run == 0 ? 1u : 0u) << "run " << run;
        EXPECT_EQ(again.stats().hits, run == 0 ? 0u : 1u) << "run " << run;
        EXPECT_TRUE(readFile(entry).value() == good) << "run " << run;
    }
    EXPECT_EQ(key, entries(dir)[0].filename().string());
}

TEST(ShaderCache, ConcurrentWritersShareOneFolder) {
    const fs::path dir = freshFolder("hexc_cache_concurrent");
    const Material rock = material("rock");
    const CompileResult fresh = compileWith(rock, nullptr);
    std::vector<CompileResult> results(6);
    std::vector<std::thread> threads;
    for (CompileResult& r : results)
        threads.emplace_back([&] {
            ShaderCache own(dir);  // each as a process of its own would: no memory shared
            r = compileWith(rock, &own);
        });
    for (auto& t : threads) t.join();
    for (const CompileResult& r : results) expectSameFiles(r, fresh);
    EXPECT_EQ(entries(dir).size(), 1u);  // one entry, no temporaries left
    ShaderCache after(dir);
    compileWith(rock, &after);
    EXPECT_EQ(after.stats().hits, 1u);

    // Processes: four hexc at once on one cache folder give the same outputs.
    const fs::path out = freshFolder("hexc_cache_processes");
    std::string script;
    for (int i = 0; i < 4; ++i)
        script += std::string(HEXC_EXE) + " materials/scenes/forest.json -q --cache-dir " + (out / "cache").string() + " -o " +
                  (out / std::to_string(i)).string() + " & ";
    ASSERT_EQ(std::system(("(" + script + "wait) 2>&1").c_str()), 0);
    for (int i = 1; i < 4; ++i)
        for (const auto& e : fs::directory_iterator(out / "0"))
            EXPECT_TRUE(readFile(e.path()) == readFile(out / std::to_string(i) / e.path().filename()))
                << e.path().filename() << " of " << i;
}

// Threads asking for a key another thread is computing wait for it; a failed computation stores nothing.
TEST(ShaderCache, AKeyIsComputedOnceAndFailuresAreNotKept) {
    ShaderCache cache;
    std::atomic<int> computed = 0;
    std::vector<std::thread> threads;
    std::vector<std::optional<std::string>> got(4);
    for (auto& g : got)
        threads.emplace_back([&] {
            g = cache.getOrCompute("key", [&] {
                ++computed;
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
                return std::optional<std::string>("value");
            });
        });
    for (auto& t : threads) t.join();
    EXPECT_EQ(computed, 1);
    for (const auto& g : got) EXPECT_EQ(g, "value");
    int failed = 0;
    for (int i = 0; i < 2; ++i) EXPECT_FALSE(cache.getOrCompute("bad", [&] { return ++failed, std::optional<std::string>(); }));
    EXPECT_EQ(failed, 2);
}

// What a cache keeps in memory stays within its bound (a long `hexc edit` session asks for many large entries): the
// oldest are dropped and computed again when asked for, the newest is kept even when larger than the bound alone.
TEST(ShaderCache, MemoryStaysWithinTheBound) {
    ShaderCache cache({}, 2500);
    int computed = 0;
    auto get = [&](const std::string& key, size_t size) {
        return cache.getOrCompute(key, [&] { return ++computed, std::optional<std::string>(std::string(size, 'x')); });
    };
    for (int i = 0; i < 10; ++i) get("k" + std::to_string(i), 1000);  // 10,000 bytes asked for
    EXPECT_EQ(computed, 10);
    get("k9", 1000), get("k8", 1000);  // the two newest are kept
    EXPECT_EQ(computed, 10);
    get("k0", 1000);  // long dropped: computed again
    EXPECT_EQ(computed, 11);
    get("big", 10000), get("big", 10000);
    EXPECT_EQ(computed, 12);
}

// The folder keeps its most recently used entries within the bound.
TEST(ShaderCache, TrimRemovesTheLeastRecentlyUsed) {
    const fs::path dir = freshFolder("hexc_cache_trim");
    const std::string value(1000, 'x');
    {
        ShaderCache cache(dir);
        for (const char* key : {"aa01", "bb02", "cc03"}) cache.getOrCompute(key, [&] { return std::optional<std::string>(value); });
    }
    const auto now = fs::file_time_type::clock::now();
    fs::last_write_time(dir / "aa" / "aa01", now - std::chrono::hours(1));
    fs::last_write_time(dir / "bb" / "bb02", now - std::chrono::hours(3));
    fs::last_write_time(dir / "cc" / "cc03", now - std::chrono::hours(2));
    const uint64_t each = fs::file_size(dir / "aa" / "aa01");
    ShaderCache bounded(dir, 2 * each);
    bounded.getOrCompute("aa01", [] { return std::optional<std::string>("unused"); });  // a hit: aa01 is now the newest
    bounded.trim();
    EXPECT_TRUE(fs::exists(dir / "aa" / "aa01"));
    EXPECT_FALSE(fs::exists(dir / "bb" / "bb02"));
    EXPECT_TRUE(fs::exists(dir / "cc" / "cc03"));
    ShaderCache(dir, 0).trim();
    EXPECT_TRUE(entries(dir).empty());
}

// Through the command line: a uniform-only edit recompiles the material (its manifest changes) from the cache; a
// rebuilt hexc (another executable, the same version) does not trust the entries of the old one.
TEST(ShaderCache, CommandLineHitsAndAnotherBuildMisses) {
    const fs::path dir = freshFolder("hexc_cache_cli");
    fs::create_directories(dir);
    fs::copy("materials/textures", dir / "textures", fs::copy_options::recursive);
    const std::string rock = readFile("materials/rock.json").value();
    std::ofstream(dir / "rock.json") << rock;
    const std::string args = (dir / "rock.json").string() + " -v --cache-dir " + (dir / "cache").string() + " -o " + (dir / "out").string();
    std::string err;
    ASSERT_EQ(runHexc(args, &err), 0) << err;
    EXPECT_NE(err.find("shader code: 1 compiled, 0 from the cache"), std::string::npos) << err;
    std::string edited = rock;
    edited.replace(edited.find("[4, 4]"), 6, "[7, 7]");
    std::ofstream(dir / "rock.json") << edited;
    ASSERT_EQ(runHexc(args, &err), 0) << err;
    EXPECT_NE(err.find("rock: compiled"), std::string::npos) << err;
    EXPECT_NE(err.find("shader code: 0 compiled, 1 from the cache"), std::string::npos) << err;
    EXPECT_NE(readFile(dir / "out" / "rock.manifest.json").value().find("7.0"), std::string::npos);

    const fs::path other = dir / "hexc-other";
    hexc::test::copyAsAnotherBuild(other);
    const fs::path log = dir / "other.txt";
    const int status = std::system((other.string() + " " + args + " --force 2> " + log.string()).c_str());
    err = readFile(log).value_or("");
    ASSERT_EQ(WEXITSTATUS(status), 0) << err;
    EXPECT_NE(err.find("shader code: 1 compiled, 0 from the cache"), std::string::npos) << err;

    // A cache folder that cannot be written costs speed, not the build: a warning, and the outputs.
    std::ofstream(dir / "a-file") << "not a folder";
    fs::remove_all(dir / "out");
    ASSERT_EQ(runHexc((dir / "rock.json").string() + " --cache-dir " + (dir / "a-file").string() + " -o " + (dir / "out").string(), &err),
              0)
        << err;
    EXPECT_NE(err.find("warning: the shader cache keeps nothing for later runs (cannot create " + (dir / "a-file").string()),
              std::string::npos)
        << err;
    EXPECT_TRUE(fs::exists(dir / "out" / "rock.frag.spv"));

    // --no-cache: no folder; the summary says so.
    ASSERT_EQ(runHexc((dir / "rock.json").string() + " -v --force --no-cache -o " + (dir / "out").string(), &err), 0) << err;
    EXPECT_NE(err.find("1 compiled, 0 from the cache (this run only)"), std::string::npos) << err;
}

// naga writes the wgsl target's code, so another naga-wasm (its package.json's version) is another cache entry and
// another stamp: the entry of the old one is not used, the outputs are not up to date, and the banner names it.
// Through the command line with tests/node's naga-wasm, under a package.json whose version the test changes.
TEST(ShaderCache, AnotherNagaVersionMisses) {
    REQUIRE_NAGA_BY(true);
    const fs::path dir = freshFolder("hexc_cache_naga");
    const fs::path modules = fs::absolute("tests/node/node_modules");
    fs::create_directories(dir / "node_modules" / "naga-wasm");
    fs::create_directory_symlink(modules / "naga-wasm" / "dist", dir / "node_modules" / "naga-wasm" / "dist");
    auto setVersion = [&](const std::string& v) {
        nlohmann::json package = nlohmann::json::parse(readFile(modules / "naga-wasm" / "package.json").value());
        package["version"] = v;
        std::ofstream(dir / "node_modules" / "naga-wasm" / "package.json") << package.dump();
    };
    const std::string args =
        "materials/rock.json -v --targets wgsl --cache-dir " + (dir / "cache").string() + " -o " + (dir / "out").string();
    const std::string env = "HEXC_NAGA=node HEXC_NODE_PATH=" + (dir / "node_modules").string();  // Node's package
    std::string err;
    setVersion("30.1.0");
    ASSERT_EQ(runHexc(args, &err, env), 0) << err;
    EXPECT_NE(err.find("shader code: 1 compiled, 0 from the cache"), std::string::npos) << err;
    ASSERT_EQ(runHexc(args + " --force", &err, env), 0) << err;
    EXPECT_NE(err.find("shader code: 0 compiled, 1 from the cache"), std::string::npos) << err;
    EXPECT_NE(readFile(dir / "out" / "rock.frag.wgsl").value().find("// Settings: naga-wasm 30.1.0; optimised;"), std::string::npos);

    setVersion("30.1.1");
    ASSERT_EQ(runHexc(args, &err, env), 0) << err;
    EXPECT_NE(err.find("rock: compiled"), std::string::npos) << err;  // not up to date by the stamp
    EXPECT_NE(err.find("shader code: 1 compiled, 0 from the cache"), std::string::npos) << err;
    EXPECT_NE(readFile(dir / "out" / "rock.frag.wgsl").value().find("// Settings: naga-wasm 30.1.1; optimised;"), std::string::npos);
    // Only the wgsl target's key takes naga's: the other targets' entries stay.
    EXPECT_EQ(codeOptionsKey(CompileOptions()).find("naga"), std::string::npos);
}
