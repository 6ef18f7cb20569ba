/* The helpers the tool tests share (test_tool.c, test_tool_sandbox.c):
** running the tool in a fresh directory, its output read back; static
** inline where not every file uses it. */
#ifndef CURVEFIG_TESTS_TEST_TOOL_H
#define CURVEFIG_TESTS_TEST_TOOL_H

#define _XOPEN_SOURCE 700
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <cmocka.h>
#include "curvefig/bezier.h"
#include "curvefig/bspline.h"
#include "curvefig/interp.h"
#include "curvefig/offset.h"
#include "spawn.h"

static char tool[4096];

static char srcdir[4096];

typedef struct result {
    int status;          /* exit status, or -1 */
    char out[65536];     /* stdout */
    char err[16384];     /* stderr */
    char dir[256];       /* the working directory of the run */
} result;

static void
slurp(const char *path, char *buf, size_t cap)
{
    FILE *f = fopen(path, "rb");
    size_t n = 0;
    if (f != NULL) {
        n = fread(buf, 1, cap - 1, f);
        fclose(f);
    }
    buf[n] = '\0';
}

/* The run's directory, made when it is empty (run_tool's, put_file's). */
static void
own_dir(result *r)
{
    if (r->dir[0] == '\0') {
        snprintf(r->dir, sizeof r->dir, "/tmp/curvefig-test-XXXXXX");
        assert_non_null(mkdtemp(r->dir));
    }
}

/* Run TOOL with args (NULL-terminated, after the tool's name) in the
** temporary directory r->dir, made when it is empty (see reset). */
static void
run_tool(result *r, const char *const *args)
{
    char *argv[64], outp[300], errp[300];
    int n = 0, status;
    tu_spawn_t sp;
    own_dir(r);
    snprintf(outp, sizeof outp, "/tmp/curvefig-out-%d", (int)getpid());
    snprintf(errp, sizeof errp, "/tmp/curvefig-err-%d", (int)getpid());
    argv[n++] = tool;
    for (; *args != NULL && n < 63; args++)
        argv[n++] = (char *)*args;
    argv[n] = NULL;
    memset(&sp, 0, sizeof sp);
    sp.argv = (const char *const *)argv;
    sp.dir = r->dir;
    sp.out = outp;
    sp.err = errp;
    status = tu_spawn(&sp);
    assert_true(status >= 0);
    r->status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    slurp(outp, r->out, sizeof r->out);
    slurp(errp, r->err, sizeof r->err);
    remove(outp);
    remove(errp);
}

/* Number of entries in r->dir (recursively), for "touches nothing". */
static int
count_files(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    if (d == NULL)
        return -1;
    while ((e = readdir(d)) != NULL) {
        char path[1024];
        struct stat sb;
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        n++;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (stat(path, &sb) == 0 && S_ISDIR(sb.st_mode))
            n += count_files(path);
    }
    closedir(d);
    return n;
}

static void
remove_tree(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    if (d == NULL)
        return;
    while ((e = readdir(d)) != NULL) {
        char path[1024];
        struct stat sb;
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (stat(path, &sb) == 0 && S_ISDIR(sb.st_mode))
            remove_tree(path);
        else
            remove(path);
    }
    closedir(d);
    rmdir(dir);
}

/* A file `name` in the run's directory (made at need) holding text; its
** path into path[0..size-1] when path is not NULL. */
static void
put_file(result *r, const char *name, const char *text, char *path,
         size_t size)
{
    char p[600];
    FILE *f;
    own_dir(r);
    snprintf(p, sizeof p, "%s/%s", r->dir, name);
    f = fopen(p, "w");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
    if (path != NULL)
        snprintf(path, size, "%s", p);
}

/* Remove the run's directory; the next run makes a new one. */
static void
reset(result *r)
{
    if (r->dir[0] != '\0')
        remove_tree(r->dir);
    r->dir[0] = '\0';
}

static const char *
src(const char *name)
{
    static char buf[8][4200];
    static int k;
    k = (k + 1) % 8;
    snprintf(buf[k], sizeof buf[k], "%s/%s", srcdir, name);
    return buf[k];
}

#define assert_contains(hay, needle)                                         \
    do {                                                                     \
        if (strstr((hay), (needle)) == NULL)                                 \
            fail_msg("expected \"%s\" in:\n%s", (needle), (hay));            \
    } while (0)

/* ---- fixtures ----------------------------------------------------------- */

static int
setup(void **state)
{
    result *r = calloc(1, sizeof *r);
    if (r == NULL)
        return -1;
    *state = r;
    return 0;
}

static int
teardown(void **state)
{
    result *r = *state;
    reset(r);
    free(r);
    return 0;
}

#define T(f) cmocka_unit_test_setup_teardown(f, setup, teardown)

/* The arguments TOOL SRCDIR into tool and srcdir, made absolute (the
** child changes directory): 0, else -1 after a message. */
static int
tool_args(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: %s TOOL SRCDIR\n", argv[0]);
        return -1;
    }
    if (realpath(argv[1], tool) == NULL) {
        fprintf(stderr, "%s: %s: %s\n", argv[0], argv[1], strerror(errno));
        return -1;
    }
    if (realpath(argv[2], srcdir) == NULL) {
        fprintf(stderr, "%s: %s: %s\n", argv[0], argv[2], strerror(errno));
        return -1;
    }
    return 0;
}

#endif
