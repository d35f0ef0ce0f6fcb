#include "hexc/files.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hexc {

std::optional<std::string> readFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void writeFileAtomically(const std::filesystem::path& file, const std::function<bool(const std::filesystem::path&)>& write) {
    // A hidden name in the target folder: the rename stays on one file system, so it is atomic.
    std::filesystem::path temp = file.parent_path() / ("." + file.filename().string() + ".tmp");
    std::error_code ec;
    if (!write(temp)) {
        std::filesystem::remove(temp, ec);
        throw std::runtime_error("cannot write " + file.string());
    }
    std::filesystem::rename(temp, file, ec);
    if (ec) {
        std::string why = ec.message();
        std::filesystem::remove(temp, ec);
        throw std::runtime_error("cannot write " + file.string() + ": " + why);
    }
}

}  // namespace hexc
