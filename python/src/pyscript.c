/*
** curvefig._core.Script: a figure script run in the sandbox of the tool
** (render/lua/script.h), its figures rendered to memory in every format
** (curvefig/output.h), its sliders and points (render/lua/params.h), and
** the course page of `curvefig render -f html` (render/tool/html.c, built
** in when the WebAssembly module is).  The Python side (curvefig/figure.py)
** writes its figures as scripts of the language and renders them here.
*/
#include "pycommon.h"

#include <stdio.h>
#include <stdlib.h>

#include "curvefig/figure.h"
#include "curvefig/output.h"
#include "html.h"
#include "params.h"
#include "script.h"

typedef struct {
    PyObject_HEAD
    cf_script_t *s;
    FILE *out;          /* what print writes (open_memstream) */
    char *outbuf;
    size_t outsize;
    int busy;           /* a call runs without the GIL */
} cfpy_Script;

#define SELF(o) ((cfpy_Script *)(o))

static int
enter(cfpy_Script *o)
{
    if (o->busy) {
        PyErr_SetString(PyExc_RuntimeError,
                        "the script is in use by another thread");
        return -1;
    }
    o->busy = 1;
    return 0;
}

static void
sc_dealloc(PyObject *self)
{
    cfpy_Script *o = SELF(self);
    cf_script_destroy(o->s);
    if (o->out != NULL)
        fclose(o->out);
    free(o->outbuf);
    Py_TYPE(self)->tp_free(self);
}

static PyObject *
sc_new(PyTypeObject *type, PyObject *args, PyObject *kw)
{
    static char *names[] = { "code", "name", "params", "labels", NULL };
    const char *code, *name = "<script>", *params = NULL;
    Py_ssize_t code_len, params_len = 0;
    int labels = 1;
    cfpy_Script *o;
    cf_diag_t d;
    cf_status_t st;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "s#|sz#p:Script", names,
                                     &code, &code_len, &name, &params,
                                     &params_len, &labels))
        return NULL;
    if ((size_t)code_len != strlen(code))
        return cfpy_error("Script", "the script contains a NUL byte");
    o = (cfpy_Script *)type->tp_alloc(type, 0);
    if (o == NULL)
        return NULL;
    o->out = open_memstream(&o->outbuf, &o->outsize);
    if (o->out == NULL) {
        Py_DECREF(o);
        return PyErr_NoMemory();
    }
    st = cf_script_create(NULL, o->out, &o->s, &d);
    if (st != CF_STATUS_OK) {
        Py_DECREF(o);
        return cfpy_fail("Script", st, &d);
    }
    cf_script_set_labels(o->s, labels != 0);
    if (params != NULL) {
        char err[256];
        if (cf__params_give_json(cf_script_params(o->s), params,
                                 (size_t)params_len, err, sizeof err) != 0) {
            Py_DECREF(o);
            return cfpy_error("Script", "params: %s", err);
        }
    }
    o->busy = 1;
    Py_BEGIN_ALLOW_THREADS
    st = cf_script_run_string(o->s, code, name);
    Py_END_ALLOW_THREADS
    o->busy = 0;
    fflush(o->out);
    if (st != CF_STATUS_OK) {
        if (st == CF_STATUS_NO_MEMORY && cf_script_error(o->s)[0] == '\0') {
            Py_DECREF(o);
            return PyErr_NoMemory();
        }
        PyErr_SetString(PyExc_ValueError, cf_script_error(o->s));
        Py_DECREF(o);
        return NULL;
    }
    return (PyObject *)o;
}

static int
figure_index(cfpy_Script *o, Py_ssize_t i, const char *fn)
{
    size_t n = cf_script_figure_count(o->s);
    if (i < 0 || (size_t)i >= n) {
        PyErr_Format(PyExc_IndexError, "%s: no figure %zd (the script made "
                     "%zu)", fn, i, n);
        return -1;
    }
    return 0;
}

static PyObject *
sc_render(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *names[] = { "index", "format", "dpi", "tight", "padding",
                             "step", NULL };
    cfpy_Script *o = SELF(self);
    Py_ssize_t i;
    const char *fmt;
    cf_write_options_t opt;
    cf_format_t format;
    unsigned char *data = NULL;
    size_t size = 0;
    int tight = 0, step = 0;
    PyObject *r;
    cf_diag_t d;
    cf_status_t st;
    cf_write_options_init(&opt);
    if (!PyArg_ParseTupleAndKeywords(args, kw, "ns|dpdi:render", names, &i,
                                     &fmt, &opt.dpi, &tight, &opt.padding,
                                     &step))
        return NULL;
    if (figure_index(o, i, "render") != 0)
        return NULL;
    if (step < 0)
        return cfpy_error("render", "step %d is negative", step);
    st = cf_format_from_name(fmt, &format, &d);
    if (st != CF_STATUS_OK)
        return cfpy_fail("render", st, &d);
    opt.tight = tight != 0;
    opt.step = (unsigned)step;
    if (enter(o) != 0)
        return NULL;
    Py_BEGIN_ALLOW_THREADS
    st = cf_figure_render(cf_script_figure(o->s, (size_t)i), format, &opt,
                          &data, &size, &d);
    Py_END_ALLOW_THREADS
    o->busy = 0;
    if (st != CF_STATUS_OK)
        return cfpy_fail("render", st, &d);
    r = PyBytes_FromStringAndSize((const char *)data, (Py_ssize_t)size);
    cf_free(data);
    return r;
}

static PyObject *
sc_html(PyObject *self, PyObject *args)
{
    cfpy_Script *o = SELF(self);
    Py_ssize_t i;
    const char *script_path, *out_path, *module;
    cf__tool_limits limits = { { 0, 0 }, CF__TOOL_TIMEOUT, 0 };
    char err[512];
    int rc;
    if (!PyArg_ParseTuple(args, "nsss:html", &i, &script_path, &out_path,
                          &module))
        return NULL;
    if (figure_index(o, i, "html") != 0 || enter(o) != 0)
        return NULL;
    Py_BEGIN_ALLOW_THREADS
    rc = cf__tool_write_html(o->s, (size_t)i, script_path, &limits, out_path,
                             module, err, sizeof err);
    Py_END_ALLOW_THREADS
    o->busy = 0;
    if (rc != 0)
        return cfpy_error("html", "%s", err);
    Py_RETURN_NONE;
}

static PyObject *
sc_figures(PyObject *self, void *unused)
{
    cfpy_Script *o = SELF(self);
    size_t n = cf_script_figure_count(o->s);
    PyObject *l = PyList_New((Py_ssize_t)n);
    (void)unused;
    for (size_t i = 0; l != NULL && i < n; i++) {
        const char *cap = cf_script_figure_caption(o->s, i);
        PyObject *t = Py_BuildValue("(ss)", cf_script_figure_name(o->s, i),
                                    cap != NULL ? cap : "");
        if (t == NULL)
            Py_CLEAR(l);
        else
            PyList_SET_ITEM(l, (Py_ssize_t)i, t);
    }
    return l;
}

static PyObject *
sc_output(PyObject *self, void *unused)
{
    cfpy_Script *o = SELF(self);
    (void)unused;
    fflush(o->out);
    return PyUnicode_DecodeUTF8(o->outbuf != NULL ? o->outbuf : "",
                                (Py_ssize_t)o->outsize, "replace");
}

/* The sliders and point lists the script declared. */
static PyObject *
sc_params(PyObject *self, void *unused)
{
    const cf__params_t *p = cf_script_params(SELF(self)->s);
    size_t n = cf__params_count(p);
    PyObject *l = PyList_New((Py_ssize_t)n);
    (void)unused;
    for (size_t i = 0; l != NULL && i < n; i++) {
        const cf__param_t *q = cf__params_at(p, i);
        PyObject *item;
        if (q->kind == CF__PARAM_SLIDER)
            item = Py_BuildValue("{sssssssdsdsdsdsd}", "kind", "slider",
                                 "name", q->name, "label",
                                 q->label[0] ? q->label : q->name, "min",
                                 q->min, "max", q->max, "step", q->step,
                                 "default", q->def, "value", q->value);
        else
            item = Py_BuildValue("{s:s,s:s,s:s,s:N,s:N}", "kind", "points", "name",
                                 q->name, "figure", q->figure, "default",
                                 cfpy_matrix(q->def_xy, (npy_intp)q->count, 2),
                                 "value",
                                 cfpy_matrix(q->xy, (npy_intp)q->count, 2));
        if (item == NULL)
            Py_CLEAR(l);
        else
            PyList_SET_ITEM(l, (Py_ssize_t)i, item);
    }
    return l;
}

static PyMethodDef sc_methods[] = {
    { "render", (PyCFunction)(void (*)(void))sc_render,
      METH_VARARGS | METH_KEYWORDS,
      "render(index, format, dpi=150, tight=False, padding=0, step=0): the "
      "bytes of figure index in format svg, pdf, ps, eps, png or pgf" },
    { "html", sc_html, METH_VARARGS,
      "html(index, script_path, out_path, module): the course page of "
      "figure index, running the script at script_path, written to "
      "out_path, carrying the WebAssembly module read from module" },
    { NULL, NULL, 0, NULL }
};

static PyGetSetDef sc_getset[] = {
    { "figures", sc_figures, NULL, "[(name, caption), ...]", NULL },
    { "output", sc_output, NULL, "what the script printed", NULL },
    { "params", sc_params, NULL, "the sliders and point lists", NULL },
    { NULL, NULL, NULL, NULL, NULL }
};

PyTypeObject cfpy_ScriptType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "curvefig._core.Script",
    .tp_basicsize = sizeof(cfpy_Script),
    .tp_dealloc = sc_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "Script(code, name='<script>', params=None, labels=True): run "
              "a figure script (params: JSON of slider and point values)",
    .tp_methods = sc_methods,
    .tp_getset = sc_getset,
    .tp_new = sc_new,
};
