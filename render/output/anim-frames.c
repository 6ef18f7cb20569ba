/*
** The frames of an animation (anim.h): steps 1 and 2 of the frame loop
** (anim.c), each frame measured with the label places of the frame before
** and one map and one page settled for all of them; and in step 3 each
** frame built again on that map and page, drawn on a cairo context or into
** a raster.
*/
#include <math.h>
#include <string.h>

#include "anim-write-private.h"
#include "measure.h"

/* Frame fig laid out (common: with that map instead of its own) and built
** into dl, its automatic labels offered hint[0..nhint-1] (force: taking
** them). */
static cf_status_t
build(cf_figure_t *fig, const cf__layout_t *common,
      const cf__auto_place_t *hint, size_t nhint, bool force,
      cf__layout_t *lay, cf__dl_t *dl, cf_diag_t *diag)
{
    cf_status_t st = CF_STATUS_OK;
    fig->place_hint = hint;
    fig->nplace_hint = nhint;
    fig->place_hint_force = force;
    cf__dl_reset(dl);
    if (cf__figure_layout(fig, lay) != CF_STATUS_OK)
        st = cf_figure_status(fig, diag);
    if (st == CF_STATUS_OK && common != NULL)
        *lay = *common;
    if (st == CF_STATUS_OK && cf__figure_build(fig, lay, dl) != CF_STATUS_OK)
        st = cf_figure_status(fig, diag);
    fig->place_hint = NULL;
    fig->nplace_hint = 0;
    fig->place_hint_force = false;
    return st;
}

static char *
copy_text(const char *s)
{
    char *c;
    if (s == NULL)
        return NULL;
    c = cf_malloc(strlen(s) + 1);
    if (c != NULL)
        strcpy(c, s);
    return c;
}

/* The first frame's figure: what every frame shares (page size, theme,
** title) is read from it. */
static void
read_page(anim_t *a, cf_figure_t *fig)
{
    const cf__anim_options_t *o = a->o;
    a->tight = o->tight || fig->page_mode == CF_PAGE_INK;
    memset(&a->page, 0, sizeof a->page);
    cf_figure_get_size(fig, &a->page.width, &a->page.height);
    a->page.background = fig->theme.background;
    a->page.label_size = fig->theme.role[CF_ROLE_LABEL].font_size;
    a->raster_page = a->page;
    a->raster_page.raster = true;
    if (fig->background != CF_BACKGROUND_ALWAYS)
        a->page.background.a = 0;
    if (fig->background == CF_BACKGROUND_NONE)
        a->raster_page.background.a = 0;
    if (a->title == NULL)
        a->title = copy_text(fig->title);
    if (a->caption == NULL)
        a->caption = copy_text(fig->caption);
}

/* Step 1 with map common (NULL: each frame's own). */
static cf_status_t
measure(anim_t *a, const cf__layout_t *common, cf_diag_t *diag)
{
    const cf__anim_source_t *src = a->src;
    cf__dl_t dl;
    cf_status_t st = CF_STATUS_OK;
    unsigned k;
    cf__dl_init(&dl);
    for (k = 0; k < src->frames && st == CF_STATUS_OK; k++) {
        frame_info_t *fi = &a->info[k], *prev = k > 0 ? &a->info[k - 1] : NULL;
        cf_figure_t *fig = NULL;
        size_t n;
        cf_free(fi->places);
        fi->places = NULL;
        st = src->make(src->ctx, k, &fig, &fi->step, diag);
        if (st != CF_STATUS_OK)
            break;
        if (k == 0)
            read_page(a, fig);
        if (k > 0 && src->same_figure) {
            unsigned step = fi->step;
            *fi = *prev;
            fi->step = step;
            fi->places = NULL;
            if (prev->nplaces > 0) {
                fi->places = cf_alloc_array(prev->nplaces, sizeof *fi->places);
                if (fi->places == NULL)
                    st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                                     "out of memory for the label places");
                else
                    memcpy(fi->places, prev->places,
                           prev->nplaces * sizeof *fi->places);
            }
            src->release(src->ctx, k, fig);
            continue;
        }
        st = build(fig, common, prev != NULL ? prev->places : NULL,
                   prev != NULL ? prev->nplaces : 0, false, &fi->lay, &dl,
                   diag);
        if (st == CF_STATUS_OK && cf__dl_ink(&dl, 0, dl.count, fi->ink) != 0)
            st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                             "out of memory measuring the ink");
        /* a page cropped to the ink: each frame's as a still's (render/
        ** output/output.c), naming an element far outside the drawing */
        if (st == CF_STATUS_OK && a->tight)
            st = cf__figure_check_size(&dl, fi->ink[2] - fi->ink[0],
                                       fi->ink[3] - fi->ink[1],
                                       a->page.width, a->page.height, diag);
        n = st == CF_STATUS_OK ? cf__place_chosen(fig, NULL, 0) : 0;
        fi->nplaces = n;
        if (n > 0) {
            fi->places = cf_alloc_array(n, sizeof *fi->places);
            if (fi->places == NULL)
                st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                                 "out of memory for the label places");
            else
                cf__place_chosen(fig, fi->places, n);
        }
        src->release(src->ctx, k, fig);
    }
    cf__dl_free(&dl);
    return st;
}

/* One map for frames whose own maps differ: the union of their windows
** onto the union of the page boxes the frames gave their windows (equal
** scales when every frame's are). */
static void
union_map(const anim_t *a, cf__layout_t *u)
{
    double r[4] = { INFINITY, INFINITY, -INFINITY, -INFINITY };
    bool aspect = true;
    *u = a->info[0].lay;
    for (unsigned k = 0; k < a->src->frames; k++) {
        const cf__layout_t *l = &a->info[k].lay;
        u->xmin = fmin(u->xmin, l->xmin);
        u->xmax = fmax(u->xmax, l->xmax);
        u->ymin = fmin(u->ymin, l->ymin);
        u->ymax = fmax(u->ymax, l->ymax);
        u->tol = fmin(u->tol, l->tol);
        r[0] = fmin(r[0], l->ox);
        r[2] = fmax(r[2], l->ox + l->sx * (l->xmax - l->xmin));
        r[1] = fmin(r[1], l->oy - l->sy * (l->ymax - l->ymin));
        r[3] = fmax(r[3], l->oy);
        aspect = aspect && fabs(l->sx - l->sy) <= 1e-9 * l->sx;
    }
    u->sx = (r[2] - r[0]) / fmax(u->xmax - u->xmin, 1e-300);
    u->sy = (r[3] - r[1]) / fmax(u->ymax - u->ymin, 1e-300);
    if (aspect)
        u->sx = u->sy = fmin(u->sx, u->sy);
    u->ox = 0.5 * (r[0] + r[2]) - 0.5 * u->sx * (u->xmax - u->xmin);
    u->oy = 0.5 * (r[1] + r[3]) + 0.5 * u->sy * (u->ymax - u->ymin);
}

/* The frames' inks u together too large a page: the check of a still's
** page size (cf__figure_check_size) on the frame whose ink lies farthest
** outside the figure's page, which names the element. */
static cf_status_t
union_too_large(anim_t *a, const double u[4], cf_diag_t *diag)
{
    unsigned k, worst = 0;
    double far = -INFINITY;
    cf_figure_t *fig = NULL;
    cf__layout_t lay;
    cf__dl_t dl;
    cf_status_t st;
    for (k = 0; k < a->src->frames; k++) {
        const double *ink = a->info[k].ink;
        double o = fmax(fmax(-ink[0], -ink[1]),
                        fmax(ink[2] - a->page.width, ink[3] - a->page.height));
        if (ink[2] > ink[0] && o > far) {
            far = o;
            worst = k;
        }
    }
    st = a->src->make(a->src->ctx, worst, &fig, &k, diag);
    if (st != CF_STATUS_OK)
        return st;
    cf__dl_init(&dl);
    st = build(fig, &a->common, a->info[worst].places,
               a->info[worst].nplaces, true, &lay, &dl, diag);
    if (st == CF_STATUS_OK)
        st = cf__figure_check_size(&dl, u[2] - u[0], u[3] - u[1],
                                   a->page.width, a->page.height, diag);
    cf__dl_free(&dl);
    a->src->release(a->src->ctx, worst, fig);
    return st;
}

/* Steps 1 and 2. */
cf_status_t
cf__anim_settle(anim_t *a, cf_diag_t *diag)
{
    unsigned n = a->src->frames, k;
    bool same = true;
    double u[4] = { INFINITY, INFINITY, -INFINITY, -INFINITY }, pad;
    cf_status_t st = measure(a, NULL, diag);
    if (st != CF_STATUS_OK)
        return st;
    for (k = 1; k < n; k++)
        same = same && cf__layout_same_map(&a->info[0].lay, &a->info[k].lay)
            && a->info[0].lay.px == a->info[k].lay.px
            && a->info[0].lay.py == a->info[k].lay.py;
    a->common = a->info[0].lay;
    if (!same) {
        union_map(a, &a->common);
        st = measure(a, &a->common, diag);
        if (st != CF_STATUS_OK)
            return st;
    }
    if (!a->tight)
        return CF_STATUS_OK;
    for (k = 0; k < n; k++) {
        const double *ink = a->info[k].ink;
        if (!(ink[2] > ink[0] && ink[3] > ink[1]))
            continue;
        u[0] = fmin(u[0], ink[0]);
        u[1] = fmin(u[1], ink[1]);
        u[2] = fmax(u[2], ink[2]);
        u[3] = fmax(u[3], ink[3]);
    }
    if (!(u[2] > u[0] && u[3] > u[1]))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "the animation draws nothing in any of its %u "
                           "frames", n);
    if (u[2] - u[0] > CF__PAGE_MAX || u[3] - u[1] > CF__PAGE_MAX)
        return union_too_large(a, u, diag);
    pad = a->o->tight ? a->o->padding : 0;
    if (!a->o->tight) {
        cf_figure_t *fig;
        unsigned step;
        st = a->src->make(a->src->ctx, 0, &fig, &step, diag);
        if (st != CF_STATUS_OK)
            return st;
        pad = fig->margin;
        a->src->release(a->src->ctx, 0, fig);
    }
    a->page.width = a->raster_page.width = u[2] - u[0] + 2 * pad;
    a->page.height = a->raster_page.height = u[3] - u[1] + 2 * pad;
    a->common.ox += pad - u[0];
    a->common.oy += pad - u[1];
    a->common.px += pad - u[0];
    a->common.py += pad - u[1];
    return CF_STATUS_OK;
}

cf_status_t
cf__anim_frame_dl(anim_t *a, unsigned k, cf__dl_t *dl, unsigned *step,
         cf_figure_t **fig, cf_diag_t *diag)
{
    const frame_info_t *fi = &a->info[k];
    cf__layout_t lay;
    cf_status_t st;
    *fig = NULL;
    st = a->src->make(a->src->ctx, k, fig, step, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = build(*fig, &a->common, fi->places, fi->nplaces, true, &lay, dl,
               diag);
    if (st == CF_STATUS_OK)
        st = cf__figure_check_page(*fig, dl, a->page.width, a->page.height,
                                   !a->tight, diag);
    return st;
}

void
cf__anim_frame_done(anim_t *a, unsigned k, cf__dl_t *dl, cf_figure_t *fig)
{
    cf__dl_reset(dl);
    if (fig != NULL)
        a->src->release(a->src->ctx, k, fig);
}

void
cf__anim_draw(const cf__dl_t *dl, const cf__page_t *pg, unsigned step,
              cairo_t *cr)
{
    if (step == 0) {
        cf__dl_play_page(dl, pg, &cf__cairo_backend, cr);
        return;
    }
    cf__cairo_backend.begin_page(cr, pg);
    cf__dl_play_step(dl, pg, step, &cf__cairo_backend, cr);
    cf__cairo_backend.end_page(cr);
}

cf_status_t
cf__anim_raster(anim_t *a, unsigned k, cairo_surface_t *surf, cf__dl_t *dl,
       cf_diag_t *diag)
{
    unsigned step = 0;
    cairo_t *cr;
    cairo_status_t cst;
    cf_figure_t *fig;
    cf_status_t st = cf__anim_frame_dl(a, k, dl, &step, &fig, diag);
    if (st != CF_STATUS_OK) {
        cf__anim_frame_done(a, k, dl, fig);
        return st;
    }
    cr = cairo_create(surf);
    cairo_set_operator(cr, CAIRO_OPERATOR_CLEAR);
    cairo_paint(cr);
    cairo_set_operator(cr, CAIRO_OPERATOR_OVER);
    cairo_scale(cr, a->o->dpi / 72.0, a->o->dpi / 72.0);
    cf__anim_draw(dl, &a->raster_page, step, cr);
    cst = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_flush(surf);
    cf__anim_frame_done(a, k, dl, fig);
    if (cst != CAIRO_STATUS_SUCCESS)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "cairo failed drawing frame %u: %s", k + 1,
                           cairo_status_to_string(cst));
    return CF_STATUS_OK;
}
