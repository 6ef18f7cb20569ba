/*
** The surface chapter's figures (figures/surfaces/):
**
**   visibility  every line the surface elements draw, sampled densely
**               (4 points a piece: the pieces are short; the ray caster takes about 1 ms a sample), is visible where the figure draws it
**               visible and hidden where it draws it hidden, as an
**               independent ray caster (tests/unit/raycast-ref.h: long
**               double Newton on the exact surfaces) finds, except within
**               3 times the split tolerance (on the page) of a split point;
**   on surface  every line drawn on a surface (a boundary, an iso- or
**               knot line: offset 0, with its (u, v) curve) is the
**               surface along that curve: the piece's point and the
**               surface evaluated at its (u, v) by the library's own
**               evaluator agree to 1e-9 of the figure's extent in space;
**   cubic       the surface elements' paths are made of cubic segments
**               only (no line segment: no polyline) in the display list,
**               and the SVG and PDF files carry exactly the line segments
**               of the other elements (a surface's lines reach both
**               formats as cubics).
*/
#include <dirent.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <zlib.h>

#include "curvefig/figure3d.h"
#include "raycast-ref.h"
#include "script.h"
#include "surface-lines.h"

#define SURF_DIR CF_SOURCE_ROOT "/figures/surfaces"
/* scenes for the test alone: points and lines in space among surfaces */
#define SCENE_DIR CF_SOURCE_ROOT "/tests/surfaces/scenes"

/* ---- the scripts -------------------------------------------------------- */

static int
by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The scripts of dir, sorted; returns how many. */
static size_t
scripts_in(const char *dir, char **names, size_t max)
{
    DIR *d = opendir(dir);
    struct dirent *de;
    size_t n = 0;
    assert_non_null(d);
    while ((de = readdir(d)) != NULL && n < max) {
        size_t len = strlen(de->d_name);
        if (len > 4 && strcmp(de->d_name + len - 4, ".lua") == 0)
            names[n++] = strdup(de->d_name);
    }
    closedir(d);
    qsort(names, n, sizeof *names, by_name);
    return n;
}

/* The scripts of figures/surfaces. */
static size_t
scripts(char **names, size_t max)
{
    return scripts_in(SURF_DIR, names, max);
}

static cf_script_t *
run_in(const char *dir, const char *name)
{
    char path[1024];
    cf_script_t *sc = NULL;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    assert_int_equal(cf_script_create(NULL, NULL, &sc, NULL), 0);
    if (cf_script_run_file(sc, path) != CF_STATUS_OK)
        fail_msg("%s: %s", path, cf_script_error(sc));
    return sc;
}

static cf_script_t *
run(const char *name)
{
    return run_in(SURF_DIR, name);
}

/* ---- visibility --------------------------------------------------------- */

typedef struct piece {
    cf_bezier_t *bez;
    cf_bezier_t *uv;           /* on its surface, or NULL */
    double offset;
    size_t el;
    double t0, t1;
    bool visible;
    int family;
} piece_t;

typedef struct probe {
    piece_t *pieces;
    size_t n, cap;
    /* the surfaces by element index, for the normals of silhouettes */
    const cf_bspline_surface_t *surf[256];
    const cf_bezier_triangle_t *tri[256];
    rc_scene_t *rc;
    size_t occluders;
} probe_t;

static void
on_piece(void *closure, size_t el, int family, const cf_bezier_t *bez,
         const cf_bezier_t *uv, double offset, double t0, double t1,
         bool visible)
{
    probe_t *p = closure;
    if (p->n == p->cap) {
        p->cap = p->cap ? 2 * p->cap : 256;
        p->pieces = realloc(p->pieces, p->cap * sizeof *p->pieces);
        assert_non_null(p->pieces);
    }
    assert_int_equal(cf_bezier_copy(bez, &p->pieces[p->n].bez, NULL), 0);
    p->pieces[p->n].uv = NULL;
    if (uv != NULL)
        assert_int_equal(cf_bezier_copy(uv, &p->pieces[p->n].uv, NULL), 0);
    p->pieces[p->n].offset = offset;
    p->pieces[p->n].el = el;
    p->pieces[p->n].t0 = t0;
    p->pieces[p->n].t1 = t1;
    p->pieces[p->n].visible = visible;
    p->pieces[p->n].family = family;
    p->n++;
}

static void
on_surface(void *closure, size_t el, const cf_bspline_surface_t *s,
           const cf_bezier_triangle_t *t, bool occludes)
{
    probe_t *p = closure;
    if (el < 256) {
        p->surf[el] = s;
        p->tri[el] = t;
    }
    if (!occludes)
        return;
    assert_true(t != NULL ? rc_add_triangle(p->rc, t)
                          : rc_add_bspline(p->rc, s));
    p->occluders++;
}

static double
image_dist(const cf_view_t *v, const double *a, const double *b)
{
    double pa[2], pb[2];
    assert_int_equal(cf_view_project(v, a, pa, NULL), 0);
    assert_int_equal(cf_view_project(v, b, pb, NULL), 0);
    return hypot(pa[0] - pb[0], pa[1] - pb[1]);
}

/* Whether the sample x of piece pc at t is hidden (1) or visible (0), or
** -1 when that is not decided within the tolerance.  A silhouette point
** (offset > 0) has the line of sight tangent to its surface, and lies
** within offset of it on either side: the ray caster is asked at x moved
** off the surface along the normal by 2 (offset + vtol) on both sides; the
** answer counts when both agree (the surface's own tangent touch near x
** hides one of them at most; both differ only within that distance of
** another contour in front, a split within tolerance). */
static int
sample_hidden(const probe_t *p, const piece_t *pc, double t, const double *x,
              double vtol, double *dist)
{
    double uv[2], n[3], y[3], e = 2 * (pc->offset + vtol);
    bool a, b;
    if (!(pc->offset > 0) || pc->uv == NULL || pc->el >= 256)
        return rc_hidden(p->rc, x, 2 * vtol, dist);
    assert_int_equal(cf_bezier_eval(pc->uv, t, uv), 0);
    if ((p->tri[pc->el] != NULL
         ? cf_bezier_triangle_normal(p->tri[pc->el], uv[0], uv[1], n)
         : cf_bspline_surface_normal(p->surf[pc->el], uv[0], uv[1], n))
        != CF_STATUS_OK)
        return rc_hidden(p->rc, x, 2 * vtol, dist);
    for (int k = 0; k < 3; k++)
        y[k] = x[k] + e * n[k];
    a = rc_hidden(p->rc, y, 2 * vtol, dist);
    for (int k = 0; k < 3; k++)
        y[k] = x[k] - e * n[k];
    b = rc_hidden(p->rc, y, 2 * vtol, dist);
    return a == b ? a : -1;
}

/*
** How far (in space) piece pc is from its surface at three parameters,
** over extent; 0 for a piece not on a surface.  The piece is the surface
** restricted to its (u, v) curve, made by blossoming or knot insertion;
** the surface point is the evaluator's (de Casteljau, de Boor): the two
** differ by the roundings of some 3 n operations on each coordinate (n
** the degree, weights up to 2^10 in the scenes), far below 1e-9.
*/
static double
off_surface(const probe_t *p, const piece_t *pc, double extent)
{
    double worst = 0;
    if (pc->uv == NULL || pc->offset > 0 || pc->el >= 256
        || (p->surf[pc->el] == NULL && p->tri[pc->el] == NULL))
        return 0;
    for (int k = 0; k <= 2; k++) {
        double t = pc->t0 + 0.5 * k * (pc->t1 - pc->t0), uv[2], x[3], y[3];
        assert_int_equal(cf_bezier_eval(pc->bez, t, x), 0);
        assert_int_equal(cf_bezier_eval(pc->uv, t, uv), 0);
        assert_int_equal(p->tri[pc->el] != NULL
                         ? cf_bezier_triangle_eval(p->tri[pc->el], uv[0],
                                                   uv[1], y)
                         : cf_bspline_surface_eval(p->surf[pc->el], uv[0],
                                                   uv[1], y), 0);
        for (int c = 0; c < 3; c++)
            worst = fmax(worst, fabs(x[c] - y[c]) / extent);
    }
    return worst;
}

/* Samples of one figure that disagree with the ray caster; *checked
** counts the samples compared.  Fails when a line on a surface leaves
** it (off_surface). */
static size_t
check_figure(const char *script, const char *name, cf_figure_t *fig,
             size_t *checked)
{
    cf_view_t view;
    probe_t p;
    double win[4], sx, sy, tol, vtol, extent, worst_off = 0;
    size_t bad = 0, on_surfaces = 0;
    enum { K = 4 };
    memset(&p, 0, sizeof p);
    if (!cf_figure_get_view(fig, &view))
        return 0;
    /* the layout's fitting tolerance in data units: the figure's 0.01 bp
    ** at the page's scale; the split points are found to 20 times it */
    assert_int_equal(cf_figure_get_window(fig, win, &sx, &sy), 0);
    tol = 0.01 / sx;
    vtol = 20 * tol;
    p.rc = rc_create(&view);
    assert_non_null(p.rc);
    assert_int_equal(cf__figure_surface_pieces(fig, tol, on_piece,
                                               on_surface, &p), 0);
    /* the figure's extent in space: its window's diagonal over the
    ** page's scale in data units, as the view maps space to the page */
    extent = hypot(win[1] - win[0], win[3] - win[2]);
    for (size_t i = 0; i < p.n; i++) {
        piece_t *pc = &p.pieces[i];
        double a[3], b[3], off = off_surface(&p, pc, extent);
        if (off > 1e-9)
            fail_msg("%s %s: family %d piece [%g, %g] of element %zu lies "
                     "%g (of the extent) off its surface", script, name,
                     pc->family, pc->t0, pc->t1, pc->el, off);
        worst_off = fmax(worst_off, off);
        on_surfaces += pc->uv != NULL && !(pc->offset > 0);
        assert_int_equal(cf_bezier_eval(pc->bez, pc->t0, a), 0);
        assert_int_equal(cf_bezier_eval(pc->bez, pc->t1, b), 0);
        for (int k = 0; k < K && p.occluders > 0; k++) {
            double t = pc->t0 + (k + 0.5) / K * (pc->t1 - pc->t0), x[3];
            double dist = 0;
            int hidden;
            assert_int_equal(cf_bezier_eval(pc->bez, t, x), 0);
            /* a split point's neighbourhood is left out: the split is
            ** found to vtol on the page */
            if ((pc->t0 > 0 && image_dist(&view, x, a) < 3 * vtol)
                || (pc->t1 < 1 && image_dist(&view, x, b) < 3 * vtol))
                continue;
            /* a surface point nearer than the library's depth tolerance
            ** hides nothing (the line's own surface at the line) */
            hidden = sample_hidden(&p, pc, t, x, vtol, &dist);
            if (hidden < 0)
                continue;
            /* drawn hidden behind a surface between vtol and 2 vtol in
            ** front (a net segment close to its surface): within the
            ** depth tolerance, either answer is right */
            if (hidden == 0 && !pc->visible && !(pc->offset > 0)
                && rc_hidden(p.rc, x, vtol, NULL))
                continue;
            (*checked)++;
            if ((hidden == 1) == pc->visible) {
                if (bad < 5)
                    print_message("%s %s: family %d piece [%g, %g] drawn "
                                  "%s, at t = %g (%g, %g, %g) the ray "
                                  "caster finds it %s (hit at %g; split tolerance %g)\n", script, name,
                                  pc->family, pc->t0, pc->t1,
                                  pc->visible ? "visible" : "hidden", t,
                                  x[0], x[1], x[2],
                                  hidden ? "hidden" : "visible", dist, vtol);
                bad++;
            }
        }
        cf_bezier_destroy(pc->bez);
        cf_bezier_destroy(pc->uv);
    }
    free(p.pieces);
    rc_destroy(p.rc);
    print_message("%s %s: %zu pieces on surfaces, within %.2g of the "
                  "extent\n", script, name, on_surfaces, worst_off);
    return bad;
}

/* Every figure of the scripts of dir; counts into the totals. */
static void
check_dir(const char *dir, size_t *checked, size_t *bad, size_t *figures)
{
    char *names[64];
    size_t n = scripts_in(dir, names, 64);
    assert_true(n >= 1);
    for (size_t i = 0; i < n; i++) {
        cf_script_t *sc = run_in(dir, names[i]);
        for (size_t f = 0; f < cf_script_figure_count(sc); f++) {
            cf_figure_t *fig = cf_script_figure(sc, f);
            /* the figure, then each of its panels (model.h), which keep
            ** their own view and elements */
            int np = fig->panels != NULL ? fig->rows * fig->cols : 0;
            for (int k = -1; k < np; k++) {
                size_t before = *checked, b;
                b = check_figure(names[i], cf_script_figure_name(sc, f),
                                 k < 0 ? fig : fig->panels[k], checked);
                print_message("%s%s%c: %zu of %zu samples disagree\n",
                              cf_script_figure_name(sc, f),
                              k < 0 ? "" : ", panel ",
                              k < 0 ? ' ' : (char)('a' + k), b,
                              *checked - before);
                *bad += b;
                (*figures)++;
            }
        }
        cf_script_destroy(sc);
        free(names[i]);
    }
}

static void
test_visibility(void **state)
{
    size_t checked = 0, bad = 0, figures = 0;
    (void)state;
    check_dir(SURF_DIR, &checked, &bad, &figures);
    assert_true(figures >= 10);
    check_dir(SCENE_DIR, &checked, &bad, &figures);
    print_message("%zu figures, %zu samples checked, %zu disagree\n",
                  figures, checked, bad);
    assert_true(checked > 1000);
    /* (under valgrind long double is double: the ray caster is no
    ** reference then, and only the runs are checked: rc_long_double) */
    if (rc_long_double())
        assert_int_equal(bad, 0);
}

/* ---- cubic segments ----------------------------------------------------- */

/* The straight edges a path draws, fed its commands in order: each line
** segment, and a close whose current point is not the subpath's start,
** farther than rounding from it (cairo's PDF closes "l l l h" where the
** display list and the SVG draw the last edge back to the start, then
** close: the same four edges). */
typedef struct edges {
    double sx, sy, cx, cy;
    size_t n;
} edges_t;

static void
edge_move(edges_t *e, double x, double y)
{
    e->sx = e->cx = x;
    e->sy = e->cy = y;
}

static void
edge_line(edges_t *e, double x, double y)
{
    e->n++;
    e->cx = x;
    e->cy = y;
}

/* A close draws an edge when it spans more than 0.01 bp: the formats
** round the points they write (the SVG to 0.001 bp), so a closed curve
** whose end meets its start within rounding closes with no edge in one
** format and a speck of one in another. */
static void
edge_close(edges_t *e)
{
    if (fabs(e->cx - e->sx) > 0.01 || fabs(e->cy - e->sy) > 0.01)
        e->n++;
    e->cx = e->sx;
    e->cy = e->sy;
}

/* Line segments of stroked-only paths in the dump: inside surface groups
** (*in_surface) and elsewhere (*other); cubic segments of surface groups
** into *cubics. */
static void
dump_segments(const char *text, size_t *in_surface, size_t *other,
              size_t *cubics)
{
    bool surface = false;
    *in_surface = *other = *cubics = 0;
    for (const char *line = text; line != NULL && *line != '\0';) {
        const char *nl = strchr(line, '\n');
        size_t len = nl != NULL ? (size_t)(nl - line) : strlen(line);
        if (strncmp(line, "group ", 6) == 0)
            surface = memmem(line, len, " surface", 8) != NULL;
        else if (strncmp(line, "end", 3) == 0)
            surface = false;
        else if (strncmp(line, "path stroke", 11) == 0) {
            /* after " :", the segments: a letter and its numbers */
            static const char letter[] = "MLCRAZ";
            static const int count[] = { 2, 2, 6, 4, 5, 0 };
            const char *p = memmem(line, len, " :", 2), *end = line + len;
            edges_t e = { 0, 0, 0, 0, 0 };
            while (p != NULL && (p = strchr(p, ' ')) != NULL && p < end) {
                const char *at = strchr(letter, p[1]);
                double v[6];
                int k, seg = at != NULL && p[1] != '\0'
                                 ? (int)(at - letter) : -1;
                p += 2;
                if (seg < 0)
                    continue;
                for (k = 0; k < count[seg]; k++)
                    v[k] = strtod(p, (char **)&p);
                if (seg == 0)
                    edge_move(&e, v[0], v[1]);
                else if (seg == 1)
                    edge_line(&e, v[0], v[1]);
                else if (seg == 2) {
                    if (surface)
                        (*cubics)++;
                    e.cx = v[4];
                    e.cy = v[5];
                } else if (seg == 5)
                    edge_close(&e);
            }
            *(surface ? in_surface : other) += e.n;
        }
        line = nl != NULL ? nl + 1 : NULL;
    }
}

static char *
slurp(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long n;
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = malloc((size_t)n + 1);
    assert_non_null(buf);
    assert_int_equal(fread(buf, 1, (size_t)n, f), (size_t)n);
    buf[n] = '\0';
    fclose(f);
    *size = (size_t)n;
    return buf;
}

/* The straight edges ('L', and 'Z' where it draws one: edges_t) of the
** SVG's stroked paths without fill (the SVG writer
** sets fill="none" on its outer group: a stroked path without a fill of
** its own is not filled; the glyph outlines in <defs> have no stroke). */
static size_t
svg_lines(const char *svg)
{
    size_t n = 0;
    for (const char *p = strstr(svg, "<path"); p != NULL;
         p = strstr(p + 1, "<path")) {
        const char *end = strchr(p, '>'), *d, *fill, *stroke;
        if (end == NULL)
            continue;
        /* stroked only: fill:none in its style, or a stroke and no fill
        ** of its own (the document's group has fill="none") */
        fill = strstr(p, " fill=\"");
        stroke = strstr(p, " stroke=\"");
        if (!(strstr(p, "fill:none") != NULL && strstr(p, "fill:none") < end)
            && !(stroke != NULL && stroke < end
                 && (fill == NULL || fill > end)))
            continue;
        d = strstr(p, " d=\"");
        {
            /* the writer's commands are absolute: M L C Z */
            edges_t e = { 0, 0, 0, 0, 0 };
            char *q;
            for (d = d != NULL && d < end ? d + 4 : end; d < end && *d != '"';
                 ) {
                char c = *d++;
                double v[6];
                int k, m = c == 'M' || c == 'L' ? 2 : c == 'C' ? 6 : 0;
                for (k = 0; k < m; k++) {
                    while (*d == ' ' || *d == ',')
                        d++;
                    v[k] = strtod(d, &q);
                    d = q;
                }
                if (c == 'M')
                    edge_move(&e, v[0], v[1]);
                else if (c == 'L')
                    edge_line(&e, v[0], v[1]);
                else if (c == 'C') {
                    e.cx = v[4];
                    e.cy = v[5];
                } else if (c == 'Z')
                    edge_close(&e);
            }
            n += e.n;
        }
    }
    return n;
}

/* The straight edges ('l', and 'h' where it draws one: edges_t) of the
** PDF's paths painted by S (stroke only), in every Flate stream. */
static size_t
pdf_lines(const char *pdf, size_t size)
{
    size_t n = 0;
    for (const char *p = pdf; (p = memmem(p, size - (size_t)(p - pdf),
                                          "stream\n", 7)) != NULL;) {
        const char *e = memmem(p, size - (size_t)(p - pdf), "endstream", 9);
        uLongf out = 1u << 24;
        unsigned char *buf = malloc(out + 1);
        edges_t ed = { 0, 0, 0, 0, 0 };
        double v[6];
        int nv = 0;
        assert_non_null(buf);
        if (e != NULL && uncompress(buf, &out, (const Bytef *)p + 7,
                                    (uLong)(e - p - 7)) == Z_OK) {
            buf[out] = '\0';
            for (char *tok = strtok((char *)buf, " \n\r"); tok != NULL;
                 tok = strtok(NULL, " \n\r")) {
                char *q;
                double x = strtod(tok, &q);
                if (q != tok && *q == '\0') {   /* an operand */
                    if (nv == 6)
                        memmove(v, v + 1, 5 * sizeof *v), nv = 5;
                    v[nv++] = x;
                    continue;
                }
                if (strcmp(tok, "m") == 0 && nv >= 2)
                    edge_move(&ed, v[nv - 2], v[nv - 1]);
                else if (strcmp(tok, "l") == 0 && nv >= 2)
                    edge_line(&ed, v[nv - 2], v[nv - 1]);
                else if (strcmp(tok, "c") == 0 && nv >= 2) {
                    ed.cx = v[nv - 2];
                    ed.cy = v[nv - 1];
                } else if (strcmp(tok, "h") == 0)
                    edge_close(&ed);
                else if (strcmp(tok, "S") == 0) {
                    n += ed.n;
                    ed.n = 0;
                } else if (strcmp(tok, "f") == 0 || strcmp(tok, "B") == 0
                           || strcmp(tok, "n") == 0 || strcmp(tok, "f*") == 0
                           || strcmp(tok, "b") == 0 || strcmp(tok, "s") == 0
                           || strcmp(tok, "W") == 0) {
                    ed.n = 0;
                }
                nv = 0;
            }
        }
        free(buf);
        p = e != NULL ? e : pdf + size;
    }
    return n;
}

static void
test_cubic(void **state)
{
    char *names[64], dir[] = "/tmp/cf-surface-figures-XXXXXX";
    size_t n = scripts(names, 64), figures = 0;
    (void)state;
    assert_non_null(mkdtemp(dir));
    for (size_t i = 0; i < n; i++) {
        cf_script_t *sc = run(names[i]);
        for (size_t f = 0; f < cf_script_figure_count(sc); f++) {
            cf_figure_t *fig = cf_script_figure(sc, f);
            const char *name = cf_script_figure_name(sc, f);
            char *text, *svg, *pdf, path[1200];
            size_t size, in_surface, other, cubics, svg_size, pdf_size;
            assert_int_equal(cf_figure_dump(fig, NULL, &text, &size, NULL),
                             0);
            dump_segments(text, &in_surface, &other, &cubics);
            cf_free(text);
            if (in_surface != 0)
                fail_msg("%s: %zu line segments in surface paths", name,
                         in_surface);
            assert_true(cubics > 0);
            snprintf(path, sizeof path, "%s/%s.svg", dir, name);
            assert_int_equal(cf_figure_write(fig, path, CF_FORMAT_SVG, NULL,
                                             NULL), 0);
            svg = slurp(path, &svg_size);
            remove(path);
            snprintf(path, sizeof path, "%s/%s.pdf", dir, name);
            assert_int_equal(cf_figure_write(fig, path, CF_FORMAT_PDF, NULL,
                                             NULL), 0);
            pdf = slurp(path, &pdf_size);
            remove(path);
            if (svg_lines(svg) != other || pdf_lines(pdf, pdf_size) != other)
                fail_msg("%s: line segments: %zu in the display list's "
                         "other paths, %zu in the SVG, %zu in the PDF",
                         name, other, svg_lines(svg),
                         pdf_lines(pdf, pdf_size));
            free(svg);
            free(pdf);
            figures++;
        }
        cf_script_destroy(sc);
        free(names[i]);
    }
    rmdir(dir);
    assert_true(figures >= 10);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_visibility),
        cmocka_unit_test(test_cubic),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
