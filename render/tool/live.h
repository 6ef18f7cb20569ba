/*
** `curvefig live` (live.c) and its web server (live-server.c, built with
** libmicrohttpd; without it the command says that this build has none).
*/
#ifndef CURVEFIG_TOOL_LIVE_H
#define CURVEFIG_TOOL_LIVE_H

#include <stdbool.h>
#include <stddef.h>

#include "script.h"

/* `curvefig live SCRIPT.lua [--port N] [--once [VALUES]]`; argv[0] is
** "live".  Returns the exit status. */
int cf__tool_live(int argc, char **argv);
void cf__tool_live_help(void);

/* One run of the script file with the values' JSON text: the JSON of
** render/lua/interactive.h (malloc'd; NULL when memory ran out);
** *bad_values when the values were not valid; the run's error message
** into error[0..error_len-1] ("" when it ran; error NULL: not asked). */
char *cf__live_run(const char *script, const cf_script_limits_t *limits,
                   const char *values, size_t len, bool *bad_values,
                   char *error, size_t error_len);
/* A text that changes whenever the script file is saved. */
void cf__live_version(const char *script, char out[64]);

/* Serve the live view of script on 127.0.0.1:port (0: a free port) until
** SIGINT or SIGTERM; prints the URL.  Returns the exit status. */
int cf__live_serve(const char *script, const cf_script_limits_t *limits,
                   unsigned port);

#endif
