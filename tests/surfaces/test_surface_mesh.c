/*
** Smooth shading as a mesh gradient (render/dlist/dlist.h, MESH), on the
** shaded surface of revolution (figures/surfaces/revolution.lua):
**
**   pdf     the PDF holds one shading of type 7 (tensor-product patches,
**           which cairo writes) whose data is a whole number of patches
**           of the size its dictionary declares, one patch per mesh
**           triangle of the display list; the PostScript likewise names
**           a shading of type 7;
**   svg     the SVG has no mesh: the same triangles as flat pieces, four
**           a triangle (less the few of no area), and no trace of a
**           gradient;
**   raster  the mesh drawn by cairo agrees with the flat pieces drawn by
**           cairo (the same display list, played to a copy of the cairo
**           backend without mesh gradients) inside the surface, within
**           the difference of the colours themselves: a pixel of the mesh
**           is a linear mix of its triangle's corner colours, a pixel of
**           the pieces the colour at a piece's centroid, so the two differ
**           by at most the largest difference between a triangle's corner
**           and piece colours (measured here from the display list), plus
**           1/255 for rounding (all but 0.5 % of the pixels: a fold's
**           seam inside the surface is anti-aliased differently), and
**           99 % of them within the 99th percentile of the triangles'
**           own differences + 1/255; the mean difference below 2/255.
**           Pixels near an edge (anti-aliasing, the pieces' hairlines
**           reach 0.125 bp beyond them) are left out;
**   dlist   consecutive mesh triangles are one MESH operation (a path
**           ends it), a backend with mesh gradients receives them whole,
**           one without receives four flat pieces a triangle covering it,
**           and a mesh moved into a panel's cell moves its corners.
*/
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <cairo.h>
#include <zlib.h>

#include "backend.h"
#include "backend-text.h"
#include "layout-private.h"
#include "output-private.h"
#include "script.h"

#define SCRIPT CF_SOURCE_ROOT "/figures/surfaces/revolution.lua"
#define RES 2.0   /* raster pixels per bp (144 dpi, as the pixel tests) */

typedef struct fixture {
    cf_script_t *sc;
    cf_figure_t *fig;
    cf__dl_t dl;
    size_t ntri;         /* mesh triangles in the display list */
} fixture_t;

static int
setup(void **state)
{
    fixture_t *fx = calloc(1, sizeof *fx);
    cf__layout_t lay;
    assert_non_null(fx);
    assert_int_equal(cf_script_create(NULL, NULL, &fx->sc, NULL), 0);
    if (cf_script_run_file(fx->sc, SCRIPT) != CF_STATUS_OK)
        fail_msg("%s: %s", SCRIPT, cf_script_error(fx->sc));
    fx->fig = cf_script_figure(fx->sc, 0);
    cf__dl_init(&fx->dl);
    assert_int_equal(cf__figure_layout(fx->fig, &lay), CF_STATUS_OK);
    assert_int_equal(cf__figure_build(fx->fig, &lay, &fx->dl), CF_STATUS_OK);
    for (size_t i = 0; i < fx->dl.count; i++)
        if (fx->dl.ops[i].kind == CF__OP_MESH)
            fx->ntri += fx->dl.ops[i].u.mesh.ntri;
    assert_true(fx->ntri > 500);
    *state = fx;
    return 0;
}

static int
teardown(void **state)
{
    fixture_t *fx = *state;
    cf__dl_free(&fx->dl);
    cf_script_destroy(fx->sc);
    free(fx);
    return 0;
}

/* The display list as a file of the format, in memory (NUL-terminated). */
static char *
render(const fixture_t *fx, cf_format_t format, size_t *size)
{
    cf__page_t page;
    cf__buf_t out;
    char *text;
    memset(&page, 0, sizeof page);
    memset(&out, 0, sizeof out);
    cf_figure_get_size(fx->fig, &page.width, &page.height);
    assert_int_equal(cf__format_render(format, &fx->dl, &page, 144.0, NULL,
                                       NULL, &out, NULL), CF_STATUS_OK);
    text = malloc(out.size + 1);
    assert_non_null(text);
    memcpy(text, out.data, out.size);
    text[out.size] = '\0';
    *size = out.size;
    cf__buf_free(&out);
    return text;
}

static long
dict_int(const char *dict, const char *end, const char *key)
{
    const char *p = strstr(dict, key);
    if (p == NULL || p > end)
        return -1;
    return strtol(p + strlen(key), NULL, 10);
}

static void
test_pdf(void **state)
{
    fixture_t *fx = *state;
    size_t size, shadings = 0;
    char *pdf = render(fx, CF_FORMAT_PDF, &size);
    for (const char *p = pdf; (p = memmem(p, size - (size_t)(p - pdf),
                                          "/ShadingType", 12)) != NULL;
         p++) {
        const char *end = memmem(p, size - (size_t)(p - pdf), "stream", 6);
        long type = dict_int(p, end, "/ShadingType "),
             bc = dict_int(p, end, "/BitsPerCoordinate "),
             bk = dict_int(p, end, "/BitsPerComponent "),
             bf = dict_int(p, end, "/BitsPerFlag "),
             len = dict_int(p, end, "/Length ");
        assert_non_null(end);
        assert_true(type == 4 || type == 6 || type == 7);
        assert_true(bc > 0 && bk > 0 && bf > 0 && len > 0);
        /* a triangle of a free-form shading (type 4, the PDF writer's):
        ** 3 vertices of a flag, a point and an RGB colour; a patch (6,
        ** 7): its flag, 12 or 16 points, 4 RGB colours (whole bytes for
        ** these sizes) */
        long pts = type == 6 ? 12 : 16;
        long patch = type == 4 ? 3 * (bf + 2 * bc + 3 * bk) / 8
                               : (bf + pts * 2 * bc + 4 * 3 * bk) / 8;
        const unsigned char *data = (const unsigned char *)end + 6;
        if (*data == '\r')
            data++;
        if (*data == '\n')
            data++;
        long nbytes = len;
        unsigned char *raw = NULL;
        const char *filter = strstr(p, "/FlateDecode");
        if (filter != NULL && filter < end) {
            uLongf out = (uLongf)(patch * (long)(2 * fx->ntri) + 1);
            raw = malloc(out);
            assert_non_null(raw);
            assert_int_equal(uncompress(raw, &out, data, (uLong)len), Z_OK);
            nbytes = (long)out;
        }
        print_message("shading of type %ld: %ld bytes, %ld pieces of %ld; "
                      "%zu mesh triangles\n", type, nbytes, nbytes / patch,
                      patch, fx->ntri);
        assert_int_equal(nbytes % patch, 0);
        assert_int_equal((size_t)(nbytes / patch), fx->ntri);
        free(raw);
        shadings++;
    }
    assert_int_equal(shadings, 1);
    free(pdf);
    char *ps = render(fx, CF_FORMAT_PS, &size);
    assert_non_null(strstr(ps, "/ShadingType 7"));
    free(ps);
}

static void
test_svg(void **state)
{
    fixture_t *fx = *state;
    size_t size, pieces = 0;
    char *svg = render(fx, CF_FORMAT_SVG, &size);
    assert_null(strstr(svg, "mesh"));
    assert_null(strstr(svg, "Gradient"));
    /* the pieces: closed paths of one move and two lines */
    for (const char *p = strstr(svg, " d=\"M"); p != NULL;
         p = strstr(p + 1, " d=\"M")) {
        const char *q = strchr(p + 4, '"');
        size_t ls = 0, other = 0;
        for (const char *c = p + 5; c < q; c++) {
            if (*c == 'L')
                ls++;
            else if (*c == 'C' || *c == 'M' || *c == 'H' || *c == 'V')
                other++;
        }
        pieces += ls == 2 && other == 0 && q[-1] == 'Z';
    }
    print_message("%zu flat pieces for %zu mesh triangles\n", pieces,
                  fx->ntri);
    assert_true(pieces <= 4 * fx->ntri);
    assert_true(pieces >= 4 * fx->ntri - fx->ntri / 50);
    free(svg);
}

static uint32_t
pixel(cairo_surface_t *s, int x, int y)
{
    const unsigned char *d = cairo_image_surface_get_data(s);
    uint32_t v;
    memcpy(&v, d + (size_t)y * (size_t)cairo_image_surface_get_stride(s)
                   + 4 * (size_t)x, 4);
    return v;
}

static cairo_surface_t *
draw(const cf__dl_t *dl, const cf__backend_t *be, int w, int h)
{
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w,
                                                    h);
    cairo_t *cr = cairo_create(s);
    cairo_scale(cr, RES, RES);
    cf__dl_play(dl, 0, dl->count, be, cr);
    assert_int_equal(cairo_status(cr), CAIRO_STATUS_SUCCESS);
    cairo_destroy(cr);
    cairo_surface_flush(s);
    return s;
}

static int
channel_diff(uint32_t a, uint32_t b)
{
    int d = 0;
    for (int k = 0; k < 32; k += 8)
        d = fmax(d, abs((int)((a >> k) & 255) - (int)((b >> k) & 255)));
    return d;
}

static int
by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void
test_raster(void **state)
{
    fixture_t *fx = *state;
    cf__backend_t flat = cf__cairo_backend;
    double pw, ph, bound = 0.0;
    flat.draw_mesh = NULL;
    cf_figure_get_size(fx->fig, &pw, &ph);
    int w = (int)ceil(pw * RES), h = (int)ceil(ph * RES);
    /* each triangle's largest difference between its corner colours and
    ** its pieces' colours, in 1/255: the largest of all, and the 99th
    ** percentile over the triangles */
    double *tb = malloc(fx->dl.ntris * sizeof *tb);
    assert_non_null(tb);
    for (size_t i = 0; i < fx->dl.ntris; i++) {
        const cf__mesh_tri_t *t = &fx->dl.tris[i];
        tb[i] = 0.0;
        for (int c = 0; c < 3; c++)
            for (int k = 0; k < 4; k++)
                tb[i] = fmax(tb[i], 255 * fmax(fabs(t->corner[c].r - t->piece[k].r),
                                    fmax(fabs(t->corner[c].g - t->piece[k].g),
                                         fabs(t->corner[c].b - t->piece[k].b))));
        bound = fmax(bound, tb[i]);
    }
    qsort(tb, fx->dl.ntris, sizeof *tb, by_value);
    double bound99 = tb[fx->dl.ntris * 99 / 100];
    free(tb);
    int tol = (int)ceil(bound) + 1;
    cairo_surface_t *a = draw(&fx->dl, &cf__cairo_backend, w, h),
                    *b = draw(&fx->dl, &flat, w, h);
    long inside = 0, worst = 0, over = 0, hist[256] = {0};
    double sum = 0;
    for (int y = 1; y + 1 < h; y++)
        for (int x = 1; x + 1 < w; x++) {
            bool opaque = true;
            /* inside: every pixel around opaque in both, and the pixel
            ** not on a line (lines are the same in both drawings) */
            for (int dy = -1; dy <= 1 && opaque; dy++)
                for (int dx = -1; dx <= 1 && opaque; dx++)
                    opaque = (pixel(a, x + dx, y + dy) >> 24) == 255
                          && (pixel(b, x + dx, y + dy) >> 24) == 255;
            if (!opaque)
                continue;
            int d = channel_diff(pixel(a, x, y), pixel(b, x, y));
            inside++;
            sum += d;
            worst = d > worst ? d : worst;
            over += d > tol;
            hist[d]++;
        }
    /* the 99th percentile of the differences */
    int p99 = 0;
    for (long acc = 0; p99 < 255 && (acc += hist[p99]) < inside * 99 / 100;)
        p99++;
    print_message("%ld pixels inside the surface: mean difference %.2f, "
                  "99th percentile %d (the triangles' %.1f), largest %ld, "
                  "%ld beyond %d/255 (the colours' own difference "
                  "%.1f/255 + 1)\n", inside, sum / (double)inside, p99,
                  bound99, worst, over, tol, bound);
    assert_true(inside > 20000);
    /* edges of folds inside the surface (front against back) and the
    ** lines' anti-aliased sides may differ on a thin seam: 0.5 % */
    assert_true((double)over <= 0.005 * (double)inside);
    assert_true(sum / (double)inside < 2.0);
    assert_true(p99 <= (int)ceil(bound99) + 1);
    cairo_surface_destroy(a);
    cairo_surface_destroy(b);
}

/* ---- the display list's meshes and the seam's stand-ins ----------------- */

typedef struct counts {
    size_t paths, meshes, tris;
    double x0;              /* first corner of the first mesh triangle */
    double area;            /* the flat pieces' areas */
} counts_t;

static void
count_path(void *ctx, const cf__path_t *p, const cf__paint_t *paint)
{
    counts_t *c = ctx;
    const double *q = p->coords;
    c->paths++;
    if (p->nsegs == 4 && paint->fill)
        c->area += 0.5 * fabs((q[2] - q[0]) * (q[5] - q[1])
                              - (q[4] - q[0]) * (q[3] - q[1]));
}

static void
count_text(void *ctx, const cf__text_op_t *t)
{
    (void)ctx;
    (void)t;
}

static void
count_mesh(void *ctx, const cf__mesh_tri_t *t, size_t n)
{
    counts_t *c = ctx;
    if (c->meshes++ == 0)
        c->x0 = t[0].p[0];
    c->tris += n;
}

static void
test_dlist_mesh(void **state)
{
    cf__backend_t flat = cf__text_backend("flat", count_text);
    cf__backend_t mesh;
    cf__mesh_tri_t t;
    cf__paint_t paint;
    cf__dl_t dl, moved;
    counts_t c;
    (void)state;
    memset(&t, 0, sizeof t);
    memset(&paint, 0, sizeof paint);
    paint.fill = true;
    flat.draw_path = count_path;
    flat.draw_mesh = NULL;
    mesh = flat;
    mesh.draw_mesh = count_mesh;
    /* a right triangle of legs 10 and 20 (area 100) */
    t.p[2] = 10;
    t.p[5] = 20;
    cf__dl_init(&dl);
    cf__dl_mesh_tri(&dl, &t);
    cf__dl_mesh_tri(&dl, &t);
    cf__dl_path_begin(&dl);
    cf__dl_rect(&dl, 0, 0, 1, 1);
    cf__dl_path_paint(&dl, &paint);
    cf__dl_mesh_tri(&dl, &t);
    assert_false(dl.failed);
    /* consecutive triangles are one mesh; a path ends it */
    assert_int_equal(dl.count, 3);
    assert_int_equal(dl.ops[0].kind, CF__OP_MESH);
    assert_int_equal(dl.ops[0].u.mesh.ntri, 2);
    assert_int_equal(dl.ops[2].u.mesh.ntri, 1);
    memset(&c, 0, sizeof c);
    cf__dl_play(&dl, 0, dl.count, &mesh, &c);
    assert_int_equal(c.meshes, 2);
    assert_int_equal(c.tris, 3);
    assert_int_equal(c.paths, 1);
    /* without mesh gradients: four pieces a triangle, covering it */
    memset(&c, 0, sizeof c);
    cf__dl_play(&dl, 0, dl.count, &flat, &c);
    assert_int_equal(c.paths, 3 * 4 + 1);
    assert_true(fabs(c.area - 3 * 100.0) < 1e-9);
    /* moved into a panel's cell */
    cf__dl_init(&moved);
    cf__dl_append_moved(&moved, &dl, 5.0, 7.0);
    assert_int_equal(moved.count, 3);
    assert_int_equal(moved.ntris, 3);
    memset(&c, 0, sizeof c);
    cf__dl_play(&moved, 0, moved.count, &mesh, &c);
    assert_true(c.x0 == 5.0);
    assert_true(moved.tris[2].p[5] == 27.0);
    cf__dl_free(&moved);
    cf__dl_free(&dl);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pdf),
        cmocka_unit_test(test_svg),
        cmocka_unit_test(test_raster),
        cmocka_unit_test(test_dlist_mesh),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
