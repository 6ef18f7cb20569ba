/*
** curvefig.BezierTriangle: triangular Bézier patches
** (include/curvefig/surface-triangle.h) as numpy arrays, the language's
** bezier_triangle{} (render/lua/lsurface-triangle.c) in Python.  A point
** of the domain is (u, v) with w = 1 - u - v; the control points are in
** the header's order b_n00, b_(n-1)10, b_(n-1)01, b_(n-2)20, ...
*/
#include "pycommon.h"

typedef struct {
    PyObject_HEAD
    cf_bezier_triangle_t *t;
} cfpy_Triangle;

#define SELF(o) (((cfpy_Triangle *)(o))->t)

static PyObject *
wrap(cf_bezier_triangle_t *t)
{
    cfpy_Triangle *o = PyObject_New(cfpy_Triangle, &cfpy_BezierTriangleType);
    if (o == NULL) {
        cf_bezier_triangle_destroy(t);
        return NULL;
    }
    o->t = t;
    return (PyObject *)o;
}

static void
tr_dealloc(PyObject *self)
{
    cf_bezier_triangle_destroy(SELF(self));
    Py_TYPE(self)->tp_free(self);
}

static PyObject *
tr_new(PyTypeObject *type, PyObject *args, PyObject *kw)
{
    static char *names[] = { "P", "weights", NULL };
    PyObject *P, *W = Py_None;
    PyArrayObject *p, *w = NULL;
    cf_bezier_triangle_t *t = NULL;
    cfpy_Triangle *o;
    cf_diag_t d;
    cf_status_t st;
    npy_intp count;
    int n = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|O:BezierTriangle", names,
                                     &P, &W))
        return NULL;
    p = cfpy_points(P, "BezierTriangle", "P", 1);
    if (p == NULL)
        return NULL;
    count = PyArray_DIM(p, 0);
    while ((npy_intp)(n + 1) * (n + 2) / 2 < count)
        n++;
    if ((npy_intp)(n + 1) * (n + 2) / 2 != count) {
        Py_DECREF(p);
        return cfpy_error("BezierTriangle", "P has %zd points; a patch of "
                          "degree n has (n + 1)(n + 2) / 2 (%d or %d)",
                          (Py_ssize_t)count, n * (n + 1) / 2,
                          (n + 1) * (n + 2) / 2);
    }
    if (W != Py_None) {
        w = cfpy_array(W, "BezierTriangle", "weights", 1, 1);
        if (w == NULL || PyArray_DIM(w, 0) != count) {
            if (w != NULL)
                cfpy_error("BezierTriangle", "%zd weights given for %zd "
                           "points", (Py_ssize_t)PyArray_DIM(w, 0),
                           (Py_ssize_t)count);
            Py_DECREF(p);
            Py_XDECREF(w);
            return NULL;
        }
    }
    st = cf_bezier_triangle_create((size_t)PyArray_DIM(p, 1), n,
                                   PyArray_DATA(p),
                                   w != NULL ? PyArray_DATA(w) : NULL, &t,
                                   &d);
    Py_DECREF(p);
    Py_XDECREF(w);
    if (st != CF_STATUS_OK)
        return cfpy_fail("BezierTriangle", st, &d);
    o = (cfpy_Triangle *)type->tp_alloc(type, 0);
    if (o == NULL) {
        cf_bezier_triangle_destroy(t);
        return NULL;
    }
    o->t = t;
    return (PyObject *)o;
}

/* The failure of a call at (u, v): which point is outside the triangle. */
static PyObject *
point_error(const char *fn, cf_status_t st, double u, double v)
{
    char b1[CFPY_NUM], b2[CFPY_NUM], b3[CFPY_NUM];
    if (st == CF_STATUS_DOMAIN)
        return cfpy_error(fn, "(u, v, w) = (%s, %s, %s) is outside the "
                          "triangle u, v, w >= 0", cfpy_num(u, b1),
                          cfpy_num(v, b2), cfpy_num(1.0 - u - v, b3));
    if (st == CF_STATUS_DEGENERATE)
        return cfpy_error(fn, "no normal at (u, v) = (%s, %s)",
                          cfpy_num(u, b1), cfpy_num(v, b2));
    return cfpy_fail(fn, st, NULL);
}

/* eval and normal at u, v broadcast against each other: the broadcast
** shape followed by (width,). */
static PyObject *
evaluate(PyObject *self, PyObject *args, const char *fmt, const char *fn,
         int normal)
{
    const cf_bezier_triangle_t *t = SELF(self);
    size_t width = normal ? 3 : cf_bezier_triangle_dim(t);
    PyObject *uo, *vo, *b = NULL;
    PyArrayObject *u = NULL, *v = NULL, *out = NULL;
    npy_intp shape[NPY_MAXDIMS + 1];
    double bu = 0.0, bv = 0.0;
    cf_status_t st = CF_STATUS_OK;
    int nd;
    if (!PyArg_ParseTuple(args, fmt, &uo, &vo))
        return NULL;
    if (normal && cf_bezier_triangle_dim(t) != 3)
        return cfpy_error(fn, "the patch lies in R^%zu; normals need R^3",
                          cf_bezier_triangle_dim(t));
    u = cfpy_array(uo, fn, "u", 0, 0);
    v = u != NULL ? cfpy_array(vo, fn, "v", 0, 0) : NULL;
    b = v != NULL ? PyArray_MultiIterNew(2, u, v) : NULL;
    if (b == NULL)
        goto done;
    nd = ((PyArrayMultiIterObject *)b)->nd;
    if (nd >= NPY_MAXDIMS) {
        cfpy_error(fn, "u and v have too many dimensions");
        goto done;
    }
    memcpy(shape, ((PyArrayMultiIterObject *)b)->dimensions,
           (size_t)nd * sizeof(npy_intp));
    shape[nd] = (npy_intp)width;
    out = cfpy_new(nd + 1, shape);
    if (out == NULL)
        goto done;
    {
        PyArrayMultiIterObject *m = (PyArrayMultiIterObject *)b;
        double *o = PyArray_DATA(out);
        Py_BEGIN_ALLOW_THREADS
        while (PyArray_MultiIter_NOTDONE(m) && st == CF_STATUS_OK) {
            bu = *(double *)PyArray_MultiIter_DATA(m, 0);
            bv = *(double *)PyArray_MultiIter_DATA(m, 1);
            st = normal ? cf_bezier_triangle_normal(t, bu, bv, o)
                        : cf_bezier_triangle_eval(t, bu, bv, o);
            o += width;
            PyArray_MultiIter_NEXT(m);
        }
        Py_END_ALLOW_THREADS
    }
    if (st != CF_STATUS_OK) {
        point_error(fn, st, bu, bv);
        Py_CLEAR(out);
    }
done:
    Py_XDECREF(b);
    Py_XDECREF(u);
    Py_XDECREF(v);
    return (PyObject *)out;
}

static PyObject *
tr_eval(PyObject *self, PyObject *args)
{
    return evaluate(self, args, "OO:eval", "eval", 0);
}

static PyObject *
tr_normal(PyObject *self, PyObject *args)
{
    return evaluate(self, args, "OO:normal", "normal", 1);
}

/* derivs(u, v, direction, k=1): D[j] = D_dir^j T(u, v), j = 0..k */
static PyObject *
tr_derivs(PyObject *self, PyObject *args)
{
    const cf_bezier_triangle_t *t = SELF(self);
    PyObject *uo, *vo, *dobj;
    double u, v, dir[3];
    size_t dim = cf_bezier_triangle_dim(t);
    PyArrayObject *out;
    npy_intp shape[2];
    cf_status_t st;
    int k = 1;
    char b1[CFPY_NUM], b2[CFPY_NUM], b3[CFPY_NUM];
    if (!PyArg_ParseTuple(args, "OOO|i:derivs", &uo, &vo, &dobj, &k) ||
        cfpy_finite(uo, "derivs", "u", &u) != 0 ||
        cfpy_finite(vo, "derivs", "v", &v) != 0 ||
        cfpy_point(dobj, "derivs", "direction", 3, dir) != 0)
        return NULL;
    if (k < 0 || k > 16)
        return cfpy_error("derivs", "the order is %d; it must be in 0..16",
                          k);
    shape[0] = k + 1;
    shape[1] = (npy_intp)dim;
    out = cfpy_new(2, shape);
    if (out == NULL)
        return NULL;
    st = cf_bezier_triangle_eval_derivs(t, dir, u, v, k, PyArray_DATA(out));
    if (st == CF_STATUS_OK)
        return (PyObject *)out;
    Py_DECREF(out);
    if (st == CF_STATUS_INVALID_ARG)
        return cfpy_error("derivs", "the direction (du, dv, dw) = (%s, %s, "
                          "%s) must sum to 0", cfpy_num(dir[0], b1),
                          cfpy_num(dir[1], b2), cfpy_num(dir[2], b3));
    return point_error("derivs", st, u, v);
}

/* decasteljau(u, v): the list of levels, level l of shape
** ((n - l + 1)(n - l + 2) / 2, dim); the last is T(u, v) */
static PyObject *
tr_decasteljau(PyObject *self, PyObject *args)
{
    const cf_bezier_triangle_t *t = SELF(self);
    PyObject *uo, *vo, *levels;
    double u, v, *buf;
    size_t dim = cf_bezier_triangle_dim(t), at = 0;
    int n = cf_bezier_triangle_degree(t);
    cf_status_t st;
    if (!PyArg_ParseTuple(args, "OO:decasteljau", &uo, &vo) ||
        cfpy_finite(uo, "decasteljau", "u", &u) != 0 ||
        cfpy_finite(vo, "decasteljau", "v", &v) != 0)
        return NULL;
    buf = PyMem_Malloc(cf_bezier_triangle_decasteljau_size(t) *
                       sizeof(double));
    if (buf == NULL)
        return PyErr_NoMemory();
    st = cf_bezier_triangle_decasteljau(t, u, v, buf);
    if (st != CF_STATUS_OK) {
        PyMem_Free(buf);
        return point_error("decasteljau", st, u, v);
    }
    levels = PyList_New(n + 1);
    for (int m = n; levels != NULL && m >= 0; m--) {
        size_t cnt = ((size_t)m + 1) * ((size_t)m + 2) / 2;
        PyObject *lev = cfpy_matrix(buf + at * dim, (npy_intp)cnt,
                                    (npy_intp)dim);
        if (lev == NULL)
            Py_CLEAR(levels);
        else
            PyList_SET_ITEM(levels, n - m, lev);
        at += cnt;
    }
    PyMem_Free(buf);
    return levels;
}

static PyObject *
tr_subdivide(PyObject *self, PyObject *args)
{
    PyObject *uo, *vo, *a, *b, *c;
    cf_bezier_triangle_t *parts[3] = { NULL, NULL, NULL };
    double u, v;
    cf_diag_t d;
    cf_status_t st;
    if (!PyArg_ParseTuple(args, "OO:subdivide", &uo, &vo) ||
        cfpy_finite(uo, "subdivide", "u", &u) != 0 ||
        cfpy_finite(vo, "subdivide", "v", &v) != 0)
        return NULL;
    st = cf_bezier_triangle_subdivide(SELF(self), u, v, parts, &d);
    if (st != CF_STATUS_OK)
        return cfpy_fail("subdivide", st, &d);
    a = wrap(parts[0]);
    b = wrap(parts[1]);
    c = wrap(parts[2]);
    if (a == NULL || b == NULL || c == NULL) {
        Py_XDECREF(a);
        Py_XDECREF(b);
        Py_XDECREF(c);
        return NULL;
    }
    return Py_BuildValue("(NNN)", a, b, c);
}

static PyObject *
tr_elevate(PyObject *self, PyObject *unused)
{
    cf_bezier_triangle_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    (void)unused;
    st = cf_bezier_triangle_elevate(SELF(self), &out, &d);
    return st == CF_STATUS_OK ? wrap(out) : cfpy_fail("elevate", st, &d);
}

static PyObject *
tr_boundary(PyObject *self, PyObject *args)
{
    cf_bezier_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    int e;
    if (!PyArg_ParseTuple(args, "i:boundary", &e))
        return NULL;
    if (e < 0 || e > 2)
        return cfpy_error("boundary", "edge %d; the edges are 0 (w = 0), "
                          "1 (u = 0) and 2 (v = 0)", e);
    st = cf_bezier_triangle_boundary(SELF(self), e, &out, &d);
    return st == CF_STATUS_OK ? cfpy_wrap_bezier(out)
                              : cfpy_fail("boundary", st, &d);
}

static PyObject *
tr_points(PyObject *self, void *unused)
{
    const cf_bezier_triangle_t *t = SELF(self);
    npy_intp shape[2] = { (npy_intp)cf_bezier_triangle_count(t),
                          (npy_intp)cf_bezier_triangle_dim(t) };
    PyArrayObject *a = cfpy_new(2, shape);
    (void)unused;
    if (a != NULL)
        cf_bezier_triangle_get_points(t, PyArray_DATA(a));
    return (PyObject *)a;
}

static PyObject *
tr_weights(PyObject *self, void *unused)
{
    npy_intp n = (npy_intp)cf_bezier_triangle_count(SELF(self));
    PyArrayObject *a = cfpy_new(1, &n);
    (void)unused;
    if (a != NULL)
        cf_bezier_triangle_get_weights(SELF(self), PyArray_DATA(a));
    return (PyObject *)a;
}

static PyObject *
tr_degree(PyObject *self, void *unused)
{
    (void)unused;
    return PyLong_FromLong(cf_bezier_triangle_degree(SELF(self)));
}

static PyObject *
tr_dim(PyObject *self, void *unused)
{
    (void)unused;
    return PyLong_FromSize_t(cf_bezier_triangle_dim(SELF(self)));
}

static PyObject *
tr_is_rational(PyObject *self, void *unused)
{
    (void)unused;
    return PyBool_FromLong(cf_bezier_triangle_is_rational(SELF(self)));
}

static PyObject *
tr_repr(PyObject *self)
{
    return PyUnicode_FromFormat("<curvefig.BezierTriangle of degree %d in "
                                "R^%zu%s>",
                                cf_bezier_triangle_degree(SELF(self)),
                                cf_bezier_triangle_dim(SELF(self)),
                                cf_bezier_triangle_is_rational(SELF(self))
                                    ? ", rational" : "");
}

static PyMethodDef tr_methods[] = {
    { "eval", tr_eval, METH_VARARGS,
      "eval(u, v): T(u, v, 1 - u - v); u and v broadcast (shape + (dim,))" },
    { "normal", tr_normal, METH_VARARGS,
      "normal(u, v): unit normal (R^3), u and v broadcast" },
    { "derivs", tr_derivs, METH_VARARGS,
      "derivs(u, v, direction, k=1): D[j] = D_dir^j T(u, v), j = 0..k; "
      "direction (du, dv, dw) sums to 0" },
    { "decasteljau", tr_decasteljau, METH_VARARGS,
      "decasteljau(u, v): the scheme's levels; the last is T(u, v)" },
    { "subdivide", tr_subdivide, METH_VARARGS,
      "subdivide(u, v): three patches on (p, b_0n0, b_00n), "
      "(b_n00, p, b_00n), (b_n00, b_0n0, p)" },
    { "elevate", tr_elevate, METH_NOARGS, "elevate(): degree n + 1" },
    { "boundary", tr_boundary, METH_VARARGS,
      "boundary(e): edge 0 (w = 0), 1 (u = 0) or 2 (v = 0) as a Bezier" },
    { NULL, NULL, 0, NULL }
};

static PyGetSetDef tr_getset[] = {
    { "points", tr_points, NULL, "the control points, (count, dim)", NULL },
    { "weights", tr_weights, NULL, "the weights, (count,)", NULL },
    { "degree", tr_degree, NULL, "the degree n", NULL },
    { "dim", tr_dim, NULL, "the dimension of the points", NULL },
    { "is_rational", tr_is_rational, NULL, "True when rational", NULL },
    { NULL, NULL, NULL, NULL, NULL }
};

PyTypeObject cfpy_BezierTriangleType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "curvefig.BezierTriangle",
    .tp_basicsize = sizeof(cfpy_Triangle),
    .tp_dealloc = tr_dealloc,
    .tp_repr = tr_repr,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "BezierTriangle(P, weights=None): a triangular Bézier patch "
              "of degree n, P of shape ((n+1)(n+2)/2, dim) in the order "
              "b_n00, b_(n-1)10, b_(n-1)01, b_(n-2)20, ...",
    .tp_methods = tr_methods,
    .tp_getset = tr_getset,
    .tp_new = tr_new,
};
