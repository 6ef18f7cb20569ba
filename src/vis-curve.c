/* Visibility of curves and points in a scene (curvefig/visibility.h). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "vis-private.h"

/* Samples per Bézier piece: at least MIN_SAMPLES, at image steps of at
** most STEP tol, at most MAX_SAMPLES. */
#define MIN_SAMPLES 64
#define STEP 16.0
#define MAX_SAMPLES 65536

/* A curve to classify: Bézier pieces with their parameter ranges. */
typedef struct vcurve {
    const cf_bezier_t **piece;
    const double *t0, *t1;
    size_t n;
    const cf_vis_on_t *on;
    const cf_silhouette_piece_t *sil;   /* classify at the exact contour */
} vcurve_t;

typedef struct sample {
    double t;
    double q[3];
    bool in_front;      /* in front of the eye */
    bool hidden;
    size_t occ;
} sample_t;

static cf_status_t
check_on(const cf_scene_t *sc, const cf_vis_on_t *on, bool curve,
         cf_diag_t *diag)
{
    if (on == NULL)
        return CF_STATUS_OK;
    if (on->surface >= sc->nsurf)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "on: surface %zu is not in the scene (it has %zu)",
                         on->surface, sc->nsurf);
    if (curve && on->uv_bezier != NULL && on->uv_bspline != NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "on: give uv_bezier or uv_bspline, not both");
    if (curve && ((on->uv_bezier != NULL && cf_bezier_dim(on->uv_bezier) != 2) ||
                  (on->uv_bspline != NULL &&
                   cf_bspline_dim(on->uv_bspline) != 2)))
        return cf__error(diag, CF_STATUS_DIM_MISMATCH, -1,
                         "on: the (u, v) curve must be in R^2");
    if (!(on->offset >= 0.0 && isfinite(on->offset)))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "on: offset %g must be finite and >= 0", on->offset);
    if (!curve && (!isfinite(on->uv[0]) || !isfinite(on->uv[1])))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "on: uv (%g, %g) is not finite", on->uv[0],
                         on->uv[1]);
    return CF_STATUS_OK;
}

static void
classify(const cf_scene_t *sc, const vcurve_t *vc, size_t k, double tau,
         sample_t *s)
{
    double p[3], t = vc->t0[k] + tau * (vc->t1[k] - vc->t0[k]);
    cf__vself_t self = {false, 0, {0.0, 0.0}, 0.0};
    s->t = t;
    s->hidden = false;
    s->occ = SIZE_MAX;
    if (vc->sil != NULL) {
        double uv[2], a = 1.0 - tau;
        const double *c = vc->sil->uv;
        for (int e = 0; e < 2; e++)
            uv[e] = a * a * a * c[e] + 3 * a * a * tau * c[2 + e] +
                    3 * a * tau * tau * c[4 + e] + tau * tau * tau * c[6 + e];
        s->in_front = cf__contour_point(sc, vc->sil->surface, uv, s->q);
        if (!s->in_front)
            s->hidden = true;
        else
            s->hidden = cf__scene_hidden(sc, s->q, &self, &s->occ);
        return;
    }
    s->in_front = cf_bezier_eval(vc->piece[k], tau, p) == CF_STATUS_OK &&
                  cf__view_apply(sc->M, p, s->q);
    if (!s->in_front) {
        s->hidden = true;
        return;
    }
    if (vc->on != NULL) {
        const cf_vis_on_t *on = vc->on;
        self.surface = on->surface;
        self.offset = on->offset;
        if (on->uv_bezier != NULL)
            self.has = cf_bezier_eval(on->uv_bezier, t, self.uv) ==
                       CF_STATUS_OK;
        else if (on->uv_bspline != NULL)
            self.has = cf_bspline_eval(on->uv_bspline, t, self.uv) ==
                       CF_STATUS_OK;
    }
    s->hidden = cf__scene_hidden(sc, s->q, &self, &s->occ);
}

/* Samples of piece k. */
static size_t
sample_count(const cf_scene_t *sc, const cf_bezier_t *c)
{
    size_t n = (size_t)cf_bezier_degree(c) + 1;
    double len = 0.0, prev[3] = {0, 0, 0}, pts[3];
    const double *h = cf_bezier_hpoints(c);
    bool rat = cf_bezier_is_rational(c), have = false;
    for (size_t i = 0; i < n; i++) {
        const double *x = h + i * (rat ? 4 : 3);
        double p[3] = {x[0], x[1], x[2]}, q[3];
        if (rat)
            for (int e = 0; e < 3; e++)
                p[e] /= x[3];
        if (!cf__view_apply(sc->M, p, q))
            continue;
        if (have)
            len += hypot(q[0] - prev[0], q[1] - prev[1]);
        memcpy(prev, q, sizeof prev);
        have = true;
    }
    (void)pts;
    double want = ceil(len / (STEP * sc->tol));
    if (!(want >= MIN_SAMPLES))
        return MIN_SAMPLES;
    return want > MAX_SAMPLES ? MAX_SAMPLES : (size_t)want;
}

static cf_status_t
push(cf_visibility_t *v, size_t *cap, double t0, double t1, bool visible,
     size_t occ)
{
    if (v->n > 0 && v->items[v->n - 1].visible == visible) {
        v->items[v->n - 1].t1 = t1;
        return CF_STATUS_OK;
    }
    cf_vis_interval_t *it = cf__grow(v->items, cap, v->n + 1, sizeof *it, 8);
    if (it == NULL)
        return CF_STATUS_NO_MEMORY;
    v->items = it;
    it[v->n].t0 = t0;
    it[v->n].t1 = t1;
    it[v->n].visible = visible;
    it[v->n].occluder = visible ? SIZE_MAX : occ;
    v->n++;
    return CF_STATUS_OK;
}

/* Bisect between samples a and b (local tau ta, tb of piece k) of
** different visibility until their images are within tol / 2. */
static double
bisect(const cf_scene_t *sc, const vcurve_t *vc, size_t k, double ta,
       double tb, sample_t a, sample_t b)
{
    for (int it = 0; it < 60; it++) {
        double d = a.in_front && b.in_front
                       ? hypot(a.q[0] - b.q[0], a.q[1] - b.q[1])
                       : HUGE_VAL;
        if (d <= 0.5 * sc->tol || tb - ta <= 1e-15)
            break;
        double tm = 0.5 * (ta + tb);
        sample_t m;
        classify(sc, vc, k, tm, &m);
        if (m.hidden == a.hidden) {
            a = m;
            ta = tm;
        } else {
            b = m;
            tb = tm;
        }
    }
    return vc->t0[k] + 0.5 * (ta + tb) * (vc->t1[k] - vc->t0[k]);
}

/*
** Whether nothing can hide the part [ta, tb] (local) of piece k between
** two visible samples: the view-space box of its control points (the
** view is projective, so the part's view-space net keeps the convex hull
** while its weights stay positive) meets no leaf that may lie in front.
*/
static bool
part_clear(const cf_scene_t *sc, const cf_bezier_t *c, double ta, double tb)
{
    double h[CF__VIS_MAX_DEG + 1][4], lo[3], hi[3];
    int n = cf_bezier_degree(c);
    bool rat = cf_bezier_is_rational(c);
    const double *x = cf_bezier_hpoints(c);
    if (n > CF__VIS_MAX_DEG || !(tb > ta))
        return false;
    for (int i = 0; i <= n; i++)
        for (int e = 0; e < 4; e++)
            h[i][e] = e < 3 ? x[i * (rat ? 4 : 3) + e]
                            : (rat ? x[i * 4 + 3] : 1.0);
    /* [0, tb] by de Casteljau, then its part [ta / tb, 1] */
    for (int r = 1; r <= n; r++)
        for (int i = n; i >= r; i--)
            for (int e = 0; e < 4; e++)
                h[i][e] = (1 - tb) * h[i - 1][e] + tb * h[i][e];
    double a = ta / tb;
    for (int r = 1; r <= n; r++)
        for (int i = 0; i <= n - r; i++)
            for (int e = 0; e < 4; e++)
                h[i][e] = (1 - a) * h[i][e] + a * h[i + 1][e];
    for (int e = 0; e < 3; e++) {
        lo[e] = HUGE_VAL;
        hi[e] = -HUGE_VAL;
    }
    for (int i = 0; i <= n; i++) {
        double g[4];
        for (int r = 0; r < 4; r++)
            g[r] = sc->M[4 * r] * h[i][0] + sc->M[4 * r + 1] * h[i][1] +
                   sc->M[4 * r + 2] * h[i][2] + sc->M[4 * r + 3] * h[i][3];
        if (!(g[3] > 0.0))
            return false;
        for (int e = 0; e < 3; e++) {
            lo[e] = fmin(lo[e], g[e] / g[3]);
            hi[e] = fmax(hi[e], g[e] / g[3]);
        }
    }
    return cf__scene_box_clear(sc, lo, hi);
}

typedef struct walk {
    cf_visibility_t *v;
    size_t cap;
    double tstart;
} walk_t;

/* Between samples a and b (local ta, tb of piece k): a split where they
** differ; where both are visible the part between them is certified clear
** of occluders or halved, down to image steps of tol (free curves: a curve
** on a surface meets its own surface's boxes everywhere). */
static cf_status_t
span(const cf_scene_t *sc, const vcurve_t *vc, size_t k, walk_t *w,
     double ta, const sample_t *a, double tb, const sample_t *b, int depth)
{
    if (b->hidden != a->hidden) {
        double ts = bisect(sc, vc, k, ta, tb, *a, *b);
        cf_status_t st = push(w->v, &w->cap, w->tstart, ts, !a->hidden,
                              a->occ);
        w->tstart = ts;
        return st;
    }
    if (a->hidden || vc->on != NULL || vc->sil != NULL || depth >= 40 ||
        hypot(a->q[0] - b->q[0], a->q[1] - b->q[1]) <= sc->tol ||
        part_clear(sc, vc->piece[k], ta, tb))
        return CF_STATUS_OK;
    double tm = 0.5 * (ta + tb);
    sample_t m;
    classify(sc, vc, k, tm, &m);
    cf_status_t st = span(sc, vc, k, w, ta, a, tm, &m, depth + 1);
    if (st == CF_STATUS_OK)
        st = span(sc, vc, k, w, tm, &m, tb, b, depth + 1);
    return st;
}

static cf_status_t
run(const cf_scene_t *sc, const vcurve_t *vc, cf_visibility_t **out,
    cf_diag_t *diag)
{
    walk_t w = {cf__calloc(1, sizeof *w.v), 0, 0.0};
    cf_status_t st = CF_STATUS_OK;
    if (w.v == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    for (size_t k = 0; k < vc->n && st == CF_STATUS_OK; k++) {
        size_t ns = sample_count(sc, vc->piece[k]);
        sample_t a, b;
        double ta = 0.0;
        w.tstart = vc->t0[k];
        classify(sc, vc, k, 0.0, &a);
        for (size_t i = 1; i <= ns && st == CF_STATUS_OK; i++) {
            double tb = (double)i / (double)ns;
            classify(sc, vc, k, tb, &b);
            st = span(sc, vc, k, &w, ta, &a, tb, &b, 0);
            a = b;
            ta = tb;
        }
        if (st == CF_STATUS_OK)
            st = push(w.v, &w.cap, w.tstart, vc->t1[k], !a.hidden, a.occ);
    }
    if (st != CF_STATUS_OK) {
        cf_visibility_destroy(w.v);
        return cf__error(diag, st, -1, "out of memory");
    }
    *out = w.v;
    return CF_STATUS_OK;
}

void
cf_visibility_destroy(cf_visibility_t *v)
{
    if (v == NULL)
        return;
    cf__free(v->items);
    cf__free(v);
}

static cf_status_t
check_args(const cf_scene_t *sc, const void *c, size_t dim,
           const cf_vis_on_t *on, cf_visibility_t **out, cf_diag_t *diag)
{
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    if (sc == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "scene is NULL");
    if (c == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "curve is NULL");
    if (dim != 3)
        return cf__error(diag, CF_STATUS_DIM_MISMATCH, -1,
                         "curve is in R^%zu; visibility is for curves in "
                         "R^3", dim);
    return check_on(sc, on, true, diag);
}

cf_status_t
cf_scene_curve_visibility(const cf_scene_t *sc, const cf_bezier_t *c,
                          const cf_vis_on_t *on, cf_visibility_t **out,
                          cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st;
    double t0 = 0.0, t1 = 1.0;
    if ((st = check_args(sc, c, cf_bezier_dim(c), on, out, diag)) != 0)
        return st;
    vcurve_t vc = {&c, &t0, &t1, 1, on, NULL};
    return run(sc, &vc, out, diag);
}

cf_status_t
cf_scene_bspline_visibility(const cf_scene_t *sc, const cf_bspline_t *c,
                            const cf_vis_on_t *on, cf_visibility_t **out,
                            cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st;
    cf_bezier_list_t *list = NULL;
    if ((st = check_args(sc, c, cf_bspline_dim(c), on, out, diag)) != 0)
        return st;
    if ((st = cf_bspline_to_beziers(c, &list, diag)) != CF_STATUS_OK)
        return st;
    if (list->t0 == NULL || list->t1 == NULL) {
        cf_bezier_list_destroy(list);
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "curve: its Bézier pieces have no parameter ranges");
    }
    vcurve_t vc = {(const cf_bezier_t **)list->items, list->t0, list->t1,
                   list->count, on, NULL};
    st = run(sc, &vc, out, diag);
    cf_bezier_list_destroy(list);
    return st;
}

cf_status_t
cf_scene_point_visible(const cf_scene_t *sc, const double *p,
                       const cf_vis_on_t *on, bool *visible, size_t *occluder,
                       cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st;
    double q[3];
    size_t occ = SIZE_MAX;
    cf__vself_t self = {false, 0, {0.0, 0.0}, 0.0};
    if (sc == NULL || p == NULL || visible == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "%s is NULL",
                         sc == NULL ? "scene" : p == NULL ? "point"
                                                          : "visible");
    if ((st = check_on(sc, on, false, diag)) != CF_STATUS_OK)
        return st;
    for (int i = 0; i < 3; i++)
        if (!isfinite(p[i]))
            return cf__error(diag, CF_STATUS_NOT_FINITE, i,
                             "point coordinate %d = %g is not finite", i,
                             p[i]);
    if (on != NULL) {
        self.has = true;
        self.surface = on->surface;
        self.uv[0] = on->uv[0];
        self.uv[1] = on->uv[1];
        self.offset = on->offset;
    }
    if (!cf__view_apply(sc->M, p, q)) {
        *visible = false;
    } else {
        *visible = !cf__scene_hidden(sc, q, &self, &occ);
    }
    if (occluder != NULL)
        *occluder = *visible ? SIZE_MAX : occ;
    return CF_STATUS_OK;
}

cf_status_t
cf_scene_silhouette_visibility(const cf_scene_t *sc,
                               const cf_silhouette_t *sil, size_t piece,
                               cf_visibility_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st;
    cf_bezier_t *c = NULL;
    double t0 = 0.0, t1 = 1.0;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    if (sc == NULL || sil == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "%s is NULL",
                         sc == NULL ? "scene" : "silhouette");
    if (piece >= sil->n)
        return cf__error(diag, CF_STATUS_INVALID_ARG, (long)piece,
                         "piece %zu is not in the silhouette (it has %zu)",
                         piece, sil->n);
    if (sil->items[piece].surface >= sc->nsurf)
        return cf__error(diag, CF_STATUS_INVALID_ARG, (long)piece,
                         "piece %zu: surface %zu is not in the scene",
                         piece, sil->items[piece].surface);
    st = cf_bezier_create(3, 3, sil->items[piece].space, NULL, &c, diag);
    if (st != CF_STATUS_OK)
        return st;
    const cf_bezier_t *cc = c;
    vcurve_t vc = {&cc, &t0, &t1, 1, NULL, &sil->items[piece]};
    st = run(sc, &vc, out, diag);
    cf_bezier_destroy(c);
    return st;
}
