/*
** Arrays in and out, and errors (pycommon.h).
*/
#include "pycommon.h"

#include <math.h>
#include <stdarg.h>

const char *
cfpy_num(double v, char buf[CFPY_NUM])
{
    char *r = PyOS_double_to_string(v, 'r', 0, 0, NULL);
    if (r == NULL) {
        PyErr_Clear();
        snprintf(buf, CFPY_NUM, "%.17g", v);
        return buf;
    }
    snprintf(buf, CFPY_NUM, "%s", r);
    PyMem_Free(r);
    return buf;
}

PyObject *
cfpy_fail(const char *fn, cf_status_t st, const cf_diag_t *diag)
{
    const char *msg = (diag != NULL && diag->msg[0] != '\0')
                          ? diag->msg : cf_status_to_string(st);
    if (st == CF_STATUS_NO_MEMORY)
        return PyErr_NoMemory();
    PyErr_Format(PyExc_ValueError, "%s: %s", fn, msg);
    return NULL;
}

PyObject *
cfpy_error(const char *fn, const char *fmt, ...)
{
    va_list ap;
    PyObject *msg;
    va_start(ap, fmt);
    msg = PyUnicode_FromFormatV(fmt, ap);
    va_end(ap);
    if (msg == NULL)
        return NULL;
    PyErr_Format(PyExc_ValueError, "%s: %U", fn, msg);
    Py_DECREF(msg);
    return NULL;
}

/* The conversion's own exception, with fn and what in front. */
static void
conversion_error(const char *fn, const char *what)
{
    PyObject *type, *value, *tb, *text;
    PyErr_Fetch(&type, &value, &tb);
    PyErr_NormalizeException(&type, &value, &tb);
    text = value != NULL ? PyObject_Str(value) : NULL;
    if (type == NULL || !PyErr_GivenExceptionMatches(type, PyExc_TypeError))
        type = PyExc_ValueError;
    else
        type = PyExc_TypeError;
    if (text != NULL)
        PyErr_Format(type, "%s: %s must be an array of numbers (%U)", fn,
                     what, text);
    else
        PyErr_Format(type, "%s: %s must be an array of numbers", fn, what);
    Py_XDECREF(text);
    Py_XDECREF(value);
    Py_XDECREF(tb);
}

PyArrayObject *
cfpy_array(PyObject *obj, const char *fn, const char *what, int ndim,
           int finite)
{
    PyArrayObject *a;
    PyArray_Descr *d;
    if (obj == NULL || obj == Py_None) {
        cfpy_error(fn, "%s is missing", what);
        return NULL;
    }
    if (PyArray_Check(obj)) {
        int k = PyArray_TYPE((PyArrayObject *)obj);
        if (!PyTypeNum_ISBOOL(k) && !PyTypeNum_ISINTEGER(k) &&
            !PyTypeNum_ISFLOAT(k)) {
            PyErr_Format(PyExc_TypeError,
                         "%s: %s must be an array of real numbers, got "
                         "dtype %S", fn, what,
                         (PyObject *)PyArray_DESCR((PyArrayObject *)obj));
            return NULL;
        }
    }
    d = PyArray_DescrFromType(NPY_DOUBLE);
    a = (PyArrayObject *)PyArray_FromAny(obj, d, 0, 0,
                                         NPY_ARRAY_CARRAY_RO, NULL);
    if (a == NULL) {
        conversion_error(fn, what);
        return NULL;
    }
    if (ndim > 0 && PyArray_NDIM(a) != ndim) {
        PyErr_Format(PyExc_ValueError,
                     "%s: %s must have %d dimension%s, got %d", fn, what,
                     ndim, ndim == 1 ? "" : "s", PyArray_NDIM(a));
        Py_DECREF(a);
        return NULL;
    }
    if (finite) {
        const double *v = (const double *)PyArray_DATA(a);
        npy_intp n = PyArray_SIZE(a);
        for (npy_intp i = 0; i < n; i++) {
            char b[CFPY_NUM];
            if (isfinite(v[i]))
                continue;
            if (PyArray_NDIM(a) == 2) {
                npy_intp cols = PyArray_DIM(a, 1);
                cfpy_error(fn, "%s[%zd, %zd] is %s; coordinates must be "
                           "finite", what, (Py_ssize_t)(i / cols),
                           (Py_ssize_t)(i % cols), cfpy_num(v[i], b));
            } else if (PyArray_NDIM(a) == 3) {
                npy_intp d1 = PyArray_DIM(a, 1), d2 = PyArray_DIM(a, 2);
                cfpy_error(fn, "%s[%zd, %zd, %zd] is %s; coordinates must "
                           "be finite", what, (Py_ssize_t)(i / (d1 * d2)),
                           (Py_ssize_t)(i / d2 % d1), (Py_ssize_t)(i % d2),
                           cfpy_num(v[i], b));
            } else {
                cfpy_error(fn, "%s[%zd] is %s; values must be finite",
                           what, (Py_ssize_t)i, cfpy_num(v[i], b));
            }
            Py_DECREF(a);
            return NULL;
        }
    }
    return a;
}

PyArrayObject *
cfpy_points(PyObject *obj, const char *fn, const char *what, npy_intp min)
{
    PyArrayObject *a = cfpy_array(obj, fn, what, 2, 1);
    if (a == NULL)
        return NULL;
    if (PyArray_DIM(a, 0) < min || PyArray_DIM(a, 1) < 1) {
        cfpy_error(fn, "%s has shape (%zd, %zd); it needs at least %zd "
                   "point%s of at least one coordinate", what,
                   (Py_ssize_t)PyArray_DIM(a, 0),
                   (Py_ssize_t)PyArray_DIM(a, 1), (Py_ssize_t)min,
                   min == 1 ? "" : "s");
        Py_DECREF(a);
        return NULL;
    }
    return a;
}

int
cfpy_finite(PyObject *obj, const char *fn, const char *what, double *out)
{
    double v;
    if (!PyFloat_Check(obj) && !PyLong_Check(obj) && !PyIndex_Check(obj) &&
        !PyArray_IsScalar(obj, Floating)) {
        PyErr_Format(PyExc_TypeError, "%s: %s must be a number, got %s", fn,
                     what, Py_TYPE(obj)->tp_name);
        return -1;
    }
    v = PyFloat_AsDouble(obj);
    if (v == -1.0 && PyErr_Occurred())
        return -1;
    if (!isfinite(v)) {
        cfpy_error(fn, "%s is %R; it must be finite", what, obj);
        return -1;
    }
    *out = v;
    return 0;
}

int
cfpy_point(PyObject *obj, const char *fn, const char *what, size_t dim,
           double *out)
{
    PyArrayObject *a = cfpy_array(obj, fn, what, 1, 1);
    if (a == NULL)
        return -1;
    if ((size_t)PyArray_DIM(a, 0) != dim) {
        cfpy_error(fn, "%s has %zd coordinates; the curve's points have %zu",
                   what, (Py_ssize_t)PyArray_DIM(a, 0), dim);
        Py_DECREF(a);
        return -1;
    }
    memcpy(out, PyArray_DATA(a), dim * sizeof(double));
    Py_DECREF(a);
    return 0;
}

int
cfpy_affine(PyObject *Aobj, PyObject *bobj, const char *fn, size_t dim,
            PyArrayObject **A, double **b)
{
    *b = NULL;
    *A = cfpy_array(Aobj, fn, "A", 2, 1);
    if (*A == NULL)
        return -1;
    if ((size_t)PyArray_DIM(*A, 0) != dim ||
        (size_t)PyArray_DIM(*A, 1) != dim) {
        cfpy_error(fn, "A must be %zu x %zu", dim, dim);
        Py_CLEAR(*A);
        return -1;
    }
    *b = PyMem_Calloc(dim, sizeof(double));
    if (*b == NULL) {
        Py_CLEAR(*A);
        PyErr_NoMemory();
        return -1;
    }
    if (bobj != Py_None && cfpy_point(bobj, fn, "b", dim, *b) != 0) {
        Py_CLEAR(*A);
        PyMem_Free(*b);
        *b = NULL;
        return -1;
    }
    return 0;
}

PyArrayObject *
cfpy_new(int ndim, const npy_intp *shape)
{
    return (PyArrayObject *)PyArray_SimpleNew(ndim, (npy_intp *)shape,
                                              NPY_DOUBLE);
}

PyObject *
cfpy_vector(const double *v, npy_intp n)
{
    PyArrayObject *a = cfpy_new(1, &n);
    if (a != NULL && n > 0)
        memcpy(PyArray_DATA(a), v, (size_t)n * sizeof(double));
    return (PyObject *)a;
}

PyObject *
cfpy_matrix(const double *v, npy_intp rows, npy_intp cols)
{
    npy_intp shape[2] = { rows, cols };
    PyArrayObject *a = cfpy_new(2, shape);
    if (a != NULL && rows * cols > 0)
        memcpy(PyArray_DATA(a), v, (size_t)(rows * cols) * sizeof(double));
    return (PyObject *)a;
}

int
cfpy_shape_plus(PyArrayObject *t, const npy_intp *extra, int nextra,
                npy_intp *out)
{
    int nd = PyArray_NDIM(t);
    for (int i = 0; i < nd; i++)
        out[i] = PyArray_DIM(t, i);
    for (int i = 0; i < nextra; i++)
        out[nd + i] = extra[i];
    return nd + nextra;
}

PyObject *
cfpy_param_error(const char *fn, cf_status_t st, const double *t, size_t n,
                 double a, double b)
{
    double slack = 8 * 2.220446049250313e-16 *
                   (fabs(a) > fabs(b) ? fabs(a) : fabs(b));
    char b1[CFPY_NUM], b2[CFPY_NUM], b3[CFPY_NUM];
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(t[i]))
            return cfpy_error(fn, "parameter %zu is %s; parameters must be "
                              "finite", i, cfpy_num(t[i], b1));
        if (t[i] < a - slack || t[i] > b + slack)
            return cfpy_error(fn, "parameter %zu (%s) is outside the "
                              "domain [%s, %s]", i, cfpy_num(t[i], b1),
                              cfpy_num(a, b2), cfpy_num(b, b3));
    }
    return cfpy_fail(fn, st, NULL);
}

int
cfpy_dir(PyObject *obj, const char *fn, int *dir)
{
    const char *s = PyUnicode_Check(obj) ? PyUnicode_AsUTF8(obj) : NULL;
    if (s != NULL && strcmp(s, "u") == 0)
        *dir = CF_DIR_U;
    else if (s != NULL && strcmp(s, "v") == 0)
        *dir = CF_DIR_V;
    else {
        PyErr_Clear();
        cfpy_error(fn, "the direction must be \"u\" or \"v\", got %R", obj);
        return -1;
    }
    return 0;
}

PyObject *
cfpy_eval_params(PyObject *tobj, const char *fn, const void *obj,
                 cfpy_many_t many, const void *arg, const npy_intp *extra,
                 int nextra, double a, double b)
{
    return cfpy_eval_params_into(tobj, NULL, fn, obj, many, arg, extra,
                                 nextra, a, b);
}

/* out as the result array: float64, C-contiguous, writeable, of shape
** shape[0..nd-1]; a new reference, or NULL with the error set. */
static PyArrayObject *
given_out(PyObject *outobj, const char *fn, int nd, const npy_intp *shape)
{
    PyArrayObject *o = (PyArrayObject *)outobj;
    int ok = PyArray_Check(outobj) && PyArray_TYPE(o) == NPY_DOUBLE &&
             PyArray_IS_C_CONTIGUOUS(o) && PyArray_ISWRITEABLE(o) &&
             PyArray_ISALIGNED(o) && PyArray_NDIM(o) == nd;
    for (int i = 0; ok && i < nd; i++)
        ok = PyArray_DIM(o, i) == shape[i];
    if (!ok) {
        PyErr_Format(PyExc_ValueError, "%s: out must be a writeable "
                     "C-contiguous float64 array of the result's shape "
                     "(the parameters' shape, then the points' dimension)",
                     fn);
        return NULL;
    }
    Py_INCREF(outobj);
    return o;
}

PyObject *
cfpy_eval_params_into(PyObject *tobj, PyObject *outobj, const char *fn,
                      const void *obj, cfpy_many_t many, const void *arg,
                      const npy_intp *extra, int nextra, double a, double b)
{
    npy_intp shape[NPY_MAXDIMS];
    PyArrayObject *t, *out;
    cf_status_t st;
    size_t n;
    int nd;
    t = cfpy_array(tobj, fn, "the parameters", 0, 0);
    if (t == NULL)
        return NULL;
    if (PyArray_NDIM(t) + nextra > NPY_MAXDIMS) {
        Py_DECREF(t);
        return cfpy_error(fn, "the parameters have too many dimensions");
    }
    nd = cfpy_shape_plus(t, extra, nextra, shape);
    out = outobj != NULL && outobj != Py_None
              ? given_out(outobj, fn, nd, shape) : cfpy_new(nd, shape);
    if (out == NULL) {
        Py_DECREF(t);
        return NULL;
    }
    n = (size_t)PyArray_SIZE(t);
    if (n >= CFPY_NOGIL_MIN) {
        Py_BEGIN_ALLOW_THREADS
        st = many(obj, (const double *)PyArray_DATA(t), n,
                  (double *)PyArray_DATA(out), arg);
        Py_END_ALLOW_THREADS
    } else {
        st = many(obj, (const double *)PyArray_DATA(t), n,
                  (double *)PyArray_DATA(out), arg);
    }
    if (st != CF_STATUS_OK) {
        cfpy_param_error(fn, st, (const double *)PyArray_DATA(t), n, a, b);
        Py_DECREF(t);
        Py_DECREF(out);
        return NULL;
    }
    Py_DECREF(t);
    return (PyObject *)out;
}

PyObject *
cfpy_pair(PyObject *a, PyObject *b)
{
    if (a == NULL || b == NULL) {
        Py_XDECREF(a);
        Py_XDECREF(b);
        return NULL;
    }
    return Py_BuildValue("(NN)", a, b);
}
