/*
** The font configuration's hook (render/backends/font-config.h).
*/
#include <pthread.h>
#include <stddef.h>

#include "font-config.h"
#include "font-faces.h"

/* fontconfig's configuration is one per process: so is its hook */
static void (*before_open)(void);
static pthread_once_t configured = PTHREAD_ONCE_INIT;

void
cf__fonts_before_open(void (*fn)(void))
{
    before_open = fn;
}

static void
configure(void)
{
    if (before_open != NULL)
        before_open();
}

void
cf__fonts_configure(void)
{
    pthread_once(&configured, configure);
}

static void (*before_fontconfig)(void);
static pthread_once_t fontconfig_configured = PTHREAD_ONCE_INIT;

void
cf__fonts_before_fontconfig(void (*fn)(void))
{
    before_fontconfig = fn;
}

static void
configure_fontconfig(void)
{
    if (before_fontconfig != NULL)
        before_fontconfig();
}

void
cf__fonts_configure_fontconfig(void)
{
    cf__fonts_configure();
    pthread_once(&fontconfig_configured, configure_fontconfig);
}

bool
cf__fonts_own_faces(const cf__fm_source_t *dirs, size_t n,
                    const char *const *families, size_t nfamilies)
{
    return cf__nfaces_use_dirs(dirs, n, families, nfamilies);
}
