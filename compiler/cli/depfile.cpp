#include "depfile.h"

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
    return joined(outputs) + ": " + joined(inputs) + "\n";
}

}  // namespace hexc::cli
