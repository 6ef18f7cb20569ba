/*
** Generated bad inputs: every key of every table the figure language takes
** and every name of every enumerated value, as the binding lists them
** (render/lua/lkeys.c, read through cf__lua_schema_at), misspelt in a call
** of its function built from the schema's example.  Each script must fail
** with the misspelt name, the nearest valid one and the script's line:
**
**   misspelt.lua:5: bspline: unknown field 'knts' (did you mean 'knots'?)
**   misspelt.lua:5: interpolate: method "natral" is unknown (did you mean
**   "natural"?)
**
** A key added to a schema is covered the day it is added.  The
** misspellings: the last letter dropped, two letters swapped, the first
** doubled, a letter put in front or
** after; one counts when no valid name is as near
** to it as the one misspelt (by this file's own edit distance), and every
** name must get at least one.
**
** usage: misspelt [-v]
*/
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lschema.h"
#include "script.h"

#define MAX 128

static int failures, cases;
static bool verbose;
static FILE *sink;

/* Levenshtein distance with adjacent transpositions, written apart from
** the binding's so that the two check each other. */
static int
distance(const char *a, const char *b)
{
    int d[MAX + 1][MAX + 1];
    int n = (int)strlen(a), m = (int)strlen(b);
    for (int i = 0; i <= n; i++)
        d[i][0] = i;
    for (int j = 0; j <= m; j++)
        d[0][j] = j;
    for (int i = 1; i <= n; i++)
        for (int j = 1; j <= m; j++) {
            int best = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
            if (d[i - 1][j] + 1 < best)
                best = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < best)
                best = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] &&
                a[i - 2] == b[j - 1] && d[i - 2][j - 2] + 1 < best)
                best = d[i - 2][j - 2] + 1;
            d[i][j] = best;
        }
    return d[n][m];
}

/* True when name is the one nearest to v among names (strictly) and v is
** not itself a name. */
static bool
uniquely_nearest(const char *v, const char *name, const char *const *names,
                 size_t n)
{
    int dn = distance(v, name);
    if (dn == 0)
        return false;
    for (size_t i = 0; i < n; i++)
        if (strcmp(names[i], name) != 0 && distance(v, names[i]) <= dn)
            return false;
    return true;
}

static size_t
variants(const char *name, char out[5][MAX])
{
    size_t len = strlen(name), n = 0;
    if (len >= 3) {
        snprintf(out[n], MAX, "%.*s", (int)len - 1, name);
        n++;
    }
    if (len >= 4) {
        snprintf(out[n], MAX, "%s", name);
        out[n][len / 2] = name[len / 2 - 1];
        out[n][len / 2 - 1] = name[len / 2];
        n++;
    }
    snprintf(out[n++], MAX, "%c%s", name[0], name);
    snprintf(out[n++], MAX, "q%s", name);
    snprintf(out[n++], MAX, "%sq", name);
    return n;
}

/* Run prelude + the example with table in place of its %s; the error must
** contain each of the fragments. */
static void
run_case(const cf__lua_schema_t *s, const char *table, const char *want)
{
    char code[4096], where[64];
    const char *at = strstr(s->example, "%s");
    cf_script_t *sc = NULL;
    cf_diag_t diag;
    const char *err;
    int lines = 1;
    for (const char *p = cf__lua_schema_prelude; *p; p++)
        lines += *p == '\n';
    snprintf(code, sizeof code, "%s%.*s%s%s\n", cf__lua_schema_prelude,
             (int)(at - s->example), s->example, table, at + 2);
    snprintf(where, sizeof where, "misspelt.lua:%d: ", lines);
    cf_diag_clear(&diag);
    if (cf_script_create(NULL, sink, &sc, &diag) != CF_STATUS_OK) {
        fprintf(stderr, "FAIL cannot create a script: %s\n", diag.msg);
        exit(1);
    }
    cases++;
    err = cf_script_run_string(sc, code, "misspelt.lua") == CF_STATUS_OK
              ? "(no error)"
              : cf_script_error(sc);
    if (strstr(err, where) == NULL || strstr(err, s->fn) == NULL ||
        strstr(err, want) == NULL) {
        failures++;
        fprintf(stderr, "FAIL %s\n     script: %s     expected: %s%s: ... "
                "%s\n     got: %s\n", s->fn, code + strlen(
                    cf__lua_schema_prelude), where, s->fn, want, err);
    } else if (verbose) {
        printf("ok   %.*s\n", (int)strcspn(err, "\n"), err);
    }
    cf_script_destroy(sc);
}

static size_t
all_keys(const cf__lua_schema_t *s, const char **names, size_t cap)
{
    size_t n = 0;
    for (int l = 0; l < CF__LUA_KEY_LISTS; l++)
        for (const cf__lua_key_t *k = s->keys[l]; k && k->name; k++)
            if (n < cap)
                names[n++] = k->name;
    for (const cf__lua_key_t *k = s->elsewhere; k && k->name; k++)
        if (n < cap)
            names[n++] = k->name;
    return n;
}

static void
misspell_key(const cf__lua_schema_t *s, const char *key)
{
    const char *names[256];
    size_t n = all_keys(s, names, 256), nv, used = 0;
    char v[5][MAX], table[MAX * 2], want[MAX * 3];
    nv = variants(key, v);
    for (size_t i = 0; i < nv; i++) {
        if (!uniquely_nearest(v[i], key, names, n))
            continue;
        snprintf(table, sizeof table, "{ [\"%s\"] = 1 }", v[i]);
        snprintf(want, sizeof want, "unknown %s '%s' (did you mean '%s'?)",
                 s->noun, v[i], key);
        run_case(s, table, want);
        used++;
    }
    if (used == 0) {
        failures++;
        fprintf(stderr, "FAIL %s: no misspelling of '%s' is nearest to it\n",
                s->fn, key);
    }
}

static void
misspell_value(const cf__lua_schema_t *s, const cf__lua_key_t *k,
               const char *value)
{
    size_t n = 0, nv, used = 0;
    char v[5][MAX], table[MAX * 2], want[MAX * 3];
    while (k->values[n] != NULL)
        n++;
    nv = variants(value, v);
    for (size_t i = 0; i < nv; i++) {
        if (!uniquely_nearest(v[i], value, k->values, n))
            continue;
        snprintf(table, sizeof table, "{ %s = '%s' }", k->name, v[i]);
        snprintf(want, sizeof want, "%s \"%s\" is unknown (did you mean "
                 "\"%s\"?)", k->name, v[i], value);
        run_case(s, table, want);
        used++;
    }
    if (used == 0) {
        failures++;
        fprintf(stderr, "FAIL %s: no misspelling of %s \"%s\" is nearest to "
                "it\n", s->fn, k->name, value);
    }
}

int
main(int argc, char **argv)
{
    size_t keys = 0, names = 0;
    verbose = argc > 1 && strcmp(argv[1], "-v") == 0;
    sink = fopen("/dev/null", "w");
    for (int i = 1; i < CF__KEYS_COUNT_; i++) {
        const cf__lua_schema_t *s = cf__lua_schema_at((cf__lua_keys_t)i);
        if (s->example == NULL || strstr(s->example, "%s") == NULL) {
            failures++;
            fprintf(stderr, "FAIL schema %s has no example call\n", s->fn);
            continue;
        }
        for (int l = 0; l < CF__LUA_KEY_LISTS; l++)
            for (const cf__lua_key_t *k = s->keys[l]; k && k->name; k++) {
                misspell_key(s, k->name);
                keys++;
                for (size_t j = 0; k->values && k->values[j]; j++) {
                    misspell_value(s, k, k->values[j]);
                    names++;
                }
            }
    }
    printf("%d generated cases (%zu keys and %zu names of %d tables), %d "
           "failed\n", cases, keys, names, CF__KEYS_COUNT_ - 1, failures);
    fclose(sink);
    return failures == 0 ? 0 : 1;
}
