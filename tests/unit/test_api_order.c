/*
** The argument order of the evaluators (core.h, "Argument order"), read
** from the public headers so that a new evaluator that breaks it fails
** here: the object; the parameter (`double t` / `double u`), or the
** parameter array and its count (`const double *t, size_t n`); the other
** numbers (derivative order `int k`, distance `double d`); the outputs
** (non-const pointers); the diag, if any.
**
** An evaluator is a function whose name contains "eval" or ends in
** "_point", "_point_many", "_many", "_deriv" or "_ders".
*/
#include <ctype.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "testutil.h"

#ifndef CF_SOURCE_ROOT
#error "CF_SOURCE_ROOT (the source tree) must be defined by the build"
#endif

/* No messages while the checker checks itself. */
static int quiet;
#define REPORT(...) \
    do { \
        if (!quiet) \
            print_error(__VA_ARGS__); \
    } while (0)

enum role { OBJ, PARAM, COUNT, NUMBER, OUTPUT, DIAG };

static const char *const role_name[] = { "object", "parameter", "count",
                                         "number (k, d)", "output", "diag" };

static int
ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), m = strlen(suffix);
    return n >= m && strcmp(s + n - m, suffix) == 0;
}

static int
is_evaluator(const char *name)
{
    return strstr(name, "eval") != NULL || ends_with(name, "_point") ||
           ends_with(name, "_point_many") || ends_with(name, "_many") ||
           ends_with(name, "_deriv") || ends_with(name, "_ders");
}

/* The role of one declared parameter (whitespace already collapsed);
** prev is the role of the one before. */
static enum role
classify(const char *decl, enum role prev, int *is_array)
{
    char name[64] = "";
    const char *e = decl + strlen(decl), *s;
    int ptr = strchr(decl, '*') != NULL || strchr(decl, '[') != NULL;
    int is_const = strncmp(decl, "const ", 6) == 0;
    size_t n;
    if (strchr(decl, '[') != NULL)
        e = strchr(decl, '[');
    while (e > decl && !(isalnum((unsigned char)e[-1]) || e[-1] == '_'))
        e--;
    s = e;
    while (s > decl && (isalnum((unsigned char)s[-1]) || s[-1] == '_'))
        s--;
    n = (size_t)(e - s) < sizeof name - 1 ? (size_t)(e - s) : sizeof name - 1;
    memcpy(name, s, n);
    name[n] = '\0';
    *is_array = 0;
    if (strstr(decl, "cf_diag_t") != NULL)
        return DIAG;
    /* a surface's (u, v), and its grid of parameters uv with counts nu, nv */
    if (strcmp(decl, "double v") == 0 && prev == PARAM)
        return PARAM;
    if (strcmp(decl, "const double *uv") == 0) {
        *is_array = 1;
        return PARAM;
    }
    if ((prev == PARAM || prev == COUNT) &&
        (strcmp(decl, "size_t nu") == 0 || strcmp(decl, "size_t nv") == 0))
        return COUNT;
    if (strcmp(name, "t") == 0 || strcmp(name, "u") == 0) {
        if (strcmp(decl, "double t") == 0 || strcmp(decl, "double u") == 0)
            return PARAM;
        if (strcmp(decl, "const double *t") == 0 ||
            strcmp(decl, "const double *u") == 0) {
            *is_array = 1;
            return PARAM;
        }
    }
    if (prev == PARAM && strcmp(decl, "size_t n") == 0)
        return COUNT;
    if (strcmp(decl, "int k") == 0 || strcmp(decl, "double d") == 0)
        return NUMBER;
    if (ptr && !is_const)
        return OUTPUT;
    return OBJ;
}

/*
** Check one declaration "ret name(params)" against the rule; returns the
** number of violations (printed).  *checked counts evaluators.
*/
static int
check_decl(const char *decl, const char *where, int *checked)
{
    char name[128], params[1024], one[256];
    const char *open = strchr(decl, '('), *s, *close;
    enum role roles[32], prev = OBJ;
    int arrays[32], np = 0, bad = 0, seen_param = 0;
    size_t n;
    if (open == NULL)
        return 0;
    s = open;
    while (s > decl && (s[-1] == ' '))
        s--;
    n = 0;
    while (s > decl && (isalnum((unsigned char)s[-1]) || s[-1] == '_'))
        s--, n++;
    if (n == 0 || n >= sizeof name)
        return 0;
    memcpy(name, s, n);
    name[n] = '\0';
    if (!is_evaluator(name))
        return 0;
    close = strrchr(decl, ')');
    if (close == NULL || (size_t)(close - open) >= sizeof params)
        return 0;
    memcpy(params, open + 1, (size_t)(close - open - 1));
    params[close - open - 1] = '\0';
    (*checked)++;
    for (char *p = params; *p != '\0' && np < 32;) {
        char *comma = strchr(p, ',');
        size_t len = comma ? (size_t)(comma - p) : strlen(p);
        size_t o = 0;
        int space = 0;
        /* whitespace collapsed to single spaces, trimmed */
        for (size_t i = 0; i < len && o < sizeof one - 2; i++) {
            if (isspace((unsigned char)p[i])) {
                space = o > 0;
                continue;
            }
            if (space)
                one[o++] = ' ';
            space = 0;
            one[o++] = p[i];
        }
        one[o] = '\0';
        roles[np] = classify(one, prev, &arrays[np]);
        prev = roles[np];
        np++;
        p += len + (comma != NULL);
    }
    for (int i = 0; i < np; i++) {
        enum role r = roles[i];
        if (r == PARAM)
            seen_param = 1;
        if (r == NUMBER && !seen_param) {
            int later = 0;
            for (int j = i + 1; j < np; j++)
                later |= roles[j] == PARAM;
            if (later) {
                REPORT("%s: %s: %s comes before the parameter\n",
                            where, name, role_name[r]);
                bad++;
            }
        }
        if (r == PARAM && arrays[i] && (i + 1 >= np || roles[i + 1] != COUNT)) {
            REPORT("%s: %s: the parameter array is not followed by its "
                        "count\n", where, name);
            bad++;
        }
        if (i > 0 && roles[i - 1] == OUTPUT && r != OUTPUT && r != DIAG) {
            REPORT("%s: %s: %s after an output\n", where, name,
                        role_name[r]);
            bad++;
        }
        if ((r == OBJ) && seen_param) {
            REPORT("%s: %s: object argument after the parameter\n",
                        where, name);
            bad++;
        }
        if (r == DIAG && i != np - 1) {
            REPORT("%s: %s: the diag is not last\n", where, name);
            bad++;
        }
    }
    if (np == 0 || (roles[np - 1] != OUTPUT &&
                    !(roles[np - 1] == DIAG && np > 1 &&
                      roles[np - 2] == OUTPUT))) {
        REPORT("%s: %s: the output is not last (before the diag)\n",
                    where, name);
        bad++;
    }
    return bad;
}

/* Comments removed, in place. */
static void
strip_comments(char *text)
{
    char *w = text;
    for (char *r = text; *r != '\0';) {
        if (r[0] == '/' && r[1] == '*') {
            char *end = strstr(r + 2, "*/");
            r = end ? end + 2 : r + strlen(r);
            *w++ = ' ';
        } else if (r[0] == '/' && r[1] == '/') {
            while (*r != '\0' && *r != '\n')
                r++;
        } else {
            *w++ = *r++;
        }
    }
    *w = '\0';
}

/* Every CF_API declaration of one header text; returns violations. */
static int
check_text(char *text, const char *where, int *checked)
{
    int bad = 0;
    strip_comments(text);
    for (char *p = text; (p = strstr(p, "CF_API ")) != NULL;) {
        char decl[2048];
        char *end = strchr(p, ';');
        size_t len;
        if (end == NULL)
            break;
        len = (size_t)(end - p);
        if (len < sizeof decl) {
            memcpy(decl, p, len);
            decl[len] = '\0';
            bad += check_decl(decl, where, checked);
        }
        p = end;
    }
    return bad;
}

/* The checker itself: it accepts the rule and refuses each way of
** breaking it (the derivative order before the parameters among them). */
static void
test_checker(void **state)
{
    static const struct {
        const char *decl;
        int bad;
    } cases[] = {
        { "CF_API cf_status_t cf_x_eval_deriv_many(const cf_x_t *c, "
          "const double *t, size_t n, int k, double *out);", 0 },
        { "CF_API cf_status_t cf_x_eval_deriv_many(const cf_x_t *c, int k, "
          "const double *t, size_t n, double *out);", 1 },
        { "CF_API cf_status_t cf_x_eval_derivs(const cf_x_t *c, int k, "
          "double t, double *out);", 1 },
        { "CF_API cf_status_t cf_x_point_many(const cf_x_t *c, "
          "const double *t, double d, size_t n, double *out);", 1 },
        { "CF_API cf_status_t cf_x_eval(const cf_x_t *c, double *out, "
          "double t);", 1 },
        { "CF_API cf_status_t cf_x_ders(int p, const double *knots, "
          "size_t nknots, double u, int k, size_t *span, double *ders, "
          "cf_diag_t *diag);", 0 },
        { "CF_API cf_status_t cf_x_ders(int p, const double *knots, "
          "size_t nknots, double u, int k, cf_diag_t *diag, double *o);", 1 },
        { "CF_API cf_status_t cf_x_split(const cf_x_t *c, int k, double t, "
          "cf_x_t **out);", 0 },   /* not an evaluator */
    };
    (void)state;
    quiet = 1;
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        char text[512];
        int checked = 0, bad;
        snprintf(text, sizeof text, "%s", cases[i].decl);
        bad = check_text(text, "case", &checked);
        if ((bad != 0) != (cases[i].bad != 0))
            fail_msg("case %zu: %d violations, expected %s", i, bad,
                     cases[i].bad ? "some" : "none");
    }
    quiet = 0;
}

static void
test_public_headers(void **state)
{
    static const char *const headers[] = {
        "core.h", "knots.h", "bernstein.h", "bezier.h", "bspline.h",
        "geometry.h", "conic.h", "interp.h", "offset.h", "surface.h", "surface-make.h",
        "surface-triangle.h", "view.h", "visibility.h",
#ifdef CF_TEST_RENDER
        "figure.h", "style.h", "label.h", "output.h",
#endif
    };
    static char text[200000];
    int bad = 0, checked = 0;
    (void)state;
    for (size_t h = 0; h < sizeof headers / sizeof *headers; h++) {
        tu_read_header(CF_SOURCE_ROOT, headers[h], text, sizeof text);
        bad += check_text(text, headers[h], &checked);
    }
    /* the parser found the evaluators (eval, eval_many, eval_derivs,
    ** eval_deriv_many of both families, the offset points, Bernstein's,
    ** the basis derivatives, coons_eval) */
    if (checked < 15)
        fail_msg("only %d evaluators found in the headers", checked);
    if (bad != 0)
        fail_msg("%d violations of the argument order (core.h)", bad);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_checker),
        cmocka_unit_test(test_public_headers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
