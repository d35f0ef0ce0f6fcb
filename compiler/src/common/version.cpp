// What identifies this build of hexc and its shader tool chain (hexc/compiler.h), for banners and cache keys.
#include <glslang/build_info.h>
#include <spirv-tools/libspirv.h>

#include "backends/naga.h"
#include "hexc/compiler.h"

namespace hexc {

const char* version() { return HEXC_VERSION; }

std::string toolchainVersions() {
    return "glslang " + std::to_string(GLSLANG_VERSION_MAJOR) + "." + std::to_string(GLSLANG_VERSION_MINOR) + "." +
           std::to_string(GLSLANG_VERSION_PATCH) + GLSLANG_VERSION_FLAVOR + "\nSPIRV-Tools " + spvSoftwareVersionString() +
           "\nSPIRV-Cross " + HEXC_SPIRV_CROSS_VERSION + "\nWGSL: " + nagaBuild();
}

}  // namespace hexc
