/*
** Helpers shared by the Python binding's files (python/src/py*.c): numpy
** arrays in (checked, converted once to C-contiguous float64), arrays out,
** a failed status as a ValueError with the library's message, and the
** types' registration.  The binding is thin, as render/lua/ is: each
** method checks its arguments, calls one core function, and wraps the
** result; every object is immutable (no method changes its curve).
*/
#ifndef CURVEFIG_PYTHON_PYCOMMON_H
#define CURVEFIG_PYTHON_PYCOMMON_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#ifndef CFPY_IMPORT_ARRAY_HERE
#define NO_IMPORT_ARRAY
#endif
#define PY_ARRAY_UNIQUE_SYMBOL cfpy_ARRAY_API
#include <numpy/arrayobject.h>

#include "curvefig/curvefig.h"

/* Evaluations of at least this many parameters run without the GIL. */
#define CFPY_NOGIL_MIN 2048

/* ValueError "fn: message" from a failed status (diag may be NULL: the
** status's text).  Returns NULL. */
PyObject *cfpy_fail(const char *fn, cf_status_t st, const cf_diag_t *diag);
/* A number as Python's repr writes it, into buf. */
#define CFPY_NUM 40
const char *cfpy_num(double v, char buf[CFPY_NUM]);

/* ValueError "fn: formatted message" (PyErr_Format's % codes).  NULL. */
PyObject *cfpy_error(const char *fn, const char *fmt, ...);

/* obj as a C-contiguous float64 array of ndim dimensions (ndim 0: any),
** copied when it is not one already; a ragged list, a non-numeric dtype or
** a wrong number of dimensions raise TypeError/ValueError naming fn and
** what.  finite: also refuse NaN and infinities, naming the entry.  A new
** reference or NULL. */
PyArrayObject *cfpy_array(PyObject *obj, const char *fn, const char *what,
                          int ndim, int finite);
/* An (n, dim) array of points, n >= min, dim >= 1, finite. */
PyArrayObject *cfpy_points(PyObject *obj, const char *fn, const char *what,
                           npy_intp min);
/* A finite float argument. */
int cfpy_finite(PyObject *obj, const char *fn, const char *what,
                double *out);
/* An optional point of dimension dim (finite) into out[dim]. */
int cfpy_point(PyObject *obj, const char *fn, const char *what, size_t dim,
               double *out);

/* The arguments of transform(A, b=None) for points of dimension dim: A
** a dim x dim array (a new reference), b a PyMem buffer of dim numbers
** (zeros for None).  -1 (nothing to release) on bad input. */
int cfpy_affine(PyObject *Aobj, PyObject *bobj, const char *fn, size_t dim,
                PyArrayObject **A, double **b);

/* New float64 arrays (uninitialised, C order). */
PyArrayObject *cfpy_new(int ndim, const npy_intp *shape);
PyObject *cfpy_vector(const double *v, npy_intp n);
PyObject *cfpy_matrix(const double *v, npy_intp rows, npy_intp cols);

/* The shape of a parameter array followed by extra dimensions: out gets
** ndim(t) + nextra entries. */
int cfpy_shape_plus(PyArrayObject *t, const npy_intp *extra, int nextra,
                    npy_intp *out);

/* Which parameter of t[0..n-1] is bad for a curve on [a, b], for the
** message of a failed batch evaluation. */
PyObject *cfpy_param_error(const char *fn, cf_status_t st, const double *t,
                           size_t n, double a, double b);

/* Evaluate at every parameter of tobj (any shape; a number gives a 0-d
** shape): many(obj, t, n, out, arg) fills out, whose shape is the
** parameters' followed by extra[0..nextra-1].  Without the GIL from
** CFPY_NOGIL_MIN parameters on.  A failed status names the first
** parameter outside [a, b] or not finite. */
typedef cf_status_t (*cfpy_many_t)(const void *obj, const double *t,
                                   size_t n, double *out, const void *arg);
PyObject *cfpy_eval_params(PyObject *tobj, const char *fn, const void *obj,
                           cfpy_many_t many, const void *arg,
                           const npy_intp *extra, int nextra, double a,
                           double b);
/* The same into outobj when it is an array (NULL or None: a new one):
** float64, C-contiguous, writeable, of the result's shape, and not
** overlapping the parameters. */
PyObject *cfpy_eval_params_into(PyObject *tobj, PyObject *outobj,
                                const char *fn, const void *obj,
                                cfpy_many_t many, const void *arg,
                                const npy_intp *extra, int nextra, double a,
                                double b);

/* The tuple (a, b), taking both references; NULL (both released) when
** either is NULL. */
PyObject *cfpy_pair(PyObject *a, PyObject *b);

/* Map a direction "u" / "v" (surfaces). */
int cfpy_dir(PyObject *obj, const char *fn, int *dir);

/* The types and their wrappers (each file registers its own). */
extern PyTypeObject cfpy_BezierType;
extern PyTypeObject cfpy_BSplineType;
extern PyTypeObject cfpy_BezierSurfaceType;
extern PyTypeObject cfpy_BSplineSurfaceType;
extern PyTypeObject cfpy_BezierTriangleType;
extern PyTypeObject cfpy_ScriptType;

typedef struct {
    PyObject_HEAD
    cf_bezier_t *c;
} cfpy_Bezier;
typedef struct {
    PyObject_HEAD
    cf_bspline_t *c;
} cfpy_BSpline;

/* Wrap a curve (taken over; destroyed on failure).  NULL on failure. */
PyObject *cfpy_wrap_bezier(cf_bezier_t *c);
PyObject *cfpy_wrap_bspline(cf_bspline_t *c);
PyObject *cfpy_wrap_bspline_surface(cf_bspline_surface_t *s);
PyObject *cfpy_wrap_bezier_surface(cf_bezier_surface_t *s);

/* The surfaces' schemes and patches (pyscheme.c), as the language's
** s:decasteljau(u, v) -> (columns, v), s:deboor(u, v) -> ((columns, v),
** (span_u, span_v)), s:to_bezier() -> grid, s:knot_lines(dir). */
PyObject *cfpy_bezier_surface_decasteljau(const cf_bezier_surface_t *s,
                                          PyObject *args);
PyObject *cfpy_bspline_surface_deboor(const cf_bspline_surface_t *s,
                                      PyObject *args);
PyObject *cfpy_bspline_surface_to_beziers(const cf_bspline_surface_t *s);
PyObject *cfpy_bspline_surface_knot_lines(const cf_bspline_surface_t *s,
                                          PyObject *dirobj);
/* A Python list of Bézier curves, taken out of the list (destroyed). */
PyObject *cfpy_bezier_list(cf_bezier_list_t *list);
/* A list of cubic Bézier curves, one per segment of cu (not destroyed). */
PyObject *cfpy_cubics(const cf_cubics_t *cu);
/* Offsets of either kind of curve, as the language's c:offset. */
PyObject *cfpy_offset(const cf_bezier_t *bz, const cf_bspline_t *bs,
                      PyObject *args, PyObject *kw);

/* Degree reduction of either kind of curve, as the language's c:reduce. */
PyObject *cfpy_reduce(const cf_bezier_t *bz, const cf_bspline_t *bs,
                      PyObject *args, PyObject *kw);

/* The options of interpolate/approximate (and of the surfaces' in
** pymake.c) into opt: None leaves a default; the arrays params,
** start_tangent and end_tangent are kept alive in keep[0..2] (the caller
** releases them).  -1 on bad input. */
int cfpy_interp_options(const char *fn, PyObject *method, PyObject *param,
                        PyObject *exponent, PyObject *params, PyObject *t0,
                        PyObject *t1, int degree, size_t dim,
                        cf_interp_options_t *opt, PyArrayObject **keep);

/* Module-level functions of each file, NULL-terminated tables. */
extern PyMethodDef cfpy_interp_functions[];
extern PyMethodDef cfpy_make_functions[];

#endif
