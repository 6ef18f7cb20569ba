/*
** The font configuration's hook (render/backends/font-config.h).
*/
#include <pthread.h>
#include <stddef.h>

#include "font-config.h"

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
