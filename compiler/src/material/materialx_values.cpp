// MaterialX values and constant folding (materialx_values.h). Folding follows MaterialX's node definitions
// (libraries/stdlib/stdlib_defs.mtlx): absent inputs take the nodedef's defaults, a float operand of a vector
// operation applies to every component.
#include "material/materialx_values.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <vector>

namespace hexc::mtlx {
namespace {

using nlohmann::json;
using pugi::xml_node;

// "0.5, 2" -> numbers; nullopt when any item is not a finite number.
std::optional<std::vector<double>> numbers(std::string_view s) {
    std::vector<double> out;
    for (size_t begin = 0; begin <= s.size();) {
        size_t end = std::min(s.find(',', begin), s.size());
        std::string_view item = s.substr(begin, end - begin);
        while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
        while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
        double x = 0;
        auto [ptr, ec] = std::from_chars(item.data(), item.data() + item.size(), x);
        if (item.empty() || ec != std::errc() || ptr != item.data() + item.size() || !std::isfinite(x)) return std::nullopt;
        out.push_back(x);
        begin = end + 1;
    }
    return out;
}

// Components of a MaterialX type that folding handles; 0 for any other.
size_t components(std::string_view type) {
    static const std::map<std::string_view, size_t> kSizes = {{"float", 1},  {"integer", 1}, {"vector2", 2}, {"vector3", 3},
                                                              {"color3", 3}, {"vector4", 4}, {"color4", 4}};
    auto it = kSizes.find(type);
    return it == kSizes.end() ? 0 : it->second;
}

std::vector<double> asVector(const json& v) {
    if (v.is_number()) return {v.get<double>()};
    std::vector<double> out;
    for (const json& x : v) out.push_back(x.get<double>());
    return out;
}

json asJson(const std::vector<double>& v) { return v.size() == 1 ? json(v.front()) : json(v); }

// The nodes folded, each with its inputs in order and their nodedef defaults.
struct Operation {
    std::vector<std::pair<const char*, double>> inputs;
    double (*apply)(double, double);
};
const std::map<std::string_view, Operation> kOperations = {
    {"add", {{{"in1", 0}, {"in2", 0}}, [](double a, double b) { return a + b; }}},
    {"subtract", {{{"in1", 0}, {"in2", 0}}, [](double a, double b) { return a - b; }}},
    {"multiply", {{{"in1", 0}, {"in2", 1}}, [](double a, double b) { return a * b; }}},
    {"divide", {{{"in1", 0}, {"in2", 1}}, [](double a, double b) { return a / b; }}},
    {"constant", {{{"value", 0}}, nullptr}},
    {"convert", {{{"in", 0}}, nullptr}},
    {"combine2", {{{"in1", 0}, {"in2", 0}}, nullptr}},
    {"combine3", {{{"in1", 0}, {"in2", 0}, {"in3", 0}}, nullptr}},
    {"combine4", {{{"in1", 0}, {"in2", 0}, {"in3", 0}, {"in4", 0}}, nullptr}},
};

class Folder {
public:
    Folded input(xml_node input, int depth) {
        if (depth > kMaxDepth) return {std::nullopt, input, "the nodes feeding it form a cycle or a chain deeper than 32"};
        if (pugi::xml_attribute name = input.attribute("interfacename")) {
            xml_node outer = input.parent().parent().find_child_by_attribute("input", "name", name.value());
            if (!outer) return {std::nullopt, input, "no nodegraph input `" + std::string(name.value()) + "`"};
            return this->input(outer, depth + 1);
        }
        if (pugi::xml_attribute v = input.attribute("value")) {
            const std::string_view type = input.attribute("type").value();
            return {type == "filename" || type == "string" ? json(std::string(v.value())) : value(v.value()), {}, {}};
        }
        if (input.attribute("nodegraph") || input.attribute("output"))
            return {std::nullopt, input, "it is connected to a nodegraph output, which hexc does not follow for a setting"};
        pugi::xml_attribute nodename = input.attribute("nodename");
        if (!nodename) return {};
        for (xml_node n : input.parent().parent().children())
            if (std::string_view(n.name()) != "input" && std::string_view(n.name()) != "output" &&
                nodename.value() == std::string_view(n.attribute("name").value()))
                return node(n, depth + 1);
        return {std::nullopt, input, "no node named `" + std::string(nodename.value()) + "`"};
    }

private:
    static constexpr int kMaxDepth = 32;

    Folded node(xml_node n, int depth) {
        const std::string category = n.name();
        auto op = kOperations.find(category);
        const size_t size = components(n.attribute("type").value());
        if (op == kOperations.end() || size == 0)
            return {std::nullopt, n, "<" + category + " type=\"" + n.attribute("type").value() + "\"> is not a constant hexc can compute"};
        std::vector<std::vector<double>> args;
        for (const auto& [name, fallback] : op->second.inputs) {
            xml_node in = n.find_child_by_attribute("input", "name", name);
            Folded f = in ? input(in, depth) : Folded{};
            if (f.blocker) return f;
            json v = f.value.value_or(json(fallback));
            if (!v.is_number() &&
                !(v.is_array() && !v.empty() && std::all_of(v.begin(), v.end(), [](const json& x) { return x.is_number(); })))
                return {std::nullopt, in, "`" + std::string(name) + "` is not a number or a vector"};
            args.push_back(asVector(v));
        }
        std::vector<double> out;
        if (op->second.apply) {
            const std::vector<double>&a = args[0], &b = args[1];
            if (a.size() != b.size() && a.size() != 1 && b.size() != 1) return {std::nullopt, n, "its operands differ in size"};
            for (size_t i = 0; i < std::max(a.size(), b.size()); ++i)
                out.push_back(op->second.apply(a[a.size() == 1 ? 0 : i], b[b.size() == 1 ? 0 : i]));
        } else {
            for (const std::vector<double>& a : args) out.insert(out.end(), a.begin(), a.end());
            if (category == "convert" && out.size() == 1) out.assign(size, out.front());  // a float fills every component
        }
        if (out.size() != size) return {std::nullopt, n, "it computes " + std::to_string(out.size()) + " components for its type"};
        return {asJson(out), {}, {}};
    }
};

}  // namespace

json value(std::string_view s) {
    if (s == "true" || s == "false") return s == "true";
    if (std::optional<std::vector<double>> v = numbers(s)) return v->size() == 1 ? json(v->front()) : json(*v);
    return std::string(s);
}

bool isNumbers(const json& v, size_t count) {
    return count == 1 ? v.is_number()
                      : v.is_array() && v.size() == count && std::all_of(v.begin(), v.end(), [](const json& x) { return x.is_number(); });
}

Folded fold(xml_node input) { return Folder().input(input, 0); }

}  // namespace hexc::mtlx
