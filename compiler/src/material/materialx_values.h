#pragma once
// MaterialX values as JSON, and the value of an input that a graph of constant nodes computes (the `convert` of an
// interface float that feeds `tiling`, as MaterialX tools write it). docs/materialx.md lists the nodes folded.
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>
#include <pugixml.hpp>

namespace hexc::mtlx {

// A MaterialX value string as JSON: a boolean, a number, an array of numbers, else the string itself (which the
// JSON rules then report where a number was expected).
nlohmann::json value(std::string_view s);

// `v` is `count` numbers (one: a number, more: an array).
bool isNumbers(const nlohmann::json& v, size_t count);

// An input's value: its `value`, its nodegraph's interface input (`interfacename`), or the node it is connected to,
// computed when that node and everything it reads are constants. `value` is unset when the input has none (absent:
// the caller's default); otherwise, when it cannot be computed, `blocker` is the element that stops it and `why`
// says what does.
struct Folded {
    std::optional<nlohmann::json> value;
    pugi::xml_node blocker;
    std::string why;
};
Folded fold(pugi::xml_node input);

}  // namespace hexc::mtlx
