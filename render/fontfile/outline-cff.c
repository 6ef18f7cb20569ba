/*
** CFF glyph outlines (render/fontfile/outline.h): the table's parts read
** once (Top DICT, Global Subrs, CharStrings, FDArray and FDSelect or the
** one Private DICT, each local Subrs), and a glyph's Type 2 charstring run
** as FreeType's Adobe engine runs it unhinted, so that the points are its
** points:
**   - operands are 16.16 (cf__cff_cs_operand, shared with the subsetter's
**     scan in cff-charstring.c), sums wrap as 32-bit integers;
**   - the path is kept in character space (CS) and each point goes out in
**     device space (DS) as FT_MulFix(v, 0x400), the "unity" scale 1/64;
**     an element waits in a queue of one until the next is known (the
**     engine's darkening joins, none here), a line whose CS end is its
**     start is dropped, and one whose DS end is the current DS point is
**     not emitted;
**   - FreeType's builder takes DS >> 10 (whole font units): a contour
**     begins at its first line or curve, its last point is dropped when
**     it is on the curve and equal to its first, a contour of one point
**     is dropped.
** Hints are counted (hstem, vstem, their hm forms, the operands before a
** hintmask or cntrmask) for the mask bytes, 96 at most as the engine's.
** The work is bounded: CF__CFF_STEPS_PER_GLYPH * 16 bytes interpreted,
** calls 10 deep, 48 operands.
*/
#include <string.h>

#include "outline-private.h"

#define MAX_STACK 48
#define MAX_DEPTH 10
#define MAX_HINTS 96
#define STEPS (CF__CFF_STEPS_PER_GLYPH * 16)

/* ---- the table ---------------------------------------------------------- */

/* A DICT's offset operand inside the table. */
static int
offset(const cf__olface_t *f, const cf__cff_op_t *op, size_t k, size_t *v)
{
    double a = k < op->nargs ? op->args[k] : -1;
    if (!(a >= 0 && a <= (double)f->tlen) || a != (double)(size_t)a)
        return 1;
    *v = (size_t)a;
    return 0;
}

/* A FontMatrix other than the default [0.001 0 0 0.001 0 0] (reals read
** as 0 by cf__cff_dict_next: any given matrix is refused unless the head
** says 1000 units, where FreeType's normalised one is the identity). */
static int
matrix_ok(const cf__olface_t *f, const cf__cff_op_t *op)
{
    (void)op;
    return f->upem == 1000 ? 0 : 1;
}

static int
private_subrs(cf__olface_t *f, size_t len, size_t pos, cf__cff_index_t *ix)
{
    cf__cff_op_t op;
    size_t at = 0, subrs = 0;
    int r;
    memset(ix, 0, sizeof *ix);
    if (!cf__ff_fits(pos, len, f->tlen))
        return 1;
    while ((r = cf__cff_dict_next(&f->ff, f->t + pos, len, &at, &op,
                                  "Private")) == 1)
        if (op.op == 19 && offset(f, &op, 0, &subrs))
            return 1;
    if (r < 0)
        return 1;
    if (subrs > 0)
        return cf__cff_index_read(&f->ff, f->t, f->tlen, pos + subrs,
                                  "Subrs", ix);
    return 0;
}

static int
font_dicts(cf__olface_t *f, const cf__cff_index_t *fdarray)
{
    size_t i;
    f->nfds = fdarray->count;
    if (f->nfds == 0 || f->nfds > CF__OL_MAX_FDS)
        return 1;
    for (i = 0; i < f->nfds; i++) {
        cf__cff_op_t op;
        size_t pos, len, at = 0, plen = 0, ppos = 0;
        int r, have = 0;
        if (cf__cff_index_item(&f->ff, fdarray, i, &pos, &len))
            return 1;
        while ((r = cf__cff_dict_next(&f->ff, f->t + pos, len, &at, &op,
                                      "Font")) == 1) {
            if (op.op == 18) {
                if (offset(f, &op, 0, &plen) || offset(f, &op, 1, &ppos))
                    return 1;
                have = 1;
            } else if (op.op == 1207 && matrix_ok(f, &op)) {
                return 1;
            }
        }
        if (r < 0 || !have || private_subrs(f, plen, ppos, &f->lsubrs[i]))
            return 1;
    }
    return 0;
}

int
cf__ol_cff_open(cf__olface_t *f, const cf__ff_table_t *cff)
{
    cf__cff_index_t names, tops, strings, fdarray;
    cf__cff_op_t op;
    size_t pos, len, at = 0, cs = 0, plen = 0, ppos = 0;
    int r, have_cs = 0, have_fda = 0;
    f->t = cff->data;
    f->tlen = cff->len;
    if (f->tlen < 4 || f->t[0] != 1 || f->t[2] < 4)
        return 1;
    if (cf__cff_index_read(&f->ff, f->t, f->tlen, f->t[2], "Name", &names) ||
        cf__cff_index_read(&f->ff, f->t, f->tlen, names.end, "Top DICT",
                           &tops) ||
        cf__cff_index_read(&f->ff, f->t, f->tlen, tops.end, "String",
                           &strings) ||
        cf__cff_index_read(&f->ff, f->t, f->tlen, strings.end,
                           "Global Subr", &f->gsubrs) ||
        cf__cff_index_item(&f->ff, &tops, 0, &pos, &len))
        return 1;
    while ((r = cf__cff_dict_next(&f->ff, f->t + pos, len, &at, &op,
                                  "Top")) == 1) {
        switch (op.op) {
        case 17:
            if (offset(f, &op, 0, &cs))
                return 1;
            have_cs = 1;
            break;
        case 18:
            if (offset(f, &op, 0, &plen) || offset(f, &op, 1, &ppos))
                return 1;
            break;
        case 1206:
            if (op.nargs != 1 || op.args[0] != 2)
                return 1;
            break;
        case 1207:
            if (matrix_ok(f, &op))
                return 1;
            break;
        case 1230:
            f->cid = true;
            break;
        case 1236:
            if (offset(f, &op, 0, &at) ||
                cf__cff_index_read(&f->ff, f->t, f->tlen, at, "FDArray",
                                   &fdarray))
                return 1;
            at = op.end;
            have_fda = 1;
            break;
        case 1237:
            if (offset(f, &op, 0, &f->fdselect))
                return 1;
            break;
        default:
            break;
        }
    }
    if (r < 0 || !have_cs ||
        cf__cff_index_read(&f->ff, f->t, f->tlen, cs, "CharStrings",
                           &f->charstrings))
        return 1;
    if (f->charstrings.count < f->num_glyphs)
        f->num_glyphs = (unsigned)f->charstrings.count;
    if (f->cid)
        return !have_fda || f->fdselect == 0 ? 1 : font_dicts(f, &fdarray);
    f->nfds = 1;
    return plen > 0 ? private_subrs(f, plen, ppos, &f->lsubrs[0]) : 0;
}

/* The Font DICT of glyph gid (FDSelect format 0 or 3). */
static int
fd_of(const cf__olface_t *f, unsigned gid, size_t *fd)
{
    unsigned k = 0;
    if (f->cid && cf__cff_fdselect(f->t, f->tlen, f->fdselect, gid, &k))
        return 1;
    *fd = k;
    return k < f->nfds ? 0 : 1;
}

/* ---- the charstring ----------------------------------------------------- */

typedef struct pt {
    int32_t x, y;
} pt_t;

enum { ELEM_LINE, ELEM_CURVE };

typedef struct cs {
    const cf__olface_t *f;
    const cf__cff_index_t *local;
    cf__outline_t *o;
    int32_t st[MAX_STACK];
    size_t sp;
    size_t stems;
    long steps;
    int err;               /* 1 refused, -1 out of memory */
    bool ended;
    pt_t cur;              /* CS */
    /* the engine's glyph path */
    bool move_pending, open, queued;
    pt_t start;            /* CS */
    int elem;
    pt_t e[4];             /* the queued element, CS */
    pt_t ds;               /* the current DS point */
    bool mask_new;         /* a hint mask not yet used by a map */
    bool map_valid;        /* a hint map built */
    /* FreeType's builder */
    bool begun;
} cs_t;

static int32_t
add32(int32_t a, int32_t b)
{
    return (int32_t)((uint32_t)a + (uint32_t)b);
}

static pt_t
to_ds(pt_t p)
{
    pt_t d;
    d.x = (int32_t)cf__ol_mulfix(p.x, 0x400);
    d.y = (int32_t)cf__ol_mulfix(p.y, 0x400);
    return d;
}

static void
put(cs_t *s, pt_t d, unsigned char tag)
{
    int r;
    if (s->err)
        return;
    /* 16.16 at 1/64 >> 10: 26.6 of whole units (arithmetic shift) */
    r = cf__ol_add(s->o, (int64_t)(d.x >> 10), (int64_t)(d.y >> 10), tag);
    if (r != 0)
        s->err = r;
}

/* ps_builder_close_contour, called at each move and at the end, as
** often as FreeType calls it: the open contour's end is recorded here or
** when the next one begins (ends[ncontours - 1] is set only then). */
static void
close_contour(cs_t *s)
{
    cf__outline_t *o = s->o;
    size_t first;
    if (s->err)
        return;
    first = o->ncontours <= 1 ? 0 : o->ends[o->ncontours - 2] + 1;
    if (o->ncontours > 0 && first == o->n) {
        o->ncontours--;
        return;
    }
    if (o->n > 1 && o->x[first] == o->x[o->n - 1] &&
        o->y[first] == o->y[o->n - 1] && o->tags[o->n - 1] == CF__OL_ON)
        o->n--;
    if (o->ncontours > 0) {
        if (first + 1 == o->n) {
            o->ncontours--;
            o->n--;
        } else {
            o->ends[o->ncontours - 1] = o->n - 1;
        }
    }
}

/* ps_builder_start_point: a contour added (the previous one's end
** recorded), its first point the current DS point. */
static void
begin(cs_t *s)
{
    cf__outline_t *o = s->o;
    if (s->begun || s->err)
        return;
    s->begun = true;
    if (o->ncontours > 0)
        o->ends[o->ncontours - 1] = o->n - 1;
    o->n += 1;   /* cf__ol_end_contour records n - 1: grow, then undo */
    if (cf__ol_end_contour(o) != 0) {
        s->err = -1;
        return;
    }
    o->n -= 1;
    put(s, s->ds, CF__OL_ON);
}

/* The queued element emitted (cf2_glyphpath_pushPrevElem, no offsets). */
static void
push_prev(cs_t *s, pt_t next0)
{
    pt_t p;
    if (s->elem == ELEM_LINE) {
        p = to_ds(s->e[1]);
        if (p.x != s->ds.x || p.y != s->ds.y) {
            begin(s);
            put(s, p, CF__OL_ON);
            s->ds = p;
        }
    } else {
        pt_t a = to_ds(s->e[1]), b = to_ds(s->e[2]), c = to_ds(s->e[3]);
        begin(s);
        put(s, a, CF__OL_CUBIC);
        put(s, b, CF__OL_CUBIC);
        put(s, c, CF__OL_ON);
        s->ds = c;
    }
    p = to_ds(next0);
    if (p.x != s->ds.x || p.y != s->ds.y) {
        begin(s);
        put(s, p, CF__OL_ON);
        s->ds = p;
    }
}

static void
push_move(cs_t *s, pt_t p0)
{
    if (!s->map_valid) {   /* a path without a moveto: the engine's */
        s->map_valid = true;
        s->mask_new = false;
    }
    close_contour(s);
    s->begun = false;
    s->ds = to_ds(p0);
}

static void
element(cs_t *s, int kind, const pt_t *p)
{
    if (s->move_pending) {
        push_move(s, p[0]);
        s->move_pending = false;
        s->open = true;
    }
    if (s->queued)
        push_prev(s, p[0]);
    s->queued = true;
    s->elem = kind;
    memcpy(s->e, p, (kind == ELEM_LINE ? 2 : 4) * sizeof *p);
}

/* A line; one of length 0 is kept only where a new hint mask begins
** (the engine passes it on, for hinting; its DS length is 0 too). */
static void
line_to(cs_t *s, int32_t x, int32_t y, bool closing)
{
    pt_t p[2];
    bool new_map = s->mask_new && !closing;
    if (s->cur.x == x && s->cur.y == y && !new_map)
        return;
    p[0] = s->cur;
    p[1].x = x;
    p[1].y = y;
    element(s, ELEM_LINE, p);
    if (new_map)
        s->mask_new = false;
    s->cur = p[1];
}

static void
curve_to(cs_t *s, int32_t x1, int32_t y1, int32_t x2, int32_t y2,
         int32_t x3, int32_t y3)
{
    pt_t p[4];
    p[0] = s->cur;
    p[1].x = x1;
    p[1].y = y1;
    p[2].x = x2;
    p[2].y = y2;
    p[3].x = x3;
    p[3].y = y3;
    element(s, ELEM_CURVE, p);
    s->mask_new = false;
    s->cur = p[3];
}

static void
close_path(cs_t *s)
{
    if (!s->open)
        return;
    line_to(s, s->start.x, s->start.y, true);
    if (s->queued)
        push_prev(s, s->start);
    s->move_pending = true;
    s->open = false;
    s->queued = false;
}

static void
move_to(cs_t *s, int32_t x, int32_t y)
{
    close_path(s);
    s->cur.x = s->start.x = x;
    s->cur.y = s->start.y = y;
    s->move_pending = true;
    if (!s->map_valid || s->mask_new) {
        s->map_valid = true;
        s->mask_new = false;
    }
}

/* Operand k from the bottom; refuses the glyph past the stack's top. */
static int32_t
arg(cs_t *s, size_t k)
{
    if (k >= s->sp) {
        s->err = 1;
        return 0;
    }
    return s->st[k];
}

static void
flex(cs_t *s, const bool *read, bool conditional_last)
{
    int32_t v[14];
    size_t k = 0;
    int i, top;
    bool hflex = !read[9];
    v[0] = s->cur.x;
    v[1] = s->cur.y;
    top = hflex ? 9 : 10;
    for (i = 0; i < top; i++) {
        v[i + 2] = v[i];
        if (read[i])
            v[i + 2] = add32(v[i + 2], arg(s, k++));
    }
    if (hflex)
        v[11] = s->cur.y;
    if (conditional_last) {
        int64_t dx = (int64_t)v[10] - s->cur.x, dy = (int64_t)v[11] - s->cur.y;
        int32_t last = arg(s, k);
        if ((dx < 0 ? -dx : dx) > (dy < 0 ? -dy : dy)) {
            v[12] = add32(v[10], last);
            v[13] = s->cur.y;
        } else {
            v[12] = s->cur.x;
            v[13] = add32(v[11], last);
        }
    } else {
        v[12] = read[10] ? add32(v[10], arg(s, k++)) : s->cur.x;
        v[13] = read[11] ? add32(v[11], arg(s, k)) : s->cur.y;
    }
    if (s->err)
        return;
    curve_to(s, v[2], v[3], v[4], v[5], v[6], v[7]);
    curve_to(s, v[8], v[9], v[10], v[11], v[12], v[13]);
}

static void
stems(cs_t *s)
{
    s->stems += s->sp / 2;
    if (s->stems > MAX_HINTS)
        s->err = 1;
}

static void run(cs_t *s, const unsigned char *p, size_t len, int depth);

static void
call(cs_t *s, const cf__cff_index_t *ix, int depth)
{
    int64_t k;
    size_t pos, len;
    if (s->sp == 0 || ix == NULL || ix->count == 0 || depth >= MAX_DEPTH) {
        s->err = 1;
        return;
    }
    /* cf2_fixedToInt: rounded */
    k = (int64_t)(int16_t)(((uint32_t)s->st[--s->sp] + 0x8000u) >> 16) +
        cf__cff_bias(ix->count);
    if (k < 0 || (size_t)k >= ix->count ||
        cf__cff_index_item((cf__ff_t *)&s->f->ff, ix, (size_t)k, &pos, &len)) {
        s->err = 1;
        return;
    }
    run(s, ix->t + pos, len, depth + 1);
}

static bool
push(cs_t *s, int32_t v)
{
    if (s->sp >= MAX_STACK) {
        s->err = 1;
        return false;
    }
    s->st[s->sp++] = v;
    return true;
}

/* The escaped operators (12 x). */
static void
escaped(cs_t *s, unsigned x)
{
    static const bool flex_r[12] = { 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1 };
    static const bool hflex_r[12] = { 1, 0, 1, 1, 1, 0, 1, 0, 1, 0, 1, 0 };
    static const bool hflex1_r[12] = { 1, 1, 1, 1, 1, 0, 1, 0, 1, 1, 1, 0 };
    static const bool flex1_r[12] = { 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0 };
    int32_t *st = s->st;
    size_t n = s->sp;
    switch (x) {
    case 35: flex(s, flex_r, false); s->sp = 0; return;
    case 34: flex(s, hflex_r, false); s->sp = 0; return;
    case 36: flex(s, hflex1_r, false); s->sp = 0; return;
    case 37: flex(s, flex1_r, true); s->sp = 0; return;
    case 0:   /* dotsection */
        s->sp = 0;
        return;
    default:
        break;
    }
    switch (x) {
    case 9:   /* abs */
        if (n < 1)
            break;
        if (st[n - 1] < 0)
            st[n - 1] = (int32_t)(0u - (uint32_t)st[n - 1]);
        return;
    case 14:  /* neg */
        if (n < 1)
            break;
        st[n - 1] = (int32_t)(0u - (uint32_t)st[n - 1]);
        return;
    case 10: case 11:   /* add sub */
        if (n < 2)
            break;
        st[n - 2] = x == 10 ? add32(st[n - 2], st[n - 1])
                            : (int32_t)((uint32_t)st[n - 2]
                                        - (uint32_t)st[n - 1]);
        s->sp--;
        return;
    case 12:  /* div */
        if (n < 2 || st[n - 1] == 0)
            break;
        st[n - 2] = (int32_t)cf__ol_divfix(st[n - 2], st[n - 1]);
        s->sp--;
        return;
    case 24:  /* mul */
        if (n < 2)
            break;
        st[n - 2] = (int32_t)cf__ol_mulfix(st[n - 2], st[n - 1]);
        s->sp--;
        return;
    case 18:  /* drop */
        if (n < 1)
            break;
        s->sp--;
        return;
    case 28: {  /* exch */
        int32_t t;
        if (n < 2)
            break;
        t = st[n - 1];
        st[n - 1] = st[n - 2];
        st[n - 2] = t;
        return;
    }
    case 27:  /* dup */
        if (n < 1)
            break;
        push(s, st[n - 1]);
        return;
    default:   /* the logic, storage and stack operators (and, or, not,
               ** eq, ifelse, put, get, index, roll), random, sqrt,
               ** reserved: not handled (no glyph of the fonts used has
               ** them; their engine's numbers are not checked) */
        break;
    }
    s->err = 1;
}

static void
run(cs_t *s, const unsigned char *p, size_t len, int depth)
{
    size_t i = 0, k, n;
    while (i < len && !s->ended && !s->err) {
        unsigned b0 = p[i];
        if (--s->steps < 0) {
            s->err = 1;
            return;
        }
        if (b0 >= 32 || b0 == 28) {
            size_t need;
            int32_t v = cf__cff_cs_operand(p + i, len - i, &need);
            if (need == 0 || !push(s, v)) {
                s->err = 1;
                return;
            }
            i += need;
            continue;
        }
        i++;
        n = s->sp;
        switch (b0) {
        case 1: case 3: case 18: case 23:   /* stem hints */
            stems(s);
            break;
        case 19: case 20:                   /* hintmask, cntrmask */
            stems(s);
            if (b0 == 19)
                s->mask_new = true;
            if (len - i < (s->stems + 7) / 8) {
                s->err = 1;
                return;
            }
            i += (s->stems + 7) / 8;
            break;
        case 21:   /* rmoveto */
            if (n < 2) {
                s->err = 1;
                return;
            }
            move_to(s, add32(s->cur.x, s->st[n - 2]),
                    add32(s->cur.y, s->st[n - 1]));
            break;
        case 22:   /* hmoveto */
        case 4:    /* vmoveto */
            if (n < 1) {
                s->err = 1;
                return;
            }
            if (b0 == 22)
                move_to(s, add32(s->cur.x, s->st[n - 1]), s->cur.y);
            else
                move_to(s, s->cur.x, add32(s->cur.y, s->st[n - 1]));
            break;
        case 5:    /* rlineto */
            for (k = 0; k < n && !s->err; k += 2) {
                int32_t x = add32(s->cur.x, arg(s, k));
                int32_t y = add32(s->cur.y, arg(s, k + 1));
                if (!s->err)
                    line_to(s, x, y, false);
            }
            break;
        case 6: case 7: {   /* hlineto, vlineto */
            bool is_x = b0 == 6;
            for (k = 0; k < n; k++) {
                if (is_x)
                    line_to(s, add32(s->cur.x, s->st[k]), s->cur.y, false);
                else
                    line_to(s, s->cur.x, add32(s->cur.y, s->st[k]), false);
                is_x = !is_x;
            }
            break;
        }
        case 8: case 24:    /* rrcurveto, rcurveline */
            for (k = 0; k + 6 <= n; k += 6) {
                int32_t x1 = add32(s->st[k], s->cur.x);
                int32_t y1 = add32(s->st[k + 1], s->cur.y);
                int32_t x2 = add32(s->st[k + 2], x1);
                int32_t y2 = add32(s->st[k + 3], y1);
                curve_to(s, x1, y1, x2, y2, add32(s->st[k + 4], x2),
                         add32(s->st[k + 5], y2));
            }
            if (b0 == 24) {
                int32_t x = add32(s->cur.x, arg(s, k));
                int32_t y = add32(s->cur.y, arg(s, k + 1));
                if (!s->err)
                    line_to(s, x, y, false);
            }
            break;
        case 25:   /* rlinecurve */
            for (k = 0; k + 6 < n; k += 2)
                line_to(s, add32(s->cur.x, s->st[k]),
                        add32(s->cur.y, s->st[k + 1]), false);
            for (; k < n && !s->err; k += 6) {
                int32_t x1 = add32(arg(s, k), s->cur.x);
                int32_t y1 = add32(arg(s, k + 1), s->cur.y);
                int32_t x2 = add32(arg(s, k + 2), x1);
                int32_t y2 = add32(arg(s, k + 3), y1);
                int32_t x3 = add32(arg(s, k + 4), x2);
                int32_t y3 = add32(arg(s, k + 5), y2);
                if (!s->err)
                    curve_to(s, x1, y1, x2, y2, x3, y3);
            }
            break;
        case 26: case 27: {   /* vvcurveto, hhcurveto */
            size_t count = n & ~(size_t)2;
            k = n - count;
            while (k < count && !s->err) {
                int32_t x1 = s->cur.x, y1 = s->cur.y, x2, y2;
                if ((count - k) & 1) {
                    if (b0 == 26)
                        x1 = add32(s->st[k], s->cur.x);
                    else
                        y1 = add32(s->st[k], s->cur.y);
                    k++;
                }
                if (b0 == 26) {
                    y1 = add32(arg(s, k), s->cur.y);
                    x2 = add32(arg(s, k + 1), x1);
                    y2 = add32(arg(s, k + 2), y1);
                    if (!s->err)
                        curve_to(s, x1, y1, x2, y2, x2,
                                 add32(arg(s, k + 3), y2));
                } else {
                    x1 = add32(arg(s, k), s->cur.x);
                    x2 = add32(arg(s, k + 1), x1);
                    y2 = add32(arg(s, k + 2), y1);
                    if (!s->err)
                        curve_to(s, x1, y1, x2, y2,
                                 add32(arg(s, k + 3), x2), y2);
                }
                k += 4;
            }
            break;
        }
        case 30: case 31: {   /* vhcurveto, hvcurveto */
            size_t count = n & ~(size_t)2;
            bool alt = b0 == 31;
            k = n - count;
            while (k < count && !s->err) {
                int32_t x1, y1, x2, y2, x3, y3;
                if (alt) {
                    x1 = add32(arg(s, k), s->cur.x);
                    y1 = s->cur.y;
                    x2 = add32(arg(s, k + 1), x1);
                    y2 = add32(arg(s, k + 2), y1);
                    y3 = add32(arg(s, k + 3), y2);
                    if (count - k == 5) {
                        x3 = add32(arg(s, k + 4), x2);
                        k++;
                    } else {
                        x3 = x2;
                    }
                } else {
                    x1 = s->cur.x;
                    y1 = add32(arg(s, k), s->cur.y);
                    x2 = add32(arg(s, k + 1), x1);
                    y2 = add32(arg(s, k + 2), y1);
                    x3 = add32(arg(s, k + 3), x2);
                    if (count - k == 5) {
                        y3 = add32(arg(s, k + 4), y2);
                        k++;
                    } else {
                        y3 = y2;
                    }
                }
                alt = !alt;
                if (!s->err)
                    curve_to(s, x1, y1, x2, y2, x3, y3);
                k += 4;
            }
            break;
        }
        case 10:   /* callsubr */
            call(s, s->local, depth);
            continue;
        case 29:   /* callgsubr */
            call(s, &s->f->gsubrs, depth);
            continue;
        case 11:   /* return */
            return;
        case 14:   /* endchar */
            if (n >= 4) {   /* seac: not handled */
                s->err = 1;
                return;
            }
            close_path(s);
            s->ended = true;
            return;
        case 12:
            if (i >= len) {
                s->err = 1;
                return;
            }
            escaped(s, p[i++]);
            continue;
        default:   /* reserved operators, CFF2's: not handled */
            s->err = 1;
            return;
        }
        s->sp = 0;
    }
}

int
cf__ol_cff_glyph(const cf__olface_t *f, unsigned gid, cf__outline_t *o)
{
    cs_t s;
    size_t pos, len, fd;
    if (gid >= f->charstrings.count || fd_of(f, gid, &fd) ||
        cf__cff_index_item((cf__ff_t *)&f->ff, &f->charstrings, gid, &pos,
                           &len))
        return 1;
    memset(&s, 0, sizeof s);
    s.f = f;
    s.local = &f->lsubrs[fd];
    s.o = o;
    s.steps = STEPS;
    s.move_pending = true;
    run(&s, f->t + pos, len, 0);
    if (!s.err && !s.ended)
        close_path(&s);   /* a charstring that ends without endchar */
    close_contour(&s);
    return s.err;
}
