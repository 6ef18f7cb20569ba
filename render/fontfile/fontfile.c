/*
** Font files subset for the PDF writer (render/fontfile/fontfile.h): the
** file mapped read-only, its face's directory and metrics read (sfnt.c),
** the glyph ids sorted, checked and glyph 0 added, then the subsetter of
** its outlines (cff-subset.c or glyf-subset.c).
*/
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "curvefig/core.h"
#include "fontfile-private.h"
#include "sfnt.h"

static int
by_value(const void *a, const void *b)
{
    unsigned x = *(const unsigned *)a, y = *(const unsigned *)b;
    return (x > y) - (x < y);
}

/* gids sorted, repeats dropped, 0 first: *keep (cf_free'd by the
** caller), *nkeep. */
static int
kept_glyphs(const unsigned *gids, size_t n, unsigned **keep, size_t *nkeep)
{
    unsigned *k = cf_alloc_array(n + 1, sizeof *k);
    size_t i, m = 1;
    if (k == NULL)
        return -1;
    k[0] = 0;
    if (n > 0)
        memcpy(k + 1, gids, n * sizeof *k);
    qsort(k, n + 1, sizeof *k, by_value);
    for (i = 1; i <= n; i++)
        if (k[i] != k[m - 1])
            k[m++] = k[i];
    *keep = k;
    *nkeep = m;
    return 0;
}

static int
subset(cf__ff_t *f, unsigned index, const unsigned *gids, size_t n,
       cf__fontfile_subset_t *out)
{
    cf__ff_face_t face;
    cf__ff_table_t cff, glyf;
    unsigned num_glyphs = 0, *keep = NULL;
    size_t i, nkeep;
    int r;
    if (cf__ff_face_open(f, index, &face) ||
        cf__ff_table_find(f, &face, CF__FF_TAG('C', 'F', 'F', ' '), 0,
                          &cff) ||
        cf__ff_table_find(f, &face, CF__FF_TAG('g', 'l', 'y', 'f'), 0,
                          &glyf))
        return 1;
    if (cff.data == NULL && glyf.data == NULL) {
        cf__ff_table_t cff2;
        if (cf__ff_table_find(f, &face, CF__FF_TAG('C', 'F', 'F', '2'), 0,
                              &cff2))
            return 1;
        return cf__ff_fail(f, cff2.data != NULL ?
                           "CFF2 outlines, not subset" :
                           "no outlines (no 'CFF ' or 'glyf' table)");
    }
    out->kind = cff.data != NULL ? CF__FONTFILE_CFF : CF__FONTFILE_TRUETYPE;
    if (n > 0) {
        out->advances = cf_alloc_array(n, sizeof *out->advances);
        if (out->advances == NULL)
            return -1;
    }
    if ((r = cf__ff_metrics(f, &face, gids, n, out, &num_glyphs)) != 0)
        return r;
    for (i = 0; i < n; i++)
        if (gids[i] >= num_glyphs)
            return cf__ff_fail(f, "glyph id %u out of range (the font has "
                               "%u glyphs)", gids[i], num_glyphs);
    if (num_glyphs == 0)
        return cf__ff_fail(f, "maxp: no glyphs");
    if ((r = kept_glyphs(gids, n, &keep, &nkeep)) != 0)
        return r;
    if (out->kind == CF__FONTFILE_CFF)
        r = cf__ff_cff_subset(f, &cff, keep, nkeep, num_glyphs, out);
    else
        r = cf__ff_glyf_subset(f, &face, keep, nkeep, num_glyphs,
                               &out->program);
    cf_free(keep);
    return r;
}

int
cf__fontfile_subset_mem(const unsigned char *data, size_t len,
                        const char *name_for_errors, unsigned index,
                        const unsigned *gids, size_t n,
                        cf__fontfile_subset_t *out, char *why,
                        size_t why_cap)
{
    cf__ff_t f;
    int r;
    memset(out, 0, sizeof *out);
    cf__ff_init(&f, data, len, name_for_errors, why, why_cap);
    r = subset(&f, index, gids, n, out);
    if (r != 0) {
        cf__fontfile_subset_fini(out);
        if (r < 0 && why != NULL && why_cap > 0)
            cf__ff_fail(&f, "out of memory");
    }
    return r;
}

const char *
cf__ff_map_file(const char *path, void **map, size_t *len, int *err)
{
    struct stat st;
    void *m;
    /* O_NONBLOCK: a FIFO where the file should be is refused below
    ** instead of waiting for a writer (it changes nothing for a file) */
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    *map = NULL;
    *len = 0;
    *err = 0;
    if (fd < 0) {
        *err = errno;
        return "cannot open";
    }
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        return "not a regular file";
    }
    if (st.st_size > 0) {
        m = mmap(NULL, (size_t)st.st_size, PROT_READ, MAP_PRIVATE, fd, 0);
        if (m == MAP_FAILED) {
            *err = errno;
            close(fd);
            return "cannot map";
        }
        *map = m;
        *len = (size_t)st.st_size;
    }
    close(fd);
    return NULL;
}

int
cf__fontfile_subset(const char *path, unsigned index, const unsigned *gids,
                    size_t n, cf__fontfile_subset_t *out, char *why,
                    size_t why_cap)
{
    cf__ff_t f;
    const char *bad;
    void *map;
    size_t len;
    int r;
    memset(out, 0, sizeof *out);
    cf__ff_init(&f, NULL, 0, path, why, why_cap);
    bad = cf__ff_map_file(path, &map, &len, &r);
    if (bad != NULL)
        return r != 0 ? cf__ff_fail(&f, "%s: %s", bad, strerror(r))
                      : cf__ff_fail(&f, "%s", bad);
    r = cf__fontfile_subset_mem(map, len, path, index, gids, n, out, why,
                                why_cap);
    if (map != NULL)
        munmap(map, len);
    return r;
}

void
cf__fontfile_subset_fini(cf__fontfile_subset_t *out)
{
    cf__buf_free(&out->program);
    cf_free(out->advances);
    out->advances = NULL;
}
