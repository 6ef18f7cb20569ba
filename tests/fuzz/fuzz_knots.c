/*
** Fuzz target: sequences of knot insertions, refinements, removals, splits,
** segments, elevations and reversals on a valid clamped or open B-spline
** (polynomial or NURBS) with moderate coordinates.  Beyond "no crash":
** every result must have a valid knot vector (cf_knots_validate), and the
** shape-preserving operations (insertion, refinement, elevation, split)
** must leave the curve where it was, to 1e-9 of the curve's size at the
** parameters tested (exact up to rounding by design; the bound is loose
** so that long sequences of operations cannot trip it by accumulated
** rounding on these small degrees and counts).
*/
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "curvefig/bspline.h"
#include "curvefig/knots.h"
#include "fuzz-check.h"
#include "fuzz-input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define DIM 2
#define MAX_STEPS 12
#define MAX_KNOTS 400   /* stop growing a curve beyond this */

static double
curve_size(const cf_bspline_t *c)
{
    size_t i, n = cf_bspline_count(c) * DIM;
    double *p = malloc(n * sizeof *p), s = 1.0;
    FZ_CHECK(p != NULL, "malloc");
    cf_bspline_get_points(c, p);
    for (i = 0; i < n; i++)
        s = fmax(s, fabs(p[i]));
    free(p);
    return s;
}

static int last_op = -1;

static void
check_valid(const cf_bspline_t *c)
{
    cf_diag_t diag;
    cf_diag_clear(&diag);
    if (cf_knots_validate(cf_bspline_degree(c), cf_bspline_count(c),
                          cf_bspline_knots(c), cf_bspline_nknots(c),
                          &diag) != CF_STATUS_OK) {
        fprintf(stderr, "result of operation %d has an invalid knot "
                "vector: %s\n", last_op, diag.msg);
        for (size_t i = 0; i < cf_bspline_nknots(c); i++)
            fprintf(stderr, " %.17g", cf_bspline_knots(c)[i]);
        fprintf(stderr, "\n");
        abort();
    }
}

/* The curves agree at 9 parameters inside (lo, hi) (a sub-interval of
** both domains).  The ends are left out: a curve with a knot of
** multiplicity p + 1 jumps there, and at the right end of a domain the
** left limit is taken, so the two values may differ legitimately. */
static void
check_same(const cf_bspline_t *a, const cf_bspline_t *b, double lo,
           double hi, const char *what)
{
    double pa[DIM], pb[DIM], tol = 1e-9 * curve_size(a);
    int j, d;
    for (j = 0; j <= 8; j++) {
        double u = lo + (hi - lo) * (j + 0.5) / 9.0;
        FZ_CHECK(cf_bspline_eval(a, u, pa) == CF_STATUS_OK, what);
        FZ_CHECK(cf_bspline_eval(b, u, pb) == CF_STATUS_OK, what);
        for (d = 0; d < DIM; d++) {
            if (!(fabs(pa[d] - pb[d]) <= tol)) {
                fprintf(stderr, "%s moved the curve at u = %.17g: %.17g vs "
                        "%.17g\n", what, u, pa[d], pb[d]);
                abort();
            }
        }
    }
}

/* A parameter: an existing knot (to stack multiplicities), a point of the
** domain, or the domain's ends. */
static double
pick_u(fz_input *in, const cf_bspline_t *c)
{
    double a, b;
    unsigned sel = fz_byte(in);
    cf_bspline_domain(c, &a, &b);
    if (sel < 96)
        return cf_bspline_knots(c)[fz_byte(in) % cf_bspline_nknots(c)];
    if (sel < 240)
        return a + (b - a) * fz_unit(in);
    return sel & 1 ? a : b;
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_input in = { data, size };
    unsigned sel = fz_byte(&in);
    int p = 1 + (int)(sel % 5), step, r, removed;
    size_t count = (size_t)p + 1 + fz_byte(&in) % 10, i;
    double pts[16 * DIM], w[16], knots[32], a, b, u, x[6];
    cf_bspline_t *c = NULL, *d = NULL, *e = NULL;
    cf_diag_t diag;
    cf_status_t st;

    for (i = 0; i < count * DIM; i++)
        pts[i] = fz_finite(&in);
    for (i = 0; i < count; i++)
        w[i] = 0.25 + fz_unit(&in) * 4.0;
    cf_diag_clear(&diag);
    if (sel & 0x80) {
        /* open knot vector with some multiplicities */
        double t = 0.0;
        for (i = 0; i < count + (size_t)p + 1; i++) {
            knots[i] = t;
            t += fz_byte(&in) < 48 ? 0.0 : 0.125 + fz_unit(&in);
        }
        st = cf_bspline_create(DIM, p, knots, count + (size_t)p + 1, pts,
                               count, sel & 0x40 ? w : NULL, &c, &diag);
    } else {
        st = cf_bspline_create_clamped(DIM, p, pts, count,
                                       sel & 0x40 ? w : NULL, &c, &diag);
    }
    fz_check_status(st, &diag, "create");
    if (c == NULL)
        return 0;
    check_valid(c);

    for (step = 0; step < MAX_STEPS && in.n > 0; step++) {
        int op = (int)(fz_byte(&in) % 8);
        cf_bspline_t *next = NULL;
        last_op = op;
        cf_diag_clear(&diag);
        cf_bspline_domain(c, &a, &b);
        u = pick_u(&in, c);
        r = 1 + (int)(fz_byte(&in) % (unsigned)(cf_bspline_degree(c) + 1));
        switch (op) {
        case 0:
        case 1:
            st = cf_bspline_insert_knot(c, u, r, &next, NULL, &diag);
            fz_check_status(st, &diag, "insert_knot");
            if (st == CF_STATUS_OK)
                check_same(c, next, a, b, "insert_knot");
            break;
        case 2:
            for (i = 0; i < 6; i++)
                x[i] = pick_u(&in, c);
            for (i = 1; i < 6; i++) {   /* sort */
                size_t j = i;
                while (j > 0 && x[j - 1] > x[j]) {
                    double t = x[j];
                    x[j] = x[j - 1];
                    x[j - 1] = t;
                    j--;
                }
            }
            st = cf_bspline_refine(c, x, fz_byte(&in) % 7, &next, &diag);
            fz_check_status(st, &diag, "refine");
            if (st == CF_STATUS_OK)
                check_same(c, next, a, b, "refine");
            break;
        case 3:
            st = cf_bspline_remove_knot(c, u, r, fz_unit(&in) * 10.0, &next,
                                        &removed, &diag);
            fz_check_status(st, &diag, "remove_knot");
            FZ_CHECK(st != CF_STATUS_OK || (removed >= 0 && removed <= r),
                     "removed count");
            break;
        case 4:
            st = cf_bspline_split(c, u, &d, &e, &diag);
            fz_check_status(st, &diag, "split");
            if (st == CF_STATUS_OK) {
                check_valid(d);
                check_valid(e);
                check_same(c, d, a, u, "split (left)");
                check_same(c, e, u, b, "split (right)");
                next = fz_byte(&in) & 1 ? d : e;
                if (next == d)
                    cf_bspline_destroy(e);
                else
                    cf_bspline_destroy(d);
            }
            d = e = NULL;
            break;
        case 5:
            st = cf_bspline_segment(c, u, pick_u(&in, c), &next, &diag);
            fz_check_status(st, &diag, "segment");
            break;
        case 6:
            if (cf_bspline_degree(c) < 8) {
                st = cf_bspline_elevate(c, 1, &next, &diag);
                fz_check_status(st, &diag, "elevate");
                if (st == CF_STATUS_OK)
                    check_same(c, next, a, b, "elevate");
            }
            break;
        default:
            st = cf_bspline_reverse(c, &next, &diag);
            fz_check_status(st, &diag, "reverse");
            break;
        }
        if (next != NULL) {
            if (getenv("FUZZ_KNOTS_TRACE") != NULL) {
                fprintf(stderr, "op %d:", op);
                for (i = 0; i < cf_bspline_nknots(c); i++)
                    fprintf(stderr, " %.17g", cf_bspline_knots(c)[i]);
                fprintf(stderr, "\n");
            }
            check_valid(next);
            cf_bspline_destroy(c);
            c = next;
            if (cf_bspline_nknots(c) > MAX_KNOTS)
                break;
        }
    }
    cf_bspline_destroy(c);
    return 0;
}
