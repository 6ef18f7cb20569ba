/*
** Label layout (cf_label_create): a label of the longest length a label
** may have (CF_LABEL_MAX_BYTES) in text and in mathematics, and the most
** labels a figure may have (250 short ones); the median of 9 runs each,
** in milliseconds.  Public API only, so the same source times any build:
**
**   cc -O2 -Iinclude bench/bench_labels.c -Lbuild/render -Lbuild/src \
**      -lcurvefig-render -lcurvefig-core -Wl,-rpath,$PWD/build/render:$PWD/build/src
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench-time.h"
#include "curvefig/label.h"

#define RUNS 9

static char *
repeat(const char *prefix, const char *unit, size_t n, const char *suffix)
{
    size_t u = strlen(unit), k = (n - strlen(prefix) - strlen(suffix)) / u;
    char *s = malloc(strlen(prefix) + k * u + strlen(suffix) + 1);
    if (s == NULL)
        exit(1);
    strcpy(s, prefix);
    for (size_t i = 0; i < k; i++)
        strcat(s, unit);
    strcat(s, suffix);
    return s;
}

/* Lay out texts[0..n-1] once; seconds. */
static double
lay_out(char **texts, size_t n)
{
    double t0 = now_s();
    for (size_t i = 0; i < n; i++) {
        cf_label_t *lab = NULL;
        cf_diag_t d;
        cf_diag_clear(&d);
        if (cf_label_create(texts[i], NULL, 10, &lab, &d) != CF_STATUS_OK) {
            fprintf(stderr, "bench-labels: %s\n", d.msg);
            exit(1);
        }
        cf_label_destroy(lab);
    }
    return now_s() - t0;
}

static void
report(const char *name, char **texts, size_t n)
{
    double t[RUNS];
    for (int r = 0; r < RUNS; r++)
        t[r] = lay_out(texts, n);
    qsort(t, RUNS, sizeof t[0], cmp_double);
    printf("%-34s median %8.2f ms  (min %.2f, max %.2f)\n", name,
           1e3 * t[RUNS / 2], 1e3 * t[0], 1e3 * t[RUNS - 1]);
}

int
main(void)
{
    char *text = repeat("", "The quick brown fox, office. ", 1000, "");
    char *math = repeat("$", "x_1 + ", 1000, "y$");
    char *letters = repeat("", "a", 1000, "");
    char *many[250];
    char buf[64];
    for (int i = 0; i < 250; i++) {
        snprintf(buf, sizeof buf, "$P_{%d}$ point %d", i, i);
        many[i] = strdup(buf);
    }
    lay_out(&text, 1);   /* fonts loaded before timing */
    report("1000-byte label, 1000 letters", &letters, 1);
    report("1000-byte label, text", &text, 1);
    report("1000-byte label, mathematics", &math, 1);
    report("250 labels", many, 250);
    for (int i = 0; i < 250; i++)
        free(many[i]);
    free(text);
    free(math);
    free(letters);
    return 0;
}
