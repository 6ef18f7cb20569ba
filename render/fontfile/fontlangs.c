/*
** A face's languages (render/fontfile/fontlangs.h): fontconfig's
** orthographies tested against the face's charset, and fontconfig's
** comparison of a requested language with a set of them.
*/
#include <stdbool.h>
#include <string.h>

#include "fontlangs.h"

typedef struct lang_set {
    const char *name;
    unsigned pages;       /* 256-character pages of its charset */
    unsigned first;       /* its ranges: lang_ranges[2 * first ...] */
    unsigned count;
} lang_set_t;

#include "langs-table.h"

#define NLANGS (sizeof lang_sets / sizeof lang_sets[0])

size_t
cf__flangs_count(void)
{
    return NLANGS;
}

const char *
cf__flangs_name(size_t i)
{
    return i < NLANGS ? lang_sets[i].name : NULL;
}

static char
lower(char c)
{
    return c >= 'A' && c <= 'Z' ? (char)(c - 'A' + 'a') : c;
}

static bool
lang_end(char c)
{
    return c == '-' || c == '\0';
}

/* fontconfig's FcLangCompare: 0 equal, 1 another territory, 2 another
** language. */
static int
lang_compare(const char *s1, const char *s2)
{
    const char *orig = s1;
    int result = 2;
    bool und = lower(s1[0]) == 'u' && lower(s1[1]) == 'n'
               && lower(s1[2]) == 'd' && lang_end(s1[3]);
    while (true) {
        char c1 = lower(*s1++), c2 = lower(*s2++);
        if (c1 != c2) {
            if (!und && lang_end(c1) && lang_end(c2))
                result = 1;
            return result;
        }
        if (c1 == '\0')
            return und ? result : 0;
        if (c1 == '-' && !und)
            result = 1;
        if (und && s1 - orig == 4)
            und = false;
    }
}

/* fontconfig's exclusive languages: OS/2 code page bits 17..20. */
static const char *const exclusive[] = { "ja", "zh-cn", "ko", "zh-tw" };

static bool
is_exclusive(const char *lang)
{
    size_t i;
    for (i = 0; i < 4; i++)
        if (lang_compare(lang, exclusive[i]) == 0)
            return true;
    return false;
}

static int
index_of(const char *lang)
{
    size_t i;
    for (i = 0; i < NLANGS; i++)
        if (strcmp(lang_sets[i].name, lang) == 0)
            return (int)i;
    return -1;
}

void
cf__flangs_of(const cf__fmeta_t *m, cf__flangset_t *out)
{
    const char *excl = NULL;
    int excl_pages = -1;
    size_t i, k;
    memset(out, 0, sizeof *out);
    if (m->has_codepages)
        for (i = 0; i < 4; i++)
            if (m->codepages[0] >> (17 + i) & 1) {
                if (excl != NULL) {
                    excl = NULL;
                    break;
                }
                excl = exclusive[i];
            }
    if (excl != NULL) {
        int e = index_of(excl);
        excl_pages = e >= 0 ? (int)lang_sets[e].pages : -1;
    }
    for (i = 0; i < NLANGS; i++) {
        const lang_set_t *l = &lang_sets[i];
        bool all = true;
        if (excl_pages >= 0 && is_exclusive(l->name)
            && (int)l->pages != excl_pages)
            continue;
        for (k = 0; k < l->count && all; k++)
            all = cf__fmeta_ranges_hold(m->ranges, m->nranges,
                                        lang_ranges[2 * (l->first + k)],
                                        lang_ranges[2 * (l->first + k) + 1]);
        if (all)
            out->bits[i / 32] |= 1u << (i % 32);
    }
}

static bool
has_bit(const cf__flangset_t *ls, size_t i)
{
    return ls->bits[i / 32] >> (i % 32) & 1;
}

/* Where lang is among the sorted names, or would be (fontconfig's
** FcLangSetIndex: >= 0 found, else -(position + 1)). */
static int
position(const char *lang)
{
    size_t lo = 0, hi = NLANGS;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        const char *a = lang_sets[mid].name, *b = lang;
        int c;
        while (*a != '\0' && lower(*a) == lower(*b)) {
            a++;
            b++;
        }
        c = (unsigned char)lower(*a) - (unsigned char)lower(*b);
        if (c == 0)
            return (int)mid;
        if (c < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return -(int)lo - 1;
}

int
cf__flangs_compare(const char *a, const char *b)
{
    return lang_compare(a, b);
}

int
cf__flangs_find(const char *lang)
{
    int id = position(lang);
    return id >= 0 ? id : -1;
}

int
cf__flangs_has(const cf__flangset_t *ls, const char *lang)
{
    int id = position(lang), best = 2, r, i;
    if (id < 0)
        id = -id - 1;
    else if (has_bit(ls, (size_t)id))
        return 0;
    for (i = id - 1; i >= 0; i--) {
        r = lang_compare(lang, lang_sets[i].name);
        if (r == 2)
            break;
        if (has_bit(ls, (size_t)i) && r < best)
            best = r;
    }
    for (i = id; i < (int)NLANGS; i++) {
        r = lang_compare(lang, lang_sets[i].name);
        if (r == 2)
            break;
        if (has_bit(ls, (size_t)i) && r < best)
            best = r;
    }
    return best;
}
