// Material -> MaterialX document: one nodegraph with a texture node per slot, a standard_surface (and a displacement
// shader for a `height` slot) reading them, and hexc_* attributes for the settings MaterialX has no input for, so
// that parseMaterialX reads back the same material (docs/materialx.md).
#include <charconv>
#include <sstream>

#include <pugixml.hpp>

#include "hexc/compiler.h"
#include "common/one_line.h"
#include "hexc/materialx.h"
#include "material/materialx_names.h"

namespace hexc {
namespace {

using pugi::xml_node;

// standard_surface's inputs a slot can feed, with their types; a slot is named after its input as the reader
// names it (base_color -> albedo).
struct SurfaceInput {
    std::string_view name, type;
};
constexpr SurfaceInput kStandardSurface[] = {
    {"base", "float"},
    {"base_color", "color3"},
    {"diffuse_roughness", "float"},
    {"metalness", "float"},
    {"specular", "float"},
    {"specular_color", "color3"},
    {"specular_roughness", "float"},
    {"specular_anisotropy", "float"},
    {"specular_rotation", "float"},
    {"transmission", "float"},
    {"transmission_color", "color3"},
    {"subsurface", "float"},
    {"subsurface_color", "color3"},
    {"subsurface_radius", "color3"},
    {"subsurface_scale", "float"},
    {"sheen", "float"},
    {"sheen_color", "color3"},
    {"sheen_roughness", "float"},
    {"coat", "float"},
    {"coat_color", "color3"},
    {"coat_roughness", "float"},
    {"coat_normal", "vector3"},
    {"thin_film_thickness", "float"},
    {"emission", "float"},
    {"emission_color", "color3"},
    {"opacity", "color3"},
    {"normal", "vector3"},
};

// Shortest text that reads back as the same double.
std::string number(double x) {
    char buf[32];
    auto end = std::to_chars(buf, buf + sizeof buf, x + 0.0).ptr;  // + 0.0: no "-0"
    return std::string(buf, end);
}

// A file name inside an XML comment: on one line (oneLine), and without `--`, which XML does not allow in a comment
// (pugixml writes a comment's text as it is): the second `-` of a pair as `\x2d`.
std::string commentText(std::string_view name) {
    std::string out;
    for (char c : oneLine(name)) out += c == '-' && out.ends_with('-') ? std::string("\\x2d") : std::string(1, c);
    return out;
}

std::string numbers(std::initializer_list<double> xs) {
    std::string out;
    for (double x : xs) out += (out.empty() ? "" : ", ") + number(x);
    return out;
}

class Writer {
public:
    Writer(const Material& m, const std::filesystem::path& outFile)
        : m_(m), dir_(std::filesystem::absolute(outFile).parent_path().lexically_normal()) {}

    MaterialXExport run() {
        xml_node decl = doc_.append_child(pugi::node_declaration);
        decl.append_attribute("version") = "1.0";
        xml_node root = doc_.append_child("materialx");
        root.append_attribute("version") = "1.39";
        root.append_attribute("colorspace") = "lin_rec709";
        root.append_child(pugi::node_comment)
            .set_value((" hexc " + std::string(version()) + ", from " + commentText(m_.sourceFile.filename().string()) +
                        ": hexc_* attributes keep the settings MaterialX has no input for (docs/materialx.md) ")
                           .c_str());
        if (m_.layers) return layered();
        graph_ = element(root, "nodegraph", "NG_" + m_.name);
        surface_ = element(root, "standard_surface", "SR_" + m_.name, "surfaceshader");
        for (size_t i = 0; i < m_.slots.size(); ++i) slot(m_.slots[i], i);
        materialElement(root);
        MaterialXExport out;
        out.diagnostics = std::move(diags_);
        if (hasErrors(out.diagnostics)) return out;
        std::ostringstream text;
        doc_.save(text, "  ", pugi::format_default, pugi::encoding_utf8);
        out.document = text.str();
        if (!out.document->ends_with('\n')) *out.document += '\n';
        return out;
    }

private:
    static xml_node element(xml_node parent, const char* category, const std::string& name, const char* type = nullptr) {
        xml_node e = parent.append_child(category);
        e.append_attribute("name") = name.c_str();
        if (type) e.append_attribute("type") = type;
        return e;
    }
    static xml_node input(xml_node node, const char* name, const char* type, const std::string& value) {
        xml_node in = element(node, "input", name, type);
        in.append_attribute("value") = value.c_str();
        return in;
    }
    // A path as the document's reader resolves it: relative to the .mtlx file's folder.
    std::string relative(const std::filesystem::path& p) const {
        return std::filesystem::absolute(p).lexically_normal().lexically_relative(dir_).generic_string();
    }

    void materialElement(xml_node root) {
        xml_node material = element(root, "surfacematerial", m_.name, "material");
        const TemplateRef& t = m_.templ;
        if (t.file || t.name != TemplateRef{}.name)
            material.append_attribute("hexc_template") = (t.file ? relative(t.name) : t.name).c_str();
        if (m_.hex.projection != Projection::Uv)
            material.append_attribute("hexc_projection") = std::string(toString(m_.hex.projection)).c_str();
        if (m_.hex.planeSharpness != HexTiling{}.planeSharpness)
            material.append_attribute("hexc_planesharpness") = number(m_.hex.planeSharpness).c_str();
        if (m_.pack) material.append_attribute("hexc_pack") = "true";
        element(material, "input", "surfaceshader", "surfaceshader").append_attribute("nodename") = surface_.attribute("name").value();
        if (displacement_)
            element(material, "input", "displacementshader", "displacementshader").append_attribute("nodename") =
                displacement_.attribute("name").value();
    }

    // MaterialX has no node for a splat-map blend of slot sets: writing the slots would flatten the layers.
    MaterialXExport layered() const {
        const Slot& first = m_.slots[m_.layers->layers.front().slots.front()];
        MaterialXExport out;
        out.diagnostics.push_back(Diagnostic::make(Code::MaterialXUnsupported, {m_.sourceFile.string(), first.line, first.col}, "/layers",
                                                   "a layered material has no MaterialX form (its splat-map blend)",
                                                   "export each layer as a material of its own"));
        return out;
    }
    void slot(const Slot& s, size_t index);
    xml_node target(const Slot& s, size_t index, std::string& input);
    void hexInputs(xml_node node, const Slot& s);
    void hexcAttributes(xml_node node, const Slot& s);
    void report(const Slot& s, size_t index, std::string message, std::string hint = {}) {
        diags_.push_back(Diagnostic::make(Code::MaterialXUnsupported, {m_.sourceFile.string(), s.line, s.col},
                                          "/slots/" + std::to_string(index), std::move(message), std::move(hint)));
    }

    const Material& m_;
    std::filesystem::path dir_;
    pugi::xml_document doc_;
    xml_node graph_, surface_, displacement_;
    Diagnostics diags_;
};

// The shader and input a slot feeds: the one whose slot the reader names `s.name` (mtlx::slotName).
xml_node Writer::target(const Slot& s, size_t index, std::string& input) {
    const std::string type = kindRow(s.kind).mtlxType;
    if (kindRow(s.kind).oneChannel && mtlx::slotName("displacement", "displacement") == s.name) {
        if (!displacement_) displacement_ = element(doc_.document_element(), "displacement", "DS_" + m_.name, "displacementshader");
        input = "displacement";
        return displacement_;
    }
    for (const SurfaceInput& in : kStandardSurface) {
        if (mtlx::slotName("standard_surface", in.name) != s.name) continue;
        if (in.type != type)
            report(s, index,
                   "slot `" + s.name + "` feeds standard_surface `" + std::string(in.name) + "`, a " + std::string(in.type) + ", but a " +
                       std::string(toString(s.kind)) + " slot is a " + type);
        input = in.name;
        return surface_;
    }
    report(s, index, "slot `" + s.name + "` has no standard_surface input to feed",
           "name it albedo, roughness, normal, height (a displacement) or after a standard_surface input such as metalness");
    return {};
}

void Writer::slot(const Slot& s, size_t index) {
    std::string feeds;
    xml_node shader = target(s, index, feeds);
    if (!shader) return;
    const bool hex = s.hex.enabled;
    const SlotKindRow& kind = kindRow(s.kind);
    const char* category = hex ? (kind.derivative ? "hextilednormalmap" : "hextiledimage") : "tiledimage";
    // A one-channel kind reads the texture's four channels and extracts its own.
    xml_node node = element(graph_, category, s.name, kind.oneChannel ? "color4" : kind.mtlxType);
    xml_node file = input(node, "file", "filename", relative(s.texturePath));
    if (s.colorSpace == ColorSpace::Srgb && !kind.derivative) file.append_attribute("colorspace") = "srgb_texture";
    if (hex)
        hexInputs(node, s);
    else
        input(node, "uvtiling", "vector2", numbers({s.hex.tiling[0], s.hex.tiling[1]}));
    hexcAttributes(node, s);
    std::string last = s.name;
    if (kind.oneChannel) {
        xml_node extract = element(graph_, "extract", s.name + "_channel", "float");
        element(extract, "input", "in", "color4").append_attribute("nodename") = last.c_str();
        input(extract, "index", "integer", std::to_string(s.channel));
        last = s.name + "_channel";
    } else if (kind.derivative && !hex) {
        xml_node normalmap = element(graph_, "normalmap", s.name + "_normalmap", "vector3");
        element(normalmap, "input", "in", "vector3").append_attribute("nodename") = last.c_str();
        last = s.name + "_normalmap";
    }
    element(graph_, "output", s.name + "_out", kind.mtlxType).append_attribute("nodename") = last.c_str();
    xml_node in = element(shader, "input", feeds.c_str(), kind.mtlxType);
    in.append_attribute("nodegraph") = graph_.attribute("name").value();
    in.append_attribute("output") = (s.name + "_out").c_str();
}

// MaterialX draws angle A + (B - A) u R, scale 1 + (lo + (hi - lo) u - 1) S, offset olo + (ohi - olo) u O; hexc
// (a + (b - a) u) rotation, a + (b - a) u, u offset. The values below give the same functions of u, and the ones
// the reader derives from them are hexc's again.
void Writer::hexInputs(xml_node node, const Slot& s) {
    const HexTiling& h = s.hex;
    const double r = h.rotation, a = h.rotationRange[0], b = h.rotationRange[1];
    input(node, "tiling", "vector2", numbers({h.tiling[0], h.tiling[1]}));
    input(node, "rotation", "float", number(r));
    input(node, "rotationrange", "vector2", r == 1 ? numbers({a, b}) : r == 0 ? numbers({0, b - a}) : numbers({a * r, a * r + (b - a)}));
    input(node, "scale", "float", "1");
    input(node, "scalerange", "vector2", numbers({h.scaleRange[0], h.scaleRange[1]}));
    input(node, "offset", "float", number(h.offset));
    input(node, "offsetrange", "vector2", "0, 1");
    input(node, "falloff", "float", number(h.falloff));
    if (kindRow(s.kind).derivative) {
        input(node, "flip_g", "boolean", s.flipY ? "true" : "false");
        return;
    }
    input(node, "falloffcontrast", "float", number(h.falloffcontrast));
    const std::array<double, 3> luma = h.mode == HashMode::MaterialX ? h.lumacoeffs : mtlx::kLuma;
    input(node, "lumacoeffs", "color3", numbers({luma[0], luma[1], luma[2]}));
}

// Settings MaterialX has no input for, where they differ from hexc's defaults.
void Writer::hexcAttributes(xml_node node, const Slot& s) {
    const HexTiling& h = s.hex;
    const HexTiling d;
    auto put = [&](const char* key, const std::string& value) {
        node.append_attribute(("hexc_" + std::string(key)).c_str()) = value.c_str();
    };
    if (h.mode != HashMode::MaterialX) put("mode", std::string(toString(h.mode)));  // a document's default is MaterialX's
    if (h.enabled) {
        if (h.exponent != d.exponent) put("exponent", number(h.exponent));
        if (h.splitCoordinates) put("split_coordinates", "true");
        if (h.rotationSteps != d.rotationSteps) put("rotationsteps", std::to_string(h.rotationSteps));
        if (h.offsetSteps != d.offsetSteps) put("offsetsteps", numbers({double(h.offsetSteps[0]), double(h.offsetSteps[1])}));
        if (h.mask != d.mask) put("mask", std::string(toString(h.mask)));
        if (h.maskScale != d.maskScale) put("maskscale", std::to_string(h.maskScale));
        if (h.taps != d.taps) put("taps", h.adaptive() ? "adaptive" : std::to_string(h.taps));
        if (h.blend != d.blend) put("blend", std::string(toString(h.blend)));
        if (h.lod != d.lod) put("lod", std::string(toString(h.lod)));
        if (kindRow(s.kind).derivative && h.falloffcontrast != d.falloffcontrast) put("falloffcontrast", number(h.falloffcontrast));
    } else if (s.flipY) {
        put("flip_y", "true");
    }
    if (s.heightBlend) {
        put("height_blend", s.heightBlend->slot);
        put("height_blend_width", number(s.heightBlend->width));
    }
}

}  // namespace

MaterialXExport exportMaterialX(const Material& m, const std::filesystem::path& outFile) { return Writer(m, outFile).run(); }

}  // namespace hexc
