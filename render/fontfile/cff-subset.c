/*
** A CFF table cut down to some glyphs (render/fontfile/sfnt.h): the
** program of a PDF's CIDFontType0C font, CID-keyed, its CIDs the glyph
** ids of the font, so that the page's codes are the glyph ids whichever
** glyphs the subset holds.
**
** Read: the header, the Name, Top DICT, String and Global Subr INDEXes,
** the Top DICT's CharStrings, and either (a CID-keyed font) its FDArray
** and FDSelect, each Font DICT's Private DICT and local Subrs, or (a
** name-keyed font) its one Private DICT and Subrs.  The kept glyphs'
** charstrings are scanned for the subroutines they call
** (cff-charstring.c).
**
** Written, in this order, every offset a 5-byte integer so that the
** layout is computed by writing the font twice (the first pass records
** where each part lands, the second writes those positions):
**   header; Name INDEX (the font's name); Top DICT INDEX: ROS Adobe
**   Identity 0, the input's Top DICT entries but its offsets, charset,
**   Encoding, unique ids and PostScript code (strings re-numbered),
**   CIDCount, charset, FDSelect, CharStrings, FDArray; String INDEX;
**   Global Subr INDEX (every subroutine not called a one-byte return, so
**   that the numbers and the bias hold); charset (format 2: new glyph i
**   is CID keep[i]); FDSelect (format 3); CharStrings INDEX (the kept
**   glyphs, ascending); FDArray INDEX (the Font DICTs the kept glyphs
**   use, renumbered in order; a name-keyed font's one, its Private DICT
**   alone); each Private DICT followed by its local Subr INDEX (emptied
**   as the global one).
*/
#include <stdlib.h>
#include <string.h>

#include "curvefig/core.h"
#include "sfnt.h"

#define MAX_STRINGS 24
#define MAX_FDS 256   /* FDSelect numbers Font DICTs with one byte */

typedef struct fd {
    size_t dict_pos, dict_len;         /* Font DICT (CID-keyed input) */
    size_t priv_pos, priv_len;         /* Private DICT */
    cf__cff_index_t subrs;             /* count 0: none */
    unsigned char *used;
    int kept;
    unsigned out_index;
    size_t out_priv_pos, out_priv_len; /* where the last pass put it */
    size_t out_dict_pos, out_dict_len; /* in fdbuf */
} fd_t;

typedef struct cff {
    cf__ff_t *f;
    const unsigned char *t;
    size_t tlen;
    cf__cff_index_t names, tops, strings, gsubrs, charstrings, fdarray;
    size_t top_pos, top_len, name_pos, name_len;
    int cid;
    size_t fdselect;
    fd_t fds[MAX_FDS];
    size_t nfds;
    unsigned char *gused;
    unsigned char *glyph_fd;        /* per kept glyph */
    const unsigned *keep;
    size_t nkeep;
    unsigned num_glyphs;
    const unsigned char *str[MAX_STRINGS];
    size_t str_len[MAX_STRINGS], nstr;
    size_t at_charset, at_fdselect, at_charstrings, at_fdarray;
    cf__buf_t fdbuf;
} cff_t;

static const unsigned char stub_return = 11;

/* ---- reading -------------------------------------------------------- */

/* The offsets of Top and Font DICT entries: an integer inside the table */
static int
offset_arg(cff_t *c, const cf__cff_op_t *op, size_t k, size_t *v)
{
    double a = k < op->nargs ? op->args[k] : -1;
    if (op->nargs <= k || !(a >= 0 && a <= (double)c->tlen) ||
        a != (double)(size_t)a)
        return cf__ff_fail(c->f, "CFF DICT operator %u: offset %g outside "
                           "the table (%zu bytes)", op->op, a, c->tlen);
    *v = (size_t)a;
    return 0;
}

static int
load_private(cff_t *c, fd_t *fd, cf__fontfile_subset_t *out, int first)
{
    cf__cff_op_t op;
    size_t pos = 0, subrs = 0;
    const unsigned char *p;
    int r;
    if (!cf__ff_fits(fd->priv_pos, fd->priv_len, c->tlen))
        return cf__ff_fail(c->f, "CFF Private DICT at %zu (%zu bytes) runs "
                           "past the table's end",
                           cf__ff_at(c->f, c->t) + fd->priv_pos,
                           fd->priv_len);
    p = c->t + fd->priv_pos;
    while ((r = cf__cff_dict_next(c->f, p, fd->priv_len, &pos, &op,
                                  "Private")) == 1) {
        if (op.op == 19 && offset_arg(c, &op, 0, &subrs))
            return 1;
        if (op.op == 11 && first && op.nargs == 1 && op.args[0] >= 1 &&
            op.args[0] < 1000)
            out->stem_v = (unsigned)op.args[0];
    }
    if (r < 0)
        return 1;
    if (subrs > 0) {
        if (cf__cff_index_read(c->f, c->t, c->tlen, fd->priv_pos + subrs,
                               "Subrs", &fd->subrs))
            return 1;
    }
    fd->used = cf_calloc(fd->subrs.count + 1, 1);
    return fd->used == NULL ? -1 : 0;
}

static int
read_top(cff_t *c, size_t *charstrings)
{
    cf__cff_op_t op;
    size_t pos = 0, v = 0;
    const unsigned char *p = c->t + c->top_pos;
    int r, have_cs = 0;
    c->cid = 0;
    while ((r = cf__cff_dict_next(c->f, p, c->top_len, &pos, &op,
                                  "Top")) == 1) {
        switch (op.op) {
        case 17:
            if (offset_arg(c, &op, 0, charstrings))
                return 1;
            have_cs = 1;
            break;
        case 18:
            if (offset_arg(c, &op, 0, &c->fds[0].priv_len) ||
                offset_arg(c, &op, 1, &c->fds[0].priv_pos))
                return 1;
            break;
        case 1206:
            if (op.nargs != 1 || op.args[0] != 2)
                return cf__ff_fail(c->f, "CFF charstring type %g, not 2",
                                   op.nargs ? op.args[0] : 0.0);
            break;
        case 1230:
            c->cid = 1;
            break;
        case 1236:
            if (offset_arg(c, &op, 0, &v) ||
                cf__cff_index_read(c->f, c->t, c->tlen, v, "FDArray",
                                   &c->fdarray))
                return 1;
            break;
        case 1237:
            if (offset_arg(c, &op, 0, &c->fdselect))
                return 1;
            break;
        default:
            break;
        }
    }
    if (r < 0)
        return 1;
    if (!have_cs)
        return cf__ff_fail(c->f, "CFF Top DICT without CharStrings");
    if (c->cid && (c->fdarray.count == 0 || c->fdselect == 0))
        return cf__ff_fail(c->f, "CID-keyed CFF without FDArray or "
                           "FDSelect");
    return 0;
}

/* The Font DICT of glyph gid (FDSelect format 0 or 3). */
static int
fd_of(cff_t *c, unsigned gid, unsigned *fd)
{
    const unsigned char *t = c->t;
    size_t at = c->fdselect;
    if (!cf__ff_fits(at, 1, c->tlen))
        goto past;
    if (t[at] == 0) {
        if (!cf__ff_fits(at + 1, (size_t)gid + 1, c->tlen))
            goto past;
        *fd = t[at + 1 + gid];
    } else if (t[at] == 3) {
        size_t n, lo, hi;
        if (!cf__ff_fits(at, 3, c->tlen))
            goto past;
        n = cf__ff_u16(t + at + 1);
        if (n == 0 || !cf__ff_fits(at + 3, 3 * n + 2, c->tlen))
            goto past;
        if (gid < cf__ff_u16(t + at + 3) ||
            gid >= cf__ff_u16(t + at + 3 + 3 * n))
            return cf__ff_fail(c->f, "CFF FDSelect at %zu: no range holds "
                               "glyph %u", cf__ff_at(c->f, t) + at, gid);
        lo = 0;
        hi = n - 1;   /* the range lo..hi holds gid: first(lo) <= gid */
        while (lo < hi) {
            size_t mid = lo + (hi - lo + 1) / 2;
            if (cf__ff_u16(t + at + 3 + 3 * mid) <= gid)
                lo = mid;
            else
                hi = mid - 1;
        }
        *fd = t[at + 3 + 3 * lo + 2];
    } else {
        return cf__ff_fail(c->f, "CFF FDSelect at %zu: format %u (0 or 3 "
                           "are read)", cf__ff_at(c->f, t) + at, t[at]);
    }
    if (*fd >= c->nfds)
        return cf__ff_fail(c->f, "CFF FDSelect: glyph %u in Font DICT %u "
                           "of %zu", gid, *fd, c->nfds);
    return 0;
past:
    return cf__ff_fail(c->f, "CFF FDSelect at %zu runs past the table's "
                       "end", cf__ff_at(c->f, t) + at);
}

static int
load_font_dict(cff_t *c, fd_t *fd)
{
    cf__cff_op_t op;
    size_t pos = 0;
    int r, have_priv = 0;
    while ((r = cf__cff_dict_next(c->f, c->t + fd->dict_pos, fd->dict_len,
                                  &pos, &op, "Font")) == 1) {
        if (op.op == 18) {
            if (offset_arg(c, &op, 0, &fd->priv_len) ||
                offset_arg(c, &op, 1, &fd->priv_pos))
                return 1;
            have_priv = 1;
        }
    }
    if (r < 0)
        return 1;
    if (!have_priv)
        return cf__ff_fail(c->f, "CFF Font DICT without a Private DICT");
    return 0;
}

/* The Font DICTs of the kept glyphs, their Private DICTs and Subrs. */
static int
read_fds(cff_t *c, cf__fontfile_subset_t *out)
{
    size_t i;
    int r, first = 1;
    if (!c->cid) {
        c->nfds = 1;
        c->fds[0].kept = 1;
        return load_private(c, &c->fds[0], out, 1);
    }
    c->nfds = c->fdarray.count < MAX_FDS ? c->fdarray.count : MAX_FDS;
    c->fds[0].priv_len = c->fds[0].priv_pos = 0;
    for (i = 0; i < c->nkeep; i++) {
        unsigned k = 0;
        if (fd_of(c, c->keep[i], &k))
            return 1;
        c->glyph_fd[i] = (unsigned char)k;
        c->fds[k].kept = 1;
    }
    for (i = 0; i < c->nfds; i++) {
        fd_t *fd = &c->fds[i];
        if (!fd->kept)
            continue;
        if (cf__cff_index_item(c->f, &c->fdarray, i, &fd->dict_pos,
                               &fd->dict_len) ||
            load_font_dict(c, fd))
            return 1;
        if ((r = load_private(c, fd, out, first)) != 0)
            return r;
        first = 0;
    }
    return 0;
}

static int
read_cff(cff_t *c, cf__fontfile_subset_t *out)
{
    size_t cs = 0, i, pos, len;
    int r;
    if (c->tlen < 4 || c->t[0] != 1 || c->t[2] < 4)
        return cf__ff_fail(c->f, "CFF table at %zu: version %u, header of "
                           "%u bytes (version 1 is read; CFF2 is not)",
                           cf__ff_at(c->f, c->t), c->tlen ? c->t[0] : 0,
                           c->tlen > 2 ? c->t[2] : 0);
    if (cf__cff_index_read(c->f, c->t, c->tlen, c->t[2], "Name",
                           &c->names) ||
        cf__cff_index_read(c->f, c->t, c->tlen, c->names.end, "Top DICT",
                           &c->tops) ||
        cf__cff_index_read(c->f, c->t, c->tlen, c->tops.end, "String",
                           &c->strings) ||
        cf__cff_index_read(c->f, c->t, c->tlen, c->strings.end,
                           "Global Subr", &c->gsubrs) ||
        cf__cff_index_item(c->f, &c->names, 0, &c->name_pos,
                           &c->name_len) ||
        cf__cff_index_item(c->f, &c->tops, 0, &c->top_pos, &c->top_len) ||
        read_top(c, &cs) ||
        cf__cff_index_read(c->f, c->t, c->tlen, cs, "CharStrings",
                           &c->charstrings))
        return 1;
    cf__ff_ps_name(out->ps_name, c->t + c->name_pos, c->name_len, 0);
    if (c->keep[c->nkeep - 1] >= c->charstrings.count)
        return cf__ff_fail(c->f, "glyph id %u out of range (the CFF table "
                           "has %zu charstrings)", c->keep[c->nkeep - 1],
                           c->charstrings.count);
    c->gused = cf_calloc(c->gsubrs.count + 1, 1);
    c->glyph_fd = cf_calloc(c->nkeep, 1);
    if (c->gused == NULL || c->glyph_fd == NULL)
        return -1;
    if (c->charstrings.count > c->num_glyphs)
        c->num_glyphs = (unsigned)c->charstrings.count;
    if ((r = read_fds(c, out)) != 0)
        return r;
    for (i = 0; i < c->nkeep; i++) {
        cf__cff_subrs_t g, l;
        fd_t *fd = &c->fds[c->glyph_fd[i]];
        g.index = &c->gsubrs;
        g.used = c->gused;
        l.index = &fd->subrs;
        l.used = fd->used;
        if (cf__cff_index_item(c->f, &c->charstrings, c->keep[i], &pos,
                               &len) ||
            cf__cff_scan_glyph(c->f, c->t + pos, len, c->keep[i], &g,
                               &l))
            return 1;
    }
    return 0;
}

/* ---- writing -------------------------------------------------------- */

/* The SID of a string of the output: a standard one as it is, another
** appended to the String INDEX; -1 when it cannot be (too many, or the
** input's SID is damaged: the entry is then left out). */
static long
sid_out(cff_t *c, double sid)
{
    size_t pos, len, k;
    cf__ff_t quiet = *c->f;
    if (!(sid >= 0 && sid < 65536) || sid != (double)(long)sid)
        return -1;
    if (sid < 391)
        return (long)sid;
    quiet.why = NULL;   /* a bad string drops its entry, silently */
    if (c->nstr >= MAX_STRINGS ||
        cf__cff_index_item(&quiet, &c->strings, (size_t)sid - 391, &pos,
                           &len))
        return -1;
    k = c->nstr++;
    c->str[k] = c->t + pos;
    c->str_len[k] = len;
    return 391 + (long)k;
}

static long
sid_new(cff_t *c, const char *s)
{
    size_t k = c->nstr++;
    c->str[k] = (const unsigned char *)s;
    c->str_len[k] = strlen(s);
    return 391 + (long)k;
}

static int
is_sid_op(unsigned op)
{
    return op <= 4 || op == 1200 || op == 1238;
}

/* Copy a DICT's entries but those `skip` names (a 0-ended list), SID
** operands re-numbered. */
static void
copy_dict(cff_t *c, cf__buf_t *b, size_t pos, size_t len,
          const unsigned *skip)
{
    cf__cff_op_t op;
    size_t at = 0, k;
    while (cf__cff_dict_next(c->f, c->t + pos, len, &at, &op, "") == 1) {
        for (k = 0; skip[k] != 0 && skip[k] != op.op; k++)
            ;
        if (skip[k] != 0)
            continue;
        if (is_sid_op(op.op)) {
            long sid = op.nargs == 1 ? sid_out(c, op.args[0]) : -1;
            if (sid >= 0) {
                cf__cff_put_int5(b, (int32_t)sid);
                cf__cff_put_op(b, op.op);
            }
            continue;
        }
        cf__buf_append(b, c->t + pos + op.start, op.end - op.start);
    }
}

static void
build_top(cff_t *c, cf__buf_t *b)
{
    /* offsets, the name-keyed encoding, unique ids, PostScript code,
       synthetic and multiple-master entries */
    static const unsigned skip[] = { 13, 14, 15, 16, 17, 18, 1220, 1221,
        1222, 1223, 1224, 1225, 1230, 1234, 1235, 1236, 1237, 1238, 0 };
    cf__cff_put_int5(b, (int32_t)sid_new(c, "Adobe"));
    cf__cff_put_int5(b, (int32_t)sid_new(c, "Identity"));
    cf__cff_put_int5(b, 0);
    cf__cff_put_op(b, 1230);
    copy_dict(c, b, c->top_pos, c->top_len, skip);
    cf__cff_put_int5(b, (int32_t)c->num_glyphs);
    cf__cff_put_op(b, 1234);
    cf__cff_put_int5(b, (int32_t)c->at_charset);
    cf__cff_put_op(b, 15);
    cf__cff_put_int5(b, (int32_t)c->at_fdselect);
    cf__cff_put_op(b, 1237);
    cf__cff_put_int5(b, (int32_t)c->at_charstrings);
    cf__cff_put_op(b, 17);
    cf__cff_put_int5(b, (int32_t)c->at_fdarray);
    cf__cff_put_op(b, 1236);
}

static void
build_font_dicts(cff_t *c)
{
    static const unsigned skip[] = { 18, 0 };
    size_t i;
    c->fdbuf.size = 0;
    for (i = 0; i < c->nfds; i++) {
        fd_t *fd = &c->fds[i];
        if (!fd->kept)
            continue;
        fd->out_dict_pos = c->fdbuf.size;
        if (c->cid)
            copy_dict(c, &c->fdbuf, fd->dict_pos, fd->dict_len, skip);
        cf__cff_put_int5(&c->fdbuf, (int32_t)fd->out_priv_len);
        cf__cff_put_int5(&c->fdbuf, (int32_t)fd->out_priv_pos);
        cf__cff_put_op(&c->fdbuf, 18);
        fd->out_dict_len = c->fdbuf.size - fd->out_dict_pos;
    }
}

typedef struct items {
    cff_t *c;
    const cf__cff_index_t *ix;
    const unsigned char *used;   /* subroutines: NULL for all */
    const unsigned char *one;    /* a single item */
    size_t one_len;
    int fds;                     /* the Font DICTs of fdbuf */
} items_t;

/* Item i of an INDEX being written (its offsets checked by the scan). */
static void
item(void *ctx, size_t i, const unsigned char **p, size_t *len)
{
    items_t *it = ctx;
    cff_t *c = it->c;
    size_t pos, k = 0, n;
    cf__ff_t quiet = *c->f;
    quiet.why = NULL;
    if (it->one != NULL) {
        *p = it->one;
        *len = it->one_len;
    } else if (it->fds) {
        for (n = 0; n < c->nfds; n++)
            if (c->fds[n].kept && k++ == i)
                break;
        *p = c->fdbuf.data + c->fds[n].out_dict_pos;
        *len = c->fds[n].out_dict_len;
    } else if (it->used == NULL && it->ix == &c->charstrings) {
        cf__cff_index_item(&quiet, it->ix, c->keep[i], &pos, len);
        *p = c->t + pos;
    } else if (it->used != NULL && it->used[i]) {
        cf__cff_index_item(&quiet, it->ix, i, &pos, len);
        *p = c->t + pos;
    } else if (it->used != NULL) {
        *p = &stub_return;
        *len = 1;
    } else {   /* the strings */
        *p = c->str[i];
        *len = c->str_len[i];
    }
}

static int
write_index(cff_t *c, cf__buf_t *b, const items_t *proto, size_t count)
{
    items_t it = *proto;
    it.c = c;
    return cf__cff_index_write(b, count, item, &it);
}

/* charset format 2 (ranges of consecutive CIDs), FDSelect format 3. */
static void
write_charset_fdselect(cff_t *c, cf__buf_t *b)
{
    unsigned char o[4];
    size_t i, j, nranges = 0, count_at;
    c->at_charset = b->size;
    o[0] = 2;
    cf__buf_append(b, o, 1);
    for (i = 1; i < c->nkeep; i = j) {
        for (j = i + 1; j < c->nkeep && c->keep[j] == c->keep[j - 1] + 1;
             j++)
            ;
        cf__ff_put16(o, c->keep[i]);
        cf__ff_put16(o + 2, (unsigned)(j - i - 1));
        cf__buf_append(b, o, 4);
    }
    c->at_fdselect = b->size;
    o[0] = 3;
    o[1] = o[2] = 0;
    cf__buf_append(b, o, 3);
    count_at = b->size - 2;
    for (i = 0; i < c->nkeep; i++) {
        unsigned k = c->cid ? c->glyph_fd[i] : 0;
        if (i > 0 && (c->cid ? c->glyph_fd[i - 1] : 0) == k)
            continue;
        cf__ff_put16(o, (unsigned)i);
        o[2] = (unsigned char)c->fds[k].out_index;
        cf__buf_append(b, o, 3);
        nranges++;
    }
    cf__ff_put16(o, (unsigned)c->nkeep);
    cf__buf_append(b, o, 2);
    if (!b->failed)
        cf__ff_put16(b->data + count_at, (unsigned)nranges);
}

static void
write_private(cff_t *c, fd_t *fd, cf__buf_t *b)
{
    static const unsigned skip[] = { 19, 0 };
    items_t it = { 0 };
    size_t start = b->size;
    fd->out_priv_pos = start;
    copy_dict(c, b, fd->priv_pos, fd->priv_len, skip);
    if (fd->subrs.count > 0) {
        /* the Subrs INDEX right after the DICT: its offset is the
           DICT's length, this entry's 6 bytes included */
        cf__cff_put_int5(b, (int32_t)(b->size - start + 6));
        cf__cff_put_op(b, 19);
    }
    fd->out_priv_len = b->size - start;
    if (fd->subrs.count > 0) {
        it.ix = &fd->subrs;
        it.used = fd->used;
        write_index(c, b, &it, fd->subrs.count);
    }
}

static void
write_font(cff_t *c, cf__buf_t *b)
{
    static const unsigned char header[4] = { 1, 0, 4, 4 };
    items_t it = { 0 };
    cf__buf_t top = { 0 };
    size_t i, k = 0;
    c->nstr = 0;
    build_top(c, &top);
    for (i = 0; i < c->nfds; i++)
        if (c->fds[i].kept)
            c->fds[i].out_index = (unsigned)k++;
    build_font_dicts(c);
    cf__buf_append(b, header, 4);
    it.one = c->t + c->name_pos;
    it.one_len = c->name_len;
    write_index(c, b, &it, 1);
    it.one = top.data;
    it.one_len = top.size;
    if (!top.failed)
        write_index(c, b, &it, 1);
    else
        b->failed = 1;
    cf__buf_free(&top);
    it.one = NULL;
    write_index(c, b, &it, c->nstr);
    it.ix = &c->gsubrs;
    it.used = c->gused;
    write_index(c, b, &it, c->gsubrs.count);
    write_charset_fdselect(c, b);
    c->at_charstrings = b->size;
    it.ix = &c->charstrings;
    it.used = NULL;
    write_index(c, b, &it, c->nkeep);
    c->at_fdarray = b->size;
    memset(&it, 0, sizeof it);
    it.fds = 1;
    write_index(c, b, &it, k);
    if (c->fdbuf.failed)
        b->failed = 1;
    for (i = 0; i < c->nfds; i++)
        if (c->fds[i].kept)
            write_private(c, &c->fds[i], b);
}

int
cf__ff_cff_subset(cf__ff_t *f, const cf__ff_table_t *table,
                  const unsigned *keep, size_t nkeep, unsigned num_glyphs,
                  cf__fontfile_subset_t *out)
{
    cff_t *c = cf_calloc(1, sizeof *c);
    cf__buf_t scratch = { 0 };
    size_t i;
    int r;
    if (c == NULL)
        return -1;
    c->f = f;
    c->t = table->data;
    c->tlen = table->len;
    c->keep = keep;
    c->nkeep = nkeep;
    c->num_glyphs = num_glyphs;
    r = read_cff(c, out);
    if (r == 0) {
        /* the first pass lays out, the second writes where it said */
        write_font(c, &scratch);
        r = scratch.failed ? -1 : 0;
        cf__buf_free(&scratch);
    }
    if (r == 0) {
        write_font(c, &out->program);
        r = out->program.failed ? -1 : 0;
    }
    for (i = 0; i < MAX_FDS; i++)
        cf_free(c->fds[i].used);
    cf_free(c->gused);
    cf_free(c->glyph_fd);
    cf__buf_free(&c->fdbuf);
    cf_free(c);
    return r;
}
