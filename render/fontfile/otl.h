/*
** What the shaper's files share (render/fontfile/shape.h): the face
** (otface.c), reads of OpenType tables that never leave their table
** (otl.c: checked reads, coverage, class definitions, GDEF classes, the
** lookups of the default features for a script, contextual rules
** matched), the shaping (shape.c, with otrun.c, gsub.c and gpos.c:
** shape-private.h).
**
** Reads go through an otl_tab_t: a read outside the table sets *bad and
** gives 0, so that a walk over a damaged table ends in "not handled".
*/
#ifndef CURVEFIG_RENDER_OTL_H
#define CURVEFIG_RENDER_OTL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "shape.h"

typedef struct otl_tab {
    const unsigned char *p;   /* NULL: no table */
    size_t len;
    bool *bad;
} otl_tab_t;

unsigned otl_u16(const otl_tab_t *t, size_t off);
int otl_s16(const otl_tab_t *t, size_t off);
uint32_t otl_u32(const otl_tab_t *t, size_t off);

#define OTL_NOT_COVERED 0xFFFFFFFFu

/* Coverage index of gid in the Coverage table at off (OTL_NOT_COVERED). */
unsigned otl_coverage(const otl_tab_t *t, size_t off, unsigned gid);
/* Class of gid in the ClassDef at off (0 when off is 0). */
unsigned otl_class(const otl_tab_t *t, size_t off, unsigned gid);

struct cf__otface {
    const unsigned char *data;
    size_t len;
    void *map;                /* the mapping to undo, or NULL */
    size_t map_len;
    bool usable;
    bool has_base;
    bool bad;                 /* a read outside a table was attempted */
    otl_tab_t cmap, hmtx, gdef, gsub, gpos;
    size_t cmap_sub;          /* the chosen subtable in cmap */
    unsigned cmap_format;     /* 4 or 12 */
    unsigned upem, num_glyphs, num_hmetrics;
    size_t glyph_classes;     /* GDEF's ClassDef, 0: none */
    int asc, desc, gap;       /* font units, as HarfBuzz picks them */
};

/* Glyph props as HarfBuzz keeps them (the bits of LookupFlag). */
#define OTL_BASE 0x02u
#define OTL_LIGATURE 0x04u
#define OTL_MARK 0x08u

/* The props of gid from GDEF's glyph classes (the ClassDef at classes). */
unsigned otl_gdef_props(const otl_tab_t *gdef, size_t classes, unsigned gid);

/* The lookups applied for script: stage[0] (GSUB's rvrn), stage[1] (the
** rest of GSUB), stage[2] (GPOS), each ascending lookup indices.  1 when
** the layout is one the shaper does not do (a required feature, damage),
** -1 out of memory. */
typedef struct otl_plan {
    uint16_t *idx[3];
    size_t n[3];
} otl_plan_t;

int otl_plan(const cf__otface_t *f, uint32_t script, otl_plan_t *plan);
void otl_plan_fini(otl_plan_t *plan);

/* The offset of lookup i in a table, its type, flag and number of
** subtables; 0 when damaged or absent. */
size_t otl_lookup(const otl_tab_t *t, unsigned i, unsigned *type,
                  unsigned *flag, unsigned *nsub);
/* The offset of subtable j of the lookup at lk, an extension (ext_type)
** resolved, and its type; 0 when damaged. */
size_t otl_subtable(const otl_tab_t *t, size_t lk, unsigned j,
                    unsigned ext_type, unsigned *type);

/* Whether the contextual (5 / GPOS 7) or chaining (6 / GPOS 8) subtable
** at off matches at g[at] of g[0..n): a match means the run is
** not handled. */
bool otl_context_matches(const otl_tab_t *t, size_t off, bool chain,
                         const cf__otglyph_t *g, size_t n, size_t at);

#endif
