// Golden outputs, one folder per feature: tests/golden/<name>/args holds the arguments hexc is run with (from the
// source root), every other file there is what hexc writes with them. A change to codegen, the library or a backend
// shows up as a readable diff: SPIR-V is kept as its disassembly (<file>.spvasm) and a texture hexc derives as its
// size and digest (<file>.digest). HEXC_UPDATE_GOLDEN=1 rewrites the folders instead (tests/update_golden.sh).
// A folder whose args name the wgsl target needs tests/node's npm packages (support.h, REQUIRE_NAGA).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "hexc/spirv.h"
#include "support.h"

namespace fs = std::filesystem;
using hexc::test::readFile;
using hexc::test::runHexc;

namespace {

const fs::path kGolden = "tests/golden";

// Every folder of tests/golden with an args file, by name.
std::vector<std::string> goldenNames() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(kGolden))
        if (fs::exists(entry.path() / "args")) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// A texture hexc derives (packed, histogram tables) as text: its size and 64-bit FNV-1a digest.
std::string digest(const std::string& bytes) {
    uint64_t h = 0xcbf29ce484222325u;
    for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3u;
    char text[64];
    std::snprintf(text, sizeof text, "%zu bytes, fnv1a64 %016llx\n", bytes.size(), static_cast<unsigned long long>(h));
    return text;
}

// What hexc wrote to `dir` as golden files: name -> text. The incremental-build stamp (a hidden file) is not an output.
std::map<std::string, std::string> goldenFiles(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string(), ext = entry.path().extension().string();
        if (name.starts_with(".")) continue;
        const std::string bytes = readFile(entry.path());
        if (ext == ".spv")
            files[name + "asm"] = hexc::disassemble(hexc::spirvWords(bytes));
        else if (ext == ".png" || ext == ".pfm" || ext == ".ktx2" || ext == ".dds" || ext == ".exr")
            files[name + ".digest"] = digest(bytes);
        else
            files[name] = bytes;
    }
    return files;
}

// `diff -u` of the golden file against what hexc wrote now, at most 60 lines.
std::string unifiedDiff(const fs::path& golden, const std::string& now) {
    const fs::path actual = fs::temp_directory_path() / ("hexc_golden_now_" + golden.filename().string());
    std::ofstream(actual, std::ios::binary) << now;
    const std::string command = "diff -u " + golden.string() + " " + actual.string() + " | head -n 60";
    std::string out;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[4096];
        for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
        pclose(pipe);
    }
    return out;
}

class Golden : public testing::TestWithParam<std::string> {};

TEST_P(Golden, OutputsMatch) {
    const fs::path folder = kGolden / GetParam();
    std::string args = readFile(folder / "args");
    args.erase(args.find_last_not_of("\n") + 1);
    const fs::path out = fs::temp_directory_path() / ("hexc_golden_" + GetParam());
    fs::remove_all(out);
    std::string prefix;  // the wgsl target's goldens run with tests/node's naga-wasm
    if (args.find("wgsl") != std::string::npos) {
        REQUIRE_NAGA();
        prefix = naga;
    }
    std::string err;
    ASSERT_EQ(runHexc(args + " -q --no-cache -o " + out.string(), &err, prefix), 0) << args << "\n" << err;
    const std::map<std::string, std::string> now = goldenFiles(out);
    if (std::getenv("HEXC_UPDATE_GOLDEN")) {
        for (const auto& entry : fs::directory_iterator(folder))
            if (entry.path().filename() != "args") fs::remove(entry.path());
        for (const auto& [name, text] : now) std::ofstream(folder / name, std::ios::binary) << text;
        return;
    }
    std::vector<std::string> expected;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().filename() != "args") expected.push_back(entry.path().filename().string());
    std::sort(expected.begin(), expected.end());
    std::vector<std::string> written;
    for (const auto& [name, text] : now) written.push_back(name);
    EXPECT_EQ(written, expected) << "hexc " << args << " writes other files than " << folder << " holds (tests/update_golden.sh)";
    for (const auto& [name, text] : now)
        if (fs::exists(folder / name) && readFile(folder / name) != text)
            ADD_FAILURE() << (folder / name).string() << " differs (if intended, run tests/update_golden.sh and review):\n"
                          << unifiedDiff(folder / name, text);
}

INSTANTIATE_TEST_SUITE_P(Features, Golden, testing::ValuesIn(goldenNames()), [](const auto& info) { return info.param; });

}  // namespace
