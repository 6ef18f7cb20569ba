/*
** What the shaper's lookups share (render/fontfile/shape.c drives them):
** the state of one run being shaped, its output as a substitution builds
** it, and the check of a subtable of a type not applied here
** (otrun.c); GSUB's subtables (gsub.c) and GPOS's (gpos.c) applied at a
** glyph.
*/
#ifndef CURVEFIG_RENDER_SHAPE_PRIVATE_H
#define CURVEFIG_RENDER_SHAPE_PRIVATE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "otl.h"

/* LookupFlag's ignore bits, and the glyph props they test */
#define IGNORE_FLAGS 0x0Eu

typedef struct ctx {
    const cf__otface_t *f;
    otl_tab_t gsub, gpos, gdef;
    bool bad;                 /* a read outside a table */
    bool refuse;              /* the run is not handled */
    int64_t x_mult, y_mult;   /* HarfBuzz's */
    cf__otrun_t *r;
} ctx_t;

/* room for need glyphs in g and p (*cap of each); -1 out of memory */
int otrun_grow(cf__otglyph_t **g, unsigned char **p, size_t *cap,
               size_t need);
/* a glyph appended to the substitution's output (r->tg); the run refused
** when it is a mark or out of the font's range; -1 out of memory */
int otrun_emit(ctx_t *c, unsigned id, unsigned cluster, unsigned props);
/* A subtable of a type not applied here at glyph i: 0 when it does not
** apply there (the run goes on), 1 (the run refused) when it might. */
int otrun_not_done(ctx_t *c, const otl_tab_t *t, size_t sub, unsigned type,
                   bool gsub, unsigned flag, size_t i);

/* GSUB subtable at sub of type at glyph i: 0 not applied, 1 applied
** (*used input glyphs consumed, the output emitted), -1 out of memory. */
int gsub_apply(ctx_t *c, size_t sub, unsigned type, unsigned flag, size_t i,
               size_t *used);
/* GPOS subtable at glyph *i: 0 not applied, 1 applied (*i moved past). */
int gpos_apply(ctx_t *c, size_t sub, unsigned type, unsigned flag,
               size_t *i);

/* HarfBuzz's em_mult: v font units at mult (x_mult or y_mult) */
static inline int
otrun_em_mult(int v, int64_t mult)
{
    return (int)((v * mult + 32768) >> 16);
}

#endif
