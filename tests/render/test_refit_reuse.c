/* The surfaces' products of an exact run on a page cropped to its ink
** (render/figure/surface-lines.h, cf__tol_make): for every shipped figure
** with a scene, written as SVG, the scene the drawing used was made
** within the drawing's own tolerance (20 times the layout's: never
** looser than it asks), and within 10 % of it (not the rough first
** refit's, ten times looser); the interactive patch's drawing took the
** scene its ink refits made (made below its own tolerance: one scene a
** run, not two), and the patch laid out again makes nothing new. */
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

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shipped_scenes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
