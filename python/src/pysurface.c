/*
** curvefig.BezierSurface and curvefig.BSplineSurface: tensor-product
** surfaces as numpy arrays (the language's bezier_surface{} and
** bspline_surface{}, render/lua/lsurface*.c, in Python).  Both types share
** these functions through a table of the core's calls for each kind.
*/
#include "pycommon.h"

typedef struct {
    PyObject_HEAD
    void *s;
} cfpy_Surface;

typedef struct kind {
    int bspline;
    size_t (*dim)(const void *);
    bool (*rational)(const void *);
    cf_status_t (*eval)(const void *, double, double, double *);
    cf_status_t (*normal)(const void *, double, double, double *);
    cf_status_t (*curvature)(const void *, double, double, double *,
                             double *);
    cf_status_t (*derivs)(const void *, double, double, int, double *);
    void (*get_points)(const void *, double *);
    void (*get_weights)(const void *, double *);
    void (*destroy)(void *);
} kind_t;

/* The core's calls of one kind, with the surface as void *. */
#define KIND_FUNCS(K, T) \
    static size_t K##_dim(const void *s) { return cf_##K##_dim(s); } \
    static bool K##_rational(const void *s) \
    { return cf_##K##_is_rational(s); } \
    static cf_status_t K##_eval(const void *s, double u, double v, \
                                double *o) \
    { return cf_##K##_eval((const T *)s, u, v, o); } \
    static cf_status_t K##_normal(const void *s, double u, double v, \
                                  double *o) \
    { return cf_##K##_normal((const T *)s, u, v, o); } \
    static cf_status_t K##_curvature(const void *s, double u, double v, \
                                     double *g, double *h) \
    { return cf_##K##_curvature((const T *)s, u, v, g, h); } \
    static cf_status_t K##_derivs(const void *s, double u, double v, \
                                  int k, double *o) \
    { return cf_##K##_eval_derivs((const T *)s, u, v, k, o); } \
    static void K##_points(const void *s, double *o) \
    { cf_##K##_get_points((const T *)s, o); } \
    static void K##_weights(const void *s, double *o) \
    { cf_##K##_get_weights((const T *)s, o); } \
    static void K##_destroy(void *s) { cf_##K##_destroy((T *)s); }

KIND_FUNCS(bezier_surface, cf_bezier_surface_t)
KIND_FUNCS(bspline_surface, cf_bspline_surface_t)

static const kind_t bezier_kind = {
    0, bezier_surface_dim, bezier_surface_rational, bezier_surface_eval,
    bezier_surface_normal, bezier_surface_curvature, bezier_surface_derivs,
    bezier_surface_points, bezier_surface_weights, bezier_surface_destroy,
};

static const kind_t bspline_kind = {
    1, bspline_surface_dim, bspline_surface_rational, bspline_surface_eval,
    bspline_surface_normal, bspline_surface_curvature,
    bspline_surface_derivs, bspline_surface_points, bspline_surface_weights,
    bspline_surface_destroy,
};

#define SELF(o) (((cfpy_Surface *)(o))->s)
#define KIND(o) (Py_TYPE(o) == &cfpy_BSplineSurfaceType ? &bspline_kind \
                                                          : &bezier_kind)

static PyObject *
wrap(const kind_t *k, void *s)
{
    cfpy_Surface *o = PyObject_New(cfpy_Surface, k->bspline
                                                     ? &cfpy_BSplineSurfaceType
                                                     : &cfpy_BezierSurfaceType);
    if (o == NULL) {
        k->destroy(s);
        return NULL;
    }
    o->s = s;
    return (PyObject *)o;
}

PyObject *
cfpy_wrap_bspline_surface(cf_bspline_surface_t *s)
{
    return wrap(&bspline_kind, s);
}

PyObject *
cfpy_wrap_bezier_surface(cf_bezier_surface_t *s)
{
    return wrap(&bezier_kind, s);
}

static PyObject *
new_surface(const kind_t *k, const char *fn, cf_status_t st, void **s,
            const cf_diag_t *d)
{
    if (st != CF_STATUS_OK)
        return cfpy_fail(fn, st, d);
    return wrap(k, *s);
}

static void
sf_dealloc(PyObject *self)
{
    KIND(self)->destroy(SELF(self));
    Py_TYPE(self)->tp_free(self);
}

/* The grid P (rows along u) and the weights W of a constructor. */
static int
grid(const char *fn, PyObject *P, PyObject *W, PyArrayObject **p,
     PyArrayObject **w)
{
    *w = NULL;
    *p = cfpy_array(P, fn, "P", 3, 1);
    if (*p == NULL)
        return -1;
    if (PyArray_DIM(*p, 0) < 1 || PyArray_DIM(*p, 1) < 1 ||
        PyArray_DIM(*p, 2) < 1) {
        cfpy_error(fn, "P must be a grid of shape (rows, columns, dim)");
        Py_CLEAR(*p);
        return -1;
    }
    if (W == Py_None)
        return 0;
    *w = cfpy_array(W, fn, "weights", 2, 1);
    if (*w == NULL ||
        PyArray_DIM(*w, 0) != PyArray_DIM(*p, 0) ||
        PyArray_DIM(*w, 1) != PyArray_DIM(*p, 1)) {
        if (*w != NULL)
            cfpy_error(fn, "the weights must be a (%zd, %zd) grid",
                       (Py_ssize_t)PyArray_DIM(*p, 0),
                       (Py_ssize_t)PyArray_DIM(*p, 1));
        Py_CLEAR(*p);
        Py_CLEAR(*w);
        return -1;
    }
    return 0;
}

static PyObject *
bzs_new(PyTypeObject *type, PyObject *args, PyObject *kw)
{
    static char *names[] = { "P", "weights", NULL };
    PyObject *P, *W = Py_None;
    PyArrayObject *p, *w;
    cf_bezier_surface_t *s = NULL;
    cf_diag_t d;
    cf_status_t st;
    cfpy_Surface *o;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|O:BezierSurface", names, &P,
                                     &W) ||
        grid("BezierSurface", P, W, &p, &w) != 0)
        return NULL;
    st = cf_bezier_surface_create((size_t)PyArray_DIM(p, 2),
                                  (int)PyArray_DIM(p, 0) - 1,
                                  (int)PyArray_DIM(p, 1) - 1, PyArray_DATA(p),
                                  w ? PyArray_DATA(w) : NULL, &s, &d);
    Py_DECREF(p);
    Py_XDECREF(w);
    if (st != CF_STATUS_OK)
        return cfpy_fail("BezierSurface", st, &d);
    o = (cfpy_Surface *)type->tp_alloc(type, 0);
    if (o == NULL) {
        cf_bezier_surface_destroy(s);
        return NULL;
    }
    o->s = s;
    return (PyObject *)o;
}

/* The two items of a sequence (a tuple or a list) by PyArg_ParseTuple's
** format fmt; 0 (no exception set) when seq is not a pair of them. */
static int
pair_of(PyObject *seq, const char *fmt, void *a, void *b)
{
    PyObject *t = PySequence_Check(seq) && !PyUnicode_Check(seq)
                      ? PySequence_Tuple(seq) : NULL;
    int ok = t != NULL && PyArg_ParseTuple(t, fmt, a, b);
    Py_XDECREF(t);
    if (!ok)
        PyErr_Clear();
    return ok;
}

static PyObject *
bss_new(PyTypeObject *type, PyObject *args, PyObject *kw)
{
    static char *names[] = { "degree", "knots", "P", "weights", NULL };
    PyObject *D, *K, *P, *W = Py_None;
    PyArrayObject *p, *w, *U = NULL, *V = NULL;
    cf_bspline_surface_t *s = NULL;
    cf_diag_t d;
    cf_status_t st = CF_STATUS_OK;
    cfpy_Surface *o;
    int deg[2];
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OOO|O:BSplineSurface", names,
                                     &D, &K, &P, &W))
        return NULL;
    if (PyLong_Check(D)) {
        deg[0] = deg[1] = (int)PyLong_AsLong(D);
    } else if (!pair_of(D, "ii", &deg[0], &deg[1])) {
        return cfpy_error("BSplineSurface", "degree must be p or (p, q)");
    }
    if (PyErr_Occurred())
        return NULL;
    if (grid("BSplineSurface", P, W, &p, &w) != 0)
        return NULL;
    if (K == Py_None) {
        /* clamped uniform knots on [0, 1] both ways */
        size_t nu = (size_t)PyArray_DIM(p, 0), nv = (size_t)PyArray_DIM(p, 1);
        npy_intp mu = (npy_intp)cf_knots_count(deg[0], nu),
                 mv = (npy_intp)cf_knots_count(deg[1], nv);
        U = cfpy_new(1, &mu);
        V = cfpy_new(1, &mv);
        if (U == NULL || V == NULL)
            goto fail;
        st = cf_knots_clamped_uniform(deg[0], nu, 0.0, 1.0, PyArray_DATA(U),
                                      &d);
        if (st == CF_STATUS_OK)
            st = cf_knots_clamped_uniform(deg[1], nv, 0.0, 1.0,
                                          PyArray_DATA(V), &d);
    } else {
        PyObject *Uo, *Vo;
        if (!pair_of(K, "OO", &Uo, &Vo)) {
            cfpy_error("BSplineSurface", "knots must be (U, V) or None");
            goto fail;
        }
        U = cfpy_array(Uo, "BSplineSurface", "U", 1, 1);
        V = U != NULL ? cfpy_array(Vo, "BSplineSurface", "V", 1, 1) : NULL;
        if (V == NULL)
            goto fail;
    }
    if (st == CF_STATUS_OK)
        st = cf_bspline_surface_create(
            (size_t)PyArray_DIM(p, 2), deg[0], deg[1], PyArray_DATA(U),
            (size_t)PyArray_DIM(U, 0), PyArray_DATA(V),
            (size_t)PyArray_DIM(V, 0), PyArray_DATA(p),
            (size_t)PyArray_DIM(p, 0), (size_t)PyArray_DIM(p, 1),
            w ? PyArray_DATA(w) : NULL, &s, &d);
    if (st != CF_STATUS_OK) {
        cfpy_fail("BSplineSurface", st, &d);
        goto fail;
    }
    Py_DECREF(p);
    Py_XDECREF(w);
    Py_DECREF(U);
    Py_DECREF(V);
    o = (cfpy_Surface *)type->tp_alloc(type, 0);
    if (o == NULL) {
        cf_bspline_surface_destroy(s);
        return NULL;
    }
    o->s = s;
    return (PyObject *)o;
fail:
    Py_DECREF(p);
    Py_XDECREF(w);
    Py_XDECREF(U);
    Py_XDECREF(V);
    return NULL;
}

/* ---- evaluation: u and v broadcast against each other -------------------- */

typedef enum { EV_POINT, EV_NORMAL, EV_CURVATURE, EV_DERIVS } ev_t;

static PyObject *
evaluate(PyObject *self, PyObject *uo, PyObject *vo, const char *fn, ev_t ev,
         int k)
{
    const kind_t *kd = KIND(self);
    const void *s = SELF(self);
    npy_intp dim = (npy_intp)kd->dim(s), shape[NPY_MAXDIMS + 3];
    PyArrayObject *u, *v, *out = NULL;
    NpyIter *it = NULL;
    PyObject *b = NULL;
    size_t n, w;
    int nd, bad = 0;
    cf_status_t st = CF_STATUS_OK;
    u = cfpy_array(uo, fn, "u", 0, 0);
    v = u != NULL ? cfpy_array(vo, fn, "v", 0, 0) : NULL;
    if (v == NULL)
        goto done;
    b = PyArray_MultiIterNew(2, u, v);
    if (b == NULL)
        goto done;
    nd = ((PyArrayMultiIterObject *)b)->nd;
    memcpy(shape, ((PyArrayMultiIterObject *)b)->dimensions,
           (size_t)nd * sizeof(npy_intp));
    n = (size_t)((PyArrayMultiIterObject *)b)->size;
    switch (ev) {
    case EV_POINT:
    case EV_NORMAL:
        shape[nd++] = dim;
        w = (size_t)dim;
        break;
    case EV_CURVATURE:
        shape[nd++] = 2;
        w = 2;
        break;
    default:
        shape[nd++] = k + 1;
        shape[nd++] = k + 1;
        shape[nd++] = dim;
        w = (size_t)((k + 1) * (k + 1)) * (size_t)dim;
        break;
    }
    out = cfpy_new(nd, shape);
    if (out == NULL)
        goto done;
    {
        double *o = PyArray_DATA(out);
        PyArrayMultiIterObject *m = (PyArrayMultiIterObject *)b;
        size_t i = 0;
        Py_BEGIN_ALLOW_THREADS
        while (PyArray_MultiIter_NOTDONE(m) && st == CF_STATUS_OK) {
            double uu = *(double *)PyArray_MultiIter_DATA(m, 0);
            double vv = *(double *)PyArray_MultiIter_DATA(m, 1);
            double *dst = o + i * w;
            switch (ev) {
            case EV_POINT:
                st = kd->eval(s, uu, vv, dst);
                break;
            case EV_NORMAL:
                st = kd->normal(s, uu, vv, dst);
                break;
            case EV_CURVATURE:
                st = kd->curvature(s, uu, vv, dst, dst + 1);
                break;
            default:
                st = kd->derivs(s, uu, vv, k, dst);
                break;
            }
            if (st != CF_STATUS_OK)
                bad = 1;
            PyArray_MultiIter_NEXT(m);
            i++;
        }
        Py_END_ALLOW_THREADS
        (void)n;
    }
    if (bad) {
        cfpy_fail(fn, st, NULL);
        Py_CLEAR(out);
    }
done:
    (void)it;
    Py_XDECREF(b);
    Py_XDECREF(u);
    Py_XDECREF(v);
    return (PyObject *)out;
}

static PyObject *
sf_eval(PyObject *self, PyObject *args)
{
    PyObject *u, *v;
    if (!PyArg_ParseTuple(args, "OO:eval", &u, &v))
        return NULL;
    return evaluate(self, u, v, "eval", EV_POINT, 0);
}

static PyObject *
sf_normal(PyObject *self, PyObject *args)
{
    PyObject *u, *v;
    if (!PyArg_ParseTuple(args, "OO:normal", &u, &v))
        return NULL;
    return evaluate(self, u, v, "normal", EV_NORMAL, 0);
}

static PyObject *
sf_curvature(PyObject *self, PyObject *args)
{
    PyObject *u, *v;
    if (!PyArg_ParseTuple(args, "OO:curvature", &u, &v))
        return NULL;
    return evaluate(self, u, v, "curvature", EV_CURVATURE, 0);
}

static PyObject *
sf_derivs(PyObject *self, PyObject *args)
{
    PyObject *u, *v;
    int k = 1;
    if (!PyArg_ParseTuple(args, "OO|i:derivs", &u, &v, &k))
        return NULL;
    if (k < 0 || k > 16)
        return cfpy_error("derivs", "the order is %d; it must be in 0..16",
                          k);
    return evaluate(self, u, v, "derivs", EV_DERIVS, k);
}

/* ---- constructions ------------------------------------------------------- */

static PyObject *
sf_iso(PyObject *self, PyObject *args)
{
    PyObject *dirobj;
    double x;
    int dir;
    cf_diag_t d;
    cf_status_t st;
    if (!PyArg_ParseTuple(args, "Od:iso", &dirobj, &x) ||
        cfpy_dir(dirobj, "iso", &dir) != 0)
        return NULL;
    if (KIND(self)->bspline) {
        cf_bspline_t *c = NULL;
        st = cf_bspline_surface_iso(SELF(self), (cf_dir_t)dir, x, &c, &d);
        return st == CF_STATUS_OK ? cfpy_wrap_bspline(c)
                                  : cfpy_fail("iso", st, &d);
    } else {
        cf_bezier_t *c = NULL;
        st = cf_bezier_surface_iso(SELF(self), (cf_dir_t)dir, x, &c, &d);
        return st == CF_STATUS_OK ? cfpy_wrap_bezier(c)
                                  : cfpy_fail("iso", st, &d);
    }
}

static PyObject *
sf_split(PyObject *self, PyObject *args)
{
    const kind_t *k = KIND(self);
    PyObject *dirobj;
    void *lo = NULL, *hi = NULL;
    double x;
    int dir;
    cf_diag_t d;
    cf_status_t st;
    if (!PyArg_ParseTuple(args, "Od:split", &dirobj, &x) ||
        cfpy_dir(dirobj, "split", &dir) != 0)
        return NULL;
    if (k->bspline)
        st = cf_bspline_surface_split(SELF(self), (cf_dir_t)dir, x,
                                      (cf_bspline_surface_t **)&lo,
                                      (cf_bspline_surface_t **)&hi, &d);
    else
        st = cf_bezier_surface_split(SELF(self), (cf_dir_t)dir, x,
                                     (cf_bezier_surface_t **)&lo,
                                     (cf_bezier_surface_t **)&hi, &d);
    if (st != CF_STATUS_OK)
        return cfpy_fail("split", st, &d);
    return cfpy_pair(wrap(k, lo), wrap(k, hi));
}

static PyObject *
sf_elevate(PyObject *self, PyObject *args)
{
    const kind_t *k = KIND(self);
    int ru = 1, rv = 1;
    void *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    if (!PyArg_ParseTuple(args, "|ii:elevate", &ru, &rv))
        return NULL;
    if (k->bspline)
        st = cf_bspline_surface_elevate(SELF(self), ru, rv,
                                        (cf_bspline_surface_t **)&out, &d);
    else
        st = cf_bezier_surface_elevate(SELF(self), ru, rv,
                                       (cf_bezier_surface_t **)&out, &d);
    return new_surface(k, "elevate", st, &out, &d);
}

static PyObject *
sf_insert_knot(PyObject *self, PyObject *args)
{
    PyObject *dirobj;
    cf_bspline_surface_t *out = NULL;
    double x;
    int dir, r = 1;
    cf_diag_t d;
    cf_status_t st;
    if (!PyArg_ParseTuple(args, "Od|i:insert_knot", &dirobj, &x, &r) ||
        cfpy_dir(dirobj, "insert_knot", &dir) != 0)
        return NULL;
    st = cf_bspline_surface_insert_knot(SELF(self), (cf_dir_t)dir, x, r,
                                        &out, &d);
    return new_surface(&bspline_kind, "insert_knot", st, (void **)&out, &d);
}

static PyObject *
sf_decasteljau(PyObject *self, PyObject *args)
{
    return cfpy_bezier_surface_decasteljau(SELF(self), args);
}

static PyObject *
sf_deboor(PyObject *self, PyObject *args)
{
    return cfpy_bspline_surface_deboor(SELF(self), args);
}

static PyObject *
sf_to_beziers(PyObject *self, PyObject *unused)
{
    (void)unused;
    return cfpy_bspline_surface_to_beziers(SELF(self));
}

static PyObject *
sf_knot_lines(PyObject *self, PyObject *dir)
{
    return cfpy_bspline_surface_knot_lines(SELF(self), dir);
}

/* ---- the control net ----------------------------------------------------- */

static void
grid_size(PyObject *self, npy_intp *rows, npy_intp *cols)
{
    if (KIND(self)->bspline) {
        *rows = (npy_intp)cf_bspline_surface_count_u(SELF(self));
        *cols = (npy_intp)cf_bspline_surface_count_v(SELF(self));
    } else {
        *rows = cf_bezier_surface_degree_u(SELF(self)) + 1;
        *cols = cf_bezier_surface_degree_v(SELF(self)) + 1;
    }
}

static PyObject *
sf_points(PyObject *self, void *unused)
{
    npy_intp shape[3];
    PyArrayObject *a;
    (void)unused;
    grid_size(self, &shape[0], &shape[1]);
    shape[2] = (npy_intp)KIND(self)->dim(SELF(self));
    a = cfpy_new(3, shape);
    if (a != NULL)
        KIND(self)->get_points(SELF(self), PyArray_DATA(a));
    return (PyObject *)a;
}

static PyObject *
sf_weights(PyObject *self, void *unused)
{
    npy_intp shape[2];
    PyArrayObject *a;
    (void)unused;
    grid_size(self, &shape[0], &shape[1]);
    a = cfpy_new(2, shape);
    if (a != NULL)
        KIND(self)->get_weights(SELF(self), PyArray_DATA(a));
    return (PyObject *)a;
}

static PyObject *
sf_degree(PyObject *self, void *unused)
{
    (void)unused;
    if (KIND(self)->bspline)
        return Py_BuildValue("(ii)",
                             cf_bspline_surface_degree_u(SELF(self)),
                             cf_bspline_surface_degree_v(SELF(self)));
    return Py_BuildValue("(ii)", cf_bezier_surface_degree_u(SELF(self)),
                         cf_bezier_surface_degree_v(SELF(self)));
}

static PyObject *
sf_dim(PyObject *self, void *unused)
{
    (void)unused;
    return PyLong_FromSize_t(KIND(self)->dim(SELF(self)));
}

static PyObject *
sf_is_rational(PyObject *self, void *unused)
{
    (void)unused;
    return PyBool_FromLong(KIND(self)->rational(SELF(self)));
}

static PyObject *
sf_knots(PyObject *self, void *unused)
{
    size_t nu, nv;
    const double *U = cf_bspline_surface_knots(SELF(self), CF_DIR_U, &nu);
    const double *V = cf_bspline_surface_knots(SELF(self), CF_DIR_V, &nv);
    (void)unused;
    return Py_BuildValue("(NN)", cfpy_vector(U, (npy_intp)nu),
                         cfpy_vector(V, (npy_intp)nv));
}

static PyObject *
sf_repr(PyObject *self)
{
    npy_intp r, c;
    grid_size(self, &r, &c);
    return PyUnicode_FromFormat("<%s %zd x %zd points in R^%zu%s>",
                                Py_TYPE(self)->tp_name, (Py_ssize_t)r,
                                (Py_ssize_t)c, KIND(self)->dim(SELF(self)),
                                KIND(self)->rational(SELF(self))
                                    ? ", rational" : "");
}

#define COMMON_METHODS \
    { "eval", sf_eval, METH_VARARGS, \
      "eval(u, v): S(u, v); u and v broadcast (shape + (dim,))" }, \
    { "normal", sf_normal, METH_VARARGS, "normal(u, v): unit normal (R^3)" }, \
    { "curvature", sf_curvature, METH_VARARGS, \
      "curvature(u, v): (K, H) Gaussian and mean curvature in the last axis" }, \
    { "derivs", sf_derivs, METH_VARARGS, \
      "derivs(u, v, k=1): D[a, b] = d^(a+b) S / du^a dv^b, a + b <= k" }, \
    { "iso", sf_iso, METH_VARARGS, \
      "iso('u', u0): the curve v -> S(u0, v); iso('v', v0): u -> S(u, v0)" }, \
    { "split", sf_split, METH_VARARGS, "split('u' | 'v', t): lo, hi" }, \
    { "elevate", sf_elevate, METH_VARARGS, "elevate(ru=1, rv=1)" }

static PyMethodDef bzs_methods[] = {
    COMMON_METHODS,
    { "decasteljau", sf_decasteljau, METH_VARARGS,
      "decasteljau(u, v): (columns, v), the nets in u of the columns and "
      "the net in v of the points they reach; its last level is S(u, v)" },
    { NULL, NULL, 0, NULL }
};

static PyMethodDef bss_methods[] = {
    COMMON_METHODS,
    { "insert_knot", sf_insert_knot, METH_VARARGS,
      "insert_knot('u' | 'v', x, r=1)" },
    { "deboor", sf_deboor, METH_VARARGS,
      "deboor(u, v): ((columns, v), (span_u, span_v)), the de Boor nets as "
      "decasteljau's" },
    { "to_beziers", sf_to_beziers, METH_NOARGS,
      "to_beziers(): grid[i][j] of BezierSurface, one per non-empty span" },
    { "knot_lines", sf_knot_lines, METH_O,
      "knot_lines('u' | 'v'): the distinct knots inside the domain" },
    { NULL, NULL, 0, NULL }
};

#define COMMON_GETSET \
    { "points", sf_points, NULL, "the control net (rows along u)", NULL }, \
    { "weights", sf_weights, NULL, "the weights", NULL }, \
    { "degree", sf_degree, NULL, "(p, q)", NULL }, \
    { "dim", sf_dim, NULL, "the dimension of the points", NULL }, \
    { "is_rational", sf_is_rational, NULL, "True when rational", NULL }

static PyGetSetDef bzs_getset[] = {
    COMMON_GETSET,
    { NULL, NULL, NULL, NULL, NULL }
};

static PyGetSetDef bss_getset[] = {
    COMMON_GETSET,
    { "knots", sf_knots, NULL, "(U, V)", NULL },
    { NULL, NULL, NULL, NULL, NULL }
};

PyTypeObject cfpy_BezierSurfaceType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "curvefig.BezierSurface",
    .tp_basicsize = sizeof(cfpy_Surface),
    .tp_dealloc = sf_dealloc,
    .tp_repr = sf_repr,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "BezierSurface(P, weights=None): a tensor-product Bézier "
              "surface, P of shape (m+1, n+1, dim) with rows along u.",
    .tp_methods = bzs_methods,
    .tp_getset = bzs_getset,
    .tp_new = bzs_new,
};

PyTypeObject cfpy_BSplineSurfaceType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "curvefig.BSplineSurface",
    .tp_basicsize = sizeof(cfpy_Surface),
    .tp_dealloc = sf_dealloc,
    .tp_repr = sf_repr,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "BSplineSurface(degree, knots, P, weights=None): a B-spline "
              "(NURBS) surface; degree p or (p, q), knots (U, V) or None "
              "(clamped uniform on [0, 1]).",
    .tp_methods = bss_methods,
    .tp_getset = bss_getset,
    .tp_new = bss_new,
};
