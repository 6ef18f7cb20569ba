/* The helpers the label tests share (test_label.c, test_label_tex.c);
** static inline, as not every file uses each. */
#ifndef CURVEFIG_TESTS_TEST_LABEL_H
#define CURVEFIG_TESTS_TEST_LABEL_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>
#include <pango/pangocairo.h>
#include "buffer.h"
#include "curvefig/figure.h"
#include "label-cairo.h"
#include "testutil.h"

#define SIZE 10.0

static inline cf_label_t *
layout(const char *text)
{
    cf_label_t *lab = NULL;
    cf_diag_t d;
    cf_diag_clear(&d);
    if (cf_label_create(text, NULL, SIZE, &lab, &d) != CF_STATUS_OK)
        fail_msg("label \"%s\": %s", text, d.msg);
    return lab;
}

/* s with its ASCII letters in the math italic alphabet (U+1D434 A,
** U+1D44E a, U+210E h), as mathematics sets them; static storage. */
static inline const char *
mi(const char *s)
{
    static char out[256];
    size_t n = 0;
    for (; *s != '\0' && n + 5 < sizeof out; s++) {
        unsigned c = (unsigned char)*s, cp = 0;
        if (c >= 'A' && c <= 'Z')
            cp = 0x1d434 + (c - 'A');
        else if (c == 'h')
            cp = 0x210e;
        else if (c >= 'a' && c <= 'z')
            cp = 0x1d44e + (c - 'a');
        if (cp == 0) {
            out[n++] = (char)c;
        } else if (cp < 0x10000) {
            out[n++] = (char)(0xe0 | (cp >> 12));
            out[n++] = (char)(0x80 | ((cp >> 6) & 0x3f));
            out[n++] = (char)(0x80 | (cp & 0x3f));
        } else {
            out[n++] = (char)(0xf0 | (cp >> 18));
            out[n++] = (char)(0x80 | ((cp >> 12) & 0x3f));
            out[n++] = (char)(0x80 | ((cp >> 6) & 0x3f));
            out[n++] = (char)(0x80 | (cp & 0x3f));
        }
    }
    out[n] = '\0';
    return out;
}

/* The first box whose run text equals s, or s set in the math italic. */
static inline const cf_label_box_t *
box_of(const cf_label_t *lab, const char *s)
{
    size_t i;
    for (i = 0; i < cf_label_box_count(lab); i++)
        if (strcmp(cf_label_run_text(lab, i), s) == 0)
            return cf_label_get_box(lab, i);
    for (i = 0; i < cf_label_box_count(lab); i++)
        if (strcmp(cf_label_run_text(lab, i), mi(s)) == 0)
            return cf_label_get_box(lab, i);
    fail_msg("no run \"%s\"", s);
    return NULL;
}

#endif
