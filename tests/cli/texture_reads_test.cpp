// A compile reads each texture file once: the parser reads it whole, and packing, the histogram tables, the layers'
// splat maps, the engine packages and the up-to-date check take it from there (hexc/image.h, TextureFile). Counted by
// what hexc asks the C library to open: tests/support/open_log.cpp, preloaded, logs every open.
#include <gtest/gtest.h>
#include <tinyexr.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "hexc/material.h"
#include "support.h"

namespace fs = std::filesystem;

namespace {

fs::path emptyDir(const std::string& name) {
    fs::path d = fs::temp_directory_path() / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

// The texture files the material's slots name, as real paths.
std::set<fs::path> texturesOf(const fs::path& material) {
    hexc::ParseResult r = hexc::parseMaterialFile(material);
    std::set<fs::path> files;
    if (r.material)
        for (const hexc::Slot& s : r.material->slots) files.insert(fs::canonical(s.texturePath));
    return files;
}

// How many times one run of hexc with `args` opens each of `textures`.
std::map<fs::path, int> opens(const std::string& args, const std::set<fs::path>& textures, const fs::path& log) {
    fs::remove(log);
    std::string err;
    EXPECT_EQ(hexc::test::runHexc(args, &err, "HEXC_OPEN_LOG=" + log.string() + " LD_PRELOAD=" + HEXC_OPEN_LOG_LIB), 0) << args << "\n"
                                                                                                                        << err;
    std::map<fs::path, int> count;
    for (const fs::path& t : textures) count[t] = 0;
    std::ifstream in(log);
    for (std::string line; std::getline(in, line);)
        if (textures.count(line)) ++count[line];
    return count;
}

// Each texture of `material` is opened exactly once by a compile, by the same compile up to date (nothing written),
// and by a forced one whose derived textures come from the shader cache.
void expectOneReadEach(const fs::path& material, const std::string& options, const std::string& name) {
    const std::set<fs::path> textures = texturesOf(material);
    ASSERT_FALSE(textures.empty()) << material;
    const fs::path dir = emptyDir("hexc_texture_reads_" + name), log = dir / "opens.log";
    const std::string args = material.string() + " -o " + (dir / "out").string() + " --cache-dir " + (dir / "cache").string() + options;
    const std::map<fs::path, int> once = [&] {
        std::map<fs::path, int> m;
        for (const fs::path& t : textures) m[t] = 1;
        return m;
    }();
    EXPECT_EQ(opens(args, textures, log), once) << "a compile of " << material;
    EXPECT_EQ(opens(args, textures, log), once) << "an up-to-date run of " << material;
    EXPECT_EQ(opens(args + " --force", textures, log), once) << "a forced compile from the cache of " << material;
}

TEST(TextureReads, RockOncePerCompile) { expectOneReadEach("materials/rock.json", "", "rock"); }

TEST(TextureReads, PackedMaterialOncePerCompile) { expectOneReadEach("tests/golden/materials/pack.json", "", "pack"); }

TEST(TextureReads, HistogramSlotsOncePerCompile) { expectOneReadEach("tests/golden/materials/histogram.json", "", "histogram"); }

// Four layers and a splat map, whose texels the plan reads to count fetches.
TEST(TextureReads, TerrainOncePerCompile) { expectOneReadEach("materials/terrain/terrain.json", "", "terrain"); }

// The web engines' packages copy each texture beside the module: the bytes the parser read.
TEST(TextureReads, EnginePackagesOncePerCompile) { expectOneReadEach("materials/rock.json", " --engines threejs,babylon", "engines"); }

// An OpenEXR file named by two slots, one of them blended by histogram (decoded from the bytes read): read once.
TEST(TextureReads, ExrNamedTwiceOncePerCompile) {
    const fs::path dir = emptyDir("hexc_texture_reads_exr_material");
    std::vector<float> rgba(size_t(16) * 16 * 4);
    for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = float(i % 97) / 96.0f;
    ASSERT_EQ(SaveEXR(rgba.data(), 16, 16, 4, 0, (dir / "t.exr").c_str(), nullptr), TINYEXR_SUCCESS);
    std::ofstream(dir / "m.json") << R"({"name": "m", "template": "lit", "slots": [
        {"name": "albedo", "kind": "color", "colorspace": "linear", "texture": "t.exr", "hextiling": {"blend": "histogram"}},
        {"name": "roughness", "kind": "scalar", "channel": "g", "texture": "t.exr"}]})";
    expectOneReadEach(dir / "m.json", "", "exr");
}

}  // namespace
