#pragma once
// The WGSL target's translator, naga (npm naga-wasm): built into hexc (naga_wasm.cpp) when the build has it
// (HEXC_NAGA_IN_PROCESS), else, or with HEXC_NAGA=node, in one Node.js process per hexc run, started on the first
// translation and shared by every compile after it. Either way translations take turns.
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

// `spirv` as WGSL by the naga built into hexc; only in a build that has it.
NagaResult nagaWasmWgsl(const std::vector<uint32_t>& spirv);

// The naga nagaWgsl runs, as "naga-wasm VERSION": the built-in one's, or the package Node loads
// (HEXC_NODE_PATH/naga-wasm) from its package.json, read on each call (no Node needed); "naga-wasm (not found)" when
// there is none.
std::string nagaVersion();
// How this build runs naga, for --version: built in, or Node.js.
std::string nagaBuild();
// Everything that can change nagaWgsl's output, for the shader cache's key: that version and the built-in module's
// hash or Node's driver script.
std::string nagaIdentity();

}  // namespace hexc
