/* Every shipped figure (the scripts in figures/), rendered through the
** cairo backend into rasters of its page: no label glyph lies on drawn
** ink or on another label, and no ink touches the edge of the page.
**
** A figure's display list is drawn three ways at RES pixels per bp, each
** into an alpha-only raster: everything (the page: its border rows and
** columns must stay empty, also in a figure that lets the page clip);
** everything but the text, with the fills of shadings and of the legend's
** box left out (a label may sit on a shading, not on its outline);
** and each text operation alone (its glyph mask).  A pixel counts as ink
** when its alpha exceeds one half: two anti-aliased edges that only touch
** never both pass that, two shapes that overlap by a third of a bp do.
** A label collides when one of its glyph pixels is ink of the rest, or of
** an earlier label.  And each label of a point lies with its nearest
** glyph pixel within NEAR of its point, nearer it than any other
** labelled point (a reader takes a label for the nearest point's). */
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

#include "backend.h"
#include "layout-private.h"
#include "script.h"
#include "shipped.h"
#include "testutil.h"

#define RES 3.0      /* raster pixels per bp (216 dpi) */
#define HALF 127     /* alpha of a pixel inked more than half */

#define NEAR 10.0    /* bp: a label's nearest glyph pixel at most this far
                        from its anchor (automatic placement keeps the
                        label's box within 8 bp: the offset, 4, and at
                        most 4 more; a glyph's rounded corner adds a
                        little, the box's corner on a diagonal more) */

typedef struct mask {
    int x0, y0, w, h;    /* the box of the glyphs, in raster pixels */
    unsigned char *a;    /* w * h alphas */
    const char *src;
    bool element;        /* a label element's (anchored at a point) */
    double ax, ay;       /* its anchor, bp */
} mask_t;

static void
no_text(void *ctx, const cf__text_op_t *t)
{
    (void)ctx;
    (void)t;
}

static cairo_t *
raster(int w, int h, cairo_surface_t **img)
{
    cairo_t *cr;
    *img = cairo_image_surface_create(CAIRO_FORMAT_A8, w, h);
    cr = cairo_create(*img);
    assert_int_equal(cairo_status(cr), CAIRO_STATUS_SUCCESS);
    cairo_scale(cr, RES, RES);
    return cr;
}

static unsigned char
alpha(cairo_surface_t *img, int x, int y)
{
    return cairo_image_surface_get_data(img)
        [(size_t)y * (size_t)cairo_image_surface_get_stride(img)
         + (size_t)x];
}

/* Pixels of the raster's border rows and columns with any ink. */
static long
border_pixels(cairo_surface_t *img)
{
    int w = cairo_image_surface_get_width(img);
    int h = cairo_image_surface_get_height(img), x, y;
    long n = 0;
    cairo_surface_flush(img);
    for (x = 0; x < w; x++)
        n += (alpha(img, x, 0) > 0) + (alpha(img, x, h - 1) > 0);
    for (y = 1; y < h - 1; y++)
        n += (alpha(img, 0, y) > 0) + (alpha(img, w - 1, y) > 0);
    return n;
}

/* The glyph mask of text operation k. */
static void
text_mask(const cf__dl_t *dl, size_t k, int w, int h, mask_t *m)
{
    cairo_surface_t *img;
    cairo_t *cr = raster(w, h, &img);
    double ink[4];
    int x, y;
    assert_int_equal(cf__cairo_ink(dl, k, k + 1, ink), 0);
    m->x0 = (int)fmax(0, floor(ink[0] * RES) - 1);
    m->y0 = (int)fmax(0, floor(ink[1] * RES) - 1);
    m->w = (int)fmin(w, ceil(ink[2] * RES) + 1) - m->x0;
    m->h = (int)fmin(h, ceil(ink[3] * RES) + 1) - m->y0;
    if (m->w < 0)
        m->w = 0;
    if (m->h < 0)
        m->h = 0;
    m->a = calloc((size_t)m->w * (size_t)m->h + 1, 1);
    m->src = dl->ops[k].u.text.source;
    cf__dl_play(dl, k, k + 1, &cf__cairo_backend, cr);
    cairo_surface_flush(img);
    for (y = 0; y < m->h; y++)
        for (x = 0; x < m->w; x++)
            m->a[(size_t)y * (size_t)m->w + (size_t)x] =
                alpha(img, m->x0 + x, m->y0 + y);
    cairo_destroy(cr);
    cairo_surface_destroy(img);
}

static long
mask_on_raster(const mask_t *m, cairo_surface_t *img)
{
    long n = 0;
    int x, y;
    for (y = 0; y < m->h; y++)
        for (x = 0; x < m->w; x++)
            n += m->a[(size_t)y * (size_t)m->w + (size_t)x] > HALF
                 && alpha(img, m->x0 + x, m->y0 + y) > HALF;
    return n;
}

static long
mask_on_mask(const mask_t *a, const mask_t *b)
{
    long n = 0;
    int x, y;
    for (y = 0; y < a->h; y++)
        for (x = 0; x < a->w; x++) {
            int bx = a->x0 + x - b->x0, by = a->y0 + y - b->y0;
            if (bx < 0 || by < 0 || bx >= b->w || by >= b->h)
                continue;
            n += a->a[(size_t)y * (size_t)a->w + (size_t)x] > HALF
                 && b->a[(size_t)by * (size_t)b->w + (size_t)bx] > HALF;
        }
    return n;
}

/* bp from page point (x, y) to the nearest glyph pixel of m (its
** centre); HUGE_VAL when it has none. */
static double
mask_distance(const mask_t *m, double x, double y)
{
    double best = HUGE_VAL;
    int i, j;
    for (j = 0; j < m->h; j++)
        for (i = 0; i < m->w; i++)
            if (m->a[(size_t)j * (size_t)m->w + (size_t)i] > HALF) {
                double dx = (m->x0 + i + 0.5) / RES - x;
                double dy = (m->y0 + j + 0.5) / RES - y;
                double d = sqrt(dx * dx + dy * dy);
                if (d < best)
                    best = d;
            }
    return best;
}

/* Each label element lies with its glyphs within NEAR of its own anchor; every label element lies nearer its own anchor
** than any other label's (a reader takes a label for the nearest
** labelled point's).  The faults, printed; their number. */
static int
check_anchors(const mask_t *masks, size_t nt, const char *name)
{
    size_t i, k;
    int bad = 0;
    for (i = 0; i < nt; i++) {
        const mask_t *m = &masks[i];
        double own;
        if (!m->element)
            continue;
        own = mask_distance(m, m->ax, m->ay);
        if (own == HUGE_VAL)
            continue;
        if (getenv("CF_COLLIDE_DISTANCES") != NULL)
            print_message("%s: label \"%s\" %.2f bp from its point\n", name,
                          m->src, own);
        if (own > NEAR) {
            print_message("%s: label \"%s\" lies %.1f bp from its point "
                          "(at most %.0f)\n", name, m->src, own, NEAR);
            bad++;
        }
        for (k = 0; k < nt; k++) {
            const mask_t *o = &masks[k];
            double other;
            if (k == i || !o->element
                || hypot(o->ax - m->ax, o->ay - m->ay) < 0.5)
                continue;
            other = mask_distance(m, o->ax, o->ay);
            if (other < own) {
                print_message("%s: label \"%s\" lies nearer the point of "
                              "\"%s\" (%.1f bp) than its own (%.1f bp)\n",
                              name, m->src, o->src, other, own);
                bad++;
            }
        }
    }
    return bad;
}

/* The element (and the figure or panel holding it) whose group
** operation i draws in, for every operation; NULL outside the groups of
** elements (legends, insets, panel titles). */
typedef struct owned {
    cf_figure_t *owner;
    cf__element_t *el;
} owned_t;

static owned_t *
elements_of(cf_figure_t *fig, const cf__dl_t *dl)
{
    owned_t *o = calloc(dl->count + 1, sizeof *o);
    cf_figure_t *owner = fig;
    cf__element_t *stack[64] = { NULL };
    int depth = 0, panel = -1;   /* the depth of the open panel's group */
    size_t i;
    assert_non_null(o);
    for (i = 0; i < dl->count; i++) {
        const cf__op_t *op = &dl->ops[i];
        if (op->kind == CF__OP_GROUP) {
            const char *g = op->u.group.name;
            size_t at = op->u.group.index;
            cf__element_t *e = NULL;
            if (strcmp(g, "panel") == 0 && fig->panels != NULL
                && at < (size_t)(fig->rows * fig->cols)) {
                owner = fig->panels[at];
                panel = depth;
            } else if (at < owner->count
                       && strcmp(g, owner->els[at]->kind->name) == 0) {
                e = owner->els[at];
            }
            assert_true(depth < 64);
            stack[depth++] = e;
        } else if (op->kind == CF__OP_END && depth > 0) {
            o[i].owner = owner;
            o[i].el = stack[depth - 1];
            if (--depth == panel) {
                owner = fig;
                panel = -1;
            }
            continue;
        }
        o[i].owner = owner;
        o[i].el = depth > 0 ? stack[depth - 1] : NULL;
    }
    return o;
}

/* The collisions of one figure, printed; their number. */
static int
check_figure(cf_figure_t *fig, const char *name)
{
    cf__layout_t lay;
    cf__dl_t dl;
    cf__backend_t ink_only = cf__cairo_backend;
    cairo_surface_t *page, *ink;
    cairo_t *cr;
    double pw, ph;
    int w, h, bad = 0;
    size_t i, k, nt = 0;
    mask_t *masks;
    owned_t *els;
    long n;

    cf__dl_init(&dl);
    assert_int_equal(cf__figure_layout(fig, &lay), CF_STATUS_OK);
    assert_int_equal(cf__figure_build(fig, &lay, &dl), CF_STATUS_OK);
    cf_figure_get_size(fig, &pw, &ph);
    w = (int)ceil(pw * RES);
    h = (int)ceil(ph * RES);

    cr = raster(w, h, &page);
    cf__dl_play(&dl, 0, dl.count, &cf__cairo_backend, cr);
    cairo_destroy(cr);
    n = border_pixels(page);
    if (n > 0) {
        print_message("%s: ink on %ld pixels of the page's edge\n", name, n);
        bad++;
    }
    cairo_surface_destroy(page);

    /* the shadings' fills are left out: a label may sit on a shading, and
    ** the legend's entries on its box */
    els = elements_of(fig, &dl);
    for (i = 0; i < dl.count; i++) {
        cf__op_t *op = &dl.ops[i];
        if (op->kind == CF__OP_GROUP
            && ((els[i].el != NULL
                 && (els[i].el->kind->flags & CF__KIND_SHADING))
                || strcmp(op->u.group.name, "legend") == 0))
            for (k = i + 1; k < dl.count && dl.ops[k].kind != CF__OP_END; k++)
                if (dl.ops[k].kind == CF__OP_PATH)
                    dl.ops[k].u.path.paint.fill = false;
    }
    ink_only.draw_text = no_text;
    cr = raster(w, h, &ink);
    cf__dl_play(&dl, 0, dl.count, &ink_only, cr);
    cairo_destroy(cr);
    cairo_surface_flush(ink);

    masks = calloc(dl.count + 1, sizeof *masks);
    for (i = 0; i < dl.count; i++) {
        mask_t *m;
        if (dl.ops[i].kind != CF__OP_TEXT)
            continue;
        m = &masks[nt++];
        text_mask(&dl, i, w, h, m);
        m->element = els[i].el != NULL
                     && strcmp(els[i].el->kind->name, "label") == 0;
        m->ax = dl.ops[i].u.text.px;
        m->ay = dl.ops[i].u.text.py;
        n = mask_on_raster(m, ink);
        if (n > 0) {
            print_message("%s: label \"%s\" lies on ink (%ld pixels)\n",
                          name, m->src, n);
            bad++;
        }
        for (k = 0; k + 1 < nt; k++) {
            n = mask_on_mask(m, &masks[k]);
            if (n > 0) {
                print_message("%s: labels \"%s\" and \"%s\" overlap "
                              "(%ld pixels)\n", name, masks[k].src, m->src,
                              n);
                bad++;
            }
        }
    }
    bad += check_anchors(masks, nt, name);
    free(els);
    for (k = 0; k < nt; k++)
        free(masks[k].a);
    free(masks);
    cairo_surface_destroy(ink);
    cf__dl_free(&dl);
    return bad;
}

static int
check_shipped(void *ctx, const char *script, const char *name,
              cf_figure_t *fig)
{
    (void)ctx;
    (void)script;
    return check_figure(fig, name);
}

static void
test_no_label_on_ink(void **state)
{
    size_t failed, figures;
    (void)state;
    figures = tu_each_shipped_figure(CF_SOURCE_ROOT, check_shipped, NULL,
                                     &failed);
    print_message("%zu figures, %zu with a label on ink, on another label "
                  "or ink on the page's edge\n", figures, failed);
    assert_true(figures >= 60);
    assert_int_equal(failed, 0);
}

/* The test sees what it must: a label put on a stroke, two labels on one
** another, ink on the page's edge, a label far from its point, a label
** nearer another labelled point than its own; and passes a clean
** figure. */
static void
test_detects(void **state)
{
    static const double line[] = { 0, 0, 4, 0 }, edge[] = { 0, 0, 4, 3 };
    cf_figure_t *fig;
    cf_style_t at;
    int k;
    (void)state;
    cf_style_init(&at);
    at.place = CF_PLACE_CENTER;
    at.set |= CF_STYLE_PLACE;
    for (k = 0; k < 6; k++) {
        assert_int_equal(cf_figure_create(40, 30, CF_UNIT_MM, &fig, NULL), 0);
        assert_int_equal(cf_figure_add_polyline(fig, line, 2, false, NULL),
                         0);
        if (k == 0)   /* on the stroke */
            assert_int_equal(cf_figure_add_label(fig, 2, 0, "W", &at), 0);
        if (k == 1) { /* two labels centred on one point */
            assert_int_equal(cf_figure_add_label(fig, 2, 1, "AB", &at), 0);
            assert_int_equal(cf_figure_add_label(fig, 2, 1, "CD", &at), 0);
        }
        if (k == 2) { /* a line out of the page, cut by it */
            assert_int_equal(cf_figure_set_fit(fig, 0, false), 0);
            assert_int_equal(cf_figure_set_window(fig, 0, 2, 0, 1.5), 0);
            assert_int_equal(cf_figure_set_clip(fig, true), 0);
            assert_int_equal(cf_figure_add_polyline(fig, edge, 2, false,
                                                    NULL), 0);
        }
        if (k == 3)   /* clean: automatic, above the stroke */
            assert_int_equal(cf_figure_add_label(fig, 2, 0, "W", NULL), 0);
        if (k == 4) { /* far from its point: 30 bp above it */
            cf_style_t far = at;
            far.place = CF_PLACE_N;
            far.offset = 30;
            far.set |= CF_STYLE_OFFSET;
            assert_int_equal(cf_figure_add_label(fig, 2, 0, "W", &far), 0);
        }
        if (k == 5) { /* A's label right of B's point, nearer B */
            cf_style_t e = at;
            e.place = CF_PLACE_E;
            e.offset = 6;
            e.set |= CF_STYLE_OFFSET;
            assert_int_equal(cf_figure_add_label(fig, 1, 0.5, "A", &e), 0);
            assert_int_equal(cf_figure_add_label(fig, 1.4, 0.5, "B", &e), 0);
        }
        if (k != 3)
            assert_true(check_figure(fig, "negative") > 0);
        else
            assert_int_equal(check_figure(fig, "clean"), 0);
        cf_figure_destroy(fig);
    }
}

/* A label found on ink stays part of the ink the later labels avoid:
** "WWWW" put by hand just above the stroke (touching it), then labels
** placed automatically at points under it; none of their glyphs may lie on its glyphs.  (The
** label on the stroke was once left out of the placement's raster: the
** others then took the places on it.) */
static void
test_avoids_label_on_ink(void **state)
{
    static const double line[] = { 0, 0, 4, 0 };
    cf_figure_t *fig;
    cf_style_t at;
    cf__layout_t lay;
    cf__dl_t dl;
    mask_t masks[8];
    double pw, ph;
    size_t i, nt = 0, k;
    int w, h;
    (void)state;
    cf_style_init(&at);
    at.place = CF_PLACE_N;
    at.offset = 0;
    at.set |= CF_STYLE_PLACE | CF_STYLE_OFFSET;
    assert_int_equal(cf_figure_create(40, 30, CF_UNIT_MM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_polyline(fig, line, 2, false, NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, 2, 0, "WWWW", &at), 0);
    for (k = 0; k < 4; k++)
        assert_int_equal(cf_figure_add_label(fig, 1.7 + 0.2 * (double)k,
                                             0, "a", NULL), 0);
    cf__dl_init(&dl);
    assert_int_equal(cf__figure_layout(fig, &lay), CF_STATUS_OK);
    assert_int_equal(cf__figure_build(fig, &lay, &dl), CF_STATUS_OK);
    cf_figure_get_size(fig, &pw, &ph);
    w = (int)ceil(pw * RES);
    h = (int)ceil(ph * RES);
    for (i = 0; i < dl.count && nt < 8; i++)
        if (dl.ops[i].kind == CF__OP_TEXT)
            text_mask(&dl, i, w, h, &masks[nt++]);
    assert_int_equal(nt, 5);
    assert_string_equal(masks[0].src, "WWWW");
    for (k = 1; k < nt; k++)
        assert_int_equal(mask_on_mask(&masks[k], &masks[0]), 0);
    assert_non_null(strstr(cf_figure_warnings(fig), "\"WWWW\""));
    for (k = 0; k < nt; k++)
        free(masks[k].a);
    cf__dl_free(&dl);
    cf_figure_destroy(fig);
}

/* A label with a character no font of the figure has (U+10FFFD, a
** noncharacter: no font has a glyph for it) is drawn with an empty box:
** the figure warns, naming the label and the count, after the layout
** (whose placement makes its warnings again) and once; a label every
** font covers does not warn. */
static void
test_warns_missing_glyphs(void **state)
{
    static const double line[] = { 0, 0, 4, 3 };
    cf_figure_t *fig = NULL;
    cf__layout_t lay;
    cf__dl_t dl;
    const char *w, *hit;
    (void)state;
    assert_int_equal(cf_figure_create(40, 30, CF_UNIT_MM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_polyline(fig, line, 2, false, NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, 1, 2, "P_0", NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, 3, 1,
                                         "x \xf4\x8f\xbf\xbd y", NULL), 0);
    cf__dl_init(&dl);
    assert_int_equal(cf__figure_layout(fig, &lay), CF_STATUS_OK);
    assert_int_equal(cf__figure_build(fig, &lay, &dl), CF_STATUS_OK);
    w = cf_figure_warnings(fig);
    hit = strstr(w, "1 character no font of");
    assert_non_null(hit);
    assert_non_null(strstr(w, "label \"x \xf4\x8f\xbf\xbd y\""));
    assert_null(strstr(hit + strlen("1 character no font of"),
                       "no font of"));   /* once */
    assert_null(strstr(w, "\"P_0\""));
    cf__dl_free(&dl);
    cf_figure_destroy(fig);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_detects),
        cmocka_unit_test(test_no_label_on_ink),
        cmocka_unit_test(test_avoids_label_on_ink),
        cmocka_unit_test(test_warns_missing_glyphs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
