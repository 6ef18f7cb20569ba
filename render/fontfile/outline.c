/*
** Glyph outlines from the font files (render/fontfile/outline.h): the
** face opened (the file mapped, its directory, head, maxp and the CFF or
** glyf tables found), the size's scales, and a glyph's load as FreeType's
** FT_Load_Glyph does it unhinted: the reader's points, scaled (CFF: each
** point FT_MulFix'd; glyf: scaled by its reader), the control box taken,
** then the transform applied.
*/
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

#include "curvefig/core.h"
#include "outline-private.h"

/* The face's tables: head (upem), maxp (glyphs), and CFF or glyf. */
static int
read_face(cf__olface_t *f, unsigned index)
{
    cf__ff_face_t dir;
    cf__ff_table_t head, maxp, cff, hhea;
    if (cf__ff_face_open(&f->ff, index, &dir) ||
        cf__ff_table_find(&f->ff, &dir, CF__FF_TAG('h', 'e', 'a', 'd'), 54,
                          &head) ||
        cf__ff_table_find(&f->ff, &dir, CF__FF_TAG('m', 'a', 'x', 'p'), 6,
                          &maxp) ||
        cf__ff_table_find(&f->ff, &dir, CF__FF_TAG('C', 'F', 'F', ' '), 0,
                          &cff) ||
        head.data == NULL || maxp.data == NULL)
        return 1;
    f->upem = cf__ff_u16(head.data + 18);
    f->num_glyphs = cf__ff_u16(maxp.data + 4);
    if (f->upem < 16 || f->upem > 16384)
        return 1;
    if (cff.data != NULL) {
        f->cff = true;
        return cf__ol_cff_open(f, &cff);
    }
    if (cf__ff_table_find(&f->ff, &dir, CF__FF_TAG('g', 'l', 'y', 'f'), 0,
                          &f->glyf) ||
        cf__ff_table_find(&f->ff, &dir, CF__FF_TAG('l', 'o', 'c', 'a'), 0,
                          &f->loca) ||
        cf__ff_table_find(&f->ff, &dir, CF__FF_TAG('h', 'm', 't', 'x'), 0,
                          &f->hmtx) ||
        cf__ff_table_find(&f->ff, &dir, CF__FF_TAG('h', 'h', 'e', 'a'), 36,
                          &hhea) ||
        f->glyf.data == NULL || f->loca.data == NULL ||
        f->hmtx.data == NULL || hhea.data == NULL)
        return 1;
    f->loca_long = cf__ff_s16(head.data + 50) == 1;
    f->num_hmetrics = cf__ff_u16(hhea.data + 34);
    if (f->num_hmetrics == 0 ||
        f->hmtx.len < 4 * (size_t)f->num_hmetrics ||
        f->loca.len < (f->loca_long ? 4 : 2) * ((size_t)f->num_glyphs + 1))
        return 1;
    return 0;
}

int
cf__olface_open_mem(const unsigned char *data, size_t len, unsigned index,
                    cf__olface_t **out)
{
    cf__olface_t *f = cf_calloc(1, sizeof *f);
    int r;
    *out = NULL;
    if (f == NULL)
        return -1;
    f->ff.data = data;
    f->ff.len = len;
    f->ff.name = "font";
    r = read_face(f, index);
    if (r != 0) {
        cf_free(f);
        return r;
    }
    *out = f;
    return 0;
}

int
cf__olface_open(const char *path, unsigned index, cf__olface_t **out)
{
    cf__olface_t *f;
    void *map;
    size_t len;
    int err, r;
    *out = NULL;
    if (cf__ff_map_file(path, &map, &len, &err) != NULL)
        return 1;
    f = calloc(1, sizeof *f);
    if (f == NULL) {
        if (map != NULL)
            munmap(map, len);
        return -1;
    }
    f->ff.data = map;
    f->ff.len = len;
    f->ff.name = "font";
    f->map = map;
    f->map_len = len;
    f->heap = true;
    r = read_face(f, index);
    if (r != 0) {
        if (map != NULL)
            munmap(map, len);
        free(f);
        return r;
    }
    *out = f;
    return 0;
}

void
cf__olface_close(cf__olface_t *f)
{
    if (f == NULL)
        return;
    if (f->map != NULL)
        munmap(f->map, f->map_len);
    if (f->heap)
        free(f);
    else
        cf_free(f);
}

unsigned
cf__olface_units_per_em(const cf__olface_t *f)
{
    return f->upem;
}

unsigned
cf__olface_num_glyphs(const cf__olface_t *f)
{
    return f->num_glyphs;
}

void
cf__olface_size(const cf__olface_t *f, int64_t char_w, int64_t char_h,
                const int64_t m[4], cf__olsize_t *sz)
{
    /* FT_Request_Metrics, nominal size at 72 dpi: scaled_w = char_w */
    sz->x_scale = cf__ol_divfix(char_w, f->upem);
    sz->y_scale = cf__ol_divfix(char_h, f->upem);
    memcpy(sz->m, m, sizeof sz->m);
    sz->transform = m[0] != 0x10000 || m[1] != 0 || m[2] != 0 ||
                    m[3] != 0x10000;
}

int
cf__olface_glyph(const cf__olface_t *f, unsigned gid, const cf__olsize_t *sz,
                 cf__outline_t *o)
{
    size_t i;
    int r;
    o->n = 0;
    o->ncontours = 0;
    if (gid >= f->num_glyphs)
        return 1;
    if (f->cff) {
        r = cf__ol_cff_glyph(f, gid, o);
        if (r != 0)
            return r;
        for (i = 0; i < o->n; i++) {
            o->x[i] = cf__ol_mulfix(o->x[i], sz->x_scale);
            o->y[i] = cf__ol_mulfix(o->y[i], sz->y_scale);
        }
    } else {
        r = cf__ol_glyf_glyph(f, gid, sz, o);
        if (r != 0)
            return r;
    }
    /* FT_Outline_Get_CBox: all points, control points too */
    memset(o->cbox, 0, sizeof o->cbox);
    for (i = 0; i < o->n; i++) {
        if (i == 0 || o->x[i] < o->cbox[0])
            o->cbox[0] = o->x[i];
        if (i == 0 || o->y[i] < o->cbox[1])
            o->cbox[1] = o->y[i];
        if (i == 0 || o->x[i] > o->cbox[2])
            o->cbox[2] = o->x[i];
        if (i == 0 || o->y[i] > o->cbox[3])
            o->cbox[3] = o->y[i];
    }
    if (sz->transform)
        for (i = 0; i < o->n; i++) {
            int64_t x = o->x[i], y = o->y[i];
            o->x[i] = cf__ol_mulfix(x, sz->m[0]) + cf__ol_mulfix(y, sz->m[1]);
            o->y[i] = cf__ol_mulfix(x, sz->m[2]) + cf__ol_mulfix(y, sz->m[3]);
        }
    return 0;
}
