/*
** The label places of the last few layouts of a figure.  Writing a figure
** lays it out (twice, more with a legend or insets) for every output
** format, each time with the same few layouts; the places are chosen once
** per layout and found again here.  A layout's entry is keyed by a hash of
** everything placement reads: the layout, the page size, the display list
** of the ink the labels avoid, and each label's own operations (its
** anchor, text, size and style).
*/
#include <string.h>

#include "backend.h"
#include "model.h"

#define MEMO_SLOTS 4

typedef struct slot {
    bool used;
    uint64_t key;
    size_t count;                /* the figure's elements then */
    cf__auto_place_t *chosen;    /* one per element (labels' only read) */
    char *warnings;              /* NULL: none */
} slot_t;

struct cf__place_memo {
    slot_t slot[MEMO_SLOTS];
    unsigned next;               /* the slot written next */
};

/* ---- the hash (FNV-1a, 64 bits) ---------------------------------------- */

#define FNV_BASIS 14695981039346656037ull
#define FNV_PRIME 1099511628211ull

void
cf__hash_bytes(uint64_t *h, const void *p, size_t n)
{
    const unsigned char *b = p;
    size_t i;
    for (i = 0; i < n; i++) {
        *h ^= b[i];
        *h *= FNV_PRIME;
    }
}

void
cf__hash_double(uint64_t *h, double v)
{
    cf__hash_bytes(h, &v, sizeof v);
}

static void
hash_size(uint64_t *h, size_t v)
{
    cf__hash_bytes(h, &v, sizeof v);
}

static void
hash_string(uint64_t *h, const char *s)
{
    if (s == NULL)
        hash_size(h, (size_t)-1);
    else
        cf__hash_bytes(h, s, strlen(s) + 1);
}

static void
hash_color(uint64_t *h, const cf_color_t *c)
{
    cf__hash_double(h, c->r);
    cf__hash_double(h, c->g);
    cf__hash_double(h, c->b);
    cf__hash_double(h, c->a);
}

static void
hash_paint(uint64_t *h, const cf__paint_t *p)
{
    size_t k;
    hash_size(h, (size_t)p->fill * 2u + (size_t)p->stroke);
    hash_color(h, &p->fill_color);
    cf__hash_double(h, p->fill_opacity);
    hash_color(h, &p->line.color);
    cf__hash_double(h, p->line.opacity);
    cf__hash_double(h, p->line.width);
    hash_size(h, (size_t)p->line.cap * 2u + (size_t)p->line.join);
    hash_size(h, p->line.dash_count);
    for (k = 0; k < p->line.dash_count && k < CF_STYLE_DASH_MAX; k++)
        cf__hash_double(h, p->line.dash[k]);
}

static void
hash_op(uint64_t *h, const cf__dl_t *dl, const cf__op_t *op)
{
    size_t k;
    hash_size(h, (size_t)op->kind);
    switch (op->kind) {
    case CF__OP_GROUP:
        hash_string(h, op->u.group.name);
        hash_size(h, op->u.group.index);
        hash_string(h, op->u.group.overlay);
        break;
    case CF__OP_CLIP:
        hash_size(h, op->u.clip.has_rect);
        for (k = 0; op->u.clip.has_rect && k < 4; k++)
            cf__hash_double(h, op->u.clip.rect[k]);
        break;
    case CF__OP_PATH: {
        size_t c0 = op->u.path.coord0, c1 = c0;
        const unsigned char *segs = dl->segs + op->u.path.seg0;
        static const size_t per[] = { 2, 2, 6, 4, 5, 0 };
        for (k = 0; k < op->u.path.nsegs; k++)
            c1 += segs[k] < sizeof per / sizeof per[0] ? per[segs[k]] : 0;
        cf__hash_bytes(h, segs, op->u.path.nsegs);
        cf__hash_bytes(h, dl->coords + c0, (c1 - c0) * sizeof(double));
        hash_paint(h, &op->u.path.paint);
        break;
    }
    case CF__OP_MARKER: {
        const cf__marker_op_t *m = &op->u.marker;
        hash_size(h, (size_t)m->marker * 2u + (size_t)m->has_dir);
        cf__hash_double(h, m->x);
        cf__hash_double(h, m->y);
        cf__hash_double(h, m->has_dir ? m->dir[0] : 0);
        cf__hash_double(h, m->has_dir ? m->dir[1] : 0);
        cf__hash_double(h, m->size);
        cf__hash_double(h, m->width);
        hash_color(h, &m->color);
        hash_color(h, &m->fill);
        cf__hash_double(h, m->opacity);
        break;
    }
    case CF__OP_TEXT: {
        const cf__text_op_t *t = &op->u.text;
        hash_string(h, t->source);
        cf__hash_double(h, t->px);
        cf__hash_double(h, t->py);
        hash_size(h, (size_t)t->place);
        cf__hash_double(h, t->offset);
        cf__hash_double(h, t->font_size);
        cf__hash_double(h, t->ox);
        cf__hash_double(h, t->oy);
        for (k = 0; k < 4; k++)
            cf__hash_double(h, t->ink[k]);
        hash_color(h, &t->color);
        cf__hash_double(h, t->opacity);
        cf__hash_double(h, t->halo);
        hash_color(h, &t->halo_color);
        break;
    }
    case CF__OP_END:
    case CF__OP_UNCLIP:
        break;
    }
}

void
cf__hash_dl(uint64_t *h, const cf__dl_t *dl)
{
    size_t i;
    hash_size(h, dl->count);
    for (i = 0; i < dl->count; i++)
        hash_op(h, dl, &dl->ops[i]);
}

uint64_t
cf__hash_layout(const cf_figure_t *fig, const cf__layout_t *lay)
{
    uint64_t h = FNV_BASIS;
    cf__hash_double(&h, fig->width);
    cf__hash_double(&h, fig->height);
    cf__hash_double(&h, lay->xmin);
    cf__hash_double(&h, lay->xmax);
    cf__hash_double(&h, lay->ymin);
    cf__hash_double(&h, lay->ymax);
    cf__hash_double(&h, lay->sx);
    cf__hash_double(&h, lay->sy);
    cf__hash_double(&h, lay->ox);
    cf__hash_double(&h, lay->oy);
    cf__hash_double(&h, lay->tol);
    hash_size(&h, lay->clip);
    cf__hash_double(&h, lay->px);
    cf__hash_double(&h, lay->py);
    hash_size(&h, fig->count);
    return h;
}

/* ---- the entries -------------------------------------------------------- */

bool
cf__place_memo_find(cf_figure_t *fig, uint64_t key,
                    cf__auto_place_t **chosen)
{
    struct cf__place_memo *m = fig->place_memo;
    unsigned k;
    size_t i;
    char *w = NULL;
    if (m == NULL)
        return false;
    for (k = 0; k < MEMO_SLOTS; k++) {
        slot_t *s = &m->slot[k];
        if (!s->used || s->key != key || s->count != fig->count)
            continue;
        if (s->warnings != NULL) {
            size_t n = strlen(s->warnings);
            w = cf_malloc(n + 1);
            if (w == NULL)
                return false;
            memcpy(w, s->warnings, n + 1);
        }
        for (i = 0; i < fig->count; i++)
            if (chosen[i] != NULL)
                *chosen[i] = s->chosen[i];
        cf_free(fig->warnings);
        fig->warnings = w;
        fig->warnings_len = w != NULL ? strlen(w) : 0;
        return true;
    }
    return false;
}

void
cf__place_memo_store(cf_figure_t *fig, uint64_t key,
                     cf__auto_place_t *const *chosen)
{
    struct cf__place_memo *m = fig->place_memo;
    slot_t *s;
    size_t i;
    if (m == NULL) {
        m = cf_calloc(1, sizeof *m);
        if (m == NULL)
            return;   /* nothing remembered: placed again next time */
        fig->place_memo = m;
    }
    s = &m->slot[m->next];
    cf_free(s->chosen);
    cf_free(s->warnings);
    memset(s, 0, sizeof *s);
    s->chosen = cf_calloc(fig->count ? fig->count : 1, sizeof *s->chosen);
    if (fig->warnings != NULL) {
        s->warnings = cf_malloc(fig->warnings_len + 1);
        if (s->warnings != NULL)
            memcpy(s->warnings, fig->warnings, fig->warnings_len + 1);
    }
    if (s->chosen == NULL || (fig->warnings != NULL && s->warnings == NULL)) {
        cf_free(s->chosen);
        cf_free(s->warnings);
        memset(s, 0, sizeof *s);
        return;
    }
    for (i = 0; i < fig->count; i++)
        if (chosen[i] != NULL)
            s->chosen[i] = *chosen[i];
    s->used = true;
    s->key = key;
    s->count = fig->count;
    m->next = (m->next + 1) % MEMO_SLOTS;
}

void
cf__place_memo_free(cf_figure_t *fig)
{
    struct cf__place_memo *m = fig->place_memo;
    unsigned k;
    if (m == NULL)
        return;
    for (k = 0; k < MEMO_SLOTS; k++) {
        cf_free(m->slot[k].chosen);
        cf_free(m->slot[k].warnings);
    }
    cf_free(m);
    fig->place_memo = NULL;
}
