/* Visibility of curves and points in a scene (curvefig/visibility.h). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "numtext-private.h"
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
    /* for the gaps of a curve on a surface: the surface, its (u, v) curve
    ** (a Bézier on the curve's parameter, or Bézier pieces with their
    ** ranges; both NULL: unknown), whether it lies exactly on it */
    size_t surface;
    const cf_bezier_t *uvb;
    const cf_bezier_list_t *uvl;
    bool strict;
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
                         "on: offset %s must be finite and >= 0",
                         CF__NUM(on->offset));
    if (!curve && (!isfinite(on->uv[0]) || !isfinite(on->uv[1])))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "on: uv (%s, %s) is not finite", CF__NUM(on->uv[0]),
                         CF__NUM(on->uv[1]));
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
        if ((a.in_front && b.in_front &&
             cf__hypot_le(a.q[0] - b.q[0], a.q[1] - b.q[1], 0.5 * sc->tol)) ||
            tb - ta <= 1e-15)
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

/* The homogeneous control points of the part [ta, tb] (0 <= ta < tb <= 1)
** of c (in R^1..3): h[i][e] = w x_e (e < dim), h[i][3] = w; false for a
** degree above CF__VIS_MAX_DEG. */
CF__NO_COVERAGE static bool
part_net(const cf_bezier_t *c, double ta, double tb,
         double h[CF__VIS_MAX_DEG + 1][4])
{
    int n = cf_bezier_degree(c);
    size_t dim = cf_bezier_dim(c);
    bool rat = cf_bezier_is_rational(c);
    const double *x = cf_bezier_hpoints(c);
    size_t stride = dim + (rat ? 1 : 0);
    if (n > CF__VIS_MAX_DEG || dim > 3 || !(tb > ta))
        return false;
    for (int i = 0; i <= n; i++) {
        for (size_t e = 0; e < 3; e++)
            h[i][e] = e < dim ? x[(size_t)i * stride + e] : 0.0;
        h[i][3] = rat ? x[(size_t)i * stride + dim] : 1.0;
    }
    cf__hcurve_part(&h[0][0], n, 4, ta, tb);
    return true;
}

/* The view-space box lo[3], hi[3] of the control points of the part
** [ta, tb] of c (in R^3): it holds the part (the view is projective, so
** the part's view-space net keeps the convex hull while its weights stay
** positive); false when a weight is not. */
static bool
part_box(const cf_scene_t *sc, const cf_bezier_t *c, double ta, double tb,
         double *lo, double *hi)
{
    double h[CF__VIS_MAX_DEG + 1][4];
    if (!part_net(c, ta, tb, h))
        return false;
    for (int e = 0; e < 3; e++) {
        lo[e] = HUGE_VAL;
        hi[e] = -HUGE_VAL;
    }
    for (int i = 0; i <= cf_bezier_degree(c); i++) {
        double g[4];
        for (int r = 0; r < 4; r++)
            g[r] = sc->M[4 * r] * h[i][0] + sc->M[4 * r + 1] * h[i][1] +
                   sc->M[4 * r + 2] * h[i][2] + sc->M[4 * r + 3] * h[i][3];
        if (!(g[3] > 0.0))
            return false;
        for (int e = 0; e < 3; e++) {
            lo[e] = cf__fmin(lo[e], g[e] / g[3]);
            hi[e] = cf__fmax(hi[e], g[e] / g[3]);
        }
    }
    return true;
}

/* Widen box[4] (u0 u1 v0 v1) by the control points of the part [a, b]
** of the (u, v) curve uv; false if they are not all finite. */
static bool
uv_extend(const cf_bezier_t *uv, double a, double b, double *box)
{
    double h[CF__VIS_MAX_DEG + 1][4];
    if (!part_net(uv, a, b, h))
        return false;
    for (int i = 0; i <= cf_bezier_degree(uv); i++) {
        if (!(h[i][3] > 0.0))
            return false;
        for (int e = 0; e < 2; e++) {
            double x = h[i][e] / h[i][3];
            if (!isfinite(x))
                return false;
            box[2 * e] = cf__fmin(box[2 * e], x);
            box[2 * e + 1] = cf__fmax(box[2 * e + 1], x);
        }
    }
    return true;
}

/* The box of the (u, v) of the part [ta, tb] (local) of piece k: its (u,
** v) curve's control points there; false when unknown. */
static bool
part_uv(const vcurve_t *vc, size_t k, double ta, double tb, double *box)
{
    double d = vc->t1[k] - vc->t0[k];
    double ga = vc->t0[k] + ta * d, gb = vc->t0[k] + tb * d;
    box[0] = box[2] = HUGE_VAL;
    box[1] = box[3] = -HUGE_VAL;
    if (vc->uvb != NULL)   /* parametrised as the curve: [0, 1] */
        return ga >= 0.0 && gb <= 1.0 && uv_extend(vc->uvb, ga, gb, box);
    if (vc->uvl == NULL)
        return false;
    bool any = false;
    for (size_t j = 0; j < vc->uvl->count; j++) {
        double T0 = vc->uvl->t0[j], T1 = vc->uvl->t1[j];
        if (!(T1 > T0) || T1 <= ga || T0 >= gb)
            continue;
        if (!uv_extend(vc->uvl->items[j], (cf__fmax(ga, T0) - T0) / (T1 - T0),
                       (cf__fmin(gb, T1) - T0) / (T1 - T0), box))
            return false;
        any = true;
    }
    return any;
}

/*
** Whether nothing can hide the part [ta, tb] (local) of piece k between
** two visible samples: the view-space box of its control points meets no
** leaf that may lie in front.  For a curve on a surface whose (u, v) curve
** is known, the surface's own leaves about the part's (u, v) are judged by
** cf__scene_box_clear_on; a silhouette's box is widened by its piece's
** error (the samples are the exact contour points).
*/
static bool
part_clear(const cf_scene_t *sc, const vcurve_t *vc, size_t k, double ta,
           double tb)
{
    double lo[3], hi[3], uv[4];
    if (!part_box(sc, vc->piece[k], ta, tb, lo, hi))
        return false;
    if (vc->on == NULL && vc->sil == NULL)
        return cf__scene_box_clear(sc, lo, hi);
    if (!part_uv(vc, k, ta, tb, uv))
        return false;
    if (vc->sil != NULL) {
        double e = vc->sil->error_image, f = 1.0;
        if (sc->view.projection == CF_PROJECTION_PERSPECTIVE)
            f = (sc->view.distance + hi[2]) / sc->view.distance;
        for (int i = 0; i < 3; i++) {
            double g = i < 2 ? e : vc->sil->error_space * f * f;
            lo[i] -= g;
            hi[i] += g;
        }
    }
    return cf__scene_box_clear_on(sc, lo, hi, vc->surface, uv, vc->strict);
}

typedef struct walk {
    cf_visibility_t *v;
    size_t cap;
    double tstart;
} walk_t;

/* Between samples a and b (local ta, tb of piece k): a split where they
** differ; where both are visible the part between them is certified clear
** of occluders or halved, down to image steps of tol.  A curve said to lie
** on a surface without its (u, v) curve is not certified (its own
** surface's boxes meet it everywhere). */
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
    if (a->hidden || depth >= 40 ||
        (vc->on != NULL && vc->uvb == NULL && vc->uvl == NULL) ||
        cf__hypot_le(a->q[0] - b->q[0], a->q[1] - b->q[1], sc->tol) ||
        part_clear(sc, vc, k, ta, tb))
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

/* Classify a curve said to lie on a surface (on may be NULL): its (u, v)
** curve for the certified gaps (a B-spline's Bézier pieces; left
** unknown when they cannot be made). */
static cf_status_t
run_on(const cf_scene_t *sc, vcurve_t *vc, const cf_vis_on_t *on,
       cf_visibility_t **out, cf_diag_t *diag)
{
    cf_bezier_list_t *uvl = NULL;
    cf_status_t st;
    if (on != NULL) {
        vc->surface = on->surface;
        vc->uvb = on->uv_bezier;
        vc->strict = on->offset == 0.0;
        if (on->uv_bspline != NULL &&
            cf_bspline_to_beziers(on->uv_bspline, &uvl, NULL) ==
                CF_STATUS_OK &&
            uvl->t0 != NULL && uvl->t1 != NULL)
            vc->uvl = uvl;
    }
    st = run(sc, vc, out, diag);
    cf_bezier_list_destroy(uvl);
    return st;
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
    vcurve_t vc = {&c, &t0, &t1, 1, on, NULL, 0, NULL, NULL, false};
    return run_on(sc, &vc, on, out, diag);
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
                   list->count, on, NULL, 0, NULL, NULL, false};
    st = run_on(sc, &vc, on, out, diag);
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
                             "point coordinate %d = %s is not finite", i,
                             CF__NUM(p[i]));
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
    cf_bezier_t *c = NULL, *uv = NULL;
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
    if (st == CF_STATUS_OK)
        st = cf_bezier_create(2, 3, sil->items[piece].uv, NULL, &uv, diag);
    if (st != CF_STATUS_OK) {
        cf_bezier_destroy(c);
        return st;
    }
    const cf_bezier_t *cc = c;
    vcurve_t vc = {&cc, &t0, &t1, 1, NULL, &sil->items[piece],
                   sil->items[piece].surface, uv, NULL, false};
    st = run(sc, &vc, out, diag);
    cf_bezier_destroy(c);
    cf_bezier_destroy(uv);
    return st;
}
