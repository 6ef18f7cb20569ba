/*
** A face for the shaper (render/fontfile/shape.h): the file mapped, the
** face's tables found through the table directory of sfnt.c, and what
** HarfBuzz 6.0 reads of them checked once:
**   cmap   the subtable HarfBuzz chooses ((3,0) first, as a symbol font:
**          not usable; then (3,10), (0,6), (0,4), (3,1), (0,3), (0,2),
**          (0,1), (0,0)), read when it is format 4 or 12;
**   head   unitsPerEm (16 to 16384, else HarfBuzz takes 1000: not usable);
**   maxp   the number of glyphs;
**   hhea, hmtx  advances (the last long metric's past numberOfHMetrics);
**   OS/2, hhea  the ascender, descender and line gap hb_font_get_h_extents
**          gives: OS/2's typographic ones when fsSelection's
**          USE_TYPO_METRICS bit is set, hhea's otherwise;
**   GDEF   the glyph class definition.
** The face is not usable when HarfBuzz would take another way than the
** shaper's (shape.h's list) or when a table is damaged.
*/
#include <math.h>
#include <string.h>
#include <sys/mman.h>

#include "curvefig/core.h"
#include "otl.h"
#include "sfnt.h"

static bool
find(cf__ff_t *ff, const cf__ff_face_t *dir, uint32_t tag, otl_tab_t *t,
     bool *bad)
{
    cf__ff_table_t tb;
    t->p = NULL;
    t->len = 0;
    t->bad = bad;
    if (cf__ff_table_find(ff, dir, tag, 0, &tb) != 0) {
        *bad = true;
        return false;
    }
    t->p = tb.data;
    t->len = tb.data != NULL ? tb.len : 0;
    return t->p != NULL;
}

/* The cmap subtable HarfBuzz 6.0 uses (find_best_subtable). */
static void
choose_cmap(cf__otface_t *f)
{
    static const unsigned order[][2] = {
        { 3, 10 }, { 0, 6 }, { 0, 4 }, { 3, 1 }, { 0, 3 }, { 0, 2 },
        { 0, 1 }, { 0, 0 }
    };
    const otl_tab_t *t = &f->cmap;
    unsigned n = otl_u16(t, 2), k, i;
    for (i = 0; i < n && !f->bad; i++)
        if (otl_u16(t, 4 + 8 * (size_t)i) == 3
            && otl_u16(t, 6 + 8 * (size_t)i) == 0) {
            f->bad = true;   /* a symbol font: not usable */
            return;
        }
    for (k = 0; k < sizeof order / sizeof order[0]; k++)
        for (i = 0; i < n && !f->bad; i++) {
            size_t r = 4 + 8 * (size_t)i;
            if (otl_u16(t, r) == order[k][0]
                && otl_u16(t, r + 2) == order[k][1]) {
                f->cmap_sub = otl_u32(t, r + 4);
                f->cmap_format = otl_u16(t, f->cmap_sub);
                if (f->cmap_format != 4 && f->cmap_format != 12)
                    f->bad = true;
                return;
            }
        }
    f->bad = true;
}

static unsigned
cmap4(const cf__otface_t *f, const otl_tab_t *t, uint32_t c)
{
    size_t s = f->cmap_sub;
    unsigned seg = otl_u16(t, s + 6) / 2, len = otl_u16(t, s + 2);
    size_t ends = s + 14, starts = ends + 2 * (size_t)seg + 2;
    size_t deltas = starts + 2 * (size_t)seg, ranges = deltas + 2 * (size_t)seg;
    size_t glyph_ids = ranges + 2 * (size_t)seg, nids;
    int lo = 0, hi = (int)seg - 2;
    unsigned i, ro, gid;
    if (len < 16 + 8 * (size_t)seg)
        return 0;
    nids = (len - 16 - 8 * (size_t)seg) / 2;
    while (lo <= hi) {
        int mid = (int)(((unsigned)lo + (unsigned)hi) / 2);
        if (c > otl_u16(t, ends + 2 * (size_t)mid))
            lo = mid + 1;
        else if (c < otl_u16(t, starts + 2 * (size_t)mid))
            hi = mid - 1;
        else {
            i = (unsigned)mid;
            goto found;
        }
    }
    return 0;
found:
    ro = otl_u16(t, ranges + 2 * (size_t)i);
    if (ro == 0) {
        gid = c + otl_u16(t, deltas + 2 * (size_t)i);
    } else {
        size_t index = ro / 2 + (c - otl_u16(t, starts + 2 * (size_t)i)) + i
                       - seg;
        if (index >= nids)
            return 0;
        gid = otl_u16(t, glyph_ids + 2 * index);
        if (gid == 0)
            return 0;
        gid += otl_u16(t, deltas + 2 * (size_t)i);
    }
    return gid & 0xFFFFu;
}

static unsigned
cmap12(const cf__otface_t *f, const otl_tab_t *t, uint32_t c)
{
    size_t s = f->cmap_sub, groups = s + 16;
    uint32_t n = otl_u32(t, s + 12);
    size_t lo = 0, hi = n;
    while (lo < hi && !*t->bad) {
        size_t mid = lo + (hi - lo) / 2, g = groups + 12 * mid;
        uint32_t start = otl_u32(t, g), end = otl_u32(t, g + 4);
        if (c < start)
            hi = mid;
        else if (c > end)
            lo = mid + 1;
        else
            return (unsigned)(otl_u32(t, g + 8) + (c - start));
    }
    return 0;
}

unsigned
cf__otface_glyph(const cf__otface_t *f, uint32_t c)
{
    bool bad = false;
    otl_tab_t t = f->cmap;
    unsigned gid;
    if (!f->usable)
        return 0;
    t.bad = &bad;
    gid = f->cmap_format == 4 ? cmap4(f, &t, c) : cmap12(f, &t, c);
    return bad ? 0 : gid;
}

/* A GSUB or GPOS HarfBuzz reads as the shaper does: version 1.0, or 1.1
** without feature variations. */
static bool
layout_ok(const otl_tab_t *t)
{
    unsigned major, minor;
    if (t->p == NULL)
        return true;
    major = otl_u16(t, 0);
    minor = otl_u16(t, 2);
    return major == 1 && (minor == 0 || otl_u32(t, 10) == 0);
}

/* The metrics of the face as HarfBuzz picks them; false: none. */
static bool
read_metrics(cf__otface_t *f, const otl_tab_t *hhea, const otl_tab_t *os2)
{
    if (os2->p != NULL) {
        unsigned version = otl_u16(os2, 0);
        size_t need = version >= 5 ? 100 : version >= 2 ? 96
                      : version >= 1 ? 86 : 78;
        if (os2->len < need)
            return false;   /* HarfBuzz would not read it: not ours */
        if ((otl_u16(os2, 4) || otl_u16(os2, 6) || otl_u16(os2, 64)
             || otl_u16(os2, 66))
            && (otl_u16(os2, 62) & 0x80u)) {
            f->asc = otl_s16(os2, 68);
            f->desc = otl_s16(os2, 70);
            f->gap = otl_s16(os2, 72);
            return true;
        }
    }
    if (hhea->len < 36 || otl_u16(hhea, 0) == 0)
        return false;
    f->asc = otl_s16(hhea, 4);
    f->desc = otl_s16(hhea, 6);
    f->gap = otl_s16(hhea, 8);
    return true;
}

static void
check(cf__otface_t *f, unsigned index)
{
    cf__ff_t ff;
    cf__ff_face_t dir;
    otl_tab_t head, maxp, hhea, os2, other;
    char why[160];
    static const uint32_t refused[] = {
        CF__FF_TAG('f', 'v', 'a', 'r'), CF__FF_TAG('m', 'o', 'r', 'x'),
        CF__FF_TAG('m', 'o', 'r', 't'), CF__FF_TAG('k', 'e', 'r', 'x'),
        CF__FF_TAG('t', 'r', 'a', 'k'), CF__FF_TAG('k', 'e', 'r', 'n')
    };
    size_t i;
    ff.data = f->data;
    ff.len = f->data != NULL ? f->len : 0;
    ff.name = "font";
    ff.why = why;
    ff.why_cap = sizeof why;
    if (cf__ff_face_open(&ff, index, &dir) != 0)
        return;
    for (i = 0; i < sizeof refused / sizeof refused[0]; i++)
        if (find(&ff, &dir, refused[i], &other, &f->bad) || f->bad)
            return;
    if (!find(&ff, &dir, CF__FF_TAG('c', 'm', 'a', 'p'), &f->cmap, &f->bad)
        || !find(&ff, &dir, CF__FF_TAG('h', 'e', 'a', 'd'), &head, &f->bad)
        || !find(&ff, &dir, CF__FF_TAG('m', 'a', 'x', 'p'), &maxp, &f->bad)
        || !find(&ff, &dir, CF__FF_TAG('h', 'h', 'e', 'a'), &hhea, &f->bad)
        || !find(&ff, &dir, CF__FF_TAG('h', 'm', 't', 'x'), &f->hmtx,
                 &f->bad)
        || !find(&ff, &dir, CF__FF_TAG('G', 'P', 'O', 'S'), &f->gpos,
                 &f->bad))
        return;
    f->has_base = find(&ff, &dir, CF__FF_TAG('B', 'A', 'S', 'E'), &other,
                       &f->bad);
    find(&ff, &dir, CF__FF_TAG('O', 'S', '/', '2'), &os2, &f->bad);
    find(&ff, &dir, CF__FF_TAG('G', 'D', 'E', 'F'), &f->gdef, &f->bad);
    find(&ff, &dir, CF__FF_TAG('G', 'S', 'U', 'B'), &f->gsub, &f->bad);
    if (f->bad || !layout_ok(&f->gsub) || !layout_ok(&f->gpos)
        || !read_metrics(f, &hhea, &os2))
        return;
    f->upem = otl_u16(&head, 18);
    f->num_glyphs = otl_u16(&maxp, 4);
    f->num_hmetrics = otl_u16(&hhea, 34);
    if (f->upem < 16 || f->upem > 16384 || f->num_hmetrics == 0
        || f->num_hmetrics > f->num_glyphs
        || f->hmtx.len < 4 * (size_t)f->num_hmetrics
                         + 2 * (size_t)(f->num_glyphs - f->num_hmetrics))
        return;
    if (f->gdef.p != NULL) {
        if (otl_u16(&f->gdef, 0) != 1)
            return;
        f->glyph_classes = otl_u16(&f->gdef, 4);
    }
    choose_cmap(f);
    f->usable = !f->bad;
}

int
cf__otface_open_mem(const unsigned char *data, size_t len, unsigned index,
                    cf__otface_t **out)
{
    cf__otface_t *f = cf_calloc(1, sizeof *f);
    *out = f;
    if (f == NULL)
        return -1;
    f->data = data;
    f->len = len;
    check(f, index);
    return 0;
}

size_t
cf__otface_size(void)
{
    return sizeof(cf__otface_t);
}

void
cf__otface_open_at(cf__otface_t *f, const char *path, unsigned index)
{
    void *map;
    size_t len;
    int err;
    memset(f, 0, sizeof *f);
    if (cf__ff_map_file(path, &map, &len, &err) != NULL || map == NULL)
        return;
    f->map = map;
    f->map_len = len;
    f->data = map;
    f->len = f->map_len;
    check(f, index);
}

void
cf__otface_release(cf__otface_t *f)
{
    if (f->map != NULL)
        munmap(f->map, f->map_len);
    memset(f, 0, sizeof *f);
}

int
cf__otface_open(const char *path, unsigned index, cf__otface_t **out)
{
    *out = cf_alloc_array(1, sizeof **out);
    if (*out == NULL)
        return -1;
    cf__otface_open_at(*out, path, index);
    return 0;
}

void
cf__otface_close(cf__otface_t *f)
{
    if (f == NULL)
        return;
    cf__otface_release(f);
    cf_free(f);
}

bool
cf__otface_usable(const cf__otface_t *f)
{
    return f->usable;
}

bool
cf__otface_has_base(const cf__otface_t *f)
{
    return f->has_base;
}

bool
cf__otface_h_extents(const cf__otface_t *f, int y_scale, int *asc,
                     int *desc, int *gap)
{
    float mult;
    if (!f->usable)
        return false;
    /* HarfBuzz's em_scalef_y: its roundf is floorf(v + .5f) */
    mult = (float)y_scale / (float)f->upem;
    *asc = (int)floorf((float)fabs((double)(float)f->asc) * mult + .5f);
    *desc = (int)floorf((float)-fabs((double)(float)f->desc) * mult + .5f);
    *gap = (int)floorf((float)f->gap * mult + .5f);
    return true;
}
