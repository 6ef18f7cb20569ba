/*
** `curvefig live` (live.c) and its web server (live-server.c, built with
** libmicrohttpd; without it the command says that this build has none).
*/
#ifndef CURVEFIG_TOOL_LIVE_H
#define CURVEFIG_TOOL_LIVE_H

#include <stdbool.h>
#include <stddef.h>
#include <sys/types.h>

#include "runlimits.h"
#include "script.h"

/* `curvefig live SCRIPT.lua [--port N] [--worker-runs N] [--once [VALUES]]
** [LIMITS]`; argv[0] is "live".  Returns the exit status. */
int cf__tool_live(int argc, char **argv);
void cf__tool_live_help(void);

/* One run of the script file with the values' JSON text: the JSON of
** render/lua/interactive.h (malloc'd; NULL when memory ran out);
** *bad_values when the values were not valid; the run's error message
** into error[0..error_len-1] ("" when it ran; error NULL: not asked). */
char *cf__live_run(const char *script, const cf_script_limits_t *limits,
                   const char *values, size_t len, bool *bad_values,
                   char *error, size_t error_len);
/* The same JSON for a run that failed with msg outside the script (an
** unreadable script, a limit); msg also into error (NULL: not asked). */
char *cf__live_error_json(const char *script, const char *msg, char *error,
                          size_t error_len);
/* The values a run may be given, in bytes (the server answers 413 above). */
#define CF__LIVE_MAX_VALUES ((size_t)1 << 20)

/* The process that runs the script (live-child.c): this program started
** again ahead of need (never a fork of the server, whose threads' locks a
** fork would copy held), it loads the fonts and runs a small figure of
** its own, then waits for values and serves one run after another, each in a
** fresh sandbox (a new Lua state: nothing a run leaves in Lua reaches the
** next).  It is replaced -- killed and reaped, a new one started -- when a
** run passes the time limit, is stopped, crashes or fails (a script
** error, a limit of the sandbox), after CF__LIVE_WORKER_RUNS runs (or the
** limits' worker_runs: --worker-runs N), and
** when its memory grew by more than CF__LIVE_WORKER_GROWTH bytes since its
** first run.  pid -1: none. */
typedef struct cf__live_worker {
    pid_t pid;
    int req, reply;   /* the values go in, the answers come out */
    unsigned runs;    /* the runs it served */
} cf__live_worker;
#define CF__LIVE_WORKER_RUNS 1000
#define CF__LIVE_WORKER_GROWTH ((long)64 << 20)
void cf__live_worker_init(cf__live_worker *w);
/* Start the worker when there is none (a failed start leaves none: the
** next run starts its own). */
void cf__live_worker_start(cf__live_worker *w, const char *script,
                           const cf__tool_limits *limits);
/* The worker's own main: `curvefig-live live-worker SCRIPT`, started by
** the above with its pipes at 3 and 4 (argv from "live-worker"). */
int cf__live_worker_main(int argc, char **argv);
/* Kill the worker and reap it. */
void cf__live_worker_drop(cf__live_worker *w);

/* cf__live_run in the worker w (live-child.c) under limits: w's process
** when it has one, else one started now (w NULL: started for this run
** and ended after it); killed after limits->timeout seconds from the moment
** it is given the values (the JSON then says so), or as soon as stop_fd
** (-1: none) becomes readable; a run that crashes is an error in the JSON
** too.  A worker that must be replaced (above) is gone from w afterwards:
** start the next one.  NULL only when memory ran out. */
char *cf__live_run_child(const char *script, const cf__tool_limits *limits,
                         const char *values, size_t len, int stop_fd,
                         cf__live_worker *w, bool *bad_values,
                         char *error, size_t error_len);
/* Run a small figure of our own (a curve, a label in the default fonts),
** so that a worker meets its first run with the fonts loaded and the
** caches of HarfBuzz's faces, fontconfig and cairo warm. */
void cf__live_warm(void);
/* Seconds of a monotonic clock. */
double cf__live_clock(void);
/* A text that changes whenever the script file is saved. */
void cf__live_version(const char *script, char out[64]);

/* Serve the live view of script on 127.0.0.1:port (0: a free port) until
** SIGINT or SIGTERM; prints the URL.  Returns the exit status. */
int cf__live_serve(const char *script, const cf__tool_limits *limits,
                   unsigned port);

#endif
