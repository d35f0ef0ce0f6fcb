/* hexc's C API (docs/c-api.md): compile a material to shaders and engine packages from C, or from any language with a
 * C foreign-function interface. C99; no C++ type crosses it. Implemented over the C++ API (hexc/compiler.h) in
 * libhexc, which is a static C++ library: link it with a C++ linker (CMake does, given `hexc::compiler`).
 *
 * Versions: HEXC_API_VERSION is the version of this header, hexc_api_version() that of the library linked. A library
 * serves a program whose header has the same major version and a minor version no newer than its own: minor versions
 * only add functions, options and fields at the end of the structures below, majors change or remove something.
 * hexc_context_create() refuses any other pairing with HEXC_VERSION_MISMATCH, so a program never calls into a library
 * whose structures it reads differently.
 *
 * Threads: a context may be used by several threads at once (its cache is shared and locked); an options object and a
 * result belong to one thread at a time. Nothing here keeps global state besides what a context holds. */
#ifndef HEXC_HEXC_H
#define HEXC_HEXC_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define HEXC_API_VERSION_MAJOR 1
#define HEXC_API_VERSION_MINOR 1
#define HEXC_API_VERSION ((HEXC_API_VERSION_MAJOR << 16) | HEXC_API_VERSION_MINOR)

typedef enum hexc_status {
    HEXC_OK = 0,
    HEXC_INVALID_INPUT = 1,    /* the material has errors: the result holds them as diagnostics */
    HEXC_BAD_ARGUMENT = 2,     /* a null pointer, an unknown option or value: nothing was compiled */
    HEXC_VERSION_MISMATCH = 3, /* the header's HEXC_API_VERSION cannot be served by this library */
    HEXC_OUT_OF_MEMORY = 4,
    /* since 1.1, from hexc_render, hexc_preview and hexc_build: */
    HEXC_NO_VULKAN = 5,    /* no Vulkan device, or the device failed: the result's text says why */
    HEXC_WRITE_FAILED = 6, /* an output could not be written: the result's text says which */
    HEXC_CANCELLED = 7     /* the progress callback asked to stop: nothing was written */
} hexc_status;

/* A short English name of a status, "ok", "invalid input"...; never null. */
const char* hexc_status_string(hexc_status status);

/* The library's API version, as HEXC_API_VERSION encodes it, and hexc's release ("0.1.0"). */
unsigned hexc_api_version(void);
const char* hexc_version(void);

/* A context: the compiled-shader cache of the command line (docs/cli.md, --cache-dir). `cache_dir` null: the
 * command line's default folder ($XDG_CACHE_HOME/hexc, else ~/.cache/hexc, else memory only); "": memory only; else
 * that folder, which several processes may share. Pass HEXC_API_VERSION as `api_version`. */
typedef struct hexc_context hexc_context;
hexc_status hexc_context_create(unsigned api_version, const char* cache_dir, hexc_context** context);
/* Trims the cache folder to its bound (256 MiB, as the command line does after a batch) and frees the context. */
void hexc_context_free(hexc_context* context);
/* Shader code taken from the cache and compiled, over the context's life. */
void hexc_context_cache_stats(const hexc_context* context, size_t* hits, size_t* misses);

/* Compile options, by the command line's names (docs/c-api.md lists them):
 *   "targets"     comma-separated: spirv, hlsl, glsl, msl, wgsl (default: spirv,hlsl,glsl,msl)
 *   "engines"     comma-separated engine packages: godot3, godot4, filament, threejs, babylon, unity, unreal,
 *                 threejs-webgpu
 *   "uv-origin"   top-left (default) or bottom-left
 *   "hlsl-sm"     50, 51, 60 ... 66          "glsl-version"  460, 450, 330, 310es, 300es
 *   "entry"       the fragment entry point    "bake", "debug", "vertex", "no-specialise": "1" or "0"
 * A null options pointer means every default. */
typedef struct hexc_options hexc_options;
hexc_options* hexc_options_create(void); /* null when out of memory */
/* HEXC_BAD_ARGUMENT for an unknown key or value, with the reason in hexc_options_error(); the option keeps its value. */
hexc_status hexc_options_set(hexc_options* options, const char* key, const char* value);
const char* hexc_options_error(const hexc_options* options); /* "" when the last set succeeded */
void hexc_options_free(hexc_options* options);

typedef struct hexc_result hexc_result;

/* Compiles the material (JSON, or MaterialX when it ends in .mtlx) in the file `path`. HEXC_OK or HEXC_INVALID_INPUT
 * set *result, which the caller frees with hexc_result_free; the other statuses set it to null. */
hexc_status hexc_compile_file(hexc_context* context, const char* path, const hexc_options* options, hexc_result** result);
/* The same for a material held in memory: `size` bytes of `text`. `name` is the file name diagnostics give it (its
 * extension chooses JSON or MaterialX; null: "material.json") and `base_dir` the folder its relative texture and
 * template paths start from (null: the working folder); diagnostics then name base_dir/name. */
hexc_status hexc_compile_memory(hexc_context* context, const char* text, size_t size, const char* name, const char* base_dir,
                                const hexc_options* options, hexc_result** result);

/* One file a compile writes: its name ("rock.frag.hlsl", "godot3/rock.shader") and bytes (SPIR-V is binary, the
 * others text; not terminated by a zero byte). */
typedef struct hexc_output {
    const char* name;
    const unsigned char* data;
    size_t size;
} hexc_output;

typedef enum hexc_severity { HEXC_SEVERITY_ERROR = 0, HEXC_SEVERITY_WARNING = 1 } hexc_severity;

/* A problem found, as the command line prints it: "file:line:column: error[code]: path: message (fix)". Strings are
 * never null ("" when absent); line and column are 1-based, 0 when unknown. */
typedef struct hexc_diagnostic {
    const char* code; /* "HX104", from the catalogue in docs/cli.md */
    hexc_severity severity;
    const char* file;
    int line;
    int column;
    const char* path;    /* JSON pointer, e.g. "/slots/0/falloff" */
    const char* message; /* what is wrong and what was expected */
    const char* fix;     /* what was probably meant ("did you mean `rotation`?") */
} hexc_diagnostic;

/* Outputs (none when the material has errors) sorted by name, and diagnostics in the order the command line prints
 * them. An index past the end gives null. Pointers stay valid until the result is freed. */
int hexc_result_ok(const hexc_result* result);
size_t hexc_result_output_count(const hexc_result* result);
const hexc_output* hexc_result_output(const hexc_result* result, size_t index);
size_t hexc_result_diagnostic_count(const hexc_result* result);
const hexc_diagnostic* hexc_result_diagnostic(const hexc_result* result, size_t index);
/* Every diagnostic formatted as the command line prints it, one per line; "" when there is none. */
const char* hexc_result_diagnostics_text(const hexc_result* result);
void hexc_result_free(hexc_result* result);

/* Since 1.1: the command line's `hexc render`, `hexc preview` and compile mode (builds of materials and scenes), in
 * process. They run shaders on Vulkan (Mesa lavapipe, loaded at run time) and the fp64 CPU reference, which libhexc
 * does not carry: they are in the command line's library, which the Python module and hexc's tests link (CMake target
 * hexc_cli); an installed libhexc lacks them.
 *
 * `args` are the command's arguments as its command line spells them (docs/cli.md), `count` of them, e.g.
 * {"materials/rock.json", "--output", "albedo", "--size", "64x48", "--reference"}. Every status but
 * HEXC_BAD_ARGUMENT for a null context, args or result, HEXC_VERSION_MISMATCH and HEXC_OUT_OF_MEMORY sets *result:
 * its diagnostics are those the command prints located, its diagnostics text everything it prints (diagnostics,
 * notes, usage errors, a build's summary). HEXC_BAD_ARGUMENT with a result: the arguments do not parse. */

/* A float RGBA image, row 0 at the top, 4 floats a pixel, `width` * `height` * 4 of them. */
typedef struct hexc_image {
    int width;
    int height;
    const float* rgba;
} hexc_image;

/* The image `hexc render ARGS` writes (without -o): linear values, or sRGB-encoded with "--encoding", "srgb";
 * "--reference" for the fp64 reference, else lavapipe. hexc_preview: `hexc preview ARGS`'s sheet (sRGB by default).
 * On HEXC_OK, hexc_result_image gives it. */
hexc_status hexc_render(hexc_context* context, const char* const* args, size_t count, hexc_result** result);
hexc_status hexc_preview(hexc_context* context, const char* const* args, size_t count, hexc_result** result);
/* A result's image; null for a result without one (a compile's). Valid until the result is freed. */
const hexc_image* hexc_result_image(const hexc_result* result);

/* Called as each compile of a build finishes: `done` of `total` materials or scene variants compiled (those up to
 * date are not counted), `name` the one just compiled. One call at a time, from the build's threads. Return 0 to go
 * on; anything else stops the build: compiles under way finish, nothing is written (outputs are written only once
 * every compile has succeeded) and hexc_build returns HEXC_CANCELLED. */
typedef int (*hexc_progress)(void* user, size_t done, size_t total, const char* name);
/* `hexc ARGS`: material and scene files, -o DIR and the compile mode's options, compiled with the context's cache
 * (its --cache-dir and --no-cache are ignored) and written to DIR as the command line writes them. `progress` may
 * be null. */
hexc_status hexc_build(hexc_context* context, const char* const* args, size_t count, hexc_progress progress, void* user,
                       hexc_result** result);

#ifdef __cplusplus
}
#endif

#endif /* HEXC_HEXC_H */
