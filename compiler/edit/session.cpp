#include "session.h"

#include <algorithm>
#include <chrono>

#include "hexc/budgets.h"
#include "hexc/compiler.h"
#include "hexc/files.h"
#include "hexc/histogram.h"
#include "hexc/json_text.h"
#include "hexc/report.h"
#include "hexc/spirv.h"
#include "command.h"
#include "views.h"
#include "vk/render.h"

namespace hexc::edit {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

Reply json(const Json& value, int status = 200) { return {status, value.dump()}; }

Json toJson(const Diagnostic& d) {
    return {{"code", std::string(toString(d.code))},
            {"severity", d.severity == Diagnostic::Severity::Error ? "error" : "warning"},
            {"file", d.loc.file},
            {"line", d.loc.line},
            {"col", d.loc.col},
            {"path", d.path},
            {"message", d.message},
            {"hint", d.hint},
            {"text", d.format()}};
}

Json toJson(const Diagnostics& diags) {
    Json out = Json::array();
    for (const Diagnostic& d : byPosition(diags)) out.push_back(toJson(d));
    return out;
}

// A request the page should never send (not JSON, wrong shape): a diagnostic about the request, status 400.
Reply badRequest(const std::string& what) {
    return json({{"ok", false}, {"diagnostics", toJson(Diagnostics{Diagnostic::make(Code::InputUnreadable, {"request"}, "", what)})}}, 400);
}

// A request's body as JSON, in the page's key order, when it is an object whose "document" is one; nullopt otherwise
// (a request the page never sends), with the reply that refuses it: `expected` says what the request holds.
std::optional<Json> withDocument(const std::string& body, const std::string& expected, Reply* refused) {
    // Checked before parsing: what handles the document (comparing, dumping) recurses once per level.
    if (nestsTooDeep(body)) {
        *refused = badRequest("the request nests deeper than a material may (32 levels)");
        return std::nullopt;
    }
    Json request = Json::parse(body, nullptr, false);
    if (!request.is_object() || !request.contains("document") || !request["document"].is_object()) {
        *refused = badRequest("expected " + expected);
        return std::nullopt;
    }
    return request;
}

// The page's programs: GLSL ES 3.00 for WebGL 2, every setting a uniform (no specialisation, a lattice per slot) so
// that a slider sets one member of the parameter block; packing left out, as it changes no texel and would need the
// packed textures.
CompileOptions pageOptions() {
    CompileOptions o;
    o.targets = {Target::Glsl};
    o.glslEs = true;
    o.glslVersion = 300;
    o.specialise = false;
    o.shareLattice = false;
    o.slotTexturesDecoded = true;  // the page uploads each slot's texture, a KTX2 array's layer decoded (texels())
    o.concurrentTargets = false;
    o.derivedTextures = false;  // served apart (texture()), from the texture as it is when the page asks
    o.lintTextures = false;     // it compiles at every change; `hexc lint` checks the textures
    return o;
}

const OutputFile* fileEndingIn(const CompileResult& r, const std::string& suffix) {
    auto it = std::find_if(r.files.begin(), r.files.end(), [&](const OutputFile& f) { return f.name.ends_with(suffix); });
    return it == r.files.end() ? nullptr : &*it;
}

// A compile of a program for the page, through the session's cache.
CompileResult pageCompile(const Material& m, ShaderCache& cache) {
    CompileOptions options = pageOptions();
    options.cache = &cache;
    return compile(m, options);
}

// A program for the page: the fragment shader and its manifest, or the diagnostics that stopped it.
Json program(const CompileResult& r) {
    if (!r.ok()) return {{"diagnostics", toJson(r.diagnostics)}};
    return {{"fragment", fileEndingIn(r, ".frag.glsl")->contents},
            {"manifest", Json::parse(fileEndingIn(r, ".manifest.json")->contents)},
            {"diagnostics", toJson(r.diagnostics)}};
}

// vk::shownMaterial when the page's GLSL did not compile: the SPIR-V alone says what the template declares, or why the
// material does not compile (a CompileError).
Material shownWithoutGlsl(const Material& m, ShaderCache& cache, std::string* note) {
    CompileOptions options = pageOptions();
    options.cache = &cache;
    return vk::shownMaterial(m, "", options, note);
}

// The shader as `hexc MATERIAL -o DIR` ships it: SPIR-V instructions and texture fetches per pixel, and the time its
// compile took: its first, as `times` remembers it by a hash of the generated code (a structure seen before is a cache
// hit; 16 bytes a structure).
Json shippedCost(const Material& m, ShaderCache& cache, std::map<size_t, double>& times) {
    CompileOptions options;
    options.targets = {Target::Spirv};
    options.derivedTextures = false;  // what they cost is the shader's
    options.lintTextures = false;
    options.cache = &cache;
    const auto start = std::chrono::steady_clock::now();
    CompileResult r = compile(m, options);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (!r.ok()) return nullptr;
    const ShaderOps ops = countOps(disassemble(r.spirv));
    Json cost = {{"fetches", ops.textureSamples},
                 {"instructions", ops.instructions},
                 {"compile_ms", times.try_emplace(std::hash<std::string>{}(r.glsl), ms).first->second}};
    // A layered material: the fetches the layers' blend takes per pixel, at worst and over its splat maps (plan/layers.cpp).
    for (const OutputFile& f : r.files)
        if (f.name.ends_with(".manifest.json") && Json::parse(f.contents).contains("layers"))
            cost["layer_fetches"] = Json::parse(f.contents)["layers"]["fetches_per_pixel"];
    return cost;
}

// Size and modification time of a file, as a version stamp; "-" when it cannot be read.
std::string stamp(const fs::path& file) {
    std::error_code ec;
    const auto size = fs::file_size(file, ec);
    if (ec) return "-";
    const auto time = fs::last_write_time(file, ec);
    return std::to_string(size) + "@" + std::to_string(time.time_since_epoch().count());
}

// A texture's texels for the page: RGBA, 8-bit or float, its size in headers.
Reply texels(const Texture& t) {
    Reply r{200,
            t.isFloat() ? std::string(reinterpret_cast<const char*>(t.rgba32f.data()), t.rgba32f.size() * 4)
                        : std::string(t.rgba8.begin(), t.rgba8.end()),
            "application/octet-stream"};
    r.headers = {{"X-Hexc-Width", std::to_string(t.width)},
                 {"X-Hexc-Height", std::to_string(t.height)},
                 {"X-Hexc-Format", t.isFloat() ? "rgba32f" : "rgba8"}};
    return r;
}

}  // namespace

Session::Session(fs::path material, fs::path root) : file_(std::move(material)), root_(std::move(root)) {
    // A save killed before its rename (SIGKILL runs no handler) left its temporary beside the material, where no build
    // looks: removed when the next edit of the material starts, as a build removes those in its output folder.
    std::error_code ec;
    const fs::path target = fs::is_symlink(file_, ec) ? fs::canonical(file_, ec) : file_;
    removeDeadTemporaries(target.has_parent_path() ? target.parent_path() : ".");
}

Reply Session::material() {
    std::string why;
    std::optional<std::string> text = readFile(file_, &why);
    if (!text) return json({{"diagnostics", toJson({Diagnostic::make(Code::InputUnreadable, {file_.string()}, "", why)})}}, 500);
    // The file's own diagnostics, for the page to show when it is not JSON (it has no document to compile then).
    return json({{"file", file_.string()},
                 {"text", *text},
                 {"version", version()},
                 {"diagnostics", toJson(parseMaterial(*text, file_).diagnostics)}});
}

Session::Parsed Session::parse(const nlohmann::ordered_json& edited) {
    Parsed p;
    // Parsed as it would be written, so that the diagnostics locate into the file as saved.
    std::optional<std::string> onDisk = readFile(file_);
    std::optional<std::string> text = onDisk ? rewriteJsonText(*onDisk, edited) : std::nullopt;
    p.text = text ? *text : edited.dump(2) + "\n";  // a file that is not JSON any more is written anew
    ParseResult parsed = parseMaterial(p.text, file_);
    p.diagnostics = parsed.diagnostics;
    if (parsed.material) {
        Diagnostics outside = confined(*parsed.material);
        p.diagnostics.insert(p.diagnostics.end(), outside.begin(), outside.end());
        if (outside.empty()) p.material = std::move(parsed.material);
    }
    return p;
}

Diagnostics Session::confined(const Material& material) const {
    Diagnostics out;
    std::error_code ec;
    const fs::path root = fs::weakly_canonical(root_, ec);
    for (const Slot& s : material.slots) {
        const fs::path real = fs::weakly_canonical(s.texturePath, ec);  // symlinks resolved
        const auto [r, t] = std::mismatch(root.begin(), root.end(), real.begin(), real.end());
        if (!ec && r == root.end()) continue;
        out.push_back(Diagnostic::make(Code::TextureUnreadable, {file_.string(), s.line, s.col}, "",
                                       "texture `" + s.texture + "` of slot `" + s.name + "` is outside the folder hexc edit serves (" +
                                           root_.string() + "), or is a link out of it",
                                       "--root names a folder that holds it"));
    }
    return out;
}

namespace {

// What decides whether a template declares resources of its own: its text and the macros hexc defines for it from the
// material (docs/templates.md: HEXC_HAS_<slot or role>, HEXC_FIRST_SLOT, HEXC_FIRST_KIND_<kind>,
// HEXC_PROJECTION_<projection>), so a template that declares a resource under one of them is judged per material.
std::string templateKey(const std::string& text, const Material& m) {
    std::string key = text + '\0' + std::string(toString(m.hex.projection));
    for (const Slot& s : m.slots) key += '\0' + s.name + ':' + std::string(toString(s.kind));
    if (m.layers)
        for (const Layers::Role& r : m.layers->roles) key += "\0role " + r.name + ':' + std::string(toString(r.kind));
    return key;
}

}  // namespace

// The views program of `m`, and the material as shown (*note says why its template is not the material's own).
// Whether a template declares resources of its own is read from its first views program's manifest (vk::shownMaterial),
// or from the SPIR-V alone when the page's GLSL does not compile, and remembered by templateKey().
CompileResult Session::viewsCompile(const Material& m, Material* shown, std::string* note) {
    const std::optional<std::string> text = templateText(m.templ);
    const std::optional<std::string> key = text ? std::optional(templateKey(*text, m)) : std::nullopt;
    const auto known = key ? shownTemplates_.find(*key) : shownTemplates_.end();
    *shown = m;
    if (known != shownTemplates_.end()) {
        shown->templ = known->second.templ;
        *note = known->second.note;
        return pageCompile(views_.composed(*shown), cache_);
    }
    CompileResult views = pageCompile(views_.composed(m), cache_);
    *shown = views.ok() ? vk::shownMaterial(m, views, note) : shownWithoutGlsl(m, cache_, note);
    if (key) shownTemplates_[*key] = {shown->templ, *note};
    return note->empty() ? views : pageCompile(views_.composed(*shown), cache_);
}

Reply Session::compile(const std::string& body) {
    Reply refused;
    const std::optional<Json> request = withDocument(body, "{\"document\": the material}", &refused);
    if (!request) return refused;
    std::lock_guard lock(mutex_);
    const auto start = std::chrono::steady_clock::now();
    const size_t before = compiles();
    Parsed p = parse(request->at("document"));
    if (!p.material) return json({{"ok", false}, {"diagnostics", toJson(p.diagnostics)}});
    Material m = *p.material;
    m.pack = false;
    try {
        // One program for the template's shading and every slot's values and weights (views.h), and plain tiling: a
        // structural edit compiles the first; the second only when it changes plain tiling too (a slot's kind,
        // projection, sampling); the shader cache holds the rest.
        Material shown;
        std::string note;
        const CompileResult views = viewsCompile(m, &shown, &note);
        Json slots = Json::array();
        for (const Slot& s : m.slots) slots.push_back(s.name);
        Json programs = {{"views", program(views)}, {"plain", program(pageCompile(vk::plainTiled(shown), cache_))}};
        compiled_ = m;
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        return json({{"ok", true},
                     {"text", p.text},
                     {"diagnostics", toJson(p.diagnostics)},
                     {"template", shown.templ.written()},
                     {"note", note},
                     {"slots", slots},
                     {"programs", programs},
                     {"server", {{"compiles", compiles() - before}, {"ms", ms}}}});
    } catch (const CompileError& e) {
        return json({{"ok", false}, {"diagnostics", toJson(e.diagnostics)}});
    }
}

Reply Session::cost(const std::string& body) {
    Reply refused;
    const std::optional<Json> request = withDocument(body, "{\"document\": the material}", &refused);
    if (!request) return refused;
    std::lock_guard lock(costMutex_);  // not the page's compiles': the cost line follows the new frame, never holds it up
    Parsed p = parse(request->at("document"));
    if (!p.material) return json({{"ok", false}, {"diagnostics", toJson(p.diagnostics)}});
    return json({{"ok", true}, {"cost", shippedCost(*p.material, costCache_, costTimes_)}});
}

Reply Session::save(const std::string& body) {
    const std::string expected = "{\"document\": the material, \"version\": the file's version it was edited from}";
    Reply refused;
    const std::optional<Json> request = withDocument(body, expected, &refused);
    if (!request) return refused;
    if (!request->contains("version")) return badRequest("expected " + expected);
    std::lock_guard lock(mutex_);
    if (request->at("version") != version())
        return json({{"ok", false}, {"conflict", true}, {"message", file_.string() + " changed on disk; it was reloaded"}}, 409);
    Parsed p = parse(request->at("document"));
    if (!p.material) return json({{"ok", false}, {"diagnostics", toJson(p.diagnostics)}, {"message", "not saved: fix the errors first"}});
    try {
        // A material reached through a link is saved where the link leads, and the link stays a link.
        std::error_code ec;
        const std::filesystem::path target = std::filesystem::is_symlink(file_, ec) ? std::filesystem::canonical(file_) : file_;
        command::writeAtomically(target.has_parent_path() ? target.parent_path() : ".", target.filename().string(), p.text);
    } catch (const std::exception& e) {
        return json({{"ok", false}, {"message", e.what()}}, 500);
    }
    return json({{"ok", true}, {"version", version()}, {"text", p.text}});
}

std::optional<Texture> Session::loadSlotTexture(const std::string& name, std::string* whyNot) {
    const size_t dot = name.find('.');
    const std::string slotName = name.substr(0, dot), derived = dot == std::string::npos ? "" : name.substr(dot + 1);
    auto it = std::find_if(compiled_->slots.begin(), compiled_->slots.end(), [&](const Slot& s) { return s.name == slotName; });
    if (it == compiled_->slots.end()) {
        *whyNot = "no slot `" + slotName + "` in the material";
        return std::nullopt;
    }
    // The budgets `hexc preview` keeps, checked from the header before anything is decoded: the page uploads a slot's
    // texture with its mips, and the tables are the histogram blend's precomputation.
    if (std::optional<Diagnostic> over = overTexelBudget(*compiled_, *it, derived.empty() ? vk::kRenderBudget : kHistogramBudget)) {
        *whyNot = over->format();
        return std::nullopt;
    }
    // Raw texels: the page uploads a colour slot's into an sRGB format, which decodes them as it samples.
    if (derived.empty()) return loadTexture(it->texturePath, false, it->textureLayer);
    // The histogram blend's Gaussian texture and look-up table, as hexc writes them beside the shader.
    HistogramTransform h = histogramTransform(loadTexture(it->texturePath, it->colorSpace == ColorSpace::Srgb), *it);
    return derived == "lut" ? std::move(h.lut) : std::move(h.gaussian);
}

Reply Session::texture(const std::string& name) {
    std::lock_guard lock(mutex_);
    if (!compiled_) return {404, "no material compiled yet", "text/plain"};
    if (Diagnostics outside = confined(*compiled_); !outside.empty()) return {403, formatAll(outside), "text/plain"};
    std::string why;
    try {
        if (std::optional<Texture> t = loadSlotTexture(name, &why)) return texels(*t);
    } catch (const TextureError& e) {
        why = e.what();
    }
    return {404, why, "text/plain"};
}

std::string Session::version() {
    std::lock_guard lock(versionMutex_);
    std::string v = stamp(file_);
    if (v != versionFile_) {  // the textures the file names now, parsed again only when the file changed
        versionFile_ = v;
        versionTextures_.clear();
        ParseResult parsed = parseMaterialFile(file_);
        if (parsed.material)
            for (const Slot& s : parsed.material->slots) versionTextures_.push_back(s.texturePath);
    }
    for (const fs::path& texture : versionTextures_) v += "," + stamp(texture);
    return v;
}

}  // namespace hexc::edit
