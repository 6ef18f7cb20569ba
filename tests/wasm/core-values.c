/*
** The native core's answers to the cases of tests/wasm/core.mjs, which
** asks the WebAssembly module the same: one case a line on stdin, its
** numbers (%.17g) a line on stdout.
**   bezier N x0 y0 ... xN-1 yN-1 w0 ... wN-1 K t1 ... tK    C(t) each
**   bspline P M u1 ... uM N x0 y0 ... K t1 ... tK          C(t) each
**   insert P M u1 ... uM N x0 y0 ... u                     new points
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/bezier.h"
#include "curvefig/bspline.h"

static double *
numbers(size_t *n)
{
    double *v;
    size_t i;
    if (scanf("%zu", n) != 1 || *n > 10000)
        return NULL;
    v = malloc((*n + 1) * sizeof *v);
    for (i = 0; v != NULL && i < *n; i++)
        if (scanf("%lf", &v[i]) != 1) {
            free(v);
            return NULL;
        }
    return v;
}

static void
put(const double *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        printf(i ? " %.17g" : "%.17g", v[i]);
    printf("\n");
}

static int
bezier_case(void)
{
    size_t n, nw, nt, i;
    double *p = numbers(&n), *w = NULL, *t = NULL, out[2];
    cf_bezier_t *c = NULL;
    int bad = p == NULL || (w = numbers(&nw)) == NULL
              || (t = numbers(&nt)) == NULL || n != 2 * nw
              || cf_bezier_create(2, (int)nw - 1, p, w, &c, NULL) != 0;
    for (i = 0; !bad && i < nt; i++) {
        bad = cf_bezier_eval(c, t[i], out) != 0;
        put(out, 2);
    }
    cf_bezier_destroy(c);
    free(p);
    free(w);
    free(t);
    return bad;
}

static int
bspline_case(int insert)
{
    int deg;
    size_t nk, np, nt, i;
    double *k = NULL, *p = NULL, *t = NULL, out[2], u;
    cf_bspline_t *c = NULL, *d = NULL;
    int bad = scanf("%d", &deg) != 1 || (k = numbers(&nk)) == NULL
              || (p = numbers(&np)) == NULL
              || cf_bspline_create(2, deg, k, nk, p, np / 2, NULL, &c,
                                   NULL) != 0;
    if (!bad && insert) {
        double *q;
        bad = scanf("%lf", &u) != 1
              || cf_bspline_insert_knot(c, u, 1, &d, NULL, NULL) != 0;
        if (!bad) {
            q = malloc(2 * cf_bspline_count(d) * sizeof *q);
            bad = q == NULL;
            if (!bad) {
                cf_bspline_get_points(d, q);
                put(q, 2 * cf_bspline_count(d));
            }
            free(q);
        }
    } else if (!bad) {
        bad = (t = numbers(&nt)) == NULL;
        for (i = 0; !bad && i < nt; i++) {
            bad = cf_bspline_eval(c, t[i], out) != 0;
            put(out, 2);
        }
    }
    cf_bspline_destroy(c);
    cf_bspline_destroy(d);
    free(k);
    free(p);
    free(t);
    return bad;
}

int
main(void)
{
    char kind[16];
    while (scanf("%15s", kind) == 1) {
        int bad = strcmp(kind, "bezier") == 0   ? bezier_case()
                  : strcmp(kind, "bspline") == 0 ? bspline_case(0)
                  : strcmp(kind, "insert") == 0  ? bspline_case(1)
                                                 : 1;
        if (bad) {
            fprintf(stderr, "core-values: bad case \"%s\"\n", kind);
            return 1;
        }
    }
    return 0;
}
