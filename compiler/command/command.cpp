#include "command.h"

#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <sstream>

#include "hexc/files.h"
#include "hexc/suggest.h"

namespace hexc::command {
namespace {

const char* const kExitCodes = R"(Exit codes:
  0  success (warnings may have been printed)
  1  a material, template or texture is invalid, or compilation failed (diagnostics on stderr); lint: a check warned
  2  bad command line
  3  an output could not be written
  4  render, preview, bake: no Vulkan device, or the device failed)";

// "; did you mean `--vertex`?" for the first unexpected argument that looks like a misspelt option, else "".
std::string suggestOption(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::Option* o : app.get_options()) {
        for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
        for (const std::string& n : o->get_snames()) names.push_back("-" + n);
    }
    for (const std::string& arg : app.remaining()) {
        if (!arg.starts_with("--")) continue;
        if (auto best = closestMatch(arg.substr(0, arg.find('=')), names)) return "; did you mean `" + *best + "`?";
    }
    return "";
}

}  // namespace

std::optional<int> parseWith(CLI::App& app, const std::vector<std::string>& args, std::ostream& err) {
    app.footer(kExitCodes);
    app.get_formatter()->column_width(30);
    try {
        std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 consumes from the back
        app.parse(reversed);
    } catch (const CLI::CallForVersion& e) {  // a CLI::Success too: caught first
        std::cout << e.what() << "\n";
        return kOk;
    } catch (const CLI::Success&) {
        std::cout << app.help();
        return kOk;
    } catch (const CLI::ExtrasError& e) {
        err << "hexc: " << e.what() << suggestOption(app) << " (see " << app.get_name() << " --help)\n";
        return kUsage;
    } catch (const CLI::ParseError& e) {
        err << "hexc: " << e.what() << " (see " << app.get_name() << " --help)\n";
        return kUsage;
    }
    return std::nullopt;
}

std::optional<std::pair<int, int>> parseSize(const std::string& text, int least, int most) {
    int width = 0, height = 0;
    char x = 0;
    std::istringstream in(text);
    if (!(in >> width >> x >> height) || x != 'x' || !in.eof()) return std::nullopt;
    if (width < least || height < least || width > most || height > most) return std::nullopt;
    return std::pair{width, height};
}

void writeAtomically(const std::filesystem::path& dir, const std::string& name, const std::string& contents) {
    std::filesystem::create_directories((dir / name).parent_path());  // an engine package's folder (--engine)
    writeFileAtomically(dir / name, [&](const std::filesystem::path& temp) {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out.write(contents.data(), std::streamsize(contents.size()));
        out.close();
        return bool(out);
    });
}

}  // namespace hexc::command
