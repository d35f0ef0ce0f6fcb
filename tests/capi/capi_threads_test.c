/* The C API (hexc/hexc.h) from several threads at once: each of 6 threads compiles 4 materials, first all through one
 * shared context (one cache), then each through its own, and every result must hold the bytes of the same material
 * compiled alone on the main thread; a material's bytes must differ from another's (the comparison's negative
 * control). The TSan stage of .ci/sanitize runs it to find data races in the context's shared cache and in the
 * library; the ASan stage runs it with leak detection.
 *   capi-threads-test   (from the source root) */
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include "hexc/hexc.h"
#include "same_outputs.h"

#define THREADS 6
#define ROUNDS 4

static const char* const materials[ROUNDS] = {"materials/rock.json", "materials/tiles.json", "materials/rock_normal.json",
                                              "materials/rock_blend.json"};
static hexc_result* expected[ROUNDS];

typedef struct Work {
    hexc_context* shared; /* null: the thread makes its own context */
    int index;
    int failures;
} Work;

static void* compileAll(void* argument) {
    Work* work = argument;
    hexc_context* context = work->shared;
    int round;
    if (!context && hexc_context_create(HEXC_API_VERSION, "", &context) != HEXC_OK) {
        ++work->failures;
        return NULL;
    }
    for (round = 0; round < ROUNDS; ++round) {
        const int m = (work->index + round) % ROUNDS; /* threads start on different materials */
        hexc_result* result = NULL;
        if (hexc_compile_file(context, materials[m], NULL, &result) != HEXC_OK || !sameOutputs(result, expected[m])) {
            fprintf(stderr, "FAILED: thread %d: %s is not what it is compiled alone\n", work->index, materials[m]);
            ++work->failures;
        }
        hexc_result_free(result);
    }
    if (!work->shared) hexc_context_free(context);
    return NULL;
}

/* Runs THREADS threads at once, through `shared` or (null) a context each; the failures they count. */
static int runThreads(hexc_context* shared) {
    pthread_t threads[THREADS];
    Work work[THREADS];
    int i, failures = 0;
    for (i = 0; i < THREADS; ++i) {
        work[i].shared = shared;
        work[i].index = i;
        work[i].failures = 0;
        if (pthread_create(&threads[i], NULL, compileAll, &work[i]) != 0) {
            fprintf(stderr, "FAILED: cannot start thread %d\n", i);
            return failures + 1;
        }
    }
    for (i = 0; i < THREADS; ++i) {
        pthread_join(threads[i], NULL);
        failures += work[i].failures;
    }
    return failures;
}

int main(void) {
    hexc_context *alone = NULL, *shared = NULL;
    size_t hits = 0, misses = 0;
    int m, failures = 0;
    if (hexc_context_create(HEXC_API_VERSION, "", &alone) != HEXC_OK || hexc_context_create(HEXC_API_VERSION, "", &shared) != HEXC_OK) {
        fprintf(stderr, "FAILED: cannot create a context\n");
        return 1;
    }
    for (m = 0; m < ROUNDS; ++m)
        if (hexc_compile_file(alone, materials[m], NULL, &expected[m]) != HEXC_OK) {
            fprintf(stderr, "FAILED: %s does not compile (run from the source root)\n", materials[m]);
            return 1;
        }
    if (sameOutputs(expected[0], expected[1])) {
        fprintf(stderr, "FAILED: negative control: rock's and tiles' outputs compare equal\n");
        ++failures;
    }
    failures += runThreads(shared);
    hexc_context_cache_stats(shared, &hits, &misses);
    /* Each material's code is compiled at most once per thread that found it missing; after that, threads hit. */
    if (hits + misses == 0 || hits == 0) {
        fprintf(stderr, "FAILED: the shared context's cache served no compile (%zu hits, %zu misses)\n", hits, misses);
        ++failures;
    }
    failures += runThreads(NULL);
    for (m = 0; m < ROUNDS; ++m) hexc_result_free(expected[m]);
    hexc_context_free(alone);
    hexc_context_free(shared);
    printf("%d threads x %d compiles, one shared context (cache: %zu hits, %zu misses), then a context each: %d failures\n", THREADS,
           ROUNDS, hits, misses, failures);
    return failures ? 1 : 0;
}
