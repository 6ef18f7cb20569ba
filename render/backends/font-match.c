/*
** fontconfig's match and trimmed sort over the tool's configuration,
** without fontconfig (render/backends/font-match.h).  The scores are
** FcCompare's, entry by entry in its order of priority (only the entries
** where the tool's fonts can differ: the others are equal for every
** font); the sort is qsort over the same comparison, as FcFontSetSort's.
*/
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "curvefig/core.h"
#include "font-match.h"
#include "sfnt.h"

#define MAX_LANGS 8
#define LANG_LEN 64
#define NO_MATCH 1e99

struct cf__fm_config {
    cf__fm_font_t *fonts;
    size_t nfonts;
    cf__fm_mapped_t *mapped;           /* the cache its views are of */
    char langs[MAX_LANGS][LANG_LEN];   /* fontconfig's default languages */
    size_t nlangs;
};

/* The scores FcCompare gives, in its order of priority. */
enum { S_FAMILY, S_LANG, S_SLANT, S_WEIGHT, S_WIDTH, S_DECORATIVE,
       S_VERSION, NSCORES };

typedef struct node {
    const cf__fm_font_t *font;
    double score[NSCORES];
} node_t;

/* A request as fontconfig's substituted pattern holds it. */
typedef struct request {
    const char *family;      /* the list, names split at commas */
    int slant;
    double weight;
    int size;
    char langs[MAX_LANGS + 1][LANG_LEN];
    size_t nlangs;
} request_t;

/* ---- fontconfig's default languages ------------------------------------ */

/* FcLangNormalize of tag into out (LANG_LEN); false when it gives none. */
static bool
normalise(const char *tag, char *out)
{
    char lt[LANG_LEN], mod[LANG_LEN] = "", s[3 * LANG_LEN], low[3 * LANG_LEN];
    const char *at = strchr(tag, '@');
    size_t n = at != NULL ? (size_t)(at - tag) : strlen(tag), llen, tlen = 0;
    char *dot, *terr;
    size_t i;
    if (*tag == '\0')
        return false;
    if (cf__fmeta_same_ci(tag, "C") || cf__fmeta_same_ci(tag, "C.UTF-8") || cf__fmeta_same_ci(tag, "C.utf8")
        || cf__fmeta_same_ci(tag, "POSIX")) {
        strcpy(out, "en");
        return true;
    }
    if (n >= LANG_LEN || (at != NULL && strlen(at + 1) >= LANG_LEN))
        return false;
    memcpy(lt, tag, n);
    lt[n] = '\0';
    if (at != NULL)
        strcpy(mod, at + 1);
    if ((dot = strchr(lt, '.')) != NULL)
        *dot = '\0';
    terr = strchr(lt, '_');
    if (terr == NULL)
        terr = strchr(lt, '-');
    if (terr != NULL) {
        *terr++ = '\0';
        tlen = strlen(terr);
    }
    llen = strlen(lt);
    if (llen < 2 || llen > 3)
        return false;
    if (terr != NULL && (tlen < 2 || tlen > 3) && !(terr[0] == 'z' && tlen < 5))
        return false;
    snprintf(s, sizeof s, "%s%s%s%s%s", lt, terr != NULL ? "-" : "",
             terr != NULL ? terr : "", at != NULL ? "@" : "", mod);
    for (i = 0; s[i] != '\0'; i++)
        low[i] = s[i] >= 'A' && s[i] <= 'Z' ? (char)(s[i] - 'A' + 'a') : s[i];
    low[i] = '\0';
    if (terr != NULL) {
        if (cf__flangs_find(s) >= 0)
            goto found;
        snprintf(s, sizeof s, "%s%s%s", lt, at != NULL ? "@" : "", mod);
    }
    if (at != NULL) {
        if (cf__flangs_find(s) >= 0)
            goto found;
        snprintf(s, sizeof s, "%s", lt);
    }
    if (cf__flangs_find(s) < 0) {
        if (strlen(low) >= LANG_LEN)
            return false;
        strcpy(out, low);
        return true;
    }
found:
    if (strlen(s) >= LANG_LEN)
        return false;
    strcpy(out, s);
    return true;
}

/* FcGetDefaultLangs: the first of FC_LANG, LC_ALL, LC_CTYPE, LANG set, a
** list split at colons, each normalised; "en" when none is left; false
** when there are more than this keeps. */
static bool
default_langs(cf__fm_config_t *c)
{
    static const char *const vars[] = { "FC_LANG", "LC_ALL", "LC_CTYPE",
                                        "LANG" };
    const char *v = NULL, *p;
    size_t i;
    c->nlangs = 0;
    for (i = 0; i < 4 && (v == NULL || *v == '\0'); i++)
        v = getenv(vars[i]);
    for (p = v; p != NULL && *p != '\0';) {
        const char *end = strchr(p, ':');
        size_t n = end != NULL ? (size_t)(end - p) : strlen(p), k;
        char item[128], norm[LANG_LEN];
        if (n > 127)
            n = 127;
        memcpy(item, p, n);
        item[n] = '\0';
        if (*item != '\0' && normalise(item, norm)) {
            for (k = 0; k < c->nlangs; k++)
                if (strcmp(c->langs[k], norm) == 0)
                    break;
            if (k == c->nlangs) {
                if (c->nlangs == MAX_LANGS)
                    return false;
                strcpy(c->langs[c->nlangs++], norm);
            }
        }
        p = end != NULL ? end + 1 : NULL;
    }
    if (c->nlangs == 0)
        strcpy(c->langs[c->nlangs++], "en");
    return true;
}

/* ---- the configuration -------------------------------------------------- */

bool
cf__fm_accepts(const cf__fmeta_t *m, const char *const *accept, size_t n)
{
    size_t i, k;
    for (i = 0; i < m->nfamily; i++)
        for (k = 0; k < n; k++)
            if (cf__fmeta_same_ci(m->family[i], accept[k]))
                return true;
    return false;
}

static void
free_fonts(cf__fm_font_t *fonts, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        cf_free(fonts[i].file);
        cf__fmeta_fini(&fonts[i].meta);
        free(fonts[i].reread);
    }
}

/* ---- charsets ----------------------------------------------------------- */

/* A font's charset as read: decoded ranges (w) or the cache's bytes (b),
** n pairs. */
typedef struct charset {
    const uint32_t *w;
    const unsigned char *b;
    size_t n;
} charset_t;

static inline uint32_t
cs_at(const charset_t *s, size_t i)
{
    return s->w != NULL ? s->w[i] : cf__fm_le32(s->b + 4 * i);
}

bool
cf__fm_ranges_valid(const unsigned char *p, size_t n)
{
    /* one test a range */
    int64_t last = -2;
    bool bad = false;
    size_t i;
    for (i = 0; i < n; i++) {
        uint32_t a = cf__fm_le32(p + 8 * i), b = cf__fm_le32(p + 8 * i + 4);
        bad |= (int64_t)a <= last + 1 || a > b || b > 0x10ffff;
        last = b;
    }
    return !bad;
}

/* The slow path of a view's first use, one thread at a time (the fonts'
** states are read without it once set). */
static pthread_mutex_t check_lock = PTHREAD_MUTEX_INITIALIZER;

/* A damaged view: the face's charset read again from its file, into the
** C library's heap (the configuration may outlive the library's
** allocator of the moment); none when the file cannot be read. */
static void
reread(cf__fm_font_t *f)
{
    void *map = NULL;
    size_t len = 0;
    int err;
    cf__fmeta_t m;
    char why[256];
    if (f->mapped != NULL && f->mapped->cache != NULL) {
        /* the next run writes the cache anew */
        (void)unlink(f->mapped->cache);
        free(f->mapped->cache);
        f->mapped->cache = NULL;
    }
    if (cf__ff_map_file(f->file, &map, &len, &err) != NULL)
        return;
    if (cf__fmeta_read(map, len, f->meta.index, &m, why, sizeof why) == 0) {
        if (m.nranges > 0
            && (f->reread = malloc(2 * m.nranges * sizeof *f->reread))
                   != NULL) {
            memcpy(f->reread, m.ranges, 2 * m.nranges * sizeof *f->reread);
            f->nreread = m.nranges;
        }
        cf__fmeta_fini(&m);
    }
    munmap(map, len);
}

/* Whether the font's file is the cache's: when the font was taken from
** the cache unseen (its directory unchanged), its size and time now are
** those the cache has. */
static bool
same_file(const cf__fm_font_t *f)
{
    struct stat st;
    if (!f->unverified)
        return true;
    return stat(f->file, &st) == 0 && (uint64_t)st.st_size == f->size
           && (int64_t)st.st_mtim.tv_sec == f->sec
           && (uint32_t)st.st_mtim.tv_nsec == f->nsec;
}

/* The font's charset, its view checked at its first use. */
static charset_t
charset_of(const cf__fm_font_t *cf)
{
    /* the state and the charset read again change once, under
    ** check_lock; the font is the configuration's (not const) */
    cf__fm_font_t *f = (cf__fm_font_t *)cf;
    charset_t s = { f->meta.ranges, NULL, f->meta.nranges };
    int state;
    if (f->view == NULL)
        return s;
    state = __atomic_load_n(&f->state, __ATOMIC_ACQUIRE);
    if (state == 0) {
        pthread_mutex_lock(&check_lock);
        state = f->state;
        if (state == 0) {
            state = same_file(f)
                            && cf__fm_ranges_valid(f->view, f->meta.nranges)
                        ? 1
                        : 2;
            if (state == 2)
                reread(f);
            __atomic_store_n(&f->state, state, __ATOMIC_RELEASE);
        }
        pthread_mutex_unlock(&check_lock);
    }
    if (state == 1) {
        s.w = NULL;
        s.b = f->view;
    } else {
        s.w = f->reread;
        s.n = f->nreread;
    }
    return s;
}

/* Whether s holds [a, b] whole. */
static bool
cs_holds(const charset_t *s, uint32_t a, uint32_t b)
{
    size_t lo = 0, hi = s->n;
    if (s->w != NULL)
        return cf__fmeta_ranges_hold(s->w, s->n, a, b);
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (a < cs_at(s, 2 * mid))
            hi = mid;
        else if (a > cs_at(s, 2 * mid + 1))
            lo = mid + 1;
        else
            return b <= cs_at(s, 2 * mid + 1);
    }
    return false;
}

void
cf__fm_font_verify(const cf__fm_font_t *f)
{
    (void)charset_of(f);
}

bool
cf__fm_font_has(const cf__fm_font_t *f, uint32_t c)
{
    charset_t s = charset_of(f);
    return cs_holds(&s, c, c);
}

size_t
cf__fm_font_nranges(const cf__fm_font_t *f)
{
    return charset_of(f).n;
}

bool
cf__fm_font_range(const cf__fm_font_t *f, size_t i, uint32_t *a,
                  uint32_t *b)
{
    charset_t s = charset_of(f);
    if (i >= s.n)
        return false;
    *a = cs_at(&s, 2 * i);
    *b = cs_at(&s, 2 * i + 1);
    return true;
}

void
cf__fm_mapped_free(cf__fm_mapped_t *m)
{
    /* made with its mapping (font-cache.c) */
    if (m != NULL) {
        munmap(m->map, m->len);
        free(m->cache);
        cf_free(m);
    }
}

void
cf__fm_config_keep(cf__fm_config_t *c, cf__fm_mapped_t *m)
{
    cf__fm_mapped_free(c->mapped);
    c->mapped = m;
}

int
cf__fm_config_of(cf__fm_font_t *fonts, size_t n, const char *const *accept,
                 size_t naccept, cf__fm_config_t **out, char *why,
                 size_t why_cap)
{
    cf__fm_config_t *c;
    size_t i, k = 0;
    *out = NULL;
    if (why != NULL && why_cap > 0)
        why[0] = '\0';
    c = cf_calloc(1, sizeof *c);
    if (c == NULL || (n > 0 && (c->fonts = cf_alloc_array(n, sizeof *c->fonts))
                                   == NULL)) {
        cf_free(c);
        free_fonts(fonts, n);
        return -1;
    }
    for (i = 0; i < n; i++) {
        if (!cf__fm_accepts(&fonts[i].meta, accept, naccept)) {
            free_fonts(&fonts[i], 1);
            continue;
        }
        c->fonts[k++] = fonts[i];
    }
    c->nfonts = k;
    for (i = 0; i < c->nfonts; i++)
        if (c->fonts[i].meta.has_size) {
            if (why != NULL)
                snprintf(why, why_cap, "%s: an optical size range",
                         c->fonts[i].file);
            cf__fm_config_free(c);
            return 1;
        }
    if (!default_langs(c)) {
        if (why != NULL)
            snprintf(why, why_cap, "more than %d default languages",
                     MAX_LANGS);
        cf__fm_config_free(c);
        return 1;
    }
    *out = c;
    return 0;
}

void
cf__fm_config_free(cf__fm_config_t *c)
{
    if (c == NULL)
        return;
    free_fonts(c->fonts, c->nfonts);
    cf_free(c->fonts);
    cf__fm_mapped_free(c->mapped);
    cf_free(c);
}

size_t
cf__fm_config_count(const cf__fm_config_t *c)
{
    return c->nfonts;
}

const cf__fm_font_t *
cf__fm_config_font(const cf__fm_config_t *c, size_t i)
{
    return i < c->nfonts ? &c->fonts[i] : NULL;
}

/* ---- scores ------------------------------------------------------------- */

/* The index of the first of the request's names the font has. */
static double
family_score(const char *list, const cf__fmeta_t *m)
{
    const char *f = list;
    int i = 0;
    while (true) {
        const char *comma = strchr(f, ',');
        size_t n = comma != NULL ? (size_t)(comma - f) : strlen(f), k;
        /* make_pattern drops a name of 256 bytes or more */
        if (n < 256) {
            for (k = 0; k < m->nfamily; k++)
                if (cf__fmeta_same_name(m->family[k], f, n))
                    return i;
            i++;
        }
        if (comma == NULL)
            return NO_MATCH;
        f = comma + 1;
    }
}

static void
score(const request_t *q, const cf__fm_font_t *font, node_t *out)
{
    const cf__fmeta_t *m = &font->meta;
    double best = NO_MATCH;
    size_t j;
    out->font = font;
    out->score[S_FAMILY] = family_score(q->family, m);
    for (j = 0; j < q->nlangs; j++) {
        double v = cf__flangs_has(&font->langs, q->langs[j]) * 1000.
                   + (double)j * 100;
        if (v < best)
            best = v;
    }
    out->score[S_LANG] = best;
    out->score[S_SLANT] = (m->slant > q->slant ? m->slant - q->slant
                                               : q->slant - m->slant) * 1000.;
    out->score[S_WEIGHT] = (m->weight > q->weight ? m->weight - q->weight
                                                  : q->weight - m->weight)
                           * 1000;
    out->score[S_WIDTH] = (m->width > 100 ? m->width - 100 : 100 - m->width)
                          * 1000;
    out->score[S_DECORATIVE] = m->decorative ? 1000 : 0;
    out->score[S_VERSION] = ((double)0x7fffffff - (double)m->fontversion)
                            * 1000;
}

static int
by_score(const void *pa, const void *pb)
{
    const node_t *a = *(node_t *const *)pa, *b = *(node_t *const *)pb;
    size_t i;
    for (i = 0; i < NSCORES; i++)
        if (a->score[i] != b->score[i])
            return a->score[i] < b->score[i] ? -1 : 1;
    return 0;
}

/* The request as fontconfig substitutes it: its language, then the
** default languages up to one it already holds. */
static void
request_of(const cf__fm_config_t *c, const char *family, bool italic,
           bool bold, int size, const char *lang, request_t *q)
{
    size_t i, k;
    q->family = family;
    q->slant = italic ? CF__FMETA_SLANT_ITALIC : CF__FMETA_SLANT_ROMAN;
    q->weight = bold ? 200 : 80;
    q->size = size;
    snprintf(q->langs[0], LANG_LEN, "%s", lang);
    q->nlangs = 1;
    for (i = 0; i < c->nlangs; i++) {
        for (k = 0; k < q->nlangs; k++)
            if (cf__fmeta_same_ci(q->langs[k], c->langs[i]) || cf__fmeta_same_ci(q->langs[k], "und"))
                return;
        strcpy(q->langs[q->nlangs++], c->langs[i]);
    }
}

/* ---- preparation -------------------------------------------------------- */

/* Which of the font's family names FcFontRenderPrepare puts first: the
** one whose language best fits the name language (then "en-us"). */
static size_t
first_family(const cf__fm_config_t *c, const cf__fmeta_t *m)
{
    const char *want[2];
    double best = NO_MATCH;
    size_t j, k, pos = 0;
    want[0] = c->langs[0];
    want[1] = "en-us";
    for (j = 0; j < 2; j++)
        for (k = 0; k < m->nfamily; k++) {
            /* a name without a language counts as "und" */
            const char *fl = m->familylang[k][0] ? m->familylang[k] : "und";
            double v = cf__flangs_compare(want[j], fl) * 1000.
                       + (double)j * 100 + (double)k;
            if (v < best) {
                best = v;
                pos = k;
            }
            if (best < 1000)
                return pos;
        }
    return pos;
}

static void
prepare(const cf__fm_config_t *c, const request_t *q,
        const cf__fm_font_t *font, cf__fm_face_t *out)
{
    static const char *const designs[] = {
        "LM Roman 5", "LM Roman 6", "LM Roman 7", "LM Roman 8",
        "LM Roman 9", "LM Roman 12", "LM Roman 17",
    };
    const cf__fmeta_t *m = &font->meta;
    size_t i, k;
    memset(out, 0, sizeof *out);
    out->font = font;
    out->family = m->family[first_family(c, m)];
    for (i = 0; i < sizeof designs / sizeof designs[0]; i++)
        for (k = 0; k < m->nfamily; k++)
            if (cf__fmeta_same_ci(m->family[k], designs[i]))
                out->family = designs[i];
    out->slant = m->slant;
    out->weight = m->weight;
    out->width = m->width;
    if (m->slant == CF__FMETA_SLANT_ROMAN && q->slant != CF__FMETA_SLANT_ROMAN) {
        out->sheared = true;
        out->slant = CF__FMETA_SLANT_OBLIQUE;
    }
    if (m->weight <= 100 && q->weight >= 200) {
        out->embolden = true;
        out->weight = 200;
    }
    out->dpi = 72.;
    out->pixel_size = q->size / 1024.;
    /* FcDefaultSubstitute's point size from the pixel size */
    out->size = out->pixel_size / out->dpi * 72.0 / 1.0;
}

int
cf__fm_match(const cf__fm_config_t *c, const char *family, bool italic,
             bool bold, int size, const char *lang, cf__fm_face_t *out)
{
    request_t q;
    node_t best, cur;
    size_t i;
    const node_t *pb = &best, *pc = &cur;
    if (c->nfonts == 0)
        return 1;
    request_of(c, family, italic, bold, size, lang, &q);
    score(&q, &c->fonts[0], &best);
    for (i = 1; i < c->nfonts; i++) {
        score(&q, &c->fonts[i], &cur);
        if (by_score(&pc, &pb) < 0)
            best = cur;
    }
    prepare(c, &q, best.font, out);
    return 0;
}

/* The union of characters so far (ranges, ascending, maximal). */
typedef struct cover {
    uint32_t *r;
    size_t n, cap;
} cover_t;

/* Merge the font's ranges into u; whether it added characters (-1 out of
** memory). */
static int
merge(cover_t *u, const cf__fm_font_t *font)
{
    charset_t s = charset_of(font);
    size_t i = 0, j = 0, n = 0, need = u->n + s.n;
    uint32_t *t;
    bool adds = false;
    for (j = 0; j < s.n && !adds; j++)
        adds = !cf__fmeta_ranges_hold(u->r, u->n, cs_at(&s, 2 * j),
                                      cs_at(&s, 2 * j + 1));
    if (!adds)
        return 0;
    t = cf_alloc_array(2 * need, sizeof *t);
    if (t == NULL)
        return -1;
    j = 0;
    while (i < u->n || j < s.n) {
        uint32_t a, b;
        if (j == s.n || (i < u->n && u->r[2 * i] < cs_at(&s, 2 * j))) {
            a = u->r[2 * i];
            b = u->r[2 * i + 1];
            i++;
        } else {
            a = cs_at(&s, 2 * j);
            b = cs_at(&s, 2 * j + 1);
            j++;
        }
        if (n > 0 && a <= t[2 * n - 1] + 1) {
            if (b > t[2 * n - 1])
                t[2 * n - 1] = b;
        } else {
            t[2 * n] = a;
            t[2 * n + 1] = b;
            n++;
        }
    }
    cf_free(u->r);
    u->r = t;
    u->n = n;
    u->cap = need;
    return 1;
}

int
cf__fm_sort(const cf__fm_config_t *c, const char *family, bool italic,
            bool bold, int size, const char *lang, cf__fm_face_t **out,
            size_t *n)
{
    request_t q;
    node_t *nodes;
    node_t **order;
    cf__fm_face_t *faces;
    bool sat[MAX_LANGS + 1] = { false };
    cover_t u = { NULL, 0, 0 };
    size_t i, j, k = 0;
    *out = NULL;
    *n = 0;
    request_of(c, family, italic, bold, size, lang, &q);
    nodes = cf_alloc_array(c->nfonts + 1, sizeof *nodes);
    order = cf_alloc_array(c->nfonts + 1, sizeof *order);
    faces = cf_alloc_array(c->nfonts + 1, sizeof *faces);
    if (nodes == NULL || order == NULL || faces == NULL) {
        cf_free(nodes);
        cf_free(order);
        cf_free(faces);
        return -1;
    }
    for (i = 0; i < c->nfonts; i++) {
        score(&q, &c->fonts[i], &nodes[i]);
        order[i] = &nodes[i];
    }
    qsort(order, c->nfonts, sizeof *order, by_score);
    /* each of the request's languages is kept by the first font that
    ** has it; the others lose their language score */
    for (i = 0; i < c->nfonts; i++) {
        bool satisfies = false;
        if (order[i]->score[S_LANG] < 2000)
            for (j = 0; j < q.nlangs; j++)
                if (!sat[j]
                    && cf__flangs_has(&order[i]->font->langs, q.langs[j]) < 2) {
                    sat[j] = satisfies = true;
                    break;
                }
        if (!satisfies)
            order[i]->score[S_LANG] = 10000;
    }
    qsort(order, c->nfonts, sizeof *order, by_score);
    for (i = 0; i < c->nfonts; i++) {
        int adds = merge(&u, order[i]->font);
        if (adds < 0) {
            cf_free(u.r);
            cf_free(nodes);
            cf_free(order);
            cf_free(faces);
            return -1;
        }
        if (i == 0 || adds)
            prepare(c, &q, order[i]->font, &faces[k++]);
    }
    cf_free(u.r);
    cf_free(nodes);
    cf_free(order);
    *out = faces;
    *n = k;
    return 0;
}
