/*
** The figure object: its page, title, theme, window, fit and projection
** setters, and the list of elements in drawing order (each a record of
** its kind, render/el-*.c, render/figure/axes.c, render/figure/plots.c).
*/
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "grow.h"
#include "model.h"

/* ---- errors ------------------------------------------------------------- */

cf_status_t
cf__fig_fail(cf_figure_t *fig, cf_status_t st, const char *what)
{
    if (st != CF_STATUS_OK && fig->err.status == CF_STATUS_OK)
        cf_diag_set(&fig->err, st, -1, "%s: %s", what,
                    cf_status_to_string(st));
    return st;
}

cf_status_t
cf__fig_nomem(cf_figure_t *fig, const char *what)
{
    return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                       "out of memory for %s", what);
}

cf_status_t
cf__fig_check_points(cf_figure_t *fig, const double *pts, size_t n,
                     size_t min, const char *what)
{
    if (pts == NULL && n > 0)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "%s: points are NULL", what);
    if (n < min)
        return cf_diag_set(&fig->err, CF_STATUS_TOO_FEW_POINTS, (long)n,
                           "%s: %zu points given, at least %zu needed",
                           what, n, min);
    return cf_check_finite_points(pts, n, 2, 2, what, &fig->err);
}

cf_status_t
cf__fig_check_style(cf_figure_t *fig, const cf_style_t *style)
{
    return cf__style_check(style, &fig->err);
}

/* ---- figure ------------------------------------------------------------- */

cf_status_t
cf__figure_create(const struct cf__fonts *fonts, double width,
                  double height, cf_unit_t unit, cf_figure_t **out,
                  cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_figure_t *fig;
    double w, h;
    if (out == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "figure output pointer is NULL");
    *out = NULL;
    if ((unsigned)unit >= CF_UNIT_LAST_)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "unknown unit %d", (int)unit);
    w = cf_length_to_bp(width, unit);
    h = cf_length_to_bp(height, unit);
    if (!(isfinite(w) && isfinite(h) && w > 0 && h > 0))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "figure size %g x %g must be finite and positive",
                           width, height);
    if (w > 14400 || h > 14400)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "figure size %g x %g bp exceeds 14400 bp (200 in)",
                           w, h);
    fig = cf_calloc(1, sizeof *fig);
    if (fig == NULL)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for a figure");
    cf_diag_clear(&fig->err);
    fig->fonts = fonts;
    fig->width = w;
    fig->height = h;
    cf_theme_get("default", &fig->theme, NULL);
    fig->margin = 4.0;
    fig->aspect = -1;
    fig->tol = 0.01;
    *out = fig;
    return CF_STATUS_OK;
}


void
cf_figure_destroy(cf_figure_t *fig)
{
    size_t i;
    if (fig == NULL)
        return;
    for (i = 0; i < fig->count; i++) {
        fig->els[i]->kind->fini(fig->els[i]);
        cf_free(fig->els[i]->overlay);
        cf_free(fig->els[i]);
    }
    cf_free(fig->els);
    for (i = 0; i < fig->nlegend; i++)
        cf__text_fini(&fig->legend[i].text);
    cf_free(fig->legend);
    cf_free(fig->insets);
    cf_free(fig->inset_band);
    cf_free(fig->inset_cache);
    for (i = 0; fig->panels != NULL && i < (size_t)(fig->rows * fig->cols);
         i++)
        cf_figure_destroy(fig->panels[i]);
    cf_free(fig->panels);
    cf__text_fini(&fig->panel_title);
    cf_free(fig->overlay);
    cf_free(fig->title);
    cf_free(fig->caption);
    cf_free(fig->alt);
    cf_free(fig->description);
    cf_free(fig->lang);
    cf__facts_fini(&fig->facts);
    cf_free(fig->proj);
    cf_scene_destroy(fig->scene);
    cf_free(fig->warnings);
    cf_free(fig->place_px);
    cf_free(fig->place_ready);
    cf_free(fig->all_warnings);
    cf_free(fig);
}


size_t
cf_figure_element_count(const cf_figure_t *fig)
{
    return fig != NULL ? fig->count : 0;
}

void
cf_figure_set_element_line(cf_figure_t *fig, size_t i, int line)
{
    if (fig != NULL && i < fig->count)
        fig->els[i]->line = line > 0 ? line : 0;
}

void
cf_figure_set_line(cf_figure_t *fig, int line)
{
    if (fig != NULL)
        fig->line = line > 0 ? line : 0;
}

const char *
cf__line_note(int line, char buf[CF__LINE_NOTE_SIZE])
{
    buf[0] = '\0';
    if (line > 0)
        snprintf(buf, CF__LINE_NOTE_SIZE, " (line %d)", line);
    return buf;
}

void
cf__figure_warn(cf_figure_t *fig, const char *fmt, ...)
{
    char line[512];
    size_t n;
    char *t;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    n = strlen(line);
    /* once: a layout draws an element more than once */
    for (const char *w = fig->warnings; w != NULL && *w != '\0';) {
        const char *nl = strchr(w, '\n');
        size_t len = nl != NULL ? (size_t)(nl - w) : strlen(w);
        if (len == n && memcmp(w, line, n) == 0)
            return;
        w += len + (nl != NULL);
    }
    t = cf_realloc_array(fig->warnings, fig->warnings_len + n + 2, 1);
    if (t == NULL)
        return;
    memcpy(t + fig->warnings_len, line, n);
    t[fig->warnings_len + n] = '\n';
    t[fig->warnings_len + n + 1] = '\0';
    fig->warnings = t;
    fig->warnings_len += n + 1;
}

cf_status_t
cf_figure_status(const cf_figure_t *fig, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    if (fig == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1, "figure is NULL");
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
    CF__FIG_CHECK(fig);
    if (src != NULL) {
        size_t n = strlen(src);
        copy = cf_malloc(n + 1);
        if (copy == NULL)
            return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                               "out of memory for the %s", what);
        memcpy(copy, src, n + 1);
    }
    cf_free(*dst);
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
    CF__FIG_CHECK(fig);
    if (theme == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "theme is NULL");
    for (i = 0; i < CF_ROLE_LAST_; i++) {
        cf_style_t s = theme->role[i];
        s.set = CF_STYLE_ALL_;
        if (cf__style_check(&s, &fig->err) != CF_STATUS_OK)
            return fig->err.status;
    }
    if (theme->palette_size < 1 || theme->palette_size > CF_PALETTE_MAX)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "theme palette has %zu colours (1 to %d allowed)",
                           theme->palette_size, CF_PALETTE_MAX);
    if (memchr(theme->font_family, '\0', CF_FONT_FAMILY_MAX) == NULL
        || theme->font_family[0] == '\0')
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "theme font family is empty or not terminated");
    if (!(isfinite(theme->tick_size) && theme->tick_size >= 0))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
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
    CF__FIG_CHECK(fig);
    if (!(isfinite(xmin) && isfinite(xmax) && isfinite(ymin)
          && isfinite(ymax)))
        return cf_diag_set(&fig->err, CF_STATUS_NOT_FINITE, -1,
                           "window [%g, %g] x [%g, %g] is not finite", xmin,
                           xmax, ymin, ymax);
    if (!(xmin < xmax && ymin < ymax))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
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
    CF__FIG_CHECK(fig);
    fig->window_set = false;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_set_fit(cf_figure_t *fig, double margin_bp, bool keep_aspect)
{
    CF__FIG_CHECK(fig);
    if (!(isfinite(margin_bp) && margin_bp >= 0
          && 2 * margin_bp < fmin(fig->width, fig->height)))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "margin %g bp must be >= 0 and leave room on a "
                           "%g x %g bp page", margin_bp, fig->width,
                           fig->height);
    fig->margin = margin_bp;
    fig->aspect = keep_aspect ? 1 : 0;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_set_page_mode(cf_figure_t *fig, cf_page_mode_t mode)
{
    CF__FIG_CHECK(fig);
    if (mode != CF_PAGE_FIXED && mode != CF_PAGE_INK)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "unknown page mode %d (use CF_PAGE_FIXED or "
                           "CF_PAGE_INK)", (int)mode);
    fig->page_mode = mode;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_set_background(cf_figure_t *fig, cf_background_t mode)
{
    CF__FIG_CHECK(fig);
    if (mode != CF_BACKGROUND_AUTO && mode != CF_BACKGROUND_ALWAYS
        && mode != CF_BACKGROUND_NONE)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "unknown background mode %d (use "
                           "CF_BACKGROUND_AUTO, _ALWAYS or _NONE)", (int)mode);
    fig->background = mode;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_get_fit(const cf_figure_t *fig, double *margin_bp,
                  bool *keep_aspect)
{
    size_t i;
    bool keep;
    if (fig == NULL)
        return CF_STATUS_INVALID_ARG;
    keep = fig->aspect == 1;
    if (fig->aspect < 0) {
        keep = true;
        for (i = 0; i < fig->count; i++)
            if (fig->els[i]->kind->flags & CF__KIND_AXES)
                keep = false;
    }
    if (margin_bp != NULL)
        *margin_bp = fig->margin;
    if (keep_aspect != NULL)
        *keep_aspect = keep;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_set_clip(cf_figure_t *fig, bool clip)
{
    CF__FIG_CHECK(fig);
    fig->clip_page = clip;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_set_tolerance(cf_figure_t *fig, double tol_bp)
{
    CF__FIG_CHECK(fig);
    if (!(isfinite(tol_bp) && tol_bp > 0))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "tolerance %g must be finite and positive", tol_bp);
    fig->tol = tol_bp;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_set_draft(cf_figure_t *fig, bool draft)
{
    CF__FIG_CHECK(fig);
    fig->draft = draft;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_set_projection(cf_figure_t *fig, size_t dim, const double *m)
{
    double *copy;
    CF__FIG_CHECK(fig);
    if (dim < 2 || dim > CF_FIGURE_MAX_DIM || m == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "projection: dimension %zu must be 2..%d and the "
                           "matrix not NULL", dim, CF_FIGURE_MAX_DIM);
    if (cf_check_finite_points(m, 2, dim, dim, "projection row",
                               &fig->err) != CF_STATUS_OK)
        return fig->err.status;
    copy = cf_alloc_array(2 * dim, sizeof *copy);
    if (copy == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for a projection");
    memcpy(copy, m, 2 * dim * sizeof *copy);
    cf_free(fig->proj);
    fig->proj = copy;
    fig->proj_dim = dim;
    fig->has_view = false;
    return CF_STATUS_OK;
}

/* ---- projection through a view (render/figure/figure-view.c sets it) ------- */

bool
cf__fig_is_central(const cf_figure_t *fig, size_t dim)
{
    return fig->has_view && dim == 3
        && fig->view.projection == CF_PROJECTION_PERSPECTIVE;
}

bool
cf__fig_project_h(const cf_figure_t *fig, const double *hp, size_t dim,
                  bool rational, double out[3])
{
    double w = rational ? hp[dim] : 1.0;
    if (cf__fig_is_central(fig, dim)) {
        const double *m = fig->view_m;
        for (int r = 0; r < 3; r++)
            out[r] = m[4 * r] * hp[0] + m[4 * r + 1] * hp[1]
                + m[4 * r + 2] * hp[2] + m[4 * r + 3] * w;
        /* the eye itself or behind it (W = (D - z) / D w); a point
        ** within 1e-9 D of the eye's plane is not drawable either */
        return out[2] > 1e-9 * w;
    }
    cf__fig_project1(fig, hp, dim, out);
    out[2] = w;
    return true;
}

cf_status_t
cf__fig_behind_eye(cf_figure_t *fig, const double *p, const char *what)
{
    double s = 0;
    for (int k = 0; k < 3; k++)
        s += fig->view.dir[k] * (p[k] - fig->view.target[k]);
    return cf_diag_set(&fig->err, CF_STATUS_DOMAIN, -1,
                       "%s (%g, %g, %g) lies at or behind the eye of the "
                       "view (distance = %g); a distance above %g shows it",
                       what, p[0], p[1], p[2], fig->view.distance,
                       s > 0 ? 1.5 * s : fig->view.distance);
}

void
cf__fig_project1(const cf_figure_t *fig, const double *p, size_t dim,
                 double *out)
{
    size_t j;
    if (cf__fig_is_central(fig, dim)) {
        double h[3];
        if (!cf__fig_project_h(fig, p, dim, false, h)) {
            out[0] = out[1] = NAN;
            return;
        }
        out[0] = h[0] / h[2];
        out[1] = h[1] / h[2];
    } else if (fig->proj != NULL && fig->proj_dim == dim) {
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
    CF__FIG_CHECK(fig);
    if ((in == NULL || out == NULL) && n > 0)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "points or output are NULL");
    if (dim < 2)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "dimension %zu is below 2", dim);
    if (cf_check_finite_points(in, n, dim, dim, "point", &fig->err)
        != CF_STATUS_OK)
        return fig->err.status;
    for (i = 0; i < n; i++) {
        double tmp[2];
        cf__fig_project1(fig, in + i * dim, dim, tmp);
        if (isnan(tmp[0]))
            return cf__fig_behind_eye(fig, in + i * dim, "point");
        out[2 * i] = tmp[0];
        out[2 * i + 1] = tmp[1];
    }
    return CF_STATUS_OK;
}

/* ---- element list ------------------------------------------------------- */


/* ---- element list ------------------------------------------------------- */

void *
cf__element_new(cf_figure_t *fig, const cf__kind_t *k, size_t size,
                cf_role_t role, const cf_style_t *style)
{
    cf__element_t *e;
    cf__element_t **ne = cf__grow_array(fig->els, &fig->cap,
                                        fig->count + 1, sizeof *ne, 16);
    if (ne == NULL) {
        cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                    "out of memory for figure element %zu", fig->count);
        return NULL;
    }
    fig->els = ne;
    e = cf_calloc(1, size);
    if (e == NULL) {
        cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                    "out of memory for figure element %zu", fig->count);
        return NULL;
    }
    e->kind = k;
    e->role = role;
    if (style != NULL)
        e->style = *style;
    return e;
}

cf_status_t
cf__element_commit(cf_figure_t *fig, void *el, cf_status_t st)
{
    cf__element_t *e = el;
    if (st != CF_STATUS_OK) {
        e->kind->fini(e);
        cf_free(e);
        return cf__fig_fail(fig, st, "figure element");
    }
    if (fig->overlay != NULL) {
        size_t n = strlen(fig->overlay) + 1;
        e->overlay = cf_malloc(n);
        if (e->overlay == NULL) {
            e->kind->fini(e);
            cf_free(e);
            return cf__fig_nomem(fig, "an overlay specification");
        }
        memcpy(e->overlay, fig->overlay, n);
        if (fig->overlay_last > fig->steps)
            fig->steps = fig->overlay_last;
    }
    e->line = fig->line;
    fig->els[fig->count++] = e;
    return CF_STATUS_OK;
}

cf_status_t
cf__element_draw(cf_figure_t *fig, size_t i, const cf__layout_t *lay,
                 cf__dl_t *dl)
{
    cf__element_t *e = fig->els[i];
    cf_style_t s;
    cf_status_t st;
    size_t op0 = dl->count, coord0 = dl->ncoords, tri0 = dl->ntris;
    double bad;
    cf__style_resolve(&fig->theme, e->role, &e->style, &s);
    cf__dl_group(dl, e->kind->name, i);
    if (!dl->failed && dl->count > 0) {
        dl->ops[dl->count - 1].u.group.overlay = e->overlay;
        dl->ops[dl->count - 1].u.group.line = e->line;
    }
    st = e->kind->draw(fig, e, lay, &s, dl);
    cf__dl_end(dl);
    /* a point that maps beyond every number (data near 1e308 times the
    ** window's scale) could not be drawn, measured or placed around */
    if (st == CF_STATUS_OK && !dl->failed
        && !cf__dl_finite_from(dl, op0, coord0, tri0, &bad)) {
        char at[CF__LINE_NOTE_SIZE];
        st = cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, (long)i,
                         "%s %zu%s lies too far outside the drawing's %.1f "
                         "x %.1f mm page to be drawn (its place on the page "
                         "overflows to %g); move it nearer", e->kind->name,
                         i + 1, cf__line_note(e->line, at),
                         fig->width * 25.4 / 72, fig->height * 25.4 / 72,
                         bad);
    }
    return st;
}

double *
cf__copy_doubles(const double *src, size_t n)
{
    double *d = cf_alloc_array(n ? n : 1, sizeof *d);
    if (d != NULL && n > 0)
        memcpy(d, src, n * sizeof *d);
    return d;
}

double
cf__role_font_size(const cf_figure_t *fig, cf_role_t role,
                   const cf_style_t *s)
{
    cf_style_t r;
    cf__style_resolve(&fig->theme, role, s, &r);
    return r.font_size;
}
