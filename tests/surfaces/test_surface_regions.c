/*
** Filled regions in space among surfaces (tests/surfaces/regions/ and the
** tangent plane of figures/surfaces/tangent-plane.lua):
**
**   parts     points sampled densely in every region (a lattice in each
**             of its triangles; under an orthographic view also a grid
**             of the page every 3 bp) are painted as the independent ray
**             caster (tests/unit/raycast-ref.h) finds them: seen, in the
**             region's path at its opacity; hidden, in its faded path
**             (0.4 of it, hidden "dashed"), in no path ("remove") or in
**             the seen one ("show"), in the display list (nonzero rule,
**             the page map of the layout).  A sample that disagrees is
**             excused only when the ray caster's answer changes within
**             the stated tolerance of it on the page (the boundary is
**             found there), or the nearest surface on its line of sight
**             lies within the depth tolerance;
**   area      the seen and hidden parts of a region tile its image: their
**             areas add up to its triangles' images', and a hull's to
**             the plane hull of the images of its points;
**   pixels    the opaque fill between two shaded surfaces is in the PNG
**             where it is seen and not where the upper surface hides it
**             (away from the boundary by the same tolerance plus a pixel);
**   warn      a fill added before a shaded surface (under its shading):
**             a warning naming the fill, its line and the surface;
**   bad       a fill whose points lie on one line, a hull with hidden in a
**             figure without a view, and the C API without a view: errors
**             naming the cause.
*/
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cairo.h>
#include <cmocka.h>

#include "curvefig/figure3d.h"
#include "curvefig/geometry.h"
#include "curvefig/output.h"
#include "figure/region.h"
#include "pngtest.h"
#include "raycast-ref.h"
#include "script.h"
#include "surface-lines.h"

#define REGION_DIR CF_SOURCE_ROOT "/tests/surfaces/regions"

/* The library's visibility tolerance is 20 times the fitting tolerance
** (0.01 bp): 0.2 bp; its cells are 8 of it long and the change points on
** their edges are found to half of it.  A sample is judged farther than
** EXCUSE of them from the boundary on the page. */
#define VTOL_BP 0.2
#define EXCUSE 2.0
/* The samples' offset in a lattice cell: irrational, so no sample falls on
** the corners of the library's cells. */
#define OFF 0.3819660112501051

static cf_script_t *
run(const char *name)
{
    char path[1024];
    cf_script_t *sc = NULL;
    snprintf(path, sizeof path, "%s/%s", name[0] == '/' ? "" : REGION_DIR,
             name);
    assert_int_equal(cf_script_create(NULL, NULL, &sc, NULL), 0);
    if (cf_script_run_file(sc, path) != CF_STATUS_OK)
        fail_msg("%s: %s", path, cf_script_error(sc));
    return sc;
}

/* ---- the display list's paths of one element ---------------------------- */

typedef struct path {
    double *xy;              /* vertices */
    size_t *len;             /* per subpath */
    size_t n, nxy;
    double opacity;
} path_t;

typedef struct paths {
    path_t p[8];
    size_t n;
    char kind[16];           /* the group's element kind */
} paths_t;

/* The filled paths of group `el` in the dump (M, L and Z only). */
static void
group_paths(const char *text, size_t el, paths_t *out)
{
    char head[64];
    bool in = false;
    memset(out, 0, sizeof *out);
    snprintf(head, sizeof head, "group %zu ", el);
    for (const char *line = text; line != NULL && *line != '\0';) {
        const char *nl = strchr(line, '\n');
        if (strncmp(line, "group ", 6) == 0) {
            in = strncmp(line, head, strlen(head)) == 0;
            if (in)
                sscanf(line + strlen(head), "%15s", out->kind);
        }
        else if (in && strncmp(line, "path fill ", 10) == 0
                 && out->n < 8) {
            path_t *p = &out->p[out->n++];
            const char *s = line + 10;
            char *end;
            size_t cap = 1024, lcap = 64;
            for (int k = 0; k < 4; k++)     /* past the colour r g b a */
                strtod(s, (char **)&s);
            p->opacity = strtod(s, &end);
            s = strstr(end, " :") + 2;
            p->xy = malloc(cap * sizeof *p->xy);
            p->len = malloc(lcap * sizeof *p->len);
            while (s < (nl != NULL ? nl : s + strlen(s))) {
                while (*s == ' ')
                    s++;
                if (*s == 'M' || *s == 'L') {
                    if (*s == 'M') {
                        if (p->n == lcap)
                            p->len = realloc(p->len,
                                             (lcap *= 2) * sizeof *p->len);
                        p->len[p->n++] = 0;
                    }
                    if (p->nxy + 2 > cap)
                        p->xy = realloc(p->xy, (cap *= 2) * sizeof *p->xy);
                    p->xy[p->nxy] = strtod(s + 1, &end);
                    p->xy[p->nxy + 1] = strtod(end, &end);
                    p->nxy += 2;
                    p->len[p->n - 1]++;
                    s = end;
                } else if (*s == 'Z') {
                    s++;
                } else {
                    fail_msg("unexpected segment '%c' in a region's path",
                             *s);
                }
            }
        }
        line = nl != NULL ? nl + 1 : NULL;
    }
}

static void
paths_free(paths_t *ps)
{
    for (size_t i = 0; i < ps->n; i++) {
        free(ps->p[i].xy);
        free(ps->p[i].len);
    }
}

/* The winding number of the path about (x, y). */
static int
winding(const path_t *p, double x, double y)
{
    int w = 0;
    size_t at = 0;
    for (size_t s = 0; s < p->n; s++) {
        for (size_t i = 0; i < p->len[s]; i++) {
            const double *a = p->xy + 2 * (at + i);
            const double *b = p->xy + 2 * (at + (i + 1) % p->len[s]);
            double cr = (b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1]);
            if (a[1] <= y && b[1] > y && cr > 0)
                w++;
            else if (a[1] > y && b[1] <= y && cr < 0)
                w--;
        }
        at += p->len[s];
    }
    return w;
}

/* The absolute areas of the path's subpaths, added. */
static double
path_area(const path_t *p)
{
    double total = 0;
    size_t at = 0;
    for (size_t s = 0; s < p->n; s++) {
        double a = 0;
        for (size_t i = 0; i < p->len[s]; i++) {
            const double *u = p->xy + 2 * (at + i);
            const double *v = p->xy + 2 * (at + (i + 1) % p->len[s]);
            a += u[0] * v[1] - u[1] * v[0];
        }
        total += fabs(a) / 2;
        at += p->len[s];
    }
    return total;
}

/* ---- the truth ---------------------------------------------------------- */

static void
to_page(const cf_view_t *v, const double map[6], const double *x, double *q)
{
    double img[2];
    assert_int_equal(cf_view_project(v, x, img, NULL), 0);
    q[0] = map[0] * img[0] + map[2] * img[1] + map[4];
    q[1] = map[1] * img[0] + map[3] * img[1] + map[5];
}

/* 1 hidden, 0 seen, -1 within the depth tolerance (the nearest surface on
** the line of sight is between 0.25 and 3 tolerances in front). */
static int
truth(const rc_scene_t *rc, const double *x, double vtol)
{
    bool near = rc_hidden(rc, x, 0.25 * vtol, NULL);
    bool far = rc_hidden(rc, x, 3 * vtol, NULL);
    return near == far ? (int)far : -1;
}

/* The point of triangle t at (s, u) (barycentric of its 2nd, 3rd). */
static void
tri_point(const double *t, double s, double u, double *x)
{
    for (int k = 0; k < 3; k++)
        x[k] = t[k] + s * (t[3 + k] - t[k]) + u * (t[6 + k] - t[k]);
}

/* Whether the ray caster's answer changes (or is undecided) within r bp
** of sample (s, u) of triangle t on the page. */
static bool
near_boundary(const rc_scene_t *rc, const cf_view_t *v, const double map[6],
              const double *t, double s, double u, int here, double r,
              double vtol)
{
    double x[3], q[2], qs[2], qu[2], h = 1e-4, J[4], det;
    tri_point(t, s, u, x);
    to_page(v, map, x, q);
    tri_point(t, s + h, u, x);
    to_page(v, map, x, qs);
    tri_point(t, s, u + h, x);
    to_page(v, map, x, qu);
    J[0] = (qs[0] - q[0]) / h;
    J[1] = (qu[0] - q[0]) / h;
    J[2] = (qs[1] - q[1]) / h;
    J[3] = (qu[1] - q[1]) / h;
    det = J[0] * J[3] - J[1] * J[2];
    if (!(fabs(det) > 1e-12))
        return true;
    for (int ring = 1; ring <= 2; ring++)
        for (int k = 0; k < 16; k++) {
            double a = 2 * M_PI * k / 16, dx = ring * r / 2 * cos(a);
            double dy = ring * r / 2 * sin(a);
            double ds = (J[3] * dx - J[1] * dy) / det;
            double du = (-J[2] * dx + J[0] * dy) / det;
            tri_point(t, s + ds, u + du, x);
            if (truth(rc, x, vtol) != here)
                return true;
        }
    return false;
}

typedef struct tally {
    size_t checked, bad, excused;
} tally_t;

/* What one region is checked with. */
typedef struct region_ck {
    const rc_scene_t *rc;
    cf_view_t v;
    double map[6], vtol;
    cf_hidden_t hidden;
    const path_t *seen, *faded;
    size_t el;
    tally_t *t;
} region_ck_t;

/* Sample (s, u) of triangle tri against the ray caster. */
static void
check_sample(const region_ck_t *k, const double *tri, double s, double u)
{
    double x[3], q[2];
    int h, want_seen, want_faded, got_seen, got_faded;
    tri_point(tri, s, u, x);
    h = truth(k->rc, x, k->vtol);
    if (h < 0)
        return;
    to_page(&k->v, k->map, x, q);
    want_seen = k->hidden == CF_HIDDEN_SHOW || h == 0;
    want_faded = k->hidden == CF_HIDDEN_DASHED && h == 1;
    got_seen = k->seen != NULL && winding(k->seen, q[0], q[1]) != 0;
    got_faded = k->faded != NULL && winding(k->faded, q[0], q[1]) != 0;
    k->t->checked++;
    if (want_seen == got_seen && want_faded == got_faded)
        return;
    if (k->hidden != CF_HIDDEN_SHOW
        && near_boundary(k->rc, &k->v, k->map, tri, s, u, h,
                         EXCUSE * VTOL_BP, k->vtol)) {
        k->t->excused++;
        return;
    }
    if (k->t->bad < 5)
        print_message("element %zu: (%g, %g, %g) at page (%g, %g) is %s, "
                      "painted %s%s\n", k->el, x[0], x[1], x[2], q[0], q[1],
                      h ? "hidden" : "seen", got_seen ? "seen" : "",
                      got_faded ? "faded" : "");
    k->t->bad++;
}

/* Under an orthographic view, samples on a grid of the page every STEP bp
** too (a triangle far larger than the window is sampled where it shows):
** the point of each triangle whose image is there (the image's
** barycentric coordinates are the triangle's). */
#define STEP 3.0
static void
page_samples(const region_ck_t *k, const cf__tris_t *tris, double w,
             double h)
{
    double det = k->map[0] * k->map[3] - k->map[1] * k->map[2];
    if (k->v.projection == CF_PROJECTION_PERSPECTIVE)
        return;
    for (double py = OFF * STEP; py < h; py += STEP)
        for (double px = OFF * STEP; px < w; px += STEP) {
            /* the data point of the page point */
            double dx = px - k->map[4], dy = py - k->map[5], d[2];
            d[0] = (k->map[3] * dx - k->map[2] * dy) / det;
            d[1] = (-k->map[1] * dx + k->map[0] * dy) / det;
            for (size_t i = 0; i < tris->n; i++) {
                const double *tri = tris->p + 9 * i;
                double a[2], b[2], c[2], D, l1, l2;
                assert_int_equal(cf_view_project(&k->v, tri, a, NULL), 0);
                assert_int_equal(cf_view_project(&k->v, tri + 3, b, NULL), 0);
                assert_int_equal(cf_view_project(&k->v, tri + 6, c, NULL), 0);
                D = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
                if (!(fabs(D) > 0))
                    continue;
                l1 = ((d[0] - a[0]) * (c[1] - a[1])
                      - (c[0] - a[0]) * (d[1] - a[1])) / D;
                l2 = ((b[0] - a[0]) * (d[1] - a[1])
                      - (d[0] - a[0]) * (b[1] - a[1])) / D;
                if (l1 > 0 && l2 > 0 && l1 + l2 < 1)
                    check_sample(k, tri, l1, l2);
            }
        }
}

/* The samples of region element el against the ray caster. */
static void
check_region(cf_figure_t *fig, const rc_scene_t *rc, size_t el,
             const char *text, const double map[6], tally_t *t)
{
    const cf__tris_t *tris;
    double opacity, w, h;
    paths_t ps;
    region_ck_t k;
    enum { K = 24 };
    memset(&k, 0, sizeof k);
    k.rc = rc;
    k.el = el;
    k.t = t;
    memcpy(k.map, map, sizeof k.map);
    assert_true(cf__region_triangles(fig, el, &tris, &k.hidden, &opacity));
    assert_true(cf_figure_get_view(fig, &k.v));
    k.vtol = VTOL_BP / hypot(map[0], map[1]);
    group_paths(text, el, &ps);
    for (size_t i = 0; i < ps.n; i++) {
        if (fabs(ps.p[i].opacity - opacity) < 1e-9)
            k.seen = &ps.p[i];
        else if (fabs(ps.p[i].opacity - 0.4 * opacity) < 1e-9)
            k.faded = &ps.p[i];
        else
            fail_msg("element %zu: a path at opacity %g (the fill's is %g)",
                     el, ps.p[i].opacity, opacity);
    }
    if (k.hidden != CF_HIDDEN_DASHED)
        assert_null(k.faded);
    /* a lattice in each triangle, off the grid the library cuts (its
    ** points are at multiples of 1/k of the triangle: a sample on one of
    ** its polygons' corners decides nothing) */
    for (size_t i = 0; i < tris->n; i++)
        for (int a = 0; a < K; a++)
            for (int b = 0; a + b < K - 1; b++)
                check_sample(&k, tris->p + 9 * i, (a + OFF) / K,
                             (b + OFF) / K);
    cf_figure_get_size(fig, &w, &h);
    page_samples(&k, tris, w, h);
    /* the parts tile the region's image: the triangles' images (those of
    ** a plane region or a hull do not overlap), and for a hull the plane
    ** hull of its points' images */
    if (k.hidden == CF_HIDDEN_DASHED) {
        double *img, area = 0, got = 0, tri_area = 0;
        size_t n = 3 * tris->n, *idx, hn = 0;
        img = malloc(2 * n * sizeof *img);
        idx = malloc(n * sizeof *idx);
        for (size_t j = 0; j < n; j++)
            to_page(&k.v, map, tris->p + 3 * j, img + 2 * j);
        assert_int_equal(cf_convex_hull_2d(img, n, 2, idx, &hn, NULL), 0);
        for (size_t j = 0; j < hn; j++) {
            const double *pa = img + 2 * idx[j];
            const double *pb = img + 2 * idx[(j + 1) % hn];
            area += (pa[0] * pb[1] - pa[1] * pb[0]) / 2;
        }
        for (size_t j = 0; j < tris->n; j++) {
            const double *q = img + 6 * j;
            tri_area += fabs((q[2] - q[0]) * (q[5] - q[1])
                             - (q[4] - q[0]) * (q[3] - q[1])) / 2;
        }
        got = (k.seen != NULL ? path_area(k.seen) : 0)
            + (k.faded != NULL ? path_area(k.faded) : 0);
        print_message("element %zu (%s): parts %g bp^2, triangles %g bp^2, "
                      "hull of the points %g bp^2\n", el, ps.kind, got,
                      tri_area, fabs(area));
        assert_true(fabs(got - tri_area) <= 1e-6 * tri_area);
        if (strcmp(ps.kind, "hull") == 0)
            assert_true(fabs(tri_area - fabs(area)) <= 1e-6 * fabs(area));
        free(img);
        free(idx);
    }
    paths_free(&ps);
}

static void
no_piece(void *closure, size_t el, int family, const cf_bezier_t *bez,
         const cf_bezier_t *uv, double offset, double t0, double t1,
         bool visible)
{
    (void)closure, (void)el, (void)family, (void)bez, (void)uv;
    (void)offset, (void)t0, (void)t1, (void)visible;
}

/* The figure's occluding surfaces into the ray caster. */
static void
on_surface(void *closure, size_t el, const cf_bspline_surface_t *s,
           const cf_bezier_triangle_t *t, bool occludes)
{
    (void)el;
    if (occludes)
        assert_true(t != NULL ? rc_add_triangle(closure, t)
                              : rc_add_bspline(closure, s));
}

/* Every region of every figure of the script. */
static void
check_script(const char *name, tally_t *t, size_t *regions)
{
    cf_script_t *sc = run(name);
    for (size_t f = 0; f < cf_script_figure_count(sc); f++) {
        cf_figure_t *fig = cf_script_figure(sc, f);
        cf_view_t v;
        rc_scene_t *rc;
        char *text;
        size_t size;
        double map[6];
        const cf__tris_t *tris;
        cf_hidden_t hidden;
        double opacity;
        assert_true(cf_figure_get_view(fig, &v));
        rc = rc_create(&v);
        assert_non_null(rc);
        assert_int_equal(cf__figure_surface_pieces(fig, 1e-2, no_piece,
                                                   on_surface, rc), 0);
        assert_int_equal(cf_figure_dump(fig, NULL, &text, &size, NULL), 0);
        assert_int_equal(cf_figure_page_map(fig, NULL, map, NULL), 0);
        for (size_t i = 0; i < cf_figure_element_count(fig); i++)
            if (cf__region_triangles(fig, i, &tris, &hidden, &opacity)) {
                check_region(fig, rc, i, text, map, t);
                (*regions)++;
            }
        cf_free(text);
        rc_destroy(rc);
    }
    cf_script_destroy(sc);
}

static void
test_parts(void **state)
{
    tally_t t = { 0, 0, 0 };
    size_t regions = 0;
    (void)state;
    check_script("space-regions.lua", &t, &regions);
    check_script(CF_SOURCE_ROOT "/figures/surfaces/tangent-plane.lua", &t,
                 &regions);
    print_message("%zu regions, %zu samples, %zu disagree within %g bp of "
                  "the boundary, %zu beyond\n", regions, t.checked,
                  t.excused, EXCUSE * VTOL_BP, t.bad);
    assert_int_equal(regions, 8);
    assert_true(t.checked > 2000);
    /* (under valgrind long double is double: the ray caster is no
    ** reference then, and only the runs are checked: rc_long_double) */
    if (rc_long_double())
        assert_int_equal(t.bad, 0);
}

/* ---- pixels ------------------------------------------------------------- */

/* The opaque red fill between the two shaded surfaces: red in the PNG
** where the ray caster sees it, not red where it is hidden. */
static void
test_pixels(void **state)
{
    cf_script_t *sc = run("space-regions.lua");
    cf_figure_t *fig = NULL;
    unsigned char *png = NULL;
    size_t size = 0, checked = 0, bad = 0, el = SIZE_MAX;
    double map[6], px, vtol;
    cf_view_t v;
    rc_scene_t *rc;
    cairo_surface_t *img;
    const cf__tris_t *tris;
    cf_hidden_t hidden;
    double opacity, wbp, hbp;
    (void)state;
    for (size_t f = 0; f < cf_script_figure_count(sc); f++)
        if (strcmp(cf_script_figure_name(sc, f), "space-regions-shaded")
            == 0)
            fig = cf_script_figure(sc, f);
    assert_non_null(fig);
    assert_true(cf_figure_get_view(fig, &v));
    rc = rc_create(&v);
    assert_int_equal(cf__figure_surface_pieces(fig, 1e-2, no_piece,
                                               on_surface, rc), 0);
    for (size_t i = 0; i < cf_figure_element_count(fig); i++)
        if (cf__region_triangles(fig, i, &tris, &hidden, &opacity))
            el = i;
    assert_true(el != SIZE_MAX && hidden == CF_HIDDEN_REMOVE);
    assert_int_equal(cf_figure_render_mapped(fig, CF_FORMAT_PNG, NULL, &png,
                                             &size, map, NULL), 0);
    img = tu_png_decode(png, size);
    assert_int_equal(cairo_surface_status(img), CAIRO_STATUS_SUCCESS);
    cf_figure_get_size(fig, &wbp, &hbp);
    px = cairo_image_surface_get_width(img) / wbp;   /* pixels a bp */
    vtol = VTOL_BP / hypot(map[0], map[1]);
    for (size_t i = 0; i < tris->n; i++)
        for (int a = 0; a < 40; a++)
            for (int b = 0; a + b < 39; b++) {
                const double *tri = tris->p + 9 * i;
                double s = (a + OFF) / 40, u = (b + OFF) / 40, x[3];
                double q[2];
                int h, ix, iy;
                uint32_t pix;
                bool red;
                tri_point(tri, s, u, x);
                h = truth(rc, x, vtol);
                if (h < 0 || near_boundary(rc, &v, map, tri, s, u, h,
                                           EXCUSE * VTOL_BP + 1.5 / px,
                                           vtol))
                    continue;
                to_page(&v, map, x, q);
                ix = (int)floor(q[0] * px);
                iy = (int)floor(q[1] * px);
                if (ix < 0 || iy < 0
                    || ix >= cairo_image_surface_get_width(img)
                    || iy >= cairo_image_surface_get_height(img))
                    continue;
                pix = *(const uint32_t *)(const void *)(
                    cairo_image_surface_get_data(img)
                    + (size_t)iy * (size_t)cairo_image_surface_get_stride(img)
                    + 4 * (size_t)ix);
                red = (pix & 0xffffff) == 0xff0000;
                checked++;
                if (red != (h == 0)) {
                    if (bad < 5)
                        print_message("pixel (%d, %d) of (%g, %g, %g): %06x, "
                                      "the point is %s\n", ix, iy, x[0],
                                      x[1], x[2], pix & 0xffffff,
                                      h ? "hidden" : "seen");
                    bad++;
                }
            }
    print_message("%zu pixels checked, %zu wrong\n", checked, bad);
    assert_true(checked > 500);
    /* (under valgrind long double is double: the ray caster is no
    ** reference then, and only the runs are checked: rc_long_double) */
    if (rc_long_double())
        assert_int_equal(bad, 0);
    cairo_surface_destroy(img);
    cf_free(png);
    rc_destroy(rc);
    cf_script_destroy(sc);
}

/* ---- bad input ---------------------------------------------------------- */

static void
expect_error(const char *src, const char *words)
{
    char path[] = "/tmp/cf-regions-XXXXXX";
    int fd = mkstemp(path);
    FILE *f;
    cf_script_t *sc = NULL;
    assert_true(fd >= 0);
    f = fdopen(fd, "w");
    fputs(src, f);
    fclose(f);
    assert_int_equal(cf_script_create(NULL, NULL, &sc, NULL), 0);
    assert_int_not_equal(cf_script_run_file(sc, path), CF_STATUS_OK);
    if (strstr(cf_script_error(sc), words) == NULL)
        fail_msg("error \"%s\" lacks \"%s\"", cf_script_error(sc), words);
    cf_script_destroy(sc);
    remove(path);
}

/* A patch at the ends of the doubles' range is not degenerate: the same
** twisted patch with coordinates of 1e-300 and of 1e300 passes
** f:surface's check (squared, they had read as one point and as one
** line). */
static void
test_extreme_scales(void **state)
{
    static const char *const scales[] = { "1e-300", "1e-150", "1e150",
                                          "1e300" };
    (void)state;
    for (size_t i = 0; i < sizeof scales / sizeof *scales; i++) {
        char src[512], path[] = "/tmp/cf-regions-XXXXXX";
        int fd = mkstemp(path);
        FILE *f;
        cf_script_t *sc = NULL;
        assert_true(fd >= 0);
        snprintf(src, sizeof src,
                 "local k = %s\n"
                 "local f = figure{ name = 'z', view = { 30, 20 } }\n"
                 "f:surface(bezier_surface{ points = {\n"
                 "  { {0, 0, 0}, {0, k, k} }, { {k, 0, k}, {k, k, 0} } } })\n",
                 scales[i]);
        f = fdopen(fd, "w");
        fputs(src, f);
        fclose(f);
        assert_int_equal(cf_script_create(NULL, NULL, &sc, NULL), 0);
        if (cf_script_run_file(sc, path) != CF_STATUS_OK)
            fail_msg("k = %s: %s", scales[i], cf_script_error(sc));
        cf_script_destroy(sc);
        remove(path);
    }
}

/* A fill added before a shaded surface lies under its shading: the
** figure warns, naming the fill, its line and the surface. */
static void
test_warn_order(void **state)
{
    static const char src[] =
        "local f = figure{ name = 'w', width = '7cm', height = '5cm', "
        "view = { -60, 30 } }\n"
        "f:fill({ {-1, -0.3, 0.3}, {1, -0.3, 0.3}, {1, 0.4, 0.9} })\n"
        "f:surface(bezier_surface{ points = { { {-1, -1, 0}, {-1, 1, 0} },"
        " { {1, -1, 0}, {1, 1, 0.5} } } }, { fill = '#c0c0c0' })\n";
    char path[] = "/tmp/cf-regions-XXXXXX", *text;
    size_t size;
    int fd = mkstemp(path);
    FILE *f;
    cf_script_t *sc = NULL;
    (void)state;
    assert_true(fd >= 0);
    f = fdopen(fd, "w");
    fputs(src, f);
    fclose(f);
    assert_int_equal(cf_script_create(NULL, NULL, &sc, NULL), 0);
    if (cf_script_run_file(sc, path) != CF_STATUS_OK)
        fail_msg("%s", cf_script_error(sc));
    assert_int_equal(cf_figure_dump(cf_script_figure(sc, 0), NULL, &text,
                                    &size, NULL), 0);
    cf_free(text);
    if (strstr(cf_figure_warnings(cf_script_figure(sc, 0)),
               "fill 1 (line 2) lies under the shading of surface 2")
        == NULL)
        fail_msg("warnings: \"%s\"",
                 cf_figure_warnings(cf_script_figure(sc, 0)));
    cf_script_destroy(sc);
    remove(path);
}

static void
test_bad(void **state)
{
    cf_figure_t *fig = NULL;
    cf_diag_t diag;
    double pts[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
    (void)state;
    expect_error("local f = figure{ name = 'z', view = { 30, 20 } }\n"
                 "f:fill({ {0, 0, 0}, {1, 1, 1}, {2, 2, 2} })\n",
                 "fill: its 3 points lie on one line");
    expect_error("local f = figure{ name = 'z' }\n"
                 "f:hull({ {0, 0, 0}, {1, 0, 0}, {0, 1, 1} }, "
                 "{ hidden = 'remove' })\n",
                 "hull: hidden needs a region in R^3 in a figure with a "
                 "view");
    expect_error("local f = figure{ name = 'z', view = { 30, 20 } }\n"
                 "f:fill({ {0, 0, 0}, {1, 0, 0}, {0, 1, 1} }, "
                 "{ hiden = 'remove' })\n", "hidden");
    assert_int_equal(cf_figure_create(100, 100, CF_UNIT_BP, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_space_fill(fig, pts, 3, CF_HIDDEN_DASHED,
                                              NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_status(fig, &diag), CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(diag.msg, "fill in space: the figure has no "
                                     "view"));
    cf_figure_destroy(fig);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parts),
        cmocka_unit_test(test_pixels),
        cmocka_unit_test(test_warn_order),
        cmocka_unit_test(test_bad),
        cmocka_unit_test(test_extreme_scales),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
