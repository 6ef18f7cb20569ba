/*
** The limits of a script run and their options (runlimits.h).
*/
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "runlimits.h"

int
cf__tool_number(const char *s, double lo, double hi, double *out)
{
    char *end;
    double v;
    errno = 0;
    v = strtod(s, &end);
    if (errno != 0 || end == s || *end != '\0' || !(v >= lo && v <= hi))
        return -1;
    *out = v;
    return 0;
}

int
cf__tool_limit_option(const char *opt, const char *value,
                      cf__tool_limits *l, char *msg, size_t size)
{
    double num;
    if (strcmp(opt, "--max-memory") == 0) {
        if (cf__tool_number(value, 1, 65536, &num) != 0)
            return snprintf(msg, size, "--max-memory '%s': give MiB from 1 "
                            "to 65536", value), -1;
        l->script.max_memory = (size_t)num << 20;
    } else if (strcmp(opt, "--max-instructions") == 0) {
        if (cf__tool_number(value, 1e4, 1e15, &num) != 0)
            return snprintf(msg, size, "--max-instructions '%s': give a "
                            "number from 10000 to 1e15", value), -1;
        l->script.max_instructions = (unsigned long long)num;
    } else if (strcmp(opt, "--timeout") == 0) {
        if (cf__tool_number(value, 1, 86400, &l->timeout) != 0)
            return snprintf(msg, size, "--timeout '%s': give seconds from 1 "
                            "to 86400", value), -1;
    } else {
        return 0;
    }
    return 1;
}

void
cf__tool_timeout_message(char *msg, size_t size, const char *script,
                         double seconds)
{
    snprintf(msg, size, "%s: the script exceeded the time limit of %g s "
             "(--timeout)", script, seconds);
}

/* ---- the watchdog ------------------------------------------------------- */

/* Only async-signal-safe calls in the handler. */
static char alarm_msg[600];
static size_t alarm_len;

static void
on_alarm(int sig)
{
    (void)sig;
    if (write(STDERR_FILENO, alarm_msg, alarm_len) < 0)
        _exit(1);
    _exit(1);
}

void
cf__tool_watchdog(const char *script, double seconds)
{
    struct sigaction sa;
    size_t n;
    memcpy(alarm_msg, "curvefig: ", 10);
    cf__tool_timeout_message(alarm_msg + 10, sizeof alarm_msg - 11, script,
                             seconds);
    n = strlen(alarm_msg);
    alarm_msg[n] = '\n';
    alarm_len = n + 1;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_alarm;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGALRM, &sa, NULL);
    alarm((unsigned)seconds);
}
