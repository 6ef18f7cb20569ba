/*
** `curvefig live SCRIPT.lua [--port N]`: the live view of an interactive
** figure, a web server on 127.0.0.1 (libmicrohttpd) with a random token in
** its URL:
**
**   GET  /TOKEN/              the page (render/web: page.js, live.js, page.css)
**   POST /TOKEN/run           body: the values as JSON; reply: the JSON of
**                             render/lua/interactive.h (400 for bad values)
**   GET  /TOKEN/wait?v=V      the script's version (its mtime) once it
**                             differs from V, or V after 20 s (long poll)
**
** Any other path is 403 without the token and 404 with it.  Every run
** reads the script again and runs it in a fresh sandbox with the limits of
** render; one run at a time.  `curvefig live SCRIPT.lua --once [VALUES]`
** prints the JSON of one run (VALUES: the values' JSON, default {}), in
** every build.
*/
#include <errno.h>
#include <fcntl.h>
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
#include "tool.h"

#define EXIT_SCRIPT 1
#define EXIT_USAGE 2

/* Read path whole (NUL-terminated, malloc'd), NULL on failure (errno). */
static char *
read_file(const char *path, size_t max)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    size_t len = 0, cap = 0;
    if (f == NULL)
        return NULL;
    for (;;) {
        size_t n;
        if (len + 4096 + 1 > cap) {
            char *p;
            cap = cap ? 2 * cap : 16384;
            if (cap > max + 4097 || (p = realloc(buf, cap)) == NULL) {
                free(buf);
                fclose(f);
                errno = EFBIG;
                return NULL;
            }
            buf = p;
        }
        n = fread(buf + len, 1, 4096, f);
        len += n;
        if (n < 4096)
            break;
    }
    fclose(f);
    buf[len] = '\0';
    return buf;
}

/* One run of the script with these values: the JSON (free()) and whether
** the values were good. */
char *
cf__live_run(const char *script, const cf_script_limits_t *limits,
             const char *values, size_t len, bool *bad_values, char *error,
             size_t error_len)
{
    char *code = read_file(script, (size_t)64 << 20), *json = NULL;
    size_t jlen;
    cf_status_t st;
    *bad_values = false;
    if (code == NULL) {
        /* the same JSON, with the error in it */
        char msg[600];
        size_t n;
        snprintf(msg, sizeof msg, "cannot read the script %s: %s", script,
                 strerror(errno));
        code = malloc(strlen(msg) * 2 + 64);
        if (code == NULL)
            return NULL;
        n = (size_t)sprintf(code, "error(\"");
        for (const char *p = msg; *p; p++) {
            if (*p == '"' || *p == '\\')
                code[n++] = '\\';
            code[n++] = *p;
        }
        strcpy(code + n, "\", 0)");
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
        "usage: curvefig live SCRIPT.lua [--port N]\n"
        "       curvefig live SCRIPT.lua --once [VALUES]\n"
        "\n"
        "Serve the figures of an interactive script (slider{...} and\n"
        "points{...}, docs/interactive.md) on 127.0.0.1 and print the\n"
        "address to open, which carries a random token: a request without\n"
        "it is refused (403), so no other page or user can drive the server.\n"
        "Moving a slider or dragging a point runs the script again in a\n"
        "fresh sandbox (the limits of render) and redraws; a script error\n"
        "is shown in the page; saving the script reloads the page.  The\n"
        "page shows the current values as Lua, to paste into the script.\n"
        "\n"
        "Options:\n"
        "  --port N            the port (default 0: a free port)\n"
        "  --once [VALUES]     print the JSON of one run and exit (VALUES:\n"
        "                      {\"t\": 0.5, \"P\": [[0, 0], [1, 2]]}; default {});\n"
        "                      exits 1 with the message (file:line) on a\n"
        "                      script error, 2 on bad values\n",
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
    cf_script_limits_t limits = { 0, 0 };
    struct stat sb;
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
    if (stat(script, &sb) != 0 || !S_ISREG(sb.st_mode))
        return fprintf(stderr, "curvefig: cannot read the script %s: %s\n",
                       script, errno ? strerror(errno) : "not a regular file"),
               EXIT_USAGE;
    cf__tool_fonts_init();
    if (want_once) {
        bool bad;
        char error[1024];
        const char *v = once != NULL ? once : "{}";
        char *json = cf__live_run(script, &limits, v, strlen(v), &bad, error,
                                  sizeof error);
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
