/*
** Checks shared by the fuzz targets: a failed check prints what was
** violated and aborts, which libFuzzer (and the replay driver) reports as a
** crash with the input that caused it.
*/
#ifndef CURVEFIG_FUZZ_CHECK_H
#define CURVEFIG_FUZZ_CHECK_H

#include <stdio.h>
#include <stdlib.h>

#include "curvefig/core.h"

#define FZ_CHECK(cond, what)                                              \
    do {                                                                  \
        if (!(cond)) {                                                    \
            fprintf(stderr, "%s:%d: check failed: %s (%s)\n", __FILE__,   \
                    __LINE__, #cond, what);                               \
            abort();                                                      \
        }                                                                 \
    } while (0)

/* A status is one of the enum's values; a failure that takes a diag fills
** it with the same status and a non-empty message. */
static inline void
fz_check_status_(cf_status_t st, const cf_diag_t *diag, const char *call,
                 const char *file, int line)
{
    if ((int)st < 0 || st >= CF_STATUS_LAST_) {
        fprintf(stderr, "%s:%d: %s returned %d, not a cf_status_t\n", file,
                line, call, (int)st);
        abort();
    }
    if (diag != NULL && st != CF_STATUS_OK) {
        if (diag->status != st || diag->msg[0] == '\0') {
            fprintf(stderr, "%s:%d: %s failed with %d (%s) but the diag says "
                    "%d \"%s\"\n", file, line, call, (int)st,
                    cf_status_to_string(st), (int)diag->status, diag->msg);
            abort();
        }
    }
}
#define fz_check_status(st, diag, call) \
    fz_check_status_((st), (diag), (call), __FILE__, __LINE__)

#endif
