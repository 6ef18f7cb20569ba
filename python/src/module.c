/*
** curvefig._core: the module's types and functions (python/src/py*.c).
*/
#define CFPY_IMPORT_ARRAY_HERE
#include "pycommon.h"

static PyObject *
py_have_html(PyObject *mod, PyObject *unused)
{
    (void)mod;
    (void)unused;
#ifdef CF_TOOL_HAVE_WASM
    Py_RETURN_TRUE;
#else
    Py_RETURN_FALSE;
#endif
}

static PyMethodDef module_functions[] = {
    { "have_html", py_have_html, METH_NOARGS,
      "True when the module carries the course page's WebAssembly module" },
    { NULL, NULL, 0, NULL }
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_core",
    "curvefig's core and renderer (see the package curvefig)", -1,
    module_functions, NULL, NULL, NULL, NULL
};

static int
add_functions(PyObject *m, PyMethodDef *defs)
{
    for (; defs->ml_name != NULL; defs++) {
        PyObject *f = PyCFunction_NewEx(defs, NULL, NULL);
        if (f == NULL || PyModule_AddObject(m, defs->ml_name, f) != 0) {
            Py_XDECREF(f);
            return -1;
        }
    }
    return 0;
}

PyMODINIT_FUNC PyInit__core(void);

PyMODINIT_FUNC
PyInit__core(void)
{
    PyTypeObject *types[] = { &cfpy_BezierType, &cfpy_BSplineType,
                              &cfpy_BezierSurfaceType,
                              &cfpy_BSplineSurfaceType,
                              &cfpy_BezierTriangleType, &cfpy_ScriptType };
    const char *names[] = { "Bezier", "BSpline", "BezierSurface",
                            "BSplineSurface", "BezierTriangle", "Script" };
    PyObject *m;
    import_array();
    m = PyModule_Create(&module);
    if (m == NULL)
        return NULL;
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++) {
        if (PyType_Ready(types[i]) != 0 ||
            PyModule_AddObjectRef(m, names[i], (PyObject *)types[i]) != 0) {
            Py_DECREF(m);
            return NULL;
        }
    }
    if (add_functions(m, cfpy_interp_functions) != 0 ||
        add_functions(m, cfpy_make_functions) != 0 ||
        PyModule_AddStringConstant(m, "version", cf_version_string()) != 0) {
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
