/* The C API (hexc/hexc.h) from C99: rock.json compiled from its file and from memory to the same bytes, options,
 * engine packages, the cache, the version check, and bad materials reported with the command line's diagnostics
 * (codes, lines, columns), each checked against a wrong pairing that must fail. Everything is freed: the ASan stage
 * runs it with leak detection.
 *   capi-test HEXC WORK_DIR   (from the source root) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hexc/hexc.h"
#include "same_outputs.h"

static int failures = 0;

#define CHECK(condition, what)                                                \
    do {                                                                      \
        if (!(condition)) {                                                   \
            fprintf(stderr, "%s:%d: FAILED: %s\n", __FILE__, __LINE__, what); \
            ++failures;                                                       \
        }                                                                     \
    } while (0)

/* The whole file, zero-terminated; null when it cannot be read. */
static char* readAll(const char* path, size_t* size) {
    FILE* f = fopen(path, "rb");
    char* text = NULL;
    long length;
    if (!f) return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (length = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
        text = malloc((size_t)length + 1);
        if (text && fread(text, 1, (size_t)length, f) == (size_t)length) {
            text[length] = '\0';
            *size = (size_t)length;
        } else {
            free(text);
            text = NULL;
        }
    }
    fclose(f);
    return text;
}

static const hexc_output* outputNamed(const hexc_result* r, const char* name) {
    size_t i;
    for (i = 0; i < hexc_result_output_count(r); ++i)
        if (strcmp(hexc_result_output(r, i)->name, name) == 0) return hexc_result_output(r, i);
    return NULL;
}

static void compilesRock(hexc_context* context) {
    hexc_result *fromFile = NULL, *fromMemory = NULL;
    size_t size = 0;
    char* text = readAll("materials/rock.json", &size);
    const hexc_output* spirv;
    CHECK(text != NULL, "materials/rock.json is readable (run from the source root)");
    CHECK(hexc_compile_file(context, "materials/rock.json", NULL, &fromFile) == HEXC_OK, "rock.json compiles from its file");
    CHECK(hexc_result_ok(fromFile) && hexc_result_diagnostic_count(fromFile) == 0, "rock.json has no diagnostics");
    spirv = outputNamed(fromFile, "rock.frag.spv");
    CHECK(spirv && spirv->size > 20 && spirv->data[0] == 0x03 && spirv->data[3] == 0x07, "rock.frag.spv is SPIR-V (magic 0x07230203)");
    CHECK(outputNamed(fromFile, "rock.manifest.json") && outputNamed(fromFile, "rock.frag.hlsl") &&
              outputNamed(fromFile, "rock.frag.glsl") && outputNamed(fromFile, "rock.frag.metal"),
          "the default targets and the manifest are written");
    CHECK(hexc_result_output(fromFile, hexc_result_output_count(fromFile)) == NULL, "an index past the end gives null");
    CHECK(hexc_compile_memory(context, text, size, "rock.json", "materials", NULL, &fromMemory) == HEXC_OK,
          "rock.json compiles from memory");
    CHECK(sameOutputs(fromFile, fromMemory), "from memory, the same files and bytes as from the file");
    hexc_result_free(fromFile);
    hexc_result_free(fromMemory);
    /* Negative control of sameOutputs: another material's outputs differ. */
    CHECK(hexc_compile_file(context, "materials/tiles.json", NULL, &fromFile) == HEXC_OK, "tiles.json compiles");
    CHECK(hexc_compile_file(context, "materials/rock.json", NULL, &fromMemory) == HEXC_OK, "rock.json compiles again");
    CHECK(!sameOutputs(fromFile, fromMemory), "sameOutputs tells tiles from rock");
    hexc_result_free(fromFile);
    hexc_result_free(fromMemory);
    free(text);
}

static void options(hexc_context* context) {
    hexc_options* o = hexc_options_create();
    hexc_result* r = NULL;
    CHECK(hexc_options_set(o, "targets", "hlsl,wgls") == HEXC_BAD_ARGUMENT && strstr(hexc_options_error(o), "wgls"),
          "an unknown target is refused, named");
    CHECK(hexc_options_set(o, "target", "hlsl") == HEXC_BAD_ARGUMENT, "an unknown option is refused");
    CHECK(hexc_options_set(o, "targets", "hlsl") == HEXC_OK && *hexc_options_error(o) == '\0', "targets: hlsl");
    CHECK(hexc_options_set(o, "hlsl-sm", "60") == HEXC_OK, "hlsl-sm: 60");
    CHECK(hexc_compile_file(context, "materials/rock.json", o, &r) == HEXC_OK, "rock.json compiles to HLSL");
    CHECK(hexc_result_output_count(r) == 2 && outputNamed(r, "rock.frag.hlsl"), "only rock.frag.hlsl and the manifest");
    hexc_result_free(r);
    CHECK(hexc_options_set(o, "engines", "godot3,unity") == HEXC_OK, "engines: godot3, unity");
    CHECK(hexc_compile_file(context, "materials/rock.json", o, &r) == HEXC_OK, "rock.json packages for Godot 3 and Unity");
    CHECK(hexc_result_output_count(r) > 2 && strncmp(hexc_result_output(r, 0)->name, "godot3/", 7) == 0, "the packages' files");
    hexc_result_free(r);
    hexc_options_free(o);
}

/* Caching like the command line: code compiled once is a hit for the same context, and through a folder for another. */
static void cache(const char* work) {
    char folder[4096];
    hexc_context* context = NULL;
    hexc_result* r = NULL;
    size_t hits = 0, misses = 0;
    int round;
    snprintf(folder, sizeof folder, "%s/cache", work);
    for (round = 0; round < 2; ++round) {
        CHECK(hexc_context_create(HEXC_API_VERSION, folder, &context) == HEXC_OK, "a context with a cache folder");
        CHECK(hexc_compile_file(context, "materials/rock.json", NULL, &r) == HEXC_OK, "rock.json compiles");
        hexc_result_free(r);
        hexc_context_cache_stats(context, &hits, &misses);
        if (round == 1) CHECK(hits > 0 && misses == 0, "a second context finds rock's code in the folder");
        CHECK(hexc_compile_file(context, "materials/rock.json", NULL, &r) == HEXC_OK, "rock.json compiles again");
        hexc_result_free(r);
        hexc_context_cache_stats(context, &hits, &misses);
        CHECK(hits > 0, "the same context finds rock's code");
        hexc_context_free(context);
    }
}

static void versions(void) {
    hexc_context* context = NULL;
    CHECK(hexc_api_version() == HEXC_API_VERSION, "the library's API version is the header's");
    CHECK(hexc_context_create(HEXC_API_VERSION + (1u << 16), "", &context) == HEXC_VERSION_MISMATCH && !context,
          "a newer major is refused");
    CHECK(hexc_context_create(HEXC_API_VERSION + 1u, "", &context) == HEXC_VERSION_MISMATCH, "a newer minor is refused");
    CHECK(hexc_context_create(HEXC_API_VERSION, "", NULL) == HEXC_BAD_ARGUMENT, "a null context pointer is refused");
    CHECK(strlen(hexc_version()) > 0 && strcmp(hexc_status_string(HEXC_VERSION_MISMATCH), "API version mismatch") == 0, "names");
}

/* Whether every diagnostic of `r` is a line the command line printed for the same material, by its location and code,
 * and the command line printed as many errors. */
static int sameAsCommandLine(const hexc_result* r, const char* printed) {
    size_t i, errors = 0, printedErrors = 0;
    const char* at;
    char located[1024];
    for (i = 0; i < hexc_result_diagnostic_count(r); ++i) {
        const hexc_diagnostic* d = hexc_result_diagnostic(r, i);
        errors += d->severity == HEXC_SEVERITY_ERROR;
        snprintf(located, sizeof located, "%s:%d:%d: %s[%s]: %s", d->file, d->line, d->column,
                 d->severity == HEXC_SEVERITY_ERROR ? "error" : "warning", d->code, d->path);
        if (!strstr(printed, located)) return 0;
    }
    for (at = printed; (at = strstr(at, ": error[")) != NULL; ++at) ++printedErrors;
    return errors > 0 && errors == printedErrors;
}

/* `hexc MATERIAL` run into a file; what it printed, or null. */
static char* commandLine(const char* hexc, const char* material, const char* work) {
    char command[8192], printed[4096];
    size_t size = 0;
    snprintf(printed, sizeof printed, "%s/printed.txt", work);
    snprintf(command, sizeof command, "'%s' '%s' -o '%s/out' --no-cache 2> '%s'", hexc, material, work, printed);
    if (system(command) == 0) return NULL; /* a bad material must fail */
    return readAll(printed, &size);
}

static void badMaterials(hexc_context* context, const char* hexc, const char* work) {
    static const char* const bad[] = {"materials/invalid/kind_misspelled.json",      "materials/invalid/trailing_comma.json",
                                      "materials/invalid/slot_missing_texture.json", "materials/invalid/too_many_slots.json",
                                      "materials/invalid/rotation_not_finite.json",  "materials/invalid/template_unknown.json"};
    const size_t count = sizeof bad / sizeof bad[0];
    size_t i;
    for (i = 0; i < count; ++i) {
        hexc_result* r = NULL;
        char* printed = commandLine(hexc, bad[i], work);
        char* wrong = commandLine(hexc, bad[(i + 1) % count], work);
        CHECK(printed && wrong, bad[i]);
        CHECK(hexc_compile_file(context, bad[i], NULL, &r) == HEXC_INVALID_INPUT, bad[i]);
        CHECK(!hexc_result_ok(r) && hexc_result_output_count(r) == 0 && hexc_result_diagnostic(r, 0)->line > 0, bad[i]);
        CHECK(printed && sameAsCommandLine(r, printed), bad[i]);
        CHECK(wrong && !sameAsCommandLine(r, wrong), "negative control: another material's diagnostics do not match");
        CHECK(printed && strstr(printed, hexc_result_diagnostics_text(r)), "the formatted text is the command line's");
        hexc_result_free(r);
        free(printed);
        free(wrong);
    }
}

int main(int argc, char** argv) {
    hexc_context* context = NULL;
    hexc_result* r = NULL;
    if (argc != 3) {
        fprintf(stderr, "usage: capi-test HEXC WORK_DIR\n");
        return 2;
    }
    versions();
    CHECK(hexc_context_create(HEXC_API_VERSION, "", &context) == HEXC_OK, "a context in memory");
    compilesRock(context);
    options(context);
    badMaterials(context, argv[1], argv[2]);
    CHECK(hexc_compile_memory(context, "{", 1, NULL, NULL, NULL, &r) == HEXC_INVALID_INPUT, "half a JSON object is invalid");
    CHECK(strncmp(hexc_result_diagnostics_text(r), "material.json:1:2: error[HX101]", 31) == 0, hexc_result_diagnostics_text(r));
    hexc_result_free(r);
    CHECK(hexc_compile_file(NULL, "materials/rock.json", NULL, &r) == HEXC_BAD_ARGUMENT && r == NULL, "a null context is refused");
    hexc_context_free(context);
    cache(argv[2]);
    if (failures) fprintf(stderr, "%d checks failed\n", failures);
    return failures ? 1 : 0;
}
