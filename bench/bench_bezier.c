/*
** Bézier workloads of docs/benchmarks.md: W1, W2, W1d, W7cubic, W7deg7.
*/
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "curvefig/bezier.h"

const bench_workload *bench_bezier_table(void);

enum {
    CURVES = 1000,
    PARAMS = 10000,
    CHUNK = 1000      /* parameters per call: the output stays in L1 */
};
_Static_assert(PARAMS % CHUNK == 0 && (2 * CHUNK) % 8 == 0,
               "chunks must tile the parameters and the partial sums");

typedef struct bez_state {
    cf_bezier_t *c[CURVES];
    int degree;
    double t[PARAMS];
    double s[CURVES];         /* W7 split parameters */
    double *out;              /* PARAMS points, or the W7 halves */
} bez_state;

static void
bez_teardown(void *p)
{
    bez_state *st = p;
    if (st == NULL)
        return;
    for (int i = 0; i < CURVES; i++)
        cf_bezier_destroy(st->c[i]);
    free(st->out);
    free(st);
}

/* 1000 curves of the given degree from the seed: curve by curve, point by
** point, x then y, each u01(); t_j = (j + 0.5) / 10000; W7 split
** parameters s_c = 0.05 + 0.9 u01() from seed 1007. */
static void *
bez_setup(int degree, uint64_t seed)
{
    bez_state *st = calloc(1, sizeof *st);
    bench_rng r = { seed }, rs = { 1007 };
    double P[2 * 8];
    if (st == NULL)
        return NULL;
    st->degree = degree;
    st->out = malloc(2 * (PARAMS > 2 * 8 * CURVES ? PARAMS : 2 * 8 * CURVES) *
                     sizeof *st->out);
    if (st->out == NULL) {
        bez_teardown(st);
        return NULL;
    }
    for (int i = 0; i < CURVES; i++) {
        for (int k = 0; k < 2 * (degree + 1); k++)
            P[k] = bench_rng_u01(&r);
        if (cf_bezier_create(2, degree, P, NULL, &st->c[i], NULL) !=
            CF_STATUS_OK) {
            bez_teardown(st);
            return NULL;
        }
    }
    for (int j = 0; j < PARAMS; j++)
        st->t[j] = (j + 0.5) / PARAMS;
    for (int i = 0; i < CURVES; i++)
        st->s[i] = 0.05 + 0.9 * bench_rng_u01(&rs);
    return st;
}

static void *
setup_cubic(void)
{
    return bez_setup(3, 1001);
}

static void *
setup_deg7(void)
{
    return bez_setup(7, 1002);
}

/* Sum of x and of y over CHUNK interleaved points (2 CHUNK doubles, a
** multiple of 8): eight partial sums over contiguous doubles, the even
** ones x and the odd ones y, so that the additions are independent. */
static void
add_sums(const double *p, double sum[2])
{
    double a[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    for (size_t i = 0; i < 2 * CHUNK; i += 8)
        for (int k = 0; k < 8; k++)
            a[k] += p[i + (size_t)k];
    sum[0] += ((a[0] + a[2]) + (a[4] + a[6]));
    sum[1] += ((a[1] + a[3]) + (a[5] + a[7]));
}

static int
run_eval(void *p, double sum[2])
{
    bez_state *st = p;
    sum[0] = sum[1] = 0.0;
    for (int i = 0; i < CURVES; i++)
        for (int j = 0; j < PARAMS; j += CHUNK) {
            if (cf_bezier_eval_many(st->c[i], st->t + j, CHUNK, st->out) !=
                CF_STATUS_OK)
                return 1;
            add_sums(st->out, sum);
        }
    return 0;
}

static int
run_deriv(void *p, double sum[2])
{
    bez_state *st = p;
    sum[0] = sum[1] = 0.0;
    for (int i = 0; i < CURVES; i++)
        for (int j = 0; j < PARAMS; j += CHUNK) {
            if (cf_bezier_eval_deriv_many(st->c[i], st->t + j, CHUNK, 1,
                                          st->out) != CF_STATUS_OK)
                return 1;
            add_sums(st->out, sum);
        }
    return 0;
}

/* Split every curve into its halves (kept in out); the checksum sums the
** split points c(s_c), the shared end of the two halves. */
static int
run_split(void *p, double sum[2])
{
    bez_state *st = p;
    size_t half = 2 * ((size_t)st->degree + 1);
    sum[0] = sum[1] = 0.0;
    for (int i = 0; i < CURVES; i++) {
        double *l = st->out + 2 * half * (size_t)i, *r = l + half;
        if (cf_bezier_split_into(st->c[i], st->s[i], l, r) != CF_STATUS_OK)
            return 1;
        sum[0] += r[0];
        sum[1] += r[1];
    }
    return 0;
}

static const bench_workload table[] = {
    { "W1", "eval_many cubic", "point", 1e7, setup_cubic, run_eval,
      bez_teardown, { 5035341.659929, 5023653.005949 } },
    { "W2", "eval_many degree 7", "point", 1e7, setup_deg7, run_eval,
      bez_teardown, { 4951980.846781, 4999713.383906 } },
    { "W1d", "eval_deriv_many cubic", "point", 1e7, setup_cubic, run_deriv,
      bez_teardown, { -68978.112615, -66656.194083 } },
    { "W7cubic", "split_into cubic", "split", 1e3, setup_cubic, run_split,
      bez_teardown, { 508.605159, 500.005368 } },
    { "W7deg7", "split_into degree 7", "split", 1e3, setup_deg7, run_split,
      bez_teardown, { 498.142052, 496.235320 } },
    { NULL, NULL, NULL, 0, NULL, NULL, NULL, { 0, 0 } },
};

const bench_workload *
bench_bezier_table(void)
{
    return table;
}
