/*
** Fuzz target: the label parser and layout (cf_label_create): arbitrary
** bytes (invalid UTF-8, unbalanced braces, dangling _ and ^, unknown
** commands, deep nesting) at a size and family chosen by the first byte.
** A label either lays out (every box in range, its run text of the
** stated length, finite extents) or fails with INVALID_ARG and a message
** whose index is a byte position inside the text.
*/
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/figure.h"
#include "fuzz-check.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAX_TEXT 2048

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const families[] = {
        NULL, "Latin Modern Roman", "CMU Serif, Noto Serif CJK SC", "",
        "No Such Family",
    };
    static const double sizes[] = { 10.0, 7.0, 0.5, 1000.0, 0.0, -1.0 };
    char *text;
    cf_label_t *lab = NULL;
    cf_diag_t diag;
    cf_status_t st;
    unsigned sel;
    size_t len, i, n;

    if (size == 0)
        return 0;
    sel = data[0];
    len = size - 1 < MAX_TEXT ? size - 1 : MAX_TEXT;
    text = malloc(len + 1);
    FZ_CHECK(text != NULL, "malloc");
    memcpy(text, data + 1, len);
    text[len] = '\0';
    len = strlen(text);   /* an embedded NUL ends the text */

    cf_diag_clear(&diag);
    st = cf_label_create(text, families[sel % 5], sizes[(sel / 5) % 6], &lab,
                         &diag);
    fz_check_status(st, &diag, "label_create");
    FZ_CHECK((st == CF_STATUS_OK) == (lab != NULL), "status and object");
    if (st == CF_STATUS_INVALID_ARG && sizes[(sel / 5) % 6] > 0 &&
        sel % 5 != 3)
        FZ_CHECK(diag.index >= -1 && diag.index <= (long)len,
                 "error position inside the text");
    if (lab != NULL) {
        double w, asc, desc;
        n = cf_label_box_count(lab);
        for (i = 0; i < n; i++) {
            const cf_label_box_t *b = cf_label_get_box(lab, i);
            const char *run = cf_label_run_text(lab, i);
            FZ_CHECK(b != NULL && run != NULL, "box in range");
            FZ_CHECK(isfinite(b->x) && isfinite(b->y) &&
                     isfinite(b->width) && isfinite(b->size),
                     "finite box");
            FZ_CHECK(b->end >= b->start &&
                     strlen(run) == b->end - b->start, "run text length");
        }
        FZ_CHECK(cf_label_get_box(lab, n) == NULL, "box past the end");
        cf_label_get_extents(lab, &w, &asc, &desc);
        FZ_CHECK(isfinite(w) && isfinite(asc) && isfinite(desc),
                 "finite extents");
        (void)cf_label_unknown_glyphs(lab);
    }
    cf_label_destroy(lab);
    free(text);
    return 0;
}
