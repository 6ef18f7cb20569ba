/*
** Functions of a shared library opened at need (render/backends/
** pango-lazy.c, hb-lazy.c): each definition forwards to the function of
** the same name found by lookup(name) (which never returns NULL: it stops
** the program), the pointer found once per function (a race only finds
** the same pointer twice).  The definitions are hidden (the library
** exports only CF_API), so they never stand in for the library's own in a
** program that links it.
*/
#ifndef CURVEFIG_RENDER_LAZY_FORWARD_H
#define CURVEFIG_RENDER_LAZY_FORWARD_H

#include <pthread.h>
#include <string.h>

/* A library opened at its first function's call (one per process, as
** the library is). */
typedef struct cf__lazy_lib {
    const char *file;       /* "libharfbuzz.so.0" */
    const char *what;       /* "HarfBuzz" */
    const char *package;    /* Debian's package of it */
    void (*before)(void);   /* run once before it is opened, or NULL */
    pthread_mutex_t lock;
    void *handle;
    int tried;
} cf__lazy_lib_t;

#define CF__LAZY_LIB(file, what, package, before) \
    { file, what, package, before, PTHREAD_MUTEX_INITIALIZER, NULL, 0 }

/* The address of lib's function name, the library opened at the first
** call; never NULL: when the library or the function is missing, the
** program stops with a message naming them
** (render/backends/lazy-forward.c). */
void *cf__lazy_symbol(cf__lazy_lib_t *lib, const char *name);

#define CF__FORWARD_(lookup, ret, name, params, call)                      \
    ret(name) params                                                       \
    {                                                                      \
        typedef ret(*fn_t) params;                                         \
        static _Atomic(fn_t) cached;                                       \
        fn_t f = cached;                                                   \
        if (f == NULL) {                                                   \
            void *p = lookup(#name);                                       \
            memcpy(&f, &p, sizeof f);                                      \
            cached = f;                                                    \
        }                                                                  \
        call;                                                              \
    }
#define CF__FORWARD(lookup, ret, name, params, args) \
    CF__FORWARD_(lookup, ret, name, params, return f args)
#define CF__FORWARD_VOID(lookup, name, params, args) \
    CF__FORWARD_(lookup, void, name, params, f args)

#endif
