#pragma once
// Files embedded into libhexc at build time (compiler/cmake/embed.cmake).
#include <string>
#include <vector>

namespace hexc {

struct EmbeddedFile {
    std::string name;      // file name, e.g. "lit.glsl"
    std::string contents;
};

const std::vector<EmbeddedFile>& embeddedTemplates();

}  // namespace hexc
