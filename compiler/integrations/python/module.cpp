// hexc._hexc: the C API (hexc/hexc.h) for Python, with the interpreter lock released while a material compiles, so
// that threads compile at once. The package's __init__.py turns what it returns into the module's types.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <exception>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "hexc/hexc.h"

namespace py = pybind11;

namespace {

// Owners of the C API's handles, each freed with its own function.
template <typename T, void (*Free)(T*)>
struct Freer {
    void operator()(T* p) const { Free(p); }
};
using ContextPtr = std::unique_ptr<hexc_context, Freer<hexc_context, hexc_context_free>>;
using OptionsPtr = std::unique_ptr<hexc_options, Freer<hexc_options, hexc_options_free>>;
using ResultPtr = std::unique_ptr<hexc_result, Freer<hexc_result, hexc_result_free>>;

class Context {
public:
    // `cacheDir` None: the command line's default folder; "": memory only.
    explicit Context(const std::optional<std::string>& cacheDir) {
        hexc_context* c = nullptr;
        const hexc_status s = hexc_context_create(HEXC_API_VERSION, cacheDir ? cacheDir->c_str() : nullptr, &c);
        if (s != HEXC_OK) throw std::runtime_error(std::string("hexc: cannot create a context: ") + hexc_status_string(s));
        context_.reset(c);
    }

    // (ok, [(name, bytes)], [(code, error, file, line, column, path, message, fix)], formatted diagnostics). A material
    // in memory when `inMemory`, with `name` and `baseDir` as hexc_compile_memory takes them; else the file `source`.
    py::tuple compile(const std::string& source, bool inMemory, const std::string& name, const std::string& baseDir,
                      const std::vector<std::pair<std::string, std::string>>& options) {
        OptionsPtr o(hexc_options_create());
        if (!o) throw std::bad_alloc();
        for (const auto& [key, value] : options)
            if (hexc_options_set(o.get(), key.c_str(), value.c_str()) != HEXC_OK) throw py::value_error(hexc_options_error(o.get()));
        hexc_result* r = nullptr;
        hexc_status s;
        {
            py::gil_scoped_release unlocked;  // the strings above are copies the interpreter does not touch
            s = inMemory ? hexc_compile_memory(context_.get(), source.data(), source.size(), name.c_str(),
                                               baseDir.empty() ? nullptr : baseDir.c_str(), o.get(), &r)
                         : hexc_compile_file(context_.get(), source.c_str(), o.get(), &r);
        }
        const ResultPtr result = owned(s, r);
        return toPython(r);
    }

    // (status, image as a (height, width, 4) float32 array or None, diagnostics, text) of `hexc render ARGS`, or of
    // `hexc preview ARGS` when `preview`.
    py::tuple picture(bool preview, const std::vector<std::string>& args) {
        const std::vector<const char*> argv = pointers(args);
        hexc_result* r = nullptr;
        hexc_status s;
        {
            py::gil_scoped_release unlocked;
            s = (preview ? hexc_preview : hexc_render)(context_.get(), argv.data(), argv.size(), &r);
        }
        const ResultPtr result = owned(s, r);
        py::object image = py::none();
        if (const hexc_image* i = hexc_result_image(r)) {
            py::array_t<float> pixels({py::ssize_t(i->height), py::ssize_t(i->width), py::ssize_t(4)});
            std::memcpy(pixels.mutable_data(), i->rgba, size_t(i->width) * size_t(i->height) * 4 * sizeof(float));
            image = std::move(pixels);
        }
        return py::make_tuple(int(s), image, diagnostics(r), std::string(hexc_result_diagnostics_text(r)));
    }

    // (status, diagnostics, text) of `hexc ARGS`, calling `progress(done, total, name)` (None: nothing) as compiles
    // finish. What `progress` raises stops the build and is raised here.
    py::tuple build(const std::vector<std::string>& args, py::object progress) {
        const std::vector<const char*> argv = pointers(args);
        Progress call{std::move(progress), {}};
        hexc_result* r = nullptr;
        hexc_status s;
        {
            py::gil_scoped_release unlocked;
            s = hexc_build(context_.get(), argv.data(), argv.size(), call.function.is_none() ? nullptr : &Progress::call, &call, &r);
        }
        const ResultPtr result = owned(s, r);
        if (call.raised) std::rethrow_exception(call.raised);
        return py::make_tuple(int(s), diagnostics(r), std::string(hexc_result_diagnostics_text(r)));
    }

    std::pair<size_t, size_t> cacheStats() const {
        size_t hits = 0, misses = 0;
        hexc_context_cache_stats(context_.get(), &hits, &misses);
        return {hits, misses};
    }

private:
    // A build's Python callback, called from the build's threads with the lock taken; what it raises is kept for the
    // caller and stops the build.
    struct Progress {
        py::object function;
        std::exception_ptr raised;
        static int call(void* user, size_t done, size_t total, const char* name) {
            auto* self = static_cast<Progress*>(user);
            py::gil_scoped_acquire locked;
            try {
                self->function(done, total, name);
                return 0;
            } catch (...) {
                self->raised = std::current_exception();
                return 1;
            }
        }
    };

    static std::vector<const char*> pointers(const std::vector<std::string>& args) {
        std::vector<const char*> argv;
        for (const std::string& a : args) argv.push_back(a.c_str());
        return argv;
    }

    // The result of a call that returned `s`; raises when there is none.
    static ResultPtr owned(hexc_status s, hexc_result* r) {
        if (s == HEXC_OUT_OF_MEMORY) throw std::bad_alloc();
        if (!r) throw std::runtime_error(std::string("hexc: ") + hexc_status_string(s));
        return ResultPtr(r);
    }

    static py::list diagnostics(const hexc_result* r) {
        py::list found;
        for (size_t i = 0; i < hexc_result_diagnostic_count(r); ++i) {
            const hexc_diagnostic* d = hexc_result_diagnostic(r, i);
            found.append(
                py::make_tuple(d->code, d->severity == HEXC_SEVERITY_ERROR, d->file, d->line, d->column, d->path, d->message, d->fix));
        }
        return found;
    }

    static py::tuple toPython(const hexc_result* r) {
        py::list outputs;
        for (size_t i = 0; i < hexc_result_output_count(r); ++i) {
            const hexc_output* f = hexc_result_output(r, i);
            outputs.append(py::make_tuple(f->name, py::bytes(reinterpret_cast<const char*>(f->data), f->size)));
        }
        return py::make_tuple(bool(hexc_result_ok(r)), outputs, diagnostics(r), std::string(hexc_result_diagnostics_text(r)));
    }

    ContextPtr context_;
};

}  // namespace

PYBIND11_MODULE(_hexc, m) {
    m.doc() = "hexc's C API for the hexc package (use `import hexc`)";
    m.attr("version") = hexc_version();
    m.attr("api_version") = hexc_api_version();
    py::class_<Context>(m, "Context")
        .def(py::init<const std::optional<std::string>&>(), py::arg("cache_dir"))
        .def("compile", &Context::compile, py::arg("source"), py::arg("in_memory"), py::arg("name"), py::arg("base_dir"),
             py::arg("options"))
        .def("picture", &Context::picture, py::arg("preview"), py::arg("args"))
        .def("build", &Context::build, py::arg("args"), py::arg("progress"))
        .def("cache_stats", &Context::cacheStats);
    // The C API's statuses the package tells apart (hexc/hexc.h).
    m.attr("OK") = int(HEXC_OK);
    m.attr("INVALID_INPUT") = int(HEXC_INVALID_INPUT);
    m.attr("BAD_ARGUMENT") = int(HEXC_BAD_ARGUMENT);
    m.attr("NO_VULKAN") = int(HEXC_NO_VULKAN);
    m.attr("CANCELLED") = int(HEXC_CANCELLED);
}
