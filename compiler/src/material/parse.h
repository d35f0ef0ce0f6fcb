#pragma once
// The JSON material parser itself, for the MaterialX reader, which builds the JSON a document means and validates
// it here, so both formats follow one set of rules.
#include <filesystem>
#include <map>
#include <memory>
#include <string_view>

#include "hexc/image.h"
#include "hexc/material.h"

namespace hexc {

// parseMaterial for JSON text, whatever the file's name.
ParseResult parseMaterialJson(std::string_view text, const std::filesystem::path& file);

// While one lives, the materials parsed on its thread share their texture files, each read once (by its real path):
// a scene's or a MaterialX document's thousands of materials naming the same textures hold each file once, not once
// a material (2,500 copies of rock.json took 740 MB of texture bytes, and most of their parse time in copying them).
// It lasts one reading of the documents, as one material's own sharing does, so nothing it holds is stale.
class SharedTextureFiles {
public:
    using Files = std::map<std::filesystem::path, std::shared_ptr<const TextureFile>>;
    SharedTextureFiles();
    ~SharedTextureFiles();
    SharedTextureFiles(const SharedTextureFiles&) = delete;
    SharedTextureFiles& operator=(const SharedTextureFiles&) = delete;
    // The files of the innermost one living on this thread; null when none does.
    static Files* current();

private:
    Files files_;
    Files* outer_;
};

}  // namespace hexc
