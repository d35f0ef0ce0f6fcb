#pragma once
// Writing an edited JSON document (a material) back into its file's text, keeping what did not change as written:
// the keys' order, the spacing and line breaks, the numbers' spelling (`1.0` stays `1.0`, `4` does not become `4.0`).
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace hexc {

// Whether a JSON text nests deeper than materials may (32 levels), found by a scan that does not parse: untrusted text
// (a request's body) is checked with it before it is parsed, since nlohmann's comparisons and dumps recurse per level.
bool nestsTooDeep(std::string_view text);

// `text` rewritten so that it parses to `edited`: every value equal to the one in `text` (numerically for numbers) keeps
// its bytes, a changed value is replaced in place, a member `edited` adds goes after its object's last one in the style
// of its siblings, a removed member goes with its comma. Nullopt, with the reason in *whyNot, when `text` is not JSON
// or either nests deeper than materials may.
std::optional<std::string> rewriteJsonText(std::string_view text, const nlohmann::ordered_json& edited, std::string* whyNot = nullptr);

}  // namespace hexc
