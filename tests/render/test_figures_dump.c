/* Every shipped figure (the scripts in figures/) dumps to the same display list on
** two independent runs of its script: the layout has no hidden state, no
** dependence on addresses, the clock or the order of allocation. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/figure.h"
#include "script.h"
#include "testutil.h"

/* The dumps of every figure a script defines, one after the other with
** their names; NULL when the script fails. */
static char *
dump_script(const char *path, size_t *nfig)
{
    cf_script_t *sc = NULL;
    char *all = NULL;
    size_t len = 0, i;
    assert_int_equal(cf_script_create(NULL, NULL, &sc, NULL), 0);
    if (cf_script_run_file(sc, path) != CF_STATUS_OK)
        fail_msg("%s: %s", path, cf_script_error(sc));
    *nfig = cf_script_figure_count(sc);
    for (i = 0; i < *nfig; i++) {
        const char *name = cf_script_figure_name(sc, i);
        char *text = NULL;
        size_t size = 0;
        cf_diag_t d;
        cf_diag_clear(&d);
        if (cf_figure_dump(cf_script_figure(sc, i), NULL, &text, &size, &d)
            != CF_STATUS_OK)
            fail_msg("%s: figure %s: %s", path, name, d.msg);
        all = realloc(all, len + strlen(name) + size + 3);
        assert_non_null(all);
        len += (size_t)sprintf(all + len, "%s\n", name);
        memcpy(all + len, text, size + 1);
        len += size;
        cf_free(text);
    }
    cf_script_destroy(sc);
    return all;
}

static void
test_every_figure_twice(void **state)
{
    char *names[256];
    size_t n, i, figures = 0;
    (void)state;
    n = tu_figure_scripts(CF_SOURCE_ROOT "/figures", names, 256);
    for (i = 0; i < n; i++) {
        char path[1024];
        size_t n1 = 0, n2 = 0;
        char *a, *b;
        snprintf(path, sizeof path, "%s/figures/%s", CF_SOURCE_ROOT,
                 names[i]);
        a = dump_script(path, &n1);
        b = dump_script(path, &n2);
        assert_int_equal(n1, n2);
        if (n1 > 0 && strcmp(a, b) != 0)
            fail_msg("%s: two runs give different display lists", path);
        /* a figure draws something: at least one operation past its page */
        if (n1 > 0 && strstr(a, "\ngroup ") == NULL)
            fail_msg("%s: a display list without an element", path);
        figures += n1;
        free(a);
        free(b);
        free(names[i]);
    }
    print_message("%zu scripts, %zu figures, each dumped twice alike\n", n,
                  figures);
    assert_true(n >= 30);
    assert_true(figures >= 60);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_figure_twice),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
