/* A program with a wasm2c runtime of its own beside libhexc, which holds one too (naga's, for the wgsl target):
 * wabt's wasm-rt-impl.c compiled into the program, as wasm2c's documentation builds a module's program, with its
 * default options (a SIGSEGV handler guards its modules' memories, where hexc's runtime checks bounds in code). It
 * links only while libhexc's copy of the runtime is under names of its own; then each runs: this program's runtime
 * starts and allocates a memory, hexc compiles rock to WGSL through its own, and this program's memory and runtime
 * are as they were.
 *   capi-wasm-rt-test   (from the source root) */
#include <stdio.h>
#include <string.h>

#include "hexc/hexc.h"
#include "wasm-rt.h"

static int failures = 0;

static void check(int ok, const char* what) {
    if (!ok) {
        fprintf(stderr, "FAILED: %s\n", what);
        ++failures;
    }
}

/* The WGSL files of rock compiled with --targets wgsl, through hexc's own wasm2c runtime. */
static size_t wgslFiles(void) {
    hexc_context* context = NULL;
    hexc_options* options = hexc_options_create();
    hexc_result* result = NULL;
    size_t i, found = 0;
    if (options && hexc_options_set(options, "targets", "wgsl") == HEXC_OK &&
        hexc_context_create(HEXC_API_VERSION, "", &context) == HEXC_OK &&
        hexc_compile_file(context, "materials/rock.json", options, &result) == HEXC_OK) {
        for (i = 0; i < hexc_result_output_count(result); ++i) {
            const hexc_output* file = hexc_result_output(result, i);
            const size_t length = strlen(file->name);
            found += length > 5 && strcmp(file->name + length - 5, ".wgsl") == 0 && file->size > 0;
        }
    }
    if (result && hexc_result_diagnostic_count(result)) fputs(hexc_result_diagnostics_text(result), stderr);
    hexc_result_free(result);
    hexc_context_free(context);
    hexc_options_free(options);
    return found;
}

int main(void) {
    wasm_rt_memory_t memory;
    wasm_rt_init();
    check(wasm_rt_is_initialized(), "this program's wasm2c runtime did not install its signal handler");
    wasm_rt_allocate_memory(&memory, 1, 2);
    memset(memory.data, 0x5a, memory.size);
    check(wgslFiles() == 1, "hexc did not compile materials/rock.json to one WGSL file");
    check(wasm_rt_is_initialized(), "this program's wasm2c runtime is not initialised after hexc's translation");
    check(memory.size == 65536 && memory.data[0] == 0x5a && memory.data[65535] == 0x5a, "this program's memory changed");
    check(wasm_rt_grow_memory(&memory, 1) == 1 && memory.size == 131072, "this program's memory does not grow");
    wasm_rt_free_memory(&memory);
    wasm_rt_free();
    if (failures) return 1;
    puts("ok: a program with its own wasm2c runtime links libhexc, and both runtimes run");
    return 0;
}
