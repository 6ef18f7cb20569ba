/*
** Output: a figure laid out (render/layout/layout.c) into a display list,
** drawn in each format (render/output/formats.c: cairo's devices) into
** memory, then written to a temporary file in the target directory and renamed
** over the target.
*/
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "curvefig/access.h"
#include "layout-private.h"
#include "measure.h"
#include "output-private.h"

void
cf_write_options_init(cf_write_options_t *options)
{
    if (options == NULL)
        return;
    memset(options, 0, sizeof *options);
    options->dpi = 150;
    options->tight = false;
    options->padding = 0;
}

static cf_status_t
check_options(const cf_write_options_t *o, unsigned steps, cf_diag_t *diag)
{
    if (!(isfinite(o->dpi) && o->dpi >= 1 && o->dpi <= 2400))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "resolution %g dpi must lie in [1, 2400]",
                           o->dpi);
    if (!(isfinite(o->padding) && o->padding >= 0 && o->padding <= 1000))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "padding %g bp must lie in [0, 1000]",
                           o->padding);
    if (o->step > 0 && o->step > steps)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "step %u: the figure has %u step%s", o->step,
                           steps, steps == 1 ? "" : "s");
    return CF_STATUS_OK;
}

/* ---- the page ----------------------------------------------------------- */

/* A figure laid out for writing: its page and display list. */
typedef struct job {
    cf__layout_t lay;
    cf__page_t page;
    double ink[4];    /* ink box at the physical size (x0 y0 x1 y1) */
    cf__dl_t dl;
} job_t;

/* bp: a cropped page is laid out again until its ink lies this close to
** the padding on every side (automatic label places may differ a little
** once the drawing has moved) */
#define CROP_TOL 0.01

/* Whether the ink of job lies pad inside its page on every side. */
static bool
ink_fits(const job_t *job, double pad)
{
    const double *ink = job->ink;
    return fabs(ink[0] - pad) < CROP_TOL && fabs(ink[1] - pad) < CROP_TOL
        && fabs(job->page.width - pad - ink[2]) < CROP_TOL
        && fabs(job->page.height - pad - ink[3]) < CROP_TOL;
}

/* Layout, page size and display list.  The ink box needs a first display
** list; it is made only when asked for (need_ink) or when the page is
** cropped to it (tight; then the ink is in the cropped page's
** coordinates); otherwise ink is left zero. */
static cf_status_t
lay_out_job(cf_figure_t *fig, const cf_write_options_t *o, bool need_ink,
            job_t *job, cf_diag_t *diag)
{
    bool tight = o->tight || fig->page_mode == CF_PAGE_INK;
    double pad = fig->page_mode == CF_PAGE_INK ? fig->margin : o->padding;
    int tries;
    memset(job, 0, sizeof *job);
    cf__dl_init(&job->dl);
    if (cf__figure_layout(fig, &job->lay) != CF_STATUS_OK)
        return cf_figure_status(fig, diag);
    cf_figure_get_size(fig, &job->page.width, &job->page.height);
    job->page.background = fig->theme.background;
    job->page.label_size = fig->theme.role[CF_ROLE_LABEL].font_size;
    for (tries = 0; (need_ink || tight) && tries < 3; tries++) {
        double *ink = job->ink, w, h;
        if (cf__figure_build(fig, &job->lay, &job->dl) != CF_STATUS_OK)
            return cf_figure_status(fig, diag);
        if (cf__dl_ink(&job->dl, 0, job->dl.count, ink) != 0)
            return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                               "out of memory measuring the ink");
        w = ink[2] - ink[0];
        h = ink[3] - ink[1];
        if (!tight)
            return CF_STATUS_OK;
        /* an element far outside the drawing would make the page huge */
        if (cf__figure_check_size(&job->dl, w, h, job->page.width,
                                  job->page.height, diag) != CF_STATUS_OK)
            return diag->status;
        if (!(w > 0 && h > 0)) {
            cf__dl_reset(&job->dl);
            break;
        }
        if (tries > 0 && ink_fits(job, pad))
            return cf__figure_check_page(fig, &job->dl, job->page.width,
                                         job->page.height, false, diag);
        /* the shift goes into the data -> page map, so that the files
        ** carry plain coordinates (no SVG transform attributes) */
        job->page.width = w + 2 * pad;
        job->page.height = h + 2 * pad;
        job->lay.ox += pad - ink[0];
        job->lay.oy += pad - ink[1];
        job->lay.px += pad - ink[0];
        job->lay.py += pad - ink[1];
        ink[2] += pad - ink[0];
        ink[3] += pad - ink[1];
        ink[0] = ink[1] = pad;
        cf__dl_reset(&job->dl);
    }
    if (cf__figure_build(fig, &job->lay, &job->dl) != CF_STATUS_OK)
        return cf_figure_status(fig, diag);
    return cf__figure_check_page(fig, &job->dl, job->page.width,
                                 job->page.height, !tight, diag);
}

static cf_status_t
make_job(cf_figure_t *fig, const cf_write_options_t *o, bool need_ink,
         job_t *job, cf_diag_t *diag)
{
    cf_status_t st = lay_out_job(fig, o, need_ink, job, diag);
    cf__place_release(fig);
    return st;
}

static void
job_free(job_t *job)
{
    cf__dl_free(&job->dl);
}

cf_status_t
cf__figure_play(cf_figure_t *fig, unsigned step, const cf__backend_t *be,
                void *ctx, cf_diag_t *diag)
{
    cf_write_options_t o;
    job_t job;
    cf_status_t st;
    cf_write_options_init(&o);
    st = make_job(fig, &o, false, &job, diag);
    if (st == CF_STATUS_OK) {
        be->begin_page(ctx, &job.page);
        cf__dl_play_step(&job.dl, &job.page,
                         step <= cf_figure_steps(fig) ? step : 0, be, ctx);
        if (be->end_page(ctx) != 0)
            st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                             "the %s backend failed drawing the figure",
                             be->name);
    }
    job_free(&job);
    return st;
}

/* The accessible text every format carries (docs/accessibility.md): the
** alt text, and the long description (the caption when alt was given
** apart from it and there is no description). */
static cf_status_t
a11y_text(cf_figure_t *fig, char **alt, char **desc, cf_diag_t *diag)
{
    if (cf_figure_alt_text(fig, alt) != CF_STATUS_OK
        || cf_figure_description(fig, desc) != CF_STATUS_OK) {
        cf_free(*alt);
        *alt = NULL;
        return cf_figure_status(fig, diag);
    }
    if (*desc == NULL && fig->alt != NULL && fig->caption != NULL
        && fig->caption[0] != '\0' && strcmp(fig->caption, *alt) != 0) {
        *desc = cf_malloc(strlen(fig->caption) + 1);
        if (*desc == NULL) {
            cf_free(*alt);
            *alt = NULL;
            return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                               "out of memory for the description");
        }
        strcpy(*desc, fig->caption);
    }
    return CF_STATUS_OK;
}

static cf_status_t render_text(cf_figure_t *fig, cf_format_t format,
                               const cf_write_options_t *o, const job_t *job,
                               const char *alt, const char *desc,
                               cf__buf_t *out, cf_diag_t *diag);

/* One format of a laid-out figure; with overlay steps, step o->step
** alone, or the whole sequence (render/figure/overlay.c, docs/overlays.md). */
static cf_status_t
render_job(cf_figure_t *fig, cf_format_t format, const cf_write_options_t *o,
           const job_t *job, cf__buf_t *out, cf_diag_t *diag)
{
    char *alt = NULL, *desc = NULL;
    cf_status_t st = a11y_text(fig, &alt, &desc, diag);
    if (st == CF_STATUS_OK)
        st = render_text(fig, format, o, job, alt, desc, out, diag);
    cf_free(alt);
    cf_free(desc);
    return st;
}

static cf_status_t
render_text(cf_figure_t *fig, cf_format_t format, const cf_write_options_t *o,
            const job_t *job, const char *alt, const char *desc,
            cf__buf_t *out, cf_diag_t *diag)
{
    cf__page_t pg = job->page;
    unsigned n = cf_figure_steps(fig);
    bool multi;
    pg.lang = fig->lang;
    if (fig->background == CF_BACKGROUND_NONE
        || (fig->background == CF_BACKGROUND_AUTO
            && format != CF_FORMAT_PNG))
        pg.background.a = 0;
    if (n > 1 && o->step > 0) {
        pg.first_step = pg.last_step = o->step;
    } else if (n > 1 && format == CF_FORMAT_SVG) {
        return cf__svg_steps(&job->dl, &pg, n, alt, desc, out, diag);
    } else if (n > 1) {
        multi = format == CF_FORMAT_PDF || format == CF_FORMAT_PS;
        pg.first_step = multi ? 1 : n;
        pg.last_step = n;
    }
    return cf__format_render(format, &job->dl, &pg, o->dpi, alt, desc, out,
                             diag);
}

static cf_status_t
options_or_default(const cf_figure_t *fig,
                   const cf_write_options_t *options, cf_write_options_t *o,
                   cf_diag_t *diag)
{
    if (options != NULL)
        *o = *options;
    else
        cf_write_options_init(o);
    return check_options(o, cf_figure_steps(fig), diag);
}

static cf_status_t
check_fig_format(cf_figure_t *fig, cf_format_t format, cf_diag_t *diag)
{
    if (fig == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "figure is NULL");
    if (cf_figure_status(fig, NULL) != CF_STATUS_OK)
        return cf_figure_status(fig, diag);
    if ((unsigned)format >= CF_FORMAT_LAST_)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "unknown format %d (use CF_FORMAT_SVG .. PNG)",
                           (int)format);
    return CF_STATUS_OK;
}

/* The map data -> page bp of layout l (cf_figure_page_map's). */
static void
layout_map(const cf__layout_t *l, double map[6])
{
    map[0] = l->sx;
    map[1] = 0;
    map[2] = 0;
    map[3] = -l->sy;
    map[4] = l->ox - l->sx * l->xmin;
    map[5] = l->oy + l->sy * l->ymin;
}

/* Check the arguments, lay out and render one format into buf; the page
** map of that layout into map (when not NULL). */
static cf_status_t
render_checked(cf_figure_t *fig, cf_format_t format,
               const cf_write_options_t *options, cf__buf_t *buf,
               double *map, cf__buf_t *places, cf_diag_t *diag)
{
    cf_write_options_t o;
    job_t job;
    cf_status_t st = check_fig_format(fig, format, diag);
    memset(buf, 0, sizeof *buf);
    if (st == CF_STATUS_OK)
        st = options_or_default(fig, options, &o, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = make_job(fig, &o, false, &job, diag);
    if (st == CF_STATUS_OK)
        st = render_job(fig, format, &o, &job, buf, diag);
    if (st == CF_STATUS_OK && map != NULL)
        layout_map(&job.lay, map);
    if (st == CF_STATUS_OK && places != NULL
        && cf__label_places(&job.dl, &job.page, places) != 0)
        st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory listing the places of the labels");
    job_free(&job);
    return st;
}

cf_status_t
cf_figure_render(cf_figure_t *fig, cf_format_t format,
                 const cf_write_options_t *options, unsigned char **data,
                 size_t *size, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    return cf_figure_render_mapped(fig, format, options, data, size, NULL,
                                   diag);
}

cf_status_t
cf_figure_render_mapped(cf_figure_t *fig, cf_format_t format,
                        const cf_write_options_t *options,
                        unsigned char **data, size_t *size, double map[6],
                        cf_diag_t *diag)
{
    cf_diag_clear(diag);
    return cf_figure_render_places(fig, format, options, data, size, map,
                                   NULL, NULL, diag);
}

cf_status_t
cf_figure_render_places(cf_figure_t *fig, cf_format_t format,
                        const cf_write_options_t *options,
                        unsigned char **data, size_t *size, double map[6],
                        char **places, size_t *places_size, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf__buf_t buf, pl;
    cf_status_t st;
    if (data == NULL || size == NULL || (places == NULL) != (places_size
                                                             == NULL))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "render: output pointers are NULL");
    *data = NULL;
    *size = 0;
    if (places != NULL) {
        *places = NULL;
        *places_size = 0;
    }
    memset(&pl, 0, sizeof pl);
    st = render_checked(fig, format, options, &buf, map,
                        places != NULL ? &pl : NULL, diag);
    if (st != CF_STATUS_OK) {
        cf__buf_free(&pl);
        return st;
    }
    if (places != NULL && cf__buf_append(&pl, "", 1) != 0) {
        cf__buf_free(&buf);
        cf__buf_free(&pl);
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory listing the places of the labels");
    }
    *data = buf.data;
    *size = buf.size;
    if (places != NULL) {
        *places = (char *)pl.data;
        *places_size = pl.size - 1;
    }
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_ink_box(cf_figure_t *fig, const cf_write_options_t *options,
                  double box[4], double *page_width, double *page_height,
                  cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_write_options_t o;
    job_t job;
    cf_status_t st = check_fig_format(fig, CF_FORMAT_SVG, diag);
    if (st == CF_STATUS_OK)
        st = options_or_default(fig, options, &o, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = make_job(fig, &o, true, &job, diag);
    if (st == CF_STATUS_OK) {
        if (box != NULL)
            memcpy(box, job.ink, sizeof job.ink);
        if (page_width != NULL)
            *page_width = job.page.width;
        if (page_height != NULL)
            *page_height = job.page.height;
    }
    job_free(&job);
    return st;
}

cf_status_t
cf_figure_page_map(cf_figure_t *fig, const cf_write_options_t *options,
                   double map[6], cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_write_options_t o;
    job_t job;
    cf_status_t st = check_fig_format(fig, CF_FORMAT_SVG, diag);
    if (st == CF_STATUS_OK && map == NULL)
        st = cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                         "page map: map is NULL");
    if (st == CF_STATUS_OK)
        st = options_or_default(fig, options, &o, diag);
    if (st != CF_STATUS_OK)
        return st;
    /* a tight or ink page moves the map by the ink box, which needs the
    ** drawing */
    if (o.tight || fig->page_mode == CF_PAGE_INK) {
        st = make_job(fig, &o, false, &job, diag);
    } else {
        memset(&job, 0, sizeof job);
        cf__dl_init(&job.dl);
        if (cf__figure_layout(fig, &job.lay) != CF_STATUS_OK)
            st = cf_figure_status(fig, diag);
    }
    if (st == CF_STATUS_OK)
        layout_map(&job.lay, map);
    job_free(&job);
    return st;
}

cf_status_t
cf_figure_dump(cf_figure_t *fig, const cf_write_options_t *options,
               char **text, size_t *size, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_write_options_t o;
    job_t job;
    cf__dump_t d;
    cf_status_t st;
    if (text == NULL || size == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "dump: output pointers are NULL");
    *text = NULL;
    *size = 0;
    st = check_fig_format(fig, CF_FORMAT_SVG, diag);
    if (st == CF_STATUS_OK)
        st = options_or_default(fig, options, &o, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = make_job(fig, &o, false, &job, diag);
    memset(&d, 0, sizeof d);
    if (st == CF_STATUS_OK
        && cf__dl_play_page(&job.dl, &job.page, &cf__dump_backend, &d) != 0)
        st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory dumping the display list");
    job_free(&job);
    if (st != CF_STATUS_OK) {
        cf_free(d.text);
        return st;
    }
    *text = d.text;
    *size = d.len;
    return CF_STATUS_OK;
}

/* ---- files -------------------------------------------------------------- */

/* A name for a temporary file that nobody can guess: 12 characters from
** /dev/urandom (from the clock, the process and the address of a local
** where there is none; the exclusive open below stays safe either way). */
static void
random_name(char out[13])
{
    static const char digits[] =
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-";
    unsigned char b[12];
    int fd = open("/dev/urandom", O_RDONLY | O_CLOEXEC);
    ssize_t n = fd >= 0 ? read(fd, b, sizeof b) : -1;
    if (fd >= 0)
        close(fd);
    if (n != (ssize_t)sizeof b) {
        struct timespec ts;
        unsigned long long x;
        clock_gettime(CLOCK_REALTIME, &ts);
        x = (unsigned long long)ts.tv_nsec * 0x9e3779b97f4a7c15ull
            ^ (unsigned long long)ts.tv_sec ^ (unsigned long long)getpid()
            << 32 ^ (unsigned long long)(uintptr_t)&ts;
        for (size_t i = 0; i < sizeof b; i++) {
            x ^= x >> 29;
            x *= 0xbf58476d1ce4e5b9ull;
            b[i] = (unsigned char)(x >> 56);
        }
    }
    for (size_t i = 0; i < sizeof b; i++)
        out[i] = digits[b[i] & 63];
    out[12] = '\0';
}

cf_status_t
cf__temp_open(const char *path, int *fd, char **tmp, cf_diag_t *diag)
{
    const char *slash;
    size_t dlen;
    cf_status_t st;

    *fd = -1;
    *tmp = NULL;
    if (path[0] == '\0' || path[strlen(path) - 1] == '/')
        return cf_diag_set(diag, CF_STATUS_IO, -1,
                           "\"%s\" is not a file name", path);
    slash = strrchr(path, '/');
    dlen = slash != NULL ? (size_t)(slash - path) + 1 : 0;
    *tmp = cf_malloc(dlen + 24);
    if (*tmp == NULL)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for a file name");
    memcpy(*tmp, path, dlen);
    memcpy(*tmp + dlen, ".cf-tmp-", 8);
    for (int tries = 0; *fd < 0 && tries < 100; tries++) {
        random_name(*tmp + dlen + 8);
        *fd = open(*tmp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW
                             | O_CLOEXEC, 0666);
        if (*fd < 0 && errno != EEXIST)
            break;
    }
    if (*fd >= 0)
        return CF_STATUS_OK;
    st = cf_diag_set(diag, CF_STATUS_IO, -1,
                     "cannot create a temporary file for \"%s\": %s", path,
                     strerror(errno));
    cf_free(*tmp);
    *tmp = NULL;
    return st;
}

/* The one writer of every file that curvefig makes (the figures here, and
** the tool's pages, manifests, galleries, images and reports): the data
** goes to a new file of a random name in the target's directory
** (cf__temp_open, opened with O_CREAT | O_EXCL | O_NOFOLLOW, so that no
** file or symbolic link planted there, under any name, is followed or
** truncated; mode 0666 less the umask), and that file is renamed over the
** target: a reader sees the old file or the new one, never a part, and a
** symbolic link at the target is replaced, not followed.  No fsync:
** figures are build products (as the object files ninja writes), and a
** sync costs 4 to 20 ms of waiting per file, more than rendering it. */
cf_status_t
cf_write_file(const char *path, const void *data, size_t n, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    char *tmp;
    int fd;
    size_t off = 0;
    cf_status_t st = CF_STATUS_OK;

    if (path == NULL || (data == NULL && n > 0))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "write: path or data is NULL");
    st = cf__temp_open(path, &fd, &tmp, diag);
    if (st != CF_STATUS_OK)
        return st;
    while (off < n) {
        ssize_t w = write(fd, (const unsigned char *)data + off, n - off);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0) {
            st = cf_diag_set(diag, CF_STATUS_IO, -1,
                             "cannot write \"%s\": %s", path,
                             w < 0 ? strerror(errno) : "no progress");
            break;
        }
        off += (size_t)w;
    }
    if (close(fd) != 0 && st == CF_STATUS_OK)
        st = cf_diag_set(diag, CF_STATUS_IO, -1, "cannot write \"%s\": %s",
                         path, strerror(errno));
    if (st == CF_STATUS_OK && rename(tmp, path) != 0)
        st = cf_diag_set(diag, CF_STATUS_IO, -1, "cannot write \"%s\": %s",
                         path, strerror(errno));
    if (st != CF_STATUS_OK)
        unlink(tmp);
    cf_free(tmp);
    return st;
}

cf_status_t
cf_figure_write(cf_figure_t *fig, const char *path, cf_format_t format,
                const cf_write_options_t *options, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf__buf_t buf;
    cf_status_t st;
    if (path == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "path is NULL");
    st = render_checked(fig, format, options, &buf, NULL, NULL, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = cf_write_file(path, buf.data, buf.size, diag);
    cf__buf_free(&buf);
    return st;
}

/* basename-K.<ext> for every step K of a figure with steps: PNG always,
** the other formats when o->step_files. */
static cf_status_t
write_steps(cf_figure_t *fig, const char *basename, unsigned formats,
            const cf_write_options_t *o, const job_t *job, char *path,
            size_t cap, cf_diag_t *diag)
{
    unsigned n = cf_figure_steps(fig), k;
    cf_write_options_t one = *o;
    cf_status_t st = CF_STATUS_OK;
    int f;
    if (n < 2 || o->step > 0)
        return CF_STATUS_OK;
    for (f = 0; f < CF_FORMAT_LAST_ && st == CF_STATUS_OK; f++) {
        if (!(formats & CF_FORMAT_BIT(f))
            || !(f == CF_FORMAT_PNG || o->step_files))
            continue;
        for (k = 1; k <= n && st == CF_STATUS_OK; k++) {
            cf__buf_t buf;
            memset(&buf, 0, sizeof buf);
            one.step = k;
            snprintf(path, cap, "%s-%u.%s", basename, k,
                     cf_format_extension((cf_format_t)f));
            st = render_job(fig, (cf_format_t)f, &one, job, &buf, diag);
            if (st == CF_STATUS_OK)
                st = cf_write_file(path, buf.data, buf.size, diag);
            cf__buf_free(&buf);
        }
    }
    return st;
}

cf_status_t
cf_figure_write_all(cf_figure_t *fig, const char *basename, unsigned formats,
                    const cf_write_options_t *options, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_write_options_t o;
    job_t job;
    cf__buf_t ps;
    bool derive_eps;
    size_t n;
    int f;
    char *path;
    cf_status_t st;

    if (basename == NULL || basename[0] == '\0')
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "base name is NULL or empty");
    if (formats == 0 || (formats >> CF_FORMAT_LAST_) != 0)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "format set 0x%x is empty or has unknown bits",
                           formats);
    st = check_fig_format(fig, CF_FORMAT_SVG, diag);
    if (st == CF_STATUS_OK)
        st = options_or_default(fig, options, &o, diag);
    if (st != CF_STATUS_OK)
        return st;
    /* one layout and one display list for every format: the page is the
    ** same */
    st = make_job(fig, &o, false, &job, diag);
    n = strlen(basename);
    path = st == CF_STATUS_OK ? cf_malloc(n + 16) : NULL;
    if (st == CF_STATUS_OK && path == NULL)
        st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for a file name");
    /* PS before EPS in format order; the EPS is derived from the PS */
    derive_eps = (formats & CF_FORMAT_BIT(CF_FORMAT_PS))
        && (formats & CF_FORMAT_BIT(CF_FORMAT_EPS))
        && (cf_figure_steps(fig) == 1 || o.step > 0);
    memset(&ps, 0, sizeof ps);
    for (f = 0; f < CF_FORMAT_LAST_ && st == CF_STATUS_OK; f++) {
        cf__buf_t buf;
        int r = -1;
        if (!(formats & CF_FORMAT_BIT(f)))
            continue;
        snprintf(path, n + 8, "%s.%s", basename,
                 cf_format_extension((cf_format_t)f));
        memset(&buf, 0, sizeof buf);
        if (f == CF_FORMAT_EPS && ps.data != NULL) {
            r = cf__eps_from_ps(&ps, &buf);
            if (r == -2)
                st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                                 "out of memory writing eps");
            else if (r == -1)
                cf__buf_free(&buf);
        }
        if (r == -1)
            st = render_job(fig, (cf_format_t)f, &o, &job, &buf, diag);
        if (st == CF_STATUS_OK)
            st = cf_write_file(path, buf.data, buf.size, diag);
        if (f == CF_FORMAT_PS && derive_eps && st == CF_STATUS_OK) {
            ps = buf;
            memset(&buf, 0, sizeof buf);
        }
        cf__buf_free(&buf);
    }
    cf__buf_free(&ps);
    if (st == CF_STATUS_OK)
        st = write_steps(fig, basename, formats, &o, &job, path, n + 16,
                         diag);
    cf_free(path);
    job_free(&job);
    return st;
}
