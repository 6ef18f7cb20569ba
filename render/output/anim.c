/*
** The frame loop of an animation (anim.h, docs/animations.md).
**
** 1. Measure: every frame laid out and built once, in order, each
**    automatic label offered the place it had in the frame before
**    (render/layout/place.c keeps it while it stays within AUTO_KEEP of
**    the clearest place): each frame's map, ink box and label places.
**    When the frames' maps differ (a window fitted to what each frame
**    draws), one map is made that holds every frame's window where the
**    frames put theirs, and the frames are measured again with it.
** 2. The page: the figure's page, or on a page cropped to the ink (tight,
**    page = "ink") the union of every frame's ink plus the padding; the
**    same for every frame.
** 3. Draw: every frame built again with that map and its measured label
**    places, into the animated SVG (svg-anim.c), a page of the PDF, and a
**    raster for the encoders of anim-sink.h.  The rasters are drawn by
**    child processes where the machine has more than one core (each runs
**    its frames' scripts itself and sends the pixels through a pipe; the
**    frames are read in order, so at most one frame per child waits).
** Files are written at the end, each whole (cf_write_file; the videos by
** their sinks, through a temporary file renamed at finish).
*/
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cairo-pdf.h>
#include <sys/wait.h>
#include <unistd.h>

#include "anim.h"
#include "layout-private.h"
#include "measure.h"
#include "output-private.h"
#include "anim-sink.h"

#define MAX_WORKERS 8

typedef struct frame_info {
    cf__layout_t lay;
    double ink[4];
    cf__auto_place_t *places;
    size_t nplaces;
    unsigned step;
} frame_info_t;

/* What every frame shares. */
typedef struct anim {
    const cf__anim_source_t *src;
    const cf__anim_options_t *o;
    frame_info_t *info;
    cf__layout_t common;
    cf__page_t page;         /* for the vector forms */
    cf__page_t raster_page;  /* for the rasters (background as PNG's) */
    bool tight;
    int wpx, hpx;            /* raster size */
    char *title, *caption;
} anim_t;

const char *
cf__anim_extension(unsigned output)
{
    switch (output) {
    case CF__ANIM_OUT_SVG: return "svg";
    case CF__ANIM_OUT_PDF: return "pdf";
    case CF__ANIM_OUT_GIF: return "gif";
    case CF__ANIM_OUT_APNG: return "apng";
    case CF__ANIM_OUT_MP4: return "mp4";
    case CF__ANIM_OUT_WEBM: return "webm";
    default: return "";
    }
}

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
static cf_status_t
settle(anim_t *a, cf_diag_t *diag)
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

/* Frame k built for drawing (step 3) into dl; the display list draws
** the figure's labels, so the caller releases *fig (made when not NULL,
** also on failure) once it has drawn dl. */
static cf_status_t
frame_dl(anim_t *a, unsigned k, cf__dl_t *dl, unsigned *step,
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

static void
frame_done(anim_t *a, unsigned k, cf__dl_t *dl, cf_figure_t *fig)
{
    cf__dl_reset(dl);
    if (fig != NULL)
        a->src->release(a->src->ctx, k, fig);
}

/* The page of dl at step (0: all of it) drawn on cr (set up). */
static void
draw(const cf__dl_t *dl, const cf__page_t *pg, unsigned step, cairo_t *cr)
{
    if (step == 0) {
        cf__dl_play_page(dl, pg, &cf__cairo_backend, cr);
        return;
    }
    cf__cairo_backend.begin_page(cr, pg);
    cf__dl_play_step(dl, pg, step, &cf__cairo_backend, cr);
    cf__cairo_backend.end_page(cr);
}

/* Frame k's raster into surf (a->wpx x a->hpx, ARGB32). */
static cf_status_t
raster(anim_t *a, unsigned k, cairo_surface_t *surf, cf__dl_t *dl,
       cf_diag_t *diag)
{
    unsigned step = 0;
    cairo_t *cr;
    cairo_status_t cst;
    cf_figure_t *fig;
    cf_status_t st = frame_dl(a, k, dl, &step, &fig, diag);
    if (st != CF_STATUS_OK) {
        frame_done(a, k, dl, fig);
        return st;
    }
    cr = cairo_create(surf);
    cairo_set_operator(cr, CAIRO_OPERATOR_CLEAR);
    cairo_paint(cr);
    cairo_set_operator(cr, CAIRO_OPERATOR_OVER);
    cairo_scale(cr, a->o->dpi / 72.0, a->o->dpi / 72.0);
    draw(dl, &a->raster_page, step, cr);
    cst = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_flush(surf);
    frame_done(a, k, dl, fig);
    if (cst != CAIRO_STATUS_SUCCESS)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "cairo failed drawing frame %u: %s", k + 1,
                           cairo_status_to_string(cst));
    return CF_STATUS_OK;
}

/* ---- the rasters' workers ------------------------------------------------ */

typedef struct workers {
    int n;
    pid_t pid[MAX_WORKERS];
    int fd[MAX_WORKERS];
} workers_t;

/* The reply for one frame: status, then the message or the pixels. */
typedef struct reply {
    int32_t status;
    char msg[sizeof ((cf_diag_t *)0)->msg];
} reply_t;

static int
write_all(int fd, const void *p, size_t n)
{
    const unsigned char *b = p;
    while (n > 0) {
        ssize_t w = write(fd, b, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return -1;
        b += w;
        n -= (size_t)w;
    }
    return 0;
}

static int
read_all(int fd, void *p, size_t n)
{
    unsigned char *b = p;
    while (n > 0) {
        ssize_t r = read(fd, b, n);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0)
            return -1;
        b += r;
        n -= (size_t)r;
    }
    return 0;
}

/* A child: the rasters of frames w, w + n, ... through fd. */
static void
worker(anim_t *a, int w, int n, int fd)
{
    cairo_surface_t *surf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32,
                                                       a->wpx, a->hpx);
    size_t bytes = (size_t)cairo_image_surface_get_stride(surf)
                   * (size_t)a->hpx;
    cf__dl_t dl;
    cf__dl_init(&dl);
    for (unsigned k = (unsigned)w; k < a->src->frames; k += (unsigned)n) {
        cf_diag_t diag;
        reply_t rep;
        cf_diag_clear(&diag);
        memset(&rep, 0, sizeof rep);
        rep.status = cairo_surface_status(surf) == CAIRO_STATUS_SUCCESS
                     ? (int32_t)raster(a, k, surf, &dl, &diag)
                     : (int32_t)cf_diag_set(&diag, CF_STATUS_NO_MEMORY, -1,
                                            "out of memory for a frame");
        memcpy(rep.msg, diag.msg, sizeof rep.msg);
        if (write_all(fd, &rep, sizeof rep) != 0 || rep.status != 0
            || write_all(fd, cairo_image_surface_get_data(surf), bytes) != 0)
            break;
    }
    _exit(0);
}

static void
workers_stop(workers_t *ws)
{
    for (int i = 0; i < ws->n; i++) {
        close(ws->fd[i]);
        kill(ws->pid[i], SIGTERM);
        while (waitpid(ws->pid[i], NULL, 0) < 0 && errno == EINTR)
            ;
    }
    ws->n = 0;
}

/* n children started (fewer when fork fails: then this process draws
** the rasters itself, ws->n 0). */
static void
workers_start(anim_t *a, int n, workers_t *ws)
{
    ws->n = 0;
    fflush(NULL);
    for (int i = 0; i < n; i++) {
        int p[2];
        pid_t pid;
        if (pipe(p) != 0)
            break;
        pid = fork();
        if (pid < 0) {
            close(p[0]);
            close(p[1]);
            break;
        }
        if (pid == 0) {
            close(p[0]);
            for (int j = 0; j < ws->n; j++)
                close(ws->fd[j]);
            worker(a, i, n, p[1]);
        }
        close(p[1]);
        ws->pid[i] = pid;
        ws->fd[i] = p[0];
        ws->n++;
    }
    if (ws->n != n)
        workers_stop(ws);
}

/* ---- the forms ----------------------------------------------------------- */

typedef struct forms {
    cf__svg_anim_t svg;
    cf__buf_t pdf;
    cairo_surface_t *pdf_surf;
    cairo_t *pdf_cr;
    cf__anim_sink_t *sink[4];     /* GIF, APNG, MP4, WebM */
    cf__buf_t bytes[4];
} forms_t;

static cairo_status_t
to_buf(void *closure, const unsigned char *data, unsigned int length)
{
    return cf__buf_append(closure, data, length) == 0
        ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

/* The file of form bit. */
static char *
form_path(const anim_t *a, unsigned bit)
{
    const char *ext = cf__anim_extension(bit);
    char *p = cf_malloc(strlen(a->o->base) + strlen(ext) + 2);
    if (p != NULL)
        sprintf(p, "%s.%s", a->o->base, ext);
    return p;
}

static cf_status_t
forms_open(anim_t *a, forms_t *f, cf_diag_t *diag)
{
    unsigned out = a->o->outputs;
    memset(f, 0, sizeof *f);
    if (out & CF__ANIM_OUT_PDF) {
        f->pdf_surf = cairo_pdf_surface_create_for_stream(
            to_buf, &f->pdf, a->page.width, a->page.height);
        char date[40];
        cf__pdf_date(date, sizeof date);
        cairo_pdf_surface_set_metadata(f->pdf_surf,
                                       CAIRO_PDF_METADATA_CREATE_DATE, date);
        cairo_pdf_surface_set_metadata(f->pdf_surf,
                                       CAIRO_PDF_METADATA_MOD_DATE, date);
        if (a->title != NULL)
            cairo_pdf_surface_set_metadata(f->pdf_surf,
                                           CAIRO_PDF_METADATA_TITLE,
                                           a->title);
        if (a->caption != NULL)
            cairo_pdf_surface_set_metadata(f->pdf_surf,
                                           CAIRO_PDF_METADATA_SUBJECT,
                                           a->caption);
        f->pdf_cr = cairo_create(f->pdf_surf);
        if (cairo_status(f->pdf_cr) != CAIRO_STATUS_SUCCESS)
            return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                               "out of memory opening the pdf");
    }
    if (out & CF__ANIM_OUT_RASTER) {
        static const unsigned raster_bits[4] = {
            CF__ANIM_OUT_GIF, CF__ANIM_OUT_APNG, CF__ANIM_OUT_MP4,
            CF__ANIM_OUT_WEBM
        };
        double fps = 1.0 / a->src->seconds;
        for (int i = 0; i < 4; i++) {
            char *path = NULL;
            cf_status_t st;
            if (!(out & raster_bits[i]))
                continue;
            if (i >= 2 && (path = form_path(a, raster_bits[i])) == NULL)
                return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                                   "out of memory for a file name");
            st = cf__anim_sink_open((cf__anim_kind_t)i, a->wpx, a->hpx, fps,
                                    a->o->loop, path, &f->sink[i], diag);
            cf_free(path);
            if (st != CF_STATUS_OK)
                return st;
        }
    }
    return CF_STATUS_OK;
}

static void
forms_free(forms_t *f)
{
    cf__svg_anim_free(&f->svg);
    if (f->pdf_cr != NULL)
        cairo_destroy(f->pdf_cr);
    if (f->pdf_surf != NULL) {
        cairo_surface_finish(f->pdf_surf);
        cairo_surface_destroy(f->pdf_surf);
    }
    f->pdf_cr = NULL;
    f->pdf_surf = NULL;
    cf__buf_free(&f->pdf);
    for (int i = 0; i < 4; i++) {
        cf__anim_sink_abort(f->sink[i]);
        f->sink[i] = NULL;
        cf__buf_free(&f->bytes[i]);
    }
}

/* Frame k's vector forms (the SVG's group, the PDF's page). */
static cf_status_t
vector_frame(anim_t *a, forms_t *f, unsigned k, cf__dl_t *dl,
             cf_diag_t *diag)
{
    unsigned step = 0;
    cf_figure_t *fig;
    cf_status_t st;
    if (!(a->o->outputs & (CF__ANIM_OUT_SVG | CF__ANIM_OUT_PDF)))
        return CF_STATUS_OK;
    st = frame_dl(a, k, dl, &step, &fig, diag);
    if (st == CF_STATUS_OK && (a->o->outputs & CF__ANIM_OUT_SVG))
        st = cf__svg_anim_add(&f->svg, dl, &a->page, step, a->src->seconds,
                              diag);
    if (st == CF_STATUS_OK && (a->o->outputs & CF__ANIM_OUT_PDF)) {
        draw(dl, &a->page, step, f->pdf_cr);
        cairo_show_page(f->pdf_cr);
        if (cairo_status(f->pdf_cr) != CAIRO_STATUS_SUCCESS)
            st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                             "cairo failed on page %u of the pdf: %s", k + 1,
                             cairo_status_to_string(cairo_status(f->pdf_cr)));
    }
    frame_done(a, k, dl, fig);
    return st;
}

static cf_status_t
raster_add(forms_t *f, cairo_surface_t *surf, double seconds,
           cf_diag_t *diag)
{
    for (int i = 0; i < 4; i++)
        if (f->sink[i] != NULL) {
            cf_status_t st = cf__anim_sink_add(f->sink[i], surf, seconds,
                                               diag);
            if (st != CF_STATUS_OK)
                return st;
        }
    return CF_STATUS_OK;
}

/* Every file made: the sinks finished, the SVG, PDF, GIF and APNG
** written. */
static cf_status_t
forms_finish(anim_t *a, forms_t *f, cf_diag_t *diag)
{
    unsigned out = a->o->outputs;
    cf_status_t st = CF_STATUS_OK;
    cf__buf_t svg;
    char *path;
    memset(&svg, 0, sizeof svg);
    for (int i = 0; i < 4 && st == CF_STATUS_OK; i++)
        if (f->sink[i] != NULL) {
            st = cf__anim_sink_finish(f->sink[i], i < 2 ? &f->bytes[i] : NULL,
                                      diag);
            f->sink[i] = NULL;
        }
    if (st == CF_STATUS_OK && (out & CF__ANIM_OUT_SVG))
        st = cf__svg_anim_finish(&f->svg, a->src->same_figure
                                              ? a->src->frames - 1 : 0,
                                 a->title, a->caption, &svg, diag);
    if (st == CF_STATUS_OK && f->pdf_surf != NULL) {
        cairo_destroy(f->pdf_cr);
        f->pdf_cr = NULL;
        cairo_surface_finish(f->pdf_surf);
        if (cairo_surface_status(f->pdf_surf) != CAIRO_STATUS_SUCCESS
            || f->pdf.failed)
            st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                             "out of memory writing the pdf");
    }
    for (unsigned bit = 1; bit <= CF__ANIM_OUT_APNG && st == CF_STATUS_OK;
         bit <<= 1) {
        const cf__buf_t *b = bit == CF__ANIM_OUT_SVG ? &svg
                             : bit == CF__ANIM_OUT_PDF ? &f->pdf
                             : bit == CF__ANIM_OUT_GIF ? &f->bytes[0]
                             : &f->bytes[1];
        if (!(out & bit))
            continue;
        path = form_path(a, bit);
        st = path == NULL ? cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                                        "out of memory for a file name")
                          : cf_write_file(path, b->data, b->size, diag);
        cf_free(path);
    }
    cf__buf_free(&svg);
    return st;
}

/* ---- the loop ------------------------------------------------------------ */

static int
worker_count(const anim_t *a)
{
    long cores = a->o->workers > 0 ? a->o->workers
                                   : sysconf(_SC_NPROCESSORS_ONLN);
    if (!(a->o->outputs & CF__ANIM_OUT_RASTER) || cores < 2
        || a->src->same_figure || a->src->frames < 4)
        return 1;
    return (int)(cores < MAX_WORKERS ? cores : MAX_WORKERS);
}

static cf_status_t
draw_frames(anim_t *a, forms_t *f, cf_diag_t *diag)
{
    workers_t ws;
    cairo_surface_t *surf = NULL;
    size_t bytes = 0;
    cf__dl_t dl;
    cf_status_t st = CF_STATUS_OK;
    int nw = worker_count(a);
    memset(&ws, 0, sizeof ws);
    cf__dl_init(&dl);
    if (a->o->outputs & CF__ANIM_OUT_RASTER) {
        surf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, a->wpx,
                                          a->hpx);
        if (cairo_surface_status(surf) != CAIRO_STATUS_SUCCESS)
            st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                             "out of memory for a frame of %d x %d pixels",
                             a->wpx, a->hpx);
        bytes = (size_t)cairo_image_surface_get_stride(surf)
                * (size_t)a->hpx;
        if (st == CF_STATUS_OK && nw > 1)
            workers_start(a, nw, &ws);
    }
    for (unsigned k = 0; k < a->src->frames && st == CF_STATUS_OK; k++) {
        st = vector_frame(a, f, k, &dl, diag);
        if (st != CF_STATUS_OK || surf == NULL)
            continue;
        if (ws.n > 0) {
            reply_t rep;
            int fd = ws.fd[k % (unsigned)ws.n];
            cairo_surface_flush(surf);
            if (read_all(fd, &rep, sizeof rep) != 0
                || (rep.status == 0
                    && read_all(fd, cairo_image_surface_get_data(surf),
                                bytes) != 0))
                st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                                 "the process drawing frame %u ended "
                                 "early", k + 1);
            else if (rep.status != 0)
                st = cf_diag_set(diag, (cf_status_t)rep.status, -1, "%s",
                                 rep.msg);
            cairo_surface_mark_dirty(surf);
        } else {
            st = raster(a, k, surf, &dl, diag);
        }
        if (st == CF_STATUS_OK)
            st = raster_add(f, surf, a->src->seconds, diag);
    }
    workers_stop(&ws);
    if (surf != NULL)
        cairo_surface_destroy(surf);
    cf__dl_free(&dl);
    return st;
}

cf_status_t
cf__anim_write(const cf__anim_source_t *src, const cf__anim_options_t *o,
               double *width, double *height, cf_diag_t *diag)
{
    anim_t a;
    forms_t f;
    cf_status_t st;
    double k;
    cf_diag_clear(diag);
    if (src == NULL || o == NULL || o->base == NULL || src->make == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "animation: source, options or base is NULL");
    if (src->frames == 0)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "an animation needs at least one frame");
    if (!(src->seconds > 0 && isfinite(src->seconds)))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "a frame's time %g s must be positive",
                           src->seconds);
    if (!(isfinite(o->dpi) && o->dpi >= 1 && o->dpi <= 2400))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "resolution %g dpi must lie in [1, 2400]", o->dpi);
    memset(&a, 0, sizeof a);
    a.src = src;
    a.o = o;
    a.info = cf_alloc_array(src->frames, sizeof *a.info);
    if (a.info == NULL)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for %u frames", src->frames);
    memset(a.info, 0, src->frames * sizeof *a.info);
    st = settle(&a, diag);
    k = o->dpi / 72.0;
    a.wpx = (int)fmax(1, ceil(a.page.width * k - 1e-6));
    a.hpx = (int)fmax(1, ceil(a.page.height * k - 1e-6));
    if (st == CF_STATUS_OK && (o->outputs & CF__ANIM_OUT_RASTER)
        && (double)a.wpx * a.hpx > 4e7)
        st = cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                         "frames of %d x %d pixels are too large (at most "
                         "40 million pixels); lower the dpi", a.wpx, a.hpx);
    if (st == CF_STATUS_OK)
        st = forms_open(&a, &f, diag);
    else
        memset(&f, 0, sizeof f);
    if (st == CF_STATUS_OK)
        st = draw_frames(&a, &f, diag);
    if (st == CF_STATUS_OK)
        st = forms_finish(&a, &f, diag);
    forms_free(&f);
    if (width != NULL)
        *width = a.page.width;
    if (height != NULL)
        *height = a.page.height;
    for (unsigned i = 0; i < src->frames; i++)
        cf_free(a.info[i].places);
    cf_free(a.info);
    cf_free(a.title);
    cf_free(a.caption);
    return st;
}
