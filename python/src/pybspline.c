/*
** curvefig.BSpline: B-spline and NURBS curves as numpy arrays (the
** language's bspline{}, render/lua/lbspline.c, in Python).
*/
#include "pycommon.h"

#define SELF(o) (((cfpy_BSpline *)(o))->c)

PyObject *
cfpy_wrap_bspline(cf_bspline_t *c)
{
    cfpy_BSpline *o = PyObject_New(cfpy_BSpline, &cfpy_BSplineType);
    if (o == NULL) {
        cf_bspline_destroy(c);
        return NULL;
    }
    o->c = c;
    return (PyObject *)o;
}

static PyObject *
new_curve(const char *fn, cf_status_t st, cf_bspline_t **c, const cf_diag_t *d)
{
    /* c is read after the call that made it: a pointer, as the order in
    ** which a call's arguments are evaluated is unspecified */
    if (st != CF_STATUS_OK)
        return cfpy_fail(fn, st, d);
    return cfpy_wrap_bspline(*c);
}

static void
domain(PyObject *self, double *a, double *b)
{
    cf_bspline_domain(SELF(self), a, b);
}

static PyObject *
bs_new(PyTypeObject *type, PyObject *args, PyObject *kw)
{
    static char *names[] = { "degree", "knots", "P", "weights", NULL };
    PyObject *K, *P, *W = Py_None;
    PyArrayObject *k = NULL, *p, *w = NULL;
    cf_bspline_t *c = NULL;
    cf_diag_t d;
    cf_status_t st;
    cfpy_BSpline *o;
    int degree;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "iOO|O:BSpline", names,
                                     &degree, &K, &P, &W))
        return NULL;
    p = cfpy_points(P, "BSpline", "P", 1);
    if (p == NULL)
        return NULL;
    if (W != Py_None) {
        w = cfpy_array(W, "BSpline", "weights", 1, 1);
        if (w == NULL)
            goto fail;
        if (PyArray_DIM(w, 0) != PyArray_DIM(p, 0)) {
            cfpy_error("BSpline", "%zd weights for %zd points",
                       (Py_ssize_t)PyArray_DIM(w, 0),
                       (Py_ssize_t)PyArray_DIM(p, 0));
            goto fail;
        }
    }
    if (K == Py_None || PyUnicode_Check(K)) {
        /* knots generated: "clamped" (None) or "closed" */
        const char *kind = K == Py_None ? "clamped" : PyUnicode_AsUTF8(K);
        if (kind == NULL)
            goto fail;
        if (strcmp(kind, "clamped") == 0)
            st = cf_bspline_create_clamped((size_t)PyArray_DIM(p, 1), degree,
                                           PyArray_DATA(p),
                                           (size_t)PyArray_DIM(p, 0),
                                           w ? PyArray_DATA(w) : NULL, &c,
                                           &d);
        else if (strcmp(kind, "closed") == 0)
            st = cf_bspline_create_closed((size_t)PyArray_DIM(p, 1), degree,
                                          PyArray_DATA(p),
                                          (size_t)PyArray_DIM(p, 0),
                                          w ? PyArray_DATA(w) : NULL, &c, &d);
        else {
            cfpy_error("BSpline", "knots must be an array, None (clamped "
                       "uniform) or \"closed\", got %R", K);
            goto fail;
        }
    } else {
        k = cfpy_array(K, "BSpline", "knots", 1, 1);
        if (k == NULL)
            goto fail;
        st = cf_bspline_create((size_t)PyArray_DIM(p, 1), degree,
                               PyArray_DATA(k), (size_t)PyArray_DIM(k, 0),
                               PyArray_DATA(p), (size_t)PyArray_DIM(p, 0),
                               w ? PyArray_DATA(w) : NULL, &c, &d);
    }
    if (st != CF_STATUS_OK) {
        cfpy_fail("BSpline", st, &d);
        goto fail;
    }
    o = (cfpy_BSpline *)type->tp_alloc(type, 0);
    if (o == NULL) {
        cf_bspline_destroy(c);
        goto fail;
    }
    o->c = c;
    Py_XDECREF(k);
    Py_DECREF(p);
    Py_XDECREF(w);
    return (PyObject *)o;
fail:
    Py_XDECREF(k);
    Py_DECREF(p);
    Py_XDECREF(w);
    return NULL;
}

static void
bs_dealloc(PyObject *self)
{
    cf_bspline_destroy(SELF(self));
    Py_TYPE(self)->tp_free(self);
}

static PyObject *
bs_repr(PyObject *self)
{
    cf_bspline_t *c = SELF(self);
    return PyUnicode_FromFormat("<curvefig.BSpline degree %d, %zu points in "
                                "R^%zu%s>", cf_bspline_degree(c),
                                cf_bspline_count(c), cf_bspline_dim(c),
                                cf_bspline_is_rational(c) ? ", rational"
                                                          : "");
}

/* ---- evaluation ---------------------------------------------------------- */

static cf_status_t
many_eval(const void *c, const double *t, size_t n, double *out,
          const void *arg)
{
    (void)arg;
    return cf_bspline_eval_many(c, t, n, out);
}

static cf_status_t
many_derivs(const void *c, const double *t, size_t n, double *out,
            const void *arg)
{
    int k = *(const int *)arg;
    size_t w = (size_t)(k + 1) * cf_bspline_dim(c);
    for (size_t i = 0; i < n; i++) {
        cf_status_t st = cf_bspline_eval_derivs(c, t[i], k, out + i * w);
        if (st != CF_STATUS_OK)
            return st;
    }
    return CF_STATUS_OK;
}

static PyObject *
bs_eval(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *names[] = { "u", "out", NULL };
    npy_intp dim = (npy_intp)cf_bspline_dim(SELF(self));
    PyObject *t, *out = NULL;
    double a, b;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|O:eval", names, &t, &out))
        return NULL;
    domain(self, &a, &b);
    return cfpy_eval_params_into(t, out, "eval", SELF(self), many_eval,
                                 NULL, &dim, 1, a, b);
}

static PyObject *
bs_derivs(PyObject *self, PyObject *args)
{
    PyObject *t;
    int k = 1;
    npy_intp extra[2];
    double a, b;
    if (!PyArg_ParseTuple(args, "O|i:derivs", &t, &k))
        return NULL;
    if (k < 0 || k > 64)
        return cfpy_error("derivs", "the order is %d; it must be in 0..64",
                          k);
    extra[0] = k + 1;
    extra[1] = (npy_intp)cf_bspline_dim(SELF(self));
    domain(self, &a, &b);
    return cfpy_eval_params(t, "derivs", SELF(self), many_derivs, &k, extra,
                            2, a, b);
}

static PyObject *
bs_deboor(PyObject *self, PyObject *uobj)
{
    cf_bspline_t *c = SELF(self);
    size_t dim = cf_bspline_dim(c), span;
    int p = cf_bspline_degree(c), mult;
    double u, *buf, a, b;
    PyObject *levels;
    cf_status_t st;
    if (cfpy_finite(uobj, "deboor", "u", &u) != 0)
        return NULL;
    buf = PyMem_Malloc(cf_bspline_deboor_size(c) * sizeof(double));
    if (buf == NULL)
        return PyErr_NoMemory();
    st = cf_bspline_deboor(c, u, buf, &span, &mult);
    if (st != CF_STATUS_OK) {
        PyMem_Free(buf);
        domain(self, &a, &b);
        return cfpy_param_error("deboor", st, &u, 1, a, b);
    }
    levels = PyList_New(p + 1);
    for (int j = 0, at = 0; levels != NULL && j <= p; j++) {
        PyObject *lev = cfpy_matrix(buf + (size_t)at * dim, p + 1 - j,
                                    (npy_intp)dim);
        if (lev == NULL)
            Py_CLEAR(levels);
        else
            PyList_SET_ITEM(levels, j, lev);
        at += p + 1 - j;
    }
    PyMem_Free(buf);
    if (levels == NULL)
        return NULL;
    return Py_BuildValue("(Nni)", levels, (Py_ssize_t)span, mult);
}

static PyObject *
bs_basis(PyObject *self, PyObject *uobj)
{
    cf_bspline_t *c = SELF(self);
    double u, N[CF_BSPLINE_MAX_DEGREE + 1], a, b;
    size_t first;
    cf_status_t st;
    if (cfpy_finite(uobj, "basis", "u", &u) != 0)
        return NULL;
    st = cf_bspline_basis(c, u, &first, N);
    if (st != CF_STATUS_OK) {
        domain(self, &a, &b);
        return cfpy_param_error("basis", st, &u, 1, a, b);
    }
    return Py_BuildValue("(nN)", (Py_ssize_t)first,
                         cfpy_vector(N, cf_bspline_degree(c) + 1));
}

/* ---- constructions ------------------------------------------------------- */

static PyObject *
bs_derivative(PyObject *self, PyObject *args)
{
    int k = 1;
    cf_bspline_t *out = NULL;
    cf_diag_t d;
    if (!PyArg_ParseTuple(args, "|i:derivative", &k))
        return NULL;
    return new_curve("derivative",
                     cf_bspline_derivative(SELF(self), k, &out, &d), &out, &d);
}

static PyObject *
bs_insert_knot(PyObject *self, PyObject *args)
{
    double u;
    int r = 1;
    cf_bspline_t *out = NULL;
    cf_diag_t d;
    if (!PyArg_ParseTuple(args, "d|i:insert_knot", &u, &r))
        return NULL;
    return new_curve("insert_knot",
                     cf_bspline_insert_knot(SELF(self), u, r, &out, NULL, &d),
                     &out, &d);
}

static PyObject *
bs_refine(PyObject *self, PyObject *xobj)
{
    PyArrayObject *x = cfpy_array(xobj, "refine", "the knots", 1, 1);
    cf_bspline_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    if (x == NULL)
        return NULL;
    st = cf_bspline_refine(SELF(self), PyArray_DATA(x),
                           (size_t)PyArray_DIM(x, 0), &out, &d);
    Py_DECREF(x);
    return new_curve("refine", st, &out, &d);
}

static PyObject *
bs_remove_knot(PyObject *self, PyObject *args)
{
    double u, tol = 1e-9;
    int r = 1, removed = 0;
    cf_bspline_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    if (!PyArg_ParseTuple(args, "d|id:remove_knot", &u, &r, &tol))
        return NULL;
    st = cf_bspline_remove_knot(SELF(self), u, r, tol, &out, &removed, &d);
    if (st != CF_STATUS_OK)
        return cfpy_fail("remove_knot", st, &d);
    return Py_BuildValue("(Ni)", cfpy_wrap_bspline(out), removed);
}

static PyObject *
bs_elevate(PyObject *self, PyObject *args)
{
    int t = 1;
    cf_bspline_t *out = NULL;
    cf_diag_t d;
    if (!PyArg_ParseTuple(args, "|i:elevate", &t))
        return NULL;
    return new_curve("elevate", cf_bspline_elevate(SELF(self), t, &out, &d),
                     &out, &d);
}

static PyObject *
bs_reverse(PyObject *self, PyObject *unused)
{
    cf_bspline_t *out = NULL;
    cf_diag_t d;
    (void)unused;
    return new_curve("reverse", cf_bspline_reverse(SELF(self), &out, &d),
                     &out, &d);
}

static PyObject *
bs_split(PyObject *self, PyObject *uobj)
{
    cf_bspline_t *l = NULL, *r = NULL;
    cf_diag_t d;
    cf_status_t st;
    double u;
    if (cfpy_finite(uobj, "split", "u", &u) != 0)
        return NULL;
    st = cf_bspline_split(SELF(self), u, &l, &r, &d);
    if (st != CF_STATUS_OK)
        return cfpy_fail("split", st, &d);
    return cfpy_pair(cfpy_wrap_bspline(l), cfpy_wrap_bspline(r));
}

static PyObject *
bs_segment(PyObject *self, PyObject *args)
{
    double a, b;
    cf_bspline_t *out = NULL;
    cf_diag_t d;
    if (!PyArg_ParseTuple(args, "dd:segment", &a, &b))
        return NULL;
    return new_curve("segment",
                     cf_bspline_segment(SELF(self), a, b, &out, &d), &out, &d);
}

static PyObject *
bs_move_point(PyObject *self, PyObject *args)
{
    Py_ssize_t i;
    PyObject *vobj;
    size_t dim = cf_bspline_dim(SELF(self));
    double *v;
    cf_bspline_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    if (!PyArg_ParseTuple(args, "nO:move_point", &i, &vobj))
        return NULL;
    if (i < 0)
        return cfpy_error("move_point", "index %zd is negative", i);
    v = PyMem_Malloc(dim * sizeof(double));
    if (v == NULL)
        return PyErr_NoMemory();
    if (cfpy_point(vobj, "move_point", "v", dim, v) != 0) {
        PyMem_Free(v);
        return NULL;
    }
    st = cf_bspline_move_point(SELF(self), (size_t)i, v, &out, &d);
    PyMem_Free(v);
    return new_curve("move_point", st, &out, &d);
}

static PyObject *
bs_to_beziers(PyObject *self, PyObject *unused)
{
    cf_bezier_list_t *list = NULL;
    cf_diag_t d;
    cf_status_t st;
    (void)unused;
    st = cf_bspline_to_beziers(SELF(self), &list, &d);
    if (st != CF_STATUS_OK)
        return cfpy_fail("to_beziers", st, &d);
    return cfpy_bezier_list(list);
}

static PyObject *
bs_reduce_degree(PyObject *self, PyObject *args, PyObject *kw)
{
    return cfpy_reduce(NULL, SELF(self), args, kw);
}

static PyObject *
bs_offset(PyObject *self, PyObject *args, PyObject *kw)
{
    return cfpy_offset(NULL, SELF(self), args, kw);
}

static PyObject *
bs_support(PyObject *self, PyObject *args)
{
    Py_ssize_t i;
    double lo, hi;
    cf_status_t st;
    if (!PyArg_ParseTuple(args, "n:support", &i))
        return NULL;
    if (i < 0)
        return cfpy_error("support", "index %zd is negative", i);
    st = cf_bspline_support(SELF(self), (size_t)i, &lo, &hi);
    if (st != CF_STATUS_OK)
        return cfpy_error("support", "no control point P_%zd (the curve has "
                          "%zu)", i, cf_bspline_count(SELF(self)));
    return Py_BuildValue("(dd)", lo, hi);
}

static PyObject *
bs_transform(PyObject *self, PyObject *args)
{
    PyObject *Aobj, *bobj = Py_None;
    PyArrayObject *A;
    double *b;
    cf_bspline_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    if (!PyArg_ParseTuple(args, "O|O:transform", &Aobj, &bobj) ||
        cfpy_affine(Aobj, bobj, "transform", cf_bspline_dim(SELF(self)), &A,
                    &b) != 0)
        return NULL;
    st = cf_bspline_transform(SELF(self), PyArray_DATA(A), b, &out, &d);
    Py_DECREF(A);
    PyMem_Free(b);
    return new_curve("transform", st, &out, &d);
}

/* (first, (span_lo, span_hi)): P_first .. P_first+p act on the span that
** contains u, as the language's s:active_points(u). */
static PyObject *
bs_active_points(PyObject *self, PyObject *uobj)
{
    size_t first;
    double u, lo, hi, a, b;
    cf_status_t st;
    if (cfpy_finite(uobj, "active_points", "u", &u) != 0)
        return NULL;
    st = cf_bspline_active_points(SELF(self), u, &first, &lo, &hi);
    if (st != CF_STATUS_OK) {
        domain(self, &a, &b);
        return cfpy_param_error("active_points", st, &u, 1, a, b);
    }
    return Py_BuildValue("(n(dd))", (Py_ssize_t)first, lo, hi);
}

/* ---- the control points and knots --------------------------------------- */

static PyObject *
bs_points(PyObject *self, void *unused)
{
    cf_bspline_t *c = SELF(self);
    npy_intp shape[2] = { (npy_intp)cf_bspline_count(c),
                          (npy_intp)cf_bspline_dim(c) };
    PyArrayObject *a = cfpy_new(2, shape);
    (void)unused;
    if (a != NULL)
        cf_bspline_get_points(c, PyArray_DATA(a));
    return (PyObject *)a;
}

static PyObject *
bs_weights(PyObject *self, void *unused)
{
    cf_bspline_t *c = SELF(self);
    npy_intp n = (npy_intp)cf_bspline_count(c);
    PyArrayObject *a = cfpy_new(1, &n);
    (void)unused;
    if (a != NULL)
        cf_bspline_get_weights(c, PyArray_DATA(a));
    return (PyObject *)a;
}

static PyObject *
bs_knots(PyObject *self, void *unused)
{
    (void)unused;
    return cfpy_vector(cf_bspline_knots(SELF(self)),
                       (npy_intp)cf_bspline_nknots(SELF(self)));
}

static PyObject *
bs_domain(PyObject *self, void *unused)
{
    double a, b;
    (void)unused;
    domain(self, &a, &b);
    return Py_BuildValue("(dd)", a, b);
}

static PyObject *
bs_degree(PyObject *self, void *unused)
{
    (void)unused;
    return PyLong_FromLong(cf_bspline_degree(SELF(self)));
}

static PyObject *
bs_dim(PyObject *self, void *unused)
{
    (void)unused;
    return PyLong_FromSize_t(cf_bspline_dim(SELF(self)));
}

static PyObject *
bs_count(PyObject *self, void *unused)
{
    (void)unused;
    return PyLong_FromSize_t(cf_bspline_count(SELF(self)));
}

static PyObject *
bs_is_rational(PyObject *self, void *unused)
{
    (void)unused;
    return PyBool_FromLong(cf_bspline_is_rational(SELF(self)));
}

static PyObject *
bs_knot_kind(PyObject *self, void *unused)
{
    (void)unused;
    return PyUnicode_FromString(
        cf_knot_kind_to_string(cf_bspline_knot_kind(SELF(self))));
}

static PyObject *
bs_reduce(PyObject *self, PyObject *unused)
{
    (void)unused;
    return Py_BuildValue("(O(iNNN))", Py_TYPE(self),
                         cf_bspline_degree(SELF(self)), bs_knots(self, NULL),
                         bs_points(self, NULL),
                         cf_bspline_is_rational(SELF(self))
                             ? bs_weights(self, NULL) : Py_NewRef(Py_None));
}

static PyMethodDef bs_methods[] = {
    { "eval", (PyCFunction)(void (*)(void))bs_eval,
      METH_VARARGS | METH_KEYWORDS,
      "eval(u, out=None): the point C(u), or an array of points for an "
      "array of u (into out when given)" },
    { "derivs", bs_derivs, METH_VARARGS,
      "derivs(u, k=1): C(u), C'(u), ..., C^(k)(u) as rows" },
    { "deboor", bs_deboor, METH_O,
      "deboor(u): levels of the de Boor net (a list of arrays), span k, "
      "multiplicity of u" },
    { "basis", bs_basis, METH_O,
      "basis(u): first, the values N_first^p(u) .. N_first+p^p(u)" },
    { "derivative", bs_derivative, METH_VARARGS,
      "derivative(k=1): the curve of the k-th derivative" },
    { "insert_knot", bs_insert_knot, METH_VARARGS,
      "insert_knot(u, r=1): the same curve with u inserted r times" },
    { "refine", bs_refine, METH_O, "refine(x): every knot of x inserted" },
    { "remove_knot", bs_remove_knot, METH_VARARGS,
      "remove_knot(u, r=1, tol=1e-9): curve, times removed" },
    { "elevate", bs_elevate, METH_VARARGS,
      "elevate(t=1): the same curve of degree p + t" },
    { "reverse", bs_reverse, METH_NOARGS, "reverse()" },
    { "transform", bs_transform, METH_VARARGS,
      "transform(A, b=None): the affine image x -> A x + b" },
    { "active_points", bs_active_points, METH_O,
      "active_points(u): (first, (lo, hi)): P_first..P_first+p act on the "
      "span [lo, hi) that contains u" },
    { "split", bs_split, METH_O, "split(u): left, right" },
    { "segment", bs_segment, METH_VARARGS, "segment(a, b)" },
    { "move_point", bs_move_point, METH_VARARGS,
      "move_point(i, v): the curve with P_i moved by v" },
    { "to_beziers", bs_to_beziers, METH_NOARGS,
      "to_beziers(): the Bézier pieces, one per non-empty span" },
    { "support", bs_support, METH_VARARGS,
      "support(i): lo, hi of the span P_i acts on" },
    { "offset", (PyCFunction)(void (*)(void))bs_offset,
      METH_VARARGS | METH_KEYWORDS,
      "offset(d, tolerance=1e-3, trim=False, method='levien')" },
    { "reduce", (PyCFunction)(void (*)(void))bs_reduce_degree,
      METH_VARARGS | METH_KEYWORDS,
      "reduce(by=1, continuity=0, method='l2', tolerance=1e-3): degree "
      "reduction; the curve and a report (max_error, bound, ...)" },
    { "__reduce__", bs_reduce, METH_NOARGS, NULL },
    { NULL, NULL, 0, NULL }
};

static PyGetSetDef bs_getset[] = {
    { "points", bs_points, NULL, "the control points (a new array)", NULL },
    { "weights", bs_weights, NULL, "the weights", NULL },
    { "knots", bs_knots, NULL, "the whole knot vector", NULL },
    { "domain", bs_domain, NULL, "(a, b)", NULL },
    { "degree", bs_degree, NULL, "the degree p", NULL },
    { "dim", bs_dim, NULL, "the dimension of the points", NULL },
    { "count", bs_count, NULL, "the number of control points", NULL },
    { "is_rational", bs_is_rational, NULL, "True for a NURBS", NULL },
    { "knot_kind", bs_knot_kind, NULL, "clamped, uniform, ...", NULL },
    { NULL, NULL, NULL, NULL, NULL }
};

PyTypeObject cfpy_BSplineType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "curvefig.BSpline",
    .tp_basicsize = sizeof(cfpy_BSpline),
    .tp_dealloc = bs_dealloc,
    .tp_repr = bs_repr,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "BSpline(degree, knots, P, weights=None): a B-spline curve "
              "(a NURBS with weights); knots None gives clamped uniform "
              "knots on [0, 1], \"closed\" a closed curve.  Immutable.",
    .tp_methods = bs_methods,
    .tp_getset = bs_getset,
    .tp_new = bs_new,
};
