/*
** The commands that need large libraries run as programs of their own,
** so that `render`, `run` and `list` do not load them: `compare` and
** `test` (librsvg, with libxml2, ICU and libstdc++) are curvefig-check,
** `live` (libmicrohttpd, with GnuTLS) is curvefig-live.  The dynamic
** loader's work before main is most of a small figure's time, and grows
** with every shared object the program is linked with.
**
** A helper is looked for next to the running program (the build tree),
** then in the libexec directory relative to it (an installation moved as
** a whole), then at the libexec directory of the installation; so is the
** WebAssembly module of the course pages (render/tool/html.c), in the
** build tree in render/web beside render/tool.
*/
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "helpers.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

/* The directory of the running program into dir (no trailing '/');
** false where the system does not say (no /proc). */
static bool
program_dir(char *dir, size_t cap)
{
    ssize_t n = readlink("/proc/self/exe", dir, cap - 1);
    char *slash;
    if (n <= 0 || (size_t)n >= cap - 1)
        return false;
    dir[n] = '\0';
    slash = strrchr(dir, '/');
    if (slash == NULL)
        return false;
    *slash = '\0';
    return true;
}

static bool
try_path(char *out, size_t cap, const char *dir, const char *sub,
         const char *name, int mode)
{
    int n = snprintf(out, cap, "%s%s%s/%s", dir, sub[0] ? "/" : "", sub,
                     name);
    return n > 0 && (size_t)n < cap && access(out, mode) == 0;
}

/* Append directory d (dir/sub, or d alone) to the list where. */
static void
add_where(char *where, size_t cap, const char *dir, const char *sub)
{
    size_t n = strlen(where);
    snprintf(where + n, cap - n, "%s%s%s%s", n > 0 ? ", " : "", dir,
             sub[0] ? "/" : "", sub);
}

bool
cf__tool_find_file(const char *name, const char *build_sub, int mode,
                   char *out, size_t cap, char *where, size_t wherecap)
{
    char dir[PATH_MAX];
    bool have_dir = program_dir(dir, sizeof dir);
    where[0] = '\0';
    if (have_dir) {
        if (try_path(out, cap, dir, build_sub, name, mode))
            return true;
        add_where(where, wherecap, dir, build_sub);
        if (CF_TOOL_LIBEXEC_FROM_BIN[0] != '\0') {
            if (try_path(out, cap, dir, CF_TOOL_LIBEXEC_FROM_BIN, name, mode))
                return true;
            add_where(where, wherecap, dir, CF_TOOL_LIBEXEC_FROM_BIN);
        }
    }
    if (try_path(out, cap, CF_TOOL_LIBEXEC_DIR, "", name, mode))
        return true;
    add_where(where, wherecap, CF_TOOL_LIBEXEC_DIR, "");
    return false;
}

int
cf__tool_run_helper(const char *name, int argc, char **argv)
{
    char where[3 * PATH_MAX], path[PATH_MAX];
    (void)argc;
    if (cf__tool_find_file(name, "", X_OK, path, sizeof path, where,
                           sizeof where)) {
        argv[0] = path;
        execv(path, argv);
        fprintf(stderr, "curvefig: %s: cannot run %s: %s\n", argv[1], path,
                strerror(errno));
        return 2;
    }
    fprintf(stderr, "curvefig: %s: this installation of curvefig lacks its "
            "program %s (looked in %s): install curvefig again\n", argv[1],
            name, where);
    return 2;
}
