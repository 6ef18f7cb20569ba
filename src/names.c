/*
** The nearest name, for the "did you mean" of every message that names
** an unknown key, method, command, format or option (include/curvefig/
** core.h).
*/
#include <stdbool.h>
#include <string.h>

#include "core-private.h"

#define MAX_NAME 100  /* longer names are compared as "far" */

/* Damerau-Levenshtein distance (adjacent transpositions count one),
** capped at MAX_NAME. */
static int
name_distance(const char *a, const char *b)
{
    /* three rows of the optimal-string-alignment table */
    int rows[3][MAX_NAME + 1];
    size_t n = strlen(a), m = strlen(b);
    if (n > MAX_NAME || m > MAX_NAME)
        return MAX_NAME;
    for (size_t j = 0; j <= m; j++)
        rows[0][j] = (int)j;
    for (size_t i = 1; i <= n; i++) {
        int *cur = rows[i % 3], *prev = rows[(i - 1) % 3];
        int *prev2 = rows[(i + 1) % 3];
        cur[0] = (int)i;
        for (size_t j = 1; j <= m; j++) {
            int cost = a[i - 1] != b[j - 1];
            int v = prev[j] + 1;
            if (cur[j - 1] + 1 < v)
                v = cur[j - 1] + 1;
            if (prev[j - 1] + cost < v)
                v = prev[j - 1] + cost;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] &&
                a[i - 2] == b[j - 1] && prev2[j - 2] + 1 < v)
                v = prev2[j - 2] + 1;
            cur[j] = v;
        }
    }
    return rows[n % 3][m];
}

/* Whether name is a word of s: s contains it between '_', '-' or its ends
** (degree_elevate holds degree and elevate, output-dir holds output). */
static bool
word_of(const char *s, const char *name)
{
    size_t n = strlen(name);
    const char *p = s;
    if (n < 3)
        return false;
    while ((p = strstr(p, name)) != NULL) {
        if ((p == s || p[-1] == '_' || p[-1] == '-')
            && (p[n] == '\0' || p[n] == '_' || p[n] == '-'))
            return true;
        p++;
    }
    return false;
}

const char *
cf_nearest_name(const char *s, const char *const *names, size_t n)
{
    const char *best = NULL, *word = NULL;
    int bestd = MAX_NAME + 1;
    size_t len = strlen(s);
    int limit = len / 3 > 1 ? (int)(len / 3) : 1;
    for (size_t i = 0; i < n; i++) {
        int d = name_distance(s, names[i]);
        if (d < bestd) {
            bestd = d;
            best = names[i];
        }
        if (word_of(s, names[i])
            && (word == NULL || strlen(names[i]) > strlen(word)))
            word = names[i];   /* the longest: elevate, not degree */
    }
    return bestd <= limit ? best : word;
}
