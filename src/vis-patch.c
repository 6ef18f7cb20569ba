/* The patches of a scene: evaluation with derivatives and subdivision of
** their 4-homogeneous nets, on the stack (vis-private.h). */
#include <math.h>
#include <string.h>

#include "vis-private.h"

static size_t
tri(int n)
{
    return ((size_t)n + 1) * ((size_t)n + 2) / 2;
}

/* Index of b_ijk (k = n - i - j) in the order of surface-triangle.h. */
static size_t
tidx(int n, int i, int j)
{
    size_t r = (size_t)(n - i);
    return r * (r + 1) / 2 + (r - (size_t)j);
}

size_t
cf__vpatch_count(const cf__vpatch_t *p)
{
    return p->tri ? tri(p->n) : ((size_t)p->m + 1) * ((size_t)p->n + 1);
}

/*
** Bernstein values of degree m at s into B[0][i], first derivatives into
** B[1][i] (k >= 1), second into B[2][i] (k >= 2), from the bases of
** degrees m - 1, m - 2.  Inlined with constant degrees by tensor_h: the
** arithmetic is the same for every degree, so each specialisation rounds
** alike.
*/
CF__INLINE void
bernstein(int m, double s, int k, double B[3][CF__VIS_MAX_DEG + 1])
{
    double b[CF__VIS_MAX_DEG + 1], b1[CF__VIS_MAX_DEG + 1],
        b2[CF__VIS_MAX_DEG + 1];
    double r = 1.0 - s;
    b[0] = b1[0] = b2[0] = 1.0;
    for (int d = 1; d <= m; d++) {
        double prev = 0.0;
        for (int i = 0; i < d; i++) {
            double x = b[i];
            b[i] = prev + r * x;
            prev = s * x;
        }
        b[d] = prev;
        if (d == m - 2)
            for (int i = 0; i <= d; i++)
                b2[i] = b[i];
        if (d == m - 1)
            for (int i = 0; i <= d; i++)
                b1[i] = b[i];
    }
    for (int i = 0; i <= m; i++) {
        B[0][i] = b[i];
        if (k < 1)
            continue;
        B[1][i] = m >= 1 ? m * ((i > 0 ? b1[i - 1] : 0.0) -
                                (i < m ? b1[i] : 0.0))
                         : 0.0;
        if (k < 2)
            continue;
        if (m >= 2)
            B[2][i] = m * (m - 1) *
                      ((i >= 2 ? b2[i - 2] : 0.0) -
                       2.0 * (i >= 1 && i <= m - 1 ? b2[i - 1] : 0.0) +
                       (i <= m - 2 ? b2[i] : 0.0));
        else
            B[2][i] = 0.0;
    }
}

/*
** Homogeneous derivatives A[6][4] of a tensor net of degrees (m, n):
** 00, and with k >= 1 10 01, with k >= 2 20 11 02 (the others are left
** as they are).  Each sum starts at 0 and runs over i (rows) and j in
** order; inlined with constant m, n and k.
*/
CF__INLINE void
tensor_k(const double *net, int m, int n, double s, double t, int k,
         double A[6][4])
{
    double Bu[3][CF__VIS_MAX_DEG + 1], Bv[3][CF__VIS_MAX_DEG + 1];
    static const int oa[6] = {0, 1, 0, 2, 1, 0}, ob[6] = {0, 0, 1, 0, 1, 2};
    int ne = k >= 2 ? 6 : k >= 1 ? 3 : 1, nb = k >= 2 ? 3 : k + 1;
    /* the sums in S, not in the caller's A: a local array the unrolled
    ** loops keep in registers (A's zeroing was a call of memset in the
    ** WebAssembly module, 3 % of its exact run) */
    double S[6][4];
    bernstein(m, s, k, Bu);
    bernstein(n, t, k, Bv);
    for (int e = 0; e < ne; e++)
        for (int c = 0; c < 4; c++)
            S[e][c] = 0.0;
    for (int i = 0; i <= m; i++) {
        double R[3][4];
        const double *row = net + (size_t)i * ((size_t)n + 1) * 4;
        for (int b = 0; b < nb; b++)
            for (int c = 0; c < 4; c++)
                R[b][c] = 0.0;
        for (int j = 0; j <= n; j++)
            for (int b = 0; b < nb; b++)
                for (int c = 0; c < 4; c++)
                    R[b][c] += Bv[b][j] * row[4 * j + c];
        for (int e = 0; e < ne; e++)
            for (int c = 0; c < 4; c++)
                S[e][c] += Bu[oa[e]][i] * R[ob[e]][c];
    }
    for (int e = 0; e < ne; e++)
        for (int c = 0; c < 4; c++)
            A[e][c] = S[e][c];
}

/* tensor_k specialised for degrees 0 to 3 each way (those of nearly
** every figure). */
#define TENSOR_K(M, N)                                                     \
    CF__NO_COVERAGE static void tensor_##M##N(const double *net, double s, \
                                              double t, int k,             \
                                              double A[6][4])              \
    {                                                                      \
        if (k <= 0)                                                        \
            tensor_k(net, M, N, s, t, 0, A);                               \
        else if (k == 1)                                                   \
            tensor_k(net, M, N, s, t, 1, A);                               \
        else                                                               \
            tensor_k(net, M, N, s, t, 2, A);                               \
    }
#define TENSOR_ROW(M)                                                      \
    TENSOR_K(M, 0) TENSOR_K(M, 1) TENSOR_K(M, 2) TENSOR_K(M, 3)
TENSOR_ROW(0)
TENSOR_ROW(1)
TENSOR_ROW(2)
TENSOR_K(3, 0) TENSOR_K(3, 1) TENSOR_K(3, 2)

/* The bicubic patch, nearly every surface of the course and most of a
** hidden-line run's time (Newton's steps in cf__vpatch_locate): one copy
** per x86-64 level (CF__CLONED), whose four components go through the
** wider vectors of the level, the same operations on each. */
#if defined(__wasm_simd128__)
/* In the WebAssembly module (wasm SIMD): tensor_k's sums for degrees
** (3, 3), a point's four components as two pairs (x, y) and (z, w) in
** f64x2 vectors, the same multiplications and additions in the same order
** (simd128 has no fused multiply-add), so the same bits; the compiler's
** own vectorising of tensor_k moved half of them through scalar lanes. */
typedef double v2d __attribute__((vector_size(16)));

CF__INLINE v2d
v2d_load(const double *p)
{
    v2d v;
    memcpy(&v, p, sizeof v);
    return v;
}

CF__INLINE void
tensor_33_sums(const double *net, double s, double t, int k, v2d S[6][2])
{
    double Bu[3][CF__VIS_MAX_DEG + 1], Bv[3][CF__VIS_MAX_DEG + 1];
    static const int oa[6] = {0, 1, 0, 2, 1, 0}, ob[6] = {0, 0, 1, 0, 1, 2};
    int ne = k >= 2 ? 6 : k >= 1 ? 3 : 1, nb = k >= 2 ? 3 : k + 1;
    bernstein(3, s, k, Bu);
    bernstein(3, t, k, Bv);
    for (int e = 0; e < ne; e++)
        S[e][0] = S[e][1] = (v2d){0.0, 0.0};
    for (int i = 0; i <= 3; i++) {
        v2d R[3][2];
        const double *row = net + (size_t)i * 16;
        for (int b = 0; b < nb; b++)
            R[b][0] = R[b][1] = (v2d){0.0, 0.0};
        for (int j = 0; j <= 3; j++) {
            v2d p0 = v2d_load(row + 4 * j), p1 = v2d_load(row + 4 * j + 2);
            for (int b = 0; b < nb; b++) {
                v2d c = {Bv[b][j], Bv[b][j]};
                R[b][0] += c * p0;
                R[b][1] += c * p1;
            }
        }
        for (int e = 0; e < ne; e++) {
            v2d c = {Bu[oa[e]][i], Bu[oa[e]][i]};
            S[e][0] += c * R[ob[e]][0];
            S[e][1] += c * R[ob[e]][1];
        }
    }
}

CF__INLINE void
tensor_33_pairs(const double *net, double s, double t, int k, double A[6][4])
{
    v2d S[6][2];
    int ne = k >= 2 ? 6 : k >= 1 ? 3 : 1;
    tensor_33_sums(net, s, t, k, S);
    for (int e = 0; e < ne; e++)
        memcpy(A[e], S[e], sizeof S[e]);
}

/* cf__vpatch_eval of a bicubic patch with k <= 1 in pairs: the point and
** its first derivatives, (x, y) in a vector, z alone, the operations of
** cf__vpatch_eval below. */
CF__NO_COVERAGE static bool
eval_33_pairs(const double *net, double s, double t, int k, double *out)
{
    v2d S[6][2];
    if (k <= 0)
        tensor_33_sums(net, s, t, 0, S);
    else
        tensor_33_sums(net, s, t, 1, S);
    double w = S[0][1][1];
    if (!(w > 0.0))
        return false;
    v2d w2 = {w, w}, P = S[0][0] / w2;
    double Pz = S[0][1][0] / w;
    memcpy(out, &P, sizeof P);
    out[2] = Pz;
    if (k <= 0)
        return true;
    double ws = S[1][1][1], wt = S[2][1][1];
    v2d ws2 = {ws, ws}, wt2 = {wt, wt};
    v2d Ps = (S[1][0] - ws2 * P) / w2, Pt = (S[2][0] - wt2 * P) / w2;
    memcpy(out + 3, &Ps, sizeof Ps);
    out[5] = (S[1][1][0] - ws * Pz) / w;
    memcpy(out + 6, &Pt, sizeof Pt);
    out[8] = (S[2][1][0] - wt * Pz) / w;
    return true;
}
#endif

CF__INLINE void
tensor_33_body(const double *net, double s, double t, int k, double A[6][4])
{
#if defined(__wasm_simd128__)
    if (k <= 0)
        tensor_33_pairs(net, s, t, 0, A);
    else if (k == 1)
        tensor_33_pairs(net, s, t, 1, A);
    else
        tensor_33_pairs(net, s, t, 2, A);
#else
    if (k <= 0)
        tensor_k(net, 3, 3, s, t, 0, A);
    else if (k == 1)
        tensor_k(net, 3, 3, s, t, 1, A);
    else
        tensor_k(net, 3, 3, s, t, 2, A);
#endif
}
#ifdef CF__LEVELS
CF__CLONED(void, tensor_33,
           (const double *net, double s, double t, int k, double A[6][4]),
           (net, s, t, k, A), )
#else
/* one copy, left out of a fuzz build's coverage as the others are */
CF__NO_COVERAGE static void
tensor_33(const double *net, double s, double t, int k, double A[6][4])
{
    tensor_33_body(net, s, t, k, A);
}
#endif

typedef void (*tensor_fn)(const double *, double, double, int,
                          double[6][4]);
static const tensor_fn tensor_fns[16] = {
    tensor_00, tensor_01, tensor_02, tensor_03, tensor_10, tensor_11,
    tensor_12, tensor_13, tensor_20, tensor_21, tensor_22, tensor_23,
    tensor_30, tensor_31, tensor_32, tensor_33};

CF__NO_COVERAGE static void
tensor_h(const cf__vpatch_t *p, const double *net, double s, double t,
         int k, double A[6][4])
{
    if (p->m <= 3 && p->n <= 3)
        tensor_fns[p->m * 4 + p->n](net, s, t, k, A);
    else
        tensor_k(net, p->m, p->n, s, t, k > 2 ? 2 : k < 0 ? 0 : k, A);
}

/* Homogeneous derivatives of a triangular net, directions (1, 0, -1) and
** (0, 1, -1), by de Casteljau down to level n - 2. */
CF__NO_COVERAGE static void
tri_h(const cf__vpatch_t *p, const double *net, double u, double v, int k,
      double A[6][4])
{
    double buf[((CF__VIS_TRI_MAX_DEG + 1) * (CF__VIS_TRI_MAX_DEG + 2) / 2) *
               4];
    int n = p->n, stop = n >= 2 ? 2 : n;
    double w = 1.0 - u - v;
    memcpy(buf, net, tri(n) * 4 * sizeof(double));
    for (int d = n; d > stop; d--) {
        /* level of degree d -> d - 1 */
        for (int i = d - 1; i >= 0; i--)
            for (int j = d - 1 - i; j >= 0; j--) {
                double *o = buf + 4 * tidx(d - 1, i, j);
                const double *a = buf + 4 * tidx(d, i + 1, j);
                const double *b = buf + 4 * tidx(d, i, j + 1);
                const double *c = buf + 4 * tidx(d, i, j);
                for (int e = 0; e < 4; e++)
                    o[e] = u * a[e] + v * b[e] + w * c[e];
            }
    }
    /* buf holds degree `stop` in place (indices by tidx(stop, ...)) */
    memset(A, 0, 6 * 4 * sizeof(double));
    if (stop == 0) {
        memcpy(A[0], buf, 4 * sizeof(double));
        return;
    }
    if (stop == 1) {
        const double *a = buf + 4 * tidx(1, 1, 0), *b = buf + 4 * tidx(1, 0, 1),
                     *c = buf + 4 * tidx(1, 0, 0);
        for (int e = 0; e < 4; e++) {
            A[0][e] = u * a[e] + v * b[e] + w * c[e];
            A[1][e] = a[e] - c[e];
            A[2][e] = b[e] - c[e];
        }
        return;
    }
    /* degree 2: q_ijk, i + j + k = 2 */
    const double *q200 = buf + 4 * tidx(2, 2, 0), *q020 = buf + 4 * tidx(2, 0, 2),
                 *q002 = buf + 4 * tidx(2, 0, 0), *q110 = buf + 4 * tidx(2, 1, 1),
                 *q101 = buf + 4 * tidx(2, 1, 0), *q011 = buf + 4 * tidx(2, 0, 1);
    double nn = n, n2 = (double)n * (n - 1);
    for (int e = 0; e < 4; e++) {
        double a = u * q200[e] + v * q110[e] + w * q101[e];   /* level n-1 */
        double b = u * q110[e] + v * q020[e] + w * q011[e];
        double c = u * q101[e] + v * q011[e] + w * q002[e];
        A[0][e] = u * a + v * b + w * c;
        A[1][e] = nn * (a - c);
        A[2][e] = nn * (b - c);
        if (k >= 2) {
            A[3][e] = n2 * (q200[e] - 2.0 * q101[e] + q002[e]);
            A[4][e] = n2 * (q110[e] - q101[e] - q011[e] + q002[e]);
            A[5][e] = n2 * (q020[e] - 2.0 * q011[e] + q002[e]);
        }
    }
}

CF__NO_COVERAGE bool
cf__vpatch_eval(const cf__vpatch_t *p, const double *net, double s,
                double t, int k, double *out)
{
    double A[6][4];
#if defined(__wasm_simd128__)
    if (!p->tri && p->m == 3 && p->n == 3 && k <= 1)
        return eval_33_pairs(net, s, t, k, out);
#endif
    if (p->tri)
        tri_h(p, net, s, t, k, A);
    else
        tensor_h(p, net, s, t, k, A);
    double w = A[0][3];
    if (!(w > 0.0))
        return false;
    if (k <= 0) {
        for (int c = 0; c < 3; c++)
            out[c] = A[0][c] / w;
        return true;
    }
    double ws = A[1][3], wt = A[2][3];
    for (int c = 0; c < 3; c++) {
        double P = A[0][c] / w;
        double Ps = (A[1][c] - ws * P) / w, Pt = (A[2][c] - wt * P) / w;
        out[c] = P;
        out[3 + c] = Ps;
        out[6 + c] = Pt;
        if (k >= 2) {
            out[9 + c] = (A[3][c] - 2.0 * ws * Ps - A[3][3] * P) / w;
            out[12 + c] =
                (A[4][c] - ws * Pt - wt * Ps - A[4][3] * P) / w;
            out[15 + c] = (A[5][c] - 2.0 * wt * Pt - A[5][3] * P) / w;
        }
    }
    return true;
}

/* Halve count curves of degree d (points `stride` apart, curves `step`
** apart) at 1/2. */
CF__NO_COVERAGE static void
halve(const double *src, int d, size_t count, size_t step, size_t stride,
      double *lo, double *hi)
{
    double tmp[(CF__VIS_MAX_DEG + 1) * 4];
    for (size_t c = 0; c < count; c++) {
        const double *s = src + c * step;
        for (int i = 0; i <= d; i++)
            memcpy(tmp + 4 * i, s + (size_t)i * stride, 4 * sizeof(double));
        for (int l = 0; l <= d; l++) {
            memcpy(lo + c * step + (size_t)l * stride, tmp, 4 * sizeof(double));
            memcpy(hi + c * step + (size_t)(d - l) * stride,
                   tmp + 4 * (d - l), 4 * sizeof(double));
            for (int i = 0; i < d - l; i++)
                for (int e = 0; e < 4; e++)
                    tmp[4 * i + e] = 0.5 * (tmp[4 * i + e] + tmp[4 * i + 4 + e]);
        }
    }
}

CF__NO_COVERAGE void
cf__vnet_split(const double *net, int m, int n, int dir, double *lo,
               double *hi)
{
    size_t row = ((size_t)n + 1) * 4;
    if (dir == 0)   /* curves in s: column j, points a row apart */
        halve(net, m, (size_t)n + 1, 4, row, lo, hi);
    else            /* curves in t: row i */
        halve(net, n, (size_t)m + 1, row, 4, lo, hi);
}

/* b_ijk of a net with its corners reordered: new corner c is old corner
** perm[c], so new (e0, e1, e2) is old with e_old[perm[c]] = e_new[c]. */
CF__NO_COVERAGE static void
permute(const double *src, int n, const int perm[3], double *dst)
{
    for (int i = n; i >= 0; i--)
        for (int j = n - i; j >= 0; j--) {
            int e[3] = {i, j, n - i - j}, o[3];
            for (int c = 0; c < 3; c++)
                o[perm[c]] = e[c];
            memcpy(dst + 4 * tidx(n, i, j), src + 4 * tidx(n, o[0], o[1]),
                   4 * sizeof(double));
        }
}

/*
** Split at the middle of edge a-b.  The net is first permuted so that the
** edge runs from corner 0 to corner 1, then de Casteljau at (1/2, 1/2, 0)
** gives the part (p, b_0n0, b_00n) as b^i_0jk and (b_n00, p, b_00n) as
** b^j_i0k (surface-triangle.h, cf_bezier_triangle_subdivide).
*/
CF__NO_COVERAGE void
cf__vtri_split(const double *net, int n, int a, int b, double *lo,
               int perm_lo[3], double *hi, int perm_hi[3])
{
    enum { NT = (CF__VIS_TRI_MAX_DEG + 1) * (CF__VIS_TRI_MAX_DEG + 2) / 2 };
    double P[NT * 4], L[NT * 4];
    int c = 3 - a - b, perm[3] = {a, b, c};
    permute(net, n, perm, P);
    /* level l: points of degree n - l, b^l_ijk; keep whole levels */
    for (int l = 0; l <= n; l++) {
        int d = n - l;
        for (int i = d; i >= 0; i--)
            for (int j = d - i; j >= 0; j--) {
                int k = d - i - j;
                double *o = L + 4 * tidx(d, i, j);
                if (l == 0) {
                    memcpy(o, P + 4 * tidx(n, i, j), 4 * sizeof(double));
                } else {
                    /* from the previous level, saved in P */
                    const double *x = P + 4 * tidx(d + 1, i + 1, j);
                    const double *y = P + 4 * tidx(d + 1, i, j + 1);
                    for (int e = 0; e < 4; e++)
                        o[e] = 0.5 * (x[e] + y[e]);
                }
                /* lo (new corner 0 is p): b^i_0jk at new index (l, j, k)
                ** when i == 0; hi: b^j_i0k when j == 0 */
                if (i == 0)
                    memcpy(lo + 4 * tidx(n, l, j), o, 4 * sizeof(double));
                if (j == 0)
                    memcpy(hi + 4 * tidx(n, i, l), o, 4 * sizeof(double));
                (void)k;
            }
        memcpy(P, L, tri(d) * 4 * sizeof(double));
    }
    /* lo has corners (p, old b, old c); hi (old a, p, old c) */
    perm_lo[0] = 3;
    perm_lo[1] = b;
    perm_lo[2] = c;
    perm_hi[0] = a;
    perm_hi[1] = 3;
    perm_hi[2] = c;
}
