/* Tensor-product Bézier, B-spline and NURBS surfaces (curvefig/surface.h),
** against an independent long double computation: the Cox-de Boor
** recursion of the basis and of its derivatives over the whole grid, and
** the Leibniz rule for the rational derivatives. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/surface.h"
#include "testutil.h"

#define EPS 2.220446049250313e-16
typedef long double ld;

/* ---- the reference ----------------------------------------------------- */

/* N_i^p(u) (right-continuous; left limit when left is set: the right end
** of a domain), its d-th derivative by N' = p (N_i^{p-1} / (u_{i+p} - u_i)
** - N_{i+1}^{p-1} / (u_{i+p+1} - u_{i+1})), 0/0 = 0. */
static ld
ref_basis(const double *U, int i, int p, int d, ld u, int left)
{
    ld a = 0.0L, b = 0.0L, d1, d2;
    if (p == 0) {
        if (d > 0)
            return 0.0L;
        if (left)
            return (U[i] < u && u <= U[i + 1]) ? 1.0L : 0.0L;
        return (U[i] <= u && u < U[i + 1]) ? 1.0L : 0.0L;
    }
    d1 = (ld)U[i + p] - U[i];
    d2 = (ld)U[i + p + 1] - U[i + 1];
    if (d > 0) {
        if (d1 != 0.0L)
            a = p / d1 * ref_basis(U, i, p - 1, d - 1, u, left);
        if (d2 != 0.0L)
            b = p / d2 * ref_basis(U, i + 1, p - 1, d - 1, u, left);
        return a - b;
    }
    if (d1 != 0.0L)
        a = (u - U[i]) / d1 * ref_basis(U, i, p - 1, 0, u, left);
    if (d2 != 0.0L)
        b = (U[i + p + 1] - u) / d2 * ref_basis(U, i + 1, p - 1, 0, u, left);
    return a + b;
}

/* A surface given by its raw data, for the reference. */
typedef struct ref_surf {
    size_t dim, nu, nv;
    int p, q;
    const double *U, *V, *P; /* P Cartesian, nu nv dim */
    const double *W;         /* NULL: polynomial */
    double ub, vb;           /* right ends of the domains */
} ref_surf;

/* S_{u^a v^b}, a + b <= k, into out[(a (k+1) + b) dim] (Leibniz quotient
** rule in long double for the rational case). */
static void
ref_derivs(const ref_surf *r, double u, double v, int k, double *out)
{
    size_t K = (size_t)k + 1, dim = r->dim, h = dim + 1;
    ld *A = calloc(K * K * h, sizeof *A), *S = calloc(K * K * dim, sizeof *S);
    for (size_t a = 0; a < K; a++)
        for (size_t b = 0; a + b < K; b++)
            for (size_t i = 0; i < r->nu; i++) {
                ld Ni = ref_basis(r->U, (int)i, r->p, (int)a, u, u == r->ub);
                if (Ni == 0.0L)
                    continue;
                for (size_t j = 0; j < r->nv; j++) {
                    ld Nj = ref_basis(r->V, (int)j, r->q, (int)b, v,
                                      v == r->vb);
                    ld w = r->W ? r->W[i * r->nv + j] : 1.0L;
                    for (size_t c = 0; c < dim; c++)
                        A[(a * K + b) * h + c] +=
                            Ni * Nj * w * r->P[(i * r->nv + j) * dim + c];
                    A[(a * K + b) * h + dim] += Ni * Nj * w;
                }
            }
    for (size_t a = 0; a < K; a++)
        for (size_t b = 0; a + b < K; b++)
            for (size_t c = 0; c < dim; c++) {
                ld x = A[(a * K + b) * h + c];
                for (size_t i = 0; i <= a; i++)
                    for (size_t j = 0; j <= b; j++) {
                        ld bin = 1.0L;
                        if (i == 0 && j == 0)
                            continue;
                        for (size_t t = 0; t < i; t++)
                            bin = bin * (ld)(a - t) / (ld)(t + 1);
                        for (size_t t = 0; t < j; t++)
                            bin = bin * (ld)(b - t) / (ld)(t + 1);
                        x -= bin * A[(i * K + j) * h + dim] *
                             S[((a - i) * K + (b - j)) * dim + c];
                    }
                S[(a * K + b) * dim + c] = x / A[dim];
            }
    for (size_t e = 0; e < K * K * dim; e++)
        out[e] = (double)S[e];
    free(A);
    free(S);
}

/* ---- random surfaces ---------------------------------------------------- */

typedef struct sample {
    size_t dim, nu, nv;
    int p, q;
    double U[64], V[64], P[3000], W[1000];
    int rational;
    ref_surf ref;
} sample;

static void
random_knots(tu_rng *r, int p, size_t n, int clamp, double *K)
{
    size_t nk = n + (size_t)p + 1, i = 0, end = nk;
    double x = tu_rng_range(r, -1.0, 1.0);
    if (clamp) {
        for (; i <= (size_t)p; i++)
            K[i] = x;
        end = nk - (size_t)p - 1;
        x += tu_rng_range(r, 0.1, 1.0);
    }
    while (i < end) {
        size_t run = (clamp && p > 1 && tu_rng_u01(r) < 0.2) ? 2 : 1;
        for (size_t j = 0; j < run && i < end; j++)
            K[i++] = x;
        x += tu_rng_range(r, 0.1, 1.0);
    }
    for (; i < nk; i++)
        K[i] = x;
}

static void
make_sample(tu_rng *r, sample *s, size_t dim, int p, int q, size_t nu,
            size_t nv, int clamp, int rational)
{
    memset(s, 0, sizeof *s);
    s->dim = dim;
    s->p = p;
    s->q = q;
    s->nu = nu;
    s->nv = nv;
    s->rational = rational;
    random_knots(r, p, nu, clamp, s->U);
    random_knots(r, q, nv, clamp, s->V);
    for (size_t i = 0; i < nu * nv * dim; i++)
        s->P[i] = tu_rng_range(r, -10.0, 10.0);
    for (size_t i = 0; i < nu * nv; i++)
        s->W[i] = tu_rng_range(r, 0.3, 3.0);
    s->ref = (ref_surf){ dim, nu, nv, p, q, s->U, s->V, s->P,
                         rational ? s->W : NULL, s->U[nu], s->V[nv] };
}

static cf_bspline_surface_t *
make_bspline(const sample *s)
{
    cf_bspline_surface_t *b = NULL;
    cf_diag_t d;
    if (cf_bspline_surface_create(s->dim, s->p, s->q, s->U,
                                  s->nu + (size_t)s->p + 1, s->V,
                                  s->nv + (size_t)s->q + 1, s->P, s->nu,
                                  s->nv, s->rational ? s->W : NULL, &b, &d))
        fail_msg("create: %s", d.msg);
    return b;
}

/* A Bézier sample: clamped knots {0^(m+1), 1^(m+1)}. */
static cf_bezier_surface_t *
make_bezier(tu_rng *r, sample *s, size_t dim, int m, int n, int rational)
{
    cf_bezier_surface_t *b = NULL;
    make_sample(r, s, dim, m, n, (size_t)m + 1, (size_t)n + 1, 1, rational);
    for (int i = 0; i <= 2 * m + 1; i++)
        s->U[i] = i <= m ? 0.0 : 1.0;
    for (int i = 0; i <= 2 * n + 1; i++)
        s->V[i] = i <= n ? 0.0 : 1.0;
    s->ref.ub = s->ref.vb = 1.0;
    assert_int_equal(cf_bezier_surface_create(dim, m, n, s->P,
                                              rational ? s->W : NULL, &b,
                                              NULL), 0);
    return b;
}

static double
size_of(const sample *s)
{
    double m = 1.0;
    for (size_t i = 0; i < s->nu * s->nv * s->dim; i++)
        m = fmax(m, fabs(s->P[i]));
    return m;
}

/* Every entry a + b <= k of two derivative arrays agree relative to the
** largest entry of the same order (the derivatives of order k scale like
** (degree / span)^k times the size). */
static void
assert_derivs_close(const double *x, const double *y, size_t dim, int k,
                    double rel, const char *what)
{
    size_t K = (size_t)k + 1;
    for (size_t o = 0; o < K; o++) {
        double scale = 1.0, diff = 0.0;
        for (size_t a = 0; a <= o; a++)
            for (size_t c = 0; c < dim; c++) {
                size_t e = (a * K + (o - a)) * dim + c;
                scale = fmax(scale, fabs(y[e]));
                diff = fmax(diff, fabs(x[e] - y[e]));
            }
        if (!(diff <= rel * scale))
            fail_msg("%s: order %zu differs by %g (scale %g)", what, o, diff,
                     scale);
    }
}

/* A parameter strictly inside [a, b] or one of its ends. */
static double
param(tu_rng *r, double a, double b, int trial)
{
    if (trial % 7 == 0)
        return a;
    if (trial % 7 == 1)
        return b;
    return a + (b - a) * tu_rng_u01(r);
}

/* ---- evaluation and derivatives ---------------------------------------- */

static void
test_bezier_eval_derivs(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 27);
    for (int t = 0; t < 200; t++) {
        sample s;
        int m = (int)(tu_rng_u01(&r) * 6), n = (int)(tu_rng_u01(&r) * 6);
        size_t dim = 1 + (size_t)(tu_rng_u01(&r) * 3);
        cf_bezier_surface_t *b = make_bezier(&r, &s, dim, m, n, t % 2);
        double u = param(&r, 0, 1, t), v = param(&r, 0, 1, t / 7);
        double x[3], D[16 * 3], R[16 * 3];
        ref_derivs(&s.ref, u, v, 3, R);
        assert_int_equal(cf_bezier_surface_eval(b, u, v, x), 0);
        assert_derivs_close(x, R, dim, 0, 64 * EPS, "bezier eval");
        assert_int_equal(cf_bezier_surface_eval_derivs(b, u, v, 3, D), 0);
        assert_derivs_close(D, R, dim, 3, 1e-11, "bezier derivs");
        cf_bezier_surface_destroy(b);
    }
}

static void
test_bspline_eval_derivs(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 28);
    for (int t = 0; t < 300; t++) {
        sample s;
        int p = (int)(tu_rng_u01(&r) * 5), q = (int)(tu_rng_u01(&r) * 5);
        size_t nu = (size_t)p + 1 + (size_t)(tu_rng_u01(&r) * 5);
        size_t nv = (size_t)q + 1 + (size_t)(tu_rng_u01(&r) * 5);
        size_t dim = 1 + (size_t)(tu_rng_u01(&r) * 3);
        cf_bspline_surface_t *b;
        double ua, ub, va, vb, u, v, x[3], D[16 * 3], R[16 * 3];
        make_sample(&r, &s, dim, p, q, nu, nv, t % 3 != 0, t % 2);
        b = make_bspline(&s);
        cf_bspline_surface_domain(b, CF_DIR_U, &ua, &ub);
        cf_bspline_surface_domain(b, CF_DIR_V, &va, &vb);
        s.ref.ub = ub;
        s.ref.vb = vb;
        u = param(&r, ua, ub, t);
        v = param(&r, va, vb, t / 7);
        ref_derivs(&s.ref, u, v, 3, R);
        assert_int_equal(cf_bspline_surface_eval(b, u, v, x), 0);
        assert_derivs_close(x, R, dim, 0, 64 * EPS * size_of(&s),
                            "bspline eval");
        assert_int_equal(cf_bspline_surface_eval_derivs(b, u, v, 3, D), 0);
        assert_derivs_close(D, R, dim, 3, 1e-10, "bspline derivs");
        cf_bspline_surface_destroy(b);
    }
}

/* eval = eval of the iso-curve, both directions; and the de Casteljau /
** de Boor schemes end at the point and start at the control points. */
static void
test_iso_and_schemes(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 29);
    for (int t = 0; t < 100; t++) {
        sample s;
        int m = 1 + (int)(tu_rng_u01(&r) * 4), n = (int)(tu_rng_u01(&r) * 5);
        cf_bezier_surface_t *b = make_bezier(&r, &s, 3, m, n, t % 2);
        cf_bspline_surface_t *bs = NULL;
        cf_bezier_t *cu = NULL, *cv = NULL;
        cf_bspline_t *ku = NULL, *kv = NULL;
        double u = tu_rng_u01(&r), v = tu_rng_u01(&r), x[3], y[3], z[3];
        double *net = malloc(cf_bezier_surface_decasteljau_size(b) *
                             sizeof *net);
        double sz = size_of(&s);
        size_t last, span[2];
        assert_int_equal(cf_bezier_surface_eval(b, u, v, x), 0);
        assert_int_equal(cf_bezier_surface_iso(b, CF_DIR_U, u, &cu, NULL), 0);
        assert_int_equal(cf_bezier_surface_iso(b, CF_DIR_V, v, &cv, NULL), 0);
        assert_int_equal(cf_bezier_degree(cu), n);
        assert_int_equal(cf_bezier_degree(cv), m);
        assert_int_equal(cf_bezier_eval(cu, v, y), 0);
        assert_int_equal(cf_bezier_eval(cv, u, z), 0);
        assert_true(tu_max_diff(x, y, 3) <= 64 * EPS * sz);
        assert_true(tu_max_diff(x, z, 3) <= 64 * EPS * sz);
        assert_int_equal(cf_bezier_surface_decasteljau(b, u, v, net), 0);
        last = cf_bezier_surface_decasteljau_size(b) / 3 - 1;
        assert_true(tu_max_diff(x, net + 3 * last, 3) <= 64 * EPS * sz);
        /* column 1 starts with P[0][1] (exactly) */
        if (n >= 1)
            assert_true(tu_max_diff(net + 3 * (size_t)((m + 1) * (m + 2) / 2),
                                    s.P + 3, 3) <= 4 * EPS * sz);
        /* the B-spline form: same values, same iso-curves, de Boor net */
        assert_int_equal(cf_bspline_surface_from_bezier(b, &bs, NULL), 0);
        assert_int_equal(cf_bspline_surface_eval(bs, u, v, y), 0);
        assert_true(tu_max_diff(x, y, 3) <= 64 * EPS * sz);
        assert_int_equal(cf_bspline_surface_iso(bs, CF_DIR_U, u, &ku, NULL),
                         0);
        assert_int_equal(cf_bspline_surface_iso(bs, CF_DIR_V, v, &kv, NULL),
                         0);
        assert_int_equal(cf_bspline_eval(ku, v, y), 0);
        assert_int_equal(cf_bspline_eval(kv, u, z), 0);
        assert_true(tu_max_diff(x, y, 3) <= 64 * EPS * sz);
        assert_true(tu_max_diff(x, z, 3) <= 64 * EPS * sz);
        free(net);
        net = malloc(cf_bspline_surface_deboor_size(bs) * sizeof *net);
        assert_int_equal(cf_bspline_surface_deboor(bs, u, v, net, span), 0);
        last = cf_bspline_surface_deboor_size(bs) / 3 - 1;
        assert_true(tu_max_diff(x, net + 3 * last, 3) <= 64 * EPS * sz);
        assert_true(tu_max_diff(net, s.P, 3) <= 4 * EPS * sz);
        free(net);
        cf_bezier_destroy(cu);
        cf_bezier_destroy(cv);
        cf_bspline_destroy(ku);
        cf_bspline_destroy(kv);
        cf_bspline_surface_destroy(bs);
        cf_bezier_surface_destroy(b);
    }
}

/* max |S1 - S2| over a grid of [a, b] x [c, d] (parameters of S2 mapped
** from those of S1 by the affine maps (u - o1) * k1 + o2 etc.). */
typedef cf_status_t (*eval_fn)(const void *, double, double, double *);

static cf_status_t
ev_bez(const void *s, double u, double v, double *out)
{
    return cf_bezier_surface_eval(s, u, v, out);
}

static cf_status_t
ev_bsp(const void *s, double u, double v, double *out)
{
    return cf_bspline_surface_eval(s, u, v, out);
}

static double
gap(eval_fn f1, const void *s1, eval_fn f2, const void *s2, size_t dim,
    const double box1[4], const double box2[4])
{
    double m = 0.0;
    for (int i = 0; i <= 8; i++)
        for (int j = 0; j <= 8; j++) {
            double x[4], y[4];
            double u1 = box1[0] + (box1[1] - box1[0]) * i / 8.0;
            double v1 = box1[2] + (box1[3] - box1[2]) * j / 8.0;
            double u2 = box2[0] + (box2[1] - box2[0]) * i / 8.0;
            double v2 = box2[2] + (box2[3] - box2[2]) * j / 8.0;
            assert_int_equal(f1(s1, u1, v1, x), 0);
            assert_int_equal(f2(s2, u2, v2, y), 0);
            m = fmax(m, tu_max_diff(x, y, dim));
        }
    return m;
}

static void
test_bezier_constructions(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 30);
    for (int t = 0; t < 60; t++) {
        sample s;
        cf_bezier_surface_t *b = make_bezier(&r, &s, 3, 1 + t % 4,
                                             (t / 4) % 5, t % 2);
        cf_bezier_surface_t *lo = NULL, *hi = NULL, *e = NULL, *g = NULL;
        double c = tu_rng_range(&r, 0.1, 0.9), sz = size_of(&s);
        double all[4] = { 0, 1, 0, 1 }, lo_u[4] = { 0, c, 0, 1 };
        double hi_u[4] = { c, 1, 0, 1 }, lo_v[4] = { 0, 1, 0, c };
        double sub[4] = { 0.2, 0.7, 0.1, 0.6 }, bl[3], bh[3];
        double tol = (t % 2 ? 1e-12 : 1e-13) * sz;
        cf_dir_t dir = (t / 2) % 2 ? CF_DIR_V : CF_DIR_U;
        assert_int_equal(cf_bezier_surface_split(b, dir, c, &lo, &hi, NULL),
                         0);
        assert_true(gap(ev_bez, lo, ev_bez, b, 3, all,
                        dir == CF_DIR_U ? lo_u : lo_v) <= tol);
        if (dir == CF_DIR_U)
            assert_true(gap(ev_bez, hi, ev_bez, b, 3, all, hi_u) <= tol);
        assert_int_equal(cf_bezier_surface_elevate(b, 2, 1, &e, NULL), 0);
        assert_int_equal(cf_bezier_surface_degree_u(e),
                         cf_bezier_surface_degree_u(b) + 2);
        assert_true(gap(ev_bez, e, ev_bez, b, 3, all, all) <= tol);
        assert_int_equal(cf_bezier_surface_segment(b, 0.2, 0.7, 0.1, 0.6, &g,
                                                   NULL), 0);
        assert_true(gap(ev_bez, g, ev_bez, b, 3, all, sub) <= tol);
        /* the box of the control points holds the surface */
        cf_bezier_surface_bbox(b, bl, bh);
        for (int i = 0; i <= 10; i++) {
            double x[3];
            assert_int_equal(cf_bezier_surface_eval(b, i / 10.0,
                                                    1 - i / 10.0, x), 0);
            for (int k = 0; k < 3; k++)
                assert_true(x[k] >= bl[k] - tol && x[k] <= bh[k] + tol);
        }
        cf_bezier_surface_destroy(lo);
        cf_bezier_surface_destroy(hi);
        cf_bezier_surface_destroy(e);
        cf_bezier_surface_destroy(g);
        cf_bezier_surface_destroy(b);
    }
}

static void
test_bspline_constructions(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 31);
    for (int t = 0; t < 60; t++) {
        sample s;
        int p = 1 + t % 3, q = 1 + (t / 3) % 3;
        cf_bspline_surface_t *b, *ins = NULL, *ref = NULL, *el = NULL;
        cf_bspline_surface_t *lo = NULL, *hi = NULL;
        cf_bezier_surface_list_t *L = NULL;
        double ua, ub, va, vb, c, dom[4], tol, x[3];
        make_sample(&r, &s, 3, p, q, (size_t)p + 3, (size_t)q + 2, t % 4 != 3,
                    t % 2);
        b = make_bspline(&s);
        tol = (t % 2 ? 1e-11 : 1e-12) * size_of(&s);
        cf_bspline_surface_domain(b, CF_DIR_U, &ua, &ub);
        cf_bspline_surface_domain(b, CF_DIR_V, &va, &vb);
        dom[0] = ua, dom[1] = ub, dom[2] = va, dom[3] = vb;
        c = va + (vb - va) * tu_rng_range(&r, 0.1, 0.9);
        assert_int_equal(cf_bspline_surface_insert_knot(b, CF_DIR_V, c, 2,
                                                        &ins, NULL), 0);
        assert_int_equal(cf_bspline_surface_count_v(ins),
                         cf_bspline_surface_count_v(b) + 2);
        assert_true(gap(ev_bsp, ins, ev_bsp, b, 3, dom, dom) <= tol);
        x[0] = ua + (ub - ua) * 0.25;
        x[1] = ua + (ub - ua) * 0.5;
        x[2] = ua + (ub - ua) * 0.75;
        assert_int_equal(cf_bspline_surface_refine(b, CF_DIR_U, x, 3, &ref,
                                                   NULL), 0);
        assert_true(gap(ev_bsp, ref, ev_bsp, b, 3, dom, dom) <= tol);
        assert_int_equal(cf_bspline_surface_elevate(b, 1, 2, &el, NULL), 0);
        assert_int_equal(cf_bspline_surface_degree_v(el), q + 2);
        assert_true(gap(ev_bsp, el, ev_bsp, b, 3, dom, dom) <= tol);
        c = ua + (ub - ua) * tu_rng_range(&r, 0.1, 0.9);
        assert_int_equal(cf_bspline_surface_split(b, CF_DIR_U, c, &lo, &hi,
                                                  NULL), 0);
        {
            double l[4] = { ua, c, va, vb }, h[4] = { c, ub, va, vb };
            assert_true(gap(ev_bsp, lo, ev_bsp, b, 3, l, l) <= tol);
            assert_true(gap(ev_bsp, hi, ev_bsp, b, 3, h, h) <= tol);
        }
        /* every Bézier patch is the surface on its rectangle */
        assert_int_equal(cf_bspline_surface_to_beziers(b, &L, NULL), 0);
        assert_true(L->nu >= 1 && L->nv >= 1);
        for (size_t i = 0; i < L->nu; i++)
            for (size_t j = 0; j < L->nv; j++) {
                double unit[4] = { 0, 1, 0, 1 };
                double box[4] = { L->u0[i], L->u1[i], L->v0[j], L->v1[j] };
                assert_true(gap(ev_bez, L->items[i * L->nv + j], ev_bsp, b, 3,
                                unit, box) <= tol);
            }
        assert_true(L->u0[0] == ua && L->u1[L->nu - 1] == ub);
        cf_bezier_surface_list_destroy(L);
        cf_bspline_surface_destroy(lo);
        cf_bspline_surface_destroy(hi);
        cf_bspline_surface_destroy(el);
        cf_bspline_surface_destroy(ref);
        cf_bspline_surface_destroy(ins);
        cf_bspline_surface_destroy(b);
    }
}

/* The grid evaluator agrees with the point evaluator and the partials. */
static void
test_eval_grid(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 32);
    for (int t = 0; t < 40; t++) {
        sample s;
        int p = 1 + t % 4, q = 1 + (t / 4) % 4;
        size_t dim = t % 3 == 0 ? 2 : 3, nu = 7, nv = 9;
        cf_bspline_surface_t *b;
        double uv[16], ua, ub, va, vb, P[63 * 3], Su[63 * 3], Sv[63 * 3];
        make_sample(&r, &s, dim, p, q, (size_t)p + 4, (size_t)q + 3, t % 5,
                    t % 2);
        b = make_bspline(&s);
        cf_bspline_surface_domain(b, CF_DIR_U, &ua, &ub);
        cf_bspline_surface_domain(b, CF_DIR_V, &va, &vb);
        for (size_t i = 0; i < nu; i++)
            uv[i] = ua + (ub - ua) * (double)i / (double)(nu - 1);
        for (size_t j = 0; j < nv; j++)
            uv[nu + j] = va + (vb - va) * (double)j / (double)(nv - 1);
        assert_int_equal(cf_bspline_surface_eval_grid(b, uv, nu, nv, P, Su,
                                                      Sv), 0);
        for (size_t i = 0; i < nu; i++)
            for (size_t j = 0; j < nv; j++) {
                double D[9 * 3], one[3];
                size_t o = (i * nv + j) * dim;
                assert_int_equal(cf_bspline_surface_eval_derivs(
                                     b, uv[i], uv[nu + j], 1, D), 0);
                assert_int_equal(cf_bspline_surface_eval(b, uv[i], uv[nu + j],
                                                         one), 0);
                for (size_t c = 0; c < dim; c++) {
                    tu_assert_close(P[o + c], one[c], 64 * EPS, size_of(&s));
                    tu_assert_close(Su[o + c], D[2 * dim + c], 1e-12,
                                    size_of(&s));
                    tu_assert_close(Sv[o + c], D[1 * dim + c], 1e-12,
                                    size_of(&s));
                }
            }
        /* a parameter outside: nothing written */
        uv[3] = ub + 1.0;
        P[0] = 12345.0;
        assert_int_equal(cf_bspline_surface_eval_grid(b, uv, nu, nv, P, NULL,
                                                      NULL), CF_STATUS_DOMAIN);
        assert_true(P[0] == 12345.0);
        cf_bspline_surface_destroy(b);
    }
}

static void
test_out_of_memory(void **state)
{
    tu_rng r;
    sample s;
    (void)state;
    tu_rng_seed(&r, 33);
    make_sample(&r, &s, 3, 2, 3, 5, 6, 1, 1);
    for (long k = 1; k < 40; k++) {
        cf_bspline_surface_t *b = NULL, *e = NULL;
        cf_bezier_surface_list_t *L = NULL;
        cf_status_t st;
        tu_fail_alloc_after(k);
        st = cf_bspline_surface_create(3, 2, 3, s.U, 8, s.V, 10, s.P, 5, 6,
                                       s.W, &b, NULL);
        if (st == CF_STATUS_OK) {
            st = cf_bspline_surface_elevate(b, 1, 1, &e, NULL);
            assert_true(st == CF_STATUS_OK || st == CF_STATUS_NO_MEMORY);
            st = cf_bspline_surface_to_beziers(b, &L, NULL);
            assert_true(st == CF_STATUS_OK || st == CF_STATUS_NO_MEMORY);
        } else {
            assert_int_equal(st, CF_STATUS_NO_MEMORY);
        }
        cf_bezier_surface_list_destroy(L);
        cf_bspline_surface_destroy(e);
        cf_bspline_surface_destroy(b);
        assert_int_equal(tu_alloc_live(), 0);
        tu_fail_alloc_reset();
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bezier_eval_derivs),
        cmocka_unit_test(test_bspline_eval_derivs),
        cmocka_unit_test(test_iso_and_schemes),
        cmocka_unit_test(test_bezier_constructions),
        cmocka_unit_test(test_bspline_constructions),
        cmocka_unit_test(test_eval_grid),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
