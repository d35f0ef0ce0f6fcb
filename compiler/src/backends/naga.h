#pragma once
// The WGSL target's translator: naga (npm naga-wasm) in one Node.js process per hexc run, started on the first
// translation and shared by every compile after it (translations take turns).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hexc {

struct NagaResult {
    std::optional<std::string> wgsl;
    std::string error;         // why not: Node or naga-wasm missing, or naga's message about the module
    bool unavailable = false;  // the translator could not start (the error says what to install)
};

// `spirv` (without OpLine: naga's reader stops at them) as WGSL.
NagaResult nagaWgsl(const std::vector<uint32_t>& spirv);

// The naga-wasm package nagaWgsl loads (HEXC_NODE_PATH/naga-wasm), as "naga-wasm VERSION" from its package.json, read on
// each call (no Node needed); "naga-wasm (not found)" when there is none.
std::string nagaVersion();
// Everything that can change nagaWgsl's output, for the shader cache's key: that version and the driver script.
std::string nagaIdentity();

}  // namespace hexc
