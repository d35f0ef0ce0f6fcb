// libFuzzer target: hexc edit's save path, rewriteJsonText, on an arbitrary file text and an arbitrary edit. The input
// is split at its first NUL byte: the text on disk before it, the edited document (parsed as JSON) after it. A result
// is checked against what the rewrite promises (it parses to the edit); a refusal is fine.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "hexc/json_text.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    const size_t cut = input.find('\0');
    if (cut == std::string_view::npos) return 0;
    const std::string_view text = input.substr(0, cut), edit = input.substr(cut + 1);
    if (hexc::nestsTooDeep(edit)) return 0;  // the server refuses such a request before parsing it
    const nlohmann::ordered_json edited = nlohmann::ordered_json::parse(edit, nullptr, false);
    if (edited.is_discarded()) return 0;
    if (const std::optional<std::string> out = hexc::rewriteJsonText(text, edited))
        if (nlohmann::ordered_json::parse(*out, nullptr, false) != edited) std::abort();
    return 0;
}
