/*
** The font subsetter (render/fontfile/) against FreeType, an independent
** reader of both formats.  For each font the renderer uses (skipped when
** not installed) and several glyph sets (the glyphs of "P_0 ... P_7" by
** FreeType's cmap, seeded random sets, TrueType composites, every glyph of
** a small font), the subset is loaded by FT_New_Memory_Face and every
** glyph it holds must have the original's unscaled, unhinted outline:
** the same points, tags and contours.  A CFF subset must be CID-keyed
** with CID = the original glyph id; a TrueType subset keeps glyph ids,
** its glyphs not kept (nor components of kept ones, by FreeType's reading
** of the composites) empty, its tables aligned with their checksums and
** the file's checkSumAdjustment right.  The font bounding box and italic
** style are FreeType's; advances are FreeType's unscaled advances; the
** one-glyph subset of Latin Modern Math (a 652 KB CFF table) is small.
** A CFF subset's subroutines are renumbered: each one of them is called
** by its charstrings (the scan of cff-charstring.c over the subset), a
** one-glyph subset has a few; the scan calls a computed call's number
** computed, the case in which the subset keeps the stubs instead.
**
** Damaged fonts (every font truncated at many lengths, bytes flipped at
** seeded random offsets) give 0 or 1, never a crash (the ASan build runs
** this); an out-of-range glyph id gives 1 naming it; allocation failure
** gives -1 and leaks nothing (tu_fail_loop).
*/
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_CID_H
#include FT_OUTLINE_H

#include "curvefig/core.h"
#include "fontfile-private.h"
#include "cff-subset.h"
#include "testutil.h"

#define LM "/usr/share/texmf/fonts/opentype/public/lm/"
#define LM_ROMAN LM "lmroman10-regular.otf"
#define LM_ITALIC LM "lmroman10-italic.otf"
#define LM_SEVEN LM "lmroman7-regular.otf"
#define LM_MATH "/usr/share/texmf/fonts/opentype/public/lm-math/" \
                "latinmodern-math.otf"
#define CMU_RM "/usr/share/fonts/truetype/cmu/cmunrm.ttf"
#define CMU_TI "/usr/share/fonts/truetype/cmu/cmunti.ttf"
#define NOTO_CJK "/usr/share/fonts/opentype/noto/NotoSerifCJK-Regular.ttc"

typedef struct font {
    const char *path;
    unsigned index;
} font_t;

static const font_t fonts[] = {
    { LM_ROMAN, 0 }, { LM_ITALIC, 0 }, { LM_SEVEN, 0 }, { LM_MATH, 0 },
    { CMU_RM, 0 }, { CMU_TI, 0 }, { NOTO_CJK, 0 }, { NOTO_CJK, 2 },
};
#define NFONTS (sizeof fonts / sizeof fonts[0])

static FT_Library ft;

static int
setup(void **state)
{
    (void)state;
    return FT_Init_FreeType(&ft) != 0;
}

static int
teardown(void **state)
{
    (void)state;
    FT_Done_FreeType(ft);
    return 0;
}

/* The file mapped copy-on-write (the flips of test_damaged stay in this
** process), or NULL when it is not installed. */
static unsigned char *
map_copy(const char *path, size_t *len)
{
    struct stat st;
    void *m;
    int fd = open(path, O_RDONLY);
    if (fd < 0)
        return NULL;
    assert_int_equal(fstat(fd, &st), 0);
    assert_true(st.st_size > 0);
    m = mmap(NULL, (size_t)st.st_size, PROT_READ | PROT_WRITE, MAP_PRIVATE,
             fd, 0);
    close(fd);
    assert_true(m != MAP_FAILED);
    *len = (size_t)st.st_size;
    return m;
}

static int
installed(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f != NULL)
        fclose(f);
    return f != NULL;
}

/* Glyph g's outline loaded unscaled and unhinted; advance in *adv. */
static FT_Outline *
outline(FT_Face face, unsigned g, long *adv)
{
    FT_Error e = FT_Load_Glyph(face, g, FT_LOAD_NO_SCALE |
                               FT_LOAD_NO_HINTING);
    if (e != 0)
        fail_msg("FreeType cannot load glyph %u (error %d)", g, e);
    if (adv != NULL)
        *adv = face->glyph->metrics.horiAdvance;
    return &face->glyph->outline;
}

/* The outline of glyph a of fa equals that of glyph b of fb. */
static void
same_outline(FT_Face fa, unsigned a, FT_Face fb, unsigned b)
{
    FT_Outline *o = outline(fa, a, NULL), copy;
    int i;
    copy.n_points = o->n_points;
    copy.n_contours = o->n_contours;
    copy.points = malloc(sizeof *copy.points * (size_t)(o->n_points + 1));
    copy.tags = malloc((size_t)o->n_points + 1);
    copy.contours = malloc(sizeof *copy.contours *
                           (size_t)(o->n_contours + 1));
    assert_true(copy.points && copy.tags && copy.contours);
    memcpy(copy.points, o->points, sizeof *o->points * (size_t)o->n_points);
    memcpy(copy.tags, o->tags, (size_t)o->n_points);
    memcpy(copy.contours, o->contours,
           sizeof *o->contours * (size_t)o->n_contours);
    o = outline(fb, b, NULL);
    if (o->n_points != copy.n_points || o->n_contours != copy.n_contours)
        fail_msg("glyph %u: %d points %d contours, the subset's %u: %d "
                 "and %d", a, copy.n_points, copy.n_contours, b,
                 o->n_points, o->n_contours);
    for (i = 0; i < o->n_points; i++)
        if (o->points[i].x != copy.points[i].x ||
            o->points[i].y != copy.points[i].y ||
            o->tags[i] != copy.tags[i])
            fail_msg("glyph %u point %d: (%ld, %ld) tag %d, the subset's "
                     "(%ld, %ld) tag %d", a, i, (long)copy.points[i].x,
                     (long)copy.points[i].y, copy.tags[i],
                     (long)o->points[i].x, (long)o->points[i].y,
                     o->tags[i]);
    for (i = 0; i < o->n_contours; i++)
        assert_int_equal(o->contours[i], copy.contours[i]);
    free(copy.points);
    free(copy.tags);
    free(copy.contours);
}

static int
has(const unsigned *gids, size_t n, unsigned g)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (gids[i] == g)
            return 1;
    return g == 0;
}

/* kept[g] = 1 for glyph 0, the glyphs gids[0..n) and, to any depth, the
** components of the composite ones, as FreeType reads them. */
static void
components_of(FT_Face face, const unsigned *gids, size_t n,
              unsigned char *kept)
{
    unsigned *stack = malloc(sizeof *stack * (size_t)face->num_glyphs);
    size_t sp = 0, i;
    assert_non_null(stack);
    kept[0] = 1;
    stack[sp++] = 0;
    for (i = 0; i < n; i++)
        if (!kept[gids[i]]) {
            kept[gids[i]] = 1;
            stack[sp++] = gids[i];
        }
    while (sp > 0) {
        FT_UInt g = stack[--sp], k;
        assert_int_equal(FT_Load_Glyph(face, g, FT_LOAD_NO_SCALE |
                                       FT_LOAD_NO_RECURSE), 0);
        if (face->glyph->format != FT_GLYPH_FORMAT_COMPOSITE)
            continue;
        for (k = 0; k < face->glyph->num_subglyphs; k++) {
            FT_Int index, arg1, arg2;
            FT_UInt flags;
            FT_Matrix m;
            assert_int_equal(FT_Get_SubGlyph_Info(face->glyph, k, &index,
                                                  &flags, &arg1, &arg2,
                                                  &m), 0);
            if (!kept[index]) {
                kept[index] = 1;
                stack[sp++] = (unsigned)index;
            }
        }
    }
    free(stack);
}

static uint32_t
be32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 |
           (uint32_t)p[2] << 8 | p[3];
}

/* The sum of the 4-byte words of p[0..n), n a multiple of 4. */
static uint32_t
sum32(const unsigned char *p, size_t n)
{
    uint32_t s = 0;
    size_t i;
    for (i = 0; i < n; i += 4)
        s += be32(p + i);
    return s;
}

/* A TrueType subset's tables: 4-byte aligned, each record's checksum
** its table's (head's with checkSumAdjustment 0), the whole file summing
** to 0xB1B0AFBA (the OpenType spec's rule for checkSumAdjustment), and
** indexToLocFormat the loca written (numGlyphs + 1 entries of 2 or 4
** bytes). */
static void
check_sfnt(const unsigned char *d, size_t len, long num_glyphs)
{
    unsigned i, n = (unsigned)d[4] << 8 | d[5];
    size_t loca = 0;
    int long_loca = -1;
    assert_int_equal(len % 4, 0);
    assert_int_equal(sum32(d, len), 0xb1b0afbau);
    for (i = 0; i < n; i++) {
        const unsigned char *r = d + 12 + 16 * i;
        size_t off = be32(r + 8), tlen = be32(r + 12);
        uint32_t sum;
        assert_int_equal(off % 4, 0);
        assert_true(off + ((tlen + 3) & ~(size_t)3) <= len);
        sum = sum32(d + off, (tlen + 3) & ~(size_t)3);
        if (memcmp(r, "head", 4) == 0) {
            sum -= be32(d + off + 8);
            long_loca = d[off + 51];
        }
        if (memcmp(r, "loca", 4) == 0)
            loca = tlen;
        assert_int_equal(be32(r + 4), sum);
    }
    assert_true(long_loca == 0 || long_loca == 1);
    assert_int_equal(loca, (size_t)(num_glyphs + 1) * (long_loca ? 4 : 2));
}

/* The subroutines of the last CFF subset checked (all of its INDEXes). */
static size_t last_nsubrs;

/* An offset operand of a DICT entry of our subset (a 5-byte integer). */
static size_t
dict_offset(const cf__cff_op_t *op, size_t k)
{
    assert_true(op->nargs > k && op->args[k] >= 0);
    return (size_t)op->args[k];
}

/* A CFF subset's subroutines are exactly those its charstrings call
** (the scan of cff-charstring.c over the subset's own INDEXes): every
** one used, none a stub left for its number.  Their count. */
static size_t
check_subrs_used(const unsigned char *t, size_t tlen)
{
    cf__ff_t f;
    char why[256];
    cf__cff_index_t names, tops, strings, gsubrs, cs, fdarray;
    cf__cff_index_t lsubrs[CF__CFF_MAX_FDS];
    unsigned char *gused, *lused[CF__CFF_MAX_FDS];
    cf__cff_op_t op;
    size_t pos, len, at = 0, cs_at = 0, fda_at = 0, fds_at = 0, i, k;
    size_t total;
    long budget;
    cf__ff_init(&f, t, tlen, "subset", why, sizeof why);
    assert_int_equal(cf__cff_index_read(&f, t, tlen, t[2], "Name", &names),
                     0);
    assert_int_equal(cf__cff_index_read(&f, t, tlen, names.end, "Top",
                                        &tops), 0);
    assert_int_equal(cf__cff_index_read(&f, t, tlen, tops.end, "String",
                                        &strings), 0);
    assert_int_equal(cf__cff_index_read(&f, t, tlen, strings.end, "Global",
                                        &gsubrs), 0);
    assert_int_equal(cf__cff_index_item(&f, &tops, 0, &pos, &len), 0);
    while (cf__cff_dict_next(&f, t + pos, len, &at, &op, "Top") == 1) {
        if (op.op == 17)
            cs_at = dict_offset(&op, 0);
        else if (op.op == 1236)
            fda_at = dict_offset(&op, 0);
        else if (op.op == 1237)
            fds_at = dict_offset(&op, 0);
    }
    assert_int_equal(cf__cff_index_read(&f, t, tlen, cs_at, "CharStrings",
                                        &cs), 0);
    assert_int_equal(cf__cff_index_read(&f, t, tlen, fda_at, "FDArray",
                                        &fdarray), 0);
    assert_true(fdarray.count >= 1 && fdarray.count <= CF__CFF_MAX_FDS);
    for (k = 0; k < fdarray.count; k++) {
        size_t dpos, dlen, ppos = 0, plen = 0, sub = 0;
        at = 0;
        assert_int_equal(cf__cff_index_item(&f, &fdarray, k, &dpos, &dlen),
                         0);
        while (cf__cff_dict_next(&f, t + dpos, dlen, &at, &op, "Font") == 1)
            if (op.op == 18) {
                plen = dict_offset(&op, 0);
                ppos = dict_offset(&op, 1);
            }
        at = 0;
        while (cf__cff_dict_next(&f, t + ppos, plen, &at, &op,
                                 "Private") == 1)
            if (op.op == 19)
                sub = dict_offset(&op, 0);
        memset(&lsubrs[k], 0, sizeof lsubrs[k]);
        if (sub > 0)
            assert_int_equal(cf__cff_index_read(&f, t, tlen, ppos + sub,
                                                "Subrs", &lsubrs[k]), 0);
        lused[k] = calloc(lsubrs[k].count + 1, 1);
        assert_non_null(lused[k]);
    }
    gused = calloc(gsubrs.count + 1, 1);
    assert_non_null(gused);
    budget = cf__cff_scan_budget(cs.count);
    for (i = 0; i < cs.count; i++) {
        unsigned fd = 0;
        cf__cff_subrs_t g, l;
        assert_int_equal(cf__cff_fdselect(t, tlen, fds_at, (unsigned)i,
                                          &fd), 0);
        assert_true(fd < fdarray.count);
        g.index = &gsubrs;
        g.used = gused;
        l.index = &lsubrs[fd];
        l.used = lused[fd];
        assert_int_equal(cf__cff_index_item(&f, &cs, i, &pos, &len), 0);
        if (cf__cff_scan_glyph(&f, t + pos, len, (unsigned)i, &g, &l, NULL,
                               &budget) != 0)
            fail_msg("%s", why);
    }
    total = gsubrs.count;
    for (i = 0; i < gsubrs.count; i++)
        if (!gused[i])
            fail_msg("global subroutine %zu of %zu not called", i,
                     gsubrs.count);
    for (k = 0; k < fdarray.count; k++) {
        for (i = 0; i < lsubrs[k].count; i++)
            if (!lused[k][i])
                fail_msg("local subroutine %zu of %zu (Font DICT %zu) not "
                         "called", i, lsubrs[k].count, k);
        total += lsubrs[k].count;
        free(lused[k]);
    }
    free(gused);
    return total;
}

/* Subset gids of face orig (of file fo), check it against FreeType;
** the program's size. */
static size_t
check_subset(const font_t *fo, FT_Face orig, const unsigned *gids, size_t n)
{
    cf__fontfile_subset_t out;
    char why[256];
    FT_Face sub;
    size_t i, size;
    long adv;
    int r = cf__fontfile_subset(fo->path, fo->index, gids, n, &out, why,
                                sizeof why);
    if (r != 0)
        fail_msg("%s: %d: %s", fo->path, r, why);
    /* head's numbers as FreeType reads them, its italic style */
    assert_true(out.units_per_em == orig->units_per_EM);
    assert_true(out.bbox[0] == orig->bbox.xMin &&
                out.bbox[1] == orig->bbox.yMin &&
                out.bbox[2] == orig->bbox.xMax &&
                out.bbox[3] == orig->bbox.yMax);
    assert_int_equal((out.flags & CF__FONTFILE_ITALIC) != 0,
                     (orig->style_flags & FT_STYLE_FLAG_ITALIC) != 0);
    assert_true(out.flags & CF__FONTFILE_SYMBOLIC);
    assert_true(out.ps_name[0] != '\0');
    if (FT_New_Memory_Face(ft, out.program.data, (FT_Long)out.program.size,
                           0, &sub) != 0)
        fail_msg("%s: FreeType cannot open the subset", fo->path);
    for (i = 0; i < n; i++) {
        (void)outline(orig, gids[i], &adv);
        assert_int_equal(out.advances[i], adv);
    }
    if (out.kind == CF__FONTFILE_CFF) {
        /* glyph i of the subset has CID keep[i] (ascending); FreeType,
           like a PDF viewer, loads a CID-keyed CFF's glyphs by CID */
        FT_Bool cid = 0;
        unsigned *keep = malloc(sizeof *keep * (n + 1)), absent = 1;
        size_t nkeep = 0;
        assert_non_null(keep);
        for (i = 0; i < (size_t)orig->num_glyphs && nkeep <= n; i++)
            if (has(gids, n, (unsigned)i))
                keep[nkeep++] = (unsigned)i;
        assert_int_equal(FT_Get_CID_Is_Internally_CID_Keyed(sub, &cid), 0);
        assert_true(cid);
        for (i = 0; i < nkeep; i++) {
            FT_UInt c = 0;
            assert_int_equal(FT_Get_CID_From_Glyph_Index(sub, (FT_UInt)i,
                                                         &c), 0);
            if (c != keep[i])
                fail_msg("subset glyph %zu: CID %u, not glyph id %u", i, c,
                         keep[i]);
            same_outline(orig, c, sub, c);
        }
        /* and no other glyph */
        while (absent < (unsigned)orig->num_glyphs && has(gids, n, absent))
            absent++;
        if (absent < (unsigned)orig->num_glyphs)
            assert_int_not_equal(FT_Load_Glyph(sub, absent,
                                               FT_LOAD_NO_SCALE), 0);
        free(keep);
        last_nsubrs = check_subrs_used(out.program.data, out.program.size);
    } else {
        /* the glyphs asked for and, by FreeType's reading of the
           composites, their components: the original's outlines; every
           other glyph empty */
        unsigned char *kept = calloc((size_t)orig->num_glyphs, 1);
        assert_non_null(kept);
        assert_int_equal(sub->num_glyphs, orig->num_glyphs);
        check_sfnt(out.program.data, out.program.size, orig->num_glyphs);
        components_of(orig, gids, n, kept);
        for (i = 0; i < (size_t)orig->num_glyphs; i++) {
            if (kept[i])
                same_outline(orig, (unsigned)i, sub, (unsigned)i);
            else if (outline(sub, (unsigned)i, NULL)->n_points != 0)
                fail_msg("glyph %zu not kept, and not empty", i);
        }
        free(kept);
    }
    FT_Done_Face(sub);
    size = out.program.size;
    cf__fontfile_subset_fini(&out);
    return size;
}

/* The glyphs of text by the face's cmap (those it has). */
static size_t
text_glyphs(FT_Face face, const char *text, unsigned *gids)
{
    size_t n = 0;
    for (; *text; text++) {
        FT_UInt g = FT_Get_Char_Index(face, (unsigned char)*text);
        if (g != 0)
            gids[n++] = g;
    }
    return n;
}

static FT_Face
open_face(const font_t *fo)
{
    FT_Face face;
    if (FT_New_Face(ft, fo->path, fo->index, &face) != 0)
        return NULL;
    return face;
}

static void
test_outlines(void **state)
{
    static const unsigned cjk[] = { 0x4e2d, 0x6587, 0x5b57, 0x4f53, 0x6f22,
        0x3042, 0xac00, 0x9f98 };
    size_t f, tested = 0;
    (void)state;
    for (f = 0; f < NFONTS; f++) {
        const font_t *fo = &fonts[f];
        FT_Face face = open_face(fo);
        unsigned gids[64];
        size_t n, i, size1, size8;
        tu_rng rng;
        clock_t t0;
        if (face == NULL) {
            print_message("%s (face %u): not installed\n", fo->path,
                          fo->index);
            continue;
        }
        tested++;
        /* one glyph, then the glyphs of "P_0 ... P_7" */
        n = text_glyphs(face, "P", gids);
        assert_int_equal(n, 1);
        t0 = clock();
        last_nsubrs = 0;
        size1 = check_subset(fo, face, gids, 1);
        /* one glyph: the few subroutines it calls, not the font's
           thousands (LM Math 1,039 local ones, Noto CJK's 2,000-odd) */
        assert_true(last_nsubrs < 64);
        n = text_glyphs(face, "P_01234567 P_0", gids);
        assert_true(n >= 8);
        for (i = 0; i < sizeof cjk / sizeof cjk[0]; i++) {
            FT_UInt g = FT_Get_Char_Index(face, cjk[i]);
            if (g != 0)
                gids[n++] = g;
        }
        size8 = check_subset(fo, face, gids, n);
        print_message("%-60s face %u: %5zu bytes for 1 glyph, %6zu for "
                      "%zu (%.3f s)\n", fo->path, fo->index, size1, size8,
                      n, (double)(clock() - t0) / CLOCKS_PER_SEC);
        if (strcmp(fo->path, LM_MATH) == 0)
            /* the header, DICTs and strings (~300 bytes), one
               charstring and the few subroutines it calls (renumbered,
               not LM Math's 1,039 local Subrs with stubs): 0.7 KB; not
               the table's 652 KB */
            assert_true(size1 < 2048);
        /* seeded random sets */
        tu_rng_seed(&rng, 20261205 + f);
        for (i = 0; i < 3; i++) {
            size_t k, m = 1 + (size_t)(tu_rng_u01(&rng) * 40);
            for (k = 0; k < m; k++)
                gids[k] = (unsigned)(tu_rng_u01(&rng) * face->num_glyphs);
            check_subset(fo, face, gids, m);
        }
        FT_Done_Face(face);
    }
    if (tested == 0)
        skip();
}

/* Composite TrueType glyphs: their components kept, loading equal. */
static void
test_composites(void **state)
{
    static const char *const paths[] = { CMU_RM, CMU_TI };
    size_t p, tested = 0;
    (void)state;
    for (p = 0; p < 2; p++) {
        font_t fo = { paths[p], 0 };
        FT_Face face = open_face(&fo);
        unsigned gids[12];
        size_t n = 0;
        long g;
        if (face == NULL)
            continue;
        tested++;
        for (g = 1; g < face->num_glyphs && n < 12; g++) {
            assert_int_equal(FT_Load_Glyph(face, (FT_UInt)g,
                                           FT_LOAD_NO_SCALE |
                                           FT_LOAD_NO_RECURSE), 0);
            if (face->glyph->format == FT_GLYPH_FORMAT_COMPOSITE)
                gids[n++] = (unsigned)g;
        }
        assert_true(n > 0);
        check_subset(&fo, face, gids, n);
        FT_Done_Face(face);
    }
    if (tested == 0)
        skip();
}

/* Every glyph of a small font (LM Roman 7, CMU Serif). */
static void
test_all_glyphs(void **state)
{
    static const font_t all[] = { { LM_SEVEN, 0 }, { CMU_RM, 0 } };
    size_t f, tested = 0;
    (void)state;
    for (f = 0; f < 2; f++) {
        FT_Face face = open_face(&all[f]);
        unsigned *gids;
        size_t i, size;
        if (face == NULL)
            continue;
        tested++;
        gids = malloc(sizeof *gids * (size_t)face->num_glyphs);
        assert_non_null(gids);
        for (i = 0; i < (size_t)face->num_glyphs; i++)
            gids[i] = (unsigned)(face->num_glyphs - 1 - (long)i);
        size = check_subset(&all[f], face, gids, (size_t)face->num_glyphs);
        print_message("%s: all %ld glyphs, %zu bytes\n", all[f].path,
                      face->num_glyphs, size);
        free(gids);
        FT_Done_Face(face);
    }
    if (tested == 0)
        skip();
}

/* Every glyph of Noto Serif CJK's first face (the scan's budget of steps
** is not met by a real font's 65,535 glyphs), every 97th compared. */
static void
test_all_cjk(void **state)
{
    static const font_t fo = { NOTO_CJK, 0 };
    FT_Face face = open_face(&fo), sub;
    cf__fontfile_subset_t out;
    char why[256];
    unsigned *gids;
    size_t i, n;
    (void)state;
    if (face == NULL)
        skip();
    n = (size_t)face->num_glyphs;
    gids = malloc(sizeof *gids * n);
    assert_non_null(gids);
    for (i = 0; i < n; i++)
        gids[i] = (unsigned)i;
    if (cf__fontfile_subset(fo.path, 0, gids, n, &out, why, sizeof why))
        fail_msg("%s", why);
    assert_int_equal(FT_New_Memory_Face(ft, out.program.data,
                                        (FT_Long)out.program.size, 0, &sub),
                     0);
    for (i = 0; i < n; i += 97)
        same_outline(face, (unsigned)i, sub, (unsigned)i);
    (void)check_subrs_used(out.program.data, out.program.size);
    print_message("%s: all %zu glyphs, %zu bytes\n", fo.path, n,
                  out.program.size);
    FT_Done_Face(sub);
    FT_Done_Face(face);
    cf__fontfile_subset_fini(&out);
    free(gids);
}

/* Where table tag of face index begins in the file (0: not found). */
static size_t
table_at(const unsigned char *d, size_t len, unsigned index, const char *tag)
{
    size_t at = 0, n, i;
    if (len < 12)
        return 0;
    if (memcmp(d, "ttcf", 4) == 0) {
        at = (size_t)d[12 + 4 * index] << 24 | d[13 + 4 * index] << 16 |
             d[14 + 4 * index] << 8 | d[15 + 4 * index];
    }
    n = (size_t)d[at + 4] << 8 | d[at + 5];
    for (i = 0; i < n; i++) {
        const unsigned char *r = d + at + 12 + 16 * i;
        if (memcmp(r, tag, 4) == 0)
            return (size_t)r[8] << 24 | r[9] << 16 | r[10] << 8 | r[11];
    }
    return 0;
}

/* One subset of damaged bytes: 0, or 1 with a message and nothing out. */
static int
damaged(const unsigned char *d, size_t len, unsigned index)
{
    static const unsigned gids[] = { 1, 2, 3, 40, 41, 7, 300 };
    cf__fontfile_subset_t out;
    char why[256];
    int r = cf__fontfile_subset_mem(d, len, "damaged", index, gids, 7, &out,
                                    why, sizeof why);
    if (r != 0 && r != 1)
        fail_msg("damaged font: %d", r);
    if (r == 1) {
        assert_true(strncmp(why, "damaged: ", 9) == 0 && why[9] != '\0');
        assert_null(out.program.data);
        assert_null(out.advances);
    }
    cf__fontfile_subset_fini(&out);
    return r;
}

static void
test_damaged(void **state)
{
    size_t f, tested = 0;
    (void)state;
    for (f = 0; f < NFONTS; f++) {
        size_t len, i, refused = 0, runs = 0, outl;
        unsigned char *d = map_copy(fonts[f].path, &len);
        tu_rng rng;
        if (d == NULL)
            continue;
        tested++;
        outl = table_at(d, len, fonts[f].index, "CFF ");
        if (outl == 0)
            outl = table_at(d, len, fonts[f].index, "glyf");
        assert_int_equal(damaged(d, len, fonts[f].index), 0);
        tu_rng_seed(&rng, 1205 + f);
        /* truncated: the first bytes one by one, then across the file */
        for (i = 0; i < 300; i++, runs++) {
            size_t cut = i < 64 ? i : i < 200 ? len / 136 * (i - 64) :
                         (size_t)(tu_rng_u01(&rng) * (double)len);
            refused += (size_t)damaged(d, cut, fonts[f].index);
        }
        /* a byte changed: in the first 64 KB, in the outline table's
           first 16 KB (its INDEXes, DICTs, loca'd glyphs), anywhere */
        for (i = 0; i < 600; i++, runs++) {
            size_t span = i < 200 ? 65536 : i < 400 ? 16384 : len;
            size_t at = (i < 200 ? 0 : i < 400 ? outl : 0) +
                        (size_t)(tu_rng_u01(&rng) * (double)span);
            unsigned char keep;
            if (at >= len)
                continue;
            keep = d[at];
            d[at] ^= (unsigned char)(1 + tu_rng_u01(&rng) * 255);
            refused += (size_t)damaged(d, len, fonts[f].index);
            d[at] = keep;
        }
        print_message("%s face %u: %zu of %zu damaged copies refused\n",
                      fonts[f].path, fonts[f].index, refused, runs);
        assert_true(refused > 0);
        munmap(d, len);
    }
    if (tested == 0)
        skip();
}

static void
test_refused(void **state)
{
    static const unsigned bad[] = { 3, 70000 };
    cf__fontfile_subset_t out;
    char why[256];
    (void)state;
    assert_int_equal(cf__fontfile_subset("/nonexistent/font.otf", 0, bad, 1,
                                         &out, why, sizeof why), 1);
    assert_non_null(strstr(why, "/nonexistent/font.otf: cannot open"));
    assert_null(out.program.data);
    /* a directory, and a FIFO no one writes to (opened without waiting
    ** for a writer), where the font file should be: refused at once */
    {
        char dir[] = "/tmp/cf-fontfile-XXXXXX", fifo[64];
        assert_non_null(mkdtemp(dir));
        assert_int_equal(cf__fontfile_subset(dir, 0, bad, 1, &out, why,
                                             sizeof why), 1);
        assert_non_null(strstr(why, "not a regular file"));
        snprintf(fifo, sizeof fifo, "%s/font.otf", dir);
        assert_int_equal(mkfifo(fifo, 0600), 0);
        assert_int_equal(cf__fontfile_subset(fifo, 0, bad, 1, &out, why,
                                             sizeof why), 1);
        assert_non_null(strstr(why, "not a regular file"));
        assert_null(out.program.data);
        unlink(fifo);
        rmdir(dir);
    }
    assert_int_equal(cf__fontfile_subset_mem((const unsigned char *)"OTTO",
                                             4, "tiny", 0, bad, 1, &out,
                                             why, sizeof why), 1);
    assert_non_null(strstr(why, "tiny: "));
    if (!installed(LM_ROMAN))
        skip();
    assert_int_equal(cf__fontfile_subset(LM_ROMAN, 0, bad, 2, &out, why,
                                         sizeof why), 1);
    assert_non_null(strstr(why, "glyph id 70000 out of range"));
    assert_null(out.program.data);
    assert_null(out.advances);
    assert_int_equal(cf__fontfile_subset(LM_ROMAN, 1, bad, 1, &out, why,
                                         sizeof why), 1);
    assert_non_null(strstr(why, "face 1"));
    cf__fontfile_subset_fini(&out);
}

/* The same bytes every run. */
static void
test_deterministic(void **state)
{
    static const unsigned gids[] = { 50, 9, 120, 9, 33 };
    static const char *const paths[] = { LM_ROMAN, CMU_RM };
    size_t p;
    (void)state;
    for (p = 0; p < 2; p++) {
        cf__fontfile_subset_t a, b;
        char why[256];
        if (cf__fontfile_subset(paths[p], 0, gids, 5, &a, why, sizeof why))
            continue;
        assert_int_equal(cf__fontfile_subset(paths[p], 0, gids, 5, &b, why,
                                             sizeof why), 0);
        assert_int_equal(a.program.size, b.program.size);
        assert_memory_equal(a.program.data, b.program.data, a.program.size);
        cf__fontfile_subset_fini(&a);
        cf__fontfile_subset_fini(&b);
    }
}

static const char *alloc_path;

static cf_status_t
op_subset(cf_diag_t *diag)
{
    static const unsigned gids[] = { 40, 41, 42, 43, 44, 45, 46, 47 };
    cf__fontfile_subset_t out;
    char why[256];
    int r = cf__fontfile_subset(alloc_path, 0, gids, 8, &out, why,
                                sizeof why);
    (void)diag;
    if (r == 0)
        assert_non_null(out.program.data);
    else
        assert_null(out.program.data);
    cf__fontfile_subset_fini(&out);
    if (r == 1)
        fail_msg("%s", why);
    return r == 0 ? CF_STATUS_OK : CF_STATUS_NO_MEMORY;
}

static void
test_alloc_failure(void **state)
{
    static const char *const paths[] = { LM_ROMAN, CMU_RM, LM_MATH };
    size_t p, tested = 0;
    (void)state;
    for (p = 0; p < 3; p++) {
        if (!installed(paths[p]))
            continue;
        tested++;
        alloc_path = paths[p];
        assert_true(tu_fail_loop(paths[p], op_subset, false) > 0);
    }
    if (tested == 0)
        skip();
}

/* The scan's decision (cff-charstring.c): a call whose number is the
** integer just before it is a site to renumber; one computed ("-110 3 add
** callsubr": subroutine 0 by the bias 107) says computed, and the subset
** then keeps its stubs, as it does when there are more sites than the
** list may hold. */
static void
test_computed_call(void **state)
{
    /* a Subrs INDEX of one subroutine, "return" */
    static const unsigned char subrs_bytes[] = { 0, 1, 1, 1, 2, 11 };
    static const unsigned char literal[] = { 32, 10, 14 };   /* -107 */
    static const unsigned char computed[] = { 251, 2, 142, 12, 10, 10, 14 };
    static const unsigned char apart[] = { 32, 142, 12, 18, 10, 14 };
    const unsigned char *cs[3] = { literal, computed, apart };
    size_t cs_len[3] = { sizeof literal, sizeof computed, sizeof apart };
    cf__ff_t f;
    char why[256];
    cf__cff_index_t ix;
    size_t k;
    (void)state;
    cf__ff_init(&f, subrs_bytes, sizeof subrs_bytes, "hand-made", why,
                sizeof why);
    assert_int_equal(cf__cff_index_read(&f, subrs_bytes, sizeof subrs_bytes,
                                        0, "Subrs", &ix), 0);
    for (k = 0; k < 3; k++) {
        unsigned char used[2] = { 0, 0 };
        cf__cff_subrs_t l;
        cf__cff_sites_t sites;
        long budget = cf__cff_scan_budget(1);
        memset(&sites, 0, sizeof sites);
        sites.max = 16;
        l.index = &ix;
        l.used = used;
        assert_int_equal(cf__cff_scan_glyph(&f, cs[k], cs_len[k], 1, NULL,
                                            &l, &sites, &budget), 0);
        assert_int_equal(used[0], 1);
        if (k == 0) {
            assert_int_equal(sites.computed, 0);
            assert_int_equal(sites.n, 1);
            assert_true(sites.v[0].at == literal);
            assert_int_equal(sites.v[0].len, 1);
            assert_int_equal(sites.v[0].kind, CF__CFF_SITE_LOCAL);
            assert_int_equal(sites.v[0].old, 0);
            cf_free(sites.v);
            /* more sites than max: the list is given up (the stubs) */
            memset(&sites, 0, sizeof sites);
            used[0] = 0;
            assert_int_equal(cf__cff_scan_glyph(&f, cs[k], cs_len[k], 1,
                                                NULL, &l, &sites, &budget),
                             0);
            assert_int_equal(used[0], 1);
            assert_int_equal(sites.full, 1);
            assert_int_equal(sites.n, 0);
        } else {
            /* computed, or (drop) the literal not the number called */
            assert_int_equal(sites.computed, 1);
        }
        cf_free(sites.v);
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_outlines),
        cmocka_unit_test(test_composites),
        cmocka_unit_test(test_all_glyphs),
        cmocka_unit_test(test_all_cjk),
        cmocka_unit_test(test_damaged),
        cmocka_unit_test(test_refused),
        cmocka_unit_test(test_deterministic),
        cmocka_unit_test(test_alloc_failure),
        cmocka_unit_test(test_computed_call),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
