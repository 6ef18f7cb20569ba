/*
** The Bernstein basis: values, derivatives, power <-> Bernstein matrices and
** Bernstein's approximation of a function.
*/
#include <math.h>
#include <string.h>

#include "curvefig/bernstein.h"
#include "bezier-private.h"
#include "numtext-private.h"

#define MAXN CF_BEZIER_MAX_DEGREE
#define MAXM CF_BERNSTEIN_MATRIX_MAX_DEGREE

/* The degree, and t by the domain rule on [0, 1] (clamped). */
static cf_status_t
check_nt(int n, double *t)
{
    if (n < 0 || n > MAXN)
        return CF_STATUS_BAD_DEGREE;
    return cf__bezier_check_param(t);
}

/* out[0..n]: the recurrence B_i^m = (1-t) B_i^(m-1) + t B_(i-1)^(m-1),
** in place from the top. */
static void
all_values(int n, double t, double *out)
{
    double s = 1.0 - t;
    out[0] = 1.0;
    for (int m = 1; m <= n; m++) {
        out[m] = t * out[m - 1];
        for (int i = m - 1; i >= 1; i--)
            out[i] = s * out[i] + t * out[i - 1];
        out[0] = s * out[0];
    }
}

cf_status_t
cf_bernstein_all(int n, double t, double *out)
{
    cf_status_t st = check_nt(n, &t);
    if (st != CF_STATUS_OK)
        return st;
    if (out == NULL)
        return CF_STATUS_INVALID_ARG;
    all_values(n, t, out);
    return CF_STATUS_OK;
}

cf_status_t
cf_bernstein_value(int n, int i, double t, double *out)
{
    double v[MAXN + 1];
    cf_status_t st = check_nt(n, &t);
    if (st != CF_STATUS_OK)
        return st;
    if (out == NULL)
        return CF_STATUS_INVALID_ARG;
    if (i < 0 || i > n) {
        *out = 0.0;
        return CF_STATUS_OK;
    }
    all_values(n, t, v);
    *out = v[i];
    return CF_STATUS_OK;
}

cf_status_t
cf_bernstein_all_deriv(int n, double t, int k, double *out)
{
    cf_status_t st = check_nt(n, &t);
    int m;
    if (st != CF_STATUS_OK)
        return st;
    if (out == NULL || k < 0)
        return CF_STATUS_INVALID_ARG;
    if (k > n) {
        memset(out, 0, ((size_t)n + 1) * sizeof *out);
        return CF_STATUS_OK;
    }
    m = n - k;
    all_values(m, t, out);
    /* d/dt B_i^(m+1) = (m+1) (B_(i-1)^m - B_i^m), zero outside 0..m */
    for (; m < n; m++) {
        double f = (double)(m + 1);
        out[m + 1] = f * out[m];
        for (int i = m; i >= 1; i--)
            out[i] = f * (out[i - 1] - out[i]);
        out[0] = -f * out[0];
    }
    return CF_STATUS_OK;
}

cf_status_t
cf_bernstein_eval(int n, const double *coef, double t, double *out)
{
    double v[MAXN + 1];
    cf_status_t st = check_nt(n, &t);
    if (st != CF_STATUS_OK)
        return st;
    if (coef == NULL || out == NULL)
        return CF_STATUS_INVALID_ARG;
    memcpy(v, coef, ((size_t)n + 1) * sizeof *v);
    *out = cf__bp_decasteljau(v, n, t);
    return CF_STATUS_OK;
}

static cf_status_t
check_matrix_degree(int n, const void *p, cf_diag_t *diag)
{
    if (n < 0 || n > MAXM)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "degree %d is outside 0..%d for the basis "
                         "conversion", n, MAXM);
    if (p == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "an array argument is NULL");
    return CF_STATUS_OK;
}

/* M[j][i]: coefficient of t^j in B_i^n */
static double
m_entry(int n, int j, int i)
{
    if (j < i)
        return 0.0;
    return ((j - i) % 2 ? -1.0 : 1.0) * cf__binomial(n, i) *
           cf__binomial(n - i, j - i);
}

/* M^-1[i][j]: coefficient of B_i^n in t^j */
static double
minv_entry(int n, int i, int j)
{
    return i < j ? 0.0 : cf__binomial(i, j) / cf__binomial(n, j);
}

typedef double (*entry_fn)(int n, int r, int c);

static void
fill(int n, double *M, entry_fn e)
{
    size_t n1 = (size_t)n + 1;
    for (int r = 0; r <= n; r++)
        for (int c = 0; c <= n; c++)
            M[(size_t)r * n1 + (size_t)c] = e(n, r, c);
}

/* out = E in, E lower triangular */
static void
apply(int n, entry_fn e, const double *in, double *out)
{
    for (int r = 0; r <= n; r++) {
        double s = 0.0;
        for (int c = 0; c <= r; c++)
            s += e(n, r, c) * in[c];
        out[r] = s;
    }
}

cf_status_t
cf_bernstein_to_power_matrix(int n, double *M, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = check_matrix_degree(n, M, diag);
    if (st != CF_STATUS_OK)
        return st;
    fill(n, M, m_entry);
    return CF_STATUS_OK;
}

cf_status_t
cf_power_to_bernstein_matrix(int n, double *Minv, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = check_matrix_degree(n, Minv, diag);
    if (st != CF_STATUS_OK)
        return st;
    fill(n, Minv, minv_entry);
    return CF_STATUS_OK;
}

/*
** sum_j a_j t^j = [1 t ..] a = [B] M^-1 a, so b = M^-1 a:
**   b_i = sum_{j <= i} C(i,j)/C(n,j) a_j.
** sum_i b_i B_i = [1 t ..] M b, so a = M b:
**   a_j = sum_{i <= j} (-1)^(j-i) C(n,i) C(n-i,j-i) b_i.
*/
cf_status_t
cf_bernstein_from_power(int n, const double *a, double *b, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = check_matrix_degree(n, a, diag);
    if (st == CF_STATUS_OK)
        st = check_matrix_degree(n, b, diag);
    if (st != CF_STATUS_OK)
        return st;
    cf__bp_from_power(a, n, 1.0, b);
    return CF_STATUS_OK;
}

cf_status_t
cf_bernstein_to_power(int n, const double *b, double *a, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = check_matrix_degree(n, a, diag);
    if (st == CF_STATUS_OK)
        st = check_matrix_degree(n, b, diag);
    if (st != CF_STATUS_OK)
        return st;
    apply(n, m_entry, b, a);
    return CF_STATUS_OK;
}

cf_status_t
cf_bernstein_approx(cf_real_func_t f, void *ud, int n, double *coef,
                    cf_diag_t *diag)
{
    cf_diag_clear(diag);
    if (f == NULL || coef == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "the function or the coefficient array is NULL");
    if (n < 1 || n > MAXN)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "degree %d is outside 1..%d", n, MAXN);
    for (int i = 0; i <= n; i++) {
        double x = (double)i / (double)n, y = f(x, ud);
        if (!isfinite(y))
            return cf__error(diag, CF_STATUS_NOT_FINITE, i,
                             "f(%d/%d) = %s is not finite", i, n,
                             CF__NUM(y));
        coef[i] = y;
    }
    return CF_STATUS_OK;
}

cf_status_t
cf_bernstein_approx_curve(cf_real_func_t f, void *ud, int n,
                          cf_bezier_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    double coef[MAXN + 1];
    cf_bezier_t *c;
    cf_status_t st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "the output pointer is NULL");
    *out = NULL;
    st = cf_bernstein_approx(f, ud, n, coef, diag);
    if (st != CF_STATUS_OK)
        return st;
    c = cf__bezier_new(2, n, false);
    if (c == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory (approximation curve)");
    for (int i = 0; i <= n; i++) {
        c->pts[2 * i] = (double)i / (double)n;
        c->pts[2 * i + 1] = coef[i];
    }
    *out = c;
    return CF_STATUS_OK;
}
