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
** Written (cff-write.c), in this order, every offset a 5-byte integer
** so that the layout is computed by writing the font twice (the first
** pass records where each part lands, the second writes those positions):
**   header; Name INDEX (the font's name); Top DICT INDEX: ROS Adobe
**   Identity 0, the input's Top DICT entries but its offsets, charset,
**   Encoding, unique ids and PostScript code (strings re-numbered),
**   CIDCount, charset, FDSelect, CharStrings, FDArray; String INDEX;
**   Global Subr INDEX (every subroutine not called a one-byte return, so
**   that the numbers hold, and those after the last one called left out
**   down to the count that keeps the bias: 1240 or 33900); charset
**   (format 2: new glyph i is CID keep[i]); FDSelect (format 3);
**   CharStrings INDEX (the kept glyphs, ascending); FDArray INDEX (the
**   Font DICTs the kept glyphs use, renumbered in order; a name-keyed
**   font's one, its Private DICT alone); each Private DICT followed by
**   its local Subr INDEX (emptied as the global one).
*/
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

static int
read_cff(cf__cff_t *c, cf__fontfile_subset_t *out)
{
    size_t cs = 0, i, pos, len;
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
    for (i = 0; i < c->nkeep; i++) {
        cf__cff_subrs_t g, l;
        cf__cff_fd_t *fd = &c->fds[c->glyph_fd[i]];
        g.index = &c->gsubrs;
        g.used = c->gused;
        l.index = &fd->subrs;
        l.used = fd->used;
        if (cf__cff_index_item(c->f, &c->charstrings, c->keep[i], &pos,
                               &len) ||
            cf__cff_scan_glyph(c->f, c->t + pos, len, c->keep[i], &g,
                               &l, &budget))
            return 1;
    }
    return 0;
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
    for (i = 0; i < CF__CFF_MAX_FDS; i++)
        cf_free(c->fds[i].used);
    cf_free(c->gused);
    cf_free(c->glyph_fd);
    cf__buf_free(&c->fdbuf);
    cf_free(c);
    return r;
}
