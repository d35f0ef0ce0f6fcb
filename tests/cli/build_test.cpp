// Scenes, incremental builds and depfiles, through the command line as a build system runs it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <set>
#include <sstream>

#include "hexc/compiler.h"
#include "hexc/image.h"
#include "hexc/scene.h"
#include "support.h"

using namespace hexc;
using hexc::test::runHexc;

namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// A private copy of materials/ (examples, scene, textures) that a test may change.
fs::path copyOfMaterials(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / name;
    fs::remove_all(dir);
    fs::copy("materials", dir, fs::copy_options::recursive);
    return dir;
}

// A fresh folder in the temporary directory holding tiles.json and its texture.
fs::path tilesFolder(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / name;
    fs::remove_all(dir);
    fs::create_directories(dir / "textures");
    fs::copy("materials/tiles.json", dir / "tiles.json");
    fs::copy("materials/textures/tiles_albedo.png", dir / "textures" / "tiles_albedo.png");
    return dir;
}

size_t countFiles(const fs::path& dir, const std::string& suffix) {
    size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir)) n += e.path().string().ends_with(suffix);
    return n;
}

TEST(Scene, CompilesOnlyTheVariantsItUsesAndSharesEqualShaders) {
    fs::path out = fs::temp_directory_path() / "hexc_scene_out";
    fs::remove_all(out);
    std::string err;
    ASSERT_EQ(runHexc("materials/scenes/forest.json -o " + out.string(), &err), 0) << err;
    // 3 materials x 4 passes = 12 possible; the shadow pass renders 2 materials, weights 1: 9 used.
    EXPECT_NE(err.find("hexc: scene forest: 12 variants possible, 9 used"), std::string::npos) << err;
    // The depth pass reads no slot, so its three variants have one shader: equal files under stable names, and one
    // `shader` hash in the index.
    EXPECT_NE(err.find("9 compiled, 0 up to date, 2 scene variants share another's code"), std::string::npos) << err;
    EXPECT_EQ(countFiles(out, ".manifest.json"), 9u);
    EXPECT_EQ(countFiles(out, ".frag.spv"), 9u);
    auto depth = [&](const std::string& m) { return nlohmann::json::parse(read(out / (m + ".depth.manifest.json"))); };
    EXPECT_EQ(depth("rock")["targets"]["spirv"]["file"], "rock.depth.frag.spv");
    // Their code is the same; each has its own entry point name, so that variants can share one library.
    auto renamed = [&](const std::string& v, const std::string& entry) {
        std::string text = withoutBanner(read(out / (v + ".frag.metal")));  // the banner names the material
        for (size_t at; (at = text.find(entry)) != std::string::npos;) text.replace(at, entry.size(), "ENTRY");
        return text;
    };
    EXPECT_EQ(renamed("rock.depth", "rock_depth_frag"), renamed("tiles.depth", "tiles_depth_frag"));
    EXPECT_NE(read(out / "rock.depth.frag.spv").find("rock_depth_frag"), std::string::npos);
    EXPECT_EQ(depth("rock")["slots"].size(), 0u);
    auto shadow = nlohmann::json::parse(read(out / "rock.shadow.manifest.json"));
    ASSERT_EQ(shadow["slots"].size(), 1u);  // the pass reads albedo only
    EXPECT_EQ(shadow["slots"][0]["name"], "albedo");
    auto index = nlohmann::json::parse(read(out / "forest.scene.json"));
    EXPECT_EQ(index["variants"].size(), 9u);
    EXPECT_TRUE(fs::exists(out / index["variants"]["rock.main"]["manifest"].get<std::string>()));
    EXPECT_EQ(index["variants"]["rock.depth"]["shader"], index["variants"]["rock_normal.depth"]["shader"]);
    EXPECT_NE(index["variants"]["rock.depth"]["shader"], index["variants"]["rock.main"]["shader"]);
    // Under one --entry the shared variants' files are byte-identical.
    ASSERT_EQ(
        runHexc("materials/scenes/forest.json --entry depthPS --variant rock.depth --variant tiles.depth -o " + (out / "entry").string(),
                &err),
        0)
        << err;
    EXPECT_EQ(read(out / "entry" / "rock.depth.frag.spv"), read(out / "entry" / "tiles.depth.frag.spv"));
}

TEST(Scene, AVariantTheSceneFiltersOutIsAnError) {
    std::string err;
    fs::path out = fs::temp_directory_path() / "hexc_scene_variant";
    fs::remove_all(out);
    EXPECT_EQ(runHexc("materials/scenes/forest.json -o " + out.string() + " --variant rock.main --variant rock_normal.shadow", &err), 1);
    EXPECT_EQ(err,
              "hexc: error: --variant rock_normal.shadow: pass `shadow` of scene `forest` renders only rock, tiles, not "
              "`rock_normal`\nhexc: nothing written\n");
    EXPECT_FALSE(fs::exists(out));
    ASSERT_EQ(runHexc("materials/scenes/forest.json -o " + out.string() + " --variant rock.main", &err), 0);
    EXPECT_EQ(countFiles(out, ".manifest.json"), 1u);
}

TEST(Scene, DiagnosticsAreLocated) {
    fs::path dir = copyOfMaterials("hexc_scene_bad");
    std::ofstream(dir / "scenes" / "bad.json") << R"({
  "scene": "bad",
  "materials": ["../rock.json", ""],
  "passes": [
    { "name": "main", "materials": ["rocks"] },
    { "name": "main", "colour": 1 }
  ]
})";
    SceneParseResult r = parseSceneFile(dir / "scenes" / "bad.json");
    ASSERT_FALSE(r.scene);
    std::vector<std::string> got;
    for (const auto& d : r.diagnostics) got.push_back(d.format().substr(d.format().find("bad.json:")));
    EXPECT_EQ(
        got, (std::vector<std::string>{
                 "bad.json:3:33: error[HX100]: /materials/1: an empty path names no material file",
                 "bad.json:5:37: error[HX113]: /passes/0/materials/0: no material named `rocks` in the scene (did you mean `rock`?)",
                 "bad.json:6:23: error[HX103]: /passes/1/colour: unknown key `colour`; expected `name`, `template`, `slots` or `materials`",
                 "bad.json:6:15: error[HX109]: /passes/1/name: duplicate pass name \"main\"",
             }));
}

// parseScene on a document without the `scene` key (a material, say) reports the missing key.
TEST(Scene, ADocumentWithoutTheSceneKeyIsADiagnostic) {
    SceneParseResult r = parseScene(R"({"name": "rock", "materials": ["x.json"], "passes": [{"name": "main"}]})", "s.json");
    ASSERT_FALSE(r.scene);
    std::vector<std::string> got;
    for (const auto& d : r.diagnostics) got.push_back(d.format());
    EXPECT_EQ(got, (std::vector<std::string>{
                       "s.json:1:2: error[HX103]: /name: unknown key `name`; expected `$schema`, `scene`, `materials` or `passes`",
                       "s.json:1:1: error[HX104]: missing required key `scene` (the scene's name)",
                       "x.json: error[HX100]: cannot read material file: No such file or directory",
                       "s.json:1:32: error[HX115]: /materials/0: material x.json is invalid (see above)",
                   }));
}

// A scene's material paths are shown normalised: `scenes/../rock.json` is `rock.json` in every message.
TEST(Scene, MaterialPathsAreShownNormalised) {
    SceneParseResult r = parseScene(R"({"scene": "s", "materials": ["../sub/./x.json"], "passes": [{"name": "main"}]})", "sub/s.json");
    ASSERT_FALSE(r.scene);
    std::vector<std::string> got;
    for (const auto& d : r.diagnostics) got.push_back(d.format());
    EXPECT_EQ(got, (std::vector<std::string>{
                       "sub/x.json: error[HX100]: cannot read material file: No such file or directory",
                       "sub/s.json:1:30: error[HX115]: /materials/0: material sub/x.json is invalid (see above)",
                   }));
}

// Two scenes of one name would write one index file: refused before anything is compiled or written.
TEST(Scene, TwoScenesWithOneNameAreRefused) {
    fs::path dir = copyOfMaterials("hexc_scene_twice");
    std::ofstream(dir / "scenes" / "a.json") << R"({"scene": "same", "materials": ["../rock.json"], "passes": [{"name": "main"}]})";
    std::ofstream(dir / "scenes" / "b.json") << R"({"scene": "same", "materials": ["../tiles.json"], "passes": [{"name": "main"}]})";
    fs::path out = dir / "out";
    std::string err;
    EXPECT_EQ(runHexc((dir / "scenes" / "a.json").string() + " " + (dir / "scenes" / "b.json").string() + " -o " + out.string(), &err), 1);
    EXPECT_NE(err.find("hexc: error: two scenes are named `same`; their indexes (same.scene.json) would overwrite each other"),
              std::string::npos)
        << err;
    EXPECT_FALSE(fs::exists(out));
}

// An engine package replaces the template, so a scene's passes have none: refused, not aborted (it once was).
TEST(Scene, EnginePackagesOfASceneAreRefused) {
    fs::path dir = copyOfMaterials("hexc_scene_engines");
    fs::path out = dir / "out";
    for (const char* engine : {"godot3", "filament", "threejs", "unity"}) {
        std::string err;
        EXPECT_EQ(runHexc((dir / "scenes" / "forest.json").string() + " --engines " + engine + " -o " + out.string(), &err), 1) << engine;
        EXPECT_NE(err.find("hexc: error: --engine packages materials, not a scene's passes"), std::string::npos) << err;
        EXPECT_FALSE(fs::exists(out));
    }
}

TEST(Incremental, UnchangedInputsAreSkippedAndAChangedTextureRebuildsWhatUsesIt) {
    fs::path dir = copyOfMaterials("hexc_incremental");
    fs::path out = dir / "out";
    std::string err;
    ASSERT_EQ(runHexc(dir.string() + "/scenes/forest.json -o " + out.string(), &err), 0) << err;
    ASSERT_EQ(runHexc(dir.string() + "/scenes/forest.json -o " + out.string(), &err), 0) << err;
    EXPECT_NE(err.find("0 compiled, 9 up to date"), std::string::npos) << err;
    // New bytes in a texture of the same size: the shaders read only its size, so nothing compiles again.
    { std::ofstream(dir / "textures" / "tiles_albedo.png", std::ios::app) << ' '; }
    ASSERT_EQ(runHexc(dir.string() + "/scenes/forest.json -o " + out.string(), &err), 0) << err;
    EXPECT_NE(err.find("0 compiled, 9 up to date"), std::string::npos) << err;
    // Another size of a texture only tiles.json reads: its main and shadow variants compile again (depth reads no
    // slot).
    Image odd;
    odd.width = 127, odd.height = 80;
    odd.rgba.assign(size_t(odd.width) * odd.height * 4, 0.5f);
    writeImage(odd, dir / "textures" / "tiles_albedo.png");
    ASSERT_EQ(runHexc(dir.string() + "/scenes/forest.json -o " + out.string(), &err), 0) << err;
    EXPECT_NE(err.find("2 compiled, 7 up to date"), std::string::npos) << err;
    // Other options change every output.
    ASSERT_EQ(runHexc(dir.string() + "/scenes/forest.json -o " + out.string() + " --bake", &err), 0) << err;
    EXPECT_NE(err.find("9 compiled, 0 up to date"), std::string::npos) << err;
    // A deleted output is written again.
    fs::remove(out / "rock.main.manifest.json");
    ASSERT_EQ(runHexc(dir.string() + "/scenes/forest.json -o " + out.string() + " --bake", &err), 0) << err;
    EXPECT_NE(err.find("1 compiled, 8 up to date"), std::string::npos) << err;
}

// A layered material's plan reads its splat map's texels (the expected fetches per pixel): a splat map repainted at the
// same size compiles again, and the manifest's figure follows it.
TEST(Incremental, ARepaintedSplatMapCompilesAgain) {
    const fs::path dir = fs::temp_directory_path() / "hexc_incremental_splat";
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy("materials/textures/rock_albedo.png", dir / "a.png");
    fs::copy("materials/textures/tiles_albedo.png", dir / "b.png");
    auto paint = [&](uint8_t g) {  // layer 0 everywhere; layer 1 with weight g (0: not fetched)
        Texture splat{8, 8, false, {}, {}};
        for (int i = 0; i < 64; ++i) splat.rgba8.insert(splat.rgba8.end(), {uint8_t(255 - g), g, 0, 0});
        std::ofstream(dir / "splat.png", std::ios::binary) << pngBytes(splat);
    };
    std::ofstream(dir / "m.json") << R"({"name": "m", "layers": [
        {"name": "a", "slots": [{"name": "albedo", "kind": "color", "texture": "a.png"}]},
        {"name": "b", "slots": [{"name": "albedo", "kind": "color", "texture": "b.png"}]}],
        "layer_blend": {"splat": ["splat.png"]}})";
    auto expected = [&] {
        std::string err;
        EXPECT_EQ(runHexc((dir / "m.json").string() + " --targets spirv -o " + (dir / "out").string(), &err), 0) << err;
        return nlohmann::json::parse(read(dir / "out" / "m.manifest.json"))["layers"]["fetches_per_pixel"]["expected"].get<double>();
    };
    paint(0);
    const double alone = expected();
    paint(128);
    const double both = expected();
    // Three taps per hex-tiled layer and one splat fetch: 3 + 1 with layer 1 skipped everywhere, 6 + 1 with it kept.
    EXPECT_EQ(alone, 4.0);
    EXPECT_EQ(both, 7.0);
}

// What a texture's header says decides outputs too: a layer's texture of the same size with other channels (grey and
// alpha, where the other layers are grey) takes its role out of one array, so it compiles again.
TEST(Incremental, ATextureWithOtherChannelsCompilesAgain) {
    const fs::path dir = fs::temp_directory_path() / "hexc_incremental_channels";
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy("materials/textures/rock_roughness.png", dir / "a.png");
    fs::copy("materials/textures/rock_height.png", dir / "b.png");
    fs::copy("materials/textures/terrain_splat.png", dir / "splat.png");
    std::ofstream(dir / "m.json") << R"({"name": "m", "layers": [
        {"name": "a", "slots": [{"name": "roughness", "kind": "scalar", "texture": "a.png"}]},
        {"name": "b", "slots": [{"name": "roughness", "kind": "scalar", "texture": "b.png"}]}],
        "layer_blend": {"splat": ["splat.png"]}})";
    auto arrays = [&] {
        std::string err;
        EXPECT_EQ(runHexc((dir / "m.json").string() + " --targets spirv -o " + (dir / "out").string(), &err), 0) << err;
        return nlohmann::json::parse(read(dir / "out" / "m.manifest.json"))["layers"]["arrays"][0];
    };
    EXPECT_TRUE(arrays()["array"].get<bool>()) << "both grey, 256 x 256: one array";
    fs::copy("materials/textures/terrain_grass_rh.png", dir / "b.png", fs::copy_options::overwrite_existing);  // 256 x 256, grey + alpha
    const nlohmann::json now = arrays();
    EXPECT_FALSE(now["array"].get<bool>()) << now;
}

TEST(Incremental, AnotherHexcBuildDoesNotTrustTheStamp) {
    fs::path dir = copyOfMaterials("hexc_stale");
    fs::path out = dir / "out";
    std::string err;
    ASSERT_EQ(runHexc(dir.string() + "/tiles.json -o " + out.string(), &err), 0) << err;
    // The same version string in a different binary (as a rebuilt hexc, or one linked with newer glslang).
    fs::path other = dir / "hexc-other";
    hexc::test::copyAsAnotherBuild(other);
    fs::path log = dir / "other.txt";
    int status = std::system((other.string() + " " + dir.string() + "/tiles.json -o " + out.string() + " 2> " + log.string()).c_str());
    std::ifstream in(log);
    err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    ASSERT_EQ(WEXITSTATUS(status), 0) << err;
    EXPECT_NE(err.find("1 compiled, 0 up to date"), std::string::npos) << err;
}

// --force compiles what the stamps call up to date; -j 1 gives the same bytes as one thread per core.
TEST(Incremental, ForceAndJobs) {
    fs::path dir = copyOfMaterials("hexc_force");
    std::string err;
    ASSERT_EQ(runHexc(dir.string() + "/scenes/forest.json -o " + (dir / "a").string(), &err), 0) << err;
    ASSERT_EQ(runHexc(dir.string() + "/scenes/forest.json -o " + (dir / "a").string() + " --force", &err), 0) << err;
    EXPECT_NE(err.find("9 compiled, 0 up to date"), std::string::npos) << err;
    ASSERT_EQ(runHexc(dir.string() + "/scenes/forest.json -j 1 -o " + (dir / "b").string(), &err), 0) << err;
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir / "a")) {
        ++files;
        EXPECT_EQ(read(e.path()), read(dir / "b" / e.path().filename())) << e.path().filename();
    }
    EXPECT_EQ(files, size_t(std::distance(fs::directory_iterator(dir / "b"), fs::directory_iterator())));
    EXPECT_EQ(runHexc(dir.string() + "/tiles.json -j 0 -o " + (dir / "c").string(), &err), 2);
}

// Files an earlier build wrote and this one does not are removed, unless another stamp still lists them.
TEST(Incremental, StaleOutputsAreRemoved) {
    fs::path dir = copyOfMaterials("hexc_stale_outputs"), out = dir / "out";
    std::string err;
    ASSERT_EQ(runHexc(dir.string() + "/tiles.json -o " + out.string(), &err), 0) << err;
    ASSERT_EQ(runHexc(dir.string() + "/tiles.json --targets spirv -o " + out.string(), &err), 0) << err;
    EXPECT_TRUE(fs::exists(out / "tiles.frag.spv"));
    for (const char* gone : {"tiles.frag.hlsl", "tiles.frag.glsl", "tiles.frag.metal"}) EXPECT_FALSE(fs::exists(out / gone)) << gone;
    // Rebuilding some variants of a scene for SPIR-V alone removes only their other targets.
    ASSERT_EQ(runHexc(dir.string() + "/scenes/forest.json -o " + out.string(), &err), 0) << err;
    ASSERT_EQ(
        runHexc(dir.string() + "/scenes/forest.json --targets spirv --variant rock.depth --variant rock.main -o " + out.string(), &err), 0)
        << err;
    EXPECT_FALSE(fs::exists(out / "rock.main.frag.hlsl"));
    EXPECT_FALSE(fs::exists(out / "rock.depth.frag.hlsl"));
    EXPECT_TRUE(fs::exists(out / "rock.depth.frag.spv"));
    EXPECT_TRUE(fs::exists(out / "tiles.depth.frag.hlsl")) << "another variant's output";
    EXPECT_TRUE(fs::exists(out / "tiles.frag.spv")) << "another material's output";
}

TEST(Depfile, ListsEveryInputWithMakeEscapes) {
    // A folder name with the characters Make and Ninja treat specially.
    const fs::path dir = tilesFolder("hexc dep$#");
    fs::path out = fs::temp_directory_path() / "hexc_dep_out";
    fs::remove_all(out);
    std::string err;
    ASSERT_EQ(runHexc("'" + (dir / "tiles.json").string() + "' -o " + out.string() + " --depfile " + (out / "tiles.d").string(), &err), 0)
        << err;
    auto esc = [](std::string s) {
        std::string o;
        for (char c : s) {
            if (c == ' ' || c == '#') o += '\\';
            if (c == '$') o += '$';
            o += c;
        }
        return o;
    };
    const std::string material = esc((dir / "tiles.json").string()), texture = esc((dir / "textures" / "tiles_albedo.png").string());
    // The rule, then an empty rule per input (gcc -MP), so that deleting an input re-runs hexc instead of stopping Make.
    // Every output is a target: the manifest and the four shaders.
    std::string outputs;
    for (const char* ext : {"glsl", "hlsl", "metal", "spv"}) outputs += esc((out / ("tiles.frag." + std::string(ext))).string()) + " ";
    outputs += esc((out / "tiles.manifest.json").string());
    EXPECT_EQ(read(out / "tiles.d"), outputs + ": " + material + " " + texture + "\n\n" + material + ":\n\n" + texture + ":\n");
}

// The targets of a depfile's first rule, unescaped.
std::set<std::string> depfileTargets(const std::string& text) {
    std::set<std::string> targets;
    std::string path;
    for (size_t i = 0; i < text.find(": "); ++i) {
        if (text[i] == ' ') {
            targets.insert(path);
            path.clear();
            continue;
        }
        if ((text[i] == '\\' && (text[i + 1] == ' ' || text[i + 1] == '#')) || (text[i] == '$' && text[i + 1] == '$')) ++i;
        path += text[i];
    }
    targets.insert(path);
    return targets;
}

// Every example texture through the histogram blend, compiled and then read back from the cache: its tables are PFM
// files whose floats may begin with a whitespace byte, which the cache's check of a table once took for the header's
// (terrain_snow_albedo.png's gaussian did: an internal error).
TEST(Outputs, EveryExampleTextureHasHistogramTables) {
    const fs::path dir = copyOfMaterials("hexc_histogram_tables");
    int count = 0;
    for (const auto& entry : fs::directory_iterator(dir / "textures")) {
        if (entry.path().extension() != ".png") continue;
        const std::string name = entry.path().stem().string();
        std::ofstream(dir / (name + ".json")) << R"({"name": "h", "template": "unlit", "hextiling": {"blend": "histogram"},
            "slots": [{"name": "albedo", "kind": "color", "texture": "textures/)"
                                              << entry.path().filename().string() << "\"}]}";
        for (const char* pass : {"computed", "from the cache"}) {
            std::string err;
            EXPECT_EQ(hexc::test::runHexc("'" + (dir / (name + ".json")).string() + "' --targets spirv --force -o '" +
                                              (dir / "out" / name).string() + "' --cache-dir '" + (dir / "cache").string() + "'",
                                          &err),
                      0)
                << name << ", " << pass << ": " << err;
            EXPECT_TRUE(fs::exists(dir / "out" / name / "h.albedo.lut.pfm")) << name << ", " << pass;
        }
        ++count;
    }
    EXPECT_GE(count, 17);
}

// --list-outputs, run before the build, names exactly the files the build writes (the stamps apart) and the depfile's
// targets, for every kind of output: a histogram slot the template reads (and one it does not: no tables), a packed
// texture, a MaterialX document, a scene's variants and index, the vertex stage, the generated GLSL.
TEST(Outputs, ListedBeforeTheBuildAreExactlyThoseWritten) {
    const fs::path dir = copyOfMaterials("hexc_list_outputs"), out = dir / "out dir";
    std::ofstream(dir / "h.json") << R"({"name": "h", "template": "unlit", "hextiling": {"blend": "histogram", "tiling": 3},
        "slots": [{"name": "albedo", "kind": "color", "texture": "textures/tiles_albedo.png"},
                  {"name": "unread", "kind": "scalar", "texture": "textures/rock_height.png"}]})";
    std::ofstream(dir / "p.json") << R"({"name": "p", "pack": true, "slots": [
        {"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png"},
        {"name": "roughness", "kind": "scalar", "texture": "textures/rock_roughness.png"}]})";
    const std::string inputs = "'" + (dir / "h.json").string() + "' '" + (dir / "p.json").string() + "' '" +
                               (dir / "mtlx/rock.mtlx").string() + "' '" + (dir / "scenes/forest.json").string() + "' -o '" + out.string() +
                               "' --vertex --emit-generated";
    const nlohmann::json list = nlohmann::json::parse(hexc::test::runHexcStdout(inputs + " --list-outputs"));
    ASSERT_FALSE(fs::exists(out)) << "--list-outputs wrote its output folder";
    std::set<std::string> listed;
    for (const auto& o : list["outputs"]) listed.insert(o.get<std::string>());
    EXPECT_EQ(listed.size(), list["outputs"].size()) << "an output listed twice";
    for (const char* f : {"h.albedo.gaussian.pfm", "h.albedo.lut.pfm", "p.albedo.packed.png", "rock.vert.metal", "forest.scene.json",
                          "tiles.shadow.frag.spv", "p.generated.frag"})
        EXPECT_TRUE(listed.contains((out / f).string())) << f << " not listed";
    EXPECT_FALSE(listed.contains((out / "h.unread.gaussian.pfm").string())) << "a slot the template does not read has no tables";
    // The inputs the list is decided from: the material and scene files, and the textures of the packing material only.
    const std::vector<std::string> decidedBy = list["inputs"];
    EXPECT_NE(std::find(decidedBy.begin(), decidedBy.end(), (dir / "textures/rock_roughness.png").string()), decidedBy.end());
    EXPECT_EQ(std::find(decidedBy.begin(), decidedBy.end(), (dir / "textures/tiles_albedo.png").string()), decidedBy.end());

    std::string err;
    ASSERT_EQ(runHexc(inputs + " --no-cache --depfile '" + (dir / "all.d").string() + "'", &err), 0) << err;
    std::set<std::string> written;
    for (const auto& e : fs::directory_iterator(out))
        if (!e.path().filename().string().ends_with(".hexc-stamp")) written.insert(e.path().string());
    EXPECT_EQ(written, listed);
    EXPECT_EQ(depfileTargets(read(dir / "all.d")), listed);
    // Once up to date (nothing compiled), the depfile still names them all.
    ASSERT_EQ(runHexc(inputs + " --depfile '" + (dir / "again.d").string() + "'", &err), 0) << err;
    EXPECT_EQ(depfileTargets(read(dir / "again.d")), listed);
}

// The same for engine packages (every engine: their folders, sources, manifests, packed textures and the web
// packages' texture copies) and for the functions output (<name>.functions.<ext>).
TEST(Outputs, EnginePackagesAndFunctionsAreListedAsWritten) {
    const fs::path dir = copyOfMaterials("hexc_list_engines");
    std::ofstream(dir / "p.json") << R"({"name": "p", "pack": true, "slots": [
        {"name": "albedo", "kind": "color", "texture": "textures/rock_albedo.png"},
        {"name": "roughness", "kind": "scalar", "texture": "textures/rock_roughness.png"},
        {"name": "normal", "kind": "normal", "texture": "textures/rock_normal.png"}]})";
    const std::string materials = "'" + (dir / "p.json").string() + "' '" + (dir / "rock.json").string() + "'";
    for (const std::string& mode :
         {std::string("--engine godot3,godot4,filament,threejs,babylon,unity,unreal"), std::string("--functions")}) {
        const fs::path out = dir / (mode == "--functions" ? "functions" : "engines");
        const std::string inputs = materials + " -o '" + out.string() + "' " + mode;
        const nlohmann::json list = nlohmann::json::parse(hexc::test::runHexcStdout(inputs + " --list-outputs"));
        ASSERT_FALSE(fs::exists(out)) << "--list-outputs wrote its output folder";
        std::set<std::string> listed;
        for (const auto& o : list["outputs"]) listed.insert(o.get<std::string>());
        std::string err;
        ASSERT_EQ(runHexc(inputs + " --no-cache --depfile '" + (out.string() + ".d") + "'", &err), 0) << err;
        std::set<std::string> written;
        for (const auto& e : fs::recursive_directory_iterator(out))
            if (e.is_regular_file() && !e.path().filename().string().ends_with(".hexc-stamp")) written.insert(e.path().string());
        EXPECT_EQ(written, listed) << mode;
        EXPECT_EQ(depfileTargets(read(out.string() + ".d")), listed) << mode;
        EXPECT_TRUE(listed.contains((out / (mode == "--functions" ? "rock.functions.hlsl" : "unity/p.hexc.hlsl")).string())) << mode;
    }
}

// The library's outputNames is compile()'s file list, planned only; which slots pack depends on pixels: a colour
// texture with one translucent texel keeps its alpha, and nothing packs.
TEST(Outputs, OutputNamesAreTheFilesCompileReturns) {
    const fs::path dir = copyOfMaterials("hexc_output_names");
    Texture albedo = loadTexture(dir / "textures/rock_albedo.png", false);
    for (const bool opaque : {true, false}) {
        albedo.rgba8[4 * 17 + 3] = opaque ? 255 : 254;
        std::ofstream(dir / "textures/a.png", std::ios::binary) << pngBytes(albedo);
        std::ofstream(dir / "p.json") << R"({"name": "p", "pack": true, "slots": [
            {"name": "albedo", "kind": "color", "texture": "textures/a.png"},
            {"name": "roughness", "kind": "scalar", "texture": "textures/rock_roughness.png"}]})";
        ParseResult parsed = parseMaterial(read(dir / "p.json"), dir / "p.json");
        ASSERT_TRUE(parsed.material) << formatAll(parsed.diagnostics);
        CompileOptions options;
        options.targets = {Target::Msl, Target::Spirv};
        options.vertex = true;
        const CompileResult compiled = compile(*parsed.material, options);
        ASSERT_TRUE(compiled.ok()) << formatAll(compiled.diagnostics);
        std::vector<std::string> names;
        for (const OutputFile& f : compiled.files) names.push_back(f.name);
        EXPECT_EQ(outputNames(*parsed.material, options).names, names);
        EXPECT_EQ(std::find(names.begin(), names.end(), "p.albedo.packed.png") != names.end(), opaque);
    }
}

// The manifest names a material's template file as the material wrote it: compiling the same material from
// another working directory, or by an absolute path, gives a byte-identical manifest.
TEST(Manifest, NamesTheTemplateFileAsTheMaterialWroteIt) {
    const fs::path dir = tilesFolder("hexc_template_as_written");
    fs::create_directories(dir / "shaders");
    fs::copy("templates/builtin/unlit.glsl", dir / "shaders" / "mine.glsl");
    nlohmann::json m = nlohmann::json::parse(read(dir / "tiles.json"));
    m["template"] = "shaders/mine.glsl";
    std::ofstream(dir / "tiles.json") << m.dump(2);
    const fs::path absOut = dir / "out_abs", relOut = dir / "out_rel";
    std::string err;
    ASSERT_EQ(runHexc((dir / "tiles.json").string() + " -o " + absOut.string(), &err), 0) << err;
    ASSERT_EQ(runHexc("tiles.json -o out_rel", &err, "cd " + dir.string() + " &&"), 0) << err;
    const std::string manifest = read(absOut / "tiles.manifest.json");
    EXPECT_EQ(nlohmann::json::parse(manifest)["template"], "shaders/mine.glsl");
    EXPECT_EQ(manifest, read(relOut / "tiles.manifest.json"));
}

// The inputs of a depfile's gcc -MP rules (one "input:" line each), unescaped.
std::vector<std::string> depfileInputs(const std::string& text) {
    std::vector<std::string> inputs;
    std::istringstream in(text.substr(text.find('\n')));
    for (std::string line; std::getline(in, line);) {
        if (line.empty()) continue;
        std::string path;
        for (size_t i = 0; i + 1 < line.size(); ++i) {  // the last character is the rule's ':'
            if ((line[i] == '\\' && (line[i + 1] == ' ' || line[i + 1] == '#')) || (line[i] == '$' && line[i + 1] == '$')) ++i;
            path += line[i];
        }
        inputs.push_back(path);
    }
    return inputs;
}

// A hermetic action: hexc given only the files its depfile names (as a sandbox or a remote executor gives it)
// writes byte-identical outputs. Built-in templates are part of hexc; a user template is a named input.
TEST(Depfile, TheFilesItNamesAreEverythingACompileReads) {
    const fs::path src = copyOfMaterials("hexc_hermetic_src"), dst = fs::temp_directory_path() / "hexc_hermetic_dst";
    fs::remove_all(dst);
    fs::copy("templates/builtin/unlit.glsl", src / "mine.glsl");
    nlohmann::json custom = nlohmann::json::parse(read(src / "tiles.json"));
    custom["name"] = "custom";
    custom["template"] = "mine.glsl";
    std::ofstream(src / "custom.json") << custom.dump(2);
    const std::string build = "scenes/forest.json rock_blend.json custom.json -o out --depfile out/all.d -q";
    std::string err;
    ASSERT_EQ(runHexc(build, &err, "cd '" + src.string() + "' &&"), 0) << err;
    const std::vector<std::string> inputs = depfileInputs(read(src / "out" / "all.d"));
    EXPECT_NE(std::find(inputs.begin(), inputs.end(), "mine.glsl"), inputs.end());
    for (const std::string& in : inputs) {
        fs::create_directories((dst / in).parent_path());
        fs::copy_file(src / in, dst / in, fs::copy_options::overwrite_existing);
    }
    ASSERT_EQ(runHexc(build, &err, "cd '" + dst.string() + "' &&"), 0) << err;
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(src / "out")) {
        ++files;
        EXPECT_EQ(read(e.path()), read(dst / "out" / e.path().filename())) << e.path().filename();
    }
    EXPECT_GT(files, 40u);
}

// The Ninja rule of docs/scenes.md, with this build's hexc: a no-op rebuild does nothing, a deleted shader is
// built again.
TEST(Depfile, TheNinjaRuleInTheDocsRebuildsWhatIsMissing) {
    const fs::path dir = copyOfMaterials("hexc_ninja");
    std::ofstream(dir / "build.ninja")
        << "rule hexc\n  command = " << HEXC_EXE
        << " $in -o shaders --depfile $depfile -q\n  depfile = $depfile\n  deps = gcc\n"
           "build shaders/rock.manifest.json shaders/rock.frag.spv shaders/rock.frag.hlsl shaders/rock.frag.glsl $\n"
           "      shaders/rock.frag.metal: hexc rock.json\n  depfile = shaders/rock.d\n";
    auto ninja = [&] {
        const fs::path log = dir / "ninja.log";
        EXPECT_EQ(std::system(("ninja -C '" + dir.string() + "' > '" + log.string() + "' 2>&1").c_str()), 0) << read(log);
        return read(log);
    };
    EXPECT_NE(ninja().find("hexc rock.json"), std::string::npos);
    EXPECT_NE(ninja().find("no work to do"), std::string::npos);
    fs::remove(dir / "shaders" / "rock.frag.hlsl");
    EXPECT_NE(ninja().find("hexc rock.json"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "shaders" / "rock.frag.hlsl"));
    EXPECT_NE(ninja().find("no work to do"), std::string::npos);
}

// No depfile syntax holds a line break: such a path is an error, and nothing is written.
TEST(Depfile, APathWithALineBreakIsRefusedAndNothingIsWritten) {
    const fs::path dir = tilesFolder("hexc_dep\nline");
    fs::path out = fs::temp_directory_path() / "hexc_dep_newline_out";
    fs::remove_all(out);
    std::string err;
    EXPECT_EQ(runHexc("'" + (dir / "tiles.json").string() + "' -o " + out.string() + " --depfile " + (out / "tiles.d").string(), &err), 1);
    EXPECT_NE(err.find("holds a line break, which no depfile can express"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
