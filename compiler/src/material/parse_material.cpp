// A material document -> Material: its keys, hex-tiling settings, slots and the rules across them, with defaults filled.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "common/suggest.h"
#include "hexc/image.h"
#include "hexc/lint.h"
#include "hexc/materialx.h"
#include "material/layers.h"
#include "material/names.h"
#include "material/parse.h"
#include "material/rules.h"

namespace hexc {
namespace {

const std::vector<std::string> kMaterialKeys = {"$schema", "name", "template", "hextiling", "pack", "slots", "layers", "layer_blend"};
const std::vector<std::string> kSlotKeys = {"name", "texture",   "kind",         "channel", "colorspace", "flip_y",
                                            "role", "hextiling", "height_blend", "layer",   "lint_skip"};
const std::vector<std::string> kHexKeys = {
    "enabled",           "tiling",        "rotation",      "falloff",        "falloffcontrast", "exponent",    "mode",
    "split_coordinates", "rotationrange", "rotationsteps", "scalerange",     "offset",          "offsetsteps", "mask",
    "maskscale",         "taps",          "projection",    "planesharpness", "blend",           "lod",         "lumacoeffs"};
const std::vector<std::string> kHeightKeys = {"slot", "width"};
// Keys of one level that a user may write one level up or down: a slot's own, and the material's own.
const std::vector<std::string> kSlotOnlyKeys = {"texture", "layer", "kind", "channel", "colorspace", "flip_y", "role", "height_blend"};
const std::vector<std::string> kMaterialOnlyKeys = {"template", "pack", "slots"};
const std::vector<std::string> kTaps = {"adaptive"};  // besides a count

// [a-z][a-z0-9_]{0,31} without `__` (reserved in GLSL): a slot name becomes the GLSL function hexc_<name>.
bool isSlotName(const std::string& name) {
    auto lowerOrDigit = [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; };
    return !name.empty() && name.size() <= 32 && name[0] >= 'a' && name[0] <= 'z' && std::all_of(name.begin(), name.end(), lowerOrDigit) &&
           name.find("__") == std::string::npos && !name.starts_with("gl_");
}

class MaterialValidator : public JsonRules {
public:
    using JsonRules::JsonRules;

    Material run(const json& doc) {
        Material m;
        m.sourceFile = file_;
        duplicateKeys();
        if (!doc.is_object()) {
            report(Code::WrongType, "", "expected a material object, got " + typeName(doc));
            return m;
        }
        checkKeys(doc, "", kMaterialKeys, {{&kHexKeys, "the top-level `hextiling` or a slot's"}, {&kSlotOnlyKeys, "a slot of `slots`"}});
        if (requireKey(doc, "", "name", "a string")) {
            m.name = string(doc["name"], "/name");
            if (doc["name"].is_string() && !isFileName(m.name))
                report(Code::InvalidName, "/name",
                       "expected 1-64 letters, digits, `_` or `-` (it names the output files), got \"" + m.name + "\"");
        }
        if (doc.contains("template")) m.templ = templateRef(doc["template"], "/template");
        if (doc.contains("$schema")) string(doc["$schema"], "/$schema");
        if (doc.contains("hextiling")) hexSettings(doc["hextiling"], "/hextiling", m.hex, true);
        if (doc.contains("pack")) m.pack = boolean(doc["pack"], "/pack", false);
        // A layered material may have no slots of its own.
        if (doc.contains("slots") || (!doc.contains("layers") && requireKey(doc, "", "slots", "an array of slots")))
            slots(doc["slots"], "/slots", m);
        if (doc.contains("layers") || doc.contains("layer_blend")) layers(doc, m);
        return m;
    }

private:
    void layers(const json& doc, Material& m) {
        const LayerReaders read = {
            [this](const json& v, const std::string& p, const HexTiling& h) { return slot(v, p, h); },
            [this](const json& v, const std::string& p, HexTiling& h) { hexSettings(v, p, h); },
            [this](Slot& s, const std::string& p) {
                texture(s, p);
                if (s.line == 0) {  // a splat map, which has no kind: located at its file name
                    const TextPos at = locator_.value(p);
                    s.line = at.line, s.col = at.col;
                }
            },
        };
        parseLayers(*this, doc, m, read);
    }

    // `materialLevel`: the top-level block, the only place for material-wide keys.
    void hexSettings(const json& v, const std::string& pointer, HexTiling& hex, bool materialLevel = false) {
        if (!v.is_object()) {
            report(Code::WrongType, pointer, "expected an object of hex-tiling settings, got " + typeName(v));
            return;
        }
        checkKeys(v, pointer, kHexKeys,
                  {{&kSlotOnlyKeys, materialLevel ? "a slot of `slots`" : "the slot, one level up"},
                   {&kMaterialOnlyKeys, "the material's top level"}});
        if (v.contains("enabled")) hex.enabled = boolean(v["enabled"], pointer + "/enabled", hex.enabled);
        if (v.contains("tiling")) tiling(v["tiling"], pointer + "/tiling", hex);
        if (v.contains("rotation"))
            hex.rotation = number(v["rotation"], pointer + "/rotation", {0, INFINITY, false, true, ">= 0"}, hex.rotation);
        // 1e-6 from either end: float32 must still tell 1 - r from 0 and from 1 for the gain's exponent.
        if (v.contains("falloff"))
            hex.falloff = number(v["falloff"], pointer + "/falloff", {1e-6, 1 - 1e-6, false, false, "in [0.000001, 0.999999] (0.5 = off)"},
                                 hex.falloff);
        if (v.contains("falloffcontrast"))
            hex.falloffcontrast =
                number(v["falloffcontrast"], pointer + "/falloffcontrast", {0, 1, false, false, "in [0, 1]"}, hex.falloffcontrast);
        // Above 64, (1/3)^gamma at a triangle centre underflows float32 and the weights become 0/0.
        if (v.contains("exponent"))
            hex.exponent = number(v["exponent"], pointer + "/exponent", {1, 64, false, false, "in [1, 64]"}, hex.exponent);
        if (v.contains("mode")) {
            if (int i = choice(v["mode"], pointer + "/mode", kModes); i >= 0) hex.mode = HashMode(i);
        }
        if (v.contains("lumacoeffs")) hex.lumacoeffs = lumaCoeffs(v["lumacoeffs"], pointer + "/lumacoeffs", hex.lumacoeffs);
        if (v.contains("split_coordinates"))
            hex.splitCoordinates = boolean(v["split_coordinates"], pointer + "/split_coordinates", hex.splitCoordinates);
        if (v.contains("mask")) {
            if (int i = choice(v["mask"], pointer + "/mask", kMasks); i >= 0) hex.mask = Mask(i);
        }
        if (v.contains("maskscale"))
            hex.maskScale = int(whole(v["maskscale"], pointer + "/maskscale",
                                      {1, 64, false, false, "in 1..64 (mask cells per texture repeat)"}, hex.maskScale));
        if (v.contains("taps")) taps(v["taps"], pointer + "/taps", hex);
        if (v.contains("blend")) {
            if (int i = choice(v["blend"], pointer + "/blend", kBlends); i >= 0) hex.blend = Blend(i);
        }
        if (v.contains("lod")) {
            if (int i = choice(v["lod"], pointer + "/lod", kLods); i >= 0) hex.lod = Lod(i);
        }
        transformSettings(v, pointer, hex);
        projectionSettings(v, pointer, hex, materialLevel);
    }

    // `taps`: a count, or "adaptive".
    void taps(const json& t, const std::string& p, HexTiling& hex) {
        if (t.is_string()) {
            if (choice(t, p, kTaps) >= 0) hex.taps = HexTiling::kAdaptiveTaps;
            return;
        }
        hex.taps = int(whole(t, p, {1, 3, false, false, "in 1..3 or \"adaptive\""}, hex.taps));
    }

    // `tiling`: one number for both axes or [u, v]. Bounded to [2^-24, 2^24]: above, float32 st = uv * tiling no
    // longer tells neighbouring texture repeats apart at uv 1 (its ulp there is 2 at 2^24) and overflows to infinity
    // above 3.4e38; below, st rounds to a constant over the whole unit square (or to 0). Nothing inside loses finiteness.
    void tiling(const json& t, const std::string& p, HexTiling& hex) {
        const Range positive{0x1p-24, 0x1p24, false, false, "in [0.0000000596, 16777216] (2^-24 to 2^24)"};
        if (t.is_array() && t.size() == 2) {
            hex.tiling[0] = number(t[0], p + "/0", positive, hex.tiling[0]);
            hex.tiling[1] = number(t[1], p + "/1", positive, hex.tiling[1]);
        } else if (t.is_number()) {
            hex.tiling[0] = hex.tiling[1] = number(t, p, positive, hex.tiling[0]);
        } else {
            report(Code::WrongType, p,
                   "expected a number in [2^-24, 2^24] or an array [u, v] of two, got " +
                       (t.is_array() ? "an array of " + std::to_string(t.size()) : typeName(t)));
        }
    }

    // The per-tile transforms (stable mode): rotation and scale ranges, offset, and their steps.
    void transformSettings(const json& v, const std::string& pointer, HexTiling& hex) {
        if (v.contains("rotationrange"))
            pair(v["rotationrange"], pointer + "/rotationrange", {-3600, 3600, false, false, "in [-3600, 3600] (degrees)"},
                 hex.rotationRange);
        if (v.contains("scalerange"))
            pair(v["scalerange"], pointer + "/scalerange", {0.01, 100, false, false, "in [0.01, 100]"}, hex.scaleRange);
        if (v.contains("offset")) hex.offset = number(v["offset"], pointer + "/offset", {0, 1, false, false, "in [0, 1]"}, hex.offset);
        if (v.contains("rotationsteps"))
            hex.rotationSteps =
                int(whole(v["rotationsteps"], pointer + "/rotationsteps", {0, 360, false, false, "in 0..360 (0: continuous)"}, 0));
        if (v.contains("offsetsteps")) {
            std::array<double, 2> steps{0, 0};
            pair(v["offsetsteps"], pointer + "/offsetsteps", {0, 4096, false, false, "in 0..4096 (0: continuous)"}, steps, true);
            hex.offsetSteps = {int(steps[0]), int(steps[1])};
        }
    }

    // `projection` and `planesharpness`: the material-level block only (every slot function takes the same inputs).
    void projectionSettings(const json& v, const std::string& pointer, HexTiling& hex, bool materialLevel) {
        for (const char* key : {"projection", "planesharpness"})
            if (v.contains(key) && !materialLevel)
                report(Code::MisplacedKey, pointer + "/" + key,
                       ticked(key) + " is material-wide (every slot function takes the same inputs); set it in the top-level `hextiling`",
                       {}, true);
        if (v.contains("projection") && materialLevel) {
            if (int i = choice(v["projection"], pointer + "/projection", kProjections); i >= 0) hex.projection = Projection(i);
        }
        if (v.contains("planesharpness") && materialLevel)
            hex.planeSharpness =
                number(v["planesharpness"], pointer + "/planesharpness", {1, 64, false, false, "in [1, 64]"}, hex.planeSharpness);
    }

    void slots(const json& v, const std::string& pointer, Material& m) {
        if (!v.is_array()) {
            report(Code::WrongType, pointer, "expected an array of slots, got " + typeName(v));
            return;
        }
        if (v.empty() || v.size() > kMaxTextures) {
            report(Code::WrongCount, pointer, "expected 1 to " + std::to_string(kMaxTextures) + " slots, got " + std::to_string(v.size()));
            if (v.empty()) return;
        }
        std::map<std::string, std::string> seen;  // name -> pointer of first use
        for (size_t i = 0; i < v.size(); ++i) {
            std::string p = pointerAppend(pointer, i);
            Slot s = slot(v[i], p, m.hex);
            if (s.file && s.file->info.layers > 0 && v[i].contains("layer"))
                report(Code::TextureArray, p + "/layer",
                       "a KTX2 array texture is read by a layered material's layers, each layer's slot at its layer; a slot of "
                       "`slots` reads a 2D texture");
            if (!s.name.empty()) {
                if (auto [it, fresh] = seen.emplace(s.name, p); !fresh) {
                    TextPos first = locator_.value(it->second + "/name");
                    report(Code::DuplicateName, p + "/name",
                           "duplicate slot name \"" + s.name + "\" (first at line " + std::to_string(first.line) + ")");
                }
            }
            m.slots.push_back(std::move(s));
        }
        namePrefixes(pointer, m);
        heightSlots(pointer, m);
    }

    // Generated parameters are named <slot>_<setting> (albedo_tiling, albedo_origin_offset): two slots' names
    // can only collide when one slot's name is another's followed by `_`, so that is refused.
    void namePrefixes(const std::string& pointer, const Material& m) {
        for (size_t i = 0; i < m.slots.size(); ++i)
            for (const Slot& other : m.slots) {
                const std::string& name = m.slots[i].name;
                if (other.name.empty() || !name.starts_with(other.name + "_")) continue;
                report(Code::InvalidName, pointerAppend(pointer, i) + "/name",
                       "slot name \"" + name + "\" starts with slot `" + other.name + "`'s name and `_`, so their generated parameters " +
                           "(<slot>_tiling, <slot>_origin_offset, ...) could collide",
                       "rename one of them");
                break;
            }
    }

    Slot slot(const json& v, const std::string& pointer, const HexTiling& defaults) {
        Slot s;
        s.hex = defaults;
        if (!v.is_object()) {
            report(Code::WrongType, pointer, "expected a slot object, got " + typeName(v));
            return s;
        }
        checkKeys(v, pointer, kSlotKeys, {{&kHexKeys, "the slot's `hextiling`"}, {&kMaterialOnlyKeys, "the material's top level"}});
        if (requireKey(v, pointer, "name", "a string")) {
            s.name = string(v["name"], pointer + "/name");
            if (v["name"].is_string() && !isSlotName(s.name)) {
                report(Code::InvalidName, pointer + "/name",
                       "expected a lower-case identifier of 1-32 characters ([a-z][a-z0-9_]*, no `__`, not starting with `gl_`), got \"" +
                           s.name + "\"",
                       "it becomes the GLSL function hexc_<name>");
                s.name.clear();
            }
        }
        bool kindKnown = false;
        if (requireKey(v, pointer, "kind", "one of " + joinQuoted(kKinds))) {
            // What other tools call them: a texture's role or its data.
            static const std::map<std::string, std::string> kKindsMeant = {
                {"float", "scalar"},      {"grey", "scalar"},      {"gray", "scalar"},     {"greyscale", "scalar"}, {"grayscale", "scalar"},
                {"mono", "scalar"},       {"mask", "scalar"},      {"height", "scalar"},   {"roughness", "scalar"}, {"metallic", "scalar"},
                {"ao", "scalar"},         {"occlusion", "scalar"}, {"colour", "color"},    {"rgb", "color"},        {"rgba", "color"},
                {"albedo", "color"},      {"diffuse", "color"},    {"basecolor", "color"}, {"base_color", "color"}, {"normalmap", "normal"},
                {"normal_map", "normal"}, {"tangent", "normal"},   {"bump", "normal"}};
            const int i = choice(v["kind"], pointer + "/kind", kKinds, kKindsMeant);
            kindKnown = i >= 0;
            s.kind = kindKnown ? SlotKind(i) : s.kind;
            s.kindStated = kindKnown;
            TextPos at = locator_.value(pointer + "/kind");  // where a template-fit error points
            s.line = at.line, s.col = at.col;
        }
        const SlotKindRow& kind = kindRow(s.kind);
        s.colorSpace = kind.colorSpace;
        if (v.contains("channel")) {
            if (kindKnown && !kind.oneChannel)
                report(Code::MisplacedKey, pointer + "/channel",
                       "`channel` applies only to slots of kind " + kindsWhere(&SlotKindRow::oneChannel), {}, true);
            else if (int i = choice(v["channel"], pointer + "/channel", kChannels); i >= 0)
                s.channel = i;
        }
        if (v.contains("flip_y")) {
            if (kindKnown && !kind.derivative)
                report(Code::MisplacedKey, pointer + "/flip_y",
                       "`flip_y` applies only to slots of kind " + kindsWhere(&SlotKindRow::derivative), {}, true);
            else
                s.flipY = boolean(v["flip_y"], pointer + "/flip_y", false);
        }
        if (v.contains("role")) {
            if (int i = choice(v["role"], pointer + "/role", kRoles); i >= 0) {
                if (kindKnown && roleKind(kRoles[size_t(i)]) != s.kind)
                    report(Code::ConflictingSettings, pointer + "/role",
                           "role `" + kRoles[size_t(i)] + "` takes a slot of kind `" + std::string(toString(roleKind(kRoles[size_t(i)]))) +
                               "`, this one is `" + std::string(toString(s.kind)) + "`");
                else
                    s.role = kRoles[size_t(i)];
            }
        }
        if (v.contains("colorspace")) {
            if (int i = choice(v["colorspace"], pointer + "/colorspace", kColorSpaces); i >= 0) {
                if (kindKnown && kind.derivative && ColorSpace(i) == ColorSpace::Srgb)
                    report(Code::ConflictingSettings, pointer + "/colorspace",
                           "a normal map holds vectors and must be `linear`, got \"srgb\"");
                else
                    s.colorSpace = ColorSpace(i);
            }
        }
        if (v.contains("hextiling")) hexSettings(v["hextiling"], pointer + "/hextiling", s.hex);
        std::string at = v.contains("hextiling") ? pointer + "/hextiling" : pointer;
        settingRules(s.hex, at);
        blendRules(v, pointer, s);
        if (!s.hex.splitCoordinates) {
            // A tiling the slot inherits is the material's: reported there, once for all the slots that inherit it.
            const bool ownTiling = v.contains("hextiling") && v["hextiling"].is_object() && v["hextiling"].contains("tiling");
            if (ownTiling)
                rangeWarning(s.hex, at);
            else if (!inheritedRangeWarned_)
                inheritedRangeWarned_ = rangeWarning(s.hex, "/hextiling");
        }
        if (v.contains("height_blend")) heightBlend(v["height_blend"], pointer + "/height_blend", s);
        if (v.contains("lint_skip")) lintSkip(v["lint_skip"], pointer + "/lint_skip", s);
        if (v.contains("layer")) s.textureLayer = int(whole(v["layer"], pointer + "/layer", {0, 2047, false, false, "in [0, 2047]"}, 0));
        if (requireKey(v, pointer, "texture", "a path to an image file")) {
            s.texture = string(v["texture"], pointer + "/texture");
            if (v["texture"].is_string()) texture(s, pointer + "/texture");
        }
        arrayLayerRules(v.contains("layer"), s, pointer);
        return s;
    }

    // A KTX2 array texture is read one layer a slot, the layer `layer` names; a 2D texture has no layers to name.
    void arrayLayerRules(bool stated, const Slot& s, const std::string& pointer) {
        if (!s.file) return;
        const int layers = s.file->info.layers;
        const std::string shown = s.texturePath.lexically_normal().string();
        if (layers > 0 && !stated)
            report(Code::TextureArray, pointer + "/texture",
                   shown + " is a KTX2 array of " + std::to_string(layers) +
                       " layers; expected a 2D texture, or in a layered material's layer, `layer`: the array's layer this slot reads");
        else if (layers == 0 && stated)
            report(Code::TextureArray, pointer + "/layer", "`layer` names a layer of a KTX2 array texture; " + shown + " is a 2D texture");
        else if (stated && s.textureLayer >= layers)
            report(Code::TextureArray, pointer + "/layer",
                   "layer " + std::to_string(s.textureLayer) + " of " + shown + ", which has " + std::to_string(layers) +
                       " layers; expected 0 to " + std::to_string(layers - 1));
    }

    // The histogram blend applies to colour and scalar slots that blend every tap: one set on a normal slot itself is an
    // error, one inherited from the material leaves normal and disabled slots as they were.
    void blendRules(const json& v, const std::string& pointer, Slot& s) {
        if (s.hex.blend != Blend::Histogram) return;
        const bool own = v.contains("hextiling") && v["hextiling"].is_object() && v["hextiling"].contains("blend");
        const bool may = kindRow(s.kind).mayUseHistogram;
        if (own && !may)
            report(Code::WrongSlotKind, pointer + "/hextiling/blend",
                   "`blend` \"histogram\" applies to slots of kind " + kindsWhere(&SlotKindRow::mayUseHistogram) +
                       "; a normal map blends its derivatives");
        else if (s.hex.enabled && may && s.hex.taps == 1)
            report(
                Code::ConflictingSettings, pointer + (own ? "/hextiling/blend" : ""),
                "`blend` \"histogram\" blends every tile's sample; it cannot be combined with `taps` 1 (one fetch has nothing to blend)");
        else if (s.hex.enabled && may && s.hex.adaptive())
            report(Code::ConflictingSettings, pointer + (own ? "/hextiling/blend" : ""),
                   "`blend` \"histogram\" cannot be combined with `taps` \"adaptive\": its look-up table can magnify a skipped tap's "
                   "weight beyond the bound adaptive taps guarantee");
        if (!may || !s.hex.enabled) s.hex.blend = Blend::Falloff;
    }

    // Three weights in [0, 1].
    std::array<double, 3> lumaCoeffs(const json& v, const std::string& pointer, std::array<double, 3> fallback) {
        if (!v.is_array() || v.size() != 3) {
            report(Code::WrongType, pointer, "expected 3 numbers (luma weights of r, g, b), got " + typeName(v));
            return fallback;
        }
        for (size_t i = 0; i < 3; ++i)
            fallback[i] = number(v[i], pointerAppend(pointer, i), {0, 1, false, false, "in [0, 1]"}, fallback[i]);
        return fallback;
    }

    // MaterialX mode is MaterialX's nodes exactly: what they have no input for is refused.
    void materialxRules(const HexTiling& hex, const std::string& at) {
        std::string other;
        if (hex.mask != Mask::Hex)
            other = "mask `" + std::string(toString(hex.mask)) + "`";
        else if (hex.taps != 0)
            other = "`taps`";
        else if (hex.exponent != 7)
            other = "`exponent` other than 7";
        else if (hex.rotationSteps != 0 || hex.offsetSteps != std::array<int, 2>{0, 0})
            other = "rotation or offset steps";
        else if (hex.splitCoordinates)
            other = "`split_coordinates`";
        else if (hex.blend != Blend::Falloff)
            other = "blend `histogram`";
        else if (hex.lod != Lod::Gradients)
            other = "lod `shared`";
        if (!other.empty())
            report(Code::ConflictingSettings, at, other + " does not exist in mode `materialx`, which is MaterialX's hextiledimage exactly",
                   "use mode `stable`");
    }

    // Rules across a slot's merged hex-tiling settings, reported at `at`.
    void settingRules(const HexTiling& hex, const std::string& at) {
        if (hex.mode == HashMode::MaterialX && hex.enabled) materialxRules(hex, at);
        // A tile's angle is rotation times a point of rotationrange, computed in float32: within 3600 degrees (62.8 rad)
        // its rounding (4e-6 rad) moves a texel at the texture's far edge by 1/1000 of a texel; at rotation 1e6 whole texels.
        const double angle = hex.rotation * std::max(std::fabs(hex.rotationRange[0]), std::fabs(hex.rotationRange[1]));
        if (hex.enabled && angle > 3600)
            report(Code::ConflictingSettings, at,
                   "`rotation` times `rotationrange` reaches " + json(angle).dump() +
                       " degrees; expected at most 3600 (rotation <= 3600 / max |rotationrange|)");
        // Checked on the merged settings: the paper's lattice has no exact period to split at, and its tile
        // transforms are Listings 2 and 6 exactly.
        if (hex.splitCoordinates && hex.mode == HashMode::Paper)
            report(Code::ConflictingSettings, at,
                   "`split_coordinates` needs mode `stable`; the paper's lattice has no exact period to split at");
        if (hex.hasTransforms() && hex.mode == HashMode::Paper)
            report(Code::ConflictingSettings, at,
                   "per-tile transforms (rotationrange, rotationsteps, scalerange, offset, offsetsteps) need mode `stable`; "
                   "mode `paper` is exactly the paper's Listings 2 and 6");
        if (hex.mask != Mask::Hex && hex.mode == HashMode::Paper)
            report(Code::ConflictingSettings, at,
                   "mask `" + std::string(toString(hex.mask)) + "` needs mode `stable`; the paper defines only the hex lattice");
        if (hex.taps > 1 && hex.taps != hex.maskTaps())
            report(Code::ConflictingSettings, at,
                   "`taps` " + std::to_string(hex.taps) + " does not fit mask `" + std::string(toString(hex.mask)) + "`, which has " +
                       std::to_string(hex.maskTaps()) + " taps; expected " + std::to_string(hex.maskTaps()) + " or 1 (one dithered fetch)");
        // The bound on the gain's effect (docs/material-format.md#taps) needs its exponent k >= 1.
        if (hex.enabled && hex.adaptive() && hex.falloff < 0.5)
            report(Code::ConflictingSettings, at,
                   "`taps` \"adaptive\" needs `falloff` >= 0.5: below, the gain's renormalisation can move the result by more than a "
                   "skipped tap's weight, and no threshold bounds it");
        // At beta = 1 a tap's metric can be 0 (a black sample), so a tap of any positive weight can carry the whole blend.
        if (hex.enabled && hex.adaptive() && hex.falloffcontrast >= 1)
            report(Code::ConflictingSettings, at,
                   "`taps` \"adaptive\" needs `falloffcontrast` < 1: at 1 a black sample weighs nothing, so a tap of any weight "
                   "can carry the whole blend, and no threshold bounds a skipped one");
        if (hex.splitCoordinates && (hex.mask == Mask::Noise || hex.mask == Mask::Noise3))
            report(Code::ConflictingSettings, at,
                   "`split_coordinates` does not work with the noise masks: their copies are transformed about the origin");
        if (hex.splitCoordinates && hex.projection == Projection::Triplanar)
            report(Code::ConflictingSettings, at,
                   "`split_coordinates` does not work with the triplanar projection: it reads world positions, not uv");
    }

    // Stable mode is exact while st = uv * tiling stays within its reduction's range (docs/precision.md): |st.x| < 2^26
    // for the hex lattice (28 kx exact in float32), |st| < 2^31 for the checker (int conversion). A tiling that
    // brings that range under 2^16 uv, where an ordinary terrain's uv can reach, gets a warning.
    // HX116 when the tiling brings stable mode's exact range under 65,536 uv; whether it was reported.
    bool rangeWarning(const HexTiling& hex, const std::string& at) {
        if (!hex.enabled || hex.mode != HashMode::Stable || hex.projection != Projection::Uv) return false;
        if (hex.mask != Mask::Hex && hex.mask != Mask::Checker) return false;  // the noise masks lose precision like plain tiling
        const bool checker = hex.mask == Mask::Checker;
        const double tiling = checker ? std::max(hex.tiling[0], hex.tiling[1]) : hex.tiling[0];
        const double limit = std::ldexp(1.0, checker ? 31 : 26) / tiling;
        if (limit >= 65536) return false;
        // The limit is at least 4 (tiling <= 2^24): three significant figures below 1000, whole numbers above.
        char text[200], figure[32];
        std::snprintf(figure, sizeof figure, limit < 1000 ? "%.3g" : "%.0f", limit);
        std::snprintf(text, sizeof text,
                      "with tiling %g, stable mode's %s is exact only for |%s| < %s (2^%d / tiling); beyond, tiles come out wrong", tiling,
                      checker ? "checker" : "lattice", checker ? "uv" : "u", figure, checker ? 31 : 26);
        report(Code::TilingRange, at, text,
               "for larger uv set \"split_coordinates\": true and pass uv relative to a per-frame origin "
               "(docs/precision.md#stable-modes-range)");
        return true;
    }

    // The texture checks whose warnings the slot does not report, by name (docs/lint.md).
    void lintSkip(const json& v, const std::string& pointer, Slot& s) {
        if (!v.is_array()) return report(Code::WrongType, pointer, "expected an array of check names, got " + typeName(v));
        for (size_t i = 0; i < v.size(); ++i)
            if (int c = choice(v[i], pointer + "/" + std::to_string(i), kLintChecks); c >= 0) s.lintSkip.push_back(kLintChecks[size_t(c)]);
    }

    void heightBlend(const json& v, const std::string& pointer, Slot& s) {
        if (!v.is_object()) {
            report(Code::WrongType, pointer, "expected an object {\"slot\": name, \"width\": number}, got " + typeName(v));
            return;
        }
        checkKeys(v, pointer, kHeightKeys);
        HeightBlend h;
        if (requireKey(v, pointer, "slot", "the name of a scalar slot holding heights")) h.slot = string(v["slot"], pointer + "/slot");
        if (v.contains("width"))
            h.width = std::max(number(v["width"], pointer + "/width", {0, 1, true, false, "in (0, 1]"}, h.width), kMinHeightWidth);
        if (s.hex.taps == 1 || s.hex.adaptive())
            report(Code::ConflictingSettings, pointer,
                   std::string("`height_blend` needs every tile's height; it cannot be combined with `taps` ") +
                       (s.hex.adaptive() ? "\"adaptive\" (a tile's height can raise any weight)" : "1"),
                   {}, true);
        if (!s.hex.enabled)
            report(Code::ConflictingSettings, pointer,
                   "`height_blend` weighs tiles, and this slot has hex-tiling disabled (`enabled`: false)", {}, true);
        if (s.hex.blend == Blend::Histogram)
            report(Code::ConflictingSettings, pointer,
                   "`height_blend` cannot be combined with `blend` \"histogram\", whose weights must keep the blend's variance");
        if (s.hex.mode == HashMode::MaterialX)
            report(Code::ConflictingSettings, pointer, "`height_blend` does not exist in mode `materialx`", "use mode `stable`");
        s.heightBlend = h;
    }

    // After all slots are known: each height_blend names a scalar slot.
    void heightSlots(const std::string& pointer, const Material& m) {
        std::vector<std::string> names;
        for (const Slot& s : m.slots) names.push_back(s.name);
        for (size_t i = 0; i < m.slots.size(); ++i) {
            const Slot& s = m.slots[i];
            if (!s.heightBlend || s.heightBlend->slot.empty()) continue;
            std::string p = pointerAppend(pointer, i) + "/height_blend/slot";
            auto it = std::find(names.begin(), names.end(), s.heightBlend->slot);
            if (it == names.end()) {
                std::string hint;
                if (auto best = closestMatch(s.heightBlend->slot, names)) hint = "did you mean " + ticked(*best) + "?";
                report(Code::UnknownReference, p, "no slot named `" + s.heightBlend->slot + "` in this material", hint);
            } else if (const Slot& h = m.slots[size_t(it - names.begin())]; !kindRow(h.kind).oneChannel) {
                report(Code::WrongSlotKind, p,
                       "slot `" + h.name + "` is of kind `" + std::string(toString(h.kind)) + "`; heights come from a slot of kind " +
                           kindsWhere(&SlotKindRow::oneChannel));
            }
        }
    }

    void texture(Slot& s, const std::string& pointer) {
        s.texturePath = dir_ / s.texture;
        // Shown as the path it names (`err/../tex/x.png` as `tex/x.png`); read as written, where a link in it counts.
        const std::string shown = s.texturePath.lexically_normal().string();
        std::error_code ec;
        if (s.texture.find('\0') != std::string::npos) {  // the file system would see the path up to it, another file
            report(Code::TextureNotFound, pointer, "a texture path holds a NUL character (\\u0000)");
            return;
        }
        if (s.texture.empty() || !std::filesystem::exists(s.texturePath, ec)) {
            report(Code::TextureNotFound, pointer, "texture file not found: " + shown);
            return;
        }
        std::string why;
        SharedTextureFiles::Files* shared = SharedTextureFiles::current();
        std::shared_ptr<const TextureFile>& file = (shared ? *shared : files_)[std::filesystem::weakly_canonical(s.texturePath, ec)];
        if (!file)
            if (std::optional<TextureFile> read = readTextureFile(s.texturePath, &why))
                file = std::make_shared<const TextureFile>(std::move(*read));
        if (!file) {
            report(Code::TextureUnreadable, pointer,
                   "cannot read texture " + shown + ": " + why +
                       " (expected PNG, JPEG, TGA, BMP, PSD, GIF, HDR, PNM, PFM, OpenEXR, KTX2 or DDS)");
            return;
        }
        s.file = file;
        const TextureInfo* info = &file->info;
        s.width = info->width;
        s.height = info->height;
        s.channelNames = info->channelNames;
        s.eightBit = info->eightBit;
        if (kindRow(s.kind).derivative && info->channels < 3)
            report(Code::TextureChannels, pointer,
                   "a normal map needs 3 channels (xyz), " + shown + " has " + std::to_string(info->channels));
        // A channel the file lacks reads whatever the engine's upload puts there (0, 1 or a copy of grey): a scalar
        // slot reading one is a mistake. A grey + alpha file has r and a.
        if (info->srgb && *info->srgb != (s.colorSpace == ColorSpace::Srgb))
            report(Code::TextureColorSpace, pointer,
                   shown + " is " + info->format + ", but the slot's colorspace is " +
                       (*info->srgb ? "\"linear\"; a sampler would decode it from sRGB" : "\"srgb\"; its format stores linear values"));
        std::vector<std::string> has;
        for (char c : info->channelNames) has.emplace_back(1, c);
        if (kindRow(s.kind).oneChannel && std::find(has.begin(), has.end(), kChannels[size_t(s.channel)]) == has.end())
            report(Code::TextureChannels, pointer.substr(0, pointer.rfind('/')) + "/channel",
                   "channel `" + kChannels[size_t(s.channel)] + "` of " + shown + ", which has " + std::to_string(info->channels) +
                       " channel" + (info->channels == 1 ? "" : "s") + "; expected " + joinQuoted(has));
    }

    bool inheritedRangeWarned_ = false;  // HX116 for the material-level tiling is given once
    // Each texture file read once, however many slots name it (by its real path); null where it could not be read.
    std::map<std::filesystem::path, std::shared_ptr<const TextureFile>> files_;
};

}  // namespace

namespace {
thread_local SharedTextureFiles::Files* innermost = nullptr;
}

SharedTextureFiles::SharedTextureFiles() : outer_(innermost) { innermost = &files_; }
SharedTextureFiles::~SharedTextureFiles() { innermost = outer_; }
SharedTextureFiles::Files* SharedTextureFiles::current() { return innermost; }

ParseResult parseMaterialJson(std::string_view text, const std::filesystem::path& file) {
    return validate(text, file, &ParseResult::material, &MaterialValidator::run, &ParseResult::partial);
}

ParseResult parseMaterial(std::string_view text, const std::filesystem::path& file) {
    return isMaterialXFile(file) ? parseMaterialX(text, file) : parseMaterialJson(text, file);
}

ParseResult parseMaterialFile(const std::filesystem::path& file) { return readAndParse(file, "material", &parseMaterial); }

}  // namespace hexc
