/*
** The state of one CFF subset (render/fontfile/cff-subset.c reads the
** table and scans the kept glyphs into it, cff-write.c writes the subset
** from it).
*/
#ifndef CURVEFIG_RENDER_CFF_SUBSET_H
#define CURVEFIG_RENDER_CFF_SUBSET_H

#include <stddef.h>

#include "buffer.h"
#include "sfnt.h"

#define CF__CFF_MAX_STRINGS 24
#define CF__CFF_MAX_FDS 256   /* FDSelect numbers Font DICTs with one byte */

/* One Font DICT (a name-keyed font: its Private DICT alone). */
typedef struct cf__cff_fd {
    size_t dict_pos, dict_len;         /* Font DICT (CID-keyed input) */
    size_t priv_pos, priv_len;         /* Private DICT */
    cf__cff_index_t subrs;             /* count 0: none */
    unsigned char *used;
    unsigned *map;                     /* renumbered: old -> new */
    size_t *out_at, nout;              /* renumbered: the kept, in rebuf */
    int kept;
    unsigned out_index;
    size_t out_priv_pos, out_priv_len; /* where the last pass put it */
    size_t out_dict_pos, out_dict_len; /* in fdbuf */
} cf__cff_fd_t;

/* The table read, the glyphs kept, the layout of the last pass. */
typedef struct cf__cff {
    cf__ff_t *f;
    const unsigned char *t;
    size_t tlen;
    cf__cff_index_t names, tops, strings, gsubrs, charstrings, fdarray;
    size_t top_pos, top_len, name_pos, name_len;
    int cid;
    size_t fdselect;
    cf__cff_fd_t fds[CF__CFF_MAX_FDS];
    size_t nfds;
    unsigned char *gused;
    unsigned char *glyph_fd;        /* per kept glyph */
    const unsigned *keep;
    size_t nkeep;
    unsigned num_glyphs;
    const unsigned char *str[CF__CFF_MAX_STRINGS];
    size_t str_len[CF__CFF_MAX_STRINGS], nstr;
    size_t at_charset, at_fdselect, at_charstrings, at_fdarray;
    cf__buf_t fdbuf;
    /* the subroutines renumbered (else those not called are stubs): the
       kept charstrings and subroutines re-emitted into rebuf, item i of
       each INDEX the bytes [at[i], at[i + 1]) */
    int renumbered;
    cf__buf_t rebuf;
    size_t *cs_at;
    unsigned *gmap;
    size_t *g_at, g_out;
} cf__cff_t;

/* The subset written to b (cf__buf_t's failed flag says out of memory):
** call twice, the first time into a scratch buffer, so that the offsets
** the first pass recorded are the ones the second writes. */
void cf__cff_write_font(cf__cff_t *c, cf__buf_t *b);

#endif
