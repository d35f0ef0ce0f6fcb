#pragma once
// `hexc MATERIAL.json|SCENE.json ... -o DIR`: compile, skip what is up to date, deduplicate scene shaders,
// write outputs atomically (all or nothing), the depfile and a report.
#include "options.h"

namespace hexc::cli {

// A build's exit code when Arguments::progress stopped it (the C API's hexc_build; the command line never stops one).
constexpr int kStopped = 5;

int buildCommand(const Arguments& arguments);

}  // namespace hexc::cli
