#include "plan/template_fit.h"

#include <algorithm>
#include <sstream>

namespace hexc {
namespace {

constexpr std::string_view kMarker = "// hexc slot ";

std::string kindName(SlotKind kind) { return std::string(toString(kind)); }

}  // namespace

std::vector<TemplateSlot> readTemplateSlots(const std::string& source, const std::string& file, Diagnostics& diagnostics) {
    std::vector<TemplateSlot> out;
    std::istringstream in(source);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        size_t at = line.find_first_not_of(" \t");
        if (at == std::string::npos || line.compare(at, kMarker.size(), kMarker) != 0) continue;
        std::istringstream words(line.substr(at + kMarker.size()));
        std::string name, kind, extra, more;
        words >> name >> kind >> extra >> more;
        TemplateSlot slot{name, SlotKind::Color, extra == "required"};
        bool known = false;
        std::string kinds;  // as the message lists them: color|scalar|normal
        for (const SlotKindRow& row : kindRows()) {
            if (kind == row.name) slot.kind = row.kind, known = true;
            kinds += (kinds.empty() ? "" : "|") + std::string(row.name);
        }
        if (name.empty() || !known || !(extra.empty() || slot.required) || !more.empty()) {
            diagnostics.push_back(
                Diagnostic::make(Code::TemplateSlotLine, {file, number, int(at) + 1}, "",
                                 "expected `// hexc slot <name> <" + kinds + "> [required]`, got `" + line.substr(at) + "`"));
            continue;
        }
        out.push_back(std::move(slot));
    }
    return out;
}

Diagnostics checkTemplateFit(const std::vector<TemplateSlot>& declared, const Material& material, const std::string& templateName) {
    Diagnostics out;
    for (const TemplateSlot& t : declared) {
        bool found = false;
        for (size_t i = 0; i < material.slots.size(); ++i) {
            const Slot& s = material.slots[i];
            if (s.name != t.name) continue;
            found = true;
            if (s.kind != t.kind && s.kindStated)
                out.push_back(Diagnostic::make(Code::TemplateMismatch, {material.sourceFile.string(), s.line, s.col},
                                               "/slots/" + std::to_string(i) + "/kind",
                                               "template `" + templateName + "` reads `" + s.name + "` as a " + kindName(t.kind) +
                                                   " slot; this one is `" + kindName(s.kind) + "`"));
        }
        // A layered material's roles are read as slots (hexc_<role>).
        if (material.layers)
            for (const Layers::Role& r : material.layers->roles) {
                if (r.name != t.name) continue;
                found = true;
                if (r.kind != t.kind)
                    out.push_back(Diagnostic::make(Code::TemplateMismatch, {material.sourceFile.string()}, "/layers",
                                                   "template `" + templateName + "` reads `" + r.name + "` as a " + kindName(t.kind) +
                                                       " slot; the layers' role is `" + kindName(r.kind) + "`"));
            }
        if (!found && t.required)
            out.push_back(Diagnostic::make(Code::TemplateMismatch, {material.sourceFile.string()}, "/slots",
                                           "template `" + templateName + "` needs a " + kindName(t.kind) + " slot named `" + t.name + "`"));
    }
    return out;
}

Diagnostic readsNoSlot(const std::vector<TemplateSlot>& declared, const Material& material, const std::string& templateName) {
    // What the template could read: the material's own slots (they come first) and a layered material's roles.
    const size_t own = material.layers ? material.layers->layers.front().slots.front() : material.slots.size();
    std::vector<TemplateSlot> offered;
    for (size_t i = 0; i < own; ++i) offered.push_back({material.slots[i].name, material.slots[i].kind});
    if (material.layers)
        for (const Layers::Role& r : material.layers->roles) offered.push_back({r.name, r.kind});
    auto listed = [](const std::vector<TemplateSlot>& slots, bool kinds) {
        std::string out;
        for (size_t i = 0; i < slots.size(); ++i)
            out += std::string(i == 0                  ? ""
                               : i + 1 == slots.size() ? " and "
                                                       : ", ") +
                   "`" + slots[i].name + "`" + (kinds ? " (" + kindName(slots[i].kind) + ")" : "");
        return out;
    };
    const TemplateSlot& first = offered.front();
    const auto same = std::find_if(declared.begin(), declared.end(), [&](const TemplateSlot& t) { return t.kind == first.kind; });
    const std::string rename = same == declared.end() ? "" : "rename `" + first.name + "` to `" + same->name + "`, which it reads, ";
    const Slot& at = material.slots.front();  // an own slot, else the first layer's first
    return Diagnostic::make(
        Code::TemplateMismatch, {material.sourceFile.string(), at.line, at.col}, own > 0 ? "/slots/0" : "/layers/0/slots/0",
        "template `" + templateName + "` reads none of this material's slots (" + listed(offered, false) +
            "), so its picture would show nothing of the material: a template reads a slot by its name "
            "(`hexc_<name>`), and this one reads " +
            (declared.empty() ? "no slot it declares" : listed(declared, true)),
        rename + "pass --template with a template that reads `" + first.name + "`, or show it alone with `hexc render --output " +
            (kindRow(first.kind).derivative ? "normal" : "albedo") + " --slot " + first.name + "`");
}

}  // namespace hexc
