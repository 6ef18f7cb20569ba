/* The helpers the output tests share (test_output.c, test_output_png.c);
** static inline, as not every file uses each. */
#ifndef CURVEFIG_TESTS_TEST_OUTPUT_H
#define CURVEFIG_TESTS_TEST_OUTPUT_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmocka.h>
#include <cairo.h>
#include <librsvg/rsvg.h>
#include "curvefig/access.h"
#include "curvefig/figure.h"
#include "png-private.h"
#include "testutil.h"
#include "pngtest.h"
#include "spawn.h"

/* A figure with every kind of element and labels in four scripts. */
static inline cf_figure_t *
build_figure(bool transparent)
{
    double P[] = { 0, 5, 1, -1, 3, 0, 4, 3, 6, 10 }, tri[30];
    size_t counts[] = { 5, 4, 3, 2, 1 };
    cf_figure_t *fig = NULL;
    cf_bezier_t *c;
    cf_style_t s;
    cf_axes_t ax;
    cf_theme_t th;

    assert_int_equal(cf_figure_create(90, 70, CF_UNIT_MM, &fig, NULL), 0);
    if (transparent) {
        cf_figure_get_theme(fig, &th);
        th.background.a = 0;
        assert_int_equal(cf_figure_set_theme(fig, &th), 0);
    }
    assert_int_equal(cf_bezier_create(2, 4, P, NULL, &c, NULL), 0);
    assert_int_equal(cf_bezier_decasteljau(c, 0.75, tri), 0);
    assert_int_equal(cf_figure_add_hull(fig, P, 5, NULL), 0);
    assert_int_equal(cf_figure_add_net(fig, tri, counts, 5, NULL, NULL), 0);
    assert_int_equal(cf_figure_add_bezier(fig, c, NULL), 0);
    cf_style_init(&s);
    s.set = CF_STYLE_MARKER | CF_STYLE_MARKER_SIZE;
    s.marker = CF_MARKER_STAR;
    s.marker_size = 8;
    assert_int_equal(cf_figure_add_points(fig, tri + 28, 1, &s), 0);
    assert_int_equal(cf_figure_add_label(fig, 0, 5, "P_0", NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, 6, 10, "B_i^n(t)", NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, 3, 0, "\\omega_{k-1}", NULL),
                     0);
    assert_int_equal(cf_figure_add_label(fig, 1, -1,
                                         "k\xc5\x99ivka \xd0\x9a\xd1\x80"
                                         "\xd0\xb8\xd0\xb2\xd0\xb0\xd1\x8f"
                                         " \xe6\x9b\xb2\xe7\xba\xbf", NULL),
                     0);
    assert_int_equal(cf_figure_add_arrow(fig, 4, 3, 1, 2, NULL), 0);
    cf_axes_init(&ax);
    ax.xmin = -1;
    ax.xmax = 7;
    ax.ymin = -2;
    ax.ymax = 11;
    ax.xlabel = "x";
    ax.ylabel = "y";
    assert_int_equal(cf_figure_add_axes(fig, &ax, NULL), 0);
    assert_int_equal(cf_figure_set_title(fig, "de Casteljau <t = 3/4>"), 0);
    assert_int_equal(cf_figure_set_caption(fig, "Levels & the point C(t)"),
                     0);
    cf_bezier_destroy(c);
    return fig;
}

typedef struct blob {
    unsigned char *data;
    size_t size;
} blob_t;

static inline blob_t
render(cf_figure_t *fig, cf_format_t f, const cf_write_options_t *o)
{
    blob_t b;
    cf_diag_t d;
    cf_diag_clear(&d);
    if (cf_figure_render(fig, f, o, &b.data, &b.size, &d) != CF_STATUS_OK)
        fail_msg("render %s: %s", cf_format_extension(f), d.msg);
    return b;
}

static inline bool
blob_has(const blob_t *b, const char *s)
{
    size_t n = strlen(s), i;
    for (i = 0; i + n <= b->size; i++)
        if (memcmp(b->data + i, s, n) == 0)
            return true;
    return false;
}

static char tmpdir[64];

static inline int
make_tmpdir(void **state)
{
    (void)state;
    snprintf(tmpdir, sizeof tmpdir, "/tmp/cf-render-XXXXXX");
    return mkdtemp(tmpdir) == NULL ? -1 : 0;
}

static inline blob_t
read_file(const char *path)
{
    blob_t b = { NULL, 0 };
    FILE *f = fopen(path, "rb");
    long n;
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    b.data = malloc((size_t)n + 1);
    b.size = fread(b.data, 1, (size_t)n, f);
    fclose(f);
    return b;
}

/* ---- the tool's font configuration (render/tool/fonts.c) ---------------- */

static const char *tool_path;   /* argv[1]: the built curvefig, or NULL */

static inline int
remove_tmpdir(void **state)
{
    char cmd[128];
    (void)state;
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    return system(cmd) == 0 ? 0 : -1;
}

#endif
