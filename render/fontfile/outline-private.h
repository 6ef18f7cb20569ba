/*
** What the outline readers share (render/fontfile/outline.c, outline-
** cff.c, outline-glyf.c): the face read once, FreeType's fixed-point
** arithmetic, and the outline grown point by point.
*/
#ifndef CURVEFIG_RENDER_OUTLINE_PRIVATE_H
#define CURVEFIG_RENDER_OUTLINE_PRIVATE_H

#include "outline.h"
#include "sfnt.h"

#define CF__OL_MAX_FDS 256

struct cf__olface {
    cf__ff_t ff;
    void *map;                  /* the mapped file, or NULL (bytes given) */
    size_t map_len;
    bool heap;                  /* in malloc's heap (cf__olface_open) */
    unsigned upem, num_glyphs;
    bool cff;                   /* CFF outlines, else glyf */
    /* CFF */
    const unsigned char *t;     /* the CFF table */
    size_t tlen;
    cf__cff_index_t gsubrs, charstrings;
    bool cid;
    size_t fdselect;            /* position of FDSelect (cid) */
    size_t nfds;
    cf__cff_index_t lsubrs[CF__OL_MAX_FDS];   /* count 0: none */
    /* TrueType */
    cf__ff_table_t glyf, loca, hmtx;
    bool loca_long;
    unsigned num_hmetrics;
};

/* FreeType's FT_MulFix (its x86-64 code: 32-bit operands, the product
** rounded half away from zero) and FT_DivFix. */
static inline int64_t
cf__ol_mulfix(int64_t a, int64_t b)
{
    int64_t ab = (int64_t)(int32_t)a * (int64_t)(int32_t)b;
    return (int64_t)(int32_t)((ab + 0x8000 + (ab < 0 ? -1 : 0)) >> 16);
}

static inline int64_t
cf__ol_divfix(int64_t a, int64_t b)
{
    int s = 1;
    uint64_t ua, ub, q;
    if (a < 0) {
        ua = (uint64_t)-a;
        s = -s;
    } else {
        ua = (uint64_t)a;
    }
    if (b < 0) {
        ub = (uint64_t)-b;
        s = -s;
    } else {
        ub = (uint64_t)b;
    }
    q = ub > 0 ? ((ua << 16) + (ub >> 1)) / ub : 0x7FFFFFFFu;
    return s < 0 ? -(int64_t)q : (int64_t)q;
}

/* Append a point (tag CF__OL_*); 0, or -1 out of memory, 1 past
** CF__OL_MAX_POINTS. */
int cf__ol_add(cf__outline_t *o, int64_t x, int64_t y, unsigned char tag);
/* End the contour at the last point; 0 or -1. */
int cf__ol_end_contour(cf__outline_t *o);

/* The readers: the glyph in font units (CFF: whole units from the
** charstring; glyf: the scaled points, as FreeType scales them during the
** load), 0, 1 or -1. */
int cf__ol_cff_glyph(const cf__olface_t *f, unsigned gid, cf__outline_t *o);
int cf__ol_glyf_glyph(const cf__olface_t *f, unsigned gid,
                      const cf__olsize_t *sz, cf__outline_t *o);
/* The CFF table's parts the charstrings need. */
int cf__ol_cff_open(cf__olface_t *f, const cf__ff_table_t *cff);

#endif
