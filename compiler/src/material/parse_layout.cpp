// A layout file -> ResourceLayout: each target's object of whole numbers, every key optional; the table of its fields.
#include "hexc/layout.h"
#include "material/rules.h"

namespace hexc {
namespace {

class LayoutValidator : public JsonRules {
public:
    using JsonRules::JsonRules;

    // A layout file: each target's object of whole numbers, every key optional.
    ResourceLayout runLayout(const json& doc) {
        ResourceLayout layout;
        layout.sourceFile = file_;
        duplicateKeys();
        if (!doc.is_object()) {
            report(Code::WrongType, "", "expected a layout object, got " + typeName(doc));
            return layout;
        }
        std::vector<std::string> keys{"$schema"};
        for (const LayoutField& f : layoutFields())
            if (keys.back() != f.target) keys.push_back(f.target);
        checkKeys(doc, "", keys);
        for (size_t i = 1; i < keys.size(); ++i) {
            const std::string p = "/" + keys[i];
            if (!doc.contains(keys[i])) continue;
            const json& t = doc[keys[i]];
            if (!t.is_object()) {
                report(Code::WrongType, p, "expected an object, got " + typeName(t));
                continue;
            }
            std::vector<std::string> names;
            for (const LayoutField& f : layoutFields())
                if (f.target == keys[i]) names.push_back(f.key);
            checkKeys(t, p, names);
            for (const LayoutField& f : layoutFields())
                if (f.target == keys[i] && t.contains(f.key)) {
                    const Range range{0, double(f.max), false, false, "in [0, " + std::to_string(f.max) + "]"};
                    f.field(layout) = uint32_t(whole(t[f.key], p + "/" + f.key, range, 0));
                }
        }
        return layout;
    }
};

}  // namespace

LayoutParseResult parseLayout(std::string_view text, const std::filesystem::path& file) {
    return validate(text, file, &LayoutParseResult::layout, &LayoutValidator::runLayout);
}

LayoutParseResult parseLayoutFile(const std::filesystem::path& file) { return readAndParse(file, "layout", &parseLayout); }

const std::vector<LayoutField>& layoutFields() {
    using L = ResourceLayout;
    // Vulkan guarantees 4 descriptor sets (31 leaves room); 4095 keeps every other index well inside what targets accept.
    static const std::vector<LayoutField> fields = {
        {"vulkan", "set", 31, "hexc's Vulkan descriptor set, 0 to 31 (default 0)", [](L& l) -> uint32_t& { return l.vulkan.set; }},
        {"vulkan", "binding", 4095, "hexc's first Vulkan binding: block, sampler, textures (default 0)",
         [](L& l) -> uint32_t& { return l.vulkan.binding; }},
        {"vulkan", "combined", 1, "1: hexc's SPIR-V textures as combined image samplers, no sampler (default 0)",
         [](L& l) -> uint32_t& { return l.vulkan.combined; }},
        {"hlsl", "space", 4095, "hexc's HLSL register space (needs --hlsl-sm 51+)", [](L& l) -> uint32_t& { return l.hlsl.space; }},
        {"hlsl", "b", 4095, "hexc's first HLSL b register", [](L& l) -> uint32_t& { return l.hlsl.b; }},
        {"hlsl", "t", 4095, "hexc's first HLSL t register", [](L& l) -> uint32_t& { return l.hlsl.t; }},
        {"hlsl", "s", 4095, "hexc's first HLSL s register", [](L& l) -> uint32_t& { return l.hlsl.s; }},
        {"hlsl", "u", 4095, "first HLSL u register (template storage)", [](L& l) -> uint32_t& { return l.hlsl.u; }},
        {"hlsl", "template_b", 4095, "the template's first HLSL b register (default: after hexc's)",
         [](L& l) -> uint32_t& { return l.hlsl.templateB; }},
        {"hlsl", "template_t", 4095, "the template's first HLSL t register (default: after hexc's)",
         [](L& l) -> uint32_t& { return l.hlsl.templateT; }},
        {"hlsl", "template_s", 4095, "the template's first HLSL s register (default: after hexc's)",
         [](L& l) -> uint32_t& { return l.hlsl.templateS; }},
        {"hlsl", "template_u", 4095, "the template's first HLSL u register (default: after hexc's)",
         [](L& l) -> uint32_t& { return l.hlsl.templateU; }},
        {"hlsl", "template_spaces", 1, "1: a template resource in Vulkan set N in HLSL space N (needs --hlsl-sm 51+)",
         [](L& l) -> uint32_t& { return l.hlsl.templateSpaces; }},
        {"msl", "buffer", 4095, "hexc's first MSL buffer index", [](L& l) -> uint32_t& { return l.msl.buffer; }},
        {"msl", "texture", 4095, "hexc's first MSL texture index", [](L& l) -> uint32_t& { return l.msl.texture; }},
        {"msl", "sampler", 4095, "hexc's first MSL sampler index", [](L& l) -> uint32_t& { return l.msl.sampler; }},
        {"msl", "template_buffer", 4095, "the template's first MSL buffer index (default: after hexc's)",
         [](L& l) -> uint32_t& { return l.msl.templateBuffer; }},
        {"msl", "template_texture", 4095, "the template's first MSL texture index (default: after hexc's)",
         [](L& l) -> uint32_t& { return l.msl.templateTexture; }},
        {"msl", "template_sampler", 4095, "the template's first MSL sampler index (default: after hexc's)",
         [](L& l) -> uint32_t& { return l.msl.templateSampler; }},
        {"msl", "argument_buffers", 1, "1: a Metal argument buffer per descriptor set (default 0)",
         [](L& l) -> uint32_t& { return l.msl.argumentBuffers; }},
        {"glsl", "binding", 4095, "hexc's GLSL block binding and first texture unit", [](L& l) -> uint32_t& { return l.glsl.binding; }}};
    return fields;
}

std::string toString(const ResourceLayout& l) {
    auto n = [](uint32_t v) { return std::to_string(v); };
    // Template bases only when set, so that a layout without them reads (and stamps) as before.
    auto base = [](const char* key, uint32_t v) {
        return v == ResourceLayout::kAfterHexc ? "" : " template_" + std::string(key) + std::to_string(v);
    };
    return "vulkan " + n(l.vulkan.set) + "/" + n(l.vulkan.binding) + (l.vulkan.combined ? " combined" : "") + " hlsl space" +
           n(l.hlsl.space) + " b" + n(l.hlsl.b) + " t" + n(l.hlsl.t) + " s" + n(l.hlsl.s) + " u" + n(l.hlsl.u) +
           base("b", l.hlsl.templateB) + base("t", l.hlsl.templateT) + base("s", l.hlsl.templateS) + base("u", l.hlsl.templateU) +
           (l.hlsl.templateSpaces ? " template_spaces" : "") + " msl " + n(l.msl.buffer) + "/" + n(l.msl.texture) + "/" + n(l.msl.sampler) +
           base("buffer", l.msl.templateBuffer) + base("texture", l.msl.templateTexture) + base("sampler", l.msl.templateSampler) +
           (l.msl.argumentBuffers ? " argument buffers" : "") + " glsl " + n(l.glsl.binding);
}

}  // namespace hexc
