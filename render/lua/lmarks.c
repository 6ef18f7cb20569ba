/*
** What the drawing methods compute on a curve (lmarks.h).
*/
#include "curvefig/bezier.h"
#include "lbezier.h"
#include "lbspline.h"
#include "lcommon.h"
#include "lmarks.h"
#include "lstyle.h"

#define MAX_DIM 64

void
cf__lua_tangent_arrow(lua_State *L, cf_figure_t *fig, int idx, double t,
                      int opts, double pd[4])
{
    double d[2 * MAX_DIM], a = 0.0, b = 1.0, scale;
    cf_bezier_t *bz = cf__lua_to_bezier(L, idx);
    size_t dim;
    int deg;
    cf_status_t rc;
    if (bz != NULL) {
        dim = cf_bezier_dim(bz);
        deg = cf_bezier_degree(bz);
        rc = cf_bezier_eval_derivs(bz, t, 1, d);
    } else {
        cf_bspline_t *bs = cf__lua_check_bspline(L, idx);
        dim = cf_bspline_dim(bs);
        deg = cf_bspline_degree(bs);
        cf_bspline_domain(bs, &a, &b);
        rc = cf_bspline_eval_derivs(bs, t, 1, d);
    }
    if (rc != CF_STATUS_OK)
        cf__lua_error(L, "tangent: t = %g is outside the domain [%g, %g]", t,
                      a, b);
    scale = cf__lua_opt_number(L, opts, "scale", "tangent",
                               deg > 0 ? 1.0 / deg : 1.0, NULL);
    for (size_t k = 0; k < dim; k++)
        d[dim + k] = d[k] + scale * d[dim + k];
    cf__lua_fig_check(L, "tangent", fig, cf_figure_project(fig, d, 2, dim, pd),
                      NULL);
}

size_t
cf__lua_knot_marks(lua_State *L, cf_figure_t *fig, const cf_bspline_t *s,
                   double **pts, lua_Integer **args)
{
    const double *u = cf_bspline_knots(s);
    size_t m = cf_bspline_nknots(s), dim = cf_bspline_dim(s), n = 0;
    double a, b, *p = cf__lua_buffer(L, m * dim);
    lua_Integer *ia = lua_newuserdatauv(L, 2 * (m ? m : 1) * sizeof *ia, 0);
    cf_bspline_domain(s, &a, &b);
    for (size_t i = 0, j; i < m; i = j) {
        for (j = i + 1; j < m && u[j] == u[i]; j++)
            ;
        if (u[i] < a || u[i] > b ||
            cf_bspline_eval(s, u[i], p + n * dim) != CF_STATUS_OK)
            continue;
        ia[2 * n] = (lua_Integer)i;
        ia[2 * n + 1] = (lua_Integer)(j - i);
        n++;
    }
    *pts = cf__lua_buffer(L, 2 * (n ? n : 1));
    if (n > 0)
        cf__lua_fig_check(L, "knots", fig,
                          cf_figure_project(fig, p, n, dim, *pts), NULL);
    *args = ia;
    return n;
}
