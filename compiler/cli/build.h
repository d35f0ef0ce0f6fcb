#pragma once
// `hexc MATERIAL.json|SCENE.json ... -o DIR`: compile, skip what is up to date, deduplicate scene shaders,
// write outputs atomically (all or nothing), the depfile and a report.
#include "options.h"

namespace hexc::cli {

int buildCommand(const Arguments& arguments);

}  // namespace hexc::cli
