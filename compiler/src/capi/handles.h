#pragma once
// The C API's handles (hexc/hexc.h), shared with its part in the command line's library (compiler/cli/capi.cpp:
// render, preview and build), which libhexc cannot hold: it carries no Vulkan and no reference.
#include <string>
#include <vector>

#include "hexc/cache.h"
#include "hexc/compiler.h"
#include "hexc/hexc.h"
#include "hexc/report.h"

struct hexc_context {
    hexc::ShaderCache cache;
};

struct hexc_result {
    hexc::Diagnostics diagnostics;
    std::vector<hexc::OutputFile> files;
    std::vector<std::string> codes;  // each diagnostic's code, zero-terminated for C
    std::vector<hexc_output> outputs;
    std::vector<hexc_diagnostic> views;
    std::string text;
    std::vector<float> pixels;  // a render's: `image` views them
    hexc_image image{};
};

namespace hexc::capi {

// The result's C views of its C++ values, made once they no longer move. `text` is the diagnostics formatted unless
// it is given (what a command printed).
void makeViews(hexc_result& r);

}  // namespace hexc::capi
