// `layers` and `layer_blend` of a material document -> Material::layers (material/layers.h).
#include <algorithm>
#include <map>
#include <optional>

#include "common/suggest.h"
#include "hexc/image.h"
#include "material/layers.h"
#include "material/names.h"

namespace hexc {
namespace {

const std::vector<std::string> kLayerKeys = {"name", "hextiling", "slots"};
const std::vector<std::string> kLayerBlendKeys = {"weights", "splat", "mode", "height", "width", "skip_below", "arrays"};
const std::vector<std::string> kLayerArrays = {"auto", "off"};

// [a-z][a-z0-9]{0,15}: no `_`, so that <layer>_<role> splits at its first `_` and two layers' slots never collide.
bool isLayerName(const std::string& name) {
    auto lowerOrDigit = [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'); };
    return !name.empty() && name.size() <= 16 && name[0] >= 'a' && name[0] <= 'z' && std::all_of(name.begin(), name.end(), lowerOrDigit);
}

class LayerValidator : public JsonRules {
public:
    LayerValidator(const JsonRules& rules, const LayerReaders& read) : JsonRules(rules), read_(read) { diags.clear(); }

    void run(const json& doc, Material& m) {
        if (!doc.contains("layers")) {
            report(Code::MisplacedKey, "/layer_blend", "`layer_blend` blends `layers`, and this material has none", {}, true);
            return;
        }
        Layers layers;
        readLayers(doc["layers"], m, layers);
        for (size_t r = 0; r < layers.roles.size(); ++r) ktx2Array(m, layers, r);
        if (requireKey(doc, "", "layer_blend", "how the layers blend: splat maps and mode")) layerBlend(doc["layer_blend"], m, layers);
        for (const auto& [pointer, role] : heightRefs_) heightBlendRole(pointer, role, layers);
        m.layers = std::move(layers);
    }

private:
    void readLayers(const json& v, Material& m, Layers& layers) {
        if (!v.is_array()) {
            report(Code::WrongType, "/layers", "expected an array of layers, got " + typeName(v));
            return;
        }
        declared_ = v.size();
        const std::string count = "expected 1 to " + std::to_string(Layers::kMaxLayers) + " layers, got " + std::to_string(v.size());
        if (v.empty())
            report(Code::WrongCount, "/layers", count,
                   "give `layers` a layer {\"name\", \"slots\"}, or leave out `layers` and `layer_blend` for a material of its "
                   "`slots` alone");
        else if (v.size() > Layers::kMaxLayers)
            report(Code::WrongCount, "/layers", count,
                   "one shader blends at most " + std::to_string(Layers::kMaxLayers) +
                       " layers (two splat maps): split the terrain into materials of at most " + std::to_string(Layers::kMaxLayers) +
                       " layers each, or merge layers");
        for (size_t i = 0; i < v.size() && i < Layers::kMaxLayers; ++i) layer(v[i], pointerAppend("/layers", i), m, layers);
    }

    void layer(const json& v, const std::string& pointer, Material& m, Layers& layers) {
        if (!v.is_object()) {
            report(Code::WrongType, pointer, "expected a layer object {\"name\", \"hextiling\", \"slots\"}, got " + typeName(v));
            return;
        }
        checkKeys(v, pointer, kLayerKeys);
        Layers::Layer l;
        if (requireKey(v, pointer, "name", "a string")) l.name = string(v["name"], pointer + "/name");
        if (v.contains("name") && v["name"].is_string() && !isLayerName(l.name)) {
            report(Code::InvalidName, pointer + "/name",
                   "expected a layer name of 1-16 lower-case letters and digits, got \"" + l.name + "\"",
                   "its slots become <layer>_<role>");
            l.name.clear();
        }
        for (const Layers::Layer& other : layers.layers)
            if (!l.name.empty() && other.name == l.name)
                report(Code::DuplicateName, pointer + "/name", "duplicate layer name \"" + l.name + "\"");
        HexTiling hex = m.hex;
        if (v.contains("hextiling")) read_.hex(v["hextiling"], pointer + "/hextiling", hex);
        if (requireKey(v, pointer, "slots", "an array of the layer's slots")) layerSlots(v["slots"], pointer + "/slots", hex, m, layers, l);
        layers.layers.push_back(std::move(l));
    }

    void layerSlots(const json& v, const std::string& pointer, const HexTiling& hex, Material& m, Layers& layers, Layers::Layer& l) {
        if (!v.is_array() || v.empty()) {
            report(Code::WrongType, pointer, "expected a non-empty array of slots, got " + typeName(v));
            return;
        }
        if (v.size() > kMaxTextures) {
            report(Code::WrongCount, pointer, "expected 1 to " + std::to_string(kMaxTextures) + " slots, got " + std::to_string(v.size()));
            return;
        }
        const bool first = layers.layers.empty();
        l.slots.assign(layers.roles.size(), SIZE_MAX);
        bool misnamed = false;
        for (size_t i = 0; i < v.size(); ++i) {
            const std::string p = pointerAppend(pointer, i);
            Slot s = read_.slot(v[i], p, hex);
            if (s.name.empty()) continue;
            slotRules(s, p);
            if (first) {
                layers.roles.push_back({s.name, s.kind, {}, {}});
                l.slots.push_back(SIZE_MAX);
            }
            const size_t role = roleIndex(layers, s, p);
            if (role == SIZE_MAX) {
                misnamed = true;
                continue;
            }
            if (l.slots[role] != SIZE_MAX) {
                report(Code::DuplicateName, p + "/name", "duplicate slot name \"" + s.name + "\" in this layer");
                continue;
            }
            for (const Slot& own : m.slots)
                if (own.name == s.name)
                    report(Code::DuplicateName, p + "/name", "slot `" + s.name + "` is both a layer role and a slot of `slots`");
            if (s.heightBlend) {
                heightRefs_.emplace_back(p + "/height_blend/slot", s.heightBlend->slot);
                s.heightBlend->slot = l.name + "_" + s.heightBlend->slot;
            }
            s.name = l.name + "_" + s.name;
            slotPointers_[{layers.layers.size(), role}] = p;
            l.slots[role] = m.slots.size();
            m.slots.push_back(std::move(s));
        }
        // A role missing beside a misnamed slot is that slot's error, reported once.
        for (size_t r = 0; r < l.slots.size() && !misnamed; ++r)
            if (l.slots[r] == SIZE_MAX && !l.name.empty())
                report(Code::LayerRoles, pointer,
                       "layer `" + l.name + "` has no slot `" + layers.roles[r].name + "`; every layer has the first layer's roles (" +
                           roleList(layers) + ")");
    }

    // A role reads a KTX2 array in every layer or in none: every layer's slot names the same file at the layer's own
    // index (the array's layers in the layers' order), so that an engine binds the file as it is.
    void ktx2Array(const Material& m, Layers& layers, size_t role) {
        // The layer's slot of the role with a texture file; null where it has none (reported where it was read, or a
        // layer without slots).
        auto slotOf = [&](const Layers::Layer& l) -> const Slot* {
            const size_t i = role < l.slots.size() ? l.slots[role] : SIZE_MAX;
            return i == SIZE_MAX || !m.slots[i].file ? nullptr : &m.slots[i];
        };
        const Slot* first = nullptr;
        for (const Layers::Layer& l : layers.layers)
            if (const Slot* s = slotOf(l); s && s->file->info.layers > 0) {
                first = s;
                break;
            }
        if (!first) return;
        const std::string name = layers.roles[role].name, shown = first->texturePath.lexically_normal().string();
        bool whole = true;
        for (size_t i = 0; i < layers.layers.size(); ++i) {
            const Layers::Layer& l = layers.layers[i];
            if (!slotOf(l)) continue;
            const Slot& s = *slotOf(l);
            const std::string p = slotPointers_[{i, role}];
            if (s.file != first->file) {
                report(Code::TextureArray, p + "/texture",
                       "role `" + name + "` reads the KTX2 array " + shown + "; every layer's `" + name +
                           "` names that array at its own layer, not another file",
                       "for separate files, give every layer's `" + name + "` a 2D texture of its own");
                whole = false;
            } else if (s.textureLayer != int(i) && s.textureLayer < s.file->info.layers) {  // out of range: reported
                report(Code::TextureArray, p + "/layer",
                       "layer `" + l.name + "` is layer " + std::to_string(i) + " of the layers, and its `" + name + "` reads layer " +
                           std::to_string(s.textureLayer) + " of " + shown + "; expected `\"layer\": " + std::to_string(i) +
                           "` (the array's layers in the layers' order)");
                whole = false;
            }
        }
        if (!whole) return;
        layers.roles[role].ktx2Array = first->texture;
        layers.roles[role].ktx2ArrayPointer = slotPointers_[{0, role}] + "/texture";
    }

    // The role of a later layer's slot, by name and kind; SIZE_MAX after reporting when the first layer has no such role.
    size_t roleIndex(const Layers& layers, const Slot& s, const std::string& p) {
        std::vector<std::string> names;
        for (const Layers::Role& r : layers.roles) names.push_back(r.name);
        const auto it = std::find(names.begin(), names.end(), s.name);
        if (names.empty()) return SIZE_MAX;  // the first layer read no slot: reported there, with no roles to name here
        if (it == names.end()) {
            std::string hint;
            if (auto best = closestMatch(s.name, names)) hint = "did you mean " + ticked(*best) + "?";
            report(Code::LayerRoles, p + "/name", "no role `" + s.name + "` in the first layer; expected one of " + roleList(layers), hint);
            return SIZE_MAX;
        }
        const size_t role = size_t(it - names.begin());
        if (layers.roles[role].kind != s.kind && s.kindStated) {
            report(Code::LayerRoles, p + "/kind",
                   "role `" + s.name + "` is of kind `" + std::string(toString(layers.roles[role].kind)) + "` in the first layer, `" +
                       std::string(toString(s.kind)) + "` here");
            return SIZE_MAX;
        }
        return role;
    }

    // The role functions read each layer's slot at one uv with gradients taken before the layers' branches.
    void slotRules(const Slot& s, const std::string& p) {
        if (s.hex.projection == Projection::Triplanar)
            report(Code::ConflictingSettings, p, "layers read uv; the triplanar projection is not available in a layered material");
        if (s.hex.enabled && s.hex.blend == Blend::Histogram)
            report(Code::ConflictingSettings, p, "`blend` \"histogram\" is not available in a layered material's layers");
        if (s.hex.splitCoordinates)
            report(Code::ConflictingSettings, p, "`split_coordinates` is not available in a layered material's layers");
    }

    static std::string roleList(const Layers& layers) {
        std::vector<std::string> names;
        for (const Layers::Role& r : layers.roles) names.push_back(r.name);
        return joinQuoted(names);
    }

    void layerBlend(const json& v, Material& m, Layers& layers) {
        const std::string pointer = "/layer_blend";
        if (!v.is_object()) {
            report(Code::WrongType, pointer, "expected an object {\"splat\", \"mode\", ...}, got " + typeName(v));
            return;
        }
        checkKeys(v, pointer, kLayerBlendKeys);
        const bool known = weightSource(v, layers);  // a misspelled source is reported once, not as a missing `splat` too
        if (layers.weights == LayerWeights::Vertex) {
            if (v.contains("splat"))
                report(Code::MisplacedKey, pointer + "/splat", "`splat` applies to `weights` \"splat\" or \"both\"", {}, true);
        } else if ((known || v.contains("splat")) &&
                   requireKey(v, pointer, "splat", "an array of splat map files, RGBA = the weights of four layers each"))
            splats(v["splat"], pointer + "/splat", m, layers);
        if (v.contains("mode")) {
            if (int i = choice(v["mode"], pointer + "/mode", kLayerBlends); i >= 0) layers.blend = LayerBlend(i);
        }
        if (v.contains("width"))
            layers.width =
                std::max(number(v["width"], pointer + "/width", {0, 1, true, false, "in (0, 1]"}, layers.width), kMinHeightWidth);
        // A quarter: beyond, a layer painted at a quarter's weight would vanish.
        if (v.contains("skip_below"))
            layers.skipBelow = number(v["skip_below"], pointer + "/skip_below", {0, 0.25, false, false, "in [0, 0.25]"}, layers.skipBelow);
        if (v.contains("arrays")) {
            if (int i = choice(v["arrays"], pointer + "/arrays", kLayerArrays, {{"on", "auto"}, {"true", "auto"}}); i >= 0)
                layers.arrays = i == 0;
        }
        if (layers.blend == LayerBlend::Height && requireKey(v, pointer, "height", "the scalar role holding each layer's height"))
            heightRole(v["height"], pointer + "/height", layers);
        else if (layers.blend != LayerBlend::Height && v.contains("height"))
            report(Code::MisplacedKey, pointer + "/height", "`height` applies to `mode` \"height\"", {}, true);
    }

    // `weights`: the vertex colour's four channels weigh layers 0-3, so it serves at most four layers. False when it is
    // not one of the sources (reported).
    bool weightSource(const json& v, Layers& layers) {
        const std::string p = "/layer_blend/weights";
        if (!v.contains("weights")) return true;
        const int i = choice(v["weights"], p, kLayerWeights);
        if (i < 0) return false;
        layers.weights = LayerWeights(i);
        if (layers.weights != LayerWeights::Splat && declared_ > Layers::kMaxVertexLayers)
            report(Code::LayerWeights, p,
                   std::to_string(declared_) + " layers; the vertex colour (RGBA) weighs at most " +
                       std::to_string(Layers::kMaxVertexLayers) + " (channel i weighs layer i)",
                   "weigh them by splat maps alone (`weights` \"splat\"), or use at most four layers");
        return true;
    }

    // The index of the scalar role `name` holding heights; nothing after reporting when there is none (a non-string
    // `name`, already reported by the string read, is not reported again).
    std::optional<size_t> heightsRole(const std::string& name, bool isString, const std::string& p, const Layers& layers) {
        std::vector<std::string> names;
        for (const Layers::Role& r : layers.roles) names.push_back(r.name);
        const auto it = std::find(names.begin(), names.end(), name);
        if (names.empty()) return std::nullopt;  // no layer read a slot (reported at `layers`): no role to name
        if (it == names.end()) {
            std::string hint;
            if (auto best = closestMatch(name, names)) hint = "did you mean " + ticked(*best) + "?";
            if (isString)
                report(Code::UnknownReference, p, "no role `" + name + "` in the layers; expected one of " + roleList(layers), hint);
            return std::nullopt;
        }
        const size_t role = size_t(it - names.begin());
        if (!kindRow(layers.roles[role].kind).oneChannel) {
            report(Code::WrongSlotKind, p,
                   "role `" + name + "` is of kind `" + std::string(toString(layers.roles[role].kind)) +
                       "`; heights come from a role of kind " + kindsWhere(&SlotKindRow::oneChannel));
            return std::nullopt;
        }
        return role;
    }

    void heightRole(const json& v, const std::string& p, Layers& layers) {
        if (std::optional<size_t> role = heightsRole(string(v, p), v.is_string(), p, layers)) layers.heightRole = role;
    }

    // A layer's slot blends its tiles by the heights of a role of its own layer; in height mode, by the heights the
    // layers blend by, so that one height field decides which tile and which layer is on top.
    void heightBlendRole(const std::string& p, const std::string& name, const Layers& layers) {
        const std::optional<size_t> role = heightsRole(name, true, p, layers);
        if (!role || !layers.heightRole || *layers.heightRole == *role) return;
        const std::string heights = layers.roles[*layers.heightRole].name;
        report(Code::ConflictingSettings, p,
               "the layers blend by the heights of role `" + heights +
                   "` (/layer_blend/height); a layer's tiles blend by the same heights, not by role `" + name + "`'s",
               "name `" + heights + "`");
    }

    // Splat map i holds the weights of layers 4i .. 4i+3 in r, g, b, a.
    void splats(const json& v, const std::string& pointer, Material& m, Layers& layers) {
        const size_t needed = (declared_ + 3) / 4;
        if (!v.is_array()) {
            report(Code::WrongType, pointer, "expected an array of splat map files, got " + typeName(v));
            return;
        }
        // Counted over the layers written; none, or more than a shader blends, is the layers' error alone.
        if (v.size() != needed && declared_ > 0 && declared_ <= Layers::kMaxLayers) {
            report(Code::LayerWeights, pointer,
                   std::to_string(declared_) + " layers take their weights from " + std::to_string(needed) + " splat map" +
                       (needed == 1 ? "" : "s") + " (RGBA = four layers each); got " + std::to_string(v.size()));
        }
        for (size_t i = 0; i < v.size() && i < 2; ++i) {
            const std::string p = pointerAppend(pointer, i);
            Slot s;
            s.name = "splat" + std::to_string(i);
            s.texture = string(v[i], p);
            s.colorSpace = ColorSpace::Linear;     // weights, not colours
            const TextPos at = locator_.value(p);  // where a budget's error points
            s.line = at.line, s.col = at.col;
            s.hex.enabled = false;  // one fetch, over the whole terrain: tiling 1
            if (!v[i].is_string()) continue;
            read_.texture(s, p);
            if (s.file && s.file->info.layers > 0)
                report(Code::TextureArray, p,
                       "splat map " + s.texture + " is a KTX2 array; expected a 2D texture (RGBA = four layers' weights)");
            const size_t used = std::min<size_t>(4, layers.layers.size() - std::min(layers.layers.size(), 4 * i));
            if (!s.channelNames.empty() && s.channelNames.size() < used)
                report(Code::TextureChannels, p,
                       "splat map " + s.texture + " has " + std::to_string(s.channelNames.size()) + " channels; it weighs " +
                           std::to_string(used) + " layers (one channel each)");
            layers.splats.push_back(m.slots.size());
            m.slots.push_back(std::move(s));
        }
    }

    const LayerReaders& read_;
    size_t declared_ = 0;  // the layers `layers` lists, those past the most a shader blends included
    std::map<std::pair<size_t, size_t>, std::string> slotPointers_;  // (layer, role) -> the slot's JSON pointer
    std::vector<std::pair<std::string, std::string>> heightRefs_;    // per layer slot with height_blend: its pointer, role
};

}  // namespace

void parseLayers(JsonRules& rules, const nlohmann::json& doc, Material& m, const LayerReaders& read) {
    LayerValidator v(rules, read);
    v.run(doc, m);
    rules.diags.insert(rules.diags.end(), v.diags.begin(), v.diags.end());
}

}  // namespace hexc
