/*
** The limits of a script run (runlimits.c), the same for render, run,
** list and live: the sandbox's memory and instruction limits and the
** wall-clock time limit, with their command-line options.
*/
#ifndef CURVEFIG_TOOL_RUNLIMITS_H
#define CURVEFIG_TOOL_RUNLIMITS_H

#include <stddef.h>

#include "script.h"

#define CF__TOOL_TIMEOUT 120.0     /* seconds, --timeout's default */

typedef struct cf__tool_limits {
    cf_script_limits_t script;     /* 0: the sandbox's defaults */
    double timeout;                /* wall-clock seconds */
    unsigned worker_runs;          /* live only: the runs a worker serves
                                   ** before it is replaced (--worker-runs;
                                   ** 0: CF__LIVE_WORKER_RUNS, live.h) */
} cf__tool_limits;

/* --max-memory MIB, --max-instructions N or --timeout S with its value:
** 1 when opt is one of them and value good (stored into l), 0 when opt is
** none of them, -1 for a bad value (msg says what to give). */
int cf__tool_limit_option(const char *opt, const char *value,
                          cf__tool_limits *l, char *msg, size_t size);

/* The number s, all of it, within [lo, hi]: 0 (into *out), else -1. */
int cf__tool_number(const char *s, double lo, double hi, double *out);

/* End this process after `seconds` of wall-clock time, with "curvefig:
** SCRIPT: the script exceeded the time limit of S s (--timeout)" on
** stderr (what the instruction limit cannot see: time inside one C call). */
void cf__tool_watchdog(const char *script, double seconds);
/* That message (without "curvefig: " and the newline) into msg. */
void cf__tool_timeout_message(char *msg, size_t size, const char *script,
                              double seconds);

#endif
