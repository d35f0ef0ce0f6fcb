#pragma once
// What every `hexc` command shares, the command line's (compiler/cli) and `hexc edit`'s (compiler/edit): the exit
// codes, parsing a command's arguments and writing a file atomically.
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hexc/diagnostics.h"

namespace CLI {
class App;
}

namespace hexc::command {

// Exit codes, documented in --help and docs/cli.md.
enum Exit { kOk = 0, kInvalidInput = 1, kUsage = 2, kWriteFailed = 3, kNoVulkan = 4 };

// Parses `args` (without the program and command names) with CLI11 into what `app`'s options are bound to.
// Returns the exit code when the command is done: kOk after printing --help or --version, kUsage after printing
// "hexc: <what is wrong>" to `err`; nullopt when the command should run.
std::optional<int> parseWith(CLI::App& app, const std::vector<std::string>& args, std::ostream& err = std::cerr);

// A `--size WxH`: two whole numbers from `least` to `most`, as (width, height); nullopt when `text` is not that.
std::optional<std::pair<int, int>> parseSize(const std::string& text, int least, int most);

// Writes `contents` to dir/name through a temporary file in the same folder and a rename, so a reader
// never sees a half-written file. Throws std::runtime_error naming the file on failure.
void writeAtomically(const std::filesystem::path& dir, const std::string& name, const std::string& contents);

}  // namespace hexc::command
