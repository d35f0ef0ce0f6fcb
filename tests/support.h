#pragma once
// What several test files share: the one Vulkan runner per test binary, the skip-or-fail rule without a
// device, and running the hexc command line as a user would.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "hexc/compiler.h"
#include "hexc/material.h"
#include "vk/runner.h"

namespace hexc::test {

// Created once per binary (creating a Vulkan device is slow); nullptr with the reason when there is none.
inline vk::Runner* runner(std::string* why) {
    static std::string reason;
    static std::unique_ptr<vk::Runner> r = vk::Runner::create(&reason);
    *why = reason;
    return r.get();
}

// A material file the test relies on, parsed; an exception with its diagnostics when it does not parse.
inline Material loadMaterial(const std::filesystem::path& file) {
    ParseResult r = parseMaterialFile(file);
    if (!r.material) throw std::runtime_error(file.string() + "\n" + formatAll(r.diagnostics));
    return *r.material;
}

// The example terrain (materials/terrain/), parsed.
inline Material exampleTerrain() { return loadMaterial("materials/terrain/terrain.json"); }

// The compile's output whose name ends in `suffix`; an exception naming the suffix when there is none.
inline const OutputFile& outputFile(const CompileResult& r, const std::string& suffix) {
    for (const OutputFile& f : r.files)
        if (f.name.ends_with(suffix)) return f;
    throw std::runtime_error("no output ending in " + suffix);
}

// A file's bytes ("" when it cannot be read).
inline std::string readFile(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// The running test's name as a file name: a parameterised test's name has a `/`.
inline std::string testLogName() {
    std::string name = testing::UnitTest::GetInstance()->current_test_info()->name();
    std::replace(name.begin(), name.end(), '/', '_');
    return name;
}

// A copy of the hexc executable at `to` that is another build to hexc (buildId): its linker build id (the
// NT_GNU_BUILD_ID note, "GNU" after its name size 4 and type 3) changed, or a byte appended when it has none.
inline void copyAsAnotherBuild(const std::filesystem::path& to) {
    std::string bytes = readFile(HEXC_EXE);
    const std::string header("\x04\0\0\0", 4), type("\x03\0\0\0GNU\0", 8);
    size_t at = bytes.find(type);
    while (at != std::string::npos && (at < 8 || bytes.compare(at - 8, 4, header) != 0)) at = bytes.find(type, at + 1);
    if (at == std::string::npos)
        bytes += '\0';
    else
        bytes[at + type.size()] ^= 1;  // the first byte of the id
    std::ofstream(to, std::ios::binary) << bytes;
    std::filesystem::permissions(to, std::filesystem::perms::owner_all);
}

// Runs the hexc executable with `args`; returns its exit code and, if asked, what it wrote to stderr.
// The log is named after the running test, so tests may run in parallel. `prefix`: shell commands run first
// (e.g. `ulimit -v N;`) or a wrapper command (e.g. `timeout 20`).
inline int runHexc(const std::string& args, std::string* err = nullptr, const std::string& prefix = "") {
    std::filesystem::path log = std::filesystem::temp_directory_path() / ("hexc_stderr_" + testLogName() + ".txt");
    int status = std::system((prefix + " " + HEXC_EXE + " " + args + " 2> " + log.string() + " > /dev/null").c_str());
    if (err) {
        std::ifstream in(log);
        err->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    return WEXITSTATUS(status);
}

// Runs hexc and returns what it printed on stdout.
inline std::string runHexcStdout(const std::string& args) {
    std::filesystem::path log = std::filesystem::temp_directory_path() / ("hexc_stdout_" + testLogName() + ".txt");
    std::system((std::string(HEXC_EXE) + " " + args + " > " + log.string() + " 2>/dev/null").c_str());
    std::ifstream in(log);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The wgsl target's translator for runHexc, as its `prefix`: naga built into hexc (a build with HEXC_NAGA_IN_PROCESS)
// needs nothing, unless `node` asks for Node's (HEXC_NAGA=node), which needs Node.js and tests/node's npm packages
// (`npm ci --prefix tests/node`, which .ci/test runs): HEXC_NODE_PATH at them; "" with the reason in `why` when they or
// Node.js are missing.
inline std::string nagaPrefix(std::string* why, bool node) {
    const std::filesystem::path modules = std::filesystem::absolute("tests/node/node_modules");
#ifdef HEXC_NAGA_BUILT_IN
    constexpr bool builtIn = true;
#else
    constexpr bool builtIn = false;
#endif
    if (builtIn && !node) return "HEXC_NODE_PATH=" + modules.string();  // set, but not read
    if (std::system("node --version > /dev/null 2>&1") != 0) return *why = "no Node.js (`node`) on PATH", "";
    if (!std::filesystem::exists(modules / "naga-wasm" / "package.json"))
        return *why = "no naga-wasm in " + modules.string() + " (npm ci --prefix tests/node)", "";
    return "HEXC_NAGA=node HEXC_NODE_PATH=" + modules.string();
}

}  // namespace hexc::test

// Without a Vulkan device a test skips with the reason, unless HEXC_REQUIRE_VULKAN is set (CI), where it fails.
#define REQUIRE_VULKAN()                                                                       \
    std::string whyNoVulkan;                                                                   \
    if (!hexc::test::runner(&whyNoVulkan)) {                                                   \
        if (std::getenv("HEXC_REQUIRE_VULKAN")) FAIL() << "no Vulkan device: " << whyNoVulkan; \
        GTEST_SKIP() << "no Vulkan device: " << whyNoVulkan;                                   \
    }

// Declares `naga`, the runHexc prefix for the wgsl target by the route hexc takes (REQUIRE_NAGA) or by Node.js
// (REQUIRE_NAGA_BY(true)); without what it needs a test skips, unless HEXC_REQUIRE_BROWSER=1 (.ci/test, as for the
// other npm-backed tests), where it fails.
#define REQUIRE_NAGA() REQUIRE_NAGA_BY(false)
#define REQUIRE_NAGA_BY(node)                                                                           \
    std::string whyNoNaga;                                                                              \
    const std::string naga = hexc::test::nagaPrefix(&whyNoNaga, node);                                  \
    if (naga.empty()) {                                                                                 \
        if (std::getenv("HEXC_REQUIRE_BROWSER")) FAIL() << "the wgsl target cannot run: " << whyNoNaga; \
        GTEST_SKIP() << "the wgsl target cannot run: " << whyNoNaga;                                    \
    }
