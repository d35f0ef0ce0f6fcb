#include "cli/outputs.h"

#include <fstream>
#include <stdexcept>

namespace hexc::cli {

void writeAtomically(const std::filesystem::path& dir, const std::string& name, const std::string& contents) {
    std::filesystem::path target = dir / name;
    std::filesystem::path temp = dir / ("." + name + ".tmp");
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out.write(contents.data(), std::streamsize(contents.size()));
        out.close();
        if (!out) {
            std::error_code ignored;
            std::filesystem::remove(temp, ignored);
            throw std::runtime_error("cannot write " + target.string());
        }
    }
    std::error_code ec;
    std::filesystem::rename(temp, target, ec);
    if (ec) {
        std::filesystem::remove(temp, ec);
        throw std::runtime_error("cannot write " + target.string() + ": " + ec.message());
    }
}

}  // namespace hexc::cli
