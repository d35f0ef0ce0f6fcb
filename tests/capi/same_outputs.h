/* What the C API's tests compare results with. */
#ifndef HEXC_TESTS_SAME_OUTPUTS_H
#define HEXC_TESTS_SAME_OUTPUTS_H

#include <string.h>

#include "hexc/hexc.h"

/* 1 when both results hold the same files with the same bytes. */
static int sameOutputs(const hexc_result* a, const hexc_result* b) {
    size_t i;
    if (hexc_result_output_count(a) != hexc_result_output_count(b)) return 0;
    for (i = 0; i < hexc_result_output_count(a); ++i) {
        const hexc_output* x = hexc_result_output(a, i);
        const hexc_output* y = hexc_result_output(b, i);
        if (strcmp(x->name, y->name) != 0 || x->size != y->size || memcmp(x->data, y->data, x->size) != 0) return 0;
    }
    return 1;
}

#endif
