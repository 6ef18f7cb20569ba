/* The leaves that cf__scene_hidden leaves out without Newton
** (cf__leaf_clear, src/vis-clear.c): every leaf it clears holds no point
** that Newton from a grid of starts finds (in its region, on q, in front
** of zmin where it judges depth), and every answer of cf__scene_hidden
** (hidden or not, and the occluding surface) is the one it gives with
** every leaf's Newton run (the scene's test switch newton_all), at points
** of the silhouette, of iso-lines and of a grid in front of and behind the
** surface, over views from every side, orthographic and perspective, of a
** polynomial and of a rational bicubic patch. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/surface.h"
#include "curvefig/visibility.h"
#include "../../src/vis-private.h"

/* The patch of figures/interactive/surface-patch.lua (centred). */
static const double patch_pts[16][3] = {
    {0, 0, 0}, {0, 1, 0.6}, {0, 2, 0.6}, {0, 3, 0},
    {1, 0, 0.7}, {1, 1, 1.8}, {1, 2, 1.6}, {1, 3, 0.4},
    {2, 0, 0.6}, {2, 1, 1.5}, {2, 2, 2.0}, {2, 3, 0.7},
    {3, 0, 0}, {3, 1, 0.5}, {3, 2, 0.8}, {3, 3, 0.2}};

typedef struct tally {
    long points, hidden, cleared, leaves_checked;
} tally_t;

static cf_scene_t *
make_scene(const cf_view_t *view, bool rational, double tol)
{
    double P[16 * 3], W[16];
    cf_bezier_surface_t *s;
    cf_scene_t *sc;
    size_t id;
    for (int i = 0; i < 16; i++) {
        P[3 * i] = patch_pts[i][0] - 1.5;
        P[3 * i + 1] = patch_pts[i][1] - 1.5;
        P[3 * i + 2] = 1.6 * patch_pts[i][2] - 0.9;
        W[i] = 1.0 + 0.6 * ((i * 7) % 5) / 4.0;
    }
    assert_int_equal(cf_bezier_surface_create(3, 3, 3, P, rational ? W : NULL,
                                              &s, NULL),
                     0);
    assert_int_equal(cf_scene_create(view, tol, &sc, NULL), 0);
    assert_int_equal(cf_scene_add_bezier(sc, s, &id, NULL), 0);
    cf_bezier_surface_destroy(s);
    return sc;
}

/* Whether Newton from an 8 x 8 grid of starts over leaf l finds a point
** of it (in_region's slack) whose image is q and, with depth, whose depth
** exceeds zmin. */
static bool
newton_finds(const cf_scene_t *sc, const cf__vleaf_t *l, const double *q,
             double zmin, bool depth)
{
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 8; j++) {
            double s = l->r[0] + (i + 0.5) / 8.0 * (l->r[1] - l->r[0]),
                   t = l->r[2] + (j + 0.5) / 8.0 * (l->r[3] - l->r[2]);
            double st[2], h[3];
            if (!cf__vpatch_locate(sc, l->patch, q, s, t, st, h))
                continue;
            if (st[0] < l->r[0] - 1e-9 || st[0] > l->r[1] + 1e-9 ||
                st[1] < l->r[2] - 1e-9 || st[1] > l->r[3] + 1e-9)
                continue;
            if (!depth || h[2] > zmin)
                return true;
        }
    return false;
}

/* q: hidden alike with and without the cleared leaves; and each leaf
** that cf__leaf_clear clears for q is clear of Newton's points. */
static void
check_point(cf_scene_t *sc, const double *q, tally_t *tl)
{
    size_t occ_a = SIZE_MAX, occ_b = SIZE_MAX;
    cf__vself_t self = {false, 0, {0.0, 0.0}, 0.0};
    sc->newton_all = false;
    bool a = cf__scene_hidden(sc, q, &self, &occ_a);
    sc->newton_all = true;
    bool b = cf__scene_hidden(sc, q, &self, &occ_b);
    sc->newton_all = false;
    if (a != b || occ_a != occ_b)
        fail_msg("q = (%.17g, %.17g, %.17g): hidden %d (occluder %zu) with "
                 "leaves cleared, %d (%zu) with Newton on every leaf",
                 q[0], q[1], q[2], a, occ_a, b, occ_b);
    tl->points++;
    tl->hidden += a;
    double zmin = q[2] + sc->tol, scale = fmax(sc->size, 1e-300);
    for (size_t i = 0; i < sc->nleaf; i++) {
        const cf__vleaf_t *l = &sc->leaves[i];
        if (!l->fold || q[0] < l->lo[0] || q[0] > l->hi[0] ||
            q[1] < l->lo[1] || q[1] > l->hi[1] ||
            !cf__leaf_may_hold(l, q, scale))
            continue;
        for (int depth = 0; depth < 2; depth++) {
            if (!cf__leaf_clear(sc, l, q, zmin, depth == 1))
                continue;
            tl->leaves_checked++;
            tl->cleared += depth == 1;
            if (newton_finds(sc, l, q, zmin, depth == 1))
                fail_msg("leaf %zu cleared for q = (%.17g, %.17g, %.17g) "
                         "(depth %d) but Newton finds a point of it",
                         i, q[0], q[1], q[2], depth);
        }
    }
}

/* The view-space points of the scene's silhouette (the exact contour
** near its pieces' (u, v)), of iso-lines, and of a grid at depths in
** front of and behind the patch. */
static void
check_scene(cf_scene_t *sc, tally_t *tl)
{
    cf_silhouette_t *sil = NULL;
    assert_int_equal(cf_scene_silhouette(sc, SIZE_MAX, &sil, NULL), 0);
    for (size_t k = 0; k < sil->n; k++) {
        const cf_silhouette_piece_t *pc = &sil->items[k];
        for (int j = 0; j <= 24; j++) {
            double tau = j / 24.0, a = 1.0 - tau, uv[2], q[3];
            for (int e = 0; e < 2; e++)
                uv[e] = a * a * a * pc->uv[e] + 3 * a * a * tau * pc->uv[2 + e] +
                        3 * a * tau * tau * pc->uv[4 + e] +
                        tau * tau * tau * pc->uv[6 + e];
            if (cf__contour_point(sc, pc->surface, uv, q))
                check_point(sc, q, tl);
        }
    }
    cf_silhouette_destroy(sil);
    const cf__vpatch_t *p = &sc->patches[0];
    for (int i = 0; i <= 12; i++)
        for (int j = 0; j <= 48; j++) {
            double D[18], s = i / 12.0, t = j / 48.0;
            if (cf__vpatch_eval(p, p->g, s, t, 0, D))
                check_point(sc, D, tl);
            if (cf__vpatch_eval(p, p->g, t, s, 0, D))
                check_point(sc, D, tl);
        }
    for (int i = 0; i <= 16; i++)
        for (int j = 0; j <= 16; j++)
            for (int d = -1; d <= 1; d += 2) {
                double q[3] = {sc->size * (-0.6 + 1.2 * i / 16.0),
                               sc->size * (-0.6 + 1.2 * j / 16.0),
                               d * 0.3 * sc->size};
                check_point(sc, q, tl);
            }
}

static void
run_views(bool rational, bool perspective)
{
    tally_t tl = {0, 0, 0, 0};
    for (int az = -180; az < 180; az += 40)
        for (int el = -60; el <= 80; el += 35) {
            cf_view_t view;
            if (perspective)
                assert_int_equal(cf_view_perspective(&view, az + 5, el, 9.0,
                                                     NULL, NULL),
                                 0);
            else
                assert_int_equal(cf_view_orthographic(&view, az + 5, el,
                                                      NULL),
                                 0);
            cf_scene_t *sc = make_scene(&view, rational, 0.004);
            check_scene(sc, &tl);
            cf_scene_destroy(sc);
        }
    printf("# %s %s: %ld points (%ld hidden), %ld leaves cleared, %ld "
           "of them by depth\n",
           rational ? "rational" : "polynomial",
           perspective ? "perspective" : "orthographic", tl.points,
           tl.hidden, tl.leaves_checked, tl.cleared);
    /* not vacuous: the test clears leaves, with and without depth, and
    ** the points are both hidden and visible */
    assert_true(tl.cleared > 100);
    assert_true(tl.leaves_checked - tl.cleared > 10);
    assert_true(tl.hidden > tl.points / 20 && tl.hidden < tl.points);
}

static void
test_polynomial_orthographic(void **state)
{
    (void)state;
    run_views(false, false);
}

static void
test_polynomial_perspective(void **state)
{
    (void)state;
    run_views(false, true);
}

static void
test_rational_orthographic(void **state)
{
    (void)state;
    run_views(true, false);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_polynomial_orthographic),
        cmocka_unit_test(test_polynomial_perspective),
        cmocka_unit_test(test_rational_orthographic),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
