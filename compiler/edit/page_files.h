#pragma once
// The page of `hexc edit` (compiler/edit/page), its vertex stage and the material schema, embedded at build time
// (compiler/cmake/embed.cmake): file name -> contents.
#include <map>
#include <string>

namespace hexc::edit {

const std::map<std::string, std::string>& pageFiles();

}  // namespace hexc::edit
