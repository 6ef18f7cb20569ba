/* Paths far off a clipping page (render/backends/far-clip.h): cairo wraps
** a coordinate beyond 2^23 device units round, and rasterises wrongly an
** edge reaching about 2e5 device units upwards, so the cairo backend cuts
** such paths first.  Each far path here is drawn to PNG (and PDF,
** rasterised by pdftoppm) and compared pixel by pixel with the same path
** cut by the test itself, another way: lines cut where they are 100 bp
** outside the page (at a whole number of dash periods from the far end,
** so the dashes keep their phase), polygons clipped by Sutherland-Hodgman
** with intersections, cubics split at the parameters where they leave a
** box round the page.  Fills are also checked under the even-odd rule,
** drawn by cairo from the cut path directly. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>
#include <cairo.h>

#include "backend.h"
#include "curvefig/figure.h"
#include "dlist.h"
#include "far-clip.h"
#include "layout-private.h"
#include "output-private.h"
#include "pngtest.h"

#define W 200.0          /* the page, bp */
#define H 150.0
#define DPI 150.0
#define FAR 1e7          /* bp: 2e7 device units at 150 dpi */
#define CUT 100.0        /* the test's cuts: this far outside the page */
#define PI 3.14159265358979323846

/* Pixels (of the larger channel difference) that differ by more than
** 1/4: none; by more than 1/32 (anti-aliasing of edges cut at other
** points, in 24.8 fixed point): at most 1 in 200 of the page. */
#define BIG_DIFF 64
#define SMALL_DIFF 8

/* the page drawn on (bp): W x H but for the figure's */
static double page_w = W, page_h = H;

typedef struct image {
    cairo_surface_t *s;
    int w, h, stride;
    const unsigned char *px;
} image_t;

static image_t
decode_png(const unsigned char *data, size_t size)
{
    image_t im;
    im.s = tu_png_decode(data, size);
    assert_int_equal(cairo_surface_status(im.s), CAIRO_STATUS_SUCCESS);
    cairo_surface_flush(im.s);
    im.w = cairo_image_surface_get_width(im.s);
    im.h = cairo_image_surface_get_height(im.s);
    im.stride = cairo_image_surface_get_stride(im.s);
    im.px = cairo_image_surface_get_data(im.s);
    return im;
}

static unsigned char *
read_all(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    unsigned char *d;
    long n;
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    d = malloc((size_t)n);
    assert_int_equal(fread(d, 1, (size_t)n, f), (size_t)n);
    fclose(f);
    *size = (size_t)n;
    return d;
}

static bool
have_pdftoppm(void)
{
    return system("pdftoppm -v > /dev/null 2>&1") == 0;
}

/* dl on the W x H page as PNG, or as PDF rasterised by pdftoppm. */
static image_t
draw(const cf__dl_t *dl, cf_format_t format)
{
    cf__page_t pg;
    cf__buf_t out;
    cf_diag_t diag;
    image_t im;
    memset(&pg, 0, sizeof pg);
    memset(&out, 0, sizeof out);
    pg.width = page_w;
    pg.height = page_h;
    /* painted in PNG only, as CF_BACKGROUND_AUTO has it */
    pg.background = (cf_color_t){ 1, 1, 1, format == CF_FORMAT_PNG };
    cf_diag_clear(&diag);
    if (cf__format_render(format, dl, &pg, DPI, "far", NULL, &out, &diag)
        != CF_STATUS_OK)
        fail_msg("render: %s", diag.msg);
    if (format == CF_FORMAT_PNG) {
        im = decode_png(out.data, out.size);
    } else {
        char pdf[64], base[64], png[80], cmd[256];
        size_t size;
        unsigned char *d;
        FILE *f;
        snprintf(pdf, sizeof pdf, "far-%ld.pdf", (long)getpid());
        snprintf(base, sizeof base, "far-%ld", (long)getpid());
        snprintf(png, sizeof png, "%s.png", base);
        f = fopen(pdf, "wb");
        assert_non_null(f);
        assert_int_equal(fwrite(out.data, 1, out.size, f), out.size);
        fclose(f);
        snprintf(cmd, sizeof cmd, "pdftoppm -r %g -png -singlefile %s %s",
                 DPI, pdf, base);
        assert_int_equal(system(cmd), 0);
        d = read_all(png, &size);
        im = decode_png(d, size);
        free(d);
        remove(pdf);
        remove(png);
    }
    cf__buf_free(&out);
    return im;
}

static void
same_pixels(cf__dl_t *far, cf__dl_t *ref, cf_format_t format,
            const char *what)
{
    image_t a = draw(far, format), b = draw(ref, format);
    int big = 0, small = 0, ink = 0;
    assert_int_equal(a.w, b.w);
    assert_int_equal(a.h, b.h);
    for (int y = 0; y < a.h; y++)
        for (int x = 0; x < a.w; x++) {
            const unsigned char *p = a.px + y * a.stride + 4 * x,
                                *q = b.px + y * b.stride + 4 * x;
            int d = 0;
            for (int c = 0; c < 4; c++)
                d = abs(p[c] - q[c]) > d ? abs(p[c] - q[c]) : d;
            big += d > BIG_DIFF;
            small += d > SMALL_DIFF;
            ink += q[0] < 128 || q[1] < 128 || q[2] < 128;
        }
    if (big > 0 || small > a.w * a.h / 200 || ink == 0) {
        cairo_surface_write_to_png(a.s, "far-mine.png");
        cairo_surface_write_to_png(b.s, "far-ref.png");
        fail_msg("%s (%s): %d pixels differ by > %d, %d by > %d, %d of the "
                 "reference inked (far-mine.png, far-ref.png)", what,
                 format == CF_FORMAT_PNG ? "png" : "pdf", big, BIG_DIFF,
                 small, SMALL_DIFF, ink);
    }
    cairo_surface_destroy(a.s);
    cairo_surface_destroy(b.s);
}

/* A display list as the layout makes one: an element's group inside the
** page's clip (cairo 1.16's tagged PDF wants its content bounded). */
static void
begin(cf__dl_t *dl)
{
    static const double page[4] = { 0, 0, W, H };
    cf__dl_init(dl);
    cf__dl_clip(dl, page);
    cf__dl_group(dl, "path", 0);
}

static void
finish(cf__dl_t *dl)
{
    cf__dl_end(dl);
    cf__dl_unclip(dl);
}

/* far and ref (from begin) finished, compared in PNG and PDF, freed. */
static void
both_formats(cf__dl_t *far, cf__dl_t *ref, const char *what)
{
    finish(far);
    finish(ref);
    same_pixels(far, ref, CF_FORMAT_PNG, what);
    if (have_pdftoppm())
        same_pixels(far, ref, CF_FORMAT_PDF, what);
    cf__dl_free(far);
    cf__dl_free(ref);
}

/* The cubic c (8 numbers) as a path painted with p. */
static void
cubic(cf__dl_t *dl, const double *c, const cf__paint_t *p)
{
    cf__dl_path_begin(dl);
    cf__dl_move(dl, c[0], c[1]);
    cf__dl_curve(dl, c[2], c[3], c[4], c[5], c[6], c[7]);
    cf__dl_path_paint(dl, p);
}

/* A path through the n points of v (closed: and back), painted with p. */
static void
polyline(cf__dl_t *dl, const double *v, size_t n, bool closed,
         const cf__paint_t *p)
{
    cf__dl_path_begin(dl);
    cf__dl_move(dl, v[0], v[1]);
    for (size_t i = 1; i < n; i++)
        cf__dl_line(dl, v[2 * i], v[2 * i + 1]);
    if (closed)
        cf__dl_close(dl);
    cf__dl_path_paint(dl, p);
}

static cf__paint_t
stroke_paint(double width, const double *dash, size_t ndash)
{
    cf__paint_t p;
    memset(&p, 0, sizeof p);
    p.stroke = true;
    p.line.color = (cf_color_t){ 0.7, 0.1, 0.1, 1 };
    p.line.opacity = 1;
    p.line.width = width;
    p.line.join = CF__JOIN_MITER;
    p.line.dash_count = ndash;
    for (size_t i = 0; i < ndash; i++)
        p.line.dash[i] = dash[i];
    return p;
}

/* How far along from a to b (a fraction) the line comes within CUT of the
** page, starting from a (a outside): bisection, the test's own way. */
static double
entry(const double a[2], const double b[2])
{
    double lo = 0, hi = 1;
    for (int i = 0; i < 200; i++) {
        double t = (lo + hi) / 2, x = a[0] + (b[0] - a[0]) * t,
               y = a[1] + (b[1] - a[1]) * t;
        bool out = x < -CUT || x > page_w + CUT || y < -CUT
                || y > page_h + CUT;
        if (out)
            lo = t;
        else
            hi = t;
    }
    return lo;
}

/* A line from far away (direction k of 16, some reaching up) to a point on
** the page, solid and dashed: the same as the line from where it comes
** within CUT of the page (at a whole number of dash periods from the far
** end). */
static void
test_far_lines(void **state)
{
    static const double dash[2] = { 6, 3 };
    (void)state;
    for (int k = 0; k < 16; k++)
        for (int dashed = 0; dashed < 2; dashed++) {
            double ang = k * 2 * PI / 16 + 0.1;
            double a[4] = { W / 2 + FAR * cos(ang), H / 2 + FAR * sin(ang),
                            W * 0.4, H * 0.6 }, *b = a + 2, t, len, c[4];
            cf__paint_t p = stroke_paint(2, dash, dashed ? 2 : 0);
            cf__dl_t far, ref;
            char what[64];
            t = entry(a, b);
            len = hypot(b[0] - a[0], b[1] - a[1]);
            if (dashed)
                t = floor(t * len / 9) * 9 / len;
            c[0] = a[0] + (b[0] - a[0]) * t;
            c[1] = a[1] + (b[1] - a[1]) * t;
            c[2] = b[0];
            c[3] = b[1];
            begin(&far);
            begin(&ref);
            polyline(&far, a, 2, false, &p);
            polyline(&ref, c, 2, false, &p);
            snprintf(what, sizeof what, "line %d%s", k,
                     dashed ? " dashed" : "");
                     both_formats(&far, &ref, what);
        }
}

/* A line across the whole page from far on one side to far on the other,
** through the page (its middle piece alone is drawn), and a polyline that
** leaves the page, turns far out and comes back (two runs; the dashes of
** the second keep their phase). */
static void
test_far_through(void **state)
{
    static const double dash[2] = { 5, 4 };
    double a[4] = { -FAR, -FAR * 0.3, FAR, FAR * 0.3 + 100 }, *b = a + 2;
    cf__paint_t p = stroke_paint(1.5, dash, 2);
    cf__dl_t far, ref;
    double t0, t1, len = hypot(b[0] - a[0], b[1] - a[1]), c[4];
    (void)state;
    t0 = floor(entry(a, b) * len / 9) * 9 / len;
    t1 = 1 - entry(b, a);
    c[0] = a[0] + (b[0] - a[0]) * t0;
    c[1] = a[1] + (b[1] - a[1]) * t0;
    c[2] = a[0] + (b[0] - a[0]) * t1;
    c[3] = a[1] + (b[1] - a[1]) * t1;
    begin(&far);
    begin(&ref);
    polyline(&far, a, 2, false, &p);
    polyline(&ref, c, 2, false, &p);
    both_formats(&far, &ref, "line through");

    /* out to (W/2, -FAR) and back: pieces of 3 + 2 FAR + ... bp */
    {
        double q[5][2] = { { 20, 100 }, { 60, 40 }, { 100, -FAR },
                           { 140, 40 }, { 180, 100 } };
        double l01 = hypot(q[1][0] - q[0][0], q[1][1] - q[0][1]),
               l12 = hypot(q[2][0] - q[1][0], q[2][1] - q[1][1]),
               l23 = hypot(q[3][0] - q[2][0], q[3][1] - q[2][1]);
        double out_t = entry(q[1], q[2]), back_t, s, skip, r[3][2],
               u[3][2];
        /* the first run ends CUT outside; the second starts where the
        ** length walked is a whole number of periods */
        back_t = 1 - entry(q[3], q[2]);
        s = l01 + l12 + l23 * back_t;
        skip = ceil(s / 9) * 9 - s;
        back_t += skip / l23;
        memcpy(r, q, 2 * sizeof r[0]);
        r[2][0] = q[1][0] + (q[2][0] - q[1][0]) * out_t;
        r[2][1] = q[1][1] + (q[2][1] - q[1][1]) * out_t;
        u[0][0] = q[2][0] + (q[3][0] - q[2][0]) * back_t;
        u[0][1] = q[2][1] + (q[3][1] - q[2][1]) * back_t;
        memcpy(u[1], q[3], 2 * sizeof u[0]);
        begin(&far);
        begin(&ref);
        polyline(&far, q[0], 5, false, &p);
        polyline(&ref, r[0], 3, false, &p);
        polyline(&ref, u[0], 3, false, &p);
        both_formats(&far, &ref, "polyline out and back");
    }
}

/* A closed outline with a vertex far up, stroked with miter joins: the
** same as the open path from where it comes back within CUT of the page,
** round its near vertices (the join where it was closed among them), to
** where it leaves. */
static void
test_far_closed(void **state)
{
    double v[4][2] = { { 40, 60 }, { 90, -FAR }, { 150, 60 }, { 100, 120 } };
    double ref_pts[6][2];
    cf__paint_t p = stroke_paint(4, NULL, 0);
    cf__dl_t far, ref;
    double t;
    (void)state;
    t = entry(v[1], v[2]);
    ref_pts[0][0] = v[1][0] + (v[2][0] - v[1][0]) * t;
    ref_pts[0][1] = v[1][1] + (v[2][1] - v[1][1]) * t;
    memcpy(ref_pts[1], v[2], sizeof v[2]);
    memcpy(ref_pts[2], v[3], sizeof v[3]);
    memcpy(ref_pts[3], v[0], sizeof v[0]);
    t = 1 - entry(v[1], v[0]);
    ref_pts[4][0] = v[0][0] + (v[1][0] - v[0][0]) * t;
    ref_pts[4][1] = v[0][1] + (v[1][1] - v[0][1]) * t;
    begin(&far);
    begin(&ref);
    polyline(&far, v[0], 4, true, &p);
    polyline(&ref, ref_pts[0], 5, false, &p);
    both_formats(&far, &ref, "closed outline");
}

/* The same outline dashed, its first point at a sharp corner where a dash
** runs in and one runs out (cairo's raster joins them there): against a
** closed outline that replaces the far vertex by a detour 100 bp outside
** the page as long, modulo the dash period, as the two far edges' parts
** it replaces; cairo draws that one whole, its join included.  PNG only:
** the join is a raster's (poppler joins neither outline), and poppler
** snaps the ends of strokes to pixels, so that dash ends 0.002 bp apart
** (the reference's own rounding to PDF's 1/256 bp) differ by a row. */
static void
test_far_closed_dashed(void **state)
{
    static const double dash[2] = { 6, 3 };
    double v[4][2] = { { 100, 40 }, { 40, -FAR }, { 30, 120 },
                       { 170, 120 } };
    double r[6][2], total = 0, d, far_part, want, h, nrm[2], m[2];
    cf__paint_t p = stroke_paint(3, dash, 2);
    cf__dl_t far, ref;
    (void)state;
    /* the last vertex moved until the end falls 1..5 bp into a dash */
    for (int tries = 0; tries < 40; tries++) {
        total = 0;
        for (int i = 0; i < 4; i++)
            total += hypot(v[(i + 1) % 4][0] - v[i][0],
                           v[(i + 1) % 4][1] - v[i][1]);
        if (fmod(total, 9) > 1 && fmod(total, 9) < 5)
            break;
        v[3][0] += 0.7;
    }
    assert_true(fmod(total, 9) > 1 && fmod(total, 9) < 5);
    memcpy(r[0], v[0], sizeof v[0]);
    /* where the edges to and from the far vertex are 100 bp outside */
    {
        double t = 1 - entry(v[1], v[0]), u = entry(v[1], v[2]);
        r[1][0] = v[0][0] + (v[1][0] - v[0][0]) * t;
        r[1][1] = v[0][1] + (v[1][1] - v[0][1]) * t;
        r[3][0] = v[1][0] + (v[2][0] - v[1][0]) * u;
        r[3][1] = v[1][1] + (v[2][1] - v[1][1]) * u;
    }
    far_part = hypot(v[1][0] - r[1][0], v[1][1] - r[1][1])
             + hypot(r[3][0] - v[1][0], r[3][1] - v[1][1]);
    d = hypot(r[3][0] - r[1][0], r[3][1] - r[1][1]);
    want = d + fmod(far_part - d, 9) + 9;
    /* the detour: out from the middle of the cut, up (away from the
    ** page), as long as want */
    h = sqrt(want * want / 4 - d * d / 4);
    m[0] = (r[1][0] + r[3][0]) / 2;
    m[1] = (r[1][1] + r[3][1]) / 2;
    nrm[0] = -(r[3][1] - r[1][1]) / d;
    nrm[1] = (r[3][0] - r[1][0]) / d;
    if (nrm[1] > 0) {
        nrm[0] = -nrm[0];
        nrm[1] = -nrm[1];
    }
    r[2][0] = m[0] + nrm[0] * h;
    r[2][1] = m[1] + nrm[1] * h;
    memcpy(r[4], v[2], sizeof v[2]);
    memcpy(r[5], v[3], sizeof v[3]);
    begin(&far);
    begin(&ref);
    polyline(&far, v[0], 4, true, &p);
    polyline(&ref, r[0], 6, true, &p);
    finish(&far);
    finish(&ref);
    same_pixels(&far, &ref, CF_FORMAT_PNG, "closed outline dashed");
    cf__dl_free(&far);
    cf__dl_free(&ref);
}

/* ---- fills -------------------------------------------------------------- */

/* Sutherland-Hodgman: polygon v (n points) clipped to the box CUT round
** the page; the result in out (at most 2 n + 8 points), its count. */
static size_t
clip_side(const double *v, size_t n, int side, double *out)
{
    size_t m = 0;
    double lim[4] = { -CUT, -CUT, W + CUT, H + CUT };
    for (size_t i = 0; i < n; i++) {
        const double *p = v + 2 * i, *q = v + 2 * ((i + 1) % n);
        int ax = side % 2;
        bool pin = side < 2 ? p[ax] >= lim[side] : p[ax] <= lim[side],
             qin = side < 2 ? q[ax] >= lim[side] : q[ax] <= lim[side];
        if (pin) {
            out[m++] = p[0];
            out[m++] = p[1];
        }
        if (pin != qin) {
            double t = (lim[side] - p[ax]) / (q[ax] - p[ax]);
            out[m++] = p[0] + (q[0] - p[0]) * t;
            out[m++] = p[1] + (q[1] - p[1]) * t;
            out[m - 2 + ax] = lim[side];
        }
    }
    return m / 2;
}

static size_t
sutherland_hodgman(const double *v, size_t n, double *out)
{
    double a[64], b[64];
    memcpy(a, v, 2 * n * sizeof *v);
    for (int side = 0; side < 4; side++) {
        n = clip_side(a, n, side, b);
        memcpy(a, b, 2 * n * sizeof *b);
    }
    memcpy(out, a, 2 * n * sizeof *a);
    return n;
}

/* Far polygons: a triangle with a vertex far up, a star whose points
** reach far out on every side (self-overlapping: winding 2 inside), and a
** quadrilateral larger than the page round it. */
static const double polys[][12] = {
    { W * 0.2, H * 0.8, W * 0.5, -FAR, W * 0.8, H * 0.7 },
    { -FAR, H * 0.4, FAR, H * 0.5, W * 0.3, FAR, W * 0.5, -FAR, W * 0.7,
      FAR },
    { -FAR, -FAR * 0.9, FAR * 1.1, -FAR, FAR, FAR, -FAR * 0.8, FAR * 1.2 },
};
static const size_t poly_n[] = { 3, 5, 4 };

static void
test_far_fills(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof poly_n / sizeof *poly_n; k++) {
        double cut[64];
        size_t n = sutherland_hodgman(polys[k], poly_n[k], cut);
        cf__paint_t p;
        cf__dl_t far, ref;
        char what[32];
        memset(&p, 0, sizeof p);
        p.fill = true;
        p.fill_color = (cf_color_t){ 0.1, 0.3, 0.8, 1 };
        p.fill_opacity = 0.8;
        begin(&far);
        begin(&ref);
        polyline(&far, polys[k], poly_n[k], true, &p);
        polyline(&ref, cut, n, true, &p);
        snprintf(what, sizeof what, "fill %zu", k);
        both_formats(&far, &ref, what);
    }
}

/* The cut path drawn by cairo straight from cf__far_fill, under each fill
** rule, against the Sutherland-Hodgman polygon (even-odd: the star's
** middle, wound twice, is empty). */
static void
s_move(void *c, double x, double y) { cairo_move_to(c, x, y); }
static void
s_line(void *c, double x, double y) { cairo_line_to(c, x, y); }
static void
s_curve(void *c, double a, double b, double d, double e, double x, double y)
{
    cairo_curve_to(c, a, b, d, e, x, y);
}
static void
s_arc(void *c, double x, double y, double r, double a0, double a1)
{
    cairo_arc(c, x, y, r, a0, a1);
}
static void
s_close(void *c) { cairo_close_path(c); }

static cairo_surface_t *
rule_raster(size_t k, cairo_fill_rule_t rule, bool mine)
{
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_A8, 420,
                                                    320);
    cairo_t *cr = cairo_create(s);
    cairo_scale(cr, DPI / 72, DPI / 72);
    cairo_set_fill_rule(cr, rule);
    if (mine) {
        unsigned char segs[6] = { CF__SEG_MOVE, CF__SEG_LINE, CF__SEG_LINE,
                                  CF__SEG_LINE, CF__SEG_LINE, CF__SEG_CLOSE };
        cf__path_t path = { segs, polys[k], poly_n[k] };
        cf__far_sink_t sink = { s_move, s_line, s_curve, s_arc, s_close, cr };
        cf__far_frame_t fr;
        cairo_matrix_t m;
        double ext[4];
        cf__far_ctm_t ctm;
        segs[poly_n[k]] = CF__SEG_CLOSE;
        path.nsegs = poly_n[k] + 1;
        cairo_get_matrix(cr, &m);
        ctm = (cf__far_ctm_t){ m.xx, m.yx, m.xy, m.yy, m.x0, m.y0 };
        assert_false(cf__far_safe(&path, &ctm));
        cairo_clip_extents(cr, &ext[0], &ext[1], &ext[2], &ext[3]);
        assert_true(cf__far_frame(&ctm, ext, &fr));
        cf__far_fill(&path, &fr, &sink);
    } else {
        double cut[64];
        size_t n = sutherland_hodgman(polys[k], poly_n[k], cut);
        cairo_move_to(cr, cut[0], cut[1]);
        for (size_t i = 1; i < n; i++)
            cairo_line_to(cr, cut[2 * i], cut[2 * i + 1]);
        cairo_close_path(cr);
    }
    cairo_fill(cr);
    cairo_destroy(cr);
    cairo_surface_flush(s);
    return s;
}

static void
test_fill_rules(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof poly_n / sizeof *poly_n; k++)
        for (int r = 0; r < 2; r++) {
            cairo_fill_rule_t rule = r ? CAIRO_FILL_RULE_EVEN_ODD
                                       : CAIRO_FILL_RULE_WINDING;
            cairo_surface_t *a = rule_raster(k, rule, true),
                            *b = rule_raster(k, rule, false);
            const unsigned char *p = cairo_image_surface_get_data(a),
                                *q = cairo_image_surface_get_data(b);
            int st = cairo_image_surface_get_stride(a), big = 0, in = 0;
            for (int y = 0; y < 320; y++)
                for (int x = 0; x < 420; x++) {
                    big += abs(p[y * st + x] - q[y * st + x]) > BIG_DIFF;
                    in += q[y * st + x] == 255;
                }
            if (big > 0 || in == 0)
                fail_msg("fill %zu, %s: %d pixels differ, %d inside", k,
                         r ? "even-odd" : "nonzero", big, in);
            cairo_surface_destroy(a);
            cairo_surface_destroy(b);
        }
}

/* ---- curves ------------------------------------------------------------- */

static void
bez(const double *c, double t, double *p)
{
    double s = 1 - t;
    for (int k = 0; k < 2; k++)
        p[k] = s * s * s * c[k] + 3 * s * s * t * c[2 + k]
             + 3 * s * t * t * c[4 + k] + t * t * t * c[6 + k];
}

/* The part [t0, t1] of cubic c (8 numbers) as a cubic: blossoming. */
static void
sub_curve(const double *c, double t0, double t1, double *out)
{
    double u[3][3] = { { t0, t0, t0 }, { t0, t0, t1 }, { t0, t1, t1 } };
    bez(c, t0, out);
    bez(c, t1, out + 6);
    for (int i = 1; i < 3; i++)
        for (int k = 0; k < 2; k++) {
            /* blossom f(u0, u1, u2) by de Casteljau with the three */
            double q[8];
            memcpy(q, c, sizeof q);
            for (int l = 0; l < 3; l++)
                for (int j = 0; j < 3 - l; j++)
                    for (int m = 0; m < 2; m++)
                        q[2 * j + m] = (1 - u[i][l]) * q[2 * j + m]
                                     + u[i][l] * q[2 * j + 2 + m];
            out[2 * i + k] = q[k];
        }
}

/* A cubic with its middle far up (controls at -FAR), and one whose
** controls lie at 1e300: drawn as the parts of it within CUT of the page,
** found by bisection and cut out by blossoming. */
static void
test_far_curve(void **state)
{
    double c[8] = { W * 0.2, H * 0.7, W * 0.2, -FAR, W * 0.8, -FAR, W * 0.8,
                    H * 0.7 };
    double ends[2][2] = { { 0, 0 }, { 0, 0 } };
    cf__paint_t p = stroke_paint(2, NULL, 0);
    cf__dl_t far, ref;
    (void)state;
    /* the parameters where it leaves the box: near 0 and near 1 */
    for (int e = 0; e < 2; e++) {
        double lo = e ? 0.5 : 0, hi = e ? 1 : 0.5;
        for (int i = 0; i < 200; i++) {
            double t = (lo + hi) / 2, q[2];
            bez(c, t, q);
            bool out = q[1] < -CUT;
            if (out == (e == 0))
                hi = t;
            else
                lo = t;
        }
        ends[e][0] = e ? lo : 0;
        ends[e][1] = e ? 1 : hi;
    }
    begin(&far);
    begin(&ref);
    cubic(&far, c, &p);
    for (int e = 0; e < 2; e++) {
        double s[8];
        sub_curve(c, ends[e][0], ends[e][1], s);
        cubic(&ref, s, &p);
    }
    both_formats(&far, &ref, "far cubic");

    /* from the page straight up to controls at 1e300: its part up to
    ** where it leaves (t about 1e-297, found by 1100 bisections) */
    {
        double d[8] = { W * 0.3, H * 0.6, W * 0.5, -1e300, 1e300, -1e300,
                        1e300, 0 }, lo = 0, hi = 0.5, sub[8];
        for (int i = 0; i < 1100; i++) {
            double t = (lo + hi) / 2, q[2];
            bez(d, t, q);
            if (q[1] < -CUT)
                hi = t;
            else
                lo = t;
        }
        assert_true(hi > 0 && hi < 1e-290);
        sub_curve(d, 0, hi, sub);
        begin(&far);
        begin(&ref);
        cubic(&far, d, &p);
        cubic(&ref, sub, &p);
        both_formats(&far, &ref, "cubic to 1e300");
    }
}

/* A path within the safe region (-32768..65536 device units) is drawn as
** it is; a circle of radius 1e6 bp round a point below the page draws its
** arc through the page alone. */
static void
test_safe_and_odd(void **state)
{
    cf__far_ctm_t m = { DPI / 72, 0, 0, DPI / 72, 0, 0 };
    unsigned char segs[3] = { CF__SEG_MOVE, CF__SEG_LINE, CF__SEG_ARC };
    double v[9] = { -1000, -1000, 20000, 20000, 100, 100, 10, 0, 6 };
    cf__path_t p = { segs, v, 3 };
    (void)state;
    assert_true(cf__far_safe(&p, &m));
    v[2] = 40000;
    assert_false(cf__far_safe(&p, &m));
    /* the circle: its top crosses the page */
    {
        cf__dl_t far, ref;
        cf__paint_t pt = stroke_paint(2, NULL, 0);
        double r = 1e6, cy = H / 2 + r;
        begin(&far);
        begin(&ref);
        cf__dl_path_begin(&far);
        cf__dl_arc(&far, W / 2, cy, r, 0, 2 * PI);
        cf__dl_path_paint(&far, &pt);
        /* the reference: the arc's part near the page (its angle within
        ** 1e-3 of straight up, 1000 bp either side) */
        cf__dl_path_begin(&ref);
        cf__dl_arc(&ref, W / 2, cy, r, 1.5 * PI - 1e-3, 1.5 * PI + 1e-3);
        cf__dl_path_paint(&ref, &pt);
        both_formats(&far, &ref, "arc of radius 1e6");
    }
}

/* The case of docs/robustness.md: an arrow from (1e5, 1e5) to (0.5, 0.5)
** in a unit window on a fixed page that clips (its shaft 2e7 device units
** long at 150 dpi), drawn from the display list the layout makes, against
** the same list with the shaft's far end moved by the test to where the
** shaft comes within CUT of the page. */
static void
test_far_arrow_figure(void **state)
{
    cf_figure_t *fig = NULL;
    cf__layout_t lay;
    cf__dl_t dl;
    image_t far[2];
    size_t moved = 0;
    int nf = have_pdftoppm() ? 2 : 1;
    (void)state;
    assert_int_equal(cf_figure_create(60, 40, CF_UNIT_MM, &fig, NULL), 0);
    assert_int_equal(cf_figure_set_window(fig, 0, 1, 0, 1), 0);
    assert_int_equal(cf_figure_set_page_mode(fig, CF_PAGE_FIXED), 0);
    assert_int_equal(cf_figure_set_clip(fig, true), 0);
    assert_int_equal(cf_figure_add_arrow(fig, 1e5, 1e5, 0.5 - 1e5,
                                         0.5 - 1e5, NULL), 0);
    cf_figure_get_size(fig, &page_w, &page_h);
    cf__dl_init(&dl);
    assert_int_equal(cf__figure_layout(fig, &lay), CF_STATUS_OK);
    assert_int_equal(cf__figure_build(fig, &lay, &dl), CF_STATUS_OK);
    for (int f = 0; f < nf; f++)
        far[f] = draw(&dl, f ? CF_FORMAT_PDF : CF_FORMAT_PNG);
    /* the shaft: a far point, then the point it goes to */
    for (size_t i = 0; i + 3 < dl.ncoords; i += 2)
        if (fabs(dl.coords[i]) > 1e6 || fabs(dl.coords[i + 1]) > 1e6) {
            double t = entry(dl.coords + i, dl.coords + i + 2);
            double *a = dl.coords + i, *b = dl.coords + i + 2;
            a[0] += (b[0] - a[0]) * t;
            a[1] += (b[1] - a[1]) * t;
            moved++;
        }
    assert_int_equal(moved, 1);
    for (int f = 0; f < nf; f++) {
        image_t ref = draw(&dl, f ? CF_FORMAT_PDF : CF_FORMAT_PNG);
        int big = 0, ink = 0;
        for (int y = 0; y < ref.h; y++)
            for (int x = 0; x < ref.w; x++) {
                const unsigned char *p = far[f].px + y * far[f].stride
                                       + 4 * x,
                                    *q = ref.px + y * ref.stride + 4 * x;
                for (int c = 0; c < 3; c++)
                    big += abs(p[c] - q[c]) > BIG_DIFF;
                ink += q[1] < 128;
            }
        if (big > 0 || ink < 100)
            fail_msg("arrow figure (%s): %d values differ, %d inked",
                     f ? "pdf" : "png", big, ink);
        cairo_surface_destroy(ref.s);
    }
    for (int f = 0; f < nf; f++)
        cairo_surface_destroy(far[f].s);
    cf__dl_free(&dl);
    cf_figure_destroy(fig);
    page_w = W;
    page_h = H;
}

/* Counts what a cut sends, and keeps the last segment's ends. */
typedef struct tally {
    size_t n;
    double from[2], to[2];
} tally_t;

static void
t_move(void *c, double x, double y)
{
    tally_t *t = c;
    t->n++;
    t->to[0] = x;
    t->to[1] = y;
}

static void
t_line(void *c, double x, double y)
{
    tally_t *t = c;
    t->from[0] = t->to[0];
    t->from[1] = t->to[1];
    t_move(c, x, y);
}

static void
t_curve(void *c, double a, double b, double d, double e, double x, double y)
{
    (void)a;
    (void)b;
    (void)d;
    (void)e;
    t_line(c, x, y);
}

static void
t_arc(void *c, double x, double y, double r, double a0, double a1)
{
    (void)r;
    (void)a0;
    (void)a1;
    t_line(c, x, y);
}

static void
t_close(void *c)
{
    ((tally_t *)c)->n++;
}

/* Lines between (-1e300, -1e300) and (1e300, 1e300), solid, dashed and
** filled, are cut in a few dozen segments, the stroke's on the line
** y = x itself (halving, not intersecting: no cancellation); a path with
** a NaN or an infinity (refused upstream) ends too, sending nothing
** wrong. */
static void
test_extremes(void **state)
{
    static const double dash[2] = { 3, 2 };
    unsigned char segs[3] = { CF__SEG_MOVE, CF__SEG_LINE, CF__SEG_LINE };
    double v[6] = { -1e300, -1e300, 1e300, 1e300, -1e300, 1e300 };
    cf__path_t p = { segs, v, 2 };
    cf__far_ctm_t m = { DPI / 72, 0, 0, DPI / 72, 0, 0 };
    double ext[4] = { 0, 0, W, H };
    cf__far_frame_t fr;
    (void)state;
    assert_true(cf__far_frame(&m, ext, &fr));
    assert_false(cf__far_safe(&p, &m));
    for (int k = 0; k < 3; k++) {
        tally_t t = { 0, { 0, 0 }, { 0, 0 } };
        cf__far_sink_t sink = { t_move, t_line, t_curve, t_arc, t_close, &t };
        cf__paint_t pt = stroke_paint(1, dash, k == 1 ? 2 : 0);
        if (k == 2) {
            p.nsegs = 3;
            cf__far_fill(&p, &fr, &sink);
        } else {
            assert_true(cf__far_stroke(&p, &fr, &pt.line, &sink));
            assert_true(t.from[0] == t.from[1] && t.to[0] == t.to[1]);
            assert_true(t.to[0] > W + 100 && t.to[0] < 1e6);
        }
        assert_true(t.n >= 2 && t.n < 100);
    }
    /* a polyline of 1000 such lines, back and forth through the page:
    ** a few segments each (the far part of a line with one end near is
    ** dropped at once, the clamped points along one side merged) */
    {
        enum { N = 1000 };
        static unsigned char zs[N];
        static double zv[2 * N];
        cf__path_t z = { zs, zv, N };
        for (int i = 0; i < N; i++) {
            zs[i] = i == 0 ? CF__SEG_MOVE : CF__SEG_LINE;
            zv[2 * i] = i % 2 == 1 ? 1e300 : -1e300;
            zv[2 * i + 1] = 50 + i % 7;
        }
        for (int k = 0; k < 2; k++) {
            tally_t t = { 0, { 0, 0 }, { 0, 0 } };
            cf__far_sink_t sink = { t_move, t_line, t_curve, t_arc, t_close,
                                    &t };
            cf__paint_t pt = stroke_paint(1, dash, 2);
            if (k == 0)
                assert_true(cf__far_stroke(&z, &fr, &pt.line, &sink));
            else
                cf__far_fill(&z, &fr, &sink);
            assert_true(t.n > N && t.n < 8 * N);
        }
    }
    v[1] = NAN;
    v[2] = INFINITY;
    for (int k = 0; k < 2; k++) {
        tally_t t = { 0, { 0, 0 }, { 0, 0 } };
        cf__far_sink_t sink = { t_move, t_line, t_curve, t_arc, t_close, &t };
        cf__paint_t pt = stroke_paint(1, NULL, 0);
        if (k == 0)
            assert_true(cf__far_stroke(&p, &fr, &pt.line, &sink));
        else
            cf__far_fill(&p, &fr, &sink);
        assert_true(t.n < 100);
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_far_lines),
        cmocka_unit_test(test_far_through),
        cmocka_unit_test(test_far_closed),
        cmocka_unit_test(test_far_closed_dashed),
        cmocka_unit_test(test_far_fills),
        cmocka_unit_test(test_fill_rules),
        cmocka_unit_test(test_far_curve),
        cmocka_unit_test(test_safe_and_odd),
        cmocka_unit_test(test_far_arrow_figure),
        cmocka_unit_test(test_extremes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
