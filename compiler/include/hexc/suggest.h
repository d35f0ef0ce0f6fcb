#pragma once
// The "did you mean" of every diagnostic and of the command line.
#include <optional>
#include <string>
#include <vector>

namespace hexc {

// The candidate closest to `word` by edit distance, if close enough to be a plausible typo
// (at most a third of the word's length, and at least 1, edits).
std::optional<std::string> closestMatch(const std::string& word, const std::vector<std::string>& candidates);

// `s` with its ASCII letters in lower case: how names are compared where case does not count.
std::string lowerCase(std::string s);

}  // namespace hexc
