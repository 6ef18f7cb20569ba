/*
** Libraries opened at need (render/backends/lazy-forward.h).
*/
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>

#include "lazy-forward.h"

void *
cf__lazy_symbol(cf__lazy_lib_t *lib, const char *name)
{
    void *p;
    pthread_mutex_lock(&lib->lock);
    if (!lib->tried) {
        if (lib->before != NULL)
            lib->before();
        lib->handle = dlopen(lib->file, RTLD_LAZY | RTLD_LOCAL);
        lib->tried = 1;
    }
    pthread_mutex_unlock(&lib->lock);
    if (lib->handle == NULL) {
        fprintf(stderr, "curvefig: labels need the %s library, which "
                "cannot be loaded: %s (Debian: apt-get install %s)\n",
                lib->what, dlerror(), lib->package);
        abort();
    }
    p = dlsym(lib->handle, name);
    if (p == NULL) {
        fprintf(stderr, "curvefig: the %s library %s has no function "
                "%s (too old a version?)\n", lib->what, lib->file, name);
        abort();
    }
    return p;
}
