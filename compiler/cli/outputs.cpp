#include "outputs.h"

#include <fstream>

#include "hexc/files.h"

namespace hexc::cli {

void writeAtomically(const std::filesystem::path& dir, const std::string& name, const std::string& contents) {
    std::filesystem::create_directories((dir / name).parent_path());  // an engine package's folder (--engine)
    writeFileAtomically(dir / name, [&](const std::filesystem::path& temp) {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out.write(contents.data(), std::streamsize(contents.size()));
        out.close();
        return bool(out);
    });
}

}  // namespace hexc::cli
