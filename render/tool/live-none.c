/*
** `curvefig live` in a build without libmicrohttpd: --once works, the
** server says that there is none.
*/
#include <stdio.h>

#include "live.h"

int
cf__live_serve(const char *script, const cf__tool_limits *limits,
               unsigned port)
{
    (void)limits;
    (void)port;
    fprintf(stderr, "curvefig live: %s: this build of curvefig has no live "
            "view (it was built without libmicrohttpd; install "
            "libmicrohttpd-dev and build again)\n", script);
    return 1;
}
