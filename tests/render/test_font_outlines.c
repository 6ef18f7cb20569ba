/* The glyphs read from the font files (render/backends/font-outlines.h,
** over render/fontfile/outline.h) against cairo-ft and FreeType, the
** oracle: for every glyph of every face the labels use (LM Roman, Sans
** and Math at their optical sizes, CMU Serif and Sans, Noto Serif and
** Sans CJK SC), at several sizes, upright and slanted (a family without
** an italic: fontconfig's synthetic oblique, FC_MATRIX), the path
** cairo_glyph_path appends at a fractional origin (cairo_copy_path's
** data, every op and coordinate) and the ink extents
** cairo_scaled_font_glyph_extents reports must be the same doubles.  An
** emboldened face must be refused (it stays cairo's).  The CJK faces'
** 65,535 glyphs are all compared at one size, upright and slanted. */
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

#include "font-faces.h"
#include "font-glyphs.h"
#include "font-itemize.h"
#include "font-native.h"
#include "font-outlines.h"
#include "outline.h"
#include "testutil.h"

static cairo_t *
recording(void)
{
    cairo_surface_t *s = cairo_recording_surface_create(CAIRO_CONTENT_ALPHA,
                                                        NULL);
    cairo_t *cr = cairo_create(s);
    cairo_surface_destroy(s);
    return cr;
}

static bool
same_path(const cairo_path_t *a, const cairo_path_t *b)
{
    int i;
    if (a->status != b->status || a->num_data != b->num_data)
        return false;
    for (i = 0; i < a->num_data; i += a->data[i].header.length) {
        int k;
        if (a->data[i].header.type != b->data[i].header.type
            || a->data[i].header.length != b->data[i].header.length)
            return false;
        for (k = 1; k < a->data[i].header.length; k++)
            if (a->data[i + k].point.x != b->data[i + k].point.x
                || a->data[i + k].point.y != b->data[i + k].point.y) {
                printf("  at %d: %.17g %.17g / %.17g %.17g\n", i + k,
                       a->data[i + k].point.x, a->data[i + k].point.y,
                       b->data[i + k].point.x, b->data[i + k].point.y);
                return false;
            }
    }
    return true;
}

/* Every glyph of face f: the path and the extents; the number of glyphs
** compared. */
static unsigned
compare_face(cf__nface_t *f, cairo_t *ca, cairo_t *cb, bool all)
{
    cairo_scaled_font_t *sf = cf__nface_scaled(f);
    cf__olface_t *of;
    unsigned n, gid, step, compared = 0, bad = 0;
    assert_non_null(sf);
    assert_int_equal(cf__olface_open(f->face.file, f->face.index, &of), 0);
    n = cf__olface_num_glyphs(of);
    cf__olface_close(of);
    assert_true(cf__own_face(&f->face));
    step = (all ? 1 : 7) * tu_sample();
    for (gid = 0; gid < n; gid += step) {
        cairo_glyph_t g;
        cairo_text_extents_t ea, eb;
        cairo_path_t *pa, *pb;
        g.index = gid;
        g.x = 12.34567 + gid % 13 / 7.0;
        g.y = -3.21 + gid % 5 / 3.0;
        cairo_scaled_font_glyph_extents(sf, &g, 1, &ea);
        g.x = g.y = 0;
        cairo_scaled_font_glyph_extents(sf, &g, 1, &ea);
        assert_int_equal(cf__own_glyph_extents(&f->face, gid, &eb), 0);
        g.x = 12.34567 + gid % 13 / 7.0;
        g.y = -3.21 + gid % 5 / 3.0;
        cairo_new_path(ca);
        cairo_move_to(ca, 1, 2);
        cairo_set_scaled_font(ca, sf);
        cairo_glyph_path(ca, &g, 1);
        pa = cairo_copy_path(ca);
        cairo_new_path(cb);
        cairo_move_to(cb, 1, 2);
        assert_int_equal(cf__own_glyph_path(cb, &f->face, gid,
                                            cf__own_fixed(g.x),
                                            cf__own_fixed(g.y)), 0);
        pb = cairo_copy_path(cb);
        if (memcmp(&ea, &eb, 4 * sizeof(double)) != 0 || !same_path(pa, pb)) {
            if (bad++ < 5)
                printf("%s %u: glyph %u: extents %.17g %.17g %.17g %.17g / "
                       "%.17g %.17g %.17g %.17g, path %d / %d\n",
                       f->face.file, f->face.index, gid, ea.x_bearing,
                       ea.y_bearing, ea.width, ea.height, eb.x_bearing,
                       eb.y_bearing, eb.width, eb.height, pa->num_data,
                       pb->num_data);
        }
        cairo_path_destroy(pa);
        cairo_path_destroy(pb);
        compared++;
    }
    assert_int_equal(bad, 0);
    return compared;
}

static void
compare_set(const char *family, bool italic, bool bold, double size,
            bool all, unsigned *faces, unsigned *glyphs)
{
    cf__nfontset_t *set;
    cairo_t *ca = recording(), *cb = recording();
    cf__nface_t *f;
    cf__nfaces_lock();
    set = cf__nfontset_get(family, italic, bold, (int)(size * CF__FONT_SCALE),
                           cf__native_language());
    /* the first font of the set: the face the family names */
    f = set != NULL ? cf__nfontset_font(set, 0) : NULL;
    cf__nfaces_unlock();   /* before any assertion: one test, one thread */
    assert_non_null(f);
    if (f->face.emboldened) {
        assert_false(cf__own_face(&f->face));
    } else {
        *glyphs += compare_face(f, ca, cb, all);
        (*faces)++;
    }
    cairo_destroy(ca);
    cairo_destroy(cb);
}

static void
test_latin(void **state)
{
    static const char *const families[] = {
        "Latin Modern Roman", "LM Roman 7", "LM Roman 5", "LM Roman 12",
        "Latin Modern Sans", "LM Sans 8", "Latin Modern Math", "CMU Serif",
        "CMU Sans Serif"
    };
    static const double sizes[] = { 4.98, 9.96, 10.95, 17.28 };
    unsigned faces = 0, glyphs = 0;
    size_t f, z;
    int style;
    (void)state;
    cf__native_fonts.close(cf__native_fonts.open(cf__native_fonts.self));
    for (f = 0; f < sizeof families / sizeof families[0]; f++)
        for (z = 0; z < sizeof sizes / sizeof sizes[0]; z++)
            for (style = 0; style < 4; style++)
                compare_set(families[f], style & 1, style & 2, sizes[z],
                            true, &faces, &glyphs);
    printf("%u faces, %u glyphs: the same paths and extents as cairo-ft\n",
           faces, glyphs);
}

static void
test_cjk(void **state)
{
    static const char *const families[] = {
        "Noto Serif CJK SC", "Noto Sans CJK SC"
    };
    unsigned faces = 0, glyphs = 0;
    size_t f;
    (void)state;
    cf__native_fonts.close(cf__native_fonts.open(cf__native_fonts.self));
    for (f = 0; f < 2; f++) {
        compare_set(families[f], false, false, 9.96, true, &faces, &glyphs);
        compare_set(families[f], true, false, 9.96, true, &faces, &glyphs);
        compare_set(families[f], false, true, 14.4, false, &faces, &glyphs);
    }
    printf("%u faces, %u glyphs: the same paths and extents as cairo-ft\n",
           faces, glyphs);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_latin),
        cmocka_unit_test(test_cjk),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
