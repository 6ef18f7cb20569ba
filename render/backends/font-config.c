/*
** The font configuration's hooks (render/backends/font-config.h).
*/
#include <pthread.h>
#include <stddef.h>

#include "font-config.h"
#include "font-faces.h"

/* fontconfig's configuration is one per process: so are its hooks, the
** one before any font (OPEN) and the one before fontconfig's (FC) */
enum { OPEN, FC };
static void (*hooks[2])(void);
static pthread_once_t once[2] = { PTHREAD_ONCE_INIT, PTHREAD_ONCE_INIT };

static void
run(int which)
{
    if (hooks[which] != NULL)
        hooks[which]();
}

static void
run_open(void)
{
    run(OPEN);
}

static void
run_fc(void)
{
    run(FC);
}

void
cf__fonts_before_open(void (*fn)(void))
{
    hooks[OPEN] = fn;
}

void
cf__fonts_before_fontconfig(void (*fn)(void))
{
    hooks[FC] = fn;
}

void
cf__fonts_configure(void)
{
    pthread_once(&once[OPEN], run_open);
}

void
cf__fonts_configure_fontconfig(void)
{
    cf__fonts_configure();
    pthread_once(&once[FC], run_fc);
}

bool
cf__fonts_own_faces(const cf__fm_source_t *dirs, size_t n,
                    const char *const *families, size_t nfamilies)
{
    return cf__nfaces_use_dirs(dirs, n, families, nfamilies);
}
