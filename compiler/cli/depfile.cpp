#include "depfile.h"

#include <stdexcept>

namespace hexc::cli {
namespace {

std::string escaped(const std::filesystem::path& p) {
    std::string out;
    for (char c : p.generic_string()) {
        if (c == ' ' || c == '#' || c == '\\') out += '\\';
        if (c == '$') out += '$';
        out += c;
    }
    return out;
}

std::string joined(const std::vector<std::filesystem::path>& paths) {
    std::string out;
    for (const auto& p : paths) {
        if (!out.empty()) out += ' ';
        out += escaped(p);
    }
    return out;
}

}  // namespace

std::string depfileText(const std::vector<std::filesystem::path>& outputs, const std::vector<std::filesystem::path>& inputs) {
    for (const auto& list : {outputs, inputs})
        for (const auto& p : list)
            if (p.string().find_first_of("\n\r") != std::string::npos)
                throw std::invalid_argument("--depfile: the path " + p.string() + " holds a line break, which no depfile can express");
    std::string text = joined(outputs) + ": " + joined(inputs) + "\n";
    // One empty rule per input (as `gcc -MP`): Make then rebuilds, instead of failing, when an input is deleted.
    for (const auto& p : inputs) text += "\n" + escaped(p) + ":\n";
    return text;
}

}  // namespace hexc::cli
