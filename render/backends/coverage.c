/*
** Coverage of a polygon (render/backends/raster.h, cf__poly_paint): the
** polygon's edges sampled on 4 sub-scanlines a pixel, each sub-scanline
** crossing the pixels it covers in exact horizontal fractions, nonzero
** or even-odd.
**
** The result is a function of the crossings of each sub-scanline in order
** of x, equal x in the order the edges became active (as kept in `act`,
** which a finished edge leaves by giving its place to the last one): the
** sums of float fractions a pixel receives depend on that order, so it is
** kept exactly.  What is cheap about it: the edges are ordered by their
** first sub-scanline with a counting sort; the crossings of one
** sub-scanline are sorted starting from the order of the one before
** (nearly sorted: a pass of insertion sort, where sorting each
** sub-scanline afresh costs the square of the active edges, hundreds on
** the flattened strokes of a curve); and a row's coverage is summed only
** over the pixels of its spans, not from its leftmost to its rightmost
** (the inside of a frame).
*/
#include <math.h>
#include <string.h>

#include "raster.h"

#define SUB 4                 /* sub-scanlines a pixel */
#define GONE ((size_t)-1)     /* an edge no longer active */

/* An active edge as sorted along a sub-scanline. */
typedef struct cross {
    double x;
    size_t slot;              /* its place in act: equal x in that order */
    size_t e;
    int dir;
} cross_t;

typedef struct work {
    size_t *order;            /* the edges by first sub-scanline (y0) */
    size_t *act;              /* the active edges, in the order above */
    size_t *slot;             /* each edge's place in act, or GONE */
    cross_t *cx;              /* the active edges along the sub-scanline */
    size_t *count;            /* counting sort: nb + 1 buckets */
    int *span;                /* a row's spans: pixel pairs [a, b) */
    float *row, *run;
} work_t;

/* The scratch memory of pl carved into w (n edges, nb buckets, a row of
** width cells); -1 out of memory. */
static int
work_get(cf__poly_t *pl, size_t nb, int width, work_t *w)
{
    size_t n = pl->n, nspan = 2 * (SUB * (n / 2 + 1) + 1);
    size_t need = 4 * n * sizeof(size_t) + (nb + 1) * sizeof(size_t)
                  + n * sizeof(cross_t) + nspan * sizeof(int)
                  + 2 * (size_t)width * sizeof(float) + 4 * sizeof(double);
    unsigned char *p;
    if (need > pl->scratch_size) {
        void *q = cf_realloc_array(pl->scratch, need, 1);
        if (q == NULL)
            return -1;
        pl->scratch = q;
        pl->scratch_size = need;
    }
    p = pl->scratch;
    w->cx = (cross_t *)p;
    p += n * sizeof(cross_t);
    w->order = (size_t *)p;
    w->act = w->order + n;
    w->slot = w->act + n;
    w->count = w->slot + n;
    p = (unsigned char *)(w->count + nb + 1);
    w->row = (float *)p;
    w->run = w->row + width;
    w->span = (int *)(w->run + width);
    return 0;
}

/* Indices v[0 .. n) in order of their edges' y0, stably. */
static void
insertion_sort(const cf__edge_t *e, size_t *v, size_t n)
{
    size_t j;
    for (j = 1; j < n; j++) {
        size_t x = v[j], at = j;
        while (at > 0 && e[v[at - 1]].y0 > e[x].y0) {
            v[at] = v[at - 1];
            at--;
        }
        v[at] = x;
    }
}

/* The same for many (the edges above a clip share the first bucket),
** bottom-up, through tmp (n cells). */
static void
merge_sort(const cf__edge_t *e, size_t *v, size_t n, size_t *tmp)
{
    size_t width, i, *a = v, *b = tmp;
    for (i = 0; i < n; i += 8)
        insertion_sort(e, v + i, n - i < 8 ? n - i : 8);
    for (width = 8; width < n; width *= 2) {
        size_t *t;
        for (i = 0; i < n; i += 2 * width) {
            size_t lo = i, mid = i + width < n ? i + width : n;
            size_t hi = i + 2 * width < n ? i + 2 * width : n;
            size_t p = lo, q = mid, o = lo;
            while (p < mid && q < hi)
                b[o++] = e[a[q]].y0 < e[a[p]].y0 ? a[q++] : a[p++];
            while (p < mid)
                b[o++] = a[p++];
            while (q < hi)
                b[o++] = a[q++];
        }
        t = a;
        a = b;
        b = t;
    }
    if (a != v)
        memcpy(v, a, n * sizeof *v);
}

/* The edges in order of y0, equal y0 in the order they were added (the
** order a stable sort by y0 gives): counted into buckets by their first
** sub-scanline from s0 on (nb buckets, the last for those past the
** clip), each bucket then put in order of y0. */
static void
order_edges(const cf__poly_t *pl, double s0, size_t nb, work_t *w)
{
    const cf__edge_t *e = pl->e;
    size_t i, k, *b = w->slot;   /* each edge's bucket, for now */
    memset(w->count, 0, (nb + 1) * sizeof *w->count);
    for (i = 0; i < pl->n; i++) {
        double s = floor(e[i].y0 * SUB) - s0;
        b[i] = s < 0 ? 0 : s >= (double)(nb - 1) ? nb - 1 : (size_t)s;
        w->count[b[i] + 1]++;
    }
    for (k = 0; k < nb; k++)
        w->count[k + 1] += w->count[k];
    for (i = 0; i < pl->n; i++)
        w->order[w->count[b[i]]++] = i;
    /* count[k] is now the end of bucket k; the last bucket's edges
    ** start past the clip and are never active */
    for (k = 0; k + 1 < nb; k++) {
        size_t lo = k == 0 ? 0 : w->count[k - 1], hi = w->count[k];
        if (hi - lo < 2)
            continue;   /* (most buckets: an edge or none) */
        if (hi - lo > 16)
            merge_sort(e, w->order + lo, hi - lo, w->act);
        else
            insertion_sort(e, w->order + lo, hi - lo);
    }
}

/* Coverage w of the pixels between a and b (device x) added to row
** (whose first cell is pixel i0, of i1 - i0 cells): the partly covered
** ones in row, the whole ones as a run (w added at the first, taken
** away after the last, summed across when the row is painted). */
static void
add_span(float *row, float *run, int i0, int i1, double a, double b,
         double w)
{
    int ia, ib;
    if (a < i0)
        a = i0;
    if (b > i1)
        b = i1;
    if (!(b > a))
        return;
    /* 0 <= i0 <= a < b: truncation is floor */
    ia = (int)a;
    ib = (int)b;
    if (ia == ib) {
        row[ia - i0] += (float)((b - a) * w);
        return;
    }
    row[ia - i0] += (float)((ia + 1 - a) * w);
    if (ia + 1 < ib) {
        run[ia + 1 - i0] += (float)w;
        if (ib < i1)
            run[ib - i0] -= (float)w;
    }
    if (ib < i1)
        row[ib - i0] += (float)((b - ib) * w);
}

/* The crossings of the active edges with sub-scanline sy into w->cx, in
** order of x and then of their place in act; nc their number (on entry:
** the crossings of the sub-scanline before, in their order, and the
** edges activated since at the end). */
static void
cross_at(const cf__poly_t *pl, work_t *w, size_t *nc, double sy)
{
    cross_t *cx = w->cx;
    size_t i, j, n = 0;
    for (i = 0; i < *nc; i++) {
        size_t s = w->slot[cx[i].e];
        const cf__edge_t *e;
        if (s == GONE)
            continue;
        e = &pl->e[cx[i].e];
        cx[n].e = cx[i].e;
        cx[n].slot = s;
        cx[n].x = e->x0 + (sy - e->y0) * e->dxdy;
        cx[n].dir = e->dir;
        n++;
    }
    for (i = 1; i < n; i++) {
        cross_t v = cx[i];
        for (j = i; j > 0 && (cx[j - 1].x > v.x
                              || (!(cx[j - 1].x < v.x)
                                  && cx[j - 1].slot > v.slot)); j--)
            cx[j] = cx[j - 1];
        cx[j] = v;
    }
    *nc = n;
}

/* Merge the spans of a row (nspan pairs) and put their coverage times
** alpha over the pixels d (the row's cell 0 is pixel i0). */
static void
put_row(work_t *w, size_t nspan, unsigned char *d, int i0, int width,
        double alpha)
{
    int *sp = w->span;
    size_t k, j;
    /* insertion sort of the pairs by their start */
    for (k = 1; k < nspan; k++) {
        int a = sp[2 * k], b = sp[2 * k + 1];
        for (j = k; j > 0 && sp[2 * j - 2] > a; j--) {
            sp[2 * j] = sp[2 * j - 2];
            sp[2 * j + 1] = sp[2 * j - 1];
        }
        sp[2 * j] = a;
        sp[2 * j + 1] = b;
    }
    for (k = 0; k < nspan;) {
        int a = sp[2 * k], b = sp[2 * k + 1], i;
        float across = 0;
        for (k++; k < nspan && sp[2 * k] <= b; k++)
            b = sp[2 * k + 1] > b ? sp[2 * k + 1] : b;
        if (b > width)
            b = width;
        for (i = a; i < b; i++) {
            float c;
            across += w->run[i];
            c = w->row[i] + across;
            c = c < 1 ? c : 1;
            w->row[i] = w->run[i] = 0;
            if (c > 0) {
                /* v + a c (1 - v) in bytes, rounded */
                double v = d[i0 + i], ac = alpha * c;
                d[i0 + i] = (unsigned char)(v + ac * (255 - v) + 0.5);
            }
        }
    }
}

int
cf__poly_paint(cf__poly_t *pl, unsigned char *px, int stride,
               const int clip[4], double alpha, bool evenodd,
               const unsigned char *rows)
{
    int i0, i1, j0, j1, y, k, width;
    size_t next = 0, nact = 0, nc = 0, nb, i;
    double ends = INFINITY;   /* the least y1 of the active edges */
    work_t w;
    if (pl->failed)
        return -1;
    if (pl->n == 0 || !(alpha > 0))
        return 0;
    /* the polygon's pixels within the clip (its box bounded on both
    ** sides: one wholly beyond the page is beyond every int) */
    i0 = (int)fmax(clip[0], floor(fmin(fmax(pl->box[0], -1e9), 1e9)));
    i1 = (int)fmin(clip[2], ceil(fmin(fmax(pl->box[2], -1e9), 1e9)));
    j0 = (int)fmax(clip[1], floor(fmin(fmax(pl->box[1], -1e9), 1e9)));
    j1 = (int)fmin(clip[3], ceil(fmin(fmax(pl->box[3], -1e9), 1e9)));
    if (i1 <= i0 || j1 <= j0)
        return 0;
    width = i1 - i0;
    nb = (size_t)(j1 - j0) * SUB + 1;
    if (work_get(pl, nb, width, &w) != 0)
        return -1;
    order_edges(pl, (double)j0 * SUB, nb, &w);
    memset(w.row, 0, 2 * (size_t)width * sizeof *w.row);
    for (y = j0; y < j1; y++) {
        unsigned char *d = px + (size_t)y * (size_t)stride;
        size_t nspan = 0;
        bool on = rows == NULL || rows[y] != 0;
        for (k = 0; k < SUB; k++) {
            double sy = y + (k + 0.5) / SUB, start = 0;
            size_t j;
            int wind = 0;
            while (next < pl->n && pl->e[w.order[next]].y0 <= sy) {
                size_t e = w.order[next++];
                w.slot[e] = nact;
                w.act[nact++] = e;
                w.cx[nc++].e = e;
                ends = pl->e[e].y1 < ends ? pl->e[e].y1 : ends;
            }
            /* the finished edges leave act, in its order (a sub-scanline
            ** where none ends, most of them, is not looked through) */
            if (ends <= sy) {
                ends = INFINITY;
                for (i = 0; i < nact;) {
                    size_t e = w.act[i];
                    if (pl->e[e].y1 <= sy) {
                        w.slot[e] = GONE;
                        w.act[i] = w.act[--nact];
                        if (i < nact)
                            w.slot[w.act[i]] = i;
                        continue;
                    }
                    ends = pl->e[e].y1 < ends ? pl->e[e].y1 : ends;
                    i++;
                }
            }
            /* a row left out keeps the active edges in their order; the
            ** crossings (the edges activated since at their end) are
            ** sorted afresh at the next row painted */
            if (!on)
                continue;
            cross_at(pl, &w, &nc, sy);
            for (j = 0; j < nc; j++) {
                bool was = evenodd ? (wind & 1) != 0 : wind != 0, is;
                wind += w.cx[j].dir;
                is = evenodd ? (wind & 1) != 0 : wind != 0;
                if (!was && is) {
                    start = w.cx[j].x;
                } else if (was && !is && w.cx[j].x > i0 && start < i1) {
                    int a = start > i0 ? (int)start - i0 : 0;
                    int b = w.cx[j].x < i1 ? (int)w.cx[j].x + 1 - i0
                                           : width;
                    add_span(w.row, w.run, i0, i1, start, w.cx[j].x,
                             1.0 / SUB);
                    w.span[2 * nspan] = a;
                    w.span[2 * nspan + 1] = b < width ? b : width;
                    nspan++;
                }
            }
        }
        if (on)
            put_row(&w, nspan, d, i0, width, alpha);
        if (next == pl->n && nact == 0)
            break;
    }
    return 0;
}
