/*
** The parts of the font subsetter shared by its files (render/fontfile/):
** the bytes of a font and what an error says about them, big-endian
** reads, the table directory of one face (sfnt.c), the two subsetters
** (cff-subset.c with cff-write.c, glyf-subset.c) and the pieces of CFF
** they share (cff-format.c: INDEX and DICT; cff-charstring.c: which
** subroutines a glyph calls).
**
** Every read goes through a position and a length checked first
** (cf__ff_fits): the font is untrusted bytes.  A function that finds the
** bytes wrong writes why (cf__ff_fail: "<name>: <what> at <file offset>
** ...") and returns 1; -1 is out of memory; 0 is success.
*/
#ifndef CURVEFIG_RENDER_SFNT_H
#define CURVEFIG_RENDER_SFNT_H

#include <stddef.h>
#include <stdint.h>

#include "buffer.h"
#include "fontfile.h"

/* The font's bytes and where errors go. */
typedef struct cf__ff {
    const unsigned char *data;
    size_t len;
    const char *name;     /* the file's name, for messages */
    char *why;
    size_t why_cap;
} cf__ff_t;

/* f over data[0..len) (none when data is NULL), named name (NULL:
** "font") in messages, which go to why (why_cap bytes, emptied first). */
void cf__ff_init(cf__ff_t *f, const unsigned char *data, size_t len,
                 const char *name, char *why, size_t why_cap);

/* Write "<name>: <message>" to f->why; returns 1. */
int cf__ff_fail(cf__ff_t *f, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* The offset in the file of a pointer into it (for messages). */
static inline size_t
cf__ff_at(const cf__ff_t *f, const unsigned char *p)
{
    return (size_t)(p - f->data);
}

/* Whether n bytes from pos fit in len. */
static inline int
cf__ff_fits(size_t pos, size_t n, size_t len)
{
    return pos <= len && n <= len - pos;
}

static inline unsigned
cf__ff_u16(const unsigned char *p)
{
    return (unsigned)p[0] << 8 | p[1];
}

static inline int
cf__ff_s16(const unsigned char *p)
{
    unsigned v = cf__ff_u16(p);
    return v >= 0x8000u ? (int)v - 0x10000 : (int)v;
}

static inline uint32_t
cf__ff_u32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 |
           (uint32_t)p[2] << 8 | p[3];
}

static inline void
cf__ff_put16(unsigned char *p, unsigned v)
{
    p[0] = (unsigned char)(v >> 8);
    p[1] = (unsigned char)v;
}

static inline void
cf__ff_put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

#define CF__FF_TAG(a, b, c, d) \
    ((uint32_t)(a) << 24 | (uint32_t)(b) << 16 | (uint32_t)(c) << 8 | (d))

/* One table of a face: its bytes (inside the file), or data NULL when the
** face has none. */
typedef struct cf__ff_table {
    const unsigned char *data;
    size_t len;
} cf__ff_table_t;

/* One face of the file: its table directory. */
typedef struct cf__ff_face {
    const unsigned char *dir;   /* the table records, 16 bytes each */
    unsigned num_tables;
    uint32_t version;           /* 0x00010000, 'true' or 'OTTO' */
} cf__ff_face_t;

/* The file at path mapped read-only (render/fontfile/fontfile.c): NULL,
** with *map and *len set (*map NULL for an empty file; munmap it), or what
** went wrong ("cannot open", "not a regular file", "cannot map") with *err
** the errno or 0.  A FIFO or a device is refused without blocking. */
const char *cf__ff_map_file(const char *path, void **map, size_t *len,
                            int *err);

/* Face `index` of the file (a collection's, or the one of a single
** font's, index 0). */
int cf__ff_face_open(cf__ff_t *f, unsigned index, cf__ff_face_t *face);

/* Table `tag` of the face (data NULL when absent; 1 when the directory
** puts it outside the file); min: the length the reader needs (a shorter
** table is damaged, 1). */
int cf__ff_table_find(cf__ff_t *f, const cf__ff_face_t *face, uint32_t tag,
                      size_t min, cf__ff_table_t *t);

/* Glyph gid's bytes [*a, *b) in a glyf table of glyf_len bytes, from its
** loca table (long: 32-bit offsets; the caller has checked that it holds
** gid + 2 entries): 0, or 1 when they are out of order or past the glyf
** table's end (the caller says so as it needs). */
int cf__ff_loca_range(const cf__ff_table_t *loca, int long_loca,
                      unsigned gid, size_t glyf_len, size_t *a, size_t *b);

/* Fill out's metrics (units_per_em ... stem_v, ps_name from the name
** table; advances of gids[0..n-1]); num_glyphs from maxp. */
int cf__ff_metrics(cf__ff_t *f, const cf__ff_face_t *face,
                   const unsigned *gids, size_t n,
                   cf__fontfile_subset_t *out, unsigned *num_glyphs);

/* ps_name from len bytes of a name: the characters a PDF name holds
** unescaped (2-byte UTF-16BE when wide), at most 63, else "Font". */
void cf__ff_ps_name(char *dst, const unsigned char *src, size_t len,
                    int wide);

/* The subsetters: keep[0..nkeep-1] ascending, distinct, keep[0] == 0,
** each < num_glyphs (checked by the caller).  They append the program to
** out->program; the CFF one sets out->stem_v from StdVW when the Private
** DICT has it, and out->ps_name from its Name INDEX. */
int cf__ff_cff_subset(cf__ff_t *f, const cf__ff_table_t *cff,
                      const unsigned *keep, size_t nkeep,
                      unsigned num_glyphs, cf__fontfile_subset_t *out);
int cf__ff_glyf_subset(cf__ff_t *f, const cf__ff_face_t *face,
                       const unsigned *keep, size_t nkeep,
                       unsigned num_glyphs, cf__buf_t *out);

/* ---- CFF pieces (cff-format.c) ------------------------------------------ */

/* A CFF INDEX read from t (the CFF table): count items, item i the bytes
** [data + off(i), data + off(i + 1)) with off 0-based here. */
typedef struct cf__cff_index {
    const unsigned char *t;   /* the table */
    size_t tlen;
    size_t count;
    unsigned off_size;
    size_t offsets;           /* position of the offset array */
    size_t data;              /* position of the first item */
    size_t end;               /* position after the INDEX */
    const char *what;         /* its name, for messages */
} cf__cff_index_t;

int cf__cff_index_read(cf__ff_t *f, const unsigned char *t, size_t tlen,
                       size_t pos, const char *what, cf__cff_index_t *ix);
/* Item i's position in the table and length (1 when its offsets are
** wrong). */
int cf__cff_index_item(cf__ff_t *f, const cf__cff_index_t *ix, size_t i,
                       size_t *pos, size_t *len);

/* Items of an INDEX to write: item i's bytes through a function. */
typedef void (*cf__cff_item_fn)(void *ctx, size_t i,
                                const unsigned char **p, size_t *len);
int cf__cff_index_write(cf__buf_t *b, size_t count, cf__cff_item_fn item,
                        void *ctx);

/* One operator of a DICT with its operands. */
#define CF__CFF_MAX_ARGS 48
typedef struct cf__cff_op {
    unsigned op;              /* 0..21, or 1200 + the escaped byte */
    size_t nargs;
    double args[CF__CFF_MAX_ARGS];   /* reals read as 0 */
    size_t start, end;        /* the entry's bytes, operands to operator */
} cf__cff_op_t;

/* The next operator of the DICT p[0..len) from *pos: 1 and op filled, 0
** at the end, -1 when damaged (the message written to f, naming the DICT
** by what; the caller returns 1). */
int cf__cff_dict_next(cf__ff_t *f, const unsigned char *p, size_t len,
                      size_t *pos, cf__cff_op_t *op, const char *what);

/* The Font DICT of glyph gid from the FDSelect at t[at] (formats 0 and
** 3): 0 and *fd; 1 when it runs past the table's end, 2 when no range
** holds gid, 3 another format. */
int cf__cff_fdselect(const unsigned char *t, size_t tlen, size_t at,
                     unsigned gid, unsigned *fd);

/* DICT operands as written: an integer in 5 bytes (29, for offsets whose
** value is not known before the layout), an operator. */
int cf__cff_put_int5(cf__buf_t *b, int32_t v);
int cf__cff_put_op(cf__buf_t *b, unsigned op);

/* ---- the charstring scan (cff-charstring.c) ----------------------------- */

/* A Type 2 charstring operand at p[0] (p[0] >= 32 or 28) of the len
** bytes left: its bytes (*need; 0 when it runs past len) and its value in
** 16.16 (integers shifted, 255's a 16.16 number already). */
static inline int32_t
cf__cff_cs_operand(const unsigned char *p, size_t len, size_t *need)
{
    unsigned b0 = p[0];
    size_t n = b0 == 28 ? 3 : b0 == 255 ? 5 : b0 >= 247 ? 2 : 1;
    *need = n <= len ? n : 0;
    if (*need == 0)
        return 0;
    if (b0 == 28)
        return (int32_t)((uint32_t)cf__ff_s16(p + 1) << 16);
    if (b0 == 255)
        return (int32_t)cf__ff_u32(p + 1);
    if (b0 >= 251)
        return (int32_t)((uint32_t)(-(((int)b0 - 251) * 256) - p[1] - 108)
                         << 16);
    if (b0 >= 247)
        return (int32_t)((uint32_t)(((int)b0 - 247) * 256 + p[1] + 108)
                         << 16);
    return (int32_t)((uint32_t)((int)b0 - 139) << 16);
}

/* The bias of a subroutine number in an INDEX of count subroutines. */
static inline unsigned
cf__cff_bias(size_t count)
{
    return count < 1240 ? 107 : count < 33900 ? 1131 : 32768;
}

/* The subroutines one glyph's Type 2 charstring calls: each called
** subroutine's used[] byte set to 1 (global or local), followed to the
** Type 2 limit of 10 nested calls, with the hint count kept for the
** bytes of hintmask and cntrmask. */
typedef struct cf__cff_subrs {
    const cf__cff_index_t *index;   /* NULL: none */
    unsigned char *used;            /* index->count bytes */
} cf__cff_subrs_t;

/* What a scan met that renumbering the subroutines needs (cff-subset.c):
** each call whose number is the literal integer just before it (at: the
** operand's bytes; old: the subroutine it calls) and each hint mask inside
** a subroutine (at: its bytes), once for every time the scan met it, with
** the charstring it is in (owner: glyph `glyph` of the scan, a global or a
** local subroutine, item its number) and the glyph's Font DICT (sites->fd
** when met; kept for a local subroutine or a local call, else 0).  The
** bytes of a charstring parse the same way wherever it is called unless
** one of its masks has a different length somewhere (or a global
** subroutine's local call meets two Font DICTs): two sites of one
** charstring that overlap and differ say so.  A call whose number is
** computed (arithmetic, a real, a number not immediately before it) sets
** computed; more than max sites set full (the list is then not kept: a
** hostile font's calls over and over cost no memory). */
enum { CF__CFF_SITE_MASK, CF__CFF_SITE_GLOBAL, CF__CFF_SITE_LOCAL };
enum { CF__CFF_IN_GLYPH, CF__CFF_IN_GLOBAL, CF__CFF_IN_LOCAL };
typedef struct cf__cff_site {
    const unsigned char *at;
    unsigned len;
    unsigned item;
    unsigned old;
    unsigned short owner_fd;
    unsigned short fd;        /* a local call's Font DICT */
    unsigned char owner;      /* CF__CFF_IN_... */
    unsigned char kind;       /* CF__CFF_SITE_... */
} cf__cff_site_t;

typedef struct cf__cff_sites {
    cf__cff_site_t *v;
    size_t n, cap, max;
    unsigned fd;              /* set before each glyph */
    size_t glyph;             /* set before each glyph */
    int computed, full;
    int failed;               /* out of memory */
} cf__cff_sites_t;

/* sites: NULL when not wanted. */
int cf__cff_scan_glyph(cf__ff_t *f, const unsigned char *cs, size_t len,
                       unsigned gid, cf__cff_subrs_t *global,
                       cf__cff_subrs_t *local, cf__cff_sites_t *sites,
                       long *budget);

/* The steps (charstring bytes interpreted) the scan of n glyphs may take,
** all together: 2^22 and CF__CFF_STEPS_PER_GLYPH a glyph. */
#define CF__CFF_STEPS_PER_GLYPH 4096L
long cf__cff_scan_budget(size_t nglyphs);

#endif
