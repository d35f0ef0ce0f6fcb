// MaterialX -> Material. The document is read into the JSON material it means, which the JSON parser then
// validates, so both formats follow one set of rules; its diagnostics are moved onto the elements the values came
// from. What is read, and how each MaterialX input maps to a hexc setting, is in docs/materialx.md.
#include <algorithm>
#include <charconv>
#include <map>
#include <set>
#include <tuple>
#include <unordered_map>

#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "common/suggest.h"
#include "common/text.h"
#include "hexc/materialx.h"
#include "material/json_locator.h"
#include "material/materialx_names.h"
#include "material/materialx_nodes.h"
#include "material/materialx_values.h"
#include "material/parse.h"
#include "material/rules.h"

namespace hexc {
namespace {

using mtlx::isNumbers;
using mtlx::value;
using namespace mtlx::nodes;
using nlohmann::json;
using pugi::xml_node;

// Where a value of the JSON material came from: an element's name path and its position in the document.
struct Place {
    std::string path;
    TextPos pos;
};

// What every material of a document shares, made once: a reader per material over it keeps a document of thousands
// linear (a line index of the whole text, or a search of its top level, per material was quadratic).
struct Document {
    Document(std::string_view text, xml_node root) : text(text), root(root), lines(text) {
        for (xml_node n : root.children()) {  // the first element of a name, as a search from the start finds it
            const std::string_view kind = n.name();
            if (kind == "nodegraph") graphs.try_emplace(n.attribute("name").value(), n);
            if (kind != "input" && kind != "output") nodes.try_emplace(n.attribute("name").value(), n);
        }
    }
    std::string_view text;
    xml_node root;
    LineIndex lines;
    std::unordered_map<std::string_view, xml_node> graphs, nodes;  // the top level's nodegraphs, and its nodes, by name
};

class Reader {
public:
    Reader(const Document& doc, const std::filesystem::path& file) : doc_(doc), text_(doc.text), file_(file), root_(doc.root) {}

    // The material a <surfacematerial> means, checked by the JSON rules.
    ParseResult read(xml_node surfacematerial) {
        ParseResult result;
        json m = material(surfacematerial);
        result.diagnostics = std::move(diags_);
        // Without a slot, what the reader said is the whole story (the JSON rules would add "no slots").
        if (hasErrors(result.diagnostics) && m["slots"].empty()) return result;
        ParseResult checked = parseMaterialJson(m.dump(), file_);
        for (const Diagnostic& d : checked.diagnostics) result.diagnostics.push_back(relocate(d));
        // Slots read from one image node (each channel under its own extract) say what is wrong with it once; a set
        // keeps this linear in the diagnostics (a document can hold 80,000).
        std::set<std::tuple<Code, int, int, std::string>> seen;
        Diagnostics once;
        for (Diagnostic& d : result.diagnostics)
            if (seen.emplace(d.code, d.loc.line, d.loc.col, d.message).second) once.push_back(std::move(d));
        result.diagnostics = std::move(once);
        if (!hasErrors(result.diagnostics)) result.material = std::move(checked.material);
        return result;
    }

    // A problem of the whole document, as its only result.
    std::vector<ParseResult> problem(xml_node node, std::string message, std::string hint = {}) {
        report(Code::MaterialXUnsupported, node, std::move(message), std::move(hint));
        return {ParseResult{std::nullopt, std::move(diags_), std::nullopt}};
    }

private:
    // A diagnostic of the JSON rules, moved onto the element its value came from.
    Diagnostic relocate(const Diagnostic& d) const {
        if (d.loc.file != file_.string()) return d;
        std::string pointer = d.path;
        while (!places_.contains(pointer)) {
            const size_t cut = pointer.rfind('/');
            pointer = cut == std::string::npos ? "" : pointer.substr(0, cut);
        }
        const Place& p = places_.at(pointer);
        return Diagnostic::make(d.code, {file_.string(), p.pos.line, p.pos.col}, p.path, d.message, d.hint);
    }

    json material(xml_node material) {
        json m = {{"name", material.attribute("name").value()}, {"slots", json::array()}, {"hextiling", {{"mode", "materialx"}}}};
        material_ = material;
        at("", material);
        at("/name", material, "name");
        at("/hextiling/mode", material);  // MaterialX's meaning, unless a hexc_mode attribute says otherwise
        hexcAttributes(material, mtlx::kMaterialKeys, [&](const std::string& key, const json& v, const char* attr) {
            const bool top = key == "template" || key == "pack";  // top-level keys of the material JSON
            const std::string p = top ? "/" + key : "/hextiling/" + key;
            (top ? m[key] : m["hextiling"][key]) = v;
            at(p, material, attr);
        });
        for (xml_node input : material.children("input")) {
            const std::string name = input.attribute("name").value();
            if (name != "surfaceshader" && name != "displacementshader") {
                report(Code::MaterialXUnsupported, input, "unknown <surfacematerial> input `" + name + "`",
                       "expected surfaceshader or displacementshader");
                continue;
            }
            if (!connected(input))
                report(Code::MaterialXUnsupported, input, "`" + name + "` is not connected to a shader", "give it a nodename");
            else if (xml_node shader = source(input))
                surface(shader, m);
        }
        if (m["slots"].empty()) at("/slots", material);
        mtlx::uniqueSlotNames(m["slots"]);
        return m;
    }

    // Each input of a surface (or displacement) shader fed by a texture node is a slot; inputs given as values
    // are the template's business, said once.
    void surface(xml_node shader, json& m) {
        const std::string category = shader.name();
        static const std::vector<std::string> kShaders = {"standard_surface", "open_pbr_surface", "gltf_pbr", "UsdPreviewSurface",
                                                          "displacement"};
        if (std::find(kShaders.begin(), kShaders.end(), category) == kShaders.end()) {
            report(Code::MaterialXUnsupported, shader, "shader <" + category + "> is not supported",
                   "expected <standard_surface>, <open_pbr_surface>, <gltf_pbr>, <UsdPreviewSurface> or <displacement>");
            return;
        }
        std::string values;
        for (xml_node input : shader.children("input")) {
            if (!connected(input)) {
                values += std::string(values.empty() ? "" : ", ") + input.attribute("name").value();
                continue;
            }
            xml_node node = source(input);
            if (!node) continue;
            const std::string name = mtlx::slotName(category, input.attribute("name").value());
            if (auto fed = fed_.find(node); fed != fed_.end())
                report(Code::MaterialXIgnored, input,
                       "`" + std::string(input.attribute("name").value()) + "` reads " + namePath(node) + " like slot `" + fed->second +
                           "`: one slot serves both",
                       "a template reads it as `" + fed->second + "`");
            else
                fed_[node] = name, slot(node, name, m);
        }
        if (!values.empty())
            report(Code::MaterialXIgnored, shader,
                   "inputs given as values are left to the template (hexc compiles the ones fed by images): " + values);
    }

    // The slot for a texture node, through the `extract` (a channel) or `normalmap` node around it.
    void slot(xml_node node, const std::string& name, json& m) {
        const std::string p = pointerAppend("/slots", m["slots"].size());
        json s = {{"name", name}};
        at(p, node);
        at(p + "/name", node);
        std::string category = node.name();
        if (!hasNodedef(node)) return;
        if (category == "convert") {  // the colour of a color4 image: its rgb, which a colour slot is
            fixedInputs(node, {"in"});
            if (!(node = inner(node))) return;
            category = node.name();
        }
        std::optional<int> channel;
        const bool normalmap = category == "normalmap";
        if (category == "extract" || normalmap) {
            if (category == "extract") channel = extractIndex(node, p);
            fixedInputs(node, normalmap ? std::vector<std::string>{"in", "scale", "space"} : std::vector<std::string>{"in", "index"});
            if (!(node = inner(node))) return;
            category = node.name();
        }
        if (kConstantFactors.contains(category)) {
            report(Code::MaterialXUnsupported, node, "a <" + category + "> between the image and the shader: hexc compiles the image alone",
                   "connect the shader input to the image node, and apply the " + std::string(kConstantFactors.at(category)) +
                       " in a hexc_template of your own or bake it into the texture");
            return;
        }
        if (!kNodeInputs.contains(category)) {
            report(Code::MaterialXUnsupported, node, "node <" + category + "> cannot feed a slot",
                   "hexc compiles image, tiledimage, hextiledimage and hextilednormalmap nodes, optionally under extract, normalmap or a "
                   "convert to color3");
            return;
        }
        s["kind"] = normalmap || category == "hextilednormalmap"                             ? "normal"
                    : channel || std::string_view(node.attribute("type").value()) == "float" ? "scalar"
                                                                                             : "color";
        if (channel) s["channel"] = std::string(1, "rgba"[*channel]);
        texture(node, s, p);
        m["slots"].push_back(std::move(s));
    }

    // The node a convert, extract or normalmap node reads.
    xml_node inner(xml_node node) {
        xml_node in = node.find_child_by_attribute("input", "name", "in");
        if (!in || !connected(in)) {
            report(Code::MaterialXUnsupported, node, "<" + std::string(node.name()) + "> without a connected `in` input");
            return {};
        }
        xml_node from = source(in);
        return from && hasNodedef(from) ? from : xml_node();
    }

    // A node MaterialX defines for its type (a slot's nodes; the category itself is checked where it is read).
    bool hasNodedef(xml_node node) {
        auto types = kNodeTypes.find(std::string_view(node.name()));
        const std::string type = node.attribute("type").value();
        if (types == kNodeTypes.end() || std::find(types->second.begin(), types->second.end(), type) != types->second.end()) return true;
        std::string expected;
        for (const std::string& t : types->second) expected += (expected.empty() ? "" : ", ") + t;
        report(
            Code::MaterialXUnsupported, node, "MaterialX has no <" + std::string(node.name()) + "> of type `" + type + "`",
            "expected type " + expected +
                (type == "float" && std::string_view(node.name()) == "hextiledimage" ? "; an <extract> of a channel gives a float" : ""));
        return false;
    }

    std::optional<int> extractIndex(xml_node node, const std::string& p) {
        xml_node index = node.find_child_by_attribute("input", "name", "index");
        json v = inputValue(index, 0.0);
        if (v.is_number() && v.get<double>() >= 0 && v.get<double>() <= 3 && v.get<double>() == std::floor(v.get<double>()))
            return int(v.get<double>());
        report(Code::MaterialXUnsupported, index ? index : node, "<extract> `index` must be a channel, 0 to 3");
        at(p + "/channel", node);
        return std::nullopt;
    }

    void texture(xml_node node, json& s, const std::string& p);
    void hexSettings(xml_node node, const std::map<std::string, xml_node>& inputs, json& s, const std::string& p);
    void hexTransforms(const std::map<std::string, xml_node>& inputs, xml_node node, json& hex, const std::string& p);
    void colorSpace(xml_node from, json& s, const std::string& p);
    std::map<std::string, xml_node> inputsOf(xml_node node);
    void fixedInputs(xml_node node, const std::vector<std::string>& known);
    void texcoord(xml_node input);
    void luma(xml_node input, xml_node node, json& hex, const std::string& h);
    json inputValue(xml_node input, const json& fallback);
    template <typename F>
    void hexcAttributes(xml_node node, const std::vector<std::string>& keys, F&& each);
    xml_node source(xml_node input);
    static bool connected(xml_node input) {
        return input.attribute("nodename") || input.attribute("nodegraph") || input.attribute("output");
    }
    static std::string inherited(xml_node node, const char* attribute) {
        for (; node; node = node.parent())
            if (pugi::xml_attribute a = node.attribute(attribute)) return a.value();
        return {};
    }

    std::string namePath(xml_node node) const {
        std::string path;
        for (; node && node != root_; node = node.parent()) path = node.attribute("name").value() + (path.empty() ? "" : "/" + path);
        return path;
    }
    Place place(xml_node node, const char* attribute = nullptr) const {
        size_t offset = node.offset_debug() < 0 ? 0 : size_t(node.offset_debug());
        if (offset > 0 && offset <= text_.size() && text_[offset - 1] == '<') --offset;  // pugixml points past the `<`
        // The last element's path and attribute offsets are kept: with many attributes, finding each (or `name`) for
        // every report of the element would be quadratic.
        if (node != last_) last_ = node, lastPath_ = namePath(node), lastAttributes_ = xmlAttributeOffsets(text_, offset);
        if (attribute)
            if (auto a = lastAttributes_.find(std::string_view(attribute)); a != lastAttributes_.end()) offset = a->second;
        const bool own = attribute && std::string_view(attribute) != "value";  // an input's value is the input
        return {lastPath_ + (own ? "/@" + std::string(attribute) : ""), doc_.lines.at(offset)};
    }
    void at(const std::string& pointer, xml_node node, const char* attribute = nullptr) { places_[pointer] = place(node, attribute); }
    void report(Code code, xml_node node, std::string message, std::string hint = {}) {
        Place p = place(node);
        diags_.push_back(Diagnostic::make(code, {file_.string(), p.pos.line, p.pos.col}, p.path, std::move(message), std::move(hint)));
    }

    const Document& doc_;
    std::string_view text_;
    mutable xml_node last_;  // place()'s last element, its path and attribute offsets
    mutable std::string lastPath_;
    mutable std::map<std::string, size_t, std::less<>> lastAttributes_;
    std::filesystem::path file_;
    xml_node root_;
    std::map<std::string, Place> places_;  // JSON pointer -> where its value came from
    xml_node material_;                    // the <surfacematerial> being read
    std::map<xml_node, std::string> fed_;  // node read into a slot -> the slot's name
    Diagnostics diags_;
};

// The node an input is connected to: `nodename` in the input's own graph, or a nodegraph's output.
xml_node Reader::source(xml_node input) {
    xml_node graph = input.parent().parent();
    std::string name = input.attribute("nodename").value();
    if (pugi::xml_attribute ng = input.attribute("nodegraph")) {
        const auto found = doc_.graphs.find(ng.value());
        graph = found == doc_.graphs.end() ? xml_node() : found->second;
        if (!graph) {
            report(Code::UnknownReference, input, "no <nodegraph> named `" + std::string(ng.value()) + "`");
            return {};
        }
        const char* output = input.attribute("output").value();
        xml_node out = *output ? graph.find_child_by_attribute("output", "name", output) : graph.child("output");
        if (!out) {
            report(Code::UnknownReference, input, "nodegraph `" + std::string(ng.value()) + "` has no output `" + output + "`");
            return {};
        }
        name = out.attribute("nodename").value();
    } else if (name.empty()) {
        report(Code::MaterialXUnsupported, input, "an input connected by `output` alone is not supported", "connect it with nodename");
        return {};
    }
    if (graph == root_) {
        if (const auto found = doc_.nodes.find(name); found != doc_.nodes.end()) return found->second;
    } else {
        for (xml_node n : graph.children())
            if (std::string_view(n.name()) != "input" && std::string_view(n.name()) != "output" && name == n.attribute("name").value())
                return n;
    }
    report(Code::UnknownReference, input, "no node named `" + name + "` in " + (graph == root_ ? "the document" : namePath(graph)));
    return {};
}

// The node's inputs by name, each unknown one and each set to what hexc cannot do reported.
std::map<std::string, xml_node> Reader::inputsOf(xml_node node) {
    const std::vector<std::string>& known = kNodeInputs.find(std::string_view(node.name()))->second;
    fixedInputs(node, known);
    std::map<std::string, xml_node> inputs;
    for (xml_node input : node.children("input"))
        if (std::find(known.begin(), known.end(), input.attribute("name").value()) != known.end())
            inputs[input.attribute("name").value()] = input;
    return inputs;
}

void Reader::fixedInputs(xml_node node, const std::vector<std::string>& known) {
    const std::string category = node.name();
    for (xml_node input : node.children("input")) {
        const std::string name = input.attribute("name").value();
        if (std::find(known.begin(), known.end(), name) == known.end()) {
            std::string hint;
            if (auto best = closestMatch(name, known)) hint = "did you mean `" + *best + "`?";
            report(Code::MaterialXUnsupported, input, "<" + category + "> has no input `" + name + "` hexc knows", hint);
            continue;
        }
        if (name == "texcoord") {
            texcoord(input);
            continue;
        }
        if (name == "in") continue;  // normalmap's image, read as the slot's texture node
        // A missing interface input is inputValue's to report (HX113); anything else that stops folding, here.
        if (mtlx::Folded f = mtlx::fold(input); f.blocker && !(f.blocker == input && input.attribute("interfacename"))) {
            report(Code::MaterialXUnsupported, input, "`" + name + "` is not a constant: " + namePath(f.blocker) + ": " + f.why,
                   "hexc reads texture settings as values: constants, interface inputs, and convert, combine2-4, add, subtract, "
                   "multiply or divide of those");
            continue;
        }
        if ((name == "normal" || name == "tangent" || name == "bitangent") && category == "hextilednormalmap")
            report(Code::MaterialXUnsupported, input, "`" + name + "` is the template's: hexc returns the tangent-space result");
        for (const Fixed& f : kFixed)
            if ((f.category.empty() || f.category == category) && f.input == name && inputValue(input, value(f.value)) != value(f.value))
                report(Code::MaterialXUnsupported, input, "`" + name + "` must be \"" + std::string(f.value) + "\": " + std::string(f.why));
    }
}

// The mesh uv, which is what the template passes: a <texcoord> node of index 0 (or none, MaterialX's default).
void Reader::texcoord(xml_node input) {
    xml_node from = connected(input) ? source(input) : xml_node();
    if (!from && connected(input)) return;  // source() said why
    xml_node index = from.find_child_by_attribute("input", "name", "index");
    if (!from || std::string_view(from.name()) != "texcoord" || (index && inputValue(index, 0.0) != json(0.0)))
        report(Code::MaterialXUnsupported, input, "`texcoord` must come from a <texcoord> node of index 0",
               "hexc's template passes the mesh uv (or the triplanar position)");
}

// An input's value (through `interfacename` to its nodegraph's input, or computed from the constant nodes it is
// connected to), or `fallback` when it has none; fixedInputs reports one that cannot be computed.
json Reader::inputValue(xml_node input, const json& fallback) {
    if (!input) return fallback;
    if (pugi::xml_attribute name = input.attribute("interfacename");
        name && !input.parent().parent().find_child_by_attribute("input", "name", name.value())) {
        report(Code::UnknownReference, input, "no nodegraph input `" + std::string(name.value()) + "`");
        return fallback;
    }
    return mtlx::fold(input).value.value_or(fallback);
}

template <typename F>
void Reader::hexcAttributes(xml_node node, const std::vector<std::string>& keys, F&& each) {
    for (pugi::xml_attribute a : node.attributes()) {
        std::string_view name = a.name();
        if (!name.starts_with("hexc_")) continue;
        const std::string key(name.substr(5));
        if (std::find(keys.begin(), keys.end(), key) != keys.end()) {
            each(key, value(a.value()), a.name());
            continue;
        }
        std::string hint;
        if (auto best = closestMatch(key, keys)) hint = "did you mean `hexc_" + *best + "`?";
        report(Code::MaterialXUnsupported, node, "unknown hexc attribute `" + std::string(name) + "` on <" + node.name() + ">", hint);
    }
}

// The slot's texture, colour space and hex-tiling settings: the node's inputs, then its hexc_* attributes.
void Reader::texture(xml_node node, json& s, const std::string& p) {
    const std::map<std::string, xml_node> inputs = inputsOf(node);
    auto file = inputs.find("file");
    if (file != inputs.end()) {  // without one, the JSON rules report the missing `texture` at the node
        json v = inputValue(file->second, "");
        s["texture"] = v.is_string() ? json(inherited(file->second, "fileprefix") + v.get<std::string>()) : v;
        at(p + "/texture", file->second, "value");
    }
    colorSpace(file != inputs.end() ? file->second : node, s, p);
    hexSettings(node, inputs, s, p);
    hexcAttributes(
        node,
        [] {
            std::vector<std::string> keys = mtlx::kNodeKeys;
            keys.insert(keys.end(), mtlx::kSlotKeys.begin(), mtlx::kSlotKeys.end());
            return keys;
        }(),
        [&](const std::string& key, const json& v, const char* attr) {
            std::string pointer = p + "/hextiling/" + key;
            if (key == "flip_y") {
                s["flip_y"] = v;
                pointer = p + "/flip_y";
            } else if (key.starts_with("height_blend")) {
                const char* field = key == "height_blend" ? "slot" : "width";
                s["height_blend"][field] = v;
                pointer = p + "/height_blend/" + field;
            } else {
                s["hextiling"][key] = v;
            }
            at(pointer, node, attr);
        });
}

// MaterialX names colour spaces; an image's is its file input's, or inherited from the elements around it.
void Reader::colorSpace(xml_node from, json& s, const std::string& p) {
    const std::string space = inherited(from, "colorspace");
    at(p + "/colorspace", from, "colorspace");
    if (space == "srgb_texture") {
        s["colorspace"] = "srgb";  // on a normal map, the JSON rules report it
    } else if (space.empty() || space == "none" || space == "lin_rec709" || space == "lin_srgb" || space == "raw" || space == "Raw") {
        if (s["kind"] != "normal") s["colorspace"] = "linear";
    } else {
        report(Code::MaterialXUnsupported, from, "colour space `" + space + "` is not supported",
               "expected srgb_texture, or lin_rec709, raw or none for data stored as is");
    }
}

void Reader::hexSettings(xml_node node, const std::map<std::string, xml_node>& inputs, json& s, const std::string& p) {
    const std::string category = node.name(), h = p + "/hextiling";
    json& hex = s["hextiling"];
    auto set = [&](const char* key, const char* input, const json& fallback) {
        auto it = inputs.find(input);
        hex[key] = inputValue(it == inputs.end() ? xml_node() : it->second, fallback);
        at(h + "/" + key, it == inputs.end() ? node : it->second, it == inputs.end() ? nullptr : "value");
    };
    if (category == "image" || category == "tiledimage") {
        hex["enabled"] = false;
        at(h + "/enabled", node);
        if (category == "tiledimage") set("tiling", "uvtiling", json::array({1.0, 1.0}));
        return;
    }
    set("tiling", "tiling", json::array({1.0, 1.0}));
    set("falloff", "falloff", 0.5);
    if (category == "hextiledimage") {
        set("falloffcontrast", "falloffcontrast", 0.5);
        if (inputs.contains("lumacoeffs")) luma(inputs.at("lumacoeffs"), node, hex, h);
    } else {
        auto flip = inputs.find("flip_g");
        s["flip_y"] = inputValue(flip == inputs.end() ? xml_node() : flip->second, false);
        at(p + "/flip_y", flip == inputs.end() ? node : flip->second, "value");
    }
    hexTransforms(inputs, node, hex, h);
}

// MaterialX draws a tile's angle as A + (B - A) u R, its scale as 1 + (lo + (hi - lo) u - 1) S and its offset as
// olo + (ohi - olo) u O; hexc as (a + (b - a) u) rotation, a + (b - a) u and u offset. The same functions of u:
void Reader::hexTransforms(const std::map<std::string, xml_node>& inputs, xml_node node, json& hex, const std::string& h) {
    auto get = [&](const char* name, const json& fallback, const char* key) {
        auto it = inputs.find(name);
        at(h + "/" + key, it == inputs.end() ? node : it->second, it == inputs.end() ? nullptr : "value");
        return inputValue(it == inputs.end() ? xml_node() : it->second, fallback);
    };
    const json R = get("rotation", 1.0, "rotation"), AB = get("rotationrange", {0.0, 360.0}, "rotationrange");
    if (!isNumbers(R, 1) || !isNumbers(AB, 2)) {
        hex["rotation"] = R, hex["rotationrange"] = AB;  // the JSON rules say what is wrong
    } else if (double r = R.get<double>(), a = AB[0].get<double>(), b = AB[1].get<double>(); r == 0) {
        hex["rotation"] = a == 0 ? 0.0 : 1.0;  // every angle is A
        if (a != 0) hex["rotationrange"] = {a, a};
    } else {
        hex["rotation"] = r, hex["rotationrange"] = r == 1 ? AB : json{a / r, a / r + (b - a)};
    }
    const json S = get("scale", 1.0, "scale"), LH = get("scalerange", {0.5, 2.0}, "scalerange");
    if (isNumbers(S, 1) && isNumbers(LH, 2) && S != json(1.0))
        hex["scalerange"] = {1 + (LH[0].get<double>() - 1) * S.get<double>(), 1 + (LH[1].get<double>() - 1) * S.get<double>()};
    else
        hex["scalerange"] = isNumbers(LH, 2) ? LH : S;
    const json O = get("offset", 1.0, "offset"), OR = get("offsetrange", {0.0, 1.0}, "offsetrange");
    if (isNumbers(OR, 2) && OR[0] != json(0.0))
        report(Code::MaterialXUnsupported, inputs.contains("offsetrange") ? inputs.at("offsetrange") : node,
               "`offsetrange` must start at 0: hexc offsets tiles by u * offset");
    hex["offset"] = isNumbers(O, 1) && isNumbers(OR, 2) && OR[1] != json(1.0) ? json(O.get<double>() * OR[1].get<double>()) : O;
}

// MaterialX mode weighs colours by `lumacoeffs`; hexc's own modes by Rec. 601 luma (paper Eq. 4), whatever the
// document's working space.
void Reader::luma(xml_node input, xml_node node, json& hex, const std::string& h) {
    json v = inputValue(input, json());
    const char* mode =
        node.attribute("hexc_mode") ? node.attribute("hexc_mode").value() : material_.attribute("hexc_mode").as_string("materialx");
    if (std::string_view(mode) == "materialx") {
        hex["lumacoeffs"] = v;
        at(h + "/lumacoeffs", input, "value");
        return;
    }
    for (size_t i = 0; isNumbers(v, 3) && i < 3; ++i)
        if (std::fabs(v[i].get<double>() - mtlx::kLuma[i]) > 5e-4) v = json();
    if (!isNumbers(v, 3))
        report(Code::MaterialXIgnored, input,
               "hexc weighs colour samples by Rec. 601 luma (0.299, 0.587, 0.114); `lumacoeffs` is not used");
}

}  // namespace

bool isMaterialXFile(const std::filesystem::path& file) { return lowerCase(file.extension().string()) == ".mtlx"; }

namespace {

// Every <surfacematerial> of a document, or the one problem that stops reading it; with `one`, a document of
// several materials is such a problem.
std::vector<ParseResult> readDocument(std::string_view text, const std::filesystem::path& file, bool one) {
    auto failed = [&](Code code, size_t offset, std::string message) {
        TextPos p = textPosition(text, offset);
        return std::vector<ParseResult>{
            {std::nullopt, {Diagnostic::make(code, {file.string(), p.line, p.col}, "", std::move(message))}, std::nullopt}};
    };
    if (std::optional<size_t> at = invalidUtf8(text))
        return failed(Code::XmlSyntax, *at, "invalid UTF-8 (byte 0x" + hexByte(text[*at]) + "); MaterialX documents are UTF-8");
    pugi::xml_document doc;
    pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!parsed)
        return failed(Code::XmlSyntax, size_t(std::max<ptrdiff_t>(parsed.offset, 0)), std::string("invalid XML: ") + parsed.description());
    xml_node root = doc.document_element();
    const Document document(text, root);
    if (std::string_view(root.name()) != "materialx")
        return Reader(document, file).problem(root, "expected a <materialx> document, got <" + std::string(root.name()) + ">");
    std::vector<xml_node> materials;
    std::string names;
    for (xml_node n : root.children("surfacematerial")) {
        materials.push_back(n);
        names += std::string(names.empty() ? "" : ", ") + "`" + n.attribute("name").value() + "`";
    }
    if (materials.empty()) return Reader(document, file).problem(root, "no <surfacematerial>: the document holds no material");
    if (one && materials.size() > 1)
        return Reader(document, file)
            .problem(root, "several <surfacematerial> elements (" + names + ") where one material is read",
                     "`hexc DOCUMENT.mtlx -o DIR` compiles them all; split the document for render, preview, export and scenes");
    std::vector<ParseResult> out;
    const SharedTextureFiles shared;  // the materials' textures, each read once
    for (xml_node m : materials) out.push_back(Reader(document, file).read(m));
    return out;
}

}  // namespace

namespace {
// readDocument, or HX901 when the document needs more memory than the process has.
std::vector<ParseResult> readWithinMemory(std::string_view text, const std::filesystem::path& file, bool one) {
    try {
        return readDocument(text, file, one);
    } catch (const std::bad_alloc&) {
        return {ParseResult{std::nullopt, {outOfMemoryReading(file.string(), text.size())}, std::nullopt}};
    }
}
}  // namespace

ParseResult parseMaterialX(std::string_view text, const std::filesystem::path& file) {
    return std::move(readWithinMemory(text, file, true).front());
}

std::vector<ParseResult> parseMaterialXDocument(std::string_view text, const std::filesystem::path& file) {
    return readWithinMemory(text, file, false);
}

}  // namespace hexc
