/*
** bench-facet-order: the painting order of shading facets, before and
** after in one run.  "bsp" is the BSP tree alone (src/vis-bsp.c, the
** order before: on a closed surface its tree is nearly a chain, so its
** time grows with the square of the count); "grid" is the order of
** src/vis-order.c (image boxes in a grid, only overlapping pairs compared,
** the tree for cycles only).  The facets: a torus (R = 1, r = 0.4) cut
** into a uniform grid of a x b quads, two triangles each, with exact
** normals, seen from azimuth -50, elevation 35 (orthographic), so its
** back, front and inner side overlap; and the same torus with a plane
** through it (the plane's 2 x 200 triangles cross the tube: cycles that
** the tree splits).  Counts 10^3 .. 2 x 10^5; median of RUNS runs, the
** tree skipped beyond BSP_MAX facets (seconds there already, and growing
** with the square).  Prints the facets painted and the splits as
** checksums.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench-time.h"
#include "vis-private.h"

enum { RUNS = 3 };
#define PI 3.14159265358979323846
#define BSP_MAX 60000

static void
torus_point(double u, double v, double *p, double *n)
{
    double cu = cos(2 * PI * u), su = sin(2 * PI * u);
    double cv = cos(2 * PI * v), sv = sin(2 * PI * v);
    p[0] = (1.0 + 0.4 * cv) * cu;
    p[1] = (1.0 + 0.4 * cv) * su;
    p[2] = 0.4 * sv;
    n[0] = cv * cu;
    n[1] = cv * su;
    n[2] = sv;
}

static void
add(cf__facet_buf_t *fb, const double *p, const double *n, size_t surface)
{
    cf_facet_t f;
    memset(&f, 0, sizeof f);
    memcpy(f.p, p, sizeof f.p);
    memcpy(f.normal, n, sizeof f.normal);
    f.surface = surface;
    fb->items[fb->n++] = f;
}

/* A torus of about `count` facets (a x b quads, a = 2.5 b), with the plane
** z = 0.1 x + 0.05 y through it when `plane`. */
static void
make(cf__facet_buf_t *fb, size_t count, bool plane)
{
    size_t b = (size_t)sqrt((double)count / 5.0), a = count / (2 * b);
    size_t np = plane ? 400 : 0;
    fb->cap = 2 * a * b + np;
    fb->items = malloc(fb->cap * sizeof *fb->items);
    fb->n = 0;
    if (fb->items == NULL) {
        fprintf(stderr, "bench-facet-order: out of memory\n");
        exit(1);
    }
    for (size_t i = 0; i < a; i++)
        for (size_t j = 0; j < b; j++) {
            double P[4][3], N[4][3], p[9], n[9];
            for (int k = 0; k < 4; k++)
                torus_point((double)(i + (size_t)(k >> 1)) / (double)a,
                            (double)(j + (size_t)(k & 1)) / (double)b, P[k],
                            N[k]);
            static const int tri[2][3] = {{0, 2, 3}, {0, 3, 1}};
            for (int t = 0; t < 2; t++) {
                for (int c = 0; c < 3; c++) {
                    memcpy(p + 3 * c, P[tri[t][c]], sizeof P[0]);
                    memcpy(n + 3 * c, N[tri[t][c]], sizeof N[0]);
                }
                add(fb, p, n, 0);
            }
        }
    /* the plane: a strip of 200 x 1 quads over [-1.6, 1.6]^2 */
    for (size_t i = 0; i < np / 2; i++) {
        double x0 = -1.6 + 3.2 * (double)i / (double)(np / 2),
               x1 = -1.6 + 3.2 * (double)(i + 1) / (double)(np / 2);
        double c[4][2] = {{x0, -1.6}, {x1, -1.6}, {x0, 1.6}, {x1, 1.6}};
        double P[4][3], nn[3] = {-0.1, -0.05, 1.0}, p[9], n[9];
        for (int k = 0; k < 4; k++) {
            P[k][0] = c[k][0];
            P[k][1] = c[k][1];
            P[k][2] = 0.1 * c[k][0] + 0.05 * c[k][1];
        }
        static const int tri[2][3] = {{0, 1, 3}, {0, 3, 2}};
        for (int t = 0; t < 2; t++) {
            for (int k = 0; k < 3; k++) {
                memcpy(p + 3 * k, P[tri[t][k]], sizeof P[0]);
                memcpy(n + 3 * k, nn, sizeof nn);
            }
            add(fb, p, n, 1);
        }
    }
}

/* Seconds of one ordering (on a copy: the orderers append pieces), the
** facets painted and the splits. */
static double
run(const cf__facet_buf_t *src, const cf_view_t *v, const double *M,
    bool grid, size_t *painted, size_t *splits)
{
    cf__facet_buf_t fb = {NULL, src->n, src->n};
    size_t *order = NULL;
    fb.items = cf_alloc_array(src->n, sizeof *fb.items);
    if (fb.items == NULL) {
        fprintf(stderr, "bench-facet-order: out of memory\n");
        exit(1);
    }
    memcpy(fb.items, src->items, src->n * sizeof *fb.items);
    double t0 = now_s();
    cf_status_t st = grid
        ? cf__facet_order(&fb, v, M, 1e-9 * 4, &order, painted, splits)
        : cf__bsp_order(&fb, v, 1e-9 * 4, &order, painted, splits);
    double t = now_s() - t0;
    if (st != CF_STATUS_OK) {
        fprintf(stderr, "bench-facet-order: ordering failed (%s)\n",
                cf_status_to_string(st));
        exit(1);
    }
    cf_free(order);
    cf_free(fb.items);
    return t;
}

static double
median(const cf__facet_buf_t *fb, const cf_view_t *v, const double *M,
       bool grid, size_t *painted, size_t *splits)
{
    double t[RUNS];
    for (int r = 0; r < RUNS; r++)
        t[r] = run(fb, v, M, grid, painted, splits);
    qsort(t, RUNS, sizeof *t, cmp_double);
    return t[RUNS / 2];
}

int
main(void)
{
    static const size_t counts[] = {1000, 3000, 10000, 30000, 60000, 100000,
                                    200000};
    cf_view_t v;
    double M[16];
    if (cf_view_orthographic(&v, -50, 35, NULL) != CF_STATUS_OK)
        return 1;
    cf__view_matrix(&v, M);
    printf("%-12s %8s %12s %10s %12s %10s %8s\n", "facets", "", "bsp s",
           "splits", "grid s", "splits", "ratio");
    for (int plane = 0; plane < 2; plane++)
        for (size_t k = 0; k < sizeof counts / sizeof *counts; k++) {
            cf__facet_buf_t fb;
            size_t pb = 0, sb = 0, pg = 0, sg = 0;
            double tb = -1.0, tg;
            make(&fb, counts[k], plane != 0);
            if (fb.n <= BSP_MAX)
                tb = median(&fb, &v, M, false, &pb, &sb);
            tg = median(&fb, &v, M, true, &pg, &sg);
            if (tb >= 0)
                printf("%-12zu %8s %12.4f %10zu %12.4f %10zu %8.1f\n", fb.n,
                       plane ? "+plane" : "torus", tb, sb, tg, sg, tb / tg);
            else
                printf("%-12zu %8s %12s %10s %12.4f %10zu %8s\n", fb.n,
                       plane ? "+plane" : "torus", "-", "-", tg, sg, "-");
            fflush(stdout);
            free(fb.items);
        }
    return 0;
}
