/*
** The figure model: elements in drawing order, the data window and the
** data -> page map, and drawing onto a cairo context.
**
** Curves are kept as Bézier pieces in the plane (projected when given in
** R^3 or higher) and turned into cubic segments when the figure is laid
** out, because the fitting tolerance is given on the page and the scale is
** known only then.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "curvefig/bspline.h"
#include "render-private.h"

typedef enum el_kind {
    EL_CURVE,
    EL_POLYGON,
    EL_POLYLINE,
    EL_POINTS,
    EL_HULL,
    EL_FILL,
    EL_LABEL,
    EL_ARROW,
    EL_KNOTS,
    EL_NET,
    EL_AXES
} el_kind_t;

/* One piece of a curve: a planar Bézier converted at layout time, or a
** fixed cubic segment (8 doubles). */
typedef struct piece {
    cf_bezier_t *bez;
    double cubic[8];
    cf_cubics_t *cache;      /* conversion of bez */
    double cache_tol;
} piece_t;

/* A label's text and its current layout. */
typedef struct text {
    char *src;
    cf_label_t *lab;
} text_t;

typedef struct tick {
    double v;
    text_t t;
} tick_t;

typedef struct axes_el {
    cf_axes_t a;             /* pointers cleared */
    tick_t *xt, *yt, *kn;
    size_t nxt, nyt, nkn;
    text_t xlabel, ylabel;
} axes_el_t;

typedef struct element {
    el_kind_t kind;
    cf_role_t role;
    cf_style_t style;        /* overrides */
    double *pts;             /* 2D points (knots: then n tangents) */
    size_t n;
    bool has_dirs, closed;
    size_t *counts;          /* net levels */
    size_t levels;
    cf_color_t *colors;
    piece_t *pieces;
    size_t npieces;
    text_t text;
    double x, y, dx, dy;
    axes_el_t *axes;
    cf_place_t auto_place;   /* labels placed CF_PLACE_AUTO: the place
                                chosen for the current layout */
} element_t;

struct cf_figure {
    cf_diag_t err;           /* the first error (sticky) */
    double width, height;    /* bp */
    char *title, *caption;
    cf_theme_t theme;
    bool window_set;
    double win[4];
    double margin;
    int aspect;              /* -1 automatic, 0 free, 1 kept */
    double tol;
    size_t proj_dim;
    double *proj;            /* 2 x proj_dim */
    element_t *els;
    size_t count, cap;
};

/* ---- errors ------------------------------------------------------------- */

#define FIG_CHECK(fig)                                                     \
    do {                                                                   \
        if ((fig) == NULL)                                                 \
            return CF_STATUS_INVALID_ARG;                                  \
        if ((fig)->err.status != CF_STATUS_OK)                             \
            return (fig)->err.status;                                      \
    } while (0)

/* Record st in the figure (with a generic message if the callee left
** none) and return it. */
static cf_status_t
fig_fail(cf_figure_t *fig, cf_status_t st, const char *what)
{
    if (st != CF_STATUS_OK && fig->err.status == CF_STATUS_OK)
        cf__error(&fig->err, st, -1, "%s: %s", what,
                  cf_status_to_string(st));
    return st;
}

static cf_status_t
check_points(cf_figure_t *fig, const double *pts, size_t n, size_t min,
             const char *what)
{
    if (pts == NULL && n > 0)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "%s: points are NULL", what);
    if (n < min)
        return cf__error(&fig->err, CF_STATUS_TOO_FEW_POINTS, (long)n,
                         "%s: %zu points given, at least %zu needed", what,
                         n, min);
    return cf__check_finite_points(pts, n, 2, 2, what, &fig->err);
}

static cf_status_t
check_style(cf_figure_t *fig, const cf_style_t *style)
{
    return cf__style_check(style, &fig->err);
}

/* ---- figure ------------------------------------------------------------- */

cf_status_t
cf_figure_create(double width, double height, cf_unit_t unit,
                 cf_figure_t **out, cf_diag_t *diag)
{
    cf_figure_t *fig;
    double w, h;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "figure output pointer is NULL");
    *out = NULL;
    if ((unsigned)unit >= CF_UNIT_LAST_)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "unknown unit %d", (int)unit);
    w = cf_length_to_bp(width, unit);
    h = cf_length_to_bp(height, unit);
    if (!(isfinite(w) && isfinite(h) && w > 0 && h > 0))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "figure size %g x %g must be finite and positive",
                         width, height);
    if (w > 14400 || h > 14400)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "figure size %g x %g bp exceeds 14400 bp (200 in)",
                         w, h);
    fig = cf__calloc(1, sizeof *fig);
    if (fig == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for a figure");
    cf_diag_clear(&fig->err);
    fig->width = w;
    fig->height = h;
    cf_theme_get("default", &fig->theme, NULL);
    fig->margin = 4.0;
    fig->aspect = -1;
    fig->tol = 0.01;
    *out = fig;
    return CF_STATUS_OK;
}

static void
text_fini(text_t *t)
{
    cf__free(t->src);
    cf_label_destroy(t->lab);
    t->src = NULL;
    t->lab = NULL;
}

static void
pieces_free(piece_t *pc, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        cf_bezier_destroy(pc[i].bez);
        cf_cubics_destroy(pc[i].cache);
    }
    cf__free(pc);
}

static void
element_fini(element_t *e)
{
    size_t i;
    cf__free(e->pts);
    cf__free(e->counts);
    cf__free(e->colors);
    pieces_free(e->pieces, e->npieces);
    text_fini(&e->text);
    if (e->axes != NULL) {
        for (i = 0; i < e->axes->nxt; i++)
            text_fini(&e->axes->xt[i].t);
        for (i = 0; i < e->axes->nyt; i++)
            text_fini(&e->axes->yt[i].t);
        for (i = 0; i < e->axes->nkn; i++)
            text_fini(&e->axes->kn[i].t);
        cf__free(e->axes->xt);
        cf__free(e->axes->yt);
        cf__free(e->axes->kn);
        text_fini(&e->axes->xlabel);
        text_fini(&e->axes->ylabel);
        cf__free(e->axes);
    }
}

void
cf_figure_destroy(cf_figure_t *fig)
{
    size_t i;
    if (fig == NULL)
        return;
    for (i = 0; i < fig->count; i++)
        element_fini(&fig->els[i]);
    cf__free(fig->els);
    cf__free(fig->title);
    cf__free(fig->caption);
    cf__free(fig->proj);
    cf__free(fig);
}

cf_status_t
cf_figure_status(const cf_figure_t *fig, cf_diag_t *diag)
{
    if (fig == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "figure is NULL");
    if (fig->err.status != CF_STATUS_OK && diag != NULL
        && diag->status == CF_STATUS_OK)
        *diag = fig->err;
    return fig->err.status;
}

void
cf_figure_get_size(const cf_figure_t *fig, double *width_bp,
                   double *height_bp)
{
    if (width_bp != NULL)
        *width_bp = fig != NULL ? fig->width : 0;
    if (height_bp != NULL)
        *height_bp = fig != NULL ? fig->height : 0;
}

static cf_status_t
set_string(cf_figure_t *fig, char **dst, const char *src, const char *what)
{
    char *copy = NULL;
    FIG_CHECK(fig);
    if (src != NULL) {
        size_t n = strlen(src);
        copy = cf__malloc(n + 1);
        if (copy == NULL)
            return cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                             "out of memory for the %s", what);
        memcpy(copy, src, n + 1);
    }
    cf__free(*dst);
    *dst = copy;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_set_title(cf_figure_t *fig, const char *title)
{
    return set_string(fig, fig != NULL ? &fig->title : NULL, title, "title");
}

cf_status_t
cf_figure_set_caption(cf_figure_t *fig, const char *caption)
{
    return set_string(fig, fig != NULL ? &fig->caption : NULL, caption,
                      "caption");
}

cf_status_t
cf_figure_set_theme(cf_figure_t *fig, const cf_theme_t *theme)
{
    size_t i;
    FIG_CHECK(fig);
    if (theme == NULL)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "theme is NULL");
    for (i = 0; i < CF_ROLE_LAST_; i++) {
        cf_style_t s = theme->role[i];
        s.set = CF_STYLE_ALL_;
        if (cf__style_check(&s, &fig->err) != CF_STATUS_OK)
            return fig->err.status;
    }
    if (theme->palette_size < 1 || theme->palette_size > CF_PALETTE_MAX)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "theme palette has %zu colours (1 to %d allowed)",
                         theme->palette_size, CF_PALETTE_MAX);
    if (memchr(theme->font_family, '\0', CF_FONT_FAMILY_MAX) == NULL
        || theme->font_family[0] == '\0')
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "theme font family is empty or not terminated");
    if (!(isfinite(theme->tick_size) && theme->tick_size >= 0))
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "theme tick size %g must be finite and >= 0",
                         theme->tick_size);
    fig->theme = *theme;
    return CF_STATUS_OK;
}

void
cf_figure_get_theme(const cf_figure_t *fig, cf_theme_t *out)
{
    if (out == NULL)
        return;
    if (fig == NULL)
        cf_theme_get("default", out, NULL);
    else
        *out = fig->theme;
}

cf_status_t
cf_figure_set_window(cf_figure_t *fig, double xmin, double xmax, double ymin,
                     double ymax)
{
    FIG_CHECK(fig);
    if (!(isfinite(xmin) && isfinite(xmax) && isfinite(ymin)
          && isfinite(ymax)))
        return cf__error(&fig->err, CF_STATUS_NOT_FINITE, -1,
                         "window [%g, %g] x [%g, %g] is not finite", xmin,
                         xmax, ymin, ymax);
    if (!(xmin < xmax && ymin < ymax))
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "window [%g, %g] x [%g, %g] is empty", xmin, xmax,
                         ymin, ymax);
    fig->window_set = true;
    fig->win[0] = xmin;
    fig->win[1] = xmax;
    fig->win[2] = ymin;
    fig->win[3] = ymax;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_set_window_auto(cf_figure_t *fig)
{
    FIG_CHECK(fig);
    fig->window_set = false;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_set_fit(cf_figure_t *fig, double margin_bp, bool keep_aspect)
{
    FIG_CHECK(fig);
    if (!(isfinite(margin_bp) && margin_bp >= 0
          && 2 * margin_bp < fmin(fig->width, fig->height)))
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "margin %g bp must be >= 0 and leave room on a "
                         "%g x %g bp page", margin_bp, fig->width,
                         fig->height);
    fig->margin = margin_bp;
    fig->aspect = keep_aspect ? 1 : 0;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_set_tolerance(cf_figure_t *fig, double tol_bp)
{
    FIG_CHECK(fig);
    if (!(isfinite(tol_bp) && tol_bp > 0))
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "tolerance %g must be finite and positive", tol_bp);
    fig->tol = tol_bp;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_set_projection(cf_figure_t *fig, size_t dim, const double *m)
{
    double *copy;
    FIG_CHECK(fig);
    if (dim < 2 || dim > 64 || m == NULL)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "projection: dimension %zu must be 2..64 and the "
                         "matrix not NULL", dim);
    if (cf__check_finite_points(m, 2, dim, dim, "projection row",
                                &fig->err) != CF_STATUS_OK)
        return fig->err.status;
    copy = cf__alloc_array(2 * dim, sizeof *copy);
    if (copy == NULL)
        return cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for a projection");
    memcpy(copy, m, 2 * dim * sizeof *copy);
    cf__free(fig->proj);
    fig->proj = copy;
    fig->proj_dim = dim;
    return CF_STATUS_OK;
}

/* Project one point of dimension dim (stride 1) into out[2]. */
static void
project1(const cf_figure_t *fig, const double *p, size_t dim, double *out)
{
    size_t j;
    if (fig->proj != NULL && fig->proj_dim == dim) {
        double x = 0, y = 0;
        for (j = 0; j < dim; j++) {
            x += fig->proj[j] * p[j];
            y += fig->proj[dim + j] * p[j];
        }
        out[0] = x;
        out[1] = y;
    } else {
        out[0] = p[0];
        out[1] = p[1];
    }
}

cf_status_t
cf_figure_project(cf_figure_t *fig, const double *in, size_t n, size_t dim,
                  double *out)
{
    size_t i;
    FIG_CHECK(fig);
    if ((in == NULL || out == NULL) && n > 0)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "project: points or output are NULL");
    if (dim < 2)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "project: dimension %zu is below 2", dim);
    if (cf__check_finite_points(in, n, dim, dim, "point", &fig->err)
        != CF_STATUS_OK)
        return fig->err.status;
    for (i = 0; i < n; i++) {
        double tmp[2];
        project1(fig, in + i * dim, dim, tmp);
        out[2 * i] = tmp[0];
        out[2 * i + 1] = tmp[1];
    }
    return CF_STATUS_OK;
}

/* ---- element list ------------------------------------------------------- */

static element_t *
new_element(cf_figure_t *fig, el_kind_t kind, cf_role_t role,
            const cf_style_t *style)
{
    element_t *e;
    if (fig->count == fig->cap) {
        size_t cap = fig->cap ? 2 * fig->cap : 16;
        element_t *ne = cf__realloc_array(fig->els, cap, sizeof *ne);
        if (ne == NULL) {
            cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                      "out of memory for figure element %zu", fig->count);
            return NULL;
        }
        fig->els = ne;
        fig->cap = cap;
    }
    e = &fig->els[fig->count];
    memset(e, 0, sizeof *e);
    e->kind = kind;
    e->role = role;
    if (style != NULL)
        e->style = *style;
    return e;
}

/* Make the element (filled in at fig->els[fig->count]) part of the figure,
** or release it on failure. */
static cf_status_t
commit(cf_figure_t *fig, element_t *e, cf_status_t st)
{
    if (st != CF_STATUS_OK) {
        element_fini(e);
        return fig_fail(fig, st, "figure element");
    }
    fig->count++;
    return CF_STATUS_OK;
}

static double *
copy_doubles(const double *src, size_t n)
{
    double *d = cf__alloc_array(n ? n : 1, sizeof *d);
    if (d != NULL && n > 0)
        memcpy(d, src, n * sizeof *d);
    return d;
}

/* The label font for a role. */
static double
role_font_size(const cf_figure_t *fig, cf_role_t role, const cf_style_t *s)
{
    cf_style_t r;
    cf__style_resolve(&fig->theme, role, s, &r);
    return r.font_size;
}

static cf_status_t
text_set(cf_figure_t *fig, text_t *t, const char *src, double size)
{
    size_t n = strlen(src);
    t->src = cf__malloc(n + 1);
    if (t->src == NULL)
        return cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for a label");
    memcpy(t->src, src, n + 1);
    return cf_label_create(src, fig->theme.font_family, size, &t->lab,
                           &fig->err);
}

/* Lay the label out again if the theme's family or the size changed. */
static cf_status_t
text_ensure(cf_figure_t *fig, text_t *t, double size)
{
    cf_label_t *lab;
    cf_status_t st;
    if (cf__label_matches(t->lab, fig->theme.font_family, size))
        return CF_STATUS_OK;
    st = cf_label_create(t->src, fig->theme.font_family, size, &lab,
                         &fig->err);
    if (st != CF_STATUS_OK)
        return st;
    cf_label_destroy(t->lab);
    t->lab = lab;
    return CF_STATUS_OK;
}

/* ---- curves ------------------------------------------------------------- */

/* A planar copy of c (projected when dim >= 3). */
static cf_status_t
planar_bezier(cf_figure_t *fig, const cf_bezier_t *c, cf_bezier_t **out)
{
    size_t dim = cf_bezier_dim(c), hd, i, np;
    int deg = cf_bezier_degree(c);
    bool rat = cf_bezier_is_rational(c);
    const double *hp = cf_bezier_hpoints(c);
    double *q;
    cf_status_t st;

    if (dim == 2)
        return cf_bezier_copy(c, out, &fig->err);
    if (dim < 2)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "a curve in R^%zu cannot be drawn as a plane "
                         "curve (use a graph for functions)", dim);
    hd = dim + (rat ? 1 : 0);
    np = (size_t)deg + 1;
    q = cf__alloc_array(np * 3, sizeof *q);
    if (q == NULL)
        return cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                         "out of memory projecting a curve");
    for (i = 0; i < np; i++) {
        /* the projection is linear, so it maps (w x, w) to (w Px, w) */
        project1(fig, hp + i * hd, dim, q + i * (rat ? 3 : 2));
        if (rat)
            q[i * 3 + 2] = hp[i * hd + dim];
    }
    if (rat)
        st = cf_bezier_create_homogeneous(2, deg, q, out, &fig->err);
    else
        st = cf_bezier_create(2, deg, q, NULL, out, &fig->err);
    cf__free(q);
    return st;
}

static cf_status_t
add_piece(cf_figure_t *fig, element_t *e, cf_bezier_t *bez,
          const double *cubic)
{
    if (e->npieces % 16 == 0) {
        piece_t *np = cf__realloc_array(e->pieces, e->npieces + 16,
                                        sizeof *np);
        if (np == NULL) {
            cf_bezier_destroy(bez);
            return cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                             "out of memory for curve pieces");
        }
        e->pieces = np;
    }
    memset(&e->pieces[e->npieces], 0, sizeof e->pieces[0]);
    e->pieces[e->npieces].bez = bez;
    if (cubic != NULL)
        memcpy(e->pieces[e->npieces].cubic, cubic, 8 * sizeof(double));
    e->npieces++;
    return CF_STATUS_OK;
}

static cf_status_t
check_curve(cf_figure_t *fig, const void *c, const cf_style_t *style,
            const char *what)
{
    if (c == NULL)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "%s is NULL", what);
    return check_style(fig, style);
}

cf_status_t
cf_figure_add_bezier_range(cf_figure_t *fig, const cf_bezier_t *c, double a,
                           double b, const cf_style_t *style)
{
    element_t *e;
    cf_bezier_t *plane = NULL, *seg = NULL;
    cf_status_t st;
    FIG_CHECK(fig);
    if (check_curve(fig, c, style, "Bézier curve") != CF_STATUS_OK)
        return fig->err.status;
    if (!(isfinite(a) && isfinite(b)))
        return cf__error(&fig->err, CF_STATUS_NOT_FINITE, -1,
                         "curve range [%g, %g] is not finite", a, b);
    if (!(0 <= a && a < b && b <= 1))
        return cf__error(&fig->err, CF_STATUS_DOMAIN, -1,
                         "curve range [%g, %g] must satisfy 0 <= a < b <= 1",
                         a, b);
    st = planar_bezier(fig, c, &plane);
    if (st != CF_STATUS_OK)
        return fig_fail(fig, st, "Bézier curve");
    if (a > 0 || b < 1) {
        st = cf_bezier_segment(plane, a, b, &seg, &fig->err);
        cf_bezier_destroy(plane);
        if (st != CF_STATUS_OK)
            return fig_fail(fig, st, "Bézier curve range");
        plane = seg;
    }
    e = new_element(fig, EL_CURVE, CF_ROLE_CURVE, style);
    if (e == NULL) {
        cf_bezier_destroy(plane);
        return fig->err.status;
    }
    return commit(fig, e, add_piece(fig, e, plane, NULL));
}

cf_status_t
cf_figure_add_bezier(cf_figure_t *fig, const cf_bezier_t *c,
                     const cf_style_t *style)
{
    return cf_figure_add_bezier_range(fig, c, 0.0, 1.0, style);
}

cf_status_t
cf_figure_add_bezier_list(cf_figure_t *fig, const cf_bezier_list_t *list,
                          const cf_style_t *style)
{
    element_t *e;
    size_t i;
    cf_status_t st = CF_STATUS_OK;
    FIG_CHECK(fig);
    if (check_curve(fig, list, style, "Bézier list") != CF_STATUS_OK)
        return fig->err.status;
    if (list->count > 0 && list->items == NULL)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "Bézier list of %zu items has no items",
                         list->count);
    for (i = 0; i < list->count; i++)
        if (list->items[i] == NULL)
            return cf__error(&fig->err, CF_STATUS_INVALID_ARG, (long)i,
                             "Bézier list item %zu is NULL", i);
    e = new_element(fig, EL_CURVE, CF_ROLE_CURVE, style);
    if (e == NULL)
        return fig->err.status;
    for (i = 0; i < list->count && st == CF_STATUS_OK; i++) {
        cf_bezier_t *plane = NULL;
        st = planar_bezier(fig, list->items[i], &plane);
        if (st == CF_STATUS_OK)
            st = add_piece(fig, e, plane, NULL);
    }
    return commit(fig, e, st);
}

cf_status_t
cf_figure_add_cubics(cf_figure_t *fig, const cf_cubics_t *cubics,
                     const cf_style_t *style)
{
    element_t *e;
    size_t i, j, dim;
    cf_status_t st = CF_STATUS_OK;
    FIG_CHECK(fig);
    if (check_curve(fig, cubics, style, "cubic chain") != CF_STATUS_OK)
        return fig->err.status;
    dim = cubics->dim;
    if (dim < 2 || (cubics->count > 0 && cubics->pts == NULL))
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "cubic chain: dimension %zu (need >= 2) or no "
                         "points", dim);
    if (cf__check_finite_points(cubics->pts, 4 * cubics->count, dim, dim,
                                "cubic control point", &fig->err)
        != CF_STATUS_OK)
        return fig->err.status;
    e = new_element(fig, EL_CURVE, CF_ROLE_CURVE, style);
    if (e == NULL)
        return fig->err.status;
    for (i = 0; i < cubics->count && st == CF_STATUS_OK; i++) {
        double q[8];
        for (j = 0; j < 4; j++)
            project1(fig, cubics->pts + (4 * i + j) * dim, dim, q + 2 * j);
        st = add_piece(fig, e, NULL, q);
    }
    return commit(fig, e, st);
}

static cf_status_t
bspline_pieces(cf_figure_t *fig, element_t *e, const cf_bspline_t *s,
               double a, double b)
{
    cf_bezier_list_t *list = NULL;
    cf_status_t st;
    size_t i;
    double lo, hi;

    cf_bspline_domain(s, &lo, &hi);
    if (a == b) {
        a = lo;
        b = hi;
    }
    if (!(isfinite(a) && isfinite(b)))
        return cf__error(&fig->err, CF_STATUS_NOT_FINITE, -1,
                         "B-spline range [%g, %g] is not finite", a, b);
    if (!(lo <= a && a < b && b <= hi))
        return cf__error(&fig->err, CF_STATUS_DOMAIN, -1,
                         "B-spline range [%g, %g] must lie inside the "
                         "domain [%g, %g]", a, b, lo, hi);
    st = cf_bspline_to_beziers(s, &list, &fig->err);
    if (st != CF_STATUS_OK)
        return st;
    for (i = 0; i < list->count && st == CF_STATUS_OK; i++) {
        double t0 = list->t0[i], t1 = list->t1[i], ta, tb;
        cf_bezier_t *plane = NULL, *seg = NULL;
        if (t1 <= a || t0 >= b || !(t1 > t0))
            continue;
        ta = (fmax(a, t0) - t0) / (t1 - t0);
        tb = (fmin(b, t1) - t0) / (t1 - t0);
        st = planar_bezier(fig, list->items[i], &plane);
        if (st != CF_STATUS_OK)
            break;
        if (ta > 0 || tb < 1) {
            st = cf_bezier_segment(plane, fmax(ta, 0), fmin(tb, 1), &seg,
                                   &fig->err);
            cf_bezier_destroy(plane);
            plane = seg;
            if (st != CF_STATUS_OK)
                break;
        }
        st = add_piece(fig, e, plane, NULL);
    }
    cf_bezier_list_destroy(list);
    return st;
}

cf_status_t
cf_figure_add_bspline(cf_figure_t *fig, const struct cf_bspline *s,
                      double a, double b, const cf_style_t *style)
{
    element_t *e;
    FIG_CHECK(fig);
    if (check_curve(fig, s, style, "B-spline curve") != CF_STATUS_OK)
        return fig->err.status;
    if (cf_bspline_dim(s) < 2)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "a B-spline in R^%zu cannot be drawn as a plane "
                         "curve (use a graph for functions)",
                         cf_bspline_dim(s));
    e = new_element(fig, EL_CURVE, CF_ROLE_CURVE, style);
    if (e == NULL)
        return fig->err.status;
    return commit(fig, e, bspline_pieces(fig, e, s, a, b));
}

cf_status_t
cf_figure_add_bspline_knots(cf_figure_t *fig, const struct cf_bspline *s,
                            const cf_style_t *style)
{
    const double *u;
    size_t m, i, n = 0, dim;
    double lo, hi, *buf = NULL, *pts = NULL;
    cf_status_t st = CF_STATUS_OK;
    FIG_CHECK(fig);
    if (check_curve(fig, s, style, "B-spline curve") != CF_STATUS_OK)
        return fig->err.status;
    dim = cf_bspline_dim(s);
    if (dim < 2)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "knot marks need a curve in R^2 or more, not "
                         "R^%zu", dim);
    u = cf_bspline_knots(s);
    m = cf_bspline_nknots(s);
    cf_bspline_domain(s, &lo, &hi);
    buf = cf__alloc_array(2 * dim, sizeof *buf);
    pts = cf__alloc_array(4 * (m ? m : 1), sizeof *pts);
    if (buf == NULL || pts == NULL) {
        cf__free(buf);
        cf__free(pts);
        return cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for knot marks");
    }
    /* layout of pts: n points, then (after compaction) n tangents */
    for (i = 0; i < m && st == CF_STATUS_OK; i++) {
        if (u[i] < lo || u[i] > hi || (i > 0 && u[i] == u[i - 1]))
            continue;
        st = cf_bspline_eval_derivs(s, u[i], 1, buf);
        if (st != CF_STATUS_OK) {
            fig_fail(fig, st, "knot marks");
            break;
        }
        project1(fig, buf, dim, pts + 2 * n);
        project1(fig, buf + dim, dim, pts + 2 * m + 2 * n);
        n++;
    }
    if (st == CF_STATUS_OK) {
        memmove(pts + 2 * n, pts + 2 * m, 2 * n * sizeof *pts);
        st = cf_figure_add_knot_marks(fig, pts, pts + 2 * n, n, style);
    }
    cf__free(buf);
    cf__free(pts);
    return st;
}

/* ---- graphs ------------------------------------------------------------- */

/* The graph of a dim-1 polynomial Bézier over [x0, x1] as a planar Bézier
** whose x control values are equally spaced (x is then linear in t). */
static cf_status_t
graph_bezier(cf_figure_t *fig, const cf_bezier_t *c, double x0, double x1,
             cf_bezier_t **out)
{
    int deg = cf_bezier_degree(c), i;
    const double *y = cf_bezier_hpoints(c);
    double *q;
    cf_status_t st;
    if (cf_bezier_dim(c) != 1 || cf_bezier_is_rational(c))
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "a graph piece must be a polynomial Bézier in R^1 "
                         "(this one is in R^%zu%s)", cf_bezier_dim(c),
                         cf_bezier_is_rational(c) ? ", rational" : "");
    q = cf__alloc_array(2 * ((size_t)deg + 1), sizeof *q);
    if (q == NULL)
        return cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for a graph");
    for (i = 0; i <= deg; i++) {
        q[2 * i] = deg > 0 ? x0 + (x1 - x0) * i / deg : x0;
        q[2 * i + 1] = y[i];
    }
    if (deg == 0) {
        /* a constant: a degree-1 segment over the whole interval */
        q[2] = x1;
        q[3] = y[0];
        st = cf_bezier_create(2, 1, q, NULL, out, &fig->err);
    } else {
        st = cf_bezier_create(2, deg, q, NULL, out, &fig->err);
    }
    cf__free(q);
    return st;
}

cf_status_t
cf_figure_add_graph(cf_figure_t *fig, const cf_bezier_t *const *pieces,
                    const double *breaks, size_t count,
                    const cf_style_t *style)
{
    element_t *e;
    size_t i;
    cf_status_t st = CF_STATUS_OK;
    FIG_CHECK(fig);
    if (pieces == NULL || breaks == NULL || count == 0)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "graph: pieces or breaks NULL, or no piece");
    if (check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    if (cf__check_finite_points(breaks, count + 1, 1, 1, "graph break",
                                &fig->err) != CF_STATUS_OK)
        return fig->err.status;
    for (i = 0; i < count; i++) {
        if (breaks[i + 1] < breaks[i])
            return cf__error(&fig->err, CF_STATUS_INVALID_ARG, (long)i + 1,
                             "graph break %zu (%g) is smaller than break "
                             "%zu (%g)", i + 1, breaks[i + 1], i,
                             breaks[i]);
        if (pieces[i] == NULL)
            return cf__error(&fig->err, CF_STATUS_INVALID_ARG, (long)i,
                             "graph piece %zu is NULL", i);
    }
    e = new_element(fig, EL_CURVE, CF_ROLE_GRAPH, style);
    if (e == NULL)
        return fig->err.status;
    for (i = 0; i < count && st == CF_STATUS_OK; i++) {
        cf_bezier_t *g = NULL;
        if (!(breaks[i + 1] > breaks[i]))
            continue;
        st = graph_bezier(fig, pieces[i], breaks[i], breaks[i + 1], &g);
        if (st == CF_STATUS_OK)
            st = add_piece(fig, e, g, NULL);
    }
    return commit(fig, e, st);
}

cf_status_t
cf_figure_add_graph_list(cf_figure_t *fig, const cf_bezier_list_t *list,
                         const cf_style_t *style)
{
    double *breaks;
    size_t i;
    cf_status_t st;
    element_t *e;
    FIG_CHECK(fig);
    if (list == NULL || list->count == 0 || list->items == NULL
        || list->t0 == NULL || list->t1 == NULL)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "graph list: NULL, empty, or without t0/t1 ranges");
    if (check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    breaks = cf__alloc_array(2 * list->count, sizeof *breaks);
    if (breaks == NULL)
        return cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for a graph");
    for (i = 0; i < list->count; i++) {
        breaks[2 * i] = list->t0[i];
        breaks[2 * i + 1] = list->t1[i];
    }
    st = cf__check_finite_points(breaks, 2 * list->count, 1, 1,
                                 "graph range", &fig->err);
    for (i = 0; i < list->count && st == CF_STATUS_OK; i++) {
        if (list->items[i] == NULL || breaks[2 * i + 1] < breaks[2 * i])
            st = cf__error(&fig->err, CF_STATUS_INVALID_ARG, (long)i,
                           "graph list item %zu is NULL or has t1 < t0", i);
    }
    if (st != CF_STATUS_OK) {
        cf__free(breaks);
        return st;
    }
    e = new_element(fig, EL_CURVE, CF_ROLE_GRAPH, style);
    if (e == NULL) {
        cf__free(breaks);
        return fig->err.status;
    }
    for (i = 0; i < list->count && st == CF_STATUS_OK; i++) {
        cf_bezier_t *g = NULL;
        if (!(breaks[2 * i + 1] > breaks[2 * i]))
            continue;
        st = graph_bezier(fig, list->items[i], breaks[2 * i],
                          breaks[2 * i + 1], &g);
        if (st == CF_STATUS_OK)
            st = add_piece(fig, e, g, NULL);
    }
    cf__free(breaks);
    return commit(fig, e, st);
}

/* The graph of N_i^p over the whole knot vector [u_0, u_{m-1}].  The
** spline with the single coefficient e_{i+p} on U padded by p knots at
** each end (spacing the length of U, or 1) equals N_i^p on the padded
** domain, which contains [u_0, u_{m-1}]: N_i^p depends only on
** u_i .. u_{i+p+1}, so the padding does not change it.  Its Bézier pieces
** over [u_0, u_{m-1}] are the graph, exact. */
cf_status_t
cf_figure_add_basis(cf_figure_t *fig, const double *knots, size_t nknots,
                    int i, int p, const cf_style_t *style)
{
    cf_bspline_t *spl = NULL;
    cf_bezier_list_t *list = NULL;
    double *pu, *coef, h;
    size_t m = nknots, count, k;
    cf_status_t st;
    FIG_CHECK(fig);
    if (knots == NULL)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "basis: knots are NULL");
    if (p < 0 || p > CF_BSPLINE_MAX_DEGREE)
        return cf__error(&fig->err, CF_STATUS_BAD_DEGREE, -1,
                         "basis: degree %d is outside 0 .. %d", p,
                         CF_BSPLINE_MAX_DEGREE);
    if (i < 0 || (size_t)i + (size_t)p + 2 > m)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, i,
                         "basis: N_%d^%d needs knots u_%d .. u_%d; %zu "
                         "given", i, p, i, i + p + 1, m);
    if (cf__check_finite_points(knots, m, 1, 1, "knot", &fig->err)
        != CF_STATUS_OK || check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    for (k = 1; k < m; k++)
        if (knots[k] < knots[k - 1])
            return cf__error(&fig->err, CF_STATUS_BAD_KNOTS, (long)k,
                             "basis: knot %zu (%g) is smaller than knot %zu "
                             "(%g)", k, knots[k], k - 1, knots[k - 1]);
    if (!(knots[m - 1] > knots[0]))
        return cf__error(&fig->err, CF_STATUS_BAD_KNOTS, -1,
                         "basis: the knots span no interval (all %g)",
                         knots[0]);
    h = knots[m - 1] - knots[0];
    count = m + (size_t)p - 1;
    pu = cf__alloc_array(m + 2 * (size_t)p, sizeof *pu);
    coef = cf__calloc(count, sizeof *coef);
    if (pu == NULL || coef == NULL) {
        cf__free(pu);
        cf__free(coef);
        return cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for a basis function");
    }
    for (int r = 0; r < p; r++) {
        pu[r] = knots[0] - h * (p - r);
        pu[m + (size_t)p + (size_t)r] = knots[m - 1] + h * (r + 1);
    }
    memcpy(pu + p, knots, m * sizeof *knots);
    coef[(size_t)i + (size_t)p] = 1.0;
    /* the padded spline's domain [pu_p, pu_{count}] is [u_0, u_{m-1}] */
    st = cf_bspline_create(1, p, pu, m + 2 * (size_t)p, coef, count, NULL,
                           &spl, &fig->err);
    cf__free(pu);
    cf__free(coef);
    if (st == CF_STATUS_OK)
        st = cf_bspline_to_beziers(spl, &list, &fig->err);
    cf_bspline_destroy(spl);
    if (st == CF_STATUS_OK)
        st = cf_figure_add_graph_list(fig, list, style);
    cf_bezier_list_destroy(list);
    return st;
}

/* Sampling state of cf_figure_add_function. */
typedef struct sampler {
    cf_function_t f;
    void *closure;
    double a, b, h;
    int stopped;
    bool bad;
} sampler_t;

static bool
sample(sampler_t *s, double x, double *y)
{
    if (s->stopped || s->bad)
        return false;
    if (s->f(s->closure, x, y) != 0) {
        s->stopped = 1;
        return false;
    }
    if (!isfinite(*y)) {
        s->bad = true;
        return false;
    }
    return true;
}

/* Value and derivative (central difference, one-sided at the ends). */
static bool
sample_d(sampler_t *s, double x, double *y, double *d)
{
    double xl = fmax(s->a, x - s->h), xr = fmin(s->b, x + s->h), yl, yr;
    if (!sample(s, x, y) || !sample(s, xl, &yl) || !sample(s, xr, &yr))
        return false;
    *d = (yr - yl) / (xr - xl);
    return true;
}

#define FN_MAX_SEGMENTS 4096

cf_status_t
cf_figure_add_function(cf_figure_t *fig, cf_function_t f, void *closure,
                       double a, double b, const cf_style_t *style)
{
    enum { START = 16, STACK = 64 };
    element_t *e;
    sampler_t s;
    double ylo = INFINITY, yhi = -INFINITY, tol, y;
    double stack[STACK][4];   /* x, y, d of the right end; and level */
    double x0, y0, d0;
    size_t i, nseg = 0;
    cf_status_t st = CF_STATUS_OK;

    FIG_CHECK(fig);
    if (f == NULL)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "function is NULL");
    if (check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    if (!(isfinite(a) && isfinite(b)))
        return cf__error(&fig->err, CF_STATUS_NOT_FINITE, -1,
                         "function range [%g, %g] is not finite", a, b);
    if (!(a < b))
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "function range [%g, %g] is empty", a, b);
    s.f = f;
    s.closure = closure;
    s.a = a;
    s.b = b;
    s.h = 1e-6 * (b - a);
    s.stopped = 0;
    s.bad = false;
    /* the graph's range sets the tolerance */
    for (i = 0; i <= 64; i++) {
        if (!sample(&s, a + (b - a) * (double)i / 64, &y))
            break;
        ylo = fmin(ylo, y);
        yhi = fmax(yhi, y);
    }
    tol = 2e-5 * fmax(yhi - ylo, 1e-3 * (b - a));
    e = new_element(fig, EL_CURVE, CF_ROLE_GRAPH, style);
    if (e == NULL)
        return fig->err.status;
    if (s.stopped || s.bad || !sample_d(&s, a, &y0, &d0))
        goto done;
    x0 = a;
    {
        int top = 0;
        /* right ends still to reach, nearest last */
        for (i = START; i >= 1; i--) {
            stack[top][0] = a + (b - a) * (double)i / START;
            stack[top][3] = 0;
            stack[top][1] = NAN;
            top++;
        }
        while (top > 0 && st == CF_STATUS_OK) {
            double x1 = stack[top - 1][0], y1, d1, hx, worst = 0;
            double c[8];
            int lvl = (int)stack[top - 1][3], k;
            if (isnan(stack[top - 1][1])) {
                if (!sample_d(&s, x1, &y1, &d1))
                    goto done;
                stack[top - 1][1] = y1;
                stack[top - 1][2] = d1;
            }
            y1 = stack[top - 1][1];
            d1 = stack[top - 1][2];
            hx = x1 - x0;
            c[0] = x0;
            c[1] = y0;
            c[2] = x0 + hx / 3;
            c[3] = y0 + d0 * hx / 3;
            c[4] = x1 - hx / 3;
            c[5] = y1 - d1 * hx / 3;
            c[6] = x1;
            c[7] = y1;
            for (k = 1; k <= 3; k++) {
                double t = k / 4.0, u = 1 - t, yc, yf;
                yc = u * u * u * c[1] + 3 * u * u * t * c[3]
                    + 3 * u * t * t * c[5] + t * t * t * c[7];
                if (!sample(&s, x0 + t * hx, &yf))
                    goto done;
                worst = fmax(worst, fabs(yc - yf));
            }
            if (worst > tol && lvl < 24 && top < STACK
                && nseg + (size_t)top < FN_MAX_SEGMENTS) {
                stack[top][0] = x0 + hx / 2;
                stack[top][1] = NAN;
                stack[top][3] = lvl + 1;
                stack[top - 1][3] = lvl + 1;
                top++;
                continue;
            }
            st = add_piece(fig, e, NULL, c);
            nseg++;
            x0 = x1;
            y0 = y1;
            d0 = d1;
            top--;
        }
    }
done:
    if (st == CF_STATUS_OK && s.stopped)
        st = cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                       "the plotted function reported an error");
    if (st == CF_STATUS_OK && s.bad)
        st = cf__error(&fig->err, CF_STATUS_NOT_FINITE, -1,
                       "the plotted function is not finite on [%g, %g]", a,
                       b);
    return commit(fig, e, st);
}

/* ---- point elements ----------------------------------------------------- */

static cf_status_t
add_points_el(cf_figure_t *fig, el_kind_t kind, cf_role_t role,
              const double *pts, size_t n, size_t min, bool closed,
              const cf_style_t *style, const char *what)
{
    element_t *e;
    FIG_CHECK(fig);
    if (check_points(fig, pts, n, min, what) != CF_STATUS_OK
        || check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    e = new_element(fig, kind, role, style);
    if (e == NULL)
        return fig->err.status;
    e->pts = copy_doubles(pts, 2 * n);
    e->n = n;
    e->closed = closed;
    if (e->pts == NULL)
        return commit(fig, e, cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                                        "out of memory for %s", what));
    return commit(fig, e, CF_STATUS_OK);
}

cf_status_t
cf_figure_add_polygon(cf_figure_t *fig, const double *pts, size_t n,
                      const cf_style_t *style)
{
    return add_points_el(fig, EL_POLYGON, CF_ROLE_POLYGON, pts, n, 1, false,
                         style, "control polygon");
}

cf_status_t
cf_figure_add_polyline(cf_figure_t *fig, const double *pts, size_t n,
                       bool closed, const cf_style_t *style)
{
    return add_points_el(fig, EL_POLYLINE, CF_ROLE_POLYLINE, pts, n, 2,
                         closed, style, "polyline");
}

cf_status_t
cf_figure_add_hull(cf_figure_t *fig, const double *pts, size_t n,
                   const cf_style_t *style)
{
    return add_points_el(fig, EL_HULL, CF_ROLE_HULL, pts, n, 1, true, style,
                         "convex hull");
}

cf_status_t
cf_figure_add_fill(cf_figure_t *fig, const double *pts, size_t n,
                   const cf_style_t *style)
{
    return add_points_el(fig, EL_FILL, CF_ROLE_FILL, pts, n, 3, true, style,
                         "filled polygon");
}

cf_status_t
cf_figure_add_points(cf_figure_t *fig, const double *pts, size_t n,
                     const cf_style_t *style)
{
    return add_points_el(fig, EL_POINTS, CF_ROLE_POINTS, pts, n, 1, false,
                         style, "points");
}

cf_status_t
cf_figure_add_knot_marks(cf_figure_t *fig, const double *pts,
                         const double *tangents, size_t n,
                         const cf_style_t *style)
{
    element_t *e;
    FIG_CHECK(fig);
    if (check_points(fig, pts, n, 1, "knot mark") != CF_STATUS_OK
        || check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    if (tangents != NULL
        && cf__check_finite_points(tangents, n, 2, 2, "knot tangent",
                                   &fig->err) != CF_STATUS_OK)
        return fig->err.status;
    e = new_element(fig, EL_KNOTS, CF_ROLE_KNOTS, style);
    if (e == NULL)
        return fig->err.status;
    e->pts = cf__alloc_array(4 * n, sizeof *e->pts);
    if (e->pts == NULL)
        return commit(fig, e, cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                                        "out of memory for knot marks"));
    memcpy(e->pts, pts, 2 * n * sizeof *pts);
    if (tangents != NULL)
        memcpy(e->pts + 2 * n, tangents, 2 * n * sizeof *pts);
    e->has_dirs = tangents != NULL;
    e->n = n;
    return commit(fig, e, CF_STATUS_OK);
}

cf_status_t
cf_figure_add_arrow(cf_figure_t *fig, double x, double y, double dx,
                    double dy, const cf_style_t *style)
{
    element_t *e;
    FIG_CHECK(fig);
    if (!(isfinite(x) && isfinite(y) && isfinite(dx) && isfinite(dy)))
        return cf__error(&fig->err, CF_STATUS_NOT_FINITE, -1,
                         "arrow (%g, %g) + (%g, %g) is not finite", x, y, dx,
                         dy);
    if (check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    e = new_element(fig, EL_ARROW, CF_ROLE_ARROW, style);
    if (e == NULL)
        return fig->err.status;
    e->x = x;
    e->y = y;
    e->dx = dx;
    e->dy = dy;
    return commit(fig, e, CF_STATUS_OK);
}

cf_status_t
cf_figure_add_label(cf_figure_t *fig, double x, double y, const char *text,
                    const cf_style_t *style)
{
    element_t *e;
    FIG_CHECK(fig);
    if (text == NULL)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "label text is NULL");
    if (!(isfinite(x) && isfinite(y)))
        return cf__error(&fig->err, CF_STATUS_NOT_FINITE, -1,
                         "label \"%s\" at (%g, %g) is not finite", text, x,
                         y);
    if (check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    e = new_element(fig, EL_LABEL, CF_ROLE_LABEL, style);
    if (e == NULL)
        return fig->err.status;
    e->x = x;
    e->y = y;
    return commit(fig, e,
                  text_set(fig, &e->text, text,
                           role_font_size(fig, CF_ROLE_LABEL, style)));
}

cf_status_t
cf_figure_add_net(cf_figure_t *fig, const double *pts, const size_t *counts,
                  size_t levels, const cf_color_t *colors,
                  const cf_style_t *style)
{
    element_t *e;
    size_t total = 0, j;
    FIG_CHECK(fig);
    if (counts == NULL || levels == 0)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "net: counts NULL or no level");
    for (j = 0; j < levels; j++) {
        if (counts[j] == 0 || counts[j] > ((size_t)1 << 24))
            return cf__error(&fig->err, CF_STATUS_INVALID_ARG, (long)j,
                             "net level %zu has %zu points", j, counts[j]);
        total += counts[j];
    }
    if (check_points(fig, pts, total, 1, "net point") != CF_STATUS_OK
        || check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    if (colors != NULL) {
        for (j = 0; j < levels; j++) {
            cf_style_t t;
            cf_style_init(&t);
            t.set = CF_STYLE_COLOR;
            t.color = colors[j];
            if (cf__style_check(&t, &fig->err) != CF_STATUS_OK)
                return fig->err.status;
        }
    }
    e = new_element(fig, EL_NET, CF_ROLE_NET, style);
    if (e == NULL)
        return fig->err.status;
    e->pts = copy_doubles(pts, 2 * total);
    e->n = total;
    e->levels = levels;
    e->counts = cf__alloc_array(levels, sizeof *e->counts);
    if (colors != NULL) {
        e->colors = cf__alloc_array(levels, sizeof *e->colors);
        if (e->colors != NULL)
            memcpy(e->colors, colors, levels * sizeof *colors);
    }
    if (e->pts == NULL || e->counts == NULL
        || (colors != NULL && e->colors == NULL))
        return commit(fig, e, cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                                        "out of memory for a net"));
    memcpy(e->counts, counts, levels * sizeof *counts);
    return commit(fig, e, CF_STATUS_OK);
}

/* ---- axes --------------------------------------------------------------- */

void
cf_axes_init(cf_axes_t *axes)
{
    if (axes == NULL)
        return;
    memset(axes, 0, sizeof *axes);
    axes->xmax = 1;
    axes->ymax = 1;
    axes->arrows = true;
}

/* A "nice" step (1, 2, 5 x 10^k) giving about five intervals. */
static double
nice_step(double range)
{
    double raw = range / 5, mag = pow(10, floor(log10(raw))), m = raw / mag;
    if (m <= 1)
        return mag;
    if (m <= 2)
        return 2 * mag;
    if (m <= 5)
        return 5 * mag;
    return 10 * mag;
}

static void
format_number(double v, double step, char *buf, size_t cap)
{
    int dec = 0;
    double e = step;
    while (dec < 8 && fabs(e - round(e)) > 1e-9 * fmax(1, fabs(e))) {
        e *= 10;
        dec++;
    }
    if (fabs(v) < 1e-12 * fmax(1, step))
        v = 0;
    /* drop trailing zeros: 0, 0.25, 0.5, 0.75, 1 */
    while (dec > 0) {
        double k = pow(10, dec - 1);
        if (fabs(round(v * k) / k - v) > 1e-9 * fmax(1, fabs(v)))
            break;
        dec--;
    }
    snprintf(buf, cap, "%.*f", dec, v);
}

/* An explicit tick value: the fewest decimals (up to 3) that give it back
** to 1e-9, else 3 ("0.333"). */
static void
format_value(double v, char *buf, size_t cap)
{
    int dec;
    for (dec = 0; dec < 3; dec++) {
        double k = pow(10, dec);
        if (fabs(round(v * k) / k - v) <= 1e-9 * fmax(1, fabs(v)))
            break;
    }
    if (fabs(v) < 1e-12)
        v = 0;
    snprintf(buf, cap, "%.*f", dec, v);
}

/* Fill ticks from explicit positions or a step over [lo, hi]. */
static cf_status_t
make_ticks(cf_figure_t *fig, const double *pos, size_t count,
           const char *const *labels, double step, double lo, double hi,
           double font, tick_t **out, size_t *nout, const char *axis)
{
    size_t i, n;
    tick_t *t;
    cf_status_t st = CF_STATUS_OK;
    double first;

    *out = NULL;
    *nout = 0;
    if (count > 0) {
        if (pos == NULL)
            return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                             "%s ticks: positions are NULL", axis);
        if (cf__check_finite_points(pos, count, 1, 1, "tick", &fig->err)
            != CF_STATUS_OK)
            return fig->err.status;
        n = count;
    } else {
        if (step < 0)
            return CF_STATUS_OK;
        if (!isfinite(step))
            return cf__error(&fig->err, CF_STATUS_NOT_FINITE, -1,
                             "%s tick step is not finite", axis);
        if (step == 0)
            step = nice_step(hi - lo);
        if ((hi - lo) / step > 200)
            return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                             "%s tick step %g gives more than 200 ticks",
                             axis, step);
        first = ceil(lo / step - 1e-9) * step;
        n = (size_t)floor((hi - first) / step + 1e-9) + 1;
    }
    t = cf__calloc(n ? n : 1, sizeof *t);
    if (t == NULL)
        return cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for ticks");
    for (i = 0; i < n && st == CF_STATUS_OK; i++) {
        char buf[64];
        const char *text = buf;
        if (count > 0) {
            t[i].v = pos[i];
            if (labels != NULL && labels[i] != NULL)
                text = labels[i];
            else
                format_value(pos[i], buf, sizeof buf);
        } else {
            t[i].v = first + (double)i * step;
            if (fabs(t[i].v) < 1e-9 * step)
                t[i].v = 0;
            format_number(t[i].v, step, buf, sizeof buf);
        }
        st = text_set(fig, &t[i].t, text, font);
    }
    *out = t;
    *nout = n;
    return st;
}

cf_status_t
cf_figure_add_axes(cf_figure_t *fig, const cf_axes_t *axes,
                   const cf_style_t *style)
{
    element_t *e;
    axes_el_t *ax;
    const cf_axes_t *a = axes;
    double font, lfont;
    cf_status_t st;
    size_t i;

    FIG_CHECK(fig);
    if (a == NULL)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "axes are NULL");
    if (!(isfinite(a->xmin) && isfinite(a->xmax) && isfinite(a->ymin)
          && isfinite(a->ymax)))
        return cf__error(&fig->err, CF_STATUS_NOT_FINITE, -1,
                         "axes ranges are not finite");
    if (!(a->xmin < a->xmax && a->ymin < a->ymax))
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "axes ranges [%g, %g] x [%g, %g] are empty",
                         a->xmin, a->xmax, a->ymin, a->ymax);
    if (a->knot_count > 0 && a->knots == NULL)
        return cf__error(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "axes: %zu knots but the array is NULL",
                         a->knot_count);
    if (a->knot_count > 0
        && cf__check_finite_points(a->knots, a->knot_count, 1, 1, "knot",
                                   &fig->err) != CF_STATUS_OK)
        return fig->err.status;
    if (check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    e = new_element(fig, EL_AXES, CF_ROLE_AXES, style);
    if (e == NULL)
        return fig->err.status;
    ax = cf__calloc(1, sizeof *ax);
    e->axes = ax;
    if (ax == NULL)
        return commit(fig, e, cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                                        "out of memory for axes"));
    ax->a = *a;
    ax->a.xticks = ax->a.yticks = ax->a.knots = NULL;
    ax->a.xtick_labels = ax->a.ytick_labels = ax->a.knot_labels = NULL;
    ax->a.xlabel = ax->a.ylabel = NULL;
    font = role_font_size(fig, CF_ROLE_AXES, style);
    lfont = role_font_size(fig, CF_ROLE_LABEL, NULL);
    if (a->xtick_count == 0 && a->xtick_step == 0 && a->knot_count > 0) {
        /* knots given: they are the x ticks (distinct values) */
        double *dv = cf__alloc_array(a->knot_count, sizeof *dv);
        size_t nd = 0, j;
        if (dv == NULL)
            return commit(fig, e, cf__error(&fig->err, CF_STATUS_NO_MEMORY,
                                            -1, "out of memory for axes"));
        for (i = 0; i < a->knot_count; i++) {
            for (j = 0; j < nd && dv[j] != a->knots[i]; j++)
                ;
            if (j == nd)
                dv[nd++] = a->knots[i];
        }
        st = make_ticks(fig, dv, nd, NULL, 0, a->xmin, a->xmax, font,
                        &ax->xt, &ax->nxt, "x");
        cf__free(dv);
    } else {
        st = make_ticks(fig, a->xticks, a->xtick_count, a->xtick_labels,
                        a->xtick_step, a->xmin, a->xmax, font, &ax->xt,
                        &ax->nxt, "x");
    }
    if (st == CF_STATUS_OK)
        st = make_ticks(fig, a->yticks, a->ytick_count, a->ytick_labels,
                        a->ytick_step, a->ymin, a->ymax, font, &ax->yt,
                        &ax->nyt, "y");
    if (st == CF_STATUS_OK && a->knot_count > 0) {
        ax->kn = cf__calloc(a->knot_count, sizeof *ax->kn);
        if (ax->kn == NULL)
            st = cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for knots");
        else
            ax->nkn = a->knot_count;
        for (i = 0; i < ax->nkn && st == CF_STATUS_OK; i++) {
            ax->kn[i].v = a->knots[i];
            if (a->knot_labels != NULL && a->knot_labels[i] != NULL)
                st = text_set(fig, &ax->kn[i].t, a->knot_labels[i], font);
        }
    }
    if (st == CF_STATUS_OK && a->xlabel != NULL)
        st = text_set(fig, &ax->xlabel, a->xlabel, lfont);
    if (st == CF_STATUS_OK && a->ylabel != NULL)
        st = text_set(fig, &ax->ylabel, a->ylabel, lfont);
    return commit(fig, e, st);
}

/* ---- bounds and layout -------------------------------------------------- */

typedef struct bounds {
    double x0, x1, y0, y1;
    bool any;
} bounds_t;

static void
bounds_add(bounds_t *b, double x, double y)
{
    if (!b->any) {
        b->x0 = b->x1 = x;
        b->y0 = b->y1 = y;
        b->any = true;
        return;
    }
    b->x0 = fmin(b->x0, x);
    b->x1 = fmax(b->x1, x);
    b->y0 = fmin(b->y0, y);
    b->y1 = fmax(b->y1, y);
}

static void
element_bounds(const element_t *e, bounds_t *b)
{
    size_t i;
    switch (e->kind) {
    case EL_CURVE:
        for (i = 0; i < e->npieces; i++) {
            const piece_t *pc = &e->pieces[i];
            if (pc->bez != NULL) {
                /* the tight box of the curve, not of its control points */
                double lo[2], hi[2];
                if (cf_bezier_bbox(pc->bez, lo, hi) == CF_STATUS_OK) {
                    bounds_add(b, lo[0], lo[1]);
                    bounds_add(b, hi[0], hi[1]);
                }
            } else {
                size_t k;
                for (k = 0; k < 4; k++)
                    bounds_add(b, pc->cubic[2 * k], pc->cubic[2 * k + 1]);
            }
        }
        break;
    case EL_POLYGON:
    case EL_POLYLINE:
    case EL_POINTS:
    case EL_HULL:
    case EL_FILL:
    case EL_KNOTS:
    case EL_NET:
        for (i = 0; i < e->n; i++)
            bounds_add(b, e->pts[2 * i], e->pts[2 * i + 1]);
        break;
    case EL_LABEL:
        bounds_add(b, e->x, e->y);
        break;
    case EL_ARROW:
        bounds_add(b, e->x, e->y);
        bounds_add(b, e->x + e->dx, e->y + e->dy);
        break;
    case EL_AXES:
        bounds_add(b, e->axes->a.xmin, e->axes->a.ymin);
        bounds_add(b, e->axes->a.xmax, e->axes->a.ymax);
        break;
    }
}

static void
compute_map(const cf_figure_t *fig, const double win[4], bool keep,
            const double avail[4], cf__layout_t *lay)
{
    double aw = avail[2] - avail[0], ah = avail[3] - avail[1];
    double dx = win[1] - win[0], dy = win[3] - win[2];
    lay->xmin = win[0];
    lay->xmax = win[1];
    lay->ymin = win[2];
    lay->ymax = win[3];
    lay->sx = aw / dx;
    lay->sy = ah / dy;
    if (keep) {
        double s = fmin(lay->sx, lay->sy);
        lay->sx = lay->sy = s;
    }
    /* centre in the available box */
    lay->ox = avail[0] + 0.5 * (aw - lay->sx * dx);
    lay->oy = avail[3] - 0.5 * (ah - lay->sy * dy);
    lay->tol = fig->tol / fmax(lay->sx, lay->sy);
}

static void
ink_of(cf_figure_t *fig, const cf__layout_t *lay, double ink[4],
       cf_diag_t *diag)
{
    cairo_surface_t *rec;
    cairo_t *cr;
    double x, y, w, h;
    rec = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, NULL);
    cr = cairo_create(rec);
    cf__figure_draw(fig, lay, cr, diag);
    cairo_destroy(cr);
    cairo_recording_surface_ink_extents(rec, &x, &y, &w, &h);
    cairo_surface_destroy(rec);
    ink[0] = x;
    ink[1] = y;
    ink[2] = x + w;
    ink[3] = y + h;
}

cf_status_t
cf__figure_layout(cf_figure_t *fig, cf__layout_t *lay, cf_diag_t *diag)
{
    double win[4], avail[4], ink[4], m = fig->margin;
    bounds_t b;
    bool keep;
    size_t i;

    memset(&b, 0, sizeof b);
    for (i = 0; i < fig->count; i++)
        element_bounds(&fig->els[i], &b);
    lay->clip = fig->window_set;
    if (fig->window_set) {
        memcpy(win, fig->win, sizeof win);
    } else if (!b.any) {
        win[0] = 0;
        win[1] = 1;
        win[2] = 0;
        win[3] = 1;
    } else {
        double span = fmax(b.x1 - b.x0, b.y1 - b.y0);
        if (!(span > 0))
            span = fmax(1.0, fabs(b.x0) + fabs(b.y0));
        win[0] = b.x0;
        win[1] = b.x1;
        win[2] = b.y0;
        win[3] = b.y1;
        /* a flat box (a horizontal segment) gets some height */
        if (!(win[1] - win[0] > 1e-9 * span)) {
            win[0] -= 0.5 * span;
            win[1] += 0.5 * span;
        }
        if (!(win[3] - win[2] > 1e-9 * span)) {
            win[2] -= 0.5 * span;
            win[3] += 0.5 * span;
        }
    }
    /* the extent must itself be a finite number: coordinates near
    ** DBL_MAX (or a window of such width) overflow it (finding F4) */
    if (!isfinite(win[1] - win[0]) || !isfinite(win[3] - win[2]))
        return cf__error(diag != NULL ? diag : &fig->err,
                         CF_STATUS_NOT_FINITE, -1,
                         "the %s spans %g x %g, too large to draw "
                         "(coordinates up to about 1e307)",
                         fig->window_set ? "window" : "drawing",
                         win[1] - win[0], win[3] - win[2]);
    keep = fig->aspect == 1;
    if (fig->aspect < 0) {
        keep = true;
        for (i = 0; i < fig->count; i++)
            if (fig->els[i].kind == EL_AXES)
                keep = false;
    }
    avail[0] = m;
    avail[1] = m;
    avail[2] = fig->width - m;
    avail[3] = fig->height - m;
    compute_map(fig, win, keep, avail, lay);
    if (fig->count == 0)
        return CF_STATUS_OK;
    /* second pass: leave room for what sticks out of the data box
    ** (labels, markers, arrow heads, line widths) */
    ink_of(fig, lay, ink, diag);
    if (fig->err.status != CF_STATUS_OK)
        return fig->err.status;
    {
        double dl = lay->ox, dr = lay->ox + lay->sx * (win[1] - win[0]);
        double db = lay->oy, dt = lay->oy - lay->sy * (win[3] - win[2]);
        double ol = fmax(0, dl - ink[0]), or_ = fmax(0, ink[2] - dr);
        double ot = fmax(0, dt - ink[1]), ob = fmax(0, ink[3] - db);
        double maxw = 0.4 * (fig->width - 2 * m);
        double maxh = 0.4 * (fig->height - 2 * m);
        if (ol + or_ > maxw) {
            double k = maxw / (ol + or_);
            ol *= k;
            or_ *= k;
        }
        if (ot + ob > maxh) {
            double k = maxh / (ot + ob);
            ot *= k;
            ob *= k;
        }
        avail[0] = m + ol;
        avail[2] = fig->width - m - or_;
        avail[1] = m + ot;
        avail[3] = fig->height - m - ob;
    }
    compute_map(fig, win, keep, avail, lay);
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_get_window(cf_figure_t *fig, double window[4], double *sx,
                     double *sy)
{
    cf__layout_t lay;
    FIG_CHECK(fig);
    if (cf__figure_layout(fig, &lay, NULL) != CF_STATUS_OK)
        return fig->err.status;
    if (window != NULL) {
        window[0] = lay.xmin;
        window[1] = lay.xmax;
        window[2] = lay.ymin;
        window[3] = lay.ymax;
    }
    if (sx != NULL)
        *sx = lay.sx;
    if (sy != NULL)
        *sy = lay.sy;
    return CF_STATUS_OK;
}

const cf_color_t *
cf__figure_background(const cf_figure_t *fig)
{
    return &fig->theme.background;
}

const char *
cf__figure_title(const cf_figure_t *fig)
{
    return fig->title;
}

const char *
cf__figure_caption(const cf_figure_t *fig)
{
    return fig->caption;
}

/* ---- drawing ------------------------------------------------------------ */

static void
map_pt(const cf__layout_t *l, double x, double y, double *px, double *py)
{
    *px = l->ox + l->sx * (x - l->xmin);
    *py = l->oy - l->sy * (y - l->ymin);
}

/* Whether a point is drawn: always, unless the window was set explicitly
** and the point lies outside it (beyond rounding: 1e-9 of its size). */
static bool
in_window(const cf__layout_t *l, double x, double y)
{
    double ex = 1e-9 * (l->xmax - l->xmin), ey = 1e-9 * (l->ymax - l->ymin);
    return !l->clip
        || (x >= l->xmin - ex && x <= l->xmax + ex && y >= l->ymin - ey
            && y <= l->ymax + ey);
}

/* With an explicit window, clip what follows to it, widened by pad bp on
** every side (a line lying on the window's edge stays whole). */
static void
clip_to_window(cairo_t *cr, const cf__layout_t *l, double pad)
{
    double x0, y0, x1, y1;
    if (!l->clip)
        return;
    map_pt(l, l->xmin, l->ymax, &x0, &y0);
    map_pt(l, l->xmax, l->ymin, &x1, &y1);
    cairo_new_path(cr);
    cairo_rectangle(cr, x0 - pad, y0 - pad, x1 - x0 + 2 * pad,
                    y1 - y0 + 2 * pad);
    cairo_clip(cr);
}

/* Append a cubic (data coordinates) to the path, starting a subpath when
** it does not continue the previous one; last[2] is the previous end on
** the page (unrounded: cairo's current point is rounded to 1/256), NAN
** at the start. */
static void
path_cubic(cairo_t *cr, const cf__layout_t *l, const double *c,
           double *last)
{
    double p[8];
    size_t k;
    for (k = 0; k < 4; k++)
        map_pt(l, c[2 * k], c[2 * k + 1], &p[2 * k], &p[2 * k + 1]);
    if (isnan(last[0]) || fabs(last[0] - p[0]) > 1e-6
        || fabs(last[1] - p[1]) > 1e-6)
        cairo_move_to(cr, p[0], p[1]);
    cairo_curve_to(cr, p[2], p[3], p[4], p[5], p[6], p[7]);
    last[0] = p[6];
    last[1] = p[7];
}

static cf_status_t
draw_curve(cf_figure_t *fig, element_t *e, const cf__layout_t *l,
           cairo_t *cr, const cf_style_t *s)
{
    size_t i, k;
    double sx = 0, sy = 0, last[2] = { NAN, NAN };
    bool first = true;
    cairo_new_path(cr);
    for (i = 0; i < e->npieces; i++) {
        piece_t *pc = &e->pieces[i];
        if (pc->bez == NULL) {
            path_cubic(cr, l, pc->cubic, last);
        } else {
            /* a fit within a smaller tolerance serves a larger one: the
            ** layout's ink pass fits at the first, larger scale, and the
            ** page (smaller once labels took their room) reuses it */
            if (pc->cache == NULL || pc->cache_tol > l->tol) {
                cf_cubics_t *c = NULL;
                /* polynomial curves of degree >= 4: Hermite pieces
                ** within the a-priori bound, no fitting (rational ones:
                ** the Levien fit) */
                cf_status_t st = cf_bezier_to_cubics_bounded(pc->bez, l->tol,
                                                             &c, &fig->err);
                if (st != CF_STATUS_OK)
                    return fig_fail(fig, st, "curve to cubics");
                cf_cubics_destroy(pc->cache);
                pc->cache = c;
                pc->cache_tol = l->tol;
            }
            for (k = 0; k < pc->cache->count; k++)
                path_cubic(cr, l, pc->cache->pts + 8 * k, last);
        }
        if (first && cairo_has_current_point(cr)) {
            /* start of the path, for closing */
            const double *c0 = pc->bez == NULL ? pc->cubic
                                               : pc->cache->pts;
            map_pt(l, c0[0], c0[1], &sx, &sy);
            first = false;
        }
    }
    if (!first && fabs(last[0] - sx) < 1e-6 && fabs(last[1] - sy) < 1e-6)
        cairo_close_path(cr);
    cf__set_line(cr, s);
    cf__set_color(cr, &s->color, s->opacity);
    cairo_stroke(cr);
    return CF_STATUS_OK;
}

static void
draw_lines(cairo_t *cr, const cf__layout_t *l, const double *pts, size_t n,
           bool closed)
{
    size_t i;
    cairo_new_path(cr);
    for (i = 0; i < n; i++) {
        double px, py;
        map_pt(l, pts[2 * i], pts[2 * i + 1], &px, &py);
        if (i == 0)
            cairo_move_to(cr, px, py);
        else
            cairo_line_to(cr, px, py);
    }
    if (closed)
        cairo_close_path(cr);
}

static void
draw_markers(cairo_t *cr, const cf__layout_t *l, const cf_style_t *s,
             const double *pts, size_t n, const double *dirs)
{
    size_t i;
    for (i = 0; i < n; i++) {
        double px, py, d[2];
        if (!in_window(l, pts[2 * i], pts[2 * i + 1]))
            continue;
        map_pt(l, pts[2 * i], pts[2 * i + 1], &px, &py);
        if (dirs != NULL) {
            /* a data direction on the page (y flips) */
            d[0] = l->sx * dirs[2 * i];
            d[1] = -l->sy * dirs[2 * i + 1];
        }
        cf__draw_marker(cr, s, s->marker, px, py, dirs != NULL ? d : NULL);
    }
}

static void
stroke_lines(cairo_t *cr, const cf_style_t *s)
{
    if (s->color.a > 0 && s->width > 0) {
        cf__set_line(cr, s);
        cf__set_color(cr, &s->color, s->opacity);
        cairo_stroke(cr);
    } else {
        cairo_new_path(cr);
    }
}

/* Andrew's monotone chain; returns the hull size, vertices in out (2D),
** counter-clockwise.  idx is scratch of n entries. */
static int
cmp_xy(const double *a, const double *b)
{
    if (a[0] != b[0])
        return a[0] < b[0] ? -1 : 1;
    if (a[1] != b[1])
        return a[1] < b[1] ? -1 : 1;
    return 0;
}

static double
cross3(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

static size_t
convex_hull(const double *pts, size_t n, double *sorted, double *out)
{
    size_t i, j, k = 0, lower;
    memcpy(sorted, pts, 2 * n * sizeof *pts);
    /* insertion sort: hulls have few points */
    for (i = 1; i < n; i++) {
        double x = sorted[2 * i], y = sorted[2 * i + 1], t[2];
        t[0] = x;
        t[1] = y;
        for (j = i; j > 0 && cmp_xy(sorted + 2 * (j - 1), t) > 0; j--) {
            sorted[2 * j] = sorted[2 * (j - 1)];
            sorted[2 * j + 1] = sorted[2 * (j - 1) + 1];
        }
        sorted[2 * j] = x;
        sorted[2 * j + 1] = y;
    }
    for (i = 0; i < n; i++) {
        while (k >= 2 && cross3(out + 2 * (k - 2), out + 2 * (k - 1),
                                sorted + 2 * i) <= 0)
            k--;
        out[2 * k] = sorted[2 * i];
        out[2 * k + 1] = sorted[2 * i + 1];
        k++;
    }
    lower = k + 1;
    for (i = n - 1; i-- > 0;) {
        while (k >= lower && cross3(out + 2 * (k - 2), out + 2 * (k - 1),
                                    sorted + 2 * i) <= 0)
            k--;
        out[2 * k] = sorted[2 * i];
        out[2 * k + 1] = sorted[2 * i + 1];
        k++;
    }
    return k > 1 ? k - 1 : k;
}

static cf_status_t
draw_hull(cf_figure_t *fig, const element_t *e, const cf__layout_t *l,
          cairo_t *cr, const cf_style_t *s)
{
    double *tmp = cf__alloc_array(4 * e->n + 4, sizeof *tmp);
    size_t h;
    if (tmp == NULL)
        return cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                         "out of memory drawing a hull");
    h = convex_hull(e->pts, e->n, tmp, tmp + 2 * e->n + 2);
    draw_lines(cr, l, tmp + 2 * e->n + 2, h, true);
    cf__set_color(cr, &s->fill, s->opacity);
    cairo_fill_preserve(cr);
    stroke_lines(cr, s);
    cf__free(tmp);
    return CF_STATUS_OK;
}

/* An arrow head with its tip at (tx, ty) pointing along (ux, uy) (unit),
** length len: a slightly concave ("stealth") triangle. */
static void
arrow_head(cairo_t *cr, double tx, double ty, double ux, double uy,
           double len)
{
    double nx = -uy, ny = ux, w = 0.38 * len;
    cairo_move_to(cr, tx, ty);
    cairo_line_to(cr, tx - len * ux + w * nx, ty - len * uy + w * ny);
    cairo_line_to(cr, tx - 0.72 * len * ux, ty - 0.72 * len * uy);
    cairo_line_to(cr, tx - len * ux - w * nx, ty - len * uy - w * ny);
    cairo_close_path(cr);
    cairo_fill(cr);
}

static void
draw_arrow_page(cairo_t *cr, const cf_style_t *s, double x0, double y0,
                double x1, double y1, double head)
{
    double dx = x1 - x0, dy = y1 - y0, len = hypot(dx, dy), ux, uy;
    if (!(len > 1e-9))
        return;
    ux = dx / len;
    uy = dy / len;
    head = fmin(head, len);
    cairo_new_path(cr);
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1 - 0.8 * head * ux, y1 - 0.8 * head * uy);
    cf__set_line(cr, s);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    cf__set_color(cr, &s->color, s->opacity);
    cairo_stroke(cr);
    if (head > 0)
        arrow_head(cr, x1, y1, ux, uy, head);
}

/* Origin of a label placed at `place` of page point (px, py), gap off. */
static void
label_origin(const cf_label_t *lab, cf_place_t place, double off, double px,
             double py, double *ox, double *oy)
{
    double ink[4], cx, cy, w2, h2, d = off * 0.7071;
    cf__label_ink(lab, ink);
    cx = 0.5 * (ink[0] + ink[2]);
    cy = 0.5 * (ink[1] + ink[3]);
    w2 = 0.5 * (ink[2] - ink[0]);
    h2 = 0.5 * (ink[3] - ink[1]);
    switch (place) {
    case CF_PLACE_N:
        *ox = px - cx;
        *oy = py - off - h2 - cy;
        break;
    case CF_PLACE_S:
        *ox = px - cx;
        *oy = py + off + h2 - cy;
        break;
    case CF_PLACE_E:
        *ox = px + off + w2 - cx;
        *oy = py - cy;
        break;
    case CF_PLACE_W:
        *ox = px - off - w2 - cx;
        *oy = py - cy;
        break;
    case CF_PLACE_NE:
        *ox = px + d + w2 - cx;
        *oy = py - d - h2 - cy;
        break;
    case CF_PLACE_NW:
        *ox = px - d - w2 - cx;
        *oy = py - d - h2 - cy;
        break;
    case CF_PLACE_SE:
        *ox = px + d + w2 - cx;
        *oy = py + d + h2 - cy;
        break;
    case CF_PLACE_SW:
        *ox = px - d - w2 - cx;
        *oy = py + d + h2 - cy;
        break;
    default:
        *ox = px - cx;
        *oy = py - cy;
        break;
    }
}

static cf_status_t
draw_text(cf_figure_t *fig, text_t *t, cairo_t *cr, const cf_style_t *s,
          double px, double py, cf_place_t place, double off)
{
    double ox, oy;
    if (t->src == NULL)
        return CF_STATUS_OK;
    if (text_ensure(fig, t, s->font_size) != CF_STATUS_OK)
        return fig->err.status;
    label_origin(t->lab, place, off, px, py, &ox, &oy);
    if (s->halo > 0) {
        /* the background colour, or white on a transparent page */
        cf_color_t bg = fig->theme.background;
        if (bg.a <= 0)
            bg.r = bg.g = bg.b = bg.a = 1;
        cf__label_draw_halo(t->lab, cr, ox, oy, &bg, s->halo);
    }
    cf__label_draw(t->lab, cr, ox, oy, &s->color, s->opacity);
    return CF_STATUS_OK;
}

static cf_status_t
draw_axes(cf_figure_t *fig, element_t *e, const cf__layout_t *l,
          cairo_t *cr, const cf_style_t *s)
{
    axes_el_t *ax = e->axes;
    const cf_axes_t *a = &ax->a;
    double tick = fig->theme.tick_size, ext, head;
    double yaxis_x, xaxis_y, px0, py0, px1, py1, ax_y, ay_x, lh = 0;
    size_t i, j;
    cf_status_t st = CF_STATUS_OK;

    head = a->arrows ? s->arrow_size : 0;
    ext = a->arrows ? head + 3 : 0;
    if (a->box) {
        yaxis_x = a->xmin;
        xaxis_y = a->ymin;
        ext = 0;
        head = 0;
    } else {
        yaxis_x = (a->xmin <= 0 && 0 <= a->xmax) ? 0 : a->xmin;
        xaxis_y = (a->ymin <= 0 && 0 <= a->ymax) ? 0 : a->ymin;
    }
    map_pt(l, a->xmin, a->ymin, &px0, &py0);
    map_pt(l, a->xmax, a->ymax, &px1, &py1);
    map_pt(l, yaxis_x, xaxis_y, &ay_x, &ax_y);

    if (a->grid) {
        cf_style_t g = *s;
        g.color = s->fill;
        g.width = 0.4;
        g.dash_count = 0;
        cairo_new_path(cr);
        for (i = 0; i < ax->nxt; i++) {
            double px, py;
            map_pt(l, ax->xt[i].v, 0, &px, &py);
            cairo_move_to(cr, px, py0);
            cairo_line_to(cr, px, py1);
        }
        for (i = 0; i < ax->nyt; i++) {
            double px, py;
            map_pt(l, 0, ax->yt[i].v, &px, &py);
            cairo_move_to(cr, px0, py);
            cairo_line_to(cr, px1, py);
        }
        stroke_lines(cr, &g);
    }
    /* axis lines (or the frame) and ticks */
    cairo_new_path(cr);
    if (a->box) {
        cairo_rectangle(cr, px0, py1, px1 - px0, py0 - py1);
    } else {
        cairo_move_to(cr, px0, ax_y);
        cairo_line_to(cr, px1 + ext - 0.8 * head, ax_y);
        cairo_move_to(cr, ay_x, py0);
        cairo_line_to(cr, ay_x, py1 - ext + 0.8 * head);
    }
    for (i = 0; i < ax->nxt; i++) {
        double px, py;
        map_pt(l, ax->xt[i].v, xaxis_y, &px, &py);
        cairo_move_to(cr, px, ax_y);
        cairo_line_to(cr, px, ax_y + tick);
    }
    for (i = 0; i < ax->nyt; i++) {
        double px, py;
        map_pt(l, yaxis_x, ax->yt[i].v, &px, &py);
        cairo_move_to(cr, ay_x, py);
        cairo_line_to(cr, ay_x - tick, py);
    }
    {
        cf_style_t ls = *s;
        ls.dash_count = 0;
        cf__set_line(cr, &ls);
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
        cf__set_color(cr, &s->color, s->opacity);
        cairo_stroke(cr);
    }
    if (head > 0) {
        cf__set_color(cr, &s->color, s->opacity);
        arrow_head(cr, px1 + ext, ax_y, 1, 0, head);
        arrow_head(cr, ay_x, py1 - ext, 0, -1, head);
    }
    /* tick labels */
    for (i = 0; i < ax->nxt && st == CF_STATUS_OK; i++) {
        double px, py;
        map_pt(l, ax->xt[i].v, xaxis_y, &px, &py);
        st = draw_text(fig, &ax->xt[i].t, cr, s, px, ax_y + tick,
                       CF_PLACE_S, s->offset);
        if (ax->xt[i].t.lab != NULL) {
            double ink[4];
            cf__label_ink(ax->xt[i].t.lab, ink);
            lh = fmax(lh, ink[3] - ink[1]);
        }
    }
    for (i = 0; i < ax->nyt && st == CF_STATUS_OK; i++) {
        double px, py;
        bool at_x_axis = fabs(ax->yt[i].v - xaxis_y)
            <= 1e-9 * (a->ymax - a->ymin);
        /* the origin is labelled once, on the x axis */
        if (at_x_axis && !a->box && ax->nxt > 0 && yaxis_x >= a->xmin) {
            bool has = false;
            for (j = 0; j < ax->nxt; j++)
                if (fabs(ax->xt[j].v - yaxis_x)
                    <= 1e-9 * (a->xmax - a->xmin))
                    has = true;
            if (has)
                continue;
        }
        map_pt(l, yaxis_x, ax->yt[i].v, &px, &py);
        st = draw_text(fig, &ax->yt[i].t, cr, s, ay_x - tick, py,
                       CF_PLACE_W, s->offset);
    }
    /* knots: a marker on the axis; labels stacked below the tick labels */
    if (ax->nkn > 0 && st == CF_STATUS_OK) {
        double row = 1.25 * s->font_size;
        for (i = 0; i < ax->nkn && st == CF_STATUS_OK; i++) {
            double px, py;
            size_t rep = 0;
            for (j = 0; j < i; j++)
                if (ax->kn[j].v == ax->kn[i].v)
                    rep++;
            map_pt(l, ax->kn[i].v, xaxis_y, &px, &py);
            if (rep == 0)
                cf__draw_marker(cr, s, s->marker, px, ax_y, NULL);
            if (ax->kn[i].t.src != NULL) {
                double y = ax_y + tick + s->offset + lh + 2.5
                    + (double)rep * row;
                st = draw_text(fig, &ax->kn[i].t, cr, s, px, y, CF_PLACE_S,
                               0.0);
            }
        }
    }
    if (st == CF_STATUS_OK && ax->xlabel.src != NULL) {
        cf_style_t ls;
        cf__style_resolve(&fig->theme, CF_ROLE_LABEL, NULL, &ls);
        st = draw_text(fig, &ax->xlabel, cr, &ls, px1 + ext, ax_y,
                       a->box ? CF_PLACE_SE : CF_PLACE_E, 3.0);
    }
    if (st == CF_STATUS_OK && ax->ylabel.src != NULL) {
        cf_style_t ls;
        cf__style_resolve(&fig->theme, CF_ROLE_LABEL, NULL, &ls);
        st = draw_text(fig, &ax->ylabel, cr, &ls, ay_x, py1 - ext,
                       CF_PLACE_N, 3.0);
    }
    return st;
}

static cf_status_t
draw_element(cf_figure_t *fig, element_t *e, const cf__layout_t *l,
             cairo_t *cr)
{
    cf_style_t s;
    size_t i, j, off;
    double pad;
    cf__style_resolve(&fig->theme, e->role, &e->style, &s);
    /* lines and areas are clipped to an explicit window (widened by the
    ** line width), markers and labels of points outside it left out;
    ** arrows and axes are drawn whole */
    pad = s.width > 0 ? s.width : 0;
    switch (e->kind) {
    case EL_CURVE:
        clip_to_window(cr, l, pad);
        return draw_curve(fig, e, l, cr, &s);
    case EL_POLYGON:
    case EL_POLYLINE:
        if (e->n >= 2) {
            cairo_save(cr);
            clip_to_window(cr, l, pad);
            draw_lines(cr, l, e->pts, e->n, e->closed);
            stroke_lines(cr, &s);
            cairo_restore(cr);
        }
        draw_markers(cr, l, &s, e->pts, e->n, NULL);
        return CF_STATUS_OK;
    case EL_POINTS:
        draw_markers(cr, l, &s, e->pts, e->n, NULL);
        return CF_STATUS_OK;
    case EL_KNOTS:
        draw_markers(cr, l, &s, e->pts, e->n,
                     e->has_dirs ? e->pts + 2 * e->n : NULL);
        return CF_STATUS_OK;
    case EL_HULL:
        clip_to_window(cr, l, pad);
        return draw_hull(fig, e, l, cr, &s);
    case EL_FILL:
        clip_to_window(cr, l, pad);
        draw_lines(cr, l, e->pts, e->n, true);
        cf__set_color(cr, &s.fill, s.opacity);
        cairo_fill_preserve(cr);
        stroke_lines(cr, &s);
        return CF_STATUS_OK;
    case EL_ARROW: {
        double x0, y0, x1, y1;
        map_pt(l, e->x, e->y, &x0, &y0);
        map_pt(l, e->x + e->dx, e->y + e->dy, &x1, &y1);
        draw_arrow_page(cr, &s, x0, y0, x1, y1, s.arrow_size);
        return CF_STATUS_OK;
    }
    case EL_LABEL: {
        double px, py;
        if (!in_window(l, e->x, e->y))
            return CF_STATUS_OK;
        map_pt(l, e->x, e->y, &px, &py);
        return draw_text(fig, &e->text, cr, &s, px, py,
                         s.place == CF_PLACE_AUTO ? e->auto_place : s.place,
                         s.offset);
    }
    case EL_NET:
        /* lines of every level first, then the markers on top */
        cairo_save(cr);
        clip_to_window(cr, l, pad);
        for (j = 0, off = 0; j < e->levels; off += e->counts[j], j++) {
            cf_style_t ls = s;
            if (e->colors != NULL)
                ls.color = e->colors[j];
            else if (!(e->style.set & CF_STYLE_COLOR))
                ls.color = j == 0
                    ? fig->theme.role[CF_ROLE_POLYGON].color
                    : fig->theme.palette[(j - 1) % fig->theme.palette_size];
            if (e->counts[j] >= 2) {
                draw_lines(cr, l, e->pts + 2 * off, e->counts[j], false);
                stroke_lines(cr, &ls);
            }
        }
        cairo_restore(cr);
        for (j = 0, off = 0; j < e->levels; off += e->counts[j], j++) {
            cf_style_t ls = s;
            if (e->colors != NULL)
                ls.marker_color = e->colors[j];
            else if (!(e->style.set & (CF_STYLE_COLOR
                                       | CF_STYLE_MARKER_COLOR)))
                ls.marker_color = j == 0
                    ? fig->theme.role[CF_ROLE_POLYGON].marker_color
                    : fig->theme.palette[(j - 1) % fig->theme.palette_size];
            for (i = 0; i < e->counts[j]; i++) {
                double px, py;
                if (!in_window(l, e->pts[2 * (off + i)],
                               e->pts[2 * (off + i) + 1]))
                    continue;
                map_pt(l, e->pts[2 * (off + i)], e->pts[2 * (off + i) + 1],
                       &px, &py);
                cf__draw_marker(cr, &ls, ls.marker, px, py, NULL);
            }
        }
        return CF_STATUS_OK;
    case EL_AXES:
        return draw_axes(fig, e, l, cr, &s);
    }
    return CF_STATUS_OK;
}

/* ---- automatic label places -------------------------------------------- */

#define AUTO_RES 2.0          /* raster pixels per bp */
#define AUTO_MAX_PIXELS 4e6   /* larger pages get a coarser raster */
#define AUTO_GAP 1.0          /* bp around a label that should stay clear */
#define AUTO_NEAR 3.0         /* bp: ink this close costs a quarter */

/* Ink in the page box x0 y0 x1 y1 (bp) of an A8 raster at res pixels per
** bp, in bp^2 of full ink; pixels off the page count as full ink. */
static double
raster_ink(cairo_surface_t *img, double res, const double b[4])
{
    const unsigned char *px = cairo_image_surface_get_data(img);
    int w = cairo_image_surface_get_width(img);
    int h = cairo_image_surface_get_height(img);
    int stride = cairo_image_surface_get_stride(img);
    double i0 = floor(b[0] * res), i1 = ceil(b[2] * res);
    double j0 = floor(b[1] * res), j1 = ceil(b[3] * res);
    double sum = 0, inside = 0;
    int i, j, ci0 = (int)fmax(i0, 0), ci1 = (int)fmin(i1, w);
    int cj0 = (int)fmax(j0, 0), cj1 = (int)fmin(j1, h);
    for (j = cj0; j < cj1; j++)
        for (i = ci0; i < ci1; i++)
            sum += px[(size_t)j * (size_t)stride + (size_t)i];
    if (ci1 > ci0 && cj1 > cj0)
        inside = (double)(ci1 - ci0) * (cj1 - cj0);
    sum += 255.0 * ((i1 - i0) * (j1 - j0) - inside);
    return sum / (255.0 * res * res);
}

/* The cost of a label with ink box ink (relative to its origin) at
** origin (ox, oy): ink under the box widened by AUTO_GAP, plus a quarter
** of the ink in the ring out to AUTO_NEAR. */
static double
place_cost(cairo_surface_t *img, double res, const double ink[4], double ox,
           double oy)
{
    double hard[4], near[4], a, b;
    hard[0] = ox + ink[0] - AUTO_GAP;
    hard[1] = oy + ink[1] - AUTO_GAP;
    hard[2] = ox + ink[2] + AUTO_GAP;
    hard[3] = oy + ink[3] + AUTO_GAP;
    near[0] = ox + ink[0] - AUTO_NEAR;
    near[1] = oy + ink[1] - AUTO_NEAR;
    near[2] = ox + ink[2] + AUTO_NEAR;
    near[3] = oy + ink[3] + AUTO_NEAR;
    a = raster_ink(img, res, hard);
    b = raster_ink(img, res, near);
    return a + 0.25 * fmax(0, b - a);
}

/* Choose the places of the labels placed CF_PLACE_AUTO for this layout:
** everything else is rasterized at low resolution (fills and hulls left
** out: labels may sit on a shading), then each automatic label in turn
** takes the cheapest of the eight places and is added to the raster. */
static cf_status_t
place_auto_labels(cf_figure_t *fig, const cf__layout_t *lay)
{
    static const cf_place_t order[] = {
        CF_PLACE_NE, CF_PLACE_NW, CF_PLACE_SE, CF_PLACE_SW,
        CF_PLACE_N, CF_PLACE_S, CF_PLACE_E, CF_PLACE_W
    };
    cairo_surface_t *img;
    cairo_t *cr;
    cf_style_t s;
    double res = AUTO_RES;
    size_t i, k;
    bool any = false;
    cf_status_t st = CF_STATUS_OK;

    for (i = 0; i < fig->count && !any; i++) {
        element_t *e = &fig->els[i];
        if (e->kind != EL_LABEL)
            continue;
        cf__style_resolve(&fig->theme, e->role, &e->style, &s);
        any = s.place == CF_PLACE_AUTO;
    }
    if (!any)
        return CF_STATUS_OK;
    if (fig->width * fig->height * res * res > AUTO_MAX_PIXELS)
        res = sqrt(AUTO_MAX_PIXELS / (fig->width * fig->height));
    img = cairo_image_surface_create(CAIRO_FORMAT_A8,
                                     (int)ceil(fig->width * res),
                                     (int)ceil(fig->height * res));
    cr = cairo_create(img);
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
        cairo_destroy(cr);
        cairo_surface_destroy(img);
        return cf__error(&fig->err, CF_STATUS_NO_MEMORY, -1,
                         "out of memory placing labels");
    }
    cairo_scale(cr, res, res);
    for (i = 0; i < fig->count && st == CF_STATUS_OK; i++) {
        element_t *e = &fig->els[i];
        if (e->kind == EL_FILL || e->kind == EL_HULL)
            continue;
        if (e->kind == EL_LABEL) {
            cf__style_resolve(&fig->theme, e->role, &e->style, &s);
            if (s.place == CF_PLACE_AUTO)
                continue;
        }
        cairo_save(cr);
        st = draw_element(fig, e, lay, cr);
        cairo_restore(cr);
    }
    for (i = 0; i < fig->count && st == CF_STATUS_OK; i++) {
        element_t *e = &fig->els[i];
        double px, py, ink[4], best = INFINITY;
        if (e->kind != EL_LABEL)
            continue;
        cf__style_resolve(&fig->theme, e->role, &e->style, &s);
        if (s.place != CF_PLACE_AUTO || !in_window(lay, e->x, e->y))
            continue;
        st = text_ensure(fig, &e->text, s.font_size);
        if (st != CF_STATUS_OK)
            break;
        cf__label_ink(e->text.lab, ink);
        map_pt(lay, e->x, e->y, &px, &py);
        cairo_surface_flush(img);
        e->auto_place = order[0];
        for (k = 0; k < sizeof order / sizeof order[0]; k++) {
            double ox, oy, c;
            label_origin(e->text.lab, order[k], s.offset, px, py, &ox, &oy);
            c = place_cost(img, res, ink, ox, oy);
            /* a later place must be clearly better (0.05 bp^2) */
            if (c < best - 0.05) {
                best = c;
                e->auto_place = order[k];
            }
        }
        cairo_save(cr);
        st = draw_element(fig, e, lay, cr);
        cairo_restore(cr);
    }
    cairo_destroy(cr);
    cairo_surface_destroy(img);
    return st;
}

cf_status_t
cf__figure_draw(cf_figure_t *fig, const cf__layout_t *lay, cairo_t *cr,
                cf_diag_t *diag)
{
    size_t i;
    (void)diag;
    if (place_auto_labels(fig, lay) != CF_STATUS_OK)
        return fig->err.status;
    for (i = 0; i < fig->count; i++) {
        cairo_save(cr);
        if (draw_element(fig, &fig->els[i], lay, cr) != CF_STATUS_OK) {
            cairo_restore(cr);
            return fig->err.status;
        }
        cairo_restore(cr);
    }
    return CF_STATUS_OK;
}
