/*
** Curves made from data and offsets: curvefig.interpolate, approximate,
** parameters, nurbs_circle, nurbs_arc, coons, and the offset method of
** both curve kinds (the language's render/lua/linterp.c, lconic.c and
** loffset.c in Python).
*/
#include "pycommon.h"

PyObject *
cfpy_offset(const cf_bezier_t *bz, const cf_bspline_t *bs, PyObject *args,
            PyObject *kw)
{
    static char *names[] = { "d", "tolerance", "trim", "method", NULL };
    cf_offset_options_t opt;
    cf_offset_report_t rep;
    cf_cubics_t *raw = NULL;
    cf_cubics_list_t *trimmed = NULL;
    const char *method = "levien";
    PyObject *curves = NULL, *report = NULL, *chains = NULL;
    int trim = 0;
    double d;
    cf_diag_t diag;
    cf_status_t st;
    cf_offset_options_init(&opt);
    if (!PyArg_ParseTupleAndKeywords(args, kw, "d|dps:offset", names, &d,
                                     &opt.tolerance, &trim, &method))
        return NULL;
    if (strcmp(method, "levien") == 0)
        opt.method = CF_OFFSET_LEVIEN;
    else if (strcmp(method, "tiller-hanson") == 0)
        opt.method = CF_OFFSET_TILLER_HANSON;
    else
        return cfpy_error("offset", "method must be \"levien\" or "
                          "\"tiller-hanson\", got \"%s\"", method);
    opt.trim = trim != 0;
    Py_BEGIN_ALLOW_THREADS
    if (bz != NULL)
        st = cf_bezier_offset(bz, d, &opt, &raw, trim ? &trimmed : NULL,
                              &rep, &diag);
    else
        st = cf_bspline_offset(bs, d, &opt, &raw, trim ? &trimmed : NULL,
                               &rep, &diag);
    Py_END_ALLOW_THREADS
    if (st != CF_STATUS_OK)
        return cfpy_fail("offset", st, &diag);
    curves = cfpy_cubics(raw);
    report = Py_BuildValue("{sn,sd,sO,sn,sn,sn,sn,sn}",
        "segments", (Py_ssize_t)rep.segments, "max_error", rep.max_error,
        "converged", rep.converged ? Py_True : Py_False,
        "cusps", (Py_ssize_t)rep.cusps, "joins", (Py_ssize_t)rep.joins,
        "self_intersections", (Py_ssize_t)rep.self_intersections,
        "trimmed_chains", (Py_ssize_t)rep.trimmed_chains,
        "trimmed_segments", (Py_ssize_t)rep.trimmed_segments);
    if (trimmed != NULL) {
        chains = PyList_New((Py_ssize_t)trimmed->count);
        for (size_t i = 0; chains != NULL && i < trimmed->count; i++) {
            PyObject *ch = cfpy_cubics(trimmed->chains[i]);
            if (ch == NULL)
                Py_CLEAR(chains);
            else
                PyList_SET_ITEM(chains, (Py_ssize_t)i, ch);
        }
    }
    cf_cubics_destroy(raw);
    cf_cubics_list_destroy(trimmed);
    if (curves == NULL || report == NULL || (trim && chains == NULL)) {
        Py_XDECREF(curves);
        Py_XDECREF(report);
        Py_XDECREF(chains);
        return NULL;
    }
    if (trim)
        return Py_BuildValue("(NNN)", curves, report, chains);
    return Py_BuildValue("(NN)", curves, report);
}

PyObject *
cfpy_reduce(const cf_bezier_t *bz, const cf_bspline_t *bs, PyObject *args,
            PyObject *kw)
{
    static char *names[] = { "by", "continuity", "method", "tolerance",
                             NULL };
    cf_reduce_options_t opt;
    cf_reduce_report_t rep;
    const char *method = "l2";
    PyObject *curve;
    void *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    cf_reduce_options_init(&opt);
    if (!PyArg_ParseTupleAndKeywords(args, kw, "|iisd:reduce", names,
                                     &opt.by, &opt.continuity, &method,
                                     &opt.tolerance))
        return NULL;
    if (strcmp(method, "l2") == 0)
        opt.method = CF_REDUCE_L2;
    else if (strcmp(method, "uniform") == 0)
        opt.method = CF_REDUCE_UNIFORM;
    else
        return cfpy_error("reduce", "method must be \"l2\" or \"uniform\", "
                          "got \"%s\"", method);
    Py_BEGIN_ALLOW_THREADS
    if (bz != NULL)
        st = cf_bezier_reduce(bz, &opt, (cf_bezier_t **)&out, &rep, &d);
    else
        st = cf_bspline_reduce(bs, &opt, (cf_bspline_t **)&out, &rep, &d);
    Py_END_ALLOW_THREADS
    if (st != CF_STATUS_OK)
        return cfpy_fail("reduce", st, &d);
    curve = bz != NULL ? cfpy_wrap_bezier(out) : cfpy_wrap_bspline(out);
    if (curve == NULL)
        return NULL;
    if (bz != NULL)
        return Py_BuildValue("(N{sdsdsdsd})", curve, "max_error",
                             rep.max_error, "bound", rep.bound,
                             "polygon_bound", rep.polygon_bound, "l2_error",
                             rep.l2_error);
    return Py_BuildValue("(N{sdsdsdsdsisn})", curve, "max_error",
                         rep.max_error, "bound", rep.bound, "polygon_bound",
                         rep.polygon_bound, "l2_error", rep.l2_error,
                         "continuity", rep.continuity, "knots_removed",
                         (Py_ssize_t)rep.knots_removed);
}

int
cfpy_interp_options(const char *fn, PyObject *method, PyObject *param,
                    PyObject *exponent, PyObject *params, PyObject *t0,
                    PyObject *t1, int degree, size_t dim,
                    cf_interp_options_t *opt, PyArrayObject **keep)
{
    cf_diag_t d;
    cf_interp_options_init(opt);
    opt->degree = degree;
    if (method != Py_None) {
        const char *s = PyUnicode_Check(method) ? PyUnicode_AsUTF8(method)
                                                : NULL;
        if (s == NULL) {
            PyErr_Clear();
            cfpy_error(fn, "method must be a string");
            return -1;
        }
        if (cf_interp_method_from_string(s, &opt->method, &d) !=
            CF_STATUS_OK) {
            cfpy_error(fn, "method: %s", d.msg);
            return -1;
        }
    }
    if (param != Py_None) {
        const char *s = PyUnicode_Check(param) ? PyUnicode_AsUTF8(param)
                                               : NULL;
        if (s == NULL) {
            PyErr_Clear();
            cfpy_error(fn, "param must be a string");
            return -1;
        }
        if (cf_param_from_string(s, &opt->param, &d) != CF_STATUS_OK) {
            cfpy_error(fn, "param: %s", d.msg);
            return -1;
        }
    }
    if (exponent != Py_None) {
        if (cfpy_finite(exponent, fn, "exponent", &opt->exponent) != 0)
            return -1;
        opt->param = CF_PARAM_POWER;
    }
    if (params != Py_None) {
        keep[0] = cfpy_array(params, fn, "params", 1, 1);
        if (keep[0] == NULL)
            return -1;
        opt->params = PyArray_DATA(keep[0]);
    }
    if (t0 != Py_None) {
        keep[1] = cfpy_array(t0, fn, "start_tangent", 1, 1);
        if (keep[1] == NULL)
            return -1;
        if ((size_t)PyArray_DIM(keep[1], 0) != dim) {
            cfpy_error(fn, "start_tangent has %zd coordinates, the points "
                       "%zu", (Py_ssize_t)PyArray_DIM(keep[1], 0), dim);
            return -1;
        }
        opt->start_tangent = PyArray_DATA(keep[1]);
    }
    if (t1 != Py_None) {
        keep[2] = cfpy_array(t1, fn, "end_tangent", 1, 1);
        if (keep[2] == NULL)
            return -1;
        if ((size_t)PyArray_DIM(keep[2], 0) != dim) {
            cfpy_error(fn, "end_tangent has %zd coordinates, the points %zu",
                       (Py_ssize_t)PyArray_DIM(keep[2], 0), dim);
            return -1;
        }
        opt->end_tangent = PyArray_DATA(keep[2]);
    }
    return 0;
}

static PyObject *
py_interpolate(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *names[] = { "points", "method", "degree", "param",
                             "exponent", "params", "start_tangent",
                             "end_tangent", "closed", NULL };
    PyObject *P, *method = Py_None, *param = Py_None, *expo = Py_None,
             *params = Py_None, *t0 = Py_None, *t1 = Py_None, *r = NULL;
    PyArrayObject *p, *keep[3] = { NULL, NULL, NULL };
    cf_interp_options_t opt;
    cf_bspline_t *out = NULL;
    int degree = 3, closed = 0;
    cf_diag_t d;
    cf_status_t st;
    (void)mod;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|OiOOOOOp:interpolate",
                                     names, &P, &method, &degree, &param,
                                     &expo, &params, &t0, &t1, &closed))
        return NULL;
    p = cfpy_points(P, "interpolate", "points", 1);
    if (p == NULL)
        return NULL;
    if (cfpy_interp_options("interpolate", method, param, expo, params, t0,
                            t1, degree, (size_t)PyArray_DIM(p, 1), &opt,
                            keep) == 0) {
        opt.closed = closed != 0;
        Py_BEGIN_ALLOW_THREADS
        st = cf_interpolate((size_t)PyArray_DIM(p, 1), PyArray_DATA(p),
                            (size_t)PyArray_DIM(p, 0), &opt, &out, &d);
        Py_END_ALLOW_THREADS
        r = st == CF_STATUS_OK ? cfpy_wrap_bspline(out)
                               : cfpy_fail("interpolate", st, &d);
    }
    Py_DECREF(p);
    for (int i = 0; i < 3; i++)
        Py_XDECREF(keep[i]);
    return r;
}

static PyObject *
py_approximate(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *names[] = { "points", "count", "degree", "param",
                             "fix_ends", NULL };
    PyObject *P, *param = Py_None, *r = NULL;
    PyArrayObject *p, *keep[3] = { NULL, NULL, NULL };
    Py_ssize_t count;
    cf_interp_options_t opt;
    cf_bspline_t *out = NULL;
    int degree = 3, fix_ends = 1;
    double residual = 0.0;
    cf_diag_t d;
    cf_status_t st;
    (void)mod;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "On|iOp:approximate", names,
                                     &P, &count, &degree, &param, &fix_ends))
        return NULL;
    if (count < 1)
        return cfpy_error("approximate", "count is %zd; it must be >= 1",
                          count);
    p = cfpy_points(P, "approximate", "points", 1);
    if (p == NULL)
        return NULL;
    if (cfpy_interp_options("approximate", Py_None, param, Py_None,
                            Py_None, Py_None, Py_None, degree,
                            (size_t)PyArray_DIM(p, 1), &opt, keep) == 0) {
        Py_BEGIN_ALLOW_THREADS
        st = cf_approximate_lsq((size_t)PyArray_DIM(p, 1), PyArray_DATA(p),
                                (size_t)PyArray_DIM(p, 0), (size_t)count,
                                &opt, fix_ends != 0, &out, &residual, &d);
        Py_END_ALLOW_THREADS
        if (st == CF_STATUS_OK)
            r = Py_BuildValue("(Nd)", cfpy_wrap_bspline(out), residual);
        else
            cfpy_fail("approximate", st, &d);
    }
    Py_DECREF(p);
    return r;
}

static PyObject *
py_parameters(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *names[] = { "points", "param", "closed", "exponent", NULL };
    PyObject *P, *param = Py_None, *expo = Py_None, *r = NULL;
    PyArrayObject *p, *keep[3] = { NULL, NULL, NULL };
    cf_interp_options_t opt;
    int closed = 0;
    cf_diag_t d;
    cf_status_t st;
    npy_intp n;
    PyArrayObject *out;
    (void)mod;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|OpO:parameters", names, &P,
                                     &param, &closed, &expo))
        return NULL;
    p = cfpy_points(P, "parameters", "points", 1);
    if (p == NULL)
        return NULL;
    if (cfpy_interp_options("parameters", Py_None, param, expo, Py_None,
                            Py_None, Py_None, 3, (size_t)PyArray_DIM(p, 1),
                            &opt, keep) == 0) {
        n = PyArray_DIM(p, 0) + (closed ? 1 : 0);
        out = cfpy_new(1, &n);
        if (out != NULL) {
            st = cf_interp_parameters((size_t)PyArray_DIM(p, 1),
                                      PyArray_DATA(p),
                                      (size_t)PyArray_DIM(p, 0), opt.param,
                                      opt.exponent, closed != 0,
                                      PyArray_DATA(out), &d);
            if (st == CF_STATUS_OK)
                r = (PyObject *)out;
            else {
                Py_DECREF(out);
                cfpy_fail("parameters", st, &d);
            }
        }
    }
    Py_DECREF(p);
    return r;
}

static PyObject *
py_nurbs_circle(PyObject *mod, PyObject *args)
{
    PyObject *cobj;
    double c[2], r;
    cf_bspline_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    (void)mod;
    if (!PyArg_ParseTuple(args, "Od:nurbs_circle", &cobj, &r) ||
        cfpy_point(cobj, "nurbs_circle", "the centre", 2, c) != 0)
        return NULL;
    st = cf_nurbs_circle(c, r, &out, &d);
    return st == CF_STATUS_OK ? cfpy_wrap_bspline(out)
                              : cfpy_fail("nurbs_circle", st, &d);
}

static PyObject *
py_coons(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *names[] = { "points", "ends", NULL };
    static const char *const ends_names[] = { "plain", "tripled", "closed" };
    PyObject *P;
    const char *ends = "plain";
    PyArrayObject *p;
    cf_bspline_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    int e = -1;
    (void)mod;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|s:coons", names, &P, &ends))
        return NULL;
    for (int i = 0; i < 3; i++)
        if (strcmp(ends, ends_names[i]) == 0)
            e = i;
    if (e < 0)
        return cfpy_error("coons", "ends must be \"plain\", \"tripled\" or "
                          "\"closed\", got \"%s\"", ends);
    p = cfpy_points(P, "coons", "points", 1);
    if (p == NULL)
        return NULL;
    st = cf_bspline_create_coons((size_t)PyArray_DIM(p, 1), PyArray_DATA(p),
                                 (size_t)PyArray_DIM(p, 0),
                                 (cf_coons_ends_t)e, &out, &d);
    Py_DECREF(p);
    return st == CF_STATUS_OK ? cfpy_wrap_bspline(out)
                              : cfpy_fail("coons", st, &d);
}

/* ferguson(P0, P1, T0, T1) -> the Hermite cubic as a Bézier curve */
static PyObject *
py_ferguson(PyObject *mod, PyObject *args)
{
    PyObject *o[4];
    PyArrayObject *a;
    double *v = NULL;
    size_t dim = 0;
    cf_bezier_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    (void)mod;
    if (!PyArg_ParseTuple(args, "OOOO:ferguson", &o[0], &o[1], &o[2], &o[3]))
        return NULL;
    a = cfpy_array(o[0], "ferguson", "P0", 1, 1);
    if (a == NULL)
        return NULL;
    dim = (size_t)PyArray_DIM(a, 0);
    Py_DECREF(a);
    v = PyMem_Malloc(4 * (dim ? dim : 1) * sizeof(double));
    if (v == NULL)
        return PyErr_NoMemory();
    for (int i = 0; i < 4; i++) {
        static const char *const names[] = { "P0", "P1", "T0", "T1" };
        if (cfpy_point(o[i], "ferguson", names[i], dim, v + i * dim) != 0) {
            PyMem_Free(v);
            return NULL;
        }
    }
    st = cf_ferguson_cubic(dim, v, v + dim, v + 2 * dim, v + 3 * dim, &out,
                           &d);
    PyMem_Free(v);
    return st == CF_STATUS_OK ? cfpy_wrap_bezier(out)
                              : cfpy_fail("ferguson", st, &d);
}

/* ferguson_chain(points, tangents) -> list of Hermite cubics */
static PyObject *
py_ferguson_chain(PyObject *mod, PyObject *args)
{
    PyObject *P, *T;
    PyArrayObject *p, *t = NULL;
    cf_bezier_list_t *list = NULL;
    cf_diag_t d;
    cf_status_t st;
    (void)mod;
    if (!PyArg_ParseTuple(args, "OO:ferguson_chain", &P, &T))
        return NULL;
    p = cfpy_points(P, "ferguson_chain", "points", 2);
    if (p != NULL)
        t = cfpy_points(T, "ferguson_chain", "tangents", 2);
    if (t == NULL) {
        Py_XDECREF(p);
        return NULL;
    }
    if (PyArray_DIM(t, 0) != PyArray_DIM(p, 0) ||
        PyArray_DIM(t, 1) != PyArray_DIM(p, 1)) {
        Py_DECREF(p);
        Py_DECREF(t);
        return cfpy_error("ferguson_chain", "the tangents must have the "
                          "points' shape");
    }
    st = cf_ferguson_chain((size_t)PyArray_DIM(p, 1), PyArray_DATA(p),
                           PyArray_DATA(t), (size_t)PyArray_DIM(p, 0), &list,
                           &d);
    Py_DECREF(p);
    Py_DECREF(t);
    return st == CF_STATUS_OK ? cfpy_bezier_list(list)
                              : cfpy_fail("ferguson_chain", st, &d);
}

/* coons_cubic(P) -> the uniform cubic B-spline segment of four points */
static PyObject *
py_coons_cubic(PyObject *mod, PyObject *P)
{
    PyArrayObject *p = cfpy_points(P, "coons_cubic", "points", 4);
    cf_bezier_t *out = NULL;
    cf_diag_t d;
    cf_status_t st;
    (void)mod;
    if (p == NULL)
        return NULL;
    if (PyArray_DIM(p, 0) != 4) {
        Py_DECREF(p);
        return cfpy_error("coons_cubic", "it takes 4 points, got %zd",
                          (Py_ssize_t)PyArray_DIM(p, 0));
    }
    st = cf_coons_cubic((size_t)PyArray_DIM(p, 1), PyArray_DATA(p), &out, &d);
    Py_DECREF(p);
    return st == CF_STATUS_OK ? cfpy_wrap_bezier(out)
                              : cfpy_fail("coons_cubic", st, &d);
}

PyMethodDef cfpy_interp_functions[] = {
    { "interpolate", (PyCFunction)(void (*)(void))py_interpolate,
      METH_VARARGS | METH_KEYWORDS,
      "interpolate(points, method='natural', degree=3, param=None, "
      "exponent=None, params=None, start_tangent=None, end_tangent=None, "
      "closed=False): the B-spline through the points" },
    { "approximate", (PyCFunction)(void (*)(void))py_approximate,
      METH_VARARGS | METH_KEYWORDS,
      "approximate(points, count, degree=3, param=None, fix_ends=True): "
      "least-squares B-spline of count control points, residual" },
    { "parameters", (PyCFunction)(void (*)(void))py_parameters,
      METH_VARARGS | METH_KEYWORDS,
      "parameters(points, param=None, closed=False, exponent=None): the "
      "data parameters u_i" },
    { "nurbs_circle", py_nurbs_circle, METH_VARARGS,
      "nurbs_circle(centre, r): the exact circle as a NURBS" },
    { "coons", (PyCFunction)(void (*)(void))py_coons,
      METH_VARARGS | METH_KEYWORDS,
      "coons(points, ends='plain'): the uniform cubic (Coons) B-spline" },
    { "ferguson", py_ferguson, METH_VARARGS,
      "ferguson(P0, P1, T0, T1): the Hermite cubic as a Bézier curve" },
    { "ferguson_chain", py_ferguson_chain, METH_VARARGS,
      "ferguson_chain(points, tangents): a C1 chain of Hermite cubics" },
    { "coons_cubic", py_coons_cubic, METH_O,
      "coons_cubic(P): the uniform cubic B-spline segment of 4 points" },
    { NULL, NULL, 0, NULL }
};
