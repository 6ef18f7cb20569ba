/*
** curvefig.Bezier: polynomial and rational Bézier curves as numpy arrays
** (the language's bezier{}, render/lua/lbezier.c, in Python).
*/
#include "pycommon.h"

#define SELF(o) (((cfpy_Bezier *)(o))->c)

PyObject *
cfpy_wrap_bezier(cf_bezier_t *c)
{
    cfpy_Bezier *o = PyObject_New(cfpy_Bezier, &cfpy_BezierType);
    if (o == NULL) {
        cf_bezier_destroy(c);
        return NULL;
    }
    o->c = c;
    return (PyObject *)o;
}

PyObject *
cfpy_bezier_list(cf_bezier_list_t *list)
{
    PyObject *l = PyList_New((Py_ssize_t)list->count);
    for (size_t i = 0; l != NULL && i < list->count; i++) {
        PyObject *item = cfpy_wrap_bezier(list->items[i]);
        list->items[i] = NULL;
        if (item == NULL)
            Py_CLEAR(l);
        else
            PyList_SET_ITEM(l, (Py_ssize_t)i, item);
    }
    cf_bezier_list_destroy(list);
    return l;
}

PyObject *
cfpy_cubics(const cf_cubics_t *cu)
{
    PyObject *l = PyList_New((Py_ssize_t)cu->count);
    for (size_t i = 0; l != NULL && i < cu->count; i++) {
        cf_bezier_t *b;
        cf_diag_t d;
        cf_status_t st = cf_bezier_create(cu->dim, 3,
                                          cu->pts + 4 * cu->dim * i, NULL,
                                          &b, &d);
        PyObject *item = st == CF_STATUS_OK ? cfpy_wrap_bezier(b)
                                            : cfpy_fail("cubics", st, &d);
        if (item == NULL)
            Py_CLEAR(l);
        else
            PyList_SET_ITEM(l, (Py_ssize_t)i, item);
    }
    return l;
}

static PyObject *
new_curve(const char *fn, cf_status_t st, cf_bezier_t **c, const cf_diag_t *d)
{
    /* c is read after the call that made it: a pointer, as the order in
    ** which a call's arguments are evaluated is unspecified */
    if (st != CF_STATUS_OK)
        return cfpy_fail(fn, st, d);
    return cfpy_wrap_bezier(*c);
}

static PyObject *
bz_new(PyTypeObject *type, PyObject *args, PyObject *kw)
{
    static char *names[] = { "P", "weights", NULL };
    PyObject *P, *W = Py_None;
    PyArrayObject *p, *w = NULL;
    cf_bezier_t *c = NULL;
    cf_diag_t d;
    cf_status_t st;
    cfpy_Bezier *o;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|O:Bezier", names, &P, &W))
        return NULL;
    p = cfpy_points(P, "Bezier", "P", 1);
    if (p == NULL)
        return NULL;
    if (W != Py_None) {
        w = cfpy_array(W, "Bezier", "weights", 1, 1);
        if (w == NULL)
            goto fail;
        if (PyArray_DIM(w, 0) != PyArray_DIM(p, 0)) {
            cfpy_error("Bezier", "%zd weights for %zd points",
                       (Py_ssize_t)PyArray_DIM(w, 0),
                       (Py_ssize_t)PyArray_DIM(p, 0));
            goto fail;
        }
    }
    if (PyArray_DIM(p, 0) - 1 > INT_MAX) {
        cfpy_error("Bezier", "too many points");
        goto fail;
    }
    st = cf_bezier_create((size_t)PyArray_DIM(p, 1),
                          (int)(PyArray_DIM(p, 0) - 1),
                          (const double *)PyArray_DATA(p),
                          w != NULL ? (const double *)PyArray_DATA(w) : NULL,
                          &c, &d);
    if (st != CF_STATUS_OK) {
        cfpy_fail("Bezier", st, &d);
        goto fail;
    }
    o = (cfpy_Bezier *)type->tp_alloc(type, 0);
    if (o == NULL) {
        cf_bezier_destroy(c);
        goto fail;
    }
    o->c = c;
    Py_DECREF(p);
    Py_XDECREF(w);
    return (PyObject *)o;
fail:
    Py_DECREF(p);
    Py_XDECREF(w);
    return NULL;
}

static void
bz_dealloc(PyObject *self)
{
    cf_bezier_destroy(SELF(self));
    Py_TYPE(self)->tp_free(self);
}

static PyObject *
bz_repr(PyObject *self)
{
    cf_bezier_t *c = SELF(self);
    return PyUnicode_FromFormat("<curvefig.Bezier degree %d in R^%zu%s>",
                                cf_bezier_degree(c), cf_bezier_dim(c),
                                cf_bezier_is_rational(c) ? ", rational"
                                                         : "");
}

/* ---- evaluation ---------------------------------------------------------- */

static cf_status_t
many_eval(const void *c, const double *t, size_t n, double *out,
          const void *arg)
{
    (void)arg;
    return cf_bezier_eval_many(c, t, n, out);
}

static cf_status_t
many_derivs(const void *c, const double *t, size_t n, double *out,
            const void *arg)
{
    int k = *(const int *)arg;
    size_t w = (size_t)(k + 1) * cf_bezier_dim(c);
    for (size_t i = 0; i < n; i++) {
        cf_status_t st = cf_bezier_eval_derivs(c, t[i], k, out + i * w);
        if (st != CF_STATUS_OK)
            return st;
    }
    return CF_STATUS_OK;
}

typedef cf_status_t (*point_fn)(const cf_bezier_t *, double, double *);

static cf_status_t
many_point(const void *c, const double *t, size_t n, double *out,
           const void *arg)
{
    point_fn f = *(const point_fn *)arg;
    size_t w = cf_bezier_dim(c);
    for (size_t i = 0; i < n; i++) {
        cf_status_t st = f(c, t[i], out + i * w);
        if (st != CF_STATUS_OK)
            return st;
    }
    return CF_STATUS_OK;
}

static cf_status_t
curvature(const cf_bezier_t *c, double t, double *out)
{
    return cf_bezier_curvature(c, t, out);
}

static cf_status_t
many_offset(const void *c, const double *t, size_t n, double *out,
            const void *arg)
{
    return cf_offset_point_many(c, t, n, *(const double *)arg, out);
}

static PyObject *
bz_eval(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *names[] = { "t", "out", NULL };
    npy_intp dim = (npy_intp)cf_bezier_dim(SELF(self));
    PyObject *t, *out = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|O:eval", names, &t, &out))
        return NULL;
    return cfpy_eval_params_into(t, out, "eval", SELF(self), many_eval,
                                 NULL, &dim, 1, 0.0, 1.0);
}

static PyObject *
bz_derivs(PyObject *self, PyObject *args)
{
    PyObject *t;
    int k = 1;
    npy_intp extra[2];
    if (!PyArg_ParseTuple(args, "O|i:derivs", &t, &k))
        return NULL;
    if (k < 0 || k > 64)
        return cfpy_error("derivs", "the order is %d; it must be in 0..64",
                          k);
    extra[0] = k + 1;
    extra[1] = (npy_intp)cf_bezier_dim(SELF(self));
    return cfpy_eval_params(t, "derivs", SELF(self), many_derivs, &k, extra,
                            2, 0.0, 1.0);
}

static PyObject *
point_method(PyObject *self, PyObject *t, const char *fn, point_fn f,
             int vector)
{
    npy_intp dim = (npy_intp)cf_bezier_dim(SELF(self));
    return cfpy_eval_params(t, fn, SELF(self), many_point, &f, &dim,
                            vector ? 1 : 0, 0.0, 1.0);
}

static PyObject *
bz_tangent(PyObject *self, PyObject *t)
{
    return point_method(self, t, "tangent", cf_bezier_tangent, 1);
}

static PyObject *
bz_normal(PyObject *self, PyObject *t)
{
    return point_method(self, t, "normal", cf_bezier_normal, 1);
}

static PyObject *
bz_curvature(PyObject *self, PyObject *t)
{
    return point_method(self, t, "curvature", curvature, 0);
}

static PyObject *
bz_offset_point(PyObject *self, PyObject *args)
{
    PyObject *t, *dobj;
    double d;
    npy_intp two = 2;
    if (!PyArg_ParseTuple(args, "OO:offset_point", &t, &dobj) ||
        cfpy_finite(dobj, "offset_point", "the distance", &d) != 0)
        return NULL;
    if (cf_bezier_dim(SELF(self)) != 2)
        return cfpy_error("offset_point", "the curve is in R^%zu; offsets "
                          "are planar", cf_bezier_dim(SELF(self)));
    return cfpy_eval_params(t, "offset_point", SELF(self), many_offset, &d,
                            &two, 1, 0.0, 1.0);
}

static PyObject *
bz_decasteljau(PyObject *self, PyObject *tobj)
{
    cf_bezier_t *c = SELF(self);
    size_t dim = cf_bezier_dim(c);
    int n = cf_bezier_degree(c);
    double t, *buf;
    PyObject *levels;
    cf_status_t st;
    if (cfpy_finite(tobj, "decasteljau", "t", &t) != 0)
        return NULL;
    buf = PyMem_Malloc(cf_bezier_decasteljau_size(c) * sizeof(double));
    if (buf == NULL)
        return PyErr_NoMemory();
    st = cf_bezier_decasteljau(c, t, buf);
    if (st != CF_STATUS_OK) {
        PyMem_Free(buf);
        return cfpy_param_error("decasteljau", st, &t, 1, 0.0, 1.0);
    }
    levels = PyList_New(n + 1);
    for (int j = 0, at = 0; levels != NULL && j <= n; j++) {
        PyObject *lev = cfpy_matrix(buf + (size_t)at * dim, n + 1 - j,
                                    (npy_intp)dim);
        if (lev == NULL)
            Py_CLEAR(levels);
        else
            PyList_SET_ITEM(levels, j, lev);
        at += n + 1 - j;
    }
    PyMem_Free(buf);
    return levels;
}

/* ---- constructions ------------------------------------------------------- */

static PyObject *
bz_derivative(PyObject *self, PyObject *args)
{
    int k = 1;
    cf_bezier_t *out = NULL;
    cf_diag_t d;
    if (!PyArg_ParseTuple(args, "|i:derivative", &k))
        return NULL;
    return new_curve("derivative",
                     cf_bezier_derivative(SELF(self), k, &out, &d), &out, &d);
}

static PyObject *
bz_elevate(PyObject *self, PyObject *args)
{
    int r = 1;
    cf_bezier_t *out = NULL;
    cf_diag_t d;
    if (!PyArg_ParseTuple(args, "|i:elevate", &r))
        return NULL;
    return new_curve("elevate", cf_bezier_elevate(SELF(self), r, &out, &d),
                     &out, &d);
}

static PyObject *
bz_reverse(PyObject *self, PyObject *unused)
{
    cf_bezier_t *out = NULL;
    cf_diag_t d;
    (void)unused;
    return new_curve("reverse", cf_bezier_reverse(SELF(self), &out, &d), &out,
                     &d);
}

static PyObject *
bz_split(PyObject *self, PyObject *tobj)
{
    cf_bezier_t *l = NULL, *r = NULL;
    cf_diag_t d;
    cf_status_t st;
    double t;
    if (cfpy_finite(tobj, "split", "t", &t) != 0)
        return NULL;
    st = cf_bezier_split(SELF(self), t, &l, &r, &d);
    if (st != CF_STATUS_OK)
        return cfpy_fail("split", st, &d);
    return cfpy_pair(cfpy_wrap_bezier(l), cfpy_wrap_bezier(r));
}

static PyObject *
bz_segment(PyObject *self, PyObject *args)
{
    double a, b;
    cf_bezier_t *out = NULL;
    cf_diag_t d;
    if (!PyArg_ParseTuple(args, "dd:segment", &a, &b))
        return NULL;
    return new_curve("segment", cf_bezier_segment(SELF(self), a, b, &out, &d),
                     &out, &d);
}

static PyObject *
bz_transform(PyObject *self, PyObject *args)
{
    PyObject *Aobj, *bobj = Py_None;
    PyArrayObject *A;
    double *b;
    cf_bezier_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    if (!PyArg_ParseTuple(args, "O|O:transform", &Aobj, &bobj) ||
        cfpy_affine(Aobj, bobj, "transform", cf_bezier_dim(SELF(self)), &A,
                    &b) != 0)
        return NULL;
    st = cf_bezier_transform(SELF(self), PyArray_DATA(A), b, &out, &d);
    Py_DECREF(A);
    PyMem_Free(b);
    return new_curve("transform", st, &out, &d);
}

/* ---- queries and approximations ------------------------------------------ */

static PyObject *
bz_bbox(PyObject *self, PyObject *unused)
{
    size_t dim = cf_bezier_dim(SELF(self));
    PyArrayObject *lo, *hi;
    npy_intp n = (npy_intp)dim;
    cf_status_t st;
    (void)unused;
    lo = cfpy_new(1, &n);
    hi = cfpy_new(1, &n);
    if (lo != NULL && hi != NULL) {
        st = cf_bezier_bbox(SELF(self), PyArray_DATA(lo), PyArray_DATA(hi));
        if (st != CF_STATUS_OK) {
            cfpy_fail("bbox", st, NULL);
            Py_CLEAR(lo);
        }
    }
    return cfpy_pair((PyObject *)lo, (PyObject *)hi);
}

static PyObject *
bz_length(PyObject *self, PyObject *args)
{
    double tol = 1e-9, len;
    cf_status_t st;
    if (!PyArg_ParseTuple(args, "|d:length", &tol))
        return NULL;
    if (!(tol > 0.0))
        return cfpy_error("length", "the tolerance must be > 0");
    Py_BEGIN_ALLOW_THREADS
    st = cf_bezier_length(SELF(self), tol, &len);
    Py_END_ALLOW_THREADS
    if (st != CF_STATUS_OK)
        return cfpy_fail("length", st, NULL);
    return PyFloat_FromDouble(len);
}

static PyObject *
bz_closest(PyObject *self, PyObject *pobj)
{
    size_t dim = cf_bezier_dim(SELF(self));
    double *p = PyMem_Malloc(dim * sizeof(double)), t, dist;
    cf_status_t st;
    if (p == NULL)
        return PyErr_NoMemory();
    if (cfpy_point(pobj, "closest", "the point", dim, p) != 0) {
        PyMem_Free(p);
        return NULL;
    }
    st = cf_bezier_closest(SELF(self), p, &t, &dist);
    PyMem_Free(p);
    if (st != CF_STATUS_OK)
        return cfpy_fail("closest", st, NULL);
    return Py_BuildValue("(dd)", t, dist);
}

typedef struct flat {
    double *p;
    size_t n, cap, dim;
    int failed;
} flat_t;

static int
flat_point(void *closure, const double *p, double t)
{
    flat_t *f = closure;
    (void)t;
    if (f->failed)
        return 1;
    if (f->n == f->cap) {
        size_t cap = f->cap ? 2 * f->cap : 256;
        double *q = cap <= ((size_t)1 << 26)
                        ? PyMem_RawRealloc(f->p, cap * f->dim * sizeof(double))
                        : NULL;
        if (q == NULL) {
            f->failed = 1;
            return 1;
        }
        f->p = q;
        f->cap = cap;
    }
    memcpy(f->p + f->n * f->dim, p, f->dim * sizeof(double));
    f->n++;
    return 0;
}

static PyObject *
bz_flatten(PyObject *self, PyObject *args)
{
    flat_t f = { NULL, 0, 0, cf_bezier_dim(SELF(self)), 0 };
    double tol = 1e-3;
    PyObject *r;
    cf_status_t st;
    if (!PyArg_ParseTuple(args, "|d:flatten", &tol))
        return NULL;
    if (!(tol > 0.0))
        return cfpy_error("flatten", "the tolerance must be > 0");
    Py_BEGIN_ALLOW_THREADS
    st = cf_bezier_flatten(SELF(self), tol, flat_point, &f);
    Py_END_ALLOW_THREADS
    if (f.failed) {
        PyMem_RawFree(f.p);
        char b[CFPY_NUM];
        return cfpy_error("flatten", "too many points at tolerance %s",
                          cfpy_num(tol, b));
    }
    if (st != CF_STATUS_OK) {
        PyMem_RawFree(f.p);
        return cfpy_fail("flatten", st, NULL);
    }
    r = cfpy_matrix(f.p, (npy_intp)f.n, (npy_intp)f.dim);
    PyMem_RawFree(f.p);
    return r;
}

static PyObject *
bz_to_cubics(PyObject *self, PyObject *args)
{
    double tol = 1e-3;
    cf_cubics_t *cu = NULL;
    PyObject *l;
    cf_diag_t d;
    cf_status_t st;
    if (!PyArg_ParseTuple(args, "|d:to_cubics", &tol))
        return NULL;
    if (!(tol > 0.0))
        return cfpy_error("to_cubics", "the tolerance must be > 0");
    Py_BEGIN_ALLOW_THREADS
    st = cf_bezier_to_cubics(SELF(self), tol, &cu, &d);
    Py_END_ALLOW_THREADS
    if (st != CF_STATUS_OK)
        return cfpy_fail("to_cubics", st, &d);
    l = cfpy_cubics(cu);
    if (l == NULL) {
        cf_cubics_destroy(cu);
        return NULL;
    }
    l = Py_BuildValue("(Nd)", l, cu->max_error);
    cf_cubics_destroy(cu);
    return l;
}

static PyObject *
bz_reduce_degree(PyObject *self, PyObject *args, PyObject *kw)
{
    return cfpy_reduce(SELF(self), NULL, args, kw);
}

static PyObject *
bz_offset(PyObject *self, PyObject *args, PyObject *kw)
{
    return cfpy_offset(SELF(self), NULL, args, kw);
}

static PyObject *
bz_offset_cusps(PyObject *self, PyObject *dobj)
{
    double d, ts[64];
    size_t n = 0;
    cf_diag_t diag;
    cf_status_t st;
    if (cfpy_finite(dobj, "offset_cusps", "the distance", &d) != 0)
        return NULL;
    st = cf_offset_cusps(SELF(self), d, ts, 64, &n, &diag);
    if (st != CF_STATUS_OK)
        return cfpy_fail("offset_cusps", st, &diag);
    return cfpy_vector(ts, (npy_intp)(n < 64 ? n : 64));
}

/* ---- the control points -------------------------------------------------- */

static PyObject *
bz_points(PyObject *self, void *unused)
{
    cf_bezier_t *c = SELF(self);
    npy_intp shape[2] = { cf_bezier_degree(c) + 1,
                          (npy_intp)cf_bezier_dim(c) };
    PyArrayObject *a = cfpy_new(2, shape);
    (void)unused;
    if (a != NULL)
        cf_bezier_get_points(c, PyArray_DATA(a));
    return (PyObject *)a;
}

static PyObject *
bz_weights(PyObject *self, void *unused)
{
    cf_bezier_t *c = SELF(self);
    npy_intp n = cf_bezier_degree(c) + 1;
    PyArrayObject *a = cfpy_new(1, &n);
    (void)unused;
    if (a != NULL)
        cf_bezier_get_weights(c, PyArray_DATA(a));
    return (PyObject *)a;
}

static PyObject *
bz_degree(PyObject *self, void *unused)
{
    (void)unused;
    return PyLong_FromLong(cf_bezier_degree(SELF(self)));
}

static PyObject *
bz_dim(PyObject *self, void *unused)
{
    (void)unused;
    return PyLong_FromSize_t(cf_bezier_dim(SELF(self)));
}

static PyObject *
bz_is_rational(PyObject *self, void *unused)
{
    (void)unused;
    return PyBool_FromLong(cf_bezier_is_rational(SELF(self)));
}

static PyObject *
bz_reduce(PyObject *self, PyObject *unused)
{
    (void)unused;
    return Py_BuildValue("(O(NN))", Py_TYPE(self), bz_points(self, NULL),
                         cf_bezier_is_rational(SELF(self))
                             ? bz_weights(self, NULL) : Py_NewRef(Py_None));
}

static PyMethodDef bz_methods[] = {
    { "eval", (PyCFunction)(void (*)(void))bz_eval,
      METH_VARARGS | METH_KEYWORDS,
      "eval(t, out=None): the point c(t), or an array of points for an "
      "array of t (into out when given)" },
    { "derivs", bz_derivs, METH_VARARGS,
      "derivs(t, k=1): c(t), c'(t), ..., c^(k)(t) as rows (shape t.shape + "
      "(k+1, dim))" },
    { "tangent", bz_tangent, METH_O, "tangent(t): the unit tangent" },
    { "normal", bz_normal, METH_O,
      "normal(t): the unit normal (left of travel in 2D)" },
    { "curvature", bz_curvature, METH_O,
      "curvature(t): signed in 2D" },
    { "offset_point", bz_offset_point, METH_VARARGS,
      "offset_point(t, d): c(t) + d n(t) (planar curves)" },
    { "offset_cusps", bz_offset_cusps, METH_O,
      "offset_cusps(d): the parameters of the offset's cusps" },
    { "decasteljau", bz_decasteljau, METH_O,
      "decasteljau(t): the levels of de Casteljau's triangle, a list of "
      "arrays (level 0 the control points, the last c(t))" },
    { "derivative", bz_derivative, METH_VARARGS,
      "derivative(k=1): the curve of the k-th derivative" },
    { "elevate", bz_elevate, METH_VARARGS,
      "elevate(r=1): the same curve of degree n + r" },
    { "reverse", bz_reverse, METH_NOARGS, "reverse(): r(t) = c(1 - t)" },
    { "split", bz_split, METH_O, "split(t): left, right" },
    { "segment", bz_segment, METH_VARARGS,
      "segment(a, b): the piece on [a, b] as a curve on [0, 1]" },
    { "transform", bz_transform, METH_VARARGS,
      "transform(A, b=None): the affine image x -> A x + b" },
    { "bbox", bz_bbox, METH_NOARGS, "bbox(): lo, hi of the curve" },
    { "length", bz_length, METH_VARARGS, "length(tol=1e-9): arc length" },
    { "closest", bz_closest, METH_O,
      "closest(p): t, distance of the nearest point of the curve" },
    { "flatten", bz_flatten, METH_VARARGS,
      "flatten(tol=1e-3): a polyline within tol of the curve" },
    { "to_cubics", bz_to_cubics, METH_VARARGS,
      "to_cubics(tol=1e-3): a list of cubic Bézier curves, achieved error" },
    { "offset", (PyCFunction)(void (*)(void))bz_offset,
      METH_VARARGS | METH_KEYWORDS,
      "offset(d, tolerance=1e-3, trim=False, method='levien'): list of cubic "
      "Bézier curves, report (and the trimmed chains when trim)" },
    { "reduce", (PyCFunction)(void (*)(void))bz_reduce_degree,
      METH_VARARGS | METH_KEYWORDS,
      "reduce(by=1, continuity=0, method='l2', tolerance=1e-3): degree "
      "reduction; the curve and a report (max_error, bound, ...)" },
    { "__reduce__", bz_reduce, METH_NOARGS, NULL },
    { NULL, NULL, 0, NULL }
};

static PyGetSetDef bz_getset[] = {
    { "points", bz_points, NULL, "the control points (a new array)", NULL },
    { "weights", bz_weights, NULL, "the weights (all 1 when polynomial)",
      NULL },
    { "degree", bz_degree, NULL, "the degree n", NULL },
    { "dim", bz_dim, NULL, "the dimension of the points", NULL },
    { "is_rational", bz_is_rational, NULL, "True for a rational curve", NULL },
    { NULL, NULL, NULL, NULL, NULL }
};

PyTypeObject cfpy_BezierType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "curvefig.Bezier",
    .tp_basicsize = sizeof(cfpy_Bezier),
    .tp_dealloc = bz_dealloc,
    .tp_repr = bz_repr,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "Bezier(P, weights=None): a Bézier curve with control points "
              "P (an (n+1, dim) array); weights make it rational.  "
              "Immutable: every method returns new values.",
    .tp_methods = bz_methods,
    .tp_getset = bz_getset,
    .tp_new = bz_new,
};
