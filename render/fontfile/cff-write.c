/*
** A CFF subset written (render/fontfile/cff-subset.h) in the order
** cff-subset.c describes, every offset a 5-byte integer, so that two
** passes lay the font out and write it.
*/
#include <string.h>

#include "cff-subset.h"

static const unsigned char stub_return = 11;

/* The SID of a string of the output: a standard one as it is, another
** appended to the String INDEX; -1 when it cannot be (too many, or the
** input's SID is damaged: the entry is then left out). */
static long
sid_out(cf__cff_t *c, double sid)
{
    size_t pos, len, k;
    cf__ff_t quiet = *c->f;
    if (!(sid >= 0 && sid < 65536) || sid != (double)(long)sid)
        return -1;
    if (sid < 391)
        return (long)sid;
    quiet.why = NULL;   /* a bad string drops its entry, silently */
    if (c->nstr >= CF__CFF_MAX_STRINGS ||
        cf__cff_index_item(&quiet, &c->strings, (size_t)sid - 391, &pos,
                           &len))
        return -1;
    k = c->nstr++;
    c->str[k] = c->t + pos;
    c->str_len[k] = len;
    return 391 + (long)k;
}

static long
sid_new(cf__cff_t *c, const char *s)
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
copy_dict(cf__cff_t *c, cf__buf_t *b, size_t pos, size_t len,
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
build_top(cf__cff_t *c, cf__buf_t *b)
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
build_font_dicts(cf__cff_t *c)
{
    static const unsigned skip[] = { 18, 0 };
    size_t i;
    c->fdbuf.size = 0;
    for (i = 0; i < c->nfds; i++) {
        cf__cff_fd_t *fd = &c->fds[i];
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
    cf__cff_t *c;
    const cf__cff_index_t *ix;
    const unsigned char *used;   /* subroutines: NULL for all */
    const size_t *at;            /* renumbered: items in c->rebuf */
    const unsigned char *one;    /* a single item */
    size_t one_len;
    int fds;                     /* the Font DICTs of fdbuf */
} items_t;

/* Item i of an INDEX being written (its offsets checked by the scan). */
static void
item(void *ctx, size_t i, const unsigned char **p, size_t *len)
{
    items_t *it = ctx;
    cf__cff_t *c = it->c;
    size_t pos, k = 0, n;
    cf__ff_t quiet = *c->f;
    quiet.why = NULL;
    if (it->at != NULL) {
        *len = it->at[i + 1] - it->at[i];
        *p = *len > 0 ? c->rebuf.data + it->at[i] : &stub_return;
    } else if (it->one != NULL) {
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
write_index(cf__cff_t *c, cf__buf_t *b, const items_t *proto, size_t count)
{
    items_t it = *proto;
    it.c = c;
    return cf__cff_index_write(b, count, item, &it);
}

/* charset format 2 (ranges of consecutive CIDs), FDSelect format 3. */
static void
write_charset_fdselect(cf__cff_t *c, cf__buf_t *b)
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

/* The subroutines written: up to the last one called, but at least the
** least count of the bias of the input's count (107 below 1240, 1131
** below 33900, else 32768), so that calls find the same numbers. */
static size_t
subrs_out(const cf__cff_index_t *ix, const unsigned char *used)
{
    size_t n = ix->count, floor = n >= 33900 ? 33900 : n >= 1240 ? 1240 : 0;
    while (n > floor && !used[n - 1])
        n--;
    return n;
}

static void
write_private(cf__cff_t *c, cf__cff_fd_t *fd, cf__buf_t *b)
{
    static const unsigned skip[] = { 19, 0 };
    items_t it = { 0 };
    size_t start = b->size, nsubrs = c->renumbered ? fd->nout :
                                     subrs_out(&fd->subrs, fd->used);
    fd->out_priv_pos = start;
    copy_dict(c, b, fd->priv_pos, fd->priv_len, skip);
    if (nsubrs > 0) {
        /* the Subrs INDEX right after the DICT: its offset is the
           DICT's length, this entry's 6 bytes included */
        cf__cff_put_int5(b, (int32_t)(b->size - start + 6));
        cf__cff_put_op(b, 19);
    }
    fd->out_priv_len = b->size - start;
    if (nsubrs > 0) {
        it.ix = &fd->subrs;
        it.used = fd->used;
        it.at = c->renumbered ? fd->out_at : NULL;
        write_index(c, b, &it, nsubrs);
    }
}

void
cf__cff_write_font(cf__cff_t *c, cf__buf_t *b)
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
    it.at = c->renumbered ? c->g_at : NULL;
    write_index(c, b, &it, c->renumbered ? c->g_out :
                subrs_out(&c->gsubrs, c->gused));
    write_charset_fdselect(c, b);
    c->at_charstrings = b->size;
    it.ix = &c->charstrings;
    it.used = NULL;
    it.at = c->renumbered ? c->cs_at : NULL;
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

