/* The refits of a page cropped to its ink (render/layout/layout.c): for
** every shipped figure, the layout stops within a few passes and the
** page it gives fills the size asked for.  The ink box is measured in
** whole 1/64 bp (cf__dl_ink), so the room of a figure whose ink edge
** sits on such a step moves by one unit from one pass to the next and
** back; with a tolerance below one unit (0.01 bp) such a layout settled
** only by chance (orazem-decasteljau: 7 passes, each a placement of the
** labels and a measure of the ink); and a room that converges slowly, or
** back and forth, took up to all 8 passes (example-inset: not settled,
** its page 0.36 bp taller than asked).  Now a pass that changes the room
** by less than one unit and 0.01 bp ends the refits, and each third room
** is extrapolated from the two before it: no figure takes more than 6
** passes (markova-2.16, whose labels change places as the scale
** changes, and markova-2.19, 8 before), and the page is the size asked
** for, in the dimension that limits the drawing, to within 4 such units
** (a change below the tolerance on both sides of the last pass, plus the
** ink box's rounding out on both sides), and nowhere larger. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/output.h"
#include "model.h"
#include "shipped.h"
#include "testutil.h"

#define MAX_PASSES 6
#define UNIT (1.0 / 64)
#define SLACK (4 * (UNIT + 0.01))

typedef struct tally {
    size_t figures, refined, passes, most;
    char worst[128];
} tally_t;

static int
check(void *ctx, const char *script, const char *name, cf_figure_t *fig)
{
    tally_t *t = ctx;
    cf_write_options_t o;
    cf_diag_t d;
    double box[4], pw, ph, w, h;
    int faults = 0;
    t->figures++;
    if (fig->page_mode != CF_PAGE_INK || fig->panels != NULL)
        return 0;
    cf_write_options_init(&o);
    if (cf_figure_ink_box(fig, &o, box, &pw, &ph, &d) != CF_STATUS_OK) {
        printf("# %s (%s): %s\n", name, script, d.msg);
        return 1;
    }
    cf_figure_get_size(fig, &w, &h);
    t->refined++;
    t->passes += (size_t)fig->layout_passes;
    if ((size_t)fig->layout_passes > t->most) {
        t->most = (size_t)fig->layout_passes;
        snprintf(t->worst, sizeof t->worst, "%s", name);
    }
    if (fig->layout_passes < 1 || fig->layout_passes > MAX_PASSES) {
        printf("# %s (%s): %d passes of the layout\n", name, script,
               fig->layout_passes);
        faults++;
    }
    if (!(pw <= w + SLACK && ph <= h + SLACK
          && fmin(fabs(pw - w), fabs(ph - h)) <= SLACK)) {
        printf("# %s (%s): a page of %.4f x %.4f bp for %.4f x %.4f\n",
               name, script, pw, ph, w, h);
        faults++;
    }
    return faults;
}

static void
test_shipped_refits(void **state)
{
    tally_t t;
    size_t failed = 0;
    (void)state;
    memset(&t, 0, sizeof t);
    tu_each_shipped_figure_all(CF_SOURCE_ROOT, check, &t, &failed);
    printf("# %zu figures, %zu cropped to their ink: %zu passes of their "
           "layouts, at most %zu (%s)\n", t.figures, t.refined, t.passes,
           t.most, t.worst);
    assert_int_equal(failed, 0);
    assert_true(t.refined >= 60);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shipped_refits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
