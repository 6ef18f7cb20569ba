/*
** The palette of an animated GIF (anim-gif.c), chosen for the figure over
** every frame's pixels, and pixels mapped to it; see anim-gif.c's head
** for the method.  The counts: exactly for the first EXACT_MAX distinct
** colours, and in BINS bins of 5 bits per channel (pixels and the sums of
** their channels) for all.
*/
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "anim-private.h"

#define EXACT_MAX 4096          /* distinct colours counted exactly */
#define EXACT_SLOTS 8192        /* their hash table (load <= 1/2) */
#define BINS 32768              /* 5 bits per channel */
#define FLAT_MAX 64             /* flat colours kept exact, at most */
#define FLAT_SHARE 20000        /* ... each on >= 1/FLAT_SHARE of pixels */
#define MAP_SLOTS 65536         /* the colour -> index cache */

/* ---- counting the colours ----------------------------------------------- */

static uint32_t
hash32(uint32_t key, uint32_t mask)
{
    return (key * 2654435761u >> 13) & mask;
}

int
cf__colours_init(cf__colours_t *c)
{
    memset(c, 0, sizeof *c);
    c->key = cf_calloc(EXACT_SLOTS, sizeof *c->key);
    c->count = cf_calloc(EXACT_SLOTS, sizeof *c->count);
    c->bin = cf_calloc(BINS, sizeof *c->bin);
    return c->key != NULL && c->count != NULL && c->bin != NULL ? 0 : -1;
}

void
cf__colours_fini(cf__colours_t *c)
{
    cf_free(c->key);
    cf_free(c->count);
    cf_free(c->bin);
    memset(c, 0, sizeof *c);
}

void
cf__colours_add(cf__colours_t *g, uint32_t rgb, uint64_t n)
{
    uint32_t key = rgb | 1u << 24, i = hash32(key, EXACT_SLOTS - 1);
    uint64_t *b = g->bin[(rgb >> 9 & 0x7c00) | (rgb >> 6 & 0x3e0)
                         | (rgb >> 3 & 0x1f)];
    b[0] += n;
    b[1] += n * (rgb >> 16);
    b[2] += n * (rgb >> 8 & 0xff);
    b[3] += n * (rgb & 0xff);
    g->opaque += n;
    while (g->key[i] != 0 && g->key[i] != key)
        i = (i + 1) & (EXACT_SLOTS - 1);
    if (g->key[i] == key) {
        g->count[i] += n;
    } else if (g->distinct < EXACT_MAX) {
        g->key[i] = key;
        g->count[i] = n;
        g->distinct++;
    } else {
        g->many = true;
    }
}

/* ---- the palette -------------------------------------------------------- */

typedef struct colour {
    double c[3];                /* mean colour */
    uint64_t w;                 /* pixels */
    uint32_t rgb;               /* the colour itself (exact colours) */
} colour_t;

static int
cmp_count(const void *a, const void *b)
{
    const colour_t *p = a, *q = b;
    if (p->w != q->w)
        return p->w > q->w ? -1 : 1;
    return p->rgb < q->rgb ? -1 : p->rgb > q->rgb;
}

/* Bins ordered along one channel, ties by the others. */
static int
cmp_axis(const colour_t *p, const colour_t *q, int a)
{
    for (int i = 0; i < 3; i++) {
        int c = (a + i) % 3;
        if (p->c[c] != q->c[c])
            return p->c[c] < q->c[c] ? -1 : 1;
    }
    return 0;
}

static int cmp_r(const void *a, const void *b) { return cmp_axis(a, b, 0); }
static int cmp_g(const void *a, const void *b) { return cmp_axis(a, b, 1); }
static int cmp_b(const void *a, const void *b) { return cmp_axis(a, b, 2); }

/* A box of median cut.  The box split next is the one of the largest
** side^2 x sqrt(pixels): an anti-aliased blend far from the other colours
** gets its own entry sooner than by pixels alone (a 60-frame figure of
** 301 x 201 pixels: largest channel error 19 instead of 39 of 255, mean
** 0.074 instead of 0.069). */
typedef struct box {
    size_t lo, hi;              /* bins [lo, hi) */
    int axis;                   /* its longest side */
    double score;               /* 0: unsplittable */
} box_t;

static void
box_measure(const colour_t *c, box_t *b)
{
    double mn[3] = { 256, 256, 256 }, mx[3] = { -1, -1, -1 }, side = -1;
    uint64_t w = 0;
    for (size_t i = b->lo; i < b->hi; i++) {
        for (int a = 0; a < 3; a++) {
            mn[a] = fmin(mn[a], c[i].c[a]);
            mx[a] = fmax(mx[a], c[i].c[a]);
        }
        w += c[i].w;
    }
    for (int a = 0; a < 3; a++) {
        if (mx[a] - mn[a] > side) {
            side = mx[a] - mn[a];
            b->axis = a;
        }
    }
    b->score = b->hi - b->lo > 1 ? side * side * sqrt((double)w) : 0;
}

/* Median cut of the bins c[0..n) into at most m boxes; their weighted
** means appended to pal; the number of colours added. */
static int
median_cut(colour_t *c, size_t n, int m, box_t *box, uint32_t *pal)
{
    static int (*const cmp[3])(const void *, const void *) = {
        cmp_r, cmp_g, cmp_b
    };
    int nb = 0;
    if (n == 0 || m < 1)
        return 0;
    box[nb].lo = 0;
    box[nb].hi = n;
    box_measure(c, &box[nb++]);
    while (nb < m) {
        int best = 0;
        uint64_t total = 0, acc = 0;
        size_t cut;
        box_t *b;
        for (int i = 1; i < nb; i++)
            if (box[i].score > box[best].score)
                best = i;
        b = &box[best];
        if (b->score <= 0)
            break;
        qsort(c + b->lo, b->hi - b->lo, sizeof *c, cmp[b->axis]);
        for (size_t i = b->lo; i < b->hi; i++)
            total += c[i].w;
        /* the first bin past half the pixels starts the second half; both
        ** halves hold a bin: lo < cut < hi */
        for (cut = b->lo + 1; cut < b->hi - 1; cut++) {
            acc += c[cut - 1].w;
            if (2 * acc >= total)
                break;
        }
        box[nb].lo = cut;
        box[nb].hi = b->hi;
        b->hi = cut;
        box_measure(c, b);
        box_measure(c, &box[nb++]);
    }
    for (int i = 0; i < nb; i++) {
        double s[3] = { 0, 0, 0 }, w = 0;
        uint32_t v = 0;
        for (size_t j = box[i].lo; j < box[i].hi; j++) {
            for (int a = 0; a < 3; a++)
                s[a] += c[j].c[a] * (double)c[j].w;
            w += (double)c[j].w;
        }
        for (int a = 0; a < 3; a++)
            v = v << 8 | (uint32_t)lround(fmin(255, fmax(0, s[a] / w)));
        pal[i] = v;
    }
    return nb;
}

int
cf__colours_palette(cf__colours_t *g, uint32_t pal[256])
{
    int room = g->clear > 0 ? 255 : 256, n = 0, flat = 0;
    colour_t *c = cf_alloc_array(BINS > EXACT_MAX ? BINS : EXACT_MAX,
                                 sizeof *c);
    box_t *box = cf_alloc_array(256, sizeof *box);
    size_t nb = 0;
    if (c == NULL || box == NULL) {
        cf_free(c);
        cf_free(box);
        return -1;
    }
    for (size_t i = 0; i < EXACT_SLOTS; i++) {
        if (g->key[i] != 0) {
            c[n].rgb = g->key[i] & 0xffffff;
            c[n++].w = g->count[i];
        }
    }
    qsort(c, (size_t)n, sizeof *c, cmp_count);
    if (!g->many && n <= room) {
        for (int i = 0; i < n; i++)
            pal[i] = c[i].rgb;
        cf_free(c);
        cf_free(box);
        return n;
    }
    /* the flat colours, taken out of their bins */
    while (flat < n && flat < FLAT_MAX
           && c[flat].w * FLAT_SHARE >= g->opaque) {
        uint32_t v = c[flat].rgb;
        uint64_t *b = g->bin[(v >> 9 & 0x7c00) | (v >> 6 & 0x3e0)
                             | (v >> 3 & 0x1f)];
        b[0] -= c[flat].w;
        b[1] -= c[flat].w * (v >> 16);
        b[2] -= c[flat].w * (v >> 8 & 0xff);
        b[3] -= c[flat].w * (v & 0xff);
        pal[flat] = v;
        flat++;
    }
    for (size_t i = 0; i < BINS; i++) {
        const uint64_t *b = g->bin[i];
        if (b[0] == 0)
            continue;
        for (int a = 0; a < 3; a++)
            c[nb].c[a] = (double)b[a + 1] / (double)b[0];
        c[nb].w = b[0];
        c[nb++].rgb = (uint32_t)i;
    }
    n = flat + median_cut(c, nb, room - flat, box, pal + flat);
    cf_free(c);
    cf_free(box);
    return n;
}

/* ---- pixels to palette indices ------------------------------------------ */

static unsigned char
nearest(const cf__palette_map_t *m, uint32_t rgb)
{
    long best = -1;
    int bi = 0;
    for (int i = 0; i < m->n; i++) {
        long d = 0;
        for (int s = 0; s < 24; s += 8) {
            long e = (long)(rgb >> s & 0xff) - (long)(m->pal[i] >> s & 0xff);
            d += e * e;
        }
        if (best < 0 || d < best) {
            best = d;
            bi = i;
        }
    }
    return (unsigned char)bi;
}

void
cf__palette_map(cf__palette_map_t *m, const unsigned char *rgba, size_t n,
                unsigned char *out)
{
    uint32_t last = 0;
    unsigned char li = 0;
    for (size_t i = 0; i < n; i++, rgba += 4) {
        uint32_t key, h;
        if (rgba[3] == 0) {
            out[i] = (unsigned char)m->n;
            continue;
        }
        key = (uint32_t)rgba[0] << 16 | (uint32_t)rgba[1] << 8 | rgba[2]
            | 1u << 24;
        if (key == last) {
            out[i] = li;
            continue;
        }
        h = hash32(key, MAP_SLOTS - 1);
        while (m->key[h] != 0 && m->key[h] != key)
            h = (h + 1) & (MAP_SLOTS - 1);
        if (m->key[h] == 0) {
            if (m->used >= MAP_SLOTS / 2) {
                memset(m->key, 0, MAP_SLOTS * sizeof *m->key);
                m->used = 0;
                h = hash32(key, MAP_SLOTS - 1);
            }
            m->key[h] = key;
            m->idx[h] = nearest(m, key & 0xffffff);
            m->used++;
        }
        last = key;
        li = out[i] = m->idx[h];
    }
}

int
cf__palette_map_init(cf__palette_map_t *m, const uint32_t *pal, int n)
{
    m->pal = pal;
    m->n = n;
    m->used = 0;
    m->key = cf_calloc(MAP_SLOTS, sizeof *m->key);
    m->idx = cf_malloc(MAP_SLOTS);
    return m->key != NULL && m->idx != NULL ? 0 : -1;
}

void
cf__palette_map_fini(cf__palette_map_t *m)
{
    cf_free(m->key);
    cf_free(m->idx);
    m->key = NULL;
    m->idx = NULL;
}
