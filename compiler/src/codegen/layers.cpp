// ShaderPlan::layers -> the weights function and the role functions (templates/library/layers.glsl).
#include "codegen/layers.h"

#include "codegen/codegen.h"
#include "common/by_enum.h"
#include "common/templates.h"

namespace hexc {
namespace {

// A section of layers.glsl expanded, without its final newline.
std::string expandLayers(const std::string& section, const Tokens& values) {
    static const std::map<std::string, std::string> sections = snippetSections("layers.glsl");
    return expandSection(sections, section, values);
}

// `text` without the empty lines left where a token expanded to nothing.
std::string withoutEmptyLines(std::string text) {
    for (size_t empty; (empty = text.find("\n\n")) != std::string::npos;) text.erase(empty, 1);
    return text;
}

class LayerEmitter {
public:
    LayerEmitter(const ShaderPlan& plan, const std::function<std::string(size_t)>& read)
        : plan_(plan), read_(read), color_(vertexColorTokens(plan)) {}

    // Every section with the vertex colour's tokens.
    std::string expand(const std::string& section, Tokens values) const {
        values.insert(color_.begin(), color_.end());
        return expandLayers(section, values);
    }

    // The slot's tiling as the code reads it (the parameter its own coordinates function reads).
    std::string tiling(size_t slot) const {
        const ParamRef& ref = plan_.lattices[plan_.slots[slot].lattice].tiling;
        return ref ? read_(*ref) : "vec2(1.0)";
    }

    // When layer i's slots are fetched: where its weight is positive, or everywhere.
    std::string fetched(size_t i) const {
        return expand(plan_.layers->skip ? "layer.kept" : "layer.every", {{"index", std::to_string(i)}});
    }

    // A line per layer of `section`, for slot `slots[i]` of layer i.
    std::string perLayer(const std::string& section, const std::vector<size_t>& slots) const {
        std::string out;
        for (size_t i = 0; i < slots.size(); ++i)
            out += (out.empty() ? "" : "\n") + expand(section, {{"index", std::to_string(i)},
                                                                {"slot", plan_.slots[slots[i]].name},
                                                                {"tiling", tiling(slots[i])},
                                                                {"fetched", fetched(i)}});
        return out;
    }

    // The fill's line per lattice: its tiles where one of its layers is kept (none in the functions output).
    std::string lattices() const {
        std::string out;
        for (size_t k = 0; !plan_.functions && k < plan_.layers->lattices.size(); ++k) {
            const LayerLatticePlan& l = plan_.layers->lattices[k];
            std::string kept = fetched(l.layers.front());
            for (size_t i = 1; plan_.layers->skip && i < l.layers.size(); ++i) kept += " || " + fetched(l.layers[i]);
            out += (k ? "\n" : "") + expand("weights.lattice", {{"index", std::to_string(k)}, {"kept", kept}, {"tiling", tiling(l.slot)}});
        }
        return out;
    }

    // Layer i's weight before keeping: its splat channel, its vertex colour channel, or their product.
    std::string layerWeight(size_t i) const {
        static constexpr auto kSections = byEnum<LayerWeights::Both>({"weights.layer", "weights.layer.vertex", "weights.layer.both"});
        return expand(kSections[size_t(plan_.layers->weights)],
                      {{"index", std::to_string(i)}, {"splat", std::to_string(i / 4)}, {"channel", std::to_string(i % 4)}});
    }

    // The vertex colour's stage input, when it weighs the layers.
    std::string vertexInput() const {
        const int location = plan_.layers->vertexColorLocation;
        return location < 0 ? "" : expand("vertex.input", {{"location", std::to_string(location)}}) + "\n\n";
    }

    // A setting of the blend: its parameter in general code, else its value as a literal.
    std::string setting(const ParamRef& ref, double value) const { return ref ? read_(*ref) : floatLiteral(value); }

    std::string weights() const {
        const LayersPlan& lp = *plan_.layers;
        std::string splats, keep;
        for (size_t k = 0; k < lp.splats.size(); ++k)
            splats += (k ? "\n" : "") + expand("weights.splat", {{"index", std::to_string(k)}, {"tiling", tiling(lp.splats[k])}});
        for (size_t i = 0; i < lp.count; ++i) keep += (i ? "\n" : "") + layerWeight(i);
        const std::string heights = lp.heights.empty() ? ""
                                                       : expand("weights.heights", {{"layers", perLayer("weights.height", lp.heights)},
                                                                                    {"width", setting(lp.widthParam, lp.width)},
                                                                                    {"skip", setting(lp.skipBelowParam, lp.skipBelow)}});
        // In height mode skipping acts on the height blend's shares (hexcLayerHeights), so every weight above 0 is kept.
        const std::string keepBelow = lp.heights.empty() ? setting(lp.skipBelowParam, lp.skipBelow) : floatLiteral(0.0);
        return withoutEmptyLines(expand(  // no lattices, no heights
            "weights", {{"splats", splats},
                        {"keep", keep},
                        {"keep_below", keepBelow},
                        {"skip", setting(lp.skipBelowParam, lp.skipBelow)},
                        {"lattices", lattices()},
                        {"heights", heights}}));
    }

    std::string role(const LayerRolePlan& r, const std::string& uv) const {
        return expand("role", {{"role", r.name}, {"type", r.type}, {"uv", uv}, {"layers", perLayer("role.layer", r.slots)}});
    }

private:
    const ShaderPlan& plan_;
    const std::function<std::string(size_t)>& read_;
    const Tokens color_;
};

}  // namespace

Tokens vertexColorTokens(const ShaderPlan& plan) {
    const bool parameter = plan.functions && plan.layers && plan.layers->weights != LayerWeights::Splat;
    if (!parameter) return {{"color", "hexcVertexColor"}, {"color_param", ""}, {"color_arg", ""}};
    return {{"color", "color"}, {"color_param", expandLayers("color.parameter", {})}, {"color_arg", expandLayers("color.argument", {})}};
}

std::string layerLattice(const ShaderPlan& plan, size_t index, const std::string& tiles, const std::string& settings) {
    const std::string i = std::to_string(index);
    const std::string text = withoutEmptyLines(expandLayers("lattice", {{"index", i}, {"tiles", tiles}, {"settings", settings}}));
    return text + (plan.functions ? "" : "\n\n" + expandLayers("lattice.shared", {{"index", i}}));
}

std::string layerLatticeCall(const ShaderPlan& plan, size_t index) {
    return expandLayers(plan.functions ? "lattice.call.functions" : "lattice.call", {{"index", std::to_string(index)}});
}

std::string layerFunctions(const ShaderPlan& plan, const std::function<std::string(size_t)>& read, const std::string& uv) {
    if (!plan.layers) return {};
    LayerEmitter emit(plan, read);
    std::string out = emit.vertexInput() + emit.expand("functions", {}) + "\n\n" + emit.weights() + "\n\n" +
                      emit.expand(plan.functions ? "shared.functions" : "shared", {}) + "\n\n";
    for (const LayerRolePlan& r : plan.layers->roles) out += emit.role(r, uv) + "\n\n";
    return out;
}

}  // namespace hexc
