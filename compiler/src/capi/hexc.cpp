// The C API (hexc/hexc.h) over the C++ one: handles own C++ values, and no exception crosses into C.
#include "hexc/hexc.h"

#include <filesystem>
#include <memory>
#include <new>
#include <set>
#include <string>
#include <vector>

#include "hexc/compiler.h"
#include "hexc/engines.h"
#include "hexc/material.h"
#include "capi/handles.h"

struct hexc_options {
    hexc::CompileOptions options;
    std::vector<std::string> engines;  // a package per engine instead of shaders (hexc/engines.h)
    std::string error;
};

namespace hexc {
namespace {

std::vector<std::string> commaSeparated(std::string_view list) {
    std::vector<std::string> items;
    for (size_t start = 0; start <= list.size();) {
        const size_t end = std::min(list.find(',', start), list.size());
        items.emplace_back(list.substr(start, end - start));
        start = end + 1;
    }
    return items;
}

// The targets of a "targets" option, or why not.
std::string setTargets(CompileOptions& o, std::string_view value) {
    std::vector<Target> targets;
    for (const std::string& name : commaSeparated(value)) {
        const std::optional<Target> t = targetNamed(name);
        if (!t) return "`" + name + "` is not a target hexc writes: spirv, hlsl, glsl, msl, wgsl";
        targets.push_back(*t);
    }
    o.targets = targets;
    return "";
}

std::string setEngines(std::vector<std::string>& out, std::string_view value) {
    std::vector<std::string> engines = value.empty() ? std::vector<std::string>{} : commaSeparated(value);
    for (const std::string& name : engines)
        if (!engineNamed(name)) return "hexc has no package for engine `" + name + "`";
    out = engines;
    return "";
}

std::string setFlag(bool& flag, std::string_view value) {
    if (value != "0" && value != "1") return "expected 1 or 0, got `" + std::string(value) + "`";
    flag = value == "1";
    return "";
}

std::string setShaderModel(CompileOptions& o, const std::string& value) {
    static const std::set<std::string> models = {"50", "51", "60", "61", "62", "63", "64", "65", "66"};
    if (!models.count(value)) return "`" + value + "` is not a shader model hexc emits: 50, 51, 60 ... 66";
    o.hlslShaderModel = uint32_t(std::stoul(value));
    return "";
}

std::string setGlslVersion(CompileOptions& o, const std::string& value) {
    static const std::set<std::string> versions = {"460", "450", "330", "310es", "300es"};
    if (!versions.count(value)) return "`" + value + "` is not a GLSL version hexc emits: 460, 450, 330, 310es, 300es";
    o.glslEs = value.ends_with("es");
    o.glslVersion = uint32_t(std::stoul(value));
    return "";
}

std::string setOption(CompileOptions& o, std::vector<std::string>& engines, const std::string& key, const std::string& value) {
    if (key == "targets") return setTargets(o, value);
    if (key == "engines") return setEngines(engines, value);
    if (key == "hlsl-sm") return setShaderModel(o, value);
    if (key == "glsl-version") return setGlslVersion(o, value);
    if (key == "bake") return setFlag(o.bake, value);
    if (key == "debug") return setFlag(o.debug, value);
    if (key == "vertex") return setFlag(o.vertex, value);
    if (key == "uv-origin") {
        if (value != "top-left" && value != "bottom-left") return "expected top-left or bottom-left, got `" + value + "`";
        o.uvOrigin = value == "top-left" ? UvOrigin::TopLeft : UvOrigin::BottomLeft;
        return "";
    }
    if (key == "no-specialise") {
        bool off = !o.specialise;
        std::string why = setFlag(off, value);
        o.specialise = !off;
        return why;
    }
    if (key == "entry") {
        if (!isEntryPointName(value)) return "expected an identifier (not reserved), got `" + value + "`";
        o.entryPoint = value;
        return "";
    }
    return "unknown option `" + key + "`";
}

}  // namespace

namespace capi {

void makeViews(hexc_result& r) {
    if (r.text.empty()) r.text = formatAll(r.diagnostics);
    for (const OutputFile& f : r.files)
        r.outputs.push_back({f.name.c_str(), reinterpret_cast<const unsigned char*>(f.contents.data()), f.contents.size()});
    for (const Diagnostic& d : r.diagnostics) r.codes.emplace_back(toString(d.code));
    for (size_t i = 0; i < r.diagnostics.size(); ++i) {
        const Diagnostic& d = r.diagnostics[i];
        const hexc_severity severity = d.severity == Diagnostic::Severity::Error ? HEXC_SEVERITY_ERROR : HEXC_SEVERITY_WARNING;
        r.views.push_back(
            {r.codes[i].c_str(), severity, d.loc.file.c_str(), d.loc.line, d.loc.col, d.path.c_str(), d.message.c_str(), d.hint.c_str()});
    }
    if (!r.pixels.empty()) r.image.rgba = r.pixels.data();
}

}  // namespace capi

namespace {

// A parsed material compiled, with the diagnostics of both steps in the order the command line prints them: the
// parse's (with the template's problems when the material has errors, as the command line reports them), then the
// compile's.
hexc_status finish(ParseResult parsed, hexc_context& context, const hexc_options* options, hexc_result** result) {
    CompileOptions o = options ? options->options : CompileOptions{};
    const std::vector<std::string> engines = options ? options->engines : std::vector<std::string>{};
    o.cache = &context.cache;
    if (parsed.partial) {
        const Diagnostics t = checkTemplate(*parsed.partial, o);
        parsed.diagnostics.insert(parsed.diagnostics.end(), t.begin(), t.end());
    }
    auto r = std::make_unique<hexc_result>();
    r->diagnostics = byPosition(std::move(parsed.diagnostics));
    if (parsed.material) {
        CompileResult compiled = engines.empty() ? compile(*parsed.material, o) : compilePackages(*parsed.material, engines, o);
        for (Diagnostic& d : byPosition(std::move(compiled.diagnostics))) r->diagnostics.push_back(std::move(d));
        r->files = std::move(compiled.files);
    }
    capi::makeViews(*r);
    const bool ok = !hasErrors(r->diagnostics);
    *result = r.release();
    return ok ? HEXC_OK : HEXC_INVALID_INPUT;
}

// Runs `body`, turning what it throws into a status: C cannot catch it.
template <typename Body>
hexc_status guarded(hexc_result** result, Body body) {
    if (result) *result = nullptr;
    try {
        return body();
    } catch (const std::bad_alloc&) {
        return HEXC_OUT_OF_MEMORY;
    }
}

}  // namespace
}  // namespace hexc

extern "C" {

const char* hexc_status_string(hexc_status status) {
    switch (status) {
        case HEXC_OK:
            return "ok";
        case HEXC_INVALID_INPUT:
            return "invalid input";
        case HEXC_BAD_ARGUMENT:
            return "bad argument";
        case HEXC_VERSION_MISMATCH:
            return "API version mismatch";
        case HEXC_OUT_OF_MEMORY:
            return "out of memory";
        case HEXC_NO_VULKAN:
            return "no Vulkan device";
        case HEXC_WRITE_FAILED:
            return "an output could not be written";
        case HEXC_CANCELLED:
            return "cancelled";
    }
    return "unknown status";
}

unsigned hexc_api_version(void) { return HEXC_API_VERSION; }

const char* hexc_version(void) { return hexc::version(); }

hexc_status hexc_context_create(unsigned api_version, const char* cache_dir, hexc_context** context) {
    if (!context) return HEXC_BAD_ARGUMENT;
    *context = nullptr;
    // Same major, and the program's header no newer than the library (hexc.h, "Versions").
    if (api_version >> 16 != HEXC_API_VERSION_MAJOR || (api_version & 0xffff) > HEXC_API_VERSION_MINOR) return HEXC_VERSION_MISMATCH;
    try {
        *context = new hexc_context{hexc::ShaderCache(cache_dir ? std::filesystem::path(cache_dir) : hexc::defaultCacheDir())};
        return HEXC_OK;
    } catch (const std::bad_alloc&) {
        return HEXC_OUT_OF_MEMORY;
    }
}

void hexc_context_free(hexc_context* context) {
    if (!context) return;
    if (context->cache.stats().misses) context->cache.trim();  // only what was stored can take the folder past its bound
    delete context;
}

void hexc_context_cache_stats(const hexc_context* context, size_t* hits, size_t* misses) {
    const hexc::ShaderCache::Stats s = context ? context->cache.stats() : hexc::ShaderCache::Stats{};
    if (hits) *hits = s.hits;
    if (misses) *misses = s.misses;
}

hexc_options* hexc_options_create(void) { return new (std::nothrow) hexc_options; }

hexc_status hexc_options_set(hexc_options* options, const char* key, const char* value) {
    if (!options) return HEXC_BAD_ARGUMENT;
    try {
        options->error =
            !key || !value ? "an option's key and value must not be null" : hexc::setOption(options->options, options->engines, key, value);
        if (!options->error.empty() && key) options->error = std::string(key) + ": " + options->error;
        return options->error.empty() ? HEXC_OK : HEXC_BAD_ARGUMENT;
    } catch (const std::bad_alloc&) {
        return HEXC_OUT_OF_MEMORY;
    }
}

const char* hexc_options_error(const hexc_options* options) { return options ? options->error.c_str() : ""; }

void hexc_options_free(hexc_options* options) { delete options; }

hexc_status hexc_compile_file(hexc_context* context, const char* path, const hexc_options* options, hexc_result** result) {
    return hexc::guarded(result, [&] {
        if (!context || !path || !result) return HEXC_BAD_ARGUMENT;
        return hexc::finish(hexc::parseMaterialFile(path), *context, options, result);
    });
}

hexc_status hexc_compile_memory(hexc_context* context, const char* text, size_t size, const char* name, const char* base_dir,
                                const hexc_options* options, hexc_result** result) {
    return hexc::guarded(result, [&] {
        if (!context || (!text && size) || !result) return HEXC_BAD_ARGUMENT;
        const std::filesystem::path file = std::filesystem::path(base_dir ? base_dir : "") / (name ? name : "material.json");
        return hexc::finish(hexc::parseMaterial(std::string_view(text ? text : "", size), file), *context, options, result);
    });
}

int hexc_result_ok(const hexc_result* result) { return result && !hexc::hasErrors(result->diagnostics); }

size_t hexc_result_output_count(const hexc_result* result) { return result ? result->outputs.size() : 0; }

const hexc_output* hexc_result_output(const hexc_result* result, size_t index) {
    return result && index < result->outputs.size() ? &result->outputs[index] : nullptr;
}

size_t hexc_result_diagnostic_count(const hexc_result* result) { return result ? result->views.size() : 0; }

const hexc_diagnostic* hexc_result_diagnostic(const hexc_result* result, size_t index) {
    return result && index < result->views.size() ? &result->views[index] : nullptr;
}

const char* hexc_result_diagnostics_text(const hexc_result* result) { return result ? result->text.c_str() : ""; }

const hexc_image* hexc_result_image(const hexc_result* result) { return result && result->image.rgba ? &result->image : nullptr; }

void hexc_result_free(hexc_result* result) { delete result; }

}  // extern "C"
