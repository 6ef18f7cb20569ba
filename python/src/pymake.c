/*
** Surfaces made from curves and the exact quadrics: curvefig.revolve,
** extrude, ruled, coons_patch, nurbs_sphere, nurbs_cylinder, nurbs_cone,
** nurbs_torus, interpolate_surface and approximate_surface (the language's
** render/lua/lsurface-make.c in Python).  A Bézier curve is taken as the
** B-spline of its control points on clamped knots (the same curve).
*/
#include "pycommon.h"

#include <math.h>

/* The curve at obj as a B-spline: *owned is set when it was made here
** (the caller destroys it). */
static const cf_bspline_t *
as_bspline(PyObject *obj, const char *fn, const char *what,
           cf_bspline_t **owned)
{
    *owned = NULL;
    if (PyObject_TypeCheck(obj, &cfpy_BSplineType))
        return ((cfpy_BSpline *)obj)->c;
    if (PyObject_TypeCheck(obj, &cfpy_BezierType)) {
        const cf_bezier_t *b = ((cfpy_Bezier *)obj)->c;
        size_t dim = cf_bezier_dim(b), n = (size_t)cf_bezier_degree(b) + 1;
        double *p = PyMem_Malloc(n * dim * sizeof(double));
        double *w = PyMem_Malloc(n * sizeof(double));
        cf_diag_t d;
        cf_status_t st = CF_STATUS_NO_MEMORY;
        if (p != NULL && w != NULL) {
            cf_bezier_get_points(b, p);
            cf_bezier_get_weights(b, w);
            st = cf_bspline_create_clamped(dim, cf_bezier_degree(b), p, n,
                                           cf_bezier_is_rational(b) ? w
                                                                    : NULL,
                                           owned, &d);
        }
        PyMem_Free(p);
        PyMem_Free(w);
        if (st != CF_STATUS_OK) {
            cfpy_fail(fn, st, st == CF_STATUS_NO_MEMORY ? NULL : &d);
            return NULL;
        }
        return *owned;
    }
    PyErr_Format(PyExc_TypeError, "%s: %s must be a Bezier or a BSpline, "
                 "got %s", fn, what, Py_TYPE(obj)->tp_name);
    return NULL;
}

static PyObject *
made(const char *fn, cf_status_t st, cf_bspline_surface_t **s,
     const cf_diag_t *d)
{
    if (st != CF_STATUS_OK)
        return cfpy_fail(fn, st, d);
    return cfpy_wrap_bspline_surface(*s);
}

static PyObject *
py_revolve(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *names[] = { "curve", "axis", "center", "start", "end",
                             NULL };
    PyObject *C, *axis = Py_None, *center = Py_None;
    double A[3] = { 0, 0, 1 }, O[3] = { 0, 0, 0 }, a0 = 0, a1 = 6.283185307179586; /* 2 pi */
    cf_bspline_t *owned;
    const cf_bspline_t *c;
    cf_bspline_surface_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    (void)mod;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|OOdd:revolve", names, &C,
                                     &axis, &center, &a0, &a1))
        return NULL;
    if ((axis != Py_None && cfpy_point(axis, "revolve", "axis", 3, A)) ||
        (center != Py_None && cfpy_point(center, "revolve", "center", 3, O)))
        return NULL;
    c = as_bspline(C, "revolve", "the curve", &owned);
    if (c == NULL)
        return NULL;
    st = cf_surface_revolve(c, O, A, a0, a1, &out, &d);
    cf_bspline_destroy(owned);
    return made("revolve", st, &out, &d);
}

static PyObject *
py_extrude(PyObject *mod, PyObject *args)
{
    PyObject *C, *D;
    double *v;
    cf_bspline_t *owned;
    const cf_bspline_t *c;
    cf_bspline_surface_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    (void)mod;
    if (!PyArg_ParseTuple(args, "OO:extrude", &C, &D))
        return NULL;
    c = as_bspline(C, "extrude", "the curve", &owned);
    if (c == NULL)
        return NULL;
    v = PyMem_Malloc(cf_bspline_dim(c) * sizeof(double));
    if (v == NULL || cfpy_point(D, "extrude", "the direction",
                                cf_bspline_dim(c), v) != 0) {
        if (v == NULL)
            PyErr_NoMemory();
        PyMem_Free(v);
        cf_bspline_destroy(owned);
        return NULL;
    }
    st = cf_surface_extrude(c, v, &out, &d);
    PyMem_Free(v);
    cf_bspline_destroy(owned);
    return made("extrude", st, &out, &d);
}

/* ruled(c1, c2) and coons_patch(c0, c1, d0, d1): n curves in, a surface */
static PyObject *
from_curves(PyObject *args, const char *fn, int n)
{
    PyObject *o[4] = { NULL, NULL, NULL, NULL }, *r = NULL;
    cf_bspline_t *owned[4] = { NULL, NULL, NULL, NULL };
    const cf_bspline_t *c[4];
    cf_bspline_surface_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    int i;
    if (!PyArg_UnpackTuple(args, fn, (Py_ssize_t)n, (Py_ssize_t)n, &o[0],
                           &o[1], &o[2], &o[3]))
        return NULL;
    for (i = 0; i < n; i++) {
        static const char *const what[] = { "curve 1", "curve 2", "curve 3",
                                            "curve 4" };
        c[i] = as_bspline(o[i], fn, what[i], &owned[i]);
        if (c[i] == NULL)
            break;
    }
    if (i == n) {
        st = n == 2 ? cf_surface_ruled(c[0], c[1], &out, &d)
                    : cf_surface_coons(c[0], c[1], c[2], c[3], &out, &d);
        r = made(fn, st, &out, &d);
    }
    for (i = 0; i < n; i++)
        cf_bspline_destroy(owned[i]);
    return r;
}

static PyObject *
py_ruled(PyObject *mod, PyObject *args)
{
    (void)mod;
    return from_curves(args, "ruled", 2);
}

static PyObject *
py_coons_patch(PyObject *mod, PyObject *args)
{
    (void)mod;
    return from_curves(args, "coons_patch", 4);
}

/* The quadrics: centre, then one to two sizes. */
static PyObject *
quadric(PyObject *args, PyObject *kw, const char *fn, int kind)
{
    static char *names1[] = { "center", "r", NULL };
    static char *names2[] = { "center", "r", "h", NULL };
    static char *torus[] = { "center", "R", "r", NULL };
    PyObject *cobj;
    double C[3], a = 0, b = 0;
    cf_bspline_surface_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    int ok = kind == 0
        ? PyArg_ParseTupleAndKeywords(args, kw, "Od", names1, &cobj, &a)
        : PyArg_ParseTupleAndKeywords(args, kw, "Odd",
                                      kind == 3 ? torus : names2, &cobj, &a,
                                      &b);
    if (!ok || cfpy_point(cobj, fn, "the center", 3, C) != 0)
        return NULL;
    switch (kind) {
    case 0:
        st = cf_nurbs_sphere(C, a, &out, &d);
        break;
    case 1:
        st = cf_nurbs_cylinder(C, a, b, &out, &d);
        break;
    case 2:
        st = cf_nurbs_cone(C, a, b, &out, &d);
        break;
    default:
        st = cf_nurbs_torus(C, a, b, &out, &d);
        break;
    }
    return made(fn, st, &out, &d);
}

static PyObject *
py_sphere(PyObject *mod, PyObject *args, PyObject *kw)
{
    (void)mod;
    return quadric(args, kw, "nurbs_sphere", 0);
}

static PyObject *
py_cylinder(PyObject *mod, PyObject *args, PyObject *kw)
{
    (void)mod;
    return quadric(args, kw, "nurbs_cylinder", 1);
}

static PyObject *
py_cone(PyObject *mod, PyObject *args, PyObject *kw)
{
    (void)mod;
    return quadric(args, kw, "nurbs_cone", 2);
}

static PyObject *
py_torus(PyObject *mod, PyObject *args, PyObject *kw)
{
    (void)mod;
    return quadric(args, kw, "nurbs_torus", 3);
}

#define KW(f) ((PyCFunction)(void (*)(void))(f))

/* The grid Q of interpolate_surface / approximate_surface, (nu, nv, dim)
** finite with at least two points each way, and the options into opt.
** NULL on bad input. */
static PyArrayObject *
fit_grid(PyObject *Q, const char *fn, PyObject *method, PyObject *param,
         PyObject *expo, int degree, cf_interp_options_t *opt)
{
    PyArrayObject *q = cfpy_array(Q, fn, "points", 3, 1),
                  *keep[3] = { NULL, NULL, NULL };
    if (q != NULL && (PyArray_DIM(q, 0) < 2 || PyArray_DIM(q, 1) < 2 ||
                      PyArray_DIM(q, 2) < 1)) {
        cfpy_error(fn, "points has shape (%zd, %zd, %zd); it must be a grid "
                   "(rows, columns, dim) of at least 2 x 2 points",
                   (Py_ssize_t)PyArray_DIM(q, 0),
                   (Py_ssize_t)PyArray_DIM(q, 1),
                   (Py_ssize_t)PyArray_DIM(q, 2));
        Py_CLEAR(q);
    }
    /* no arrays among the options here: keep[] stays empty */
    if (q != NULL &&
        cfpy_interp_options(fn, method, param, expo, Py_None, Py_None,
                            Py_None, degree, (size_t)PyArray_DIM(q, 2), opt,
                            keep) != 0)
        Py_CLEAR(q);
    return q;
}

static PyObject *
py_interpolate_surface(PyObject *mod, PyObject *args, PyObject *kw)
{
    static const char *fn = "interpolate_surface";
    static char *names[] = { "points", "method", "degree", "param",
                             "exponent", NULL };
    PyObject *Q, *method = Py_None, *param = Py_None, *expo = Py_None;
    PyArrayObject *q;
    cf_interp_options_t opt;
    cf_bspline_surface_t *out = NULL;
    int degree = 3;
    cf_diag_t d;
    cf_status_t st;
    (void)mod;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|OiOO:interpolate_surface",
                                     names, &Q, &method, &degree, &param,
                                     &expo) ||
        (q = fit_grid(Q, fn, method, param, expo, degree, &opt)) == NULL)
        return NULL;
    Py_BEGIN_ALLOW_THREADS
    st = cf_interpolate_surface((size_t)PyArray_DIM(q, 2), PyArray_DATA(q),
                                (size_t)PyArray_DIM(q, 0),
                                (size_t)PyArray_DIM(q, 1), &opt, &out, NULL,
                                &d);
    Py_END_ALLOW_THREADS
    Py_DECREF(q);
    return made(fn, st, &out, &d);
}

static PyObject *
py_approximate_surface(PyObject *mod, PyObject *args, PyObject *kw)
{
    static const char *fn = "approximate_surface";
    static char *names[] = { "points", "count", "degree", "param",
                             "fix_ends", NULL };
    PyObject *Q, *param = Py_None, *r;
    PyArrayObject *q;
    Py_ssize_t cu, cv;
    cf_interp_options_t opt;
    cf_bspline_surface_t *out = NULL;
    int degree = 3, fix_ends = 1;
    double residual = 0.0;
    cf_diag_t d;
    cf_status_t st;
    (void)mod;
    if (!PyArg_ParseTupleAndKeywords(args, kw,
                                     "O(nn)|iOp:approximate_surface", names,
                                     &Q, &cu, &cv, &degree, &param,
                                     &fix_ends))
        return NULL;
    if (cu < 2 || cv < 2)
        return cfpy_error(fn, "count is (%zd, %zd); it must be at least "
                          "(2, 2) control points along u and v", cu, cv);
    q = fit_grid(Q, fn, Py_None, param, Py_None, degree, &opt);
    if (q == NULL)
        return NULL;
    Py_BEGIN_ALLOW_THREADS
    st = cf_approximate_surface((size_t)PyArray_DIM(q, 2), PyArray_DATA(q),
                                (size_t)PyArray_DIM(q, 0),
                                (size_t)PyArray_DIM(q, 1), (size_t)cu,
                                (size_t)cv, &opt, fix_ends != 0, &out,
                                &residual, &d);
    Py_END_ALLOW_THREADS
    Py_DECREF(q);
    r = made(fn, st, &out, &d);
    return r != NULL ? Py_BuildValue("(Nd)", r, residual) : NULL;
}

PyMethodDef cfpy_make_functions[] = {
    { "revolve", KW(py_revolve), METH_VARARGS | METH_KEYWORDS,
      "revolve(curve, axis=(0, 0, 1), center=(0, 0, 0), start=0, "
      "end=2 pi): the exact surface of revolution of a curve in R^3" },
    { "extrude", py_extrude, METH_VARARGS,
      "extrude(curve, d): the curve swept along the vector d" },
    { "ruled", py_ruled, METH_VARARGS,
      "ruled(c1, c2): the ruled surface between two curves" },
    { "coons_patch", py_coons_patch, METH_VARARGS,
      "coons_patch(c0, c1, d0, d1): the bilinearly blended Coons patch "
      "(c0 = S(u, 0), c1 = S(u, 1), d0 = S(0, v), d1 = S(1, v))" },
    { "nurbs_sphere", KW(py_sphere), METH_VARARGS | METH_KEYWORDS,
      "nurbs_sphere(center, r)" },
    { "nurbs_cylinder", KW(py_cylinder), METH_VARARGS | METH_KEYWORDS,
      "nurbs_cylinder(center, r, h)" },
    { "nurbs_cone", KW(py_cone), METH_VARARGS | METH_KEYWORDS,
      "nurbs_cone(center, r, h)" },
    { "nurbs_torus", KW(py_torus), METH_VARARGS | METH_KEYWORDS,
      "nurbs_torus(center, R, r)" },
    { "interpolate_surface", KW(py_interpolate_surface),
      METH_VARARGS | METH_KEYWORDS,
      "interpolate_surface(points, method=None, degree=3, param=None, "
      "exponent=None): the B-spline surface through a (rows, columns, dim) "
      "grid" },
    { "approximate_surface", KW(py_approximate_surface),
      METH_VARARGS | METH_KEYWORDS,
      "approximate_surface(points, (cu, cv), degree=3, param=None, "
      "fix_ends=True): (surface, residual), least squares" },
    { NULL, NULL, 0, NULL }
};
