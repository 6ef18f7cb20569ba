/*
** Running a program from a test (tests/support/spawn.c): the one way the
** C tests start the curvefig tool, with its output to files or a buffer,
** in a directory of their choice, with environment changes, and killed
** after a delay when a test needs an interrupted run.
*/
#ifndef CURVEFIG_TESTS_SPAWN_H
#define CURVEFIG_TESTS_SPAWN_H

#include <stdbool.h>
#include <stddef.h>

typedef struct tu_spawn {
    const char *const *argv;   /* NULL-terminated; argv[0] the program */
    const char *dir;           /* working directory; NULL: the test's */
    const char *out, *err;     /* files for stdout and stderr (created,
                                  truncated); NULL: the test's */
    char *capture;             /* not NULL: stdout read into it instead
                                  (NUL-terminated, the rest dropped) */
    size_t capture_cap;
    const char *const *env;    /* NULL-terminated "NAME=VALUE" to set,
                                  "NAME" to unset; may be NULL */
    bool kill;                 /* SIGKILL after kill_after seconds */
    double kill_after;
    long *rss_kib;             /* not NULL: the child's peak resident size
                                  (KiB, getrusage's ru_maxrss) */
} tu_spawn_t;

/* Run the program and wait for it: its wait status (as waitpid gives
** it), or -1 when it could not be started or waited for.  A child that
** cannot set itself up (directory, files) exits with 126, one that
** cannot execute the program with 127. */
int tu_spawn(const tu_spawn_t *s);

/* The exit status of a wait status; 128 + the signal when killed. */
int tu_exit_code(int status);

#endif
