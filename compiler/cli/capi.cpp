// The C API's render, preview and build (hexc/hexc.h, since 1.1): the command line's commands run in process, their
// messages and diagnostics put into a result instead of stderr. Here, not in libhexc, which carries no Vulkan and no
// reference.
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "build.h"
#include "capi/handles.h"
#include "render.h"

namespace hexc::cli {
namespace {

hexc_status statusOf(int exitCode) {
    switch (exitCode) {
        case kOk:
            return HEXC_OK;
        case kInvalidInput:
            return HEXC_INVALID_INPUT;
        case kUsage:
            return HEXC_BAD_ARGUMENT;
        case kNoVulkan:
            return HEXC_NO_VULKAN;
        case kStopped:
            return HEXC_CANCELLED;
        default:
            return HEXC_WRITE_FAILED;
    }
}

// Runs `command` (what the C call does, given the arguments and where to report) into a new result; no exception
// crosses into C.
template <typename Command>
hexc_status run(hexc_context* context, const char* const* args, size_t count, hexc_result** result, Command command) {
    if (result) *result = nullptr;
    if (!context || (!args && count) || !result) return HEXC_BAD_ARGUMENT;
    try {
        std::vector<std::string> arguments;
        for (size_t i = 0; i < count; ++i) {
            if (!args[i]) return HEXC_BAD_ARGUMENT;
            arguments.emplace_back(args[i]);
        }
        auto r = std::make_unique<hexc_result>();
        std::ostringstream text;
        const int code = command(arguments, Messages{&text, &r->diagnostics}, *r);
        r->text = text.str();
        capi::makeViews(*r);
        *result = r.release();
        return statusOf(code);
    } catch (const std::bad_alloc&) {
        return HEXC_OUT_OF_MEMORY;
    }
}

// The command's image into the result, its progress line off (the caller's terminal is not the command's).
template <int (*Command)(const std::vector<std::string>&, const Messages&, Image*)>
int picture(std::vector<std::string> args, const Messages& m, hexc_result& r) {
    args.push_back("--quiet");
    Image image;
    const int code = Command(args, m, &image);
    r.pixels = std::move(image.rgba);
    r.image = {image.width, image.height, nullptr};
    return code;
}

struct Callback {
    hexc_progress progress;
    void* user;
    bool operator()(size_t done, size_t total, const std::string& name) const { return progress(user, done, total, name.c_str()) == 0; }
};

}  // namespace
}  // namespace hexc::cli

extern "C" {

hexc_status hexc_render(hexc_context* context, const char* const* args, size_t count, hexc_result** result) {
    return hexc::cli::run(context, args, count, result, hexc::cli::picture<hexc::cli::render>);
}

hexc_status hexc_preview(hexc_context* context, const char* const* args, size_t count, hexc_result** result) {
    return hexc::cli::run(context, args, count, result, hexc::cli::picture<hexc::cli::preview>);
}

hexc_status hexc_build(hexc_context* context, const char* const* args, size_t count, hexc_progress progress, void* user,
                       hexc_result** result) {
    return hexc::cli::run(context, args, count, result,
                          [&](const std::vector<std::string>& arguments, const hexc::cli::Messages& m, hexc_result&) {
                              hexc::cli::Arguments a;
                              a.messages = m;
                              if (std::optional<int> done = hexc::cli::parseArguments(arguments, a)) return *done;
                              a.cache = &context->cache;
                              if (progress) a.progress = hexc::cli::Callback{progress, user};
                              return hexc::cli::buildCommand(a);
                          });
}

}  // extern "C"
