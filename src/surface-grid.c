/* Evaluation of a B-spline surface on a grid of parameters, using the
** tensor structure (cf_bspline_surface_eval_grid, curvefig/surface.h). */
#include <stdint.h>
#include <string.h>

#include "surface-private.h"
#include "bspline-private.h"

#if defined(__SSE2__) && !defined(CF__SANITIZED)
#include <emmintrin.h>
#define CF__STREAM 1
#endif

/* Spans and basis functions (and first derivatives) of n parameters of
** one direction; t is clamped to the domain in place. */
static cf_status_t
bases(int p, const double *K, size_t nK, double a, double b, cf_dir_t dir,
      double *t, size_t n, size_t *span, double *N, double *dN)
{
    size_t w = (size_t)p + 1;
    for (size_t i = 0; i < n; i++) {
        cf_status_t st = cf__surf_param(a, b, &t[i], dir, NULL);
        if (st != CF_STATUS_OK)
            return st;
        span[i] = cf_knots_find_span(p, K, nK, t[i]);
        cf__basis_deriv(p, K, nK, NULL, span[i], t[i], 0, N + i * w);
        if (dN != NULL)
            cf__basis_deriv(p, K, nK, NULL, span[i], t[i], 1, dN + i * w);
    }
    return CF_STATUS_OK;
}

/* One output point: sum over the q + 1 active columns of row R (h doubles
** per column) with the weights N; generic in h. */
CF__INLINE void
combine(const double *R, const double *N, size_t qv, size_t h, double *acc)
{
    for (size_t c = 0; c < h; c++)
        acc[c] = 0.0;
    for (size_t j = 0; j < qv; j++)
        for (size_t c = 0; c < h; c++)
            acc[c] += N[j] * R[j * h + c];
}

/* The common case, bicubic in v and 3 doubles per point (3-D polynomial
** or 2-D rational): out[3 b ..] = sum_c N[4 b + c] R[3 (span[b] - 3 + c)]
** for every b, one tight loop per output array. */
CF__INLINE void
row43_body(const double *R, const double *N, const size_t *span, size_t nv,
           double *out)
{
    for (size_t b = 0; b < nv; b++) {
        const double *r = R + (span[b] - 3) * 3, *n = N + 4 * b;
        double *o = out + 3 * b;
        o[0] = n[0] * r[0] + n[1] * r[3] + n[2] * r[6] + n[3] * r[9];
        o[1] = n[0] * r[1] + n[1] * r[4] + n[2] * r[7] + n[3] * r[10];
        o[2] = n[0] * r[2] + n[1] * r[5] + n[2] * r[8] + n[3] * r[11];
    }
}

CF__CLONED(void, row43,
           (const double *R, const double *N, const size_t *span, size_t nv,
            double *out),
           (R, N, span, nv, out), )

/* Rows R = sum_r N_r P[su - p + r][*] (and dR with the derivatives). */
static void
rows(const cf_bspline_surface_t *s, size_t su, const double *N,
     const double *dN, double *R, double *dR)
{
    size_t len = s->nv * s->hdim;
    const double *P = s->P + (su - (size_t)s->p) * len;
    memset(R, 0, len * sizeof *R);
    if (dR != NULL)
        memset(dR, 0, len * sizeof *dR);
    for (int r = 0; r <= s->p; r++, P += len) {
        double n = N[r], d = dR != NULL ? dN[r] : 0.0;
        for (size_t x = 0; x < len; x++)
            R[x] += n * P[x];
        if (dR != NULL)
            for (size_t x = 0; x < len; x++)
                dR[x] += d * P[x];
    }
}

/* The same for the point and both partials at once: for each run of
** parameters in one span the 4 x 3 active row values and their u
** derivatives are loaded once. */
CF__INLINE void
row43_d1_body(const double *R, const double *dR, const double *N,
              const double *dN, const size_t *span, size_t nv, double *pts,
              double *su, double *sv)
{
    size_t b = 0;
    while (b < nv) {
        size_t e = b, o = (span[b] - 3) * 3;
        double r[12], d[12];
        while (e < nv && span[e] == span[b])
            e++;
        memcpy(r, R + o, sizeof r);
        memcpy(d, dR + o, sizeof d);
        for (; b < e; b++) {
            const double *n = N + 4 * b, *m = dN + 4 * b;
            for (int c = 0; c < 3; c++) {
                pts[3 * b + (size_t)c] = n[0] * r[c] + n[1] * r[3 + c] +
                                         n[2] * r[6 + c] + n[3] * r[9 + c];
                sv[3 * b + (size_t)c] = m[0] * r[c] + m[1] * r[3 + c] +
                                        m[2] * r[6 + c] + m[3] * r[9 + c];
                su[3 * b + (size_t)c] = n[0] * d[c] + n[1] * d[3 + c] +
                                        n[2] * d[6 + c] + n[3] * d[9 + c];
            }
        }
    }
}

CF__CLONED(void, row43_d1,
           (const double *R, const double *dR, const double *N,
            const double *dN, const size_t *span, size_t nv, double *pts,
            double *su, double *sv),
           (R, dR, N, dN, span, nv, pts, su, sv), )

static void
one_row(const cf_bspline_surface_t *s, const double *R, const double *dR,
        const size_t *sv, const double *Nv, const double *dNv, size_t nv,
        double *pts, double *su_out, double *sv_out)
{
    size_t h = s->hdim, dim = s->dim, qv = (size_t)s->q + 1;
    double A[64] = { 0 }, Au[64] = { 0 }, Av[64] = { 0 };
    if (qv == 4 && h == 3 && !s->rational && su_out != NULL &&
        sv_out != NULL) {
        row43_d1(R, dR, Nv, dNv, sv, nv, pts, su_out, sv_out);
        return;
    }
    if (qv == 4 && h == 3 && !s->rational) {
        row43(R, Nv, sv, nv, pts);
        if (su_out != NULL)
            row43(dR, Nv, sv, nv, su_out);
        if (sv_out != NULL)
            row43(R, dNv, sv, nv, sv_out);
        return;
    }
    for (size_t b = 0; b < nv; b++) {
        const double *Rb = R + (sv[b] - (size_t)s->q) * h;
        double *x = pts + b * dim;
        combine(Rb, Nv + b * qv, qv, h, A);
        if (su_out != NULL)
            combine(dR + (sv[b] - (size_t)s->q) * h, Nv + b * qv, qv, h, Au);
        if (sv_out != NULL)
            combine(Rb, dNv + b * qv, qv, h, Av);
        if (!s->rational) {
            memcpy(x, A, dim * sizeof *x);
            if (su_out != NULL)
                memcpy(su_out + b * dim, Au, dim * sizeof *x);
            if (sv_out != NULL)
                memcpy(sv_out + b * dim, Av, dim * sizeof *x);
            continue;
        }
        for (size_t c = 0; c < dim; c++) {
            double w = A[dim], S = A[c] / w;
            x[c] = S;
            if (su_out != NULL)
                su_out[b * dim + c] = (Au[c] - Au[dim] * S) / w;
            if (sv_out != NULL)
                sv_out[b * dim + c] = (Av[c] - Av[dim] * S) / w;
        }
    }
}

/* Results larger than this go to memory with non-temporal stores (they
** would not stay in the cache anyway; the stores skip reading each line
** before writing it). */
#define STREAM_BYTES ((size_t)8 << 20)
/* Points of v per chunk: the chunk's results stay in the L1 cache. */
#define CHUNK 128

/* n doubles from the cache-resident src to dst, bypassing the cache. */
static void
stream_copy(double *dst, const double *src, size_t n)
{
#ifdef CF__STREAM
    size_t i = 0;
    if (((uintptr_t)dst & 15) != 0 && n > 0) {
        dst[0] = src[0];
        i = 1;
    }
    for (; i + 2 <= n; i += 2)
        _mm_stream_pd(dst + i, _mm_loadu_pd(src + i));
    if (i < n)
        dst[i] = src[i];
#else
    memcpy(dst, src, n * sizeof *dst);
#endif
}

/* One row of results in chunks of CHUNK parameters of v through a
** cache-resident buffer buf (3 CHUNK dim doubles), streamed out. */
static void
one_row_streamed(const cf_bspline_surface_t *s, const double *R,
                 const double *dR, const size_t *sv, const double *Nv,
                 const double *dNv, size_t nv, double *pts, double *su_out,
                 double *sv_out, double *buf)
{
    size_t dim = s->dim, qv = (size_t)s->q + 1;
    for (size_t b0 = 0; b0 < nv; b0 += CHUNK) {
        size_t n = nv - b0 < CHUNK ? nv - b0 : CHUNK;
        double *x = buf, *y = buf + CHUNK * dim, *z = buf + 2 * CHUNK * dim;
        one_row(s, R, dR, sv + b0, Nv + b0 * qv, dNv + b0 * qv, n, x,
                su_out != NULL ? y : NULL, sv_out != NULL ? z : NULL);
        stream_copy(pts + b0 * dim, x, n * dim);
        if (su_out != NULL)
            stream_copy(su_out + b0 * dim, y, n * dim);
        if (sv_out != NULL)
            stream_copy(sv_out + b0 * dim, z, n * dim);
    }
}

cf_status_t
cf_bspline_surface_eval_grid(const cf_bspline_surface_t *s, const double *uv,
                             size_t nu, size_t nv, double *pts, double *su,
                             double *sv)
{
    size_t pu, qv, *span, len, need;
    bool stream;
    double *work, *t, *Nu, *dNu, *Nv, *dNv, *R, *dR;
    cf_status_t st;
    if (s == NULL || uv == NULL || pts == NULL || s->hdim > 64)
        return CF_STATUS_INVALID_ARG;
    if (nu == 0 || nv == 0)
        return CF_STATUS_OK;
    pu = (size_t)s->p + 1;
    qv = (size_t)s->q + 1;
    len = s->nv * s->hdim;
    /* t[nu + nv], Nu, dNu, Nv, dNv, R, dR, then the spans */
    need = (nu + nv) * (1 + 2 * (pu > qv ? pu : qv)) + 2 * len +
           3 * CHUNK * s->dim;
    stream = nu * nv * s->dim * sizeof(double) *
                 (1 + (su != NULL) + (sv != NULL)) > STREAM_BYTES;
    work = cf__alloc_array(need + nu + nv, sizeof(double));
    if (work == NULL)
        return CF_STATUS_NO_MEMORY;
    t = work;
    Nu = t + nu + nv;
    dNu = Nu + nu * pu;
    Nv = dNu + nu * pu;
    dNv = Nv + nv * qv;
    R = dNv + nv * qv;
    dR = R + len;
    span = (size_t *)(void *)(dR + len + 3 * CHUNK * s->dim);
    memcpy(t, uv, (nu + nv) * sizeof *t);
    st = bases(s->p, s->U, s->nU, s->ua, s->ub, CF_DIR_U, t, nu, span, Nu,
               su != NULL ? dNu : NULL);
    if (st == CF_STATUS_OK)
        st = bases(s->q, s->V, s->nV, s->va, s->vb, CF_DIR_V, t + nu, nv,
                   span + nu, Nv, sv != NULL ? dNv : NULL);
    for (size_t a = 0; st == CF_STATUS_OK && a < nu; a++) {
        size_t off = a * nv * s->dim;
        rows(s, span[a], Nu + a * pu, dNu + a * pu, R,
             su != NULL ? dR : NULL);
        if (stream)
            one_row_streamed(s, R, su != NULL ? dR : NULL, span + nu, Nv,
                             dNv, nv, pts + off, su != NULL ? su + off : NULL,
                             sv != NULL ? sv + off : NULL, dR + len);
        else
            one_row(s, R, su != NULL ? dR : NULL, span + nu, Nv, dNv, nv,
                    pts + off, su != NULL ? su + off : NULL,
                    sv != NULL ? sv + off : NULL);
    }
#ifdef CF__STREAM
    if (stream)
        _mm_sfence();
#endif
    cf__free(work);
    return st;
}
