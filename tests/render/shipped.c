#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "script.h"
#include "shipped.h"
#include "testutil.h"

size_t
tu_each_shipped_figure(const char *root, tu_figure_check_t check, void *ctx,
                       size_t *failed)
{
    char dir[1024], *names[256];
    size_t n, i, figures = 0, bad = 0;
    snprintf(dir, sizeof dir, "%s/figures", root);
    n = tu_figure_scripts(dir, names, 256);
    for (i = 0; i < n; i++) {
        char path[1280];
        cf_script_t *sc = NULL;
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        assert_int_equal(cf_script_create(NULL, NULL, &sc, NULL), 0);
        if (cf_script_run_file(sc, path) != CF_STATUS_OK)
            fail_msg("%s: %s", path, cf_script_error(sc));
        for (size_t f = 0; f < cf_script_figure_count(sc); f++) {
            figures++;
            bad += check(ctx, names[i], cf_script_figure_name(sc, f),
                         cf_script_figure(sc, f)) > 0;
        }
        cf_script_destroy(sc);
        free(names[i]);
    }
    if (failed != NULL)
        *failed = bad;
    return figures;
}
