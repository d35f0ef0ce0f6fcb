#pragma once
// Incremental builds: a material (or scene variant) whose inputs have not changed since its outputs were
// written is not compiled again. Its inputs are hashed: the material file, the scene file, every texture's size
// (and the bytes of those whose texels a compile reads: histogram, packed, splat maps, web packages' copies), the
// template's text, the compile options, and the hexc version and build.
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "hexc/compiler.h"
#include "hexc/material.h"

namespace hexc::cli {

// The files a compile reads (for the depfile): the material file, its textures, a user template.
std::vector<std::filesystem::path> inputFiles(const Material& material, const CompileOptions& options);

// XXH3 (128 bit) of everything a compile depends on, as 32 hex digits; `extra` adds e.g. a scene file.
std::string inputHash(const Material& material, const CompileOptions& options, const std::vector<std::string>& engines,
                      const std::vector<std::filesystem::path>& extra);

// The stamp `dir/.<name>.hexc-stamp` records the hash and the outputs of the last successful compile; the outputs are
// up to date when the hash matches and each still holds what the stamp says it held.
bool upToDate(const std::filesystem::path& dir, const std::string& name, const std::string& hash);
// The outputs the stamp of `name` in `dir` lists; empty when there is none.
std::vector<std::string> stampedOutputs(const std::filesystem::path& dir, const std::string& name);
// Removes the files in `before` that no stamp in `dir` lists any more: what an earlier build wrote and this one
// does not (another --targets, a scene shader whose code changed). Only plain names from hexc's stamps are touched.
void removeStaleOutputs(const std::filesystem::path& dir, const std::set<std::string>& before);
// A stamp's text: `hash`, and each output's name with the hash of what it holds (checked by upToDate).
std::string stampText(const std::string& hash, const std::vector<OutputFile>& outputs);
std::string stampName(const std::string& name);

}  // namespace hexc::cli
