/* Evaluation of a B-spline surface on a grid of parameters, using the
** tensor structure (cf_bspline_surface_eval_grid, curvefig/surface.h). */
#include <string.h>

#include "surface-private.h"
#include "bspline-private.h"

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

/* The fixed-size kernel of the common case (bicubic, 3-D polynomial or
** 2-D rational: 4 columns of 3 doubles). */
CF__INLINE void
combine43(const double *R, const double *N, double *acc)
{
    acc[0] = N[0] * R[0] + N[1] * R[3] + N[2] * R[6] + N[3] * R[9];
    acc[1] = N[0] * R[1] + N[1] * R[4] + N[2] * R[7] + N[3] * R[10];
    acc[2] = N[0] * R[2] + N[1] * R[5] + N[2] * R[8] + N[3] * R[11];
}

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

static void
one_row(const cf_bspline_surface_t *s, const double *R, const double *dR,
        const size_t *sv, const double *Nv, const double *dNv, size_t nv,
        double *pts, double *su_out, double *sv_out)
{
    size_t h = s->hdim, dim = s->dim, qv = (size_t)s->q + 1;
    bool fast = qv == 4 && h == 3;
    for (size_t b = 0; b < nv; b++) {
        const double *Rb = R + (sv[b] - (size_t)s->q) * h;
        double A[64], Au[64], Av[64];
        double *x = pts + b * dim;
        if (fast) {
            combine43(Rb, Nv + b * 4, A);
            if (dR != NULL)
                combine43(dR + (sv[b] - 3) * 3, Nv + b * 4, Au);
            if (sv_out != NULL)
                combine43(Rb, dNv + b * 4, Av);
        } else {
            combine(Rb, Nv + b * qv, qv, h, A);
            if (dR != NULL)
                combine(dR + (sv[b] - (size_t)s->q) * h, Nv + b * qv, qv, h,
                        Au);
            if (sv_out != NULL)
                combine(Rb, dNv + b * qv, qv, h, Av);
        }
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

cf_status_t
cf_bspline_surface_eval_grid(const cf_bspline_surface_t *s, const double *uv,
                             size_t nu, size_t nv, double *pts, double *su,
                             double *sv)
{
    size_t pu, qv, *span, len, need;
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
    need = (nu + nv) * (1 + 2 * (pu > qv ? pu : qv)) + 2 * len;
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
    span = (size_t *)(void *)(dR + len);
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
        one_row(s, R, su != NULL ? dR : NULL, span + nu, Nv, dNv, nv,
                pts + off, su != NULL ? su + off : NULL,
                sv != NULL ? sv + off : NULL);
    }
    cf__free(work);
    return st;
}
