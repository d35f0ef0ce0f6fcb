#pragma once
// A make-style dependency file, so Make and Ninja rebuild exactly when an input changes.
#include <filesystem>
#include <string>
#include <vector>

namespace hexc::cli {

// "out1 out2: in1 in2\n" and an empty rule "in:" per input (as `gcc -MP` writes), with spaces, '#' and '\'
// escaped by a backslash and '$' doubled, as Make and Ninja read them. Paths are written as given (relative
// stays relative). Throws std::invalid_argument for a path with a line break, which neither can read.
std::string depfileText(const std::vector<std::filesystem::path>& outputs, const std::vector<std::filesystem::path>& inputs);

}  // namespace hexc::cli
