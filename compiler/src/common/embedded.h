#pragma once
// Templates and snippets embedded into libhexc at build time (compiler/cmake/embed.cmake): file name -> text.
#include <map>
#include <string>

namespace hexc {

const std::map<std::string, std::string>& embeddedTemplates();

}  // namespace hexc
