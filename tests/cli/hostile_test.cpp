// Hostile inputs: each case runs the hexc command line under a time and address-space bound and asserts the
// exit code, the located message where one applies, and that nothing was written.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "support.h"

namespace fs = std::filesystem;

namespace {

// Generous bounds for a 2-core machine running the suite in parallel; a case that needs more is a bug. The
// address-space bound includes the binary's own mappings (about 300 MiB with glslang and the C++ runtime).
constexpr int kSeconds = 20;
constexpr int kMiB = 1536;

struct Outcome {
    int exit;         // 124: killed by the time bound
    std::string err;  // stderr
};

Outcome runBounded(const std::string& args) {
#ifdef HEXC_SANITIZED
    const std::string memory;  // ASan reserves terabytes of address space for its shadow; it checks memory itself
#else
    const std::string memory = "ulimit -v " + std::to_string(kMiB * 1024) + "; ";
#endif
    std::string err;
    int exit = hexc::test::runHexc(args, &err, memory + "timeout " + std::to_string(kSeconds));
    return {exit, err};
}

class Hostile : public testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("hexc_hostile_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "out");
    }
    fs::path write(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / name, std::ios::binary) << text;
        return dir_ / name;
    }
    // A valid one-slot material; `extra` is spliced in as more top-level members.
    std::string material(const std::string& extra = "") const {
        return R"({"name": "m", "slots": [{"name": "albedo", "kind": "color", "texture": ")" +
               fs::absolute("materials/textures/rock_albedo.png").string() + "\"}]" + extra + "}";
    }
    void expectNothingWritten() const { EXPECT_TRUE(fs::is_empty(dir_ / "out")) << "an output was written"; }
    std::string out() const { return " -o " + (dir_ / "out").string(); }

    fs::path dir_;
};

TEST_F(Hostile, DeepNestingIsALocatedErrorNotACrash) {
    fs::path m = write("deep.json", std::string(50000, '[') + std::string(50000, ']'));
    Outcome o = runBounded(m.string() + out());
    EXPECT_EQ(o.exit, 1) << o.err;
    EXPECT_NE(o.err.find("deep.json:1:33: error"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("nested deeper than 32 levels"), std::string::npos) << o.err;
    expectNothingWritten();
}

TEST_F(Hostile, AMinifiedMaterialWithManyValuesIsLinear) {
    // 640 KB on one line: locating each of its 160,000 values must not rescan the line.
    std::string values;
    for (int i = 0; i < 160000; ++i) values += i ? ",1.5" : "1.5";
    fs::path m = write("long_line.json", material(R"(, "junk": [)" + values + "]"));
    Outcome o = runBounded(m.string() + out());
    EXPECT_EQ(o.exit, 1) << o.err;
    EXPECT_NE(o.err.find("long_line.json:1:"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("/junk: unknown key"), std::string::npos) << o.err;
    expectNothingWritten();
}

TEST_F(Hostile, AHugeUnknownKeyDoesNotAmplifyTheSuggestionWork) {
    fs::path m = write("huge_key.json", material(", \"" + std::string(16 << 20, 'x') + "\": 1"));
    Outcome o = runBounded(m.string() + out());
    EXPECT_EQ(o.exit, 1) << o.err.substr(0, 300);
    EXPECT_NE(o.err.find("huge_key.json:1:"), std::string::npos) << o.err.substr(0, 300);
    expectNothingWritten();
}

TEST_F(Hostile, NonRegularMaterialFilesAreRefused) {
    fs::path fifo = dir_ / "fifo.json";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    for (const auto& [file, why] : {std::pair{std::string("/dev/zero"), "not a regular file"},
                                    std::pair{fifo.string(), "not a regular file"}, std::pair{dir_.string(), "is a directory"}}) {
        Outcome o = runBounded(file + out());
        EXPECT_EQ(o.exit, 1) << file << ": " << o.err;
        EXPECT_NE(o.err.find(std::string("cannot read material file: ") + why), std::string::npos) << file << ": " << o.err;
    }
    expectNothingWritten();
}

TEST_F(Hostile, AnOversizedMaterialIsRefusedBeforeItIsParsed) {
    fs::path m = dir_ / "big.json";
    fs::resize_file(write("big.json", "{"), 100 << 20);  // sparse: 100 MB of zeros after the brace
    Outcome o = runBounded(m.string() + out());
    EXPECT_EQ(o.exit, 1) << o.err;
    EXPECT_NE(o.err.find("input limit of 64 MiB"), std::string::npos) << o.err;
    expectNothingWritten();
}

TEST_F(Hostile, AByteOrderMarkDoesNotMoveDiagnostics) {
    fs::path m = write("bom.json", "\xEF\xBB\xBF" + material(",\n  \"tiling\": 4"));
    Outcome o = runBounded(m.string() + out());
    EXPECT_EQ(o.exit, 1) << o.err;
    EXPECT_NE(o.err.find("bom.json:2:3: error"), std::string::npos) << o.err;
}

TEST_F(Hostile, ATruncatedPngIsRejectedAtValidation) {
    std::ifstream in("materials/textures/rock_albedo.png", std::ios::binary);
    std::string png(3000, '\0');
    in.read(png.data(), std::streamsize(png.size()));
    fs::path tex = write("truncated.png", png);
    fs::path m = write("m.json", R"({"name": "m", "slots": [{"name": "albedo", "kind": "color", "texture": ")" + tex.string() + "\"}]}");
    Outcome o = runBounded(m.string() + out());
    EXPECT_EQ(o.exit, 1) << o.err;
    EXPECT_NE(o.err.find("m.json:1:"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("truncated"), std::string::npos) << o.err;
    expectNothingWritten();
}

TEST_F(Hostile, ATextureTooLargeForTheReferenceIsRefusedBeforeLoading) {
    // A PNG whose header says 16384 x 16384 (the reference would need 11.5 GB in fp64); stb does not check CRCs.
    std::ifstream in("materials/textures/rock_albedo.png", std::ios::binary);
    std::string png((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (size_t at : {16u, 20u}) png.replace(at, 4, std::string("\0\0\x40\0", 4));  // IHDR width, height: 0x4000
    fs::path tex = write("huge.png", png);
    fs::path m = write("m.json", R"({"name": "m", "slots": [{"name": "albedo", "kind": "color", "texture": ")" + tex.string() + "\"}]}");
    Outcome o = runBounded("render " + m.string() + " --reference --output albedo --size 8x8 -o " + (dir_ / "out" / "r.pfm").string());
    EXPECT_EQ(o.exit, 1) << o.err;
    EXPECT_NE(o.err.find("16384x16384 is too large for --reference"), std::string::npos) << o.err;
    expectNothingWritten();
}

TEST_F(Hostile, OutputsThatAreNotRegularFilesAreNotReplaced) {
    fs::path target = write("target.txt", "keep");
    fs::create_symlink(target, dir_ / "out" / "m.frag.spv");
    fs::path m = write("m.json", material());
    Outcome o = runBounded(m.string() + out());
    EXPECT_EQ(o.exit, 3) << o.err;
    EXPECT_NE(o.err.find("not a regular file"), std::string::npos) << o.err;
    EXPECT_TRUE(fs::is_symlink(dir_ / "out" / "m.frag.spv"));
    std::ifstream keep(target);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(keep), {}), "keep");

    fs::path fifo = dir_ / "dep.d";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    o = runBounded(m.string() + " -o " + (dir_ / "out2").string() + " --depfile " + fifo.string());
    EXPECT_EQ(o.exit, 3) << o.err;
    EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST_F(Hostile, ConcurrentRunsIntoOneFolderAllSucceed) {
    fs::path m = write("m.json", material());
    std::vector<int> exits(8, -1);
    std::vector<std::thread> runs;
    for (size_t i = 0; i < exits.size(); ++i)
        runs.emplace_back([&, i] {
            exits[i] = std::system(("timeout 60 " + std::string(HEXC_EXE) + " -q " + m.string() + out() + " 2>/dev/null").c_str());
        });
    for (auto& t : runs) t.join();
    for (int e : exits) EXPECT_EQ(e, 0);
    for (const auto& f : fs::directory_iterator(dir_ / "out")) EXPECT_FALSE(f.path().extension() == ".tmp") << f.path();
}

// The built-in unlit template with `defines` after its #version line and `use` at the start of main().
std::string unlitWith(const std::string& defines, const std::string& use) {
    std::ifstream in("templates/builtin/unlit.glsl");
    std::string text(std::istreambuf_iterator<char>(in), {});
    size_t body = text.find("void main() {");
    text.insert(body + 13, " " + use);
    text.insert(text.find('\n') + 1, defines);
    return text;
}

// Lines that once overflowed the stack in std::regex (it recursed per character): 30 KB of blanks after #version
// and after #include <hexc> compile; a 100 KB #error message is a located error.
TEST_F(Hostile, LongTemplateLinesAreLinear) {
    std::ifstream in("templates/builtin/unlit.glsl");
    const std::string unlit(std::istreambuf_iterator<char>(in), {});
    auto after = [&](const std::string& line, const std::string& extra) {
        std::string text = unlit;
        text.insert(text.find(line) + line.size(), extra);
        return text;
    };
    fs::path m = write("m.json", material());
    for (const auto& [name, text] : {std::pair{"version.glsl", after("#version 450", std::string(30000, ' '))},
                                     std::pair{"include.glsl", after("#include <hexc>", std::string(30000, '\t'))}}) {
        Outcome o = runBounded(m.string() + " --template " + write(name, text).string() + out());
        EXPECT_EQ(o.exit, 0) << name << ": " << o.err;
    }
    fs::remove_all(dir_ / "out");
    fs::create_directories(dir_ / "out");
    const fs::path error = write("error.glsl", after("#include <hexc>", "\n#error " + std::string(100000, 'x')));
    Outcome o = runBounded(m.string() + " --template " + error.string() + out());
    EXPECT_EQ(o.exit, 1) << o.err;
    EXPECT_NE(o.err.find(error.string() + ":7:0: error[HX205]: '#error' : xxx"), std::string::npos) << o.err.substr(0, 300);
    expectNothingWritten();
}

TEST_F(Hostile, MacroBombsInATemplateAreRefusedBeforePreprocessing) {
    // 2^40 tokens from 41 chained lines, and from one line of nested calls; glslang has no bound of its own.
    std::string chain = "#define M0 1.0\n";
    for (int i = 1; i <= 40; ++i)
        chain += "#define M" + std::to_string(i) + " (M" + std::to_string(i - 1) + " + M" + std::to_string(i - 1) + ")\n";
    std::string nested = "1.0";
    for (int i = 0; i < 40; ++i) nested = "D(" + nested + ")";
    fs::path m = write("m.json", material());
    for (const auto& [name, text] : {std::pair{"chain.glsl", unlitWith(chain, "float bomb = M40;")},
                                     std::pair{"nested.glsl", unlitWith("#define D(x) (x + x)\n", "float bomb = " + nested + ";")}}) {
        fs::path t = write(name, text);
        Outcome o = runBounded(m.string() + " --template " + t.string() + out());
        EXPECT_EQ(o.exit, 1) << o.err;
        // The line that uses the macros: the template's main(), after its defines.
        EXPECT_NE(o.err.find(t.string() + ":"), std::string::npos) << o.err;
        EXPECT_NE(o.err.find("macros expand to more than"), std::string::npos) << o.err;
        expectNothingWritten();
    }
}

TEST_F(Hostile, MacrosWithinTheBoundStillCompile) {
    std::string chain = "#define M0 1.0\n";
    for (int i = 1; i <= 10; ++i)
        chain += "#define M" + std::to_string(i) + " (M" + std::to_string(i - 1) + " * 0.5 + M" + std::to_string(i - 1) + " * 0.5)\n";
    fs::path t = write("chain.glsl", unlitWith(chain, "float fine = M10;"));
    Outcome o = runBounded(write("m.json", material()).string() + " --template " + t.string() + out());
    EXPECT_EQ(o.exit, 0) << o.err;
}

TEST_F(Hostile, ATemplatePathWithAQuoteKeepsErrorsLocated) {
    // A quoted `#line` name cannot hold `"`: the error must still name the file and the template's own line.
    fs::path t = write("q\"t.glsl", unlitWith("", "undefined_name;"));
    Outcome o = runBounded(write("m.json", material()).string() + " --template '" + t.string() + "'" + out());
    EXPECT_EQ(o.exit, 1) << o.err;
    std::ifstream in(t);
    int line = 1;
    for (std::string l; std::getline(in, l) && l.find("undefined_name") == std::string::npos;) ++line;
    EXPECT_NE(o.err.find(t.string() + ":" + std::to_string(line) + ":"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("undeclared identifier"), std::string::npos) << o.err;
    expectNothingWritten();
}

}  // namespace
