/*
** `curvefig live SCRIPT.lua [--port N] [--worker-runs N] [LIMITS]`: the
** live view of an interactive figure, a web server on 127.0.0.1
** (libmicrohttpd) with a random token in its URL:
**
**   GET  /TOKEN/              the page (render/web: page.js and its parts
**                             page-rotate.js, page-keys.js; live.js, page.css)
**   POST /TOKEN/run           body: the values as JSON; reply: the JSON of
**                             render/lua/interactive.h (400 for bad values)
**   GET  /TOKEN/wait?v=V      the script's version (its mtime) once it
**                             differs from V, or V after 20 s (long poll)
**
** Any other path is 403 without the token and 404 with it.  Every run
** reads the script again and runs it in a fresh sandbox, in a worker
** process (live-child.c) that serves runs until one fails (or it served
** --worker-runs, default 1000), with the limits of render (--max-memory,
** --max-instructions, --timeout): a run past the time limit is killed
** with its process and its error shown in the page; one run at a time.
** `curvefig live SCRIPT.lua --once [VALUES]` prints the JSON of one run
** (VALUES: the values' JSON, default {}), in every build, under the same
** limits.
*/
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "interactive.h"
#include "live.h"
#include "runlimits.h"
#include "tool.h"

#define EXIT_SCRIPT 1
#define EXIT_USAGE 2

/* The JSON of a run that failed with msg before or outside the script
** (an unreadable script, the time limit): the same JSON as a script's
** error, made by running error(msg) in a sandbox of its own. */
char *
cf__live_error_json(const char *script, const char *msg, char *error,
                    size_t error_len)
{
    char *code = malloc(strlen(msg) * 4 + 32), *json = NULL;
    size_t n, jlen;
    if (code == NULL)
        return NULL;
    memcpy(code, "error(\"", 7);
    n = 7;
    for (const unsigned char *p = (const unsigned char *)msg; *p; p++) {
        if (*p == '"' || *p == '\\' || *p < 32) {
            /* Lua's decimal escape */
            code[n++] = '\\';
            code[n++] = (char)('0' + *p / 100);
            code[n++] = (char)('0' + *p / 10 % 10);
            code[n++] = (char)('0' + *p % 10);
        } else {
            code[n++] = (char)*p;
        }
    }
    memcpy(code + n, "\", 0)", 6);
    cf_interactive_run_error(code, script, "{}", 2, NULL, stderr, &json,
                             &jlen, error, error_len);
    free(code);
    return json;
}

void
cf__live_warm(void)
{
    static const char code[] =
        "local f = figure{ name = \"warm\", width = \"3cm\", "
        "height = \"2cm\", window = { 0, 1, 0, 1 } }\n"
        "f:curve(bezier{ { 0, 0 }, { 0.5, 1 }, { 1, 0 } })\n"
        "f:label({ 0.5, 0.5 }, \"P_0 b_0^4(t) = 0.75, \\\\alpha\", "
        "{ place = \"auto\" })\n";
    char *json = NULL;
    size_t len;
    cf_interactive_run(code, "warm-up", "{}", 2, NULL, stderr, &json, &len);
    free(json);
}

/* One run of the script with these values: the JSON (free()) and whether
** the values were good.  The script is read afresh: a file that is no
** longer a regular file (a directory, a FIFO put in its place) is an
** error in the page, not an empty run or a reader blocked for ever. */
char *
cf__live_run(const char *script, const cf_script_limits_t *limits,
             const char *values, size_t len, bool *bad_values, char *error,
             size_t error_len)
{
    size_t clen, jlen;
    const char *why;
    char *code = cf__tool_read_file(script, (size_t)64 << 20, &clen, &why);
    char *json = NULL;
    cf_status_t st;
    *bad_values = false;
    if (code == NULL) {
        char msg[600];
        snprintf(msg, sizeof msg, "cannot read the script %s: %s", script,
                 why);
        return cf__live_error_json(script, msg, error, error_len);
    }
    st = cf_interactive_run_error(code, script, values, len, limits, stderr,
                                  &json, &jlen, error, error_len);
    free(code);
    *bad_values = st == CF_STATUS_INVALID_ARG;
    return json;
}

/* The script's version: its modification time in nanoseconds and size. */
void
cf__live_version(const char *script, char out[64])
{
    struct stat sb;
    if (stat(script, &sb) != 0)
        snprintf(out, 64, "missing");
    else
        snprintf(out, 64, "%lld.%09ld-%lld", (long long)sb.st_mtim.tv_sec,
                 (long)sb.st_mtim.tv_nsec, (long long)sb.st_size);
}

void
cf__tool_live_help(void)
{
    fputs(
        "usage: curvefig live SCRIPT.lua [--port N] [--worker-runs N] "
        "[LIMITS]\n"
        "       curvefig live SCRIPT.lua --once [VALUES] [LIMITS]\n"
        "\n"
        "Serve the figures of an interactive script (slider{...} and\n"
        "points{...}, docs/interactive.md) on 127.0.0.1 and print the\n"
        "address to open, which carries a random token: a request without\n"
        "it is refused (403), so no other page or user can drive the server.\n"
        "Moving a slider or dragging a point runs the script again in a\n"
        "fresh sandbox, in a worker process under the limits of render,\n"
        "and redraws (while the pointer drags a slow figure, as a draft of\n"
        "looser tolerances; released, exactly); a script error is shown in\n"
        "the page, as is a run that exceeds a limit (it is stopped with its\n"
        "process, which is replaced; the server runs on); saving\n"
        "the script reloads the page.  The page shows the current values\n"
        "as Lua, to paste into the script.  docs/interactive.md, \"Security\",\n"
        "says what the token protects and what a script can do.\n"
        "\n"
        "Options:\n"
        "  --port N            the port (default 0: a free port)\n"
        "  --worker-runs N     the runs one worker process serves before a\n"
        "                      fresh one replaces it (default 1000; it is\n"
        "                      replaced sooner after a failed run or when\n"
        "                      it grew by 64 MiB)\n"
        "  --once [VALUES]     print the JSON of one run and exit (VALUES:\n"
        "                      {\"t\": 0.5, \"P\": [[0, 0], [1, 2]]}; default {});\n"
        "                      exits 1 with the message (file:line) on a\n"
        "                      script error or a limit, 2 on bad values\n"
        "Limits of every run (as for render):\n"
        "  --max-memory MIB    memory a run may use (default 256)\n"
        "  --max-instructions N  Lua instructions a run may execute\n"
        "                      (default 5e8)\n"
        "  --timeout S         wall-clock seconds of a run (default 120);\n"
        "                      the run's process is then killed\n",
        stdout);
}

static int
usage(const char *fmt, const char *arg)
{
    fprintf(stderr, "curvefig live: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\nTry 'curvefig help live'.\n");
    return EXIT_USAGE;
}

int
cf__tool_live(int argc, char **argv)
{
    const char *script = NULL, *once = NULL;
    bool want_once = false;
    long port = 0;
    cf__tool_limits limits = { { 0, 0 }, CF__TOOL_TIMEOUT, 0 };
    char msg[200];
    int lim;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            cf__tool_live_help();
            return 0;
        } else if (strcmp(a, "--port") == 0) {
            char *end;
            if (i + 1 >= argc)
                return usage("option '%s' needs a value", a);
            errno = 0;
            port = strtol(argv[++i], &end, 10);
            if (errno != 0 || *end != '\0' || end == argv[i] || port < 0 ||
                port > 65535)
                return usage("--port '%s': give a port from 0 to 65535 (0: "
                             "any free port)", argv[i]);
        } else if (strcmp(a, "--worker-runs") == 0) {
            double n;
            if (i + 1 >= argc)
                return usage("option '%s' needs a value", a);
            if (cf__tool_number(argv[++i], 1, 1e9, &n) != 0 || n != floor(n))
                return usage("--worker-runs '%s': give a whole number of "
                             "runs from 1 to 1000000000 (default 1000)",
                             argv[i]);
            limits.worker_runs = (unsigned)n;
        } else if (i + 1 < argc && (lim = cf__tool_limit_option(
                       a, argv[i + 1], &limits, msg, sizeof msg)) != 0) {
            if (lim < 0)
                return usage("%s", msg);
            i++;
        } else if (strcmp(a, "--once") == 0) {
            want_once = true;
            if (i + 1 < argc && argv[i + 1][0] == '{')
                once = argv[++i];
        } else if (a[0] == '-' && a[1] != '\0') {
            return usage("unknown option '%s'", a);
        } else if (script != NULL) {
            return usage("%sgive exactly one script", "");
        } else {
            script = a;
        }
    }
    if (script == NULL)
        return usage("%sno script given", "");
    {
        /* the script readable now (runs read it again each time) */
        size_t len;
        const char *why;
        char *code = cf__tool_read_file(script, (size_t)64 << 20, &len, &why);
        if (code == NULL)
            return fprintf(stderr, "curvefig: cannot read the script %s: "
                           "%s\n", script, why), EXIT_USAGE;
        free(code);
    }
    /* (the fonts are the worker's: live-child.c; this process draws
    ** nothing) */
    if (want_once) {
        bool bad;
        char error[1024];
        const char *v = once != NULL ? once : "{}";
        char *json = cf__live_run_child(script, &limits, v, strlen(v), -1,
                                        NULL,
                                        &bad, error, sizeof error);
        if (json == NULL)
            return fprintf(stderr, "curvefig: out of memory\n"), EXIT_SCRIPT;
        fputs(json, stdout);
        free(json);
        /* the JSON carries the error too; the status and stderr say it */
        if (error[0] != '\0')
            fprintf(stderr, "curvefig: %s\n", error);
        return bad ? EXIT_USAGE : error[0] != '\0' ? EXIT_SCRIPT : 0;
    }
    return cf__live_serve(script, &limits, (unsigned)port);
}
