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
** charstrings are scanned for the subroutines they call, through one
** another (cff-charstring.c), and for where each call's number is
** written.
**
** Renumbered: the subroutines called are kept alone, in their order, in
** dense INDEXes (the global one; each kept Font DICT's local one), and
** every kept charstring and subroutine is re-emitted, its bytes copied
** but for each call's number, the integer just before callsubr or
** callgsubr, written for the new number and the bias of the new count
** (107 below 1240 subroutines, 1131 below 33900, else 32768) in its
** shortest encoding.  When a call's number is not such a literal (it is
** computed by arithmetic, or is a real),
** when a hint mask inside a subroutine has two lengths (the bytes would
** not parse the same way wherever it is called) or when a global
** subroutine's local call meets two Font DICTs, the font keeps instead
** the full-count INDEXes below, charstrings copied as they are, so that
** the output never depends on the rewrite.
**
** Written (cff-write.c), in this order, every offset a 5-byte integer
** so that the layout is computed by writing the font twice (the first
** pass records where each part lands, the second writes those positions):
**   header; Name INDEX (the font's name); Top DICT INDEX: ROS Adobe
**   Identity 0, the input's Top DICT entries but its offsets, charset,
**   Encoding, unique ids and PostScript code (strings re-numbered),
**   CIDCount, charset, FDSelect, CharStrings, FDArray; String INDEX;
**   Global Subr INDEX (renumbered: those called; else every subroutine
**   not called a one-byte return, so that the numbers hold, and those
**   after the last one called left out down to the count that keeps the
**   bias: 1240 or 33900); charset
**   (format 2: new glyph i is CID keep[i]); FDSelect (format 3);
**   CharStrings INDEX (the kept glyphs, ascending); FDArray INDEX (the
**   Font DICTs the kept glyphs use, renumbered in order; a name-keyed
**   font's one, its Private DICT alone); each Private DICT followed by
**   its local Subr INDEX (renumbered or emptied as the global one; none
**   when no subroutine of it is kept).
*/
#include <stdlib.h>
#include <string.h>

#include "curvefig/core.h"
#include "cff-subset.h"

/* ---- reading -------------------------------------------------------- */

/* The offsets of Top and Font DICT entries: an integer inside the table */
static int
offset_arg(cf__cff_t *c, const cf__cff_op_t *op, size_t k, size_t *v)
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
load_private(cf__cff_t *c, cf__cff_fd_t *fd, cf__fontfile_subset_t *out,
             int first)
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
read_top(cf__cff_t *c, size_t *charstrings)
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
fd_of(cf__cff_t *c, unsigned gid, unsigned *fd)
{
    size_t at = c->fdselect;
    switch (cf__cff_fdselect(c->t, c->tlen, at, gid, fd)) {
    case 0:
        break;
    case 2:
        return cf__ff_fail(c->f, "CFF FDSelect at %zu: no range holds "
                           "glyph %u", cf__ff_at(c->f, c->t) + at, gid);
    case 3:
        return cf__ff_fail(c->f, "CFF FDSelect at %zu: format %u (0 or 3 "
                           "are read)", cf__ff_at(c->f, c->t) + at,
                           c->t[at]);
    default:
        return cf__ff_fail(c->f, "CFF FDSelect at %zu runs past the "
                           "table's end", cf__ff_at(c->f, c->t) + at);
    }
    if (*fd >= c->nfds)
        return cf__ff_fail(c->f, "CFF FDSelect: glyph %u in Font DICT %u "
                           "of %zu", gid, *fd, c->nfds);
    return 0;
}

static int
load_font_dict(cf__cff_t *c, cf__cff_fd_t *fd)
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
read_fds(cf__cff_t *c, cf__fontfile_subset_t *out)
{
    size_t i;
    int r, first = 1;
    if (!c->cid) {
        c->nfds = 1;
        c->fds[0].kept = 1;
        return load_private(c, &c->fds[0], out, 1);
    }
    c->nfds = c->fdarray.count < CF__CFF_MAX_FDS ? c->fdarray.count :
              CF__CFF_MAX_FDS;
    for (i = 0; i < c->nkeep; i++) {
        unsigned k = 0;
        if (fd_of(c, c->keep[i], &k))
            return 1;
        c->glyph_fd[i] = (unsigned char)k;
        c->fds[k].kept = 1;
    }
    for (i = 0; i < c->nfds; i++) {
        cf__cff_fd_t *fd = &c->fds[i];
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

/* ---- renumbering the subroutines ------------------------------------ */

#define CF__CFF_SITES_PER_GLYPH 256

static int
cmp_size(size_t a, size_t b)
{
    return a < b ? -1 : a > b;
}

/* Sites in order of charstring (owner, Font DICT, item), then position. */
static int
site_cmp(const void *pa, const void *pb)
{
    const cf__cff_site_t *a = pa, *b = pb;
    int r;
    if ((r = cmp_size((size_t)a->owner, (size_t)b->owner)) != 0 ||
        (r = cmp_size(a->owner_fd, b->owner_fd)) != 0 ||
        (r = cmp_size(a->item, b->item)) != 0)
        return r;
    if (a->at != b->at)
        return a->at < b->at ? -1 : 1;
    if ((r = cmp_size(a->len, b->len)) != 0 ||
        (r = cmp_size((size_t)a->kind, (size_t)b->kind)) != 0 ||
        (r = cmp_size(a->fd, b->fd)) != 0)
        return r;
    return cmp_size(a->old, b->old);
}

static int
same_item(const cf__cff_site_t *a, const cf__cff_site_t *b)
{
    return a->owner == b->owner && a->owner_fd == b->owner_fd &&
           a->item == b->item;
}

/* The sites sorted, each once: 0 when two of one charstring overlap and
** differ (its bytes not the same program everywhere it is called). */
static int
sites_settle(cf__cff_sites_t *w)
{
    size_t i, n = 0;
    if (w->n == 0)
        return 1;
    qsort(w->v, w->n, sizeof *w->v, site_cmp);
    for (i = 1; i < w->n; i++) {
        const cf__cff_site_t *a = &w->v[n], *b = &w->v[i];
        if (site_cmp(a, b) == 0)
            continue;
        if (same_item(a, b) && b->at < a->at + a->len)
            return 0;
        w->v[++n] = *b;
    }
    w->n = n + 1;
    return 1;
}

/* The used subroutines of ix numbered densely: map[old] (NULL when out
** of memory), *nout of them. */
static unsigned *
number_used(const cf__cff_index_t *ix, const unsigned char *used,
            size_t *nout)
{
    unsigned *map = cf_calloc(ix->count + 1, sizeof *map);
    size_t i, n = 0;
    if (map != NULL)
        for (i = 0; i < ix->count; i++)
            if (used[i])
                map[i] = (unsigned)n++;
    *nout = n;
    return map;
}

/* A Type 2 charstring integer (-32768 .. 32767) in its shortest form. */
static void
put_cs_int(cf__buf_t *b, long v)
{
    unsigned char o[3];
    size_t n = 2;
    if (v >= -107 && v <= 107) {
        o[0] = (unsigned char)(v + 139);
        n = 1;
    } else if (v >= 108 && v <= 1131) {
        o[0] = (unsigned char)(247 + (v - 108) / 256);
        o[1] = (unsigned char)((v - 108) % 256);
    } else if (v <= -108 && v >= -1131) {
        o[0] = (unsigned char)(251 + (-v - 108) / 256);
        o[1] = (unsigned char)((-v - 108) % 256);
    } else {
        o[0] = 28;
        cf__ff_put16(o + 1, (unsigned)v & 0xffffu);
        n = 3;
    }
    cf__buf_append(b, o, n);
}

/* Item `item` of owner (its bytes t[pos, pos + len)) appended to rebuf,
** each call's number the new one; 1 when a site falls outside it. */
static int
emit(cf__cff_t *c, const cf__cff_sites_t *w, int owner, unsigned owner_fd,
     size_t item, size_t pos, size_t len)
{
    const unsigned char *p = c->t + pos, *end = p + len;
    cf__cff_site_t key;
    size_t lo = 0, hi = w->n;
    key.owner = owner;
    key.owner_fd = owner_fd;
    key.item = item;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        const cf__cff_site_t *m = &w->v[mid];
        int r = cmp_size((size_t)m->owner, (size_t)owner);
        if (r == 0)
            r = cmp_size(m->owner_fd, owner_fd);
        if (r == 0)
            r = cmp_size(m->item, item);
        if (r < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    for (; lo < w->n && same_item(&w->v[lo], &key); lo++) {
        const cf__cff_site_t *st = &w->v[lo];
        const unsigned *map;
        size_t count;
        if (st->kind == CF__CFF_SITE_MASK)
            continue;
        if (st->at < p || st->at > end || st->len > (size_t)(end - st->at))
            return 1;
        if (st->kind == CF__CFF_SITE_GLOBAL) {
            map = c->gmap;
            count = c->g_out;
        } else {
            map = c->fds[st->fd].map;
            count = c->fds[st->fd].nout;
        }
        cf__buf_append(&c->rebuf, p, (size_t)(st->at - p));
        put_cs_int(&c->rebuf, (long)map[st->old] - (long)cf__cff_bias(count));
        p = st->at + st->len;
    }
    cf__buf_append(&c->rebuf, p, (size_t)(end - p));
    return 0;
}

/* The used subroutines of ix (local: fd's) re-emitted; *at gets their
** nout + 1 offsets in rebuf. */
static int
emit_subrs(cf__cff_t *c, const cf__cff_sites_t *w,
           const cf__cff_index_t *ix, const unsigned char *used, int owner,
           unsigned fd, size_t nout, size_t **at)
{
    size_t i, k = 0, pos, len;
    *at = cf_calloc(nout + 1, sizeof **at);
    if (*at == NULL)
        return -1;
    for (i = 0; i < ix->count; i++) {
        if (!used[i])
            continue;
        (*at)[k++] = c->rebuf.size;
        if (cf__cff_index_item(c->f, ix, i, &pos, &len) ||
            emit(c, w, owner, fd, i, pos, len))
            return 1;
    }
    (*at)[k] = c->rebuf.size;
    return 0;
}

/* Renumber the subroutines from the scan's sites: 0 done (renumbered
** set), 1 not possible (the stubs stay), -1 out of memory. */
static int
renumber(cf__cff_t *c, cf__cff_sites_t *w)
{
    size_t i, pos, len;
    int r;
    if (w->failed)
        return -1;
    if (w->computed || w->full || !sites_settle(w))
        return 1;
    c->gmap = number_used(&c->gsubrs, c->gused, &c->g_out);
    if (c->gmap == NULL)
        return -1;
    for (i = 0; i < c->nfds; i++) {
        cf__cff_fd_t *fd = &c->fds[i];
        if (!fd->kept)
            continue;
        fd->map = number_used(&fd->subrs, fd->used, &fd->nout);
        if (fd->map == NULL)
            return -1;
    }
    c->cs_at = cf_calloc(c->nkeep + 1, sizeof *c->cs_at);
    if (c->cs_at == NULL)
        return -1;
    for (i = 0; i < c->nkeep; i++) {
        c->cs_at[i] = c->rebuf.size;
        if (cf__cff_index_item(c->f, &c->charstrings, c->keep[i], &pos,
                               &len) ||
            emit(c, w, CF__CFF_IN_GLYPH, 0, i, pos, len))
            return 1;
    }
    c->cs_at[c->nkeep] = c->rebuf.size;
    if ((r = emit_subrs(c, w, &c->gsubrs, c->gused, CF__CFF_IN_GLOBAL, 0,
                        c->g_out, &c->g_at)) != 0)
        return r;
    for (i = 0; i < c->nfds; i++) {
        cf__cff_fd_t *fd = &c->fds[i];
        if (fd->kept &&
            (r = emit_subrs(c, w, &fd->subrs, fd->used, CF__CFF_IN_LOCAL,
                            (unsigned)i, fd->nout, &fd->out_at)) != 0)
            return r;
    }
    if (c->rebuf.failed)
        return -1;
    c->renumbered = 1;
    return 0;
}

static int
read_cff(cf__cff_t *c, cf__fontfile_subset_t *out)
{
    size_t cs = 0, i, pos, len;
    cf__cff_sites_t sites;
    long budget;
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
    budget = cf__cff_scan_budget(c->nkeep);
    memset(&sites, 0, sizeof sites);
    /* some 30 calls a glyph in the fonts the tests read */
    sites.max = ((size_t)1 << 16) + CF__CFF_SITES_PER_GLYPH *
                (c->nkeep < ((size_t)1 << 20) ? c->nkeep : (size_t)1 << 20);
    for (i = 0; i < c->nkeep; i++) {
        cf__cff_subrs_t g, l;
        cf__cff_fd_t *fd = &c->fds[c->glyph_fd[i]];
        g.index = &c->gsubrs;
        g.used = c->gused;
        l.index = &fd->subrs;
        l.used = fd->used;
        sites.fd = c->glyph_fd[i];
        sites.glyph = i;
        if (cf__cff_index_item(c->f, &c->charstrings, c->keep[i], &pos,
                               &len) ||
            cf__cff_scan_glyph(c->f, c->t + pos, len, c->keep[i], &g,
                               &l, &sites, &budget)) {
            cf_free(sites.v);
            return 1;
        }
    }
    r = renumber(c, &sites);
    cf_free(sites.v);
    if (r > 0)
        c->renumbered = 0;   /* the stubs: charstrings copied as they are */
    return r < 0 ? -1 : 0;
}

int
cf__ff_cff_subset(cf__ff_t *f, const cf__ff_table_t *table,
                  const unsigned *keep, size_t nkeep, unsigned num_glyphs,
                  cf__fontfile_subset_t *out)
{
    cf__cff_t *c = cf_calloc(1, sizeof *c);
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
        cf__cff_write_font(c, &scratch);
        r = scratch.failed ? -1 : 0;
        cf__buf_free(&scratch);
    }
    if (r == 0) {
        cf__cff_write_font(c, &out->program);
        r = out->program.failed ? -1 : 0;
    }
    for (i = 0; i < CF__CFF_MAX_FDS; i++) {
        cf_free(c->fds[i].used);
        cf_free(c->fds[i].map);
        cf_free(c->fds[i].out_at);
    }
    cf_free(c->gmap);
    cf_free(c->g_at);
    cf_free(c->cs_at);
    cf__buf_free(&c->rebuf);
    cf_free(c->gused);
    cf_free(c->glyph_fd);
    cf__buf_free(&c->fdbuf);
    cf_free(c);
    return r;
}
