/* The surfaces' products of an exact run on a page cropped to its ink
** (render/figure/surface-lines.h, cf__tol_make): for every shipped figure
** with a scene, written as SVG, the scene the drawing used was made
** within the drawing's own tolerance (20 times the layout's: never
** looser than it asks), and within 10 % of it (not the rough first
** refit's, ten times looser); the interactive patch's drawing took the
** scene its ink refits made (made below its own tolerance: one scene a
** run, not two), and the patch laid out again makes nothing new; and so
** at 44 views of the patch (turned as a reader turns it in the page: the
** drawing's tolerance falls by 5 % from the second refit's in some, which
** made a second scene before fig->refit_drop).  And the memory of the
** label placement's rasters, which the refits of one layout share, is
** freed once the layout is final: every shipped figure written as PDF
** and SVG holds none of it (markova-2.17's PDF then needs one 2 MiB page
** of heap, not two: docs/performance.md). */
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

#include "curvefig/output.h"
#include "layout-private.h"
#include "model.h"
#include "script.h"
#include "shipped.h"
#include "testutil.h"

typedef struct tally {
    char dir[64];
    size_t scenes, reused;
    bool patch_seen, patch_reused;
} tally_t;

static int
check(void *ctx, const char *script, const char *name, cf_figure_t *fig)
{
    tally_t *t = ctx;
    char base[128];
    cf_diag_t d;
    cf__layout_t lay;
    int faults = 0;
    snprintf(base, sizeof base, "%s/%s", t->dir, name);
    if (cf_figure_write_all(fig, base, CF_FORMAT_BIT(CF_FORMAT_SVG), NULL,
                            &d) != CF_STATUS_OK) {
        printf("# %s (%s): %s\n", name, script, d.msg);
        return 1;
    }
    snprintf(base, sizeof base, "%s/%s.svg", t->dir, name);
    unlink(base);
    if (fig->scene == NULL)
        return 0;
    struct cf_scene *sc = fig->scene;
    double made = fig->scene_tol;
    /* the layout again (its refits take what the drawing used) */
    if (cf__figure_layout(fig, &lay) != CF_STATUS_OK) {
        printf("# %s: the layout again failed\n", name);
        return 1;
    }
    double want = 20 * lay.tol;
    t->scenes++;
    if (!(made <= want) || !(made >= 0.9 * want)) {
        printf("# %s (%s): the drawing's scene made at %.9g for %.9g\n",
               name, script, made, want);
        faults++;
    }
    t->reused += made < want;
    if (strcmp(name, "surface-patch") == 0) {
        t->patch_seen = true;
        t->patch_reused = made < want && fig->scene == sc &&
                          fig->scene_tol == made;
    }
    return faults;
}

static void
test_shipped_scenes(void **state)
{
    (void)state;
    tally_t t;
    size_t failed = 0;
    memset(&t, 0, sizeof t);
    snprintf(t.dir, sizeof t.dir, "/tmp/cf-refit-XXXXXX");
    assert_non_null(mkdtemp(t.dir));
    tu_each_shipped_figure_all(CF_SOURCE_ROOT, check, &t, &failed);
    printf("# %zu figures with a scene, %zu drawn with their refits' "
           "scene\n", t.scenes, t.reused);
    rmdir(t.dir);
    assert_int_equal(failed, 0);
    assert_true(t.scenes >= 10);
    assert_true(t.patch_seen);
    assert_true(t.patch_reused);
}

/* A figure written holds no placement rasters; those that placed
** labels are counted in *ctx. */
static int
released(void *ctx, const char *script, const char *name, cf_figure_t *fig)
{
    size_t *placed = ctx;
    char dir[] = "/tmp/cf-place-XXXXXX", base[128];
    cf_diag_t d;
    int faults = 0;
    assert_non_null(mkdtemp(dir));
    snprintf(base, sizeof base, "%s/%s", dir, name);
    if (cf_figure_write_all(fig, base,
                            CF_FORMAT_BIT(CF_FORMAT_PDF)
                                | CF_FORMAT_BIT(CF_FORMAT_SVG), NULL,
                            &d) != CF_STATUS_OK) {
        printf("# %s (%s): %s\n", name, script, d.msg);
        faults = 1;
    }
    if (fig->place_px != NULL || fig->place_px_size != 0) {
        printf("# %s (%s): %zu bytes of placement rasters held after "
               "writing\n", name, script, fig->place_px_size);
        faults++;
    }
    *placed += fig->placed;
    snprintf(base, sizeof base, "%s/%s.pdf", dir, name);
    unlink(base);
    snprintf(base, sizeof base, "%s/%s.svg", dir, name);
    unlink(base);
    rmdir(dir);
    return faults;
}

static void
test_placement_memory_released(void **state)
{
    (void)state;
    size_t placed = 0, failed = 0;
    tu_each_shipped_figure_all(CF_SOURCE_ROOT, released, &placed, &failed);
    printf("# %zu figures placed labels\n", placed);
    assert_int_equal(failed, 0);
    assert_true(placed >= 40);
}

/* The interactive patch's script with its view set to (az, el), written
** as SVG: whether its drawing took the scene its refits made. */
static bool
patch_view_reused(const char *code, const char *dir, double az, double el)
{
    const char *at = strstr(code, "view = { -55, 28 }");
    size_t n = strlen(code);
    char *text = malloc(n + 64), base[128];
    cf_script_t *sc = NULL;
    cf_diag_t d;
    cf__layout_t lay;
    bool ok = false;
    assert_non_null(at);
    assert_non_null(text);
    snprintf(text, n + 64, "%.*sview = { %g, %g }%s", (int)(at - code), code,
             az, el, at + strlen("view = { -55, 28 }"));
    assert_int_equal(cf_script_create(NULL, NULL, &sc, NULL), 0);
    if (cf_script_run_string(sc, text, "surface-patch.lua") != CF_STATUS_OK)
        fail_msg("view (%g, %g): %s", az, el, cf_script_error(sc));
    cf_figure_t *fig = cf_script_figure(sc, 0);
    snprintf(base, sizeof base, "%s/patch", dir);
    assert_int_equal(cf_figure_write_all(fig, base,
                                         CF_FORMAT_BIT(CF_FORMAT_SVG), NULL,
                                         &d), CF_STATUS_OK);
    snprintf(base, sizeof base, "%s/patch.svg", dir);
    unlink(base);
    if (fig->scene != NULL && cf__figure_layout(fig, &lay) == CF_STATUS_OK) {
        double made = fig->scene_tol, want = 20 * lay.tol;
        ok = made < want && made >= 0.9 * want;
        if (!ok)
            printf("# view (%g, %g): the drawing's scene made at %.9g for "
                   "%.9g\n", az, el, made, want);
    }
    cf_script_destroy(sc);
    free(text);
    return ok;
}

static void
test_patch_views(void **state)
{
    (void)state;
    char path[512], dir[64], *code;
    size_t views = 0, reused = 0;
    FILE *f;
    long len;
    snprintf(path, sizeof path, "%s/figures/interactive/surface-patch.lua",
             CF_SOURCE_ROOT);
    f = fopen(path, "rb");
    assert_non_null(f);
    assert_int_equal(fseek(f, 0, SEEK_END), 0);
    len = ftell(f);
    assert_true(len > 0);
    rewind(f);
    code = malloc((size_t)len + 1);
    assert_non_null(code);
    assert_int_equal(fread(code, 1, (size_t)len, f), (size_t)len);
    code[len] = 0;
    fclose(f);
    snprintf(dir, sizeof dir, "/tmp/cf-refit-XXXXXX");
    assert_non_null(mkdtemp(dir));
    /* the page's arrow keys from the printed view (5 degrees a press),
    ** and a sweep about the patch */
    for (int k = -10; k <= 11; k++, views++)
        reused += patch_view_reused(code, dir, -55 + 5 * k, 28);
    for (int az = -180; az < 180; az += 60)
        for (int el = -50; el <= 60; el += 30, views++)
            reused += patch_view_reused(code, dir, az, el);
    rmdir(dir);
    free(code);
    printf("# %zu views of the patch, %zu drawn with their refits' scene\n",
           views, reused);
    assert_int_equal(reused, views);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shipped_scenes),
        cmocka_unit_test(test_patch_views),
        cmocka_unit_test(test_placement_memory_released),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
