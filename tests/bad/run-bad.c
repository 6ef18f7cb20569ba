/*
** The bad-input corpus runner: runs every case tests/bad/cases/NAME.lua
** through the built `curvefig` and checks what its header promises.
**
**   line 1   -- expect: RC "FRAGMENT"   exit status and a piece of the message
**   line 2   -- what the case is about (free text)
**   optional -- args: OPTIONS            more options for the tool
**   optional -- command: run|list        instead of render
**   optional -- max-rss: MIB             the tool's peak resident size
**                                        (getrusage of the child) must
**                                        stay below MIB: a memory limit
**                                        that holds, not only a message
**                                        (not checked under ASan, whose
**                                        shadow memory and quarantine
**                                        are resident too)
**
** A case passes when the tool exits with RC, its stderr contains FRAGMENT,
** a failed script (RC 1) is named with file and line ("NAME.lua:N"), and
** the output directory is empty afterwards: no figure and no temporary
** file was left behind.  Cases listed in the known-failures file (one name
** a line, '#' comments) reveal open bugs in code owned elsewhere; they are
** skipped unless --all is given (then a case that passes is reported, so
** the list can shrink).
**
** usage: run-bad TOOL CASES_DIR KNOWN_FAILURES SCRATCH_DIR [--all] [NAME...]
*/
#define _XOPEN_SOURCE 700   /* realpath */
#define _DEFAULT_SOURCE     /* wait4 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "spawn.h"

#define MAX_ARGS 32
#define LINE 1024

typedef struct bad_case {
    int rc;
    char fragment[LINE];
    char args[LINE];
    char command[32];
    long max_rss;        /* MiB, 0: not checked */
} bad_case;

#if defined(__SANITIZE_ADDRESS__)
#define RSS_CHECKED 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RSS_CHECKED 0
#endif
#endif
#ifndef RSS_CHECKED
#define RSS_CHECKED 1
#endif

static int
read_all(const char *path, char *buf, size_t cap)
{
    FILE *f = fopen(path, "rb");
    size_t n;
    if (f == NULL)
        return -1;
    n = fread(buf, 1, cap - 1, f);
    buf[n] = '\0';
    fclose(f);
    return 0;
}

/* Parse the header; returns a message describing the problem, or NULL. */
static const char *
parse_header(const char *path, bad_case *c)
{
    FILE *f = fopen(path, "r");
    char line[LINE];
    int lineno = 0;
    const char *err = "first line is not -- expect: RC \"FRAGMENT\"";
    memset(c, 0, sizeof *c);
    strcpy(c->command, "render");
    if (f == NULL)
        return "cannot open the case";
    while (fgets(line, sizeof line, f) != NULL && lineno < 5) {
        char *q;
        line[strcspn(line, "\n")] = '\0';
        lineno++;
        if (lineno == 1) {
            char *open, *close;
            if (sscanf(line, "-- expect: %d", &c->rc) != 1)
                break;
            open = strchr(line, '"');
            close = open ? strrchr(line, '"') : NULL;
            if (open == NULL || close == open || close - open - 1 < 1)
                break;
            memcpy(c->fragment, open + 1, (size_t)(close - open - 1));
            c->fragment[close - open - 1] = '\0';
            err = NULL;
        } else if ((q = strstr(line, "-- args: ")) == line) {
            snprintf(c->args, sizeof c->args, "%s", line + 9);
        } else if ((q = strstr(line, "-- max-rss: ")) == line) {
            c->max_rss = strtol(line + 12, NULL, 10);
        } else if ((q = strstr(line, "-- command: ")) == line) {
            size_t len = strlen(line + 12);
            if (len >= sizeof c->command)
                len = sizeof c->command - 1;
            memcpy(c->command, line + 12, len);
            c->command[len] = '\0';
        }
    }
    fclose(f);
    return err;
}

static int
is_known(const char *known, const char *name)
{
    size_t n = strlen(name);
    const char *p = known;
    while ((p = strstr(p, name)) != NULL) {
        if ((p == known || p[-1] == '\n') &&
            (p[n] == '\n' || p[n] == '\0' || p[n] == ' ' || p[n] == '\t'))
            return 1;
        p += n;
    }
    return 0;
}

/* Run the tool; returns its exit status (or 128 + signal); stderr into
** errpath, its peak resident size in KiB into *rss_kib. */
static int
run_tool(const char *tool, const char *script, const char *outdir,
         const bad_case *c, const char *errpath, long *rss_kib)
{
    char argbuf[LINE];
    char *argv[MAX_ARGS];
    int argc = 0;
    tu_spawn_t sp;

    argv[argc++] = (char *)tool;
    argv[argc++] = (char *)c->command;
    argv[argc++] = (char *)script;
    if (strcmp(c->command, "render") == 0) {
        argv[argc++] = "-o";
        argv[argc++] = (char *)outdir;
        argv[argc++] = "-f";
        argv[argc++] = "svg,pdf,png";
    }
    argv[argc++] = "--timeout";
    argv[argc++] = "60";
    snprintf(argbuf, sizeof argbuf, "%s", c->args);
    for (char *tok = strtok(argbuf, " "); tok != NULL && argc < MAX_ARGS - 1;
         tok = strtok(NULL, " "))
        argv[argc++] = tok;
    argv[argc] = NULL;

    memset(&sp, 0, sizeof sp);
    sp.argv = (const char *const *)argv;
    sp.dir = outdir;   /* `run` and `list` write nothing */
    sp.out = "/dev/null";
    sp.err = errpath;
    sp.rss_kib = rss_kib;
    return tu_exit_code(tu_spawn(&sp));
}

/* Names of the entries of dir, space-separated, into buf ("" if none). */
static void
list_dir(const char *dir, char *buf, size_t cap)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    buf[0] = '\0';
    if (d == NULL)
        return;
    while ((e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        if (strlen(buf) + strlen(e->d_name) + 2 < cap) {
            strcat(buf, e->d_name);
            strcat(buf, " ");
        }
    }
    closedir(d);
}

/* "NAME.lua:" followed by a digit somewhere in text. */
static int
names_line(const char *text, const char *name)
{
    char key[300];
    const char *p = text;
    snprintf(key, sizeof key, "%s.lua:", name);
    while ((p = strstr(p, key)) != NULL) {
        p += strlen(key);
        if (*p >= '0' && *p <= '9')
            return 1;
    }
    return 0;
}

static int
cmp_names(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

int
main(int argc, char **argv)
{
    static char known[65536], err[65536];
    char *names[1024];
    size_t n = 0;
    int all = 0, failed = 0, passed = 0, skipped = 0, fixed = 0;
    DIR *d;
    struct dirent *e;
    char abs_cases[4096], tool[4096];

    if (argc < 5) {
        fprintf(stderr, "usage: run-bad TOOL CASES_DIR KNOWN_FAILURES "
                "SCRATCH_DIR [--all] [NAME...]\n");
        return 2;
    }
    if (realpath(argv[1], tool) == NULL) {
        fprintf(stderr, "run-bad: %s: %s\n", argv[1], strerror(errno));
        return 2;
    }
    if (realpath(argv[2], abs_cases) == NULL) {
        fprintf(stderr, "run-bad: %s: %s\n", argv[2], strerror(errno));
        return 2;
    }
    if (read_all(argv[3], known, sizeof known) != 0) {
        fprintf(stderr, "run-bad: cannot read %s\n", argv[3]);
        return 2;
    }
    mkdir(argv[4], 0755);
    for (int i = 5; i < argc; i++)
        if (strcmp(argv[i], "--all") == 0)
            all = 1;

    d = opendir(abs_cases);
    if (d == NULL) {
        fprintf(stderr, "run-bad: cannot open %s\n", abs_cases);
        return 2;
    }
    while ((e = readdir(d)) != NULL && n < 1024) {
        size_t len = strlen(e->d_name);
        if (len > 4 && strcmp(e->d_name + len - 4, ".lua") == 0) {
            names[n] = strdup(e->d_name);
            names[n][len - 4] = '\0';
            n++;
        }
    }
    closedir(d);
    qsort(names, n, sizeof *names, cmp_names);

    for (size_t i = 0; i < n; i++) {
        char script[4400], outdir[4400], errpath[4400], left[2048] = "";
        const char *why = NULL;
        bad_case c;
        int rc, selected = 1, is_k;

        for (int a = 5; a < argc; a++) {
            if (argv[a][0] != '-') {
                selected = 0;
                break;
            }
        }
        for (int a = 5; a < argc && !selected; a++)
            if (strcmp(argv[a], names[i]) == 0)
                selected = 1;
        if (!selected) {
            free(names[i]);
            continue;
        }
        is_k = is_known(known, names[i]);
        if (is_k && !all) {
            printf("SKIP %s (known failure)\n", names[i]);
            skipped++;
            free(names[i]);
            continue;
        }
        err[0] = '\0';
        snprintf(script, sizeof script, "%s/%s.lua", abs_cases, names[i]);
        snprintf(outdir, sizeof outdir, "%s/%s", argv[4], names[i]);
        snprintf(errpath, sizeof errpath, "%s/%s.stderr", argv[4], names[i]);
        why = parse_header(script, &c);
        if (why == NULL) {
            /* a fresh, empty output directory */
            char rm[9000];
            snprintf(rm, sizeof rm, "rm -rf '%s'", outdir);
            if (system(rm) != 0 || mkdir(outdir, 0755) != 0)
                why = "cannot make the output directory";
        }
        if (why == NULL) {
            long rss = 0;
            rc = run_tool(tool, script, outdir, &c, errpath, &rss);
            read_all(errpath, err, sizeof err);
            list_dir(outdir, left, sizeof left);
            if (rc != c.rc) {
                static char msg[256];
                snprintf(msg, sizeof msg, "exit status %d, expected %d", rc,
                         c.rc);
                why = msg;
            } else if (strstr(err, c.fragment) == NULL) {
                why = "the message lacks the expected fragment";
            } else if (c.rc == 1 && !names_line(err, names[i])) {
                why = "the message does not name the script's file and line";
            } else if (left[0] != '\0') {
                why = "files were left in the output directory";
            } else if (RSS_CHECKED && c.max_rss > 0 &&
                       rss > c.max_rss * 1024) {
                static char msg[256];
                snprintf(msg, sizeof msg, "peak resident size %ld KiB, "
                         "above the case's %ld MiB", rss, c.max_rss);
                why = msg;
            }
        }
        if (why == NULL) {
            if (is_k) {
                printf("FIXED %s (passes now: remove it from the known "
                       "failures)\n", names[i]);
                fixed++;
            } else {
                printf("ok   %s\n", names[i]);
            }
            passed++;
        } else {
            printf("FAIL %s: %s\n     expected: %d \"%s\"\n     stderr: %.600s"
                   "%s     left: [%s]\n", names[i], why, c.rc, c.fragment,
                   err, err[0] && err[strlen(err) - 1] == '\n' ? "" : "\n",
                   why == NULL ? "" : left);
            if (!is_k)
                failed++;
        }
        free(names[i]);
    }
    printf("%d passed, %d failed, %d known failures skipped%s (%zu cases)\n",
           passed, failed, skipped, fixed ? ", some known failures pass" : "",
           n);
    return failed ? 1 : 0;
}
