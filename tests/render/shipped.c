#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <dirent.h>
#include <sys/stat.h>

#include <cmocka.h>

#include "script.h"
#include "shipped.h"
#include "testutil.h"

/* The figures of the scripts of dir, into *figures and *bad. */
static void
each_in(const char *dir, tu_figure_check_t check, void *ctx,
        size_t *figures, size_t *bad)
{
    char *names[256];
    size_t n, i;
    n = tu_figure_scripts(dir, names, 256);
    for (i = 0; i < n; i++) {
        char path[1536];
        cf_script_t *sc = NULL;
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        assert_int_equal(cf_script_create(NULL, NULL, &sc, NULL), 0);
        if (cf_script_run_file(sc, path) != CF_STATUS_OK)
            fail_msg("%s: %s", path, cf_script_error(sc));
        for (size_t f = 0; f < cf_script_figure_count(sc); f++) {
            (*figures)++;
            *bad += check(ctx, names[i], cf_script_figure_name(sc, f),
                          cf_script_figure(sc, f)) > 0;
        }
        cf_script_destroy(sc);
        free(names[i]);
    }
}

size_t
tu_each_shipped_figure(const char *root, tu_figure_check_t check, void *ctx,
                       size_t *failed)
{
    char dir[1024];
    size_t figures = 0, bad = 0;
    snprintf(dir, sizeof dir, "%s/figures", root);
    each_in(dir, check, ctx, &figures, &bad);
    if (failed != NULL)
        *failed = bad;
    return figures;
}

size_t
tu_each_shipped_figure_all(const char *root, tu_figure_check_t check,
                           void *ctx, size_t *failed)
{
    char dir[1024], sub[1280];
    size_t figures = 0, bad = 0;
    struct dirent *de;
    DIR *d;
    snprintf(dir, sizeof dir, "%s/figures", root);
    each_in(dir, check, ctx, &figures, &bad);
    d = opendir(dir);
    assert_non_null(d);
    while ((de = readdir(d)) != NULL) {
        struct stat st;
        if (de->d_name[0] == '.')
            continue;
        snprintf(sub, sizeof sub, "%s/%s", dir, de->d_name);
        if (stat(sub, &st) == 0 && S_ISDIR(st.st_mode))
            each_in(sub, check, ctx, &figures, &bad);
    }
    closedir(d);
    if (failed != NULL)
        *failed = bad;
    return figures;
}
