/*
** The surfaces' schemes and patches (the language's s:decasteljau,
** s:deboor, s:to_bezier and s:knot_lines, render/lua/lsurface-methods.c):
** the methods of curvefig.BezierSurface and BSplineSurface that
** pysurface.c lists in its tables.
*/
#include "pycommon.h"

/* A net of n points, levels 0..n-1 with n - l points each, as a list of
** (n - l, dim) arrays. */
static PyObject *
net(const double *pts, size_t n, size_t dim)
{
    PyObject *levels = PyList_New((Py_ssize_t)n);
    size_t at = 0;
    for (size_t l = 0; levels != NULL && l < n; l++) {
        PyObject *lev = cfpy_matrix(pts + at * dim, (npy_intp)(n - l),
                                    (npy_intp)dim);
        if (lev == NULL)
            Py_CLEAR(levels);
        else
            PyList_SET_ITEM(levels, (Py_ssize_t)l, lev);
        at += n - l;
    }
    return levels;
}

/* (columns, v): the nets in u of the nv columns, then the net in v of the
** points they reach (surface.h's layout). */
static PyObject *
scheme(const double *out, size_t nu, size_t nv, size_t dim)
{
    size_t tu = nu * (nu + 1) / 2;
    PyObject *cols = PyList_New((Py_ssize_t)nv);
    for (size_t j = 0; cols != NULL && j < nv; j++) {
        PyObject *c = net(out + j * tu * dim, nu, dim);
        if (c == NULL)
            Py_CLEAR(cols);
        else
            PyList_SET_ITEM(cols, (Py_ssize_t)j, c);
    }
    return cfpy_pair(cols, net(out + nv * tu * dim, nv, dim));
}

/* The failure at (u, v) on [ua, ub] x [va, vb]. */
static PyObject *
uv_error(const char *fn, cf_status_t st, double u, double v,
         const double dom[4])
{
    char b[6][CFPY_NUM];
    if (st != CF_STATUS_DOMAIN)
        return cfpy_fail(fn, st, NULL);
    return cfpy_error(fn, "(u, v) = (%s, %s) is outside the domain "
                      "[%s, %s] x [%s, %s]", cfpy_num(u, b[0]),
                      cfpy_num(v, b[1]), cfpy_num(dom[0], b[2]),
                      cfpy_num(dom[1], b[3]), cfpy_num(dom[2], b[4]),
                      cfpy_num(dom[3], b[5]));
}

static int
uv_args(PyObject *args, const char *fmt, const char *fn, double *u,
        double *v)
{
    PyObject *uo, *vo;
    if (!PyArg_ParseTuple(args, fmt, &uo, &vo) ||
        cfpy_finite(uo, fn, "u", u) != 0 || cfpy_finite(vo, fn, "v", v) != 0)
        return -1;
    return 0;
}

PyObject *
cfpy_bezier_surface_decasteljau(const cf_bezier_surface_t *s,
                                PyObject *args)
{
    static const double unit[4] = { 0.0, 1.0, 0.0, 1.0 };
    double u, v, *buf;
    PyObject *r;
    cf_status_t st;
    if (uv_args(args, "OO:decasteljau", "decasteljau", &u, &v) != 0)
        return NULL;
    buf = PyMem_Malloc(cf_bezier_surface_decasteljau_size(s) *
                       sizeof(double));
    if (buf == NULL)
        return PyErr_NoMemory();
    st = cf_bezier_surface_decasteljau(s, u, v, buf);
    r = st != CF_STATUS_OK
            ? uv_error("decasteljau", st, u, v, unit)
            : scheme(buf, (size_t)cf_bezier_surface_degree_u(s) + 1,
                     (size_t)cf_bezier_surface_degree_v(s) + 1,
                     cf_bezier_surface_dim(s));
    PyMem_Free(buf);
    return r;
}

PyObject *
cfpy_bspline_surface_deboor(const cf_bspline_surface_t *s, PyObject *args)
{
    double u, v, *buf, dom[4];
    size_t span[2];
    PyObject *r;
    cf_status_t st;
    if (uv_args(args, "OO:deboor", "deboor", &u, &v) != 0)
        return NULL;
    buf = PyMem_Malloc(cf_bspline_surface_deboor_size(s) * sizeof(double));
    if (buf == NULL)
        return PyErr_NoMemory();
    st = cf_bspline_surface_deboor(s, u, v, buf, span);
    if (st != CF_STATUS_OK) {
        cf_bspline_surface_domain(s, CF_DIR_U, &dom[0], &dom[1]);
        cf_bspline_surface_domain(s, CF_DIR_V, &dom[2], &dom[3]);
        r = uv_error("deboor", st, u, v, dom);
    } else {
        r = scheme(buf, (size_t)cf_bspline_surface_degree_u(s) + 1,
                   (size_t)cf_bspline_surface_degree_v(s) + 1,
                   cf_bspline_surface_dim(s));
        if (r != NULL)
            r = Py_BuildValue("(N(nn))", r, (Py_ssize_t)span[0],
                              (Py_ssize_t)span[1]);
    }
    PyMem_Free(buf);
    return r;
}

PyObject *
cfpy_bspline_surface_to_beziers(const cf_bspline_surface_t *s)
{
    cf_bezier_surface_list_t *list = NULL;
    PyObject *grid;
    cf_diag_t d;
    cf_status_t st = cf_bspline_surface_to_beziers(s, &list, &d);
    if (st != CF_STATUS_OK)
        return cfpy_fail("to_beziers", st, &d);
    grid = PyList_New((Py_ssize_t)list->nu);
    for (size_t i = 0; grid != NULL && i < list->nu; i++) {
        PyObject *row = PyList_New((Py_ssize_t)list->nv);
        for (size_t j = 0; row != NULL && j < list->nv; j++) {
            PyObject *o = cfpy_wrap_bezier_surface(
                list->items[i * list->nv + j]);
            list->items[i * list->nv + j] = NULL;
            if (o == NULL)
                Py_CLEAR(row);
            else
                PyList_SET_ITEM(row, (Py_ssize_t)j, o);
        }
        if (row == NULL)
            Py_CLEAR(grid);
        else
            PyList_SET_ITEM(grid, (Py_ssize_t)i, row);
    }
    cf_bezier_surface_list_destroy(list);
    return grid;
}

PyObject *
cfpy_bspline_surface_knot_lines(const cf_bspline_surface_t *s,
                                PyObject *dirobj)
{
    size_t n;
    int dir;
    double *buf;
    PyObject *r;
    if (cfpy_dir(dirobj, "knot_lines", &dir) != 0)
        return NULL;
    (void)cf_bspline_surface_knots(s, (cf_dir_t)dir, &n);
    buf = PyMem_Malloc(n * sizeof(double));
    if (buf == NULL)
        return PyErr_NoMemory();
    (void)cf_bspline_surface_knot_lines(s, (cf_dir_t)dir, buf, &n);
    r = cfpy_vector(buf, (npy_intp)n);
    PyMem_Free(buf);
    return r;
}
